"""Two sentences that say one task: a treatment, then where the treated thing goes.

"Heat the egg in the microwave. Then put it in the fridge." and "... heat it up in the microwave; when it's
warm, put it in the fridge." are one heat-and-place task, as the same words joined by a comma are; an LLM
that rewrites ALFRED's step-by-step annotations into one paragraph (the paper's test set, issue 28) splits
them so. The rules read each sentence on its own, and "it" at the start of a sentence names nothing. The
join is made only where the first sentence treats a thing and places nothing, and the second places "it"
(after "then" or "when it's warm", the treatment's end, or nothing): the "it" can only be the treated thing.
`sentences.normalize` applies `joined_treatments`.

A thing examined or treated in one clause and filled in the next ("Examine the mug by the light of the
lamp, then put a pen in it and move it to the desk") is the container of the next clause's task: both
"it"s name the mug, as in "take the mug, put a pen in it and move it to the desk" (`holder_named`).

"Put the phone in the box. Then put the box on the sofa." is one place-in-container task, as the same words
joined by a comma are (ANNOTATION_GUIDE.md: a thing put in a movable container and the container moved): the
second sentence moves, by "the" or "that", the container the first one ends with (`container_moved_on`); a
sentence between them, or a container said to be another ("another box"), keeps them apart.

"Put the plunger in the cabinet. Put the soap bottle in the cabinet too, both before you put the towel away":
"too" adds the second sentence's one task to the first's, and "both" sums up the two, as "A and B, both
before C" does (`both_of_two_sentences`); with no "too" ("A. B, both before C") "both" has nothing of its
own sentence to sum up and stays unread.
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grounding import LAMPS, MOVABLE_RECEPTACLES, find_mentions

_TREATMENTS = frozenset({"clean", "heat", "cool"})
_PLACING = frozenset({"place", "trash"})
_DONE_STATE = r"(?:warm|hot|heated|cooked|cold|chilled|cool|cooled|clean|washed|rinsed|done|ready)"
# the sentence that follows: an order word or the treatment's end, then a placing of "it"
_THEN_PLACE_IT = re.compile(
    rf"^\s*(?:(?:(?:and\s+)?then|after\s+that|afterwards|next|(?:when|once)\s+it(?:'s|\s+is)\s+{_DONE_STATE})"
    r"\s*,?\s+)?(?=(?:put|place|set|leave|move|bring|take|drop|throw|toss|store|lay|return)\s+it\b)",
    re.I,
)
_NOT_A_STEP = frozenset({"not", "don't", "never", "without", "if", "unless", "no"})
_SENTENCE_END = re.compile(r"\s*[.;]\s+")


def _treats_only(sentence: str) -> bool:
    """The sentence has a treating verb and no placing one ("grab the egg and heat it in the microwave"),
    and no negation or condition ("don't heat the egg", "if it is cold, heat it": no step to go on from)."""
    words = re.findall(r"[a-z']+", sentence.lower())
    classes = {G.VERBS[w][0] for w in words if w in G.VERBS}
    return bool(classes & _TREATMENTS) and not classes & _PLACING and not _NOT_A_STEP & set(words)


def joined_treatments(text: str) -> str:
    """Each "S1. Then put it ..." where S1 only treats a thing, written as "S1, then put it ..."."""
    parts = _SENTENCE_END.split(text)
    if len(parts) < 2:
        return text
    out = [parts[0]]
    ends = _SENTENCE_END.findall(text)
    for end, part in zip(ends, parts[1:], strict=True):
        m = _THEN_PLACE_IT.match(part)
        if m and _treats_only(out[-1]):
            rest = part[m.end() :]
            out[-1] += ", then " + rest[:1].lower() + rest[1:]
        else:
            out[-1] += end
            out.append(part)
    return "".join(out)


# "put a pen in it", "put a pen in it and move it to the desk": a thing put into "it", and "it" moved on
# ("place a box with keys in it": the box holds the keys, no "it" before)
_PUT_IN_IT = re.compile(
    r"\b(?P<put>(?:put|place|drop|stick|set)\s+(?:a|an|the)\s+(?:(?!with\b)[a-z]+\s+){0,2}?[a-z]+\s+"
    r"(?:in|into|inside)\s+)it\b"
    r"(?P<more>\s+and\s+(?:then\s+)?(?:put|place|move|set|take|bring|carry|leave)\s+)?(?(more)it\b)",
    re.I,
)
_VERB_DET = re.compile(r"\b([a-z]+(?:\s+at)?)\s+(?:the|a|an|that|this)\s+(?:[a-z]+\s+){0,2}$", re.I)


def holder_named(text: str) -> str:
    """ "Examine the mug by the light of the lamp, then put a pen in it and move it to the desk": each "it"
    written as the mug, where the last thing named before it (lamps aside) is one movable receptacle that is
    examined ("the apple in the bowl" is no such thing; "wash the plate, then put a fork in it" asks a
    cleaned container, which no base task does, and stays as written for the rules to refuse)."""

    def one(m: re.Match[str]) -> str:
        named = [x for x in find_mentions(text[: m.start()]) if not set(x.entry.types) <= LAMPS]
        if not named or named[-1].plural or named[-1].entry.canonical not in MOVABLE_RECEPTACLES:
            return m[0]
        verb = _VERB_DET.search(text[: named[-1].char_start])
        if verb is None or G.VERBS.get(verb[1].lower().split()[0], ("",))[0] != "examine":
            return m[0]
        holder = f"the {named[-1].surface}"
        return m["put"] + holder + (m["more"] + holder if m["more"] else "")

    return _PUT_IN_IT.sub(one, text)


# "S1. S2 too / as well / also S2, both before|after ...": S1 and S2 one clause each ("and" in either is a
# list of its own, which "both" would not sum up with the other sentence)
_BOTH_TOO = re.compile(
    r"(?P<first>(?:^|(?<=[.;!?]\s))[^.;!?]+?)[.;!]\s+(?P<second>[^.;!?]*?\b(?:too|as\s+well|also)\b[^.;!?,]*?)"
    r",\s*both(?:\s+of\s+(?:them|these|those))?\s+(?=(?:before|after|once|until|when)\b)",
    re.I,
)


def both_of_two_sentences(text: str) -> str:
    """Each "S1. S2 too, both before Y" written as "S1, and S2 too before Y" (both tasks before Y)."""

    def one(m: re.Match[str]) -> str:
        if any(re.search(r"\band\b", m[k], re.I) for k in ("first", "second")):
            return m[0]
        return f"{m['first']}, and {m['second'][:1].lower()}{m['second'][1:]} "

    return _BOTH_TOO.sub(one, text)


# the first sentence ends with a thing put in a movable container ("put the phone in the cardboard box"); the
# next one opens (after an order word) with a verb that moves "the" / "that" container
_INTO_END = re.compile(r"\b(?:in|into|inside|on|onto)\s+(?:the|a|an|one)\s+(?:[a-z]+\s+){0,2}?$", re.I)
_MOVE_THE = re.compile(
    r"^\s*(?:(?:(?:and\s+)?then|after\s+that|afterwards|next|once\s+(?:that's|that\s+is)\s+done)\s*,?\s+)?"
    r"(?P<verb>(?:put|place|set|move|carry|take|bring|leave|stick|pop)\s+(?:the|that|this)\s+)(?=[a-z])",
    re.I,
)


def container_moved_on(text: str) -> str:
    """Each "S1. (Then) put the C ..." where S1 ends by putting a thing in a movable container C, written as
    "S1, then put the C ..." (one task, see the module's note)."""
    parts = _SENTENCE_END.split(text)
    ends = _SENTENCE_END.findall(text)
    if len(parts) < 2:
        return text
    out = [parts[0]]
    for end, part in zip(ends, parts[1:], strict=True):
        held = _held_at_end(out[-1])
        m = _MOVE_THE.match(part)
        moved = find_mentions(part[m.end() :]) if m else []
        if held is not None and m and moved and moved[0].char_start == 0 and moved[0].entry.canonical == held:
            out[-1] += ", then " + part[m.start("verb") :]
        else:
            out[-1] += end
            out.append(part)
    return "".join(out)


def _held_at_end(sentence: str) -> str | None:
    """The movable container a sentence ends by putting a thing in ("... in the cardboard box"), or None."""
    named = find_mentions(sentence)
    if not named or named[-1].char_end != len(sentence.rstrip()) or named[-1].plural:
        return None
    last = named[-1]
    if last.entry.canonical not in MOVABLE_RECEPTACLES or not _INTO_END.search(sentence[: last.char_start]):
        return None
    # its last clause puts one thing there ("put the book away, then put the pen in the bowl")
    clause = re.split(r",|;|\b(?:and|then)\b", sentence[: last.char_start], flags=re.I)[-1]
    verbs = [w for w in re.findall(r"[a-z']+", clause.lower()) if G.VERBS.get(w, ("",))[0] == "place"]
    return last.entry.canonical if len(find_mentions(clause)) == 1 and len(verbs) == 1 else None


# "put a slice in a bowl and the bowl in the fridge": the container said again with its place is put there
# (users_h195dev; with "a slice" the verbless second clause found no object); read again after
# `sentences.supply_put` wrote "the keys go in the box, and the box goes on the sofa" as a placing (h212).
# Any shape of it (h252): the container with words before its name ("the grey bowl"), said after "on" ("on
# a plate"), joined by a comma, ";" or "then", and the container said again by "that", "this" or "your",
# with or without its own verb ("the bowl goes in the sink", "the pan put in the fridge", a protocol's "in a
# cardboard box; place the box on the table", paper_h301; not after "then", whose order the rewrite would
# drop: probes_h288held's "put a fork in a glass, then put the cup in the sink"); `container_again`
# checks that both name one movable type
_CONTAINER_AGAIN = re.compile(
    r"(?P<head>\b(?:in|into|inside|on|onto)\s+(?:a|an|the|one|your|my)\s+(?:[a-z]+\s+){0,2}?(?P<c>[a-z]+))"
    r"\s*(?:,|;)?\s+(?:and\s+)?(?:then\s+|(?:put|place|set|move|transfer|carry|take|bring)\s+)?"
    r"(?:the|that|this|your)\s+(?P<c2>[a-z]+)\s+"
    r"(?:(?:goes|go|(?:should|must|can)\s+go|(?:is|are)\s+to\s+go)\s+"
    r"|(?:(?:should|must)\s+be\s+|is\s+to\s+be\s+)?(?:put|placed|set|left|stored)\s+)?(?=(?:in|into|on|onto|inside)\s)",
    re.I,
)


def container_again(text: str) -> str:
    """ "put X in a C and the C on Y" -> "put X in a C and put the C on Y", where C names a movable container
    both times ("a spoon in the grey bowl, and the bowl goes in the sink"; not "in the fridge and the pan
    ...", nor "in a bowl and another bowl ..."). An item whose verb is carried over from before ("..., and a
    fork in a bowl and the bowl in the fridge") gets its "put" too: the rules read a carried verb's item
    and a verb's clause after it as a list of the earlier clause's things."""
    out, pos = [], 0
    for m in _CONTAINER_AGAIN.finditer(text):
        held, again = find_mentions(m["head"]), find_mentions(m["c2"])
        # the container's name ends the head ("in a glass and put the glass" is done) and is said again
        if not held or not again or held[-1].plural or again[-1].plural or held[-1].char_end < len(m["head"]):
            continue
        kind = held[-1].entry.canonical
        if kind not in MOVABLE_RECEPTACLES or again[-1].entry.canonical != kind:
            continue
        if m.start() < pos or not _places_before(text[: m.start()]):
            continue  # "X goes in the C, and the C goes on Y", "X in a C, C in Y": read as they are
        item = max((c.end() for c in _ITEM_START.finditer(text, 0, m.start())), default=0)
        words = re.findall(r"[a-z']+", text[item : m.start()].lower())
        carried = bool(words) and words[0] not in G.VERBS and not _places(text[item : m.start()])
        out.append(text[pos:item] + ("put " if carried else "") + text[item : m.start()])
        out.append(f"{m['head']} and put the {m['c2']} ")
        pos = m.end()
    return "".join(out) + text[pos:]


# where a list's item starts: after a stop or comma and the words that join it ("..., and also a fork")
_ITEM_START = re.compile(r"(?:^|[.;:!?,])\s*(?:(?:and|then|also|plus)\s+)*", re.I)


def _places(clause: str) -> bool:
    return any(G.VERBS.get(w, ("",))[0] == "place" for w in re.findall(r"[a-z']+", clause.lower()))


def _places_before(text: str) -> bool:
    """Does the sentence that `text` ends with place something before ("cut a potato and put a slice ", "put
    a spoon in a glass and the glass on the counter, and an apple slice ": the verb carried over)? Not a
    second thing ("put another slice in a pan and the pan ..."), which the drafts keep apart from the
    first."""
    if re.search(r"\b(?:another|other)\b", re.split(r"[.;:!?,]", text)[-1], re.I):
        return False
    return _places(re.split(r"[.;:!?]", text)[-1])


# "a spoon in a glass goes on the table": a thing said in a movable container named for the first time ("a
# glass") as the subject of a verb of going is the container's content, the container moved there; "the spoon
# in the bowl goes ..." (a container named definitely) says where the spoon is now, a source
# (`subject_sources`)
_CONTENT_GOES = re.compile(
    r"(?P<x>\b(?:a|an|one|the|your|my)\s+(?:[a-z]+\s+){0,2}?)(?P<p>in|inside|on)\s+(?P<c>(?:a|an|one)\s+"
    r"(?:[a-z]+\s+){0,2}?[a-z]+)\s+(?:goes|go|(?:should|must|can|needs?\s+to)\s+go|(?:is|are)\s+to\s+go)\s+"
    r"(?=(?:in|into|on|onto|inside)\s)",
    re.I,
)


def content_goes(text: str) -> str:
    """ "a spoon in a glass goes on the table" -> "put a spoon in a glass and put the glass on the table",
    where the glass names a movable container and the spoon a thing of another type."""

    def one(m: re.Match[str]) -> str:
        holder, thing = find_mentions(m["c"]), find_mentions(m["x"])
        if not holder or not thing or holder[-1].char_end != len(m["c"]) or holder[-1].plural:
            return m[0]
        movable = holder[-1].entry.canonical in MOVABLE_RECEPTACLES
        if not movable or thing[-1].entry.canonical in MOVABLE_RECEPTACLES:
            return m[0]
        return f"put {m['x']}{m['p']} {m['c']} and put the {holder[-1].surface} "

    return _CONTENT_GOES.sub(one, text)


# "put a knife in a mug and a spatula in another bowl, and set both (of them) on the table": each container
# with its thing goes there, two place-in-container tasks (h212; "both" once read the two as one pair)
_THING_IN = r"(?:a|an|the|one|another)\s+(?:[a-z]+\s+){0,2}?(?:in|into|on|onto|inside)\s+"
_HOLDER = r"(?:a|an|the|one|another|a\s+second)\s+(?:[a-z]+\s+){0,2}?[a-z]+"
_BOTH_MOVED = re.compile(
    rf"\b(?P<v>put|place|set|stick|drop|pop)\s+(?P<x>{_THING_IN})(?P<c1>{_HOLDER})\s+and\s+"
    rf"(?:(?:put|place|set|stick|drop|pop)\s+)?(?P<y>{_THING_IN})(?P<c2>{_HOLDER})\s*,?\s+(?:and\s+)?(?:then\s+)?"
    r"(?P<v2>put|place|set|move|carry|take|bring|leave)\s+(?:both(?:\s+of\s+them|\s+[a-z]+s)?|them(?:\s+both)?)\s+"
    r"(?P<dest>(?:on|onto|in|into|inside|to)\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+){0,2}?)(?=\s*(?:[,.;!?]|$))",
    re.I,
)


def both_containers_moved(text: str) -> str:
    """Each "put X in C1 and Y in C2, and set both on D" written as "put X in C1 and set it on D, and put Y
    in C2 and set it on D", where C1 and C2 name movable containers."""

    def one(m: re.Match[str]) -> str:
        holders = [find_mentions(m[k]) for k in ("c1", "c2")]
        if not all(h and h[-1].entry.canonical in MOVABLE_RECEPTACLES for h in holders):
            return m[0]
        placed = f"and {m['v2']} it {m['dest']}"
        return f"{m['v']} {m['x']}{m['c1']} {placed}, and put {m['y']}{m['c2']} {placed}"

    return _BOTH_MOVED.sub(one, text)


# "put a candle on a plate and put the plate on the table, a tissue box on the table too, and ...": the chain
# is one task, and the list after it a sentence of its own (the clause rules read the chain only as a whole
# sentence, and split it on "the plate" inside a longer list; h293)
_CHAIN_THEN_LIST = re.compile(
    r"(?P<chain>\bput\s+(?:a|an|the|one)\s+(?:[a-z]+\s+){0,2}?(?:in|into|on|onto|inside)\s+(?:a|an|one)\s+"
    r"(?P<c>[a-z]+(?:\s+[a-z]+)?)\s+and\s+put\s+(?:the|that)\s+(?P=c)\s+(?:on|onto|in|into|to)\s+(?:the|a|an)\s+"
    r"[a-z]+(?:\s+[a-z]+){0,2}?)\s*,\s*(?:and\s+)?(?=(?:a|an|the|one|two|three|\d+|another)\s)",
    re.I,
)


def container_steps(text: str) -> str:
    """The text with a thing put in a container and the container moved said as the one task the rules read
    (`container_again`, `both_containers_moved`, `container_moved_on`, `_CHAIN_THEN_LIST`): "the keys go in
    the box, and the box goes on the sofa". `sentences.normalize` calls it after `supply_put` has written the
    left-out verbs."""
    text = container_moved_on(both_containers_moved(container_again(text)))
    return _CHAIN_THEN_LIST.sub(lambda m: f"{m['chain']}. ", _VERBLESS_CHAIN.sub(_chain_said, text))


# the same chain with its verbs left out, an item of a list with verbs ("wash an apple ..., another apple in
# a pot and the pot on the counter, chill the mug ..."): said with its verbs, a sentence of its own
_VERBLESS_CHAIN = re.compile(
    r",\s*(?:and\s+)?(?P<then>then\s+)?(?P<x>(?:a|an|another|one)\s+(?:[a-z]+\s+){0,2}?)"
    r"(?P<p>in|into|on|onto|inside)\s+(?P<c1>(?:a|an|one|another)\s+(?P<c>[a-z]+))\s+and\s+"
    r"(?:(?:the|that)\s+(?P=c)|that\s+one)\s+(?P<p2>on|onto|in|into)\s+"
    r"(?P<dest>(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+){0,2}?)\s*(?P<end>,\s*(?:and\s+)?|(?=[.;!?]|$))",
    re.I,
)


def _chain_said(m: re.Match[str]) -> str:
    holder, thing = find_mentions(m["c1"]), find_mentions(m["x"])
    if not holder or not thing or holder[-1].entry.canonical not in MOVABLE_RECEPTACLES:
        return m[0]
    if thing[-1].entry.canonical in MOVABLE_RECEPTACLES:
        return m[0]
    said = f"{m['then'] or ''}put {m['x']}{m['p']} {m['c1']} and put the {m['c']} {m['p2']} {m['dest']}"
    return f". {said}" + (". " * bool(m["end"]))
