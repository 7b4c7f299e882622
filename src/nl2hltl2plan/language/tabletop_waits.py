"""A plate that waits (issue 28): "Don't touch the blue plate until the green apple and the orange are on
the yellow plate; then put the carrot and the red apple on the blue plate", "Nothing goes on the blue plate
until ...", "Put the carrot on the blue plate, but wait until the orange is on the yellow plate",
"The yellow plate gets the green apple and the orange before the blue plate gets anything;
then ...".

Such a clause says that every placement on one plate waits for what the rest of its sentence states. In
the tabletop world, where the one action is placing an object on a plate, that is an order between
placements, and it is read as one: "once STATE, REST" (the waiting form) or "FIRST. then REST" (the
"before ... anything" form), which the readers already order. It is read so only where that is all it
says: the clause opens the text (or closes its first part), the placements it waits for name no object on
the waiting plate, and every placement after it is on the waiting plate (so that ordering them after it
orders nothing the clause does not); otherwise the text is left as it is, and its negation or "anything"
is refused as before.

>>> kinds = {"blue plate": True, "yellow plate": True, "carrot": False, "orange": False}
>>> plate_waits_read("Leave the blue plate alone until the orange is on the yellow plate, then put the "
...                  "carrot on the blue plate.", kinds)
'once the orange is on the yellow plate, put the carrot on the blue plate.'
"""

from __future__ import annotations

import re

# the waiting plate and what it waits for: "don't touch / leave alone / nothing goes on PLATE until ..."
_NOT = r"(?:don't|dont|do\s+not|never)"
_WAIT_OPENER = (
    rf"(?:{_NOT}\s+(?:touch|use|fill|load|start(?:\s+on)?|(?:put|place|set)\s+anything\s+(?:on|in|onto|into))"
    r"|leave|keep"
    r"|hold\s+off\s+on|nothing\s+(?:goes|should\s+go|gets\s+put|is\s+put|lands)\s+(?:on|in|onto|into))"
)
_WAIT = re.compile(
    rf"^\W*(?:please\s+|kindly\s+)?{_WAIT_OPENER}\s+(?:the\s+)?(?P<plate>[a-z]+\s+plate)(?:\s+(?:alone|empty|untouched|as\s+it\s+is))?"
    r"\s+until\s+(?P<state>[^,.;:!?]+?)\s*(?:[,.;:!?]+\s*|\s+(?=then\b))(?:and\s+)?(?:then\b|after\s+that\b)?"
    r"\s*,?\s*(?P<rest>.*)$",
    re.IGNORECASE | re.DOTALL,
)
# "FIRST before PLATE gets anything; (then) REST" / "FIRST before anything goes on PLATE; REST"
_BEFORE_ANYTHING = re.compile(
    r"^(?P<first>[^.;:!?]+?)\s+before\s+(?:(?:the\s+)?(?P<plate>[a-z]+\s+plate)\s+(?:gets|receives|takes)\s+"
    r"anything|anything\s+(?:goes|is\s+put|gets\s+put|lands)\s+(?:on|in|onto|into)\s+(?:the\s+)?"
    r"(?P<plate2>[a-z]+\s+plate))\s*(?:[,.;:!?]+\s*)(?:and\s+)?(?:then\b|after\s+that\b)?\s*,?\s*(?P<rest>.*)$",
    re.IGNORECASE | re.DOTALL,
)
# "REST, but wait / hold off until STATE.": the placements said first wait for the state said after them
_WAIT_AFTER = re.compile(
    r"^(?P<rest>[^.;:!?]+?)\s*(?:,\s*but|;\s*but|,|;|\s+but)\s+(?:please\s+)?(?:wait|hold\s+off|hold\s+on)"
    r"\s+until\s+(?P<state>[^,.;:!?]+?)\s*[.!]?\s*$",
    re.IGNORECASE | re.DOTALL,
)
_PLATE = re.compile(r"\b[a-z]+\s+plate\b", re.IGNORECASE)
# a later stage said as a wait, at a sentence's start (h296): "Round two doesn't start till STATE: then REST",
# "The second load waits till STATE; then REST" (the stage's own words name nothing of the scene), "Nobody
# touches the carrot or the red apple till STATE; then REST" (REST places exactly the things not touched)
_UNTIL = (
    r"\s+(?:until|till|til)\s+(?P<state>[^,.;:!?]+?)\s*[,.;:!?]+\s*(?:and\s+)?(?:then\b|after\s+that\b)?\s*,?\s*"
)
_NOT_YET = r"(?:doesn't|does\s+not|don't|do\s+not|won't|can't|cannot)\s+(?:start|begin|happen)|waits?"
_STAGE_WAITS = re.compile(
    rf"(?P<start>^|(?<=[.;!?])\s+)(?:(?P<stage>(?:the\s+)?[a-z]+(?:\s+[a-z]+){{0,2}}?)\s+(?:{_NOT_YET})|"
    r"(?:nobody|no\s+one|don't|do\s+not|never)\s+(?:touch(?:es)?|moves?|picks?\s+up|handles?|lifts?)\s+"
    rf"(?P<things>[^,.;:!?]+?)){_UNTIL}(?P<rest>[^.;!?]+)",
    re.IGNORECASE,
)


def plate_waits_read(text: str, kinds: dict[str, bool]) -> str:
    """`text` with a plate that waits read as an order (see the module docstring): "once STATE, REST" (also
    for "REST, but wait until STATE") or "FIRST. then REST"; the text as it is where the clause says more
    than that order. `kinds`: each object or plate name (in words) -> is it a plate."""
    wait = _WAIT.match(text)
    if wait is not None:
        plate = _plate(wait["plate"], kinds)
        if plate and _only_on(wait["rest"], plate, kinds) and plate not in _plates(wait["state"], kinds):
            return f"once {wait['state']}, {wait['rest']}"
    after = _WAIT_AFTER.match(text)
    if after is not None:
        plates, waited_for = _plates(after["rest"], kinds), _plates(after["state"], kinds)
        named_twice = _names(after["rest"], kinds) & _names(after["state"], kinds)
        if plates and waited_for and not named_twice:
            return f"once {after['state']}, {after['rest']}."
    text = _STAGE_WAITS.sub(lambda m: _stage_wait(m, kinds), text)
    before = _BEFORE_ANYTHING.match(text)
    if before is not None:
        plate = _plate(before["plate"] or before["plate2"], kinds)
        if plate and _only_on(before["rest"], plate, kinds) and plate not in _plates(before["first"], kinds):
            return f"{before['first']}. then {before['rest']}"
    return text


def _plate(words: str, kinds: dict[str, bool]) -> str | None:
    name = " ".join(words.lower().split())
    return name if kinds.get(name) else None


def _plates(text: str, kinds: dict[str, bool]) -> set[str]:
    return {n for m in _PLATE.finditer(text) if (n := " ".join(m[0].lower().split())) in kinds}


def _names(text: str, kinds: dict[str, bool]) -> set[str]:
    """The objects and plates `text` names."""
    return {n for n in kinds if re.search(rf"\b{re.escape(n)}\b", text, re.IGNORECASE)}


def _only_on(rest: str, plate: str, kinds: dict[str, bool]) -> bool:
    """Does `rest` name the waiting plate and no other plate (every placement it makes is on it)?"""
    return _plates(rest, kinds) == {plate}


def _stage_wait(wait: re.Match[str], kinds: dict[str, bool]) -> str:
    """ "once STATE, REST" for a later stage said as a wait (`_STAGE_WAITS`), where that is all it says: the
    stage's words name nothing, or the things not touched are the ones REST places; and REST places things."""
    said = _names(wait["rest"], kinds)
    waited = _names(wait["state"], kinds) or _REFERS.search(wait["state"])
    if not any(not kinds[n] for n in said) or not waited:
        return wait[0]
    if wait["stage"] is not None and _names(wait["stage"], kinds):
        return wait[0]
    if wait["things"] is not None and _names(wait["things"], kinds) != {n for n in said if not kinds[n]}:
        return wait[0]
    return f"{wait['start']}once {wait['state']}, {wait['rest']}"


# what the waited state may say in place of the things' names: "both of them are in", "those two are in"
_REFERS = re.compile(r"\b(?:both|them|those|these|they|all)\b", re.IGNORECASE)
