"""`nl2hltl2plan train language [-o PATH] [--structure-out PATH] [--only slots|structure] [--seed S]`:
rebuild the learned language models.

Trains the slot model (`language.learned`) on ALFRED's train annotations (text-faithful labels) minus
the benchmark's excluded trials, prints its slot accuracy on valid_seen / valid_unseen, and writes
the artifact (default: the committed one inside the package); then the structure model (task spans
and their relations, a CRF over synthetic compositions of the same annotations), with its span accuracy
on compositions of valid_unseen. Deterministic for a seed; about 3-4 minutes on 2 cores (needs the
`train` extra).
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any


def register(sub: Any) -> None:
    p = sub.add_parser(
        "train", help="train learned components (language)", description=__doc__.split("\n\n")[1]
    )
    what = p.add_subparsers(dest="what", metavar="WHAT", required=True)
    lang = what.add_parser("language", help="the learned language model (slot model)")
    lang.add_argument("-o", "--out", type=Path, default=None,
                      help="where to write the model (default: the packaged slot_model.npz)")
    lang.add_argument("--structure-out", type=Path, default=None,
                      help="where to write the structure model (default: the packaged structure_model.npz)")
    lang.add_argument("--only", choices=["slots", "structure"], default=None,
                      help="train only one of the two models")
    lang.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    lang.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from importlib import resources

    from nl2hltl2plan.language.learned import structure, structure_train
    from nl2hltl2plan.language.learned.model import ARTIFACT
    from nl2hltl2plan.language.learned.train import train_and_report

    package = resources.files("nl2hltl2plan.language.learned")
    jobs = [
        ("slots", args.out or Path(str(package / ARTIFACT)), train_and_report),
        ("structure", args.structure_out or Path(str(package / structure.ARTIFACT)),
         structure_train.train_and_report),
    ]
    for name, out, job in jobs:
        if args.only not in (None, name):
            continue
        if out.parent and not out.parent.exists():
            out.parent.mkdir(parents=True)
        print(job(out, seed=args.seed))
    return 0
