"""`nl2hltl2plan train language [-o PATH] [--seed S]`: rebuild the learned language model.

Trains the slot model (`language.learned`) on ALFRED's train annotations (text-faithful labels) minus
the benchmark's excluded trials, prints its slot accuracy on valid_seen / valid_unseen, and writes
the artifact (default: the committed one inside the package). Deterministic for a seed; about 20-40 s
on 2 cores.
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from nl2hltl2plan.cli.commands import COMMANDS


def register(sub: Any) -> None:
    p = sub.add_parser(
        "train", help=COMMANDS["train"], description=__doc__.split("\n\n")[1]
    )
    what = p.add_subparsers(dest="what", metavar="WHAT", required=True)
    lang = what.add_parser("language", help="the learned language model (slot model)")
    lang.add_argument("-o", "--out", type=Path, default=None,
                      help="where to write the model (default: the packaged slot_model.npz)")
    lang.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    lang.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from importlib import resources

    from nl2hltl2plan.language.learned.model import ARTIFACT
    from nl2hltl2plan.language.learned.train import train_and_report

    out = args.out or Path(str(resources.files("nl2hltl2plan.language.learned") / ARTIFACT))
    if out.parent and not out.parent.exists():
        out.parent.mkdir(parents=True)
    print(train_and_report(out, seed=args.seed))
    return 0
