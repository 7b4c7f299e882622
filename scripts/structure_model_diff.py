"""Where a retrained structure model reads differently from the shipped one, and what that does end to end.

    python scripts/structure_model_diff.py diff NEW.npz [--sets trust+styles,framed_unseen,...] [--out FILE]
    XDG_CACHE_HOME=DIR python scripts/structure_model_diff.py read FILE

`diff` tags every instruction of the sets with both CRFs (spans' words, relations, targets; milliseconds an
instruction) and writes the lines whose readings differ (JSON lines: set, id, text); `trust+styles` is
every committed trust and style set. `read` reads those lines through the shipped path
(`trust_sets.read_line`, the household reader) with whichever model the environment makes current
(`XDG_CACHE_HOME` holding `nl2hltl2plan/models/structure_model.npz`, or none: the packaged one): run it
once per model and compare the outcomes. A line whose tags agree cannot change end to end through the
structure model, so the full reading runs only where they differ (h272: a full measurement of every set
takes longer than a retrain on the shared box). The CRF is asked about the text as written; the
household reader's rewriting (a dropped greeting) is not applied first, so a line whose rewritten text
alone tags differently is missed.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from trust_sets import STYLES, TRUST, load, read_line  # noqa: E402

from nl2hltl2plan.language.grammar.sentences import without_connective_to  # noqa: E402
from nl2hltl2plan.language.learned.slot_model import packaged_path  # noqa: E402
from nl2hltl2plan.language.learned.structure import ARTIFACT, StructureModel  # noqa: E402
from nl2hltl2plan.suites.alfred.structure_validation import rows_of_set  # noqa: E402

EXCLUDED = ("h269", "h270", "h271")  # the session's held-out sets, scored by the lead only


def committed_sets() -> list[str]:
    trust = sorted(p.stem for p in TRUST.glob("*.jsonl"))
    styles = sorted(p.stem for p in STYLES.glob("*.txt") if not any(x in p.stem for x in EXCLUDED))
    return trust + styles


def _reading(model: StructureModel, text: str) -> list[tuple[str, str, int | None]]:
    said = without_connective_to(text)
    return [(said[s.start : s.end], s.relation, s.target) for s in model.read(said).spans]


def _texts(name: str, n: int) -> list[tuple[str, str]]:
    if name in committed_sets():
        return [(gt.id, gt.instruction) for gt in load(name)]
    return [(str(r["id"]), str(r["instruction"])) for r in rows_of_set(name, n)]


def diff(new: Path, names: list[str], n: int, out: Path | None) -> None:
    shipped, model = StructureModel.load(packaged_path(ARTIFACT)), StructureModel.load(new)
    rows = []
    print("| set | lines | CRF reading differs |\n| --- | --- | --- |")
    for name in names:
        texts = _texts(name, n)
        changed = [(i, t) for i, t in texts if _reading(shipped, t) != _reading(model, t)]
        print(f"| {name} | {len(texts)} | {len(changed)} |")
        rows += [{"set": name, "id": i, "text": t} for i, t in changed]
    if out:
        out.write_text("".join(json.dumps(r) + "\n" for r in rows))


def read(path: Path) -> None:
    rows = [json.loads(line) for line in path.read_text().splitlines() if line]
    by_set: dict[str, set[str]] = {}
    for r in rows:
        by_set.setdefault(r["set"], set()).add(r["id"])
    for name, ids in by_set.items():
        if name not in committed_sets():
            continue  # a generator set: `language_failures.py --sets NAME` reads it whole
        for gt in load(name):
            if gt.id in ids:
                what, why, _ = read_line(gt)
                print(json.dumps({"set": name, "id": gt.id, "outcome": what, "why": why[:160]}))


def main() -> int:
    ap = argparse.ArgumentParser(prog="python scripts/structure_model_diff.py")
    ap.add_argument("what", choices=["diff", "read"])
    ap.add_argument("path", type=Path, help="diff: the new model file; read: the lines `diff` wrote")
    ap.add_argument("--sets", default="trust+styles")
    ap.add_argument("--n", type=int, default=400)
    ap.add_argument("--out", type=Path, default=None)
    args = ap.parse_args()
    if args.what == "read":
        read(args.path)
        return 0
    names = [x for s in args.sets.split(",") for x in (committed_sets() if s == "trust+styles" else [s])]
    diff(args.path, names, args.n, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
