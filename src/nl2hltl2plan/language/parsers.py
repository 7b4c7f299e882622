"""The backends that need no LLM, behind one interface: each reads an instruction into base tasks,
their order and groups (an `OfflineParse`) and the ambiguous words it ranked. `translate` looks the
backend up in `PARSERS` instead of switching on its name.

- `offline` (the default; `learned` is its former name): the grammar parser with the learned
  structure and slot models (`language.learned`);
- `grammar`: the grammar parser alone (`language.offline`).

>>> sorted(PARSERS)
['grammar', 'learned', 'offline']
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    from nl2hltl2plan.language.grounding import AffordanceLookup
    from nl2hltl2plan.language.offline import OfflineParse
    from nl2hltl2plan.language.result import Ambiguity


class Parser(Protocol):
    def __call__(
        self, instruction: str, types: set[str] | None, scene: str, *, strict: bool,
        affordances: AffordanceLookup | None,
    ) -> tuple[OfflineParse, list[Ambiguity]]: ...


def grammar_parser(
    instruction: str,
    types: set[str] | None,
    scene: str,
    *,
    strict: bool,
    affordances: AffordanceLookup | None,
) -> tuple[OfflineParse, list[Ambiguity]]:
    """The grammar alone: no ranking, so no ambiguities are reported."""
    from nl2hltl2plan.language import offline

    return offline.parse_instruction(instruction, types, scene, strict=strict, affordances=affordances), []


def offline_parser(
    instruction: str,
    types: set[str] | None,
    scene: str,
    *,
    strict: bool,
    affordances: AffordanceLookup | None,
) -> tuple[OfflineParse, list[Ambiguity]]:
    """The grammar with the learned structure and slot models, which rank ambiguous words."""
    from nl2hltl2plan.language import learned

    parse = learned.parse_instruction(instruction, types, scene, strict=strict, affordances=affordances)
    return parse, parse.ambiguities


PARSERS: dict[str, Parser] = {"offline": offline_parser, "learned": offline_parser, "grammar": grammar_parser}
