"""Rewrite the module paths that issue 26's moves changed, in any files (for merging branches that
still import the old paths).

    python scripts/follow_renames.py $(git ls-files '*.py' '*.md' '*.toml')

Dotted paths (`nl2hltl2plan.worlds.model`) and their file forms (`worlds/model.py`) are rewritten,
longest first; names that moved out of a module are listed in NAMES and must be re-imported by hand
(the script prints each file that imports one of them from its old module). Delete this script once
every branch is merged.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

MODULES = {  # old -> new, under nl2hltl2plan
    "evaluation.runner": "suites.runner",
    "evaluation.ray_engine": "suites.ray_engine",
    "evaluation.rows": "suites.rows",
    "evaluation.report_md": "suites.alfred.alfred_report",
    "evaluation.report": "suites.summaries",
    "evaluation.alfred": "suites.alfred.alfred_bench",
    "evaluation.language_bench": "suites.alfred.alfred_language",
    "evaluation.smartllm_script": "suites.smartllm.smartllm_script",
    "evaluation.smartllm": "suites.smartllm.smartllm_bench",
    "evaluation.tabletop": "suites.tabletop.tabletop_bench",
    "evaluation.baselines": "suites.tabletop.tabletop_baselines",
    "evaluation.handover_llm": "suites.handover.handover_llm",
    "evaluation.handover": "suites.handover.handover_bench",
    "evaluation": "suites",
    "worlds.benchmark": "suites.alfred.ground_truth",
    "worlds.smartllm": "suites.smartllm.smartllm_tasks",
    "worlds.gantt": "present.gantt",
    "worlds.pictures": "present.pictures",
    "worlds.model": "worlds.world",
    "worlds.alfred": "worlds.floor_plans",
    "worlds.tabletop": "worlds.tabletop_world",
    "worlds.handover": "worlds.handover_world",
    "outputs": "present.outputs",
    "language.render": "present.htt_pictures",
    "language.measure": "suites.alfred.conversion",
    "language.learned.measure": "suites.alfred.learned_report",
    "language.learned.validate": "suites.alfred.learned_validation",
    "language.learned.structure_validate": "suites.alfred.structure_validation",
    "language.learned.rank_check": "suites.alfred.rank_check",
    "language.learned.model": "language.learned.slot_model",
    "language.learned.relations": "language.learned.span_order",
    "language.handover": "language.handover_reading",
    "language.tasks": "language.task_specs",
    "language.offline.grammar": "language.grammar.word_tables",
    "language.offline.tasks": "language.grammar.draft_tasks",
    "language.offline.relations": "language.grammar.order_relations",
    "language.offline": "language.grammar",
    "language.options": "language.llm.llm_options",
    "language.llm.settings": "config.llm_settings",
}
NAMES = {  # names that left a module which still exists: (old module, new module)
    ("worlds.tasks", "domain.task_kinds"): (
        "Kind KINDS SLOTS State STATE_WORDS STATE_FLAG APPLIANCE TREATMENT MAX_COUNT slots_of Goal"
    ),
    ("worlds.tasks", "logic.action_sequences"): "sequences_formula formula_sequences",
    ("worlds.handover_world", "present.handover_pictures"): "draw_handover ARM_COLOURS BLOCK_COLOURS",
    ("worlds.tabletop_world", "present.tabletop_pictures"): "draw_trajectories",
    ("suites.alfred.learned_report", "suites.alfred.conversion"): "learned_generator",
    ("argtypes", "config"): "MAX_SECONDS",
}
_OLD = sorted(MODULES, key=len, reverse=True)
_DOTTED = re.compile(r"\bnl2hltl2plan\.(" + "|".join(re.escape(k) for k in _OLD) + r")\b")
_AS_FILES = "|".join(re.escape(k.replace(".", "/")) for k in _OLD)
_FILES = re.compile(r"(?<![\w/])(" + _AS_FILES + r")(?=\.py\b|/)")


def rewrite(text: str) -> str:
    text = _DOTTED.sub(lambda m: "nl2hltl2plan." + MODULES[m.group(1)], text)
    return _FILES.sub(lambda m: MODULES[m.group(1).replace("/", ".")].replace(".", "/"), text)


def moved_names(text: str) -> list[str]:
    found = []
    for (old, new), names in NAMES.items():
        for imp in re.finditer(rf"from nl2hltl2plan\.{re.escape(old)} import \(?([\w\s,]+)\)?", text):
            hit = set(re.findall(r"\w+", imp.group(1))) & set(names.split())
            if hit:
                found.append(f"{', '.join(sorted(hit))}: now in nl2hltl2plan.{new}")
    return found


def main(paths: list[str]) -> int:
    for name in paths:
        path = Path(name)
        text = path.read_text()
        new = rewrite(text)
        if new != text:
            path.write_text(new)
            print(f"rewrote {path}")
        for note in moved_names(new):
            print(f"{path}: {note}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
