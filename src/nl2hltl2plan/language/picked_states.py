"""A state said of a thing to pick which one is meant (issue 23): "put the empty mug on the dresser", "the
mug that's empty", "the open drawer". The world's things have such states (open, filled), but no reading
checks or makes them true, and a base task's atoms name types: where the floor plan holds several things
of the type, the spec (any mug does) cannot keep to the one meant, so the word is unread and the
instruction refused, as a position that picks one is (`unsupported_steps.one_of_several`). Where it holds
one, the word picks nothing and is read past ("the empty soap bottle" of a bathroom with one). "An empty
box" asks for any box (ALFRED's wording) and is read past; "the clean / hot / cold / wet mug" is a treatment
a reading makes true, and "the dirty mug" what cleaning undoes (`referent_words.txt`'s `unmet_state`).
"""

from __future__ import annotations

import re
from collections.abc import Mapping

from nl2hltl2plan.language.content_words import Unread, word_categories
from nl2hltl2plan.language.grounding import Mention, lexicon, tokens
from nl2hltl2plan.language.parse_usage import ParseUsage
from nl2hltl2plan.language.unknown_words import modifiers_before

_WHICH = word_categories("referent_words.txt")
_STATES, _DEFINITE = _WHICH["unmet_state"], _WHICH["definite"] | {"my", "your", "our"}
REASON = "a state the spec does not check picks which one is meant: any one of its type would do"
# a relative clause saying the thing's state: "the mug that's empty", "the drawer which is open"
_STATE_AFTER = re.compile(
    r"\s+(?:that|which)(?:\s*'s|\s+is|\s+are|\s+was|\s+were)?\s+(?:already\s+|still\s+)?(?P<state>[a-z]+)\b"
)


def picked_states(
    instruction: str, mentions: list[Mention], parse: ParseUsage, instances: Mapping[str, int] | None
) -> list[Unread]:
    """The state words before a name said definitely, or in a relative clause after a name, of a thing or
    place a task uses that the floor plan holds several of. Judged only where the scene is known."""
    if instances is None:
        return []
    used = {t for _, _, types in parse.slots() for t in types}
    toks = tokens(instruction)
    out: list[Unread] = []
    for m in mentions:
        if not any(instances.get(t, 0) > 1 for t in set(m.entry.types) & used):
            continue
        said = _STATE_AFTER.match(instruction.lower(), m.char_end)  # "the mug that's empty"
        words = [said["state"]] if said and said["state"] in _STATES else []
        before = modifiers_before(instruction, toks, m.start)
        opener = m.start - 1 - len(before)
        if before and opener >= 0 and toks[opener][0] in _DEFINITE:
            words += [w for w in before if w in _STATES and not _named_so(w, m)]
        out += [Unread(w, "object", REASON) for w in dict.fromkeys(words) if w not in {u.words for u in out}]
    return out


def _named_so(state: str, m: Mention) -> bool:
    """Does the lexicon name the type so, the state with the mention's last word ("empty roll": ALFRED's
    toilet paper is an empty roll)? Then the state says what every one of the type looks like, and picks
    none: "the empty toilet paper roll"."""
    named = lexicon().get((state, m.surface.lower().split()[-1]))
    return named is not None and set(named[0].types) == set(m.entry.types)
