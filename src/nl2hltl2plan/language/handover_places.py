"""Place phrases of a handover sentence (`handover_phrases.mark` calls these once the blocks are marked):
labelled regions ("region H, I and J", "G/H/I", "on I"), "the opposite side" (per block), "any empty
region", "where the red block is", the side of some arms, the complement of the targets or of named
regions, a place named twice (both readings must agree) and place pronouns ("put nothing on them",
"put the blocks there"). Each becomes a placeholder `P<k>` of the `Marked` sentence."""

from __future__ import annotations

import re
from functools import partial
from typing import Literal

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.handover_scene import COUNTS, LETTER, NOUN, PLACE_NOUN, Marked, Place, Scene
from nl2hltl2plan.language.handover_words import APPOSITION, EMPTY, NOW, VERB


def mark_place_pronouns(
    m: Marked,
    named_before: tuple[str, ...],
    place_before: Place | None,
    group_before: tuple[str, ...],
) -> None:
    """'them' after 'on', 'there' after a moved block: the last place named before it in the sentence, else
    the last regions the sentence before named, else the last place it named that a block may go to ('the
    opposite side', 'any empty region') when the same blocks go there; with none the word stays (unread, so
    refused; 'there' may still be read as a word: 'the red one should be put there before the blue one'). A
    place named as a heading ('regions H, I and J: put the blocks there') or defined ('regions G, H and I are
    the targets: place the blocks in them') is then read where the pronoun stands."""
    if "PLACEREF" not in m.text:
        return
    defined = rf"(?:is|are)\s+(?:the|our|your)\s+(?:targets?|goals?|destinations?|{TARGET}\s+{PLACE_NOUN})"
    m.sub(rf"\bP(\d+)\s+{defined}\s*:", r"P\1 :")
    headings: list[str] = []

    def resolve(match: re.Match[str]) -> str:
        word = match.group(1)
        to = " to " if word == "there" else " "
        before = re.findall(r"\bP(\d+)\b", m.text[: match.start()])
        if before:
            if re.search(rf"\bP{before[-1]}\s*:", m.text):
                headings.append(before[-1])
            return to + _new_place(m, m.places[int(before[-1])])
        if named_before:
            return to + _new_place(m, Place("regions", named_before, text=word))
        # "the blocks belong on the opposite side. Move them there.": the same blocks to that place (not "the
        # red one should be put there before the blue one", an order where "there" adds nothing; not "put the
        # yellow block there too", where the opposite side is another block's)
        moved = re.search(r"\b(?:" + VERB + r")\s+B(\d+)\s+$", m.text[: match.start()])
        same = moved is not None and sorted(m.blocks[int(moved.group(1))]) == sorted(group_before)
        if place_before is not None and same:
            return to + _new_place(m, place_before)
        return f" {word} "

    m.sub(r"\bPLACEREF_(them|it|there)\b", resolve)
    for k in headings:
        m.sub(rf"\bP{k}\s*:", " ")


def note_one_per_region(m: Marked, match: re.Match[str]) -> str:
    """A statement of the world's own rule (a cell holds one block): recorded, read to no formula."""
    m.notes.append("one block per region (the world's rule: a cell holds one block)")
    return " "


def mark_capacity(m: Marked) -> None:
    """'regions H, I and J can each hold only one block': the world's own rule (a cell holds one block),
    said of named places (a pronoun after it, '..., so put one block in each of them', was resolved
    before)."""
    m.sub(
        rf"\bP\d+\s+(?:(?:can|may|will|could)\s+)?(?:each\s+)?(?:only\s+)?(?:hold|take|fit|contain|accept)s?\s+"
        rf"(?:only\s+|just\s+|at\s+most\s+)?(?:one|a\s+single|1)\s+{NOUN}(?:\s+(?:each|apiece))?\b",
        partial(note_one_per_region, m),
    )


def _new_place(m: Marked, place: Place) -> str:
    m.places.append(place)
    return f" P{len(m.places) - 1} "


def mark_places(m: Marked, scene: Scene, named_before: tuple[str, ...]) -> None:
    _mark_target_complements(m)
    _mark_starts(m, scene)
    m.sub(
        r"\b(?:the\s+)?(?:opposite(?:\s+(?:side|sides|end|regions?|areas?|zones?|ones?))?|(?:far|other|facing)\s+"
        r"(?:side|sides|end|regions?|areas?|zones?))(?:\s+(?:regions?|areas?))?"
        r"(?:\s+of\s+the\s+(?:table|workspace|work\s+area|board))?\b",
        lambda match: _new_place(m, Place("opposite", text=match.group(0).strip())),
    )
    # "any empty region", "whichever region is free", "somewhere empty": a region other than the block's start
    m.sub(
        rf"\b(?:(?:any|an|some|a)\s+)?(?:other\s+)?{EMPTY}\s+{PLACE_NOUN}\b|"
        rf"\b(?:whichever|whatever)\s+{PLACE_NOUN}\s+(?:is|happens\s+to\s+be)\s+{EMPTY}\b|\bsomewhere\s+{EMPTY}\b",
        lambda match: _new_place(m, Place("away", text=match.group(0).strip())),
    )
    # "..., whenever there is one": the time of a goal to such a region is free ("whenever")
    m.sub(
        r"\bP(\d+)(\s*,?\s*whenever)\s+there\s+(?:is|s)\s+one\b",
        lambda match: match.group(0) if m.places[int(match[1])].kind != "away" else f"P{match[1]}{match[2]}",
    )
    _mark_arm_sides(m, scene)
    _mark_region_lists(m, scene)
    # "the placement area (on the side of) P", "any region except P", "those regions": the place named
    count = r"(?:(?:two|three|four|\d+)\s+)?"
    named = rf"\b(?:the\s+)?{count}(?:{TARGET}\s+(?:regions?|areas?|zones?)|areas?|zones?|regions)"
    m.sub(rf"{named}\s*,?\s*(?:{APPOSITION}\s*)?,?\s*(?=P\d)", " ")
    # "anywhere except P" is "on any region except P", as "outside P" is
    anywhere_but = rf"(?:outside\s+(?:of\s+)?|anywhere\s+{OTHER_THAN}\s+(?:(?:on|in)\s+)?)"
    m.sub(
        rf"\b(?:(?:the|an?|any|all)\s+)?(?:other\s+)?{PLACE_NOUN}\s+{OTHER_THAN}\s+P(\d+)|\b{anywhere_but}P(\d+)",
        lambda match: _complement_of(m, match),
    )

    def other_than_these(match: re.Match[str]) -> str:  # the labelled regions but the ones just named
        lists = [p.regions for p in m.places if p.kind == "regions"] or [named_before]
        if not lists[-1]:
            return match.group(0)
        said = match["count"]  # "other than these three": the count must be the regions just named
        if said and _COUNTS.get(said, said) != str(len(lists[-1])):
            named = len(lists[-1])
            raise HTTError(f"'{match.group(0).strip()}' counts {said}, but {named} regions were named")
        return _new_place(m, Place("complement", lists[-1], text=match.group(0).strip()))

    # "the same" only before a count or a place noun ("other than the same three", "the same regions")
    same = rf"the\s+same(?=\s+(?:two|three|four|\d|{PLACE_NOUN})\b)"
    these = rf"(?:these|those|{same})(?:\s+(?P<count>two|three|four|\d))?(?:\s+{PLACE_NOUN})?"
    m.sub(
        rf"\b(?:(?:the|any|all|an?)\s+)?(?:other\s+)?{PLACE_NOUN}\s+{OTHER_THAN}\s+"
        rf"(?:{these}|them|the\s+ones\s+(?:named|above|(?:i|we)\s+(?:said|named|mentioned|listed|gave)))\b",
        other_than_these,
    )

    def outside_these(match: re.Match[str]) -> str:  # "outside those (target) regions": the others
        complement = other_than_these(match)
        return complement if complement == match.group(0) else " on " + complement

    these_targets = (
        rf"(?:these|those)(?:\s+(?P<count>two|three|four|\d))?(?:\s+{TARGET})?(?:\s+{PLACE_NOUN})?"
    )
    m.sub(rf"\b{anywhere_but}(?:{these_targets}|them|it)\b", outside_these)
    # "those (three) regions": the place named last, or in a sentence that names none, the regions the
    # sentence before named (a count, if said, must be theirs)
    m.sub(
        rf"\b(?:those|these|the\s+same|said)(?:\s+(?P<count>two|three|four|\d))?\s+{PLACE_NOUN}\b",
        lambda match: _named_before(m, named_before, match),
    )
    # a place named twice ("region G (where the red block is)", "area (E, F, G) to the side of arm a",
    # "next to arm a and arm b, that is region E, F and G"): both readings must agree
    # ("from P to Q" names a source and a goal: not a place named twice)
    apposition = rf"(?<!from)(?<=\S)(\s+)P(\d+)\s*,?\s*{APPOSITION}?\s*,?\s*P(\d+)\s*\)?"
    while re.search(apposition, m.text):
        m.sub(apposition, lambda match: match.group(1) + _merge(m, int(match.group(2)), int(match.group(3))))


def _named_before(m: Marked, named_before: tuple[str, ...], match: re.Match[str]) -> str:
    said = match["count"]
    if m.places:
        last = m.places[-1]
        if said and (last.kind != "regions" or _COUNTS.get(said, said) != str(len(last.regions))):
            return match.group(0)  # unread: refused by name
        return _new_place(m, last)
    if len(named_before) < 2 or not match.group(0).startswith(("those", "these")):
        return match.group(0)  # "the same regions", or "those regions" of one region: unread, as before
    if said and _COUNTS.get(said, said) != str(len(named_before)):
        return match.group(0)
    return _new_place(m, Place("regions", named_before, text=match.group(0).strip()))


TARGET = r"(?:goal|target|placement|destination|assigned)"
_COUNTS = {"two": "2", "three": "3", "four": "4"}
_REGION = r"(?:region|area|zone|spot|cell|location)"
_THAT = r"(?:that|this|those|these)\s+"
OTHER_THAN = r"(?:other\s+than|except(?:\s+for)?|besides|apart\s+from|but|outside(?:\s+of)?)"


def _mark_target_complements(m: Marked) -> None:
    """'an area other than the target region', 'anywhere else', 'any other region': in a prohibition,
    every labelled region but the goals' targets."""
    non_target = (
        rf"\b(?:an?\s+|any\s+)?non\s+{TARGET}\s+{PLACE_NOUN}\b|\b(?:the\s+|all\s+(?:the\s+)?|any\s+(?:of\s+the\s+)?)?"
        rf"(?:remaining|rest\s+of\s+the)\s+{PLACE_NOUN}\b"
    )
    targets = (
        # ("outside that target area", h296)
        rf"(?:the\s+|their\s+|its\s+|an?\s+|one\s+of\s+the\s+|{_THAT})?(?:{TARGET}\s+{PLACE_NOUN}|targets?|goals?)\b"
    )
    complement = (
        rf"\b(?:the\s+|an?\s+)?(?:any\s+)?(?:other\s+)?(?:{PLACE_NOUN}|anywhere)\s+(?:{OTHER_THAN}|that\s+(?:is|are)\s+not)\s+"
        rf"{targets}|\boutside\s+(?:of\s+)?{targets}|\b(?:(?:any\s+|an\s+)?other|another)\s+{PLACE_NOUN}\s+than\s+{targets}|"
        rf"\b(?:any|all|every)\s+other\s+{PLACE_NOUN}\b|{non_target}|"
        # "on another region", "on the other regions" (not "the other side": the opposite)
        rf"\b(?:(?<!after\s)another\s+{_REGION}|(?:the\s+)?other\s+(?:{_REGION}|place)s)\b"
    )

    def other_than(match: re.Match[str]) -> str:  # "anywhere other than ...", "elsewhere": with its "on"
        on = " on " if re.match(r"anywhere|elsewhere|outside", match.group(0)) else ""
        return on + _new_place(m, Place("complement", text=match.group(0).strip()))

    m.sub(complement + r"|\b(?:anywhere\s+else|elsewhere)\b", other_than)


def _complement_of(m: Marked, match: re.Match[str]) -> str:
    """'any region except E, F and G', 'outside E, F and G', 'anywhere but E, F and G': the labelled
    regions but those."""
    named = m.places[int(match.group(1) or match.group(2))]
    if named.kind != "regions":
        raise HTTError(f"cannot tell which regions '{match.group(0).strip()}' leaves out")
    on = " on " if match.group(2) else ""
    return on + _new_place(m, Place("complement", named.regions, text=match.group(0).strip()))


def _mark_starts(m: Marked, scene: Scene) -> None:
    """'where the red block is', 'the original position of the red block': the region it starts on."""

    def start_of(match: re.Match[str], group: int = 1) -> str:
        k = int(match.group(group))
        if len(m.blocks[k]) != 1:
            return match.group(0)
        block = m.blocks[k][0]
        return _new_place(m, Place("start_of", (scene.start_region(block),), block, match.group(0).strip()))

    where = (
        r"(?:\b(?:to|in|into|on|onto|at)\s+)?\(?\s*\bwhere\s+B(\d+)\s+(?:currently\s+|now\s+|initially\s+)?"
        r"(?:is|was|lies|lay|sits|sat|stands|started|starts|locates|stays|rests)\s*"
        r"(?:currently\s+|now\s+|"
        r"initially\s+|at\s+first\s+)?(?:located|locating|lying|placed|sitting|standing|from)?\s*"
        rf"{NOW}?\s*\)?"
    )

    def where_of(match: re.Match[str]) -> str:  # "back (to) where the red block is": a place to go to
        place = start_of(match)
        return match.group(0) if place == match.group(0) else " to " + place

    m.sub(where, where_of)
    start = r"(?:original\s+|initial\s+|starting\s+|start\s+)?(?:position|place|spot|location|cell|region)"
    m.sub(rf"\b(?:the\s+)?{start}\s+of\s+B(\d+)\s*(?=\W|$)", start_of)

    # "to the blue block's position" (the possessive may be read with the block)
    def possessive(match: re.Match[str]) -> str:
        place = start_of(match, 2)
        return match.group(0) if place == match.group(0) else match.group(1) + place

    m.sub(rf"\b((?:to|into|onto|on|in|at)\s+)B(\d+)\s+(?:s\s+)?{start}\b", possessive)


def _mark_arm_sides(m: Marked, scene: Scene) -> None:
    """'the side of arm a and arm b' (a place), 'next to arm a and arm b' (a landmark beside a place)."""

    def arms(match: re.Match[str]) -> str:
        said = re.sub(r"^(?:right|just|directly)\s+", "", match.group(0).strip())  # "right next to": next to
        letters = re.findall(r"\b[a-d]\b", re.sub(r"side of|reach of", "", said))
        regions = scene.arms_side(["abcd".index(x) for x in letters])
        side = "side" in said or re.search(r"(?:area|region|zone)s?\s+of", said) is not None
        kind: Literal["regions", "landmark"] = "regions" if side else "landmark"
        if re.match(r"on|of|at", said) and kind == "landmark":  # "on arm a" names no place
            return match.group(0)
        return _new_place(m, Place(kind, regions, text=said))

    m.sub(
        r"\b(?:(?:right|just|directly)\s+(?=next|beside|by|near|close|adjacent))?"
        r"(?:(?:the\s+)?sides?\s+of|(?:the\s+)?(?:goal\s+|target\s+|placement\s+)?(?:area|region|zone)s?\s+of|"
        r"next\s+to|beside|by|near|close\s+to|in\s+front\s+of|within\s+reach\s+of|"
        r"reachable\s+by|adjacent\s+to|on|of|at)\s+(?:the\s+)?arms?\s+[a-d](?:\s*(?:,|and|&)\s*(?:the\s+)?(?:arm\s+)?[a-d])*"
        r"(?:(?:\s+s)?\s+sides?)?\b",
        arms,
    )
    # "(right) next to the arms" without their letters (marked "A" by then): a landmark of every arm's
    # reach, which only describes a place named beside it (not "the side of the arms": which side?)
    m.sub(
        r"\b(?:(?:right|just|directly)\s+)?(?:next\s+to|beside|near|close\s+to|within\s+reach\s+of|"
        r"reachable\s+by|adjacent\s+to)\s+A\b",
        lambda match: _new_place(
            m, Place("landmark", scene.arms_side([0, 1, 2, 3]), text=match.group(0).strip(), within=True)
        ),
    )
    # "the a/b side", "the side of a and b" without the word "arm"
    m.sub(
        r"\b(?:the\s+)?(?:arms?\s+)?[a-d]\s*(?:/|&|and|,)\s*(?:arm\s+)?[a-d]\s+(?:arms?\s+)?(?:s\s+)?sides?\b",
        lambda match: _new_place(
            m, Place("regions", _sides(scene, match.group(0)), text=match.group(0).strip())
        ),
    )


def _sides(scene: Scene, text: str) -> tuple[str, ...]:
    return scene.arms_side(["abcd".index(x) for x in re.findall(r"\b[a-d]\b", text)])


def _mark_region_lists(m: Marked, scene: Scene) -> None:
    """'region H, I and J', 'the goal regions G/H/I', and bare letters after a preposition ('on I')."""

    def regions(match: re.Match[str]) -> str:
        letters = [x.upper() for x in re.findall(LETTER, match.group("list"))]
        unknown = [x for x in letters if x not in scene.layout.regions]
        if unknown:
            raise HTTError(f"no region {', '.join(unknown)} in handover-{scene.layout.name}")
        text = match.group(0)[len(match.group("prep") or "") :]
        count = re.match(r"\s*(?:the\s+)?(two|three|four|\d+)\s", text)
        if count and COUNTS.get(count.group(1)) != len(set(letters)):
            raise HTTError(f"'{text.strip()}' says {count.group(1)} regions but names {len(set(letters))}")
        place = _new_place(m, Place("regions", tuple(dict.fromkeys(letters)), text=text.strip()))
        return (match.group("prep") or "") + place

    link = rf"(?:\s*(?:,|\band\b|\bor\b|\bat\b|&|/|\(|\)))*\s*(?:\b(?:{TARGET}\s+)?{PLACE_NOUN}\s+)?"
    lead = (
        rf"(?P<prep>)\b(?:the\s+)?(?:(?:two|three|four|\d+)\s+)?(?:{TARGET}\s+)?"
        rf"{PLACE_NOUN}\s*(?::\s*)?(?:\(\s*)?(?:at\s+)?(?:{PLACE_NOUN}\s+)?"
    )
    bare = r"(?P<prep>\b(?:to|into|onto|on|in|at|among|over|between|than|except|besides|from|outside)\s+)"
    letters = LETTER + r"(?:" + link + LETTER + r")*(?:\s*\))?"
    m.sub(rf"{lead}(?P<list>{letters})(?:\s+at\b(?=\s*,))?", regions)
    m.sub(rf"{bare}(?P<list>{letters})", regions)
    # telegraphic: "yellow: I, then G" (a letter after a block's heading, or after "then" ending a clause)
    m.sub(rf"(?P<prep>\bB\d+\s*:\s*)(?P<list>{letters})(?=\s*(?:$|,|\(|\bthen\b))", regions)
    m.sub(rf"(?P<prep>\bthen\s+)(?P<list>{LETTER})(?=\s*(?:$|,))", regions)
    # a bare list of two or more letters ("F, G, H stay empty"): regions anywhere (one letter may be "I")
    listed = LETTER + r"(?:(?:\s*(?:,|\band\b|\bor\b|&|/))+\s*" + LETTER + r")+"
    m.sub(rf"(?P<prep>)(?P<list>{listed})", regions)


def _merge(m: Marked, i: int, j: int) -> str:
    if m.places[i].kind != "regions":  # keep the named regions; the other reading must agree with them
        i, j = j, i
    a, b = m.places[i], m.places[j]
    agree = a.kind == "regions" and b.kind in ("regions", "start_of", "landmark")
    same = set(a.regions) <= set(b.regions) if b.within else set(a.regions) == set(b.regions)
    if not agree or not same:
        raise HTTError(f"'{a.text}' and '{b.text}' name different places")
    return f" P{i} "
