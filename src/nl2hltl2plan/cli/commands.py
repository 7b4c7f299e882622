"""The sub-commands and their one-line help: the top-level `--help` lists them without importing any
command's module (each pulls in the pipeline, scipy and more), so the CLI starts fast."""

from __future__ import annotations

# Order here is the order in `--help`; each name has a module `cli/cmd_<name>.py` with `register`.
COMMANDS: dict[str, str] = {
    "spec": "build the hierarchical sc-LTL spec of an HTT (Algorithm 1)",
    "check": "validate a hierarchical sc-LTL spec file (Definition 2.1)",
    "show": "draw an HTT or a hierarchical spec as a tree picture",
    "world": "summarise and draw a world: demo, FloorPlanN, or a benchmark instance id",
    "plan": "instruction -> HTT -> hierarchical LTL -> checked multi-robot plan",
    "bench": "benchmarks: alfred (Table I) and the other suites",
    "serve": "the local web app: instruction -> HTT, spec, animated plan and Gantt chart",
    "train": "train learned components (language)",
}
