"""What the structure model alone reads where the shipped reading is partial or refused (issue 28).

    python scripts/structure_alone.py [--sets default,styles,trust | NAME,...] [--n 400] [--rows DIR]
        [--show] [--out FILE]

For every row with ground truth of the sets (`default`: language_failures' default sets; `styles`: every
committed tests/language/data/styles/*.txt; `trust`: tests/language/data/trust/*.jsonl; or set names), the
shipped reading's class (`language_failures.classify`, the household reader as `plan --world SCENE`
reads) and, where that reading is partial or refused, the structure model's reading alone
(`inference.structure_reading` of the text the household reader passed on, each span read by the
grammar + slot model) judged as `structure_validation.converts` (complete, every word used, the strict
match): right, wrong, or incomplete (no reading). The arbitration (`structured.decide`) is asked as the
shipped path asks it, so a right model reading that the policy did not take says why: the grammar's
reading was complete (the household path refused it for another reason: a bare plural, the world's
counts), below the rescue threshold, the order words, or the grammar's "not certain" reference. Rows
are grouped by a class of what the grammar left unread (`partial_class`: the unread words' shape), the
evidence for letting the model complete or rescue that class (docs/learned.md, "structure model").
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from language_failures import classify, rows  # noqa: E402

from nl2hltl2plan.language.grammar.order_relations import ORDER_LEFT_OPEN  # noqa: E402
from nl2hltl2plan.language.grammar.references import NOT_CERTAIN  # noqa: E402
from nl2hltl2plan.language.grounding import scene_types  # noqa: E402
from nl2hltl2plan.language.learned.inference import (  # noqa: E402
    DEFAULT_POLICY,
    ParseContext,
    grammar_complete,
    grammar_first_reading,
    load_model,
    structure_reading,
)
from nl2hltl2plan.language.learned.structure import load_structure  # noqa: E402
from nl2hltl2plan.language.learned.structured import decide, order_words_kept  # noqa: E402
from nl2hltl2plan.suites.alfred.structure_validation import converts  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
STYLES, TRUST = ROOT / "tests/language/data/styles", ROOT / "tests/language/data/trust"
DEFAULT_SETS = ("plain", "users", "faithful_unseen", "trainstyle_unseen", "heldout_unseen")
PARTIAL = ("refused, reading wrong", "unread clause, reading right", "accounting false refusal", "error")
# the shape of what the grammar left, first match wins (issue 28's voices)
CLASSES = (
    ("same as before", re.compile(r"\b(the same|likewise|same thing|same goes)\b", re.I)),
    ("more of it", re.compile(r"\b(more|another|other one|others|rest of)\b", re.I)),
    ("numbered list", re.compile(r"(^|[\s'(])(\d+[.)]|step \w+|#\d)", re.I)),
    ("verbless item", re.compile(r"\b(goes|go|belongs?|should be)\b", re.I)),
    ("landmark", re.compile(r"\b(next to|by the|near|beside|closest to|nearest)\b", re.I)),
    ("reference", re.compile(r"\b(it|them|that|those|this|there)\b", re.I)),
    ("order words", re.compile(r"\(order\)|\border\b|\b(before|after|once|until|first|then)\b", re.I)),
)


def partial_class(why: str) -> str:
    """A class of what the shipped reading left unread, from its `why` (the unread words first)."""
    unread = why.split(" || ")[0].replace("rephrase it or use an LLM backend", "")
    return next((name for name, pat in CLASSES if pat.search(unread)), "other")


def set_rows(name: str, n: int) -> list[dict[str, Any]]:
    """A set's rows with ground truth that asks for tasks (a row whose truth is a refusal is left out)."""
    path = TRUST / f"{name}.jsonl"
    if not path.exists():
        return [r for r in rows(name, n) if r["tasks"] and r.get("feasible", True)]
    got = [json.loads(x) for x in path.read_text().splitlines() if x.strip()]
    return [r for r in got if r["tasks"] and r.get("feasible", True)]


def model_alone(row: dict[str, Any], text: str) -> dict[str, Any]:
    """The structure model's reading of `text` alone, judged against the row, and the arbitration's choice."""
    ctx = ParseContext(scene_types(row["scene"]), row["scene"], None, DEFAULT_POLICY, load_model())
    try:
        s = structure_reading(text, ctx, load_structure())
        first = grammar_first_reading(text, ctx)
    except Exception as exc:  # noqa: BLE001 - a refusal of a span: no model reading
        return {"model": "incomplete", "decision": "grammar", "why": type(exc).__name__, "confidence": None}
    if s is None:
        return {"model": "incomplete", "decision": "grammar", "why": "", "confidence": None}
    uncertain = any(NOT_CERTAIN in u or ORDER_LEFT_OPEN in u for u in first.unparsed)
    rule = DEFAULT_POLICY.structure
    assert rule is not None
    grammar = (first.tasks, first.before, grammar_complete(first))
    choice = decide(grammar, (s[0].tasks, s[0].before, s[1]), rule, text, s[2], uncertain)
    blocked = (
        "" if choice == "model" else "grammar complete" if grammar[2] else "not certain" if uncertain
        else "order words" if not order_words_kept(text, s[0].tasks, s[0].before) else "confidence"
    )
    right = converts(s[0].model_copy(deep=True), {**row, "instruction": text})
    return {"model": "right" if right else "wrong", "decision": choice, "why": blocked, "confidence": s[1]}


def main() -> int:
    ap = argparse.ArgumentParser(prog="python scripts/structure_alone.py")
    ap.add_argument("--sets", default="default,styles,trust")
    ap.add_argument("--n", type=int, default=400)
    ap.add_argument("--show", action="store_true", help="print every partial row and the model's verdict")
    ap.add_argument("--out", type=Path, default=None, help="write each partial row's verdict (JSON lines)")
    args = ap.parse_args()
    names: list[str] = []
    for part in args.sets.split(","):
        names += {
            "default": list(DEFAULT_SETS),
            "styles": sorted(p.stem for p in STYLES.glob("*.txt")),
            "trust": sorted(p.stem for p in TRUST.glob("*.jsonl")),
        }.get(part, [part])
    per_class: dict[str, Counter[str]] = defaultdict(Counter)
    out = []
    print("| set | rows | shipped converts | partial or refused | model alone right | wrong | incomplete |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for name in dict.fromkeys(names):  # a set named twice ("plain": a default set and a trust set) once
        counts: Counter[str] = Counter()
        for row in set_rows(name, args.n):
            cls, why, read = classify(row)
            counts["rows"] += 1
            counts["ok"] += cls == "ok"
            if cls not in PARTIAL:
                continue
            v = model_alone(row, read or row["instruction"])
            counts["partial"] += 1
            counts[v["model"]] += 1
            group = partial_class(why)
            per_class[group][v["model"]] += 1
            if v["model"] == "right" and v["decision"] != "model":
                per_class[group]["right, not taken: " + v["why"]] += 1
            out.append({"set": name, "instruction": row["instruction"], "class": group, **v, "shipped": why})
            if args.show:
                conf = f"{v['confidence']:.2f}" if v["confidence"] is not None else "-"
                said = f"{v['model']} ({conf}, {v['decision']} {v['why']}) [{group}]"
                print(f"  {said} {row['instruction'][:140]!r}", file=sys.stderr)
        cells = " | ".join(str(counts[k]) for k in ("ok", "partial", "right", "wrong", "incomplete"))
        print(f"| {name} | {counts['rows']} | {cells} |")
    print("\n| unread words | rows | model right | wrong | incomplete | right, not taken (why) |")
    print("| --- | --- | --- | --- | --- | --- |")
    verdicts = ("right", "wrong", "incomplete")
    for group, c in sorted(per_class.items(), key=lambda kv: -sum(kv[1][k] for k in verdicts)):
        total = sum(c[k] for k in verdicts)
        held = ", ".join(f"{k[18:]} {n}" for k, n in sorted(c.items()) if k.startswith("right, not"))
        print(f"| {group} | {total} | {c['right']} | {c['wrong']} | {c['incomplete']} | {held} |")
    if args.out:
        args.out.write_text("".join(json.dumps(o) + "\n" for o in out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
