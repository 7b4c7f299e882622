"""`nl2hltl2plan train language [-o PATH] [--structure-out PATH] [--request-out PATH]
[--only slots|structure|request] [--seed S] [--encoder]`: rebuild the learned language models.

Trains the slot model (`language.learned`) on ALFRED's train annotations (text-faithful labels) minus
the benchmark's excluded trials, prints its slot accuracy on valid_seen / valid_unseen, and writes
the artifacts (default: the user's cache, ~/.cache/nl2hltl2plan/models/, which the offline parser
then prefers to the packaged models; the installed package is never written): the structure model
(task spans and their relations, a CRF over synthetic compositions of the same annotations), with its
span accuracy on compositions of valid_unseen, then the slot model, whose type ranker learns from the
offline parser's readings with the structure model the parser prefers (the one just written, when it is
written to the default or the packaged place: then one run rebuilds both, whatever was there before),
and the request-unit classifier (a voice's frame against its request, `request_units`, about 40 s).
Each file is written to a temporary file and renamed: a kill leaves the previous model. Deterministic
for a seed; about 3-4 minutes on 2 cores (needs the `train` extra). `--encoder` adds the pretrained
encoder's sentence embeddings to the slot model (the `encoder` extra and its wheel; measured and not the
default: docs/learned.md); it takes about 15 minutes on a busy 2-core machine.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from functools import partial
from pathlib import Path
from typing import Any

from nl2hltl2plan.argtypes import seed
from nl2hltl2plan.cli.commands import COMMANDS


def register(sub: Any) -> None:
    p = sub.add_parser(
        "train", help=COMMANDS["train"], description=__doc__.split("\n\n")[1]
    )
    what = p.add_subparsers(dest="what", metavar="WHAT", required=True)
    lang = what.add_parser("language", help="the learned language model (slot model)")
    lang.add_argument("-o", "--out", type=Path, default=None,
                      help="where to write the slot model (default: "
                      "~/.cache/nl2hltl2plan/models/slot_model.npz, which the offline parser prefers to the "
                      "packaged model; delete it to go back)")
    lang.add_argument("--structure-out", type=Path, default=None,
                      help="where to write the structure model (default: "
                      "~/.cache/nl2hltl2plan/models/structure_model.npz, preferred likewise)")
    lang.add_argument("--request-out", type=Path, default=None,
                      help="where to write the request-unit classifier (default: "
                      "~/.cache/nl2hltl2plan/models/request_model.npz, preferred likewise)")
    lang.add_argument("--only", choices=["slots", "structure", "request"], default=None,
                      help="train only one of the three models")
    lang.add_argument("--seed", type=seed, default=0, help="random seed, 0..2^32-1 (default 0)")
    lang.add_argument("--encoder", action="store_true",
                      help="the slot model (not the structure model) also reads the pretrained "
                      "encoder's sentence embeddings (all-MiniLM-L6-v2, the `encoder` extra; "
                      "measured, not the default: docs/learned.md)")
    lang.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from nl2hltl2plan.io import check_output_file
    from nl2hltl2plan.language.learned import request_units, structure_train
    from nl2hltl2plan.language.learned.slot_model import user_model_path, user_path
    from nl2hltl2plan.language.learned.structure import user_structure_path
    from nl2hltl2plan.language.learned.train import train_and_report

    # the structure model first: the slot model's ranker reads with it
    jobs: list[tuple[str, Path, Callable[..., str]]] = [
        ("structure", args.structure_out or user_structure_path(), structure_train.train_and_report),
        ("slots", args.out or user_model_path(), partial(train_and_report, encoder=True) if args.encoder
         else train_and_report),
        # the request-unit classifier (a voice's frame against its request, h287)
        ("request", args.request_out or user_path(request_units.ARTIFACT), request_units.train_and_report),
    ]
    for name, path, job in jobs:
        if args.only not in (None, name):
            continue
        out = check_output_file(path, ("npz",), f"{name} model")
        print(job(out, seed=args.seed))
    return 0
