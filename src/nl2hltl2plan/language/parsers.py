"""The backends that need no LLM, behind one interface: each reads an instruction into base tasks,
their order and groups and the ambiguous words it ranked (an `OfflineParse`). `translate` looks the
backend up in `PARSERS` instead of switching on its name; each is imported on first use, so that the
CLI starts without the parsers.

- `offline` (the default; `learned` is its former name): the grammar parser with the learned
  structure and slot models (`language.learned`);
- `grammar`: the grammar parser alone (`language.grammar`).

>>> sorted(PARSERS)
['grammar', 'learned', 'offline']
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    from nl2hltl2plan.language.grammar import OfflineParse
    from nl2hltl2plan.language.grounding import AffordanceLookup


class Parser(Protocol):
    def __call__(
        self, instruction: str, types: set[str] | None, scene: str, *, strict: bool,
        affordances: AffordanceLookup | None,
    ) -> OfflineParse: ...


def _lazy(module: str) -> Parser:
    """The `parse_instruction` of `module`, imported when first called."""

    def parse(
        instruction: str, types: set[str] | None, scene: str, *, strict: bool,
        affordances: AffordanceLookup | None,
    ) -> OfflineParse:
        reader = importlib.import_module(module).parse_instruction
        parsed: OfflineParse = reader(instruction, types, scene, strict=strict, affordances=affordances)
        return parsed

    return parse


_OFFLINE = _lazy("nl2hltl2plan.language.learned")
PARSERS: dict[str, Parser] = {
    "offline": _OFFLINE,
    "learned": _OFFLINE,
    "grammar": _lazy("nl2hltl2plan.language.grammar"),
}
