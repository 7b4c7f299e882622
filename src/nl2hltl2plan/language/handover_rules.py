"""The rules of a handover sentence, read before its goals (`handover_reading`): the orders between
blocks' goals ("X before Y"), the touch guards ("no arm may touch X until Y has been touched") and the
prohibitions ("no block can be placed on R during this period"). Each reader consumes the placeholders
and words it reads and returns what it found; what no reader reads is refused by the caller."""

from __future__ import annotations

import re

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.handover_scene import Marked, Place
from nl2hltl2plan.language.handover_words import (
    DONE,
    DROP,
    EMPTY,
    GERUND,
    MODAL,
    NEG,
    PERIOD,
    PERIOD_WORDS,
    PREP,
    THEN,
    TOUCH,
    TOUCHED,
    TOUCHING,
    VERB,
)

Prohibition = tuple[list[str], Place | None, list[str], str]  # blocks, place, explicit regions, text
_MAY = r"(?:can|may|should|must|will|shall|(?:is|are)\s+(?:allowed|permitted)\s+to)"
_PUT = r"(?:put|place|drop|set|leave|lay)"  # the verb of a prohibition: "put nothing on F"
_PLACING = r"(?:placing|putting|dropping|setting)"  # its subject: "placing any object on R is not allowed"


def blocks_of(m: Marked, k: str) -> list[str]:
    return m.blocks[int(k)]


def one_block(m: Marked, k: str, what: str) -> str:
    names = m.blocks[int(k)]
    if len(names) != 1:
        raise HTTError(f"'{m.block_text[int(k)]}' names {len(names)} blocks where {what} needs one")
    return names[0]


def read_orders(m: Marked) -> list[tuple[str, str]]:
    """'X (should be placed) before Y', 'Y after X', 'place X first, then Y', 'X followed by Y', 'once X
    has been placed, Y may be placed', 'do not place Y until X has been placed': X's goal before Y's."""
    out: list[tuple[str, str]] = []
    tail = rf"(?:\s+(?:is|has\s+been|gets|was|have\s+been|are)\s+{DONE}|\s+does)?"
    done = (
        rf"(?:(?:{DONE}|comes?|lands?|arrives?|goes|gets?|arriving|coming|landing|getting|going)\s+)?"
        r"(?:down\s+|there\s+)?(?:first\s*,?\s*)?"
    )

    def add(match: re.Match[str], flip: bool) -> str:
        a, b = one_block(m, match.group(1), "an order"), one_block(m, match.group(2), "an order")
        out.append((b, a) if flip else (a, b))
        return " "

    def add_pair(a: str, b: str) -> str:
        out.append((one_block(m, a, "an order"), one_block(m, b, "an order")))
        return " "

    m.sub(  # "the placement of the red block must precede (come before) that of the blue block"
        rf"\b(?:the\s+)?(?:placement|placing|delivery|transfer)\s+of\s+B(\d+)\s+{MODAL}(?:comes?\s+|happens?\s+|occurs?\s+)?"
        rf"(before|after)\s+(?:(?:that|the\s+(?:placement|placing|delivery|transfer))\s+of\s+)?B(\d+)",
        lambda x: (
            add_pair(x.group(1), x.group(3)) if x.group(2) == "before" else add_pair(x.group(3), x.group(1))
        ),
    )
    # the second block's goal, without its place: "then the blue block", "followed by the blue block"
    end = r"(?=\s*(?:$|,|\band\b|\)))"
    later = r"(?:after\s+B\d+|second|next|last|afterwards?)"
    then = rf"(?:{THEN}|followed\s+by|and(?=\s+(?:{VERB}\s+)?B\d+\s+{later}\b))"

    m.sub(rf"\bB(\d+)\s+{MODAL}{DONE}\s*(?:first\s*)?,?\s*{then}\s+B(\d+){end}", lambda x: add(x, False))

    def add_then(x: re.Match[str]) -> str:  # "the red block first and the blue block after it": it = red
        if x.group(3) is not None and m.blocks[int(x.group(3))] != m.blocks[int(x.group(1))]:
            return x.group(0)
        return add(x, False)

    m.sub(
        rf"\b(?:(?:{VERB}|{GERUND})\s+)?B(\d+)\s+(?:first\s*)?,?\s*{then}\s+(?:(?:{VERB}|{GERUND})\s+)?B(\d+)"
        rf"(?:\s+(?:after\s+B(\d+)|second|next|last|afterwards?))?{end}",
        add_then,
    )

    def add_keeping_goal(x: re.Match[str]) -> str:  # the goal stays for the goal reader
        a = x.group("a1") or x.group("a2")
        add_pair(a, x.group("b")) if x.group("w") == "before" else add_pair(x.group("b"), a)
        return f" {x.group('goal')} "

    # "place the red block on the opposite side before the blue block", "the red block is to be moved ..."
    m.sub(
        rf"\b(?P<goal>(?:{VERB}|{GERUND})\s+B(?P<a1>\d+)\s+(?:back\s+)?{PREP}\s+P\d+|B(?P<a2>\d+)\s+{MODAL}{DONE}\s+"
        rf"(?:back\s+)?{PREP}\s+P\d+)\s*,?\s+(?:first\s*,?\s*)?(?P<w>before|after)\s+(?:you\s+(?:{VERB}\s+)?|{GERUND}\s+)?"
        rf"B(?P<b>\d+){tail}{end}",
        add_keeping_goal,
    )
    for word, flip in ((r"before", False), (r"(?:after|once)", True)):
        m.sub(
            rf"\b(?:{VERB}|{GERUND}|do|handle)\s+B(\d+)\s+(?:first\s*,?\s*)?{word}\s+(?:you\s+(?:{VERB}\s+)?|{GERUND}\s+)?B(\d+){tail}",
            lambda x, f=flip: add(x, f),
        )
        m.sub(
            rf"(?:\b(?:with|where|in\s+which)\s+)?\bB(\d+)\s+{MODAL}{done}(?:only\s+)?{word}\s+B(\d+){tail}",
            lambda x, f=flip: add(x, f),
        )
    m.sub(
        rf"\b(?:only\s+)?(?:once|after|when)\s+B(\d+)\s+(?:(?:has|have|had)\s+been|is|are|was|gets)\s+{DONE}\s*,?\s*"
        r"(?:only\s+then\s+)?"
        rf"(?:can|may|should|must|will)?\s*(?:B(\d+)\s+{MODAL}{DONE}|(?:{VERB})\s+B(\d+)){end}",
        lambda x: add_pair(x.group(1), x.group(2) or x.group(3)),
    )
    m.sub(  # "before the blue block is placed, the red block must be placed"
        rf"\bbefore\s+B(\d+)\s+(?:(?:has|have)\s+been|is|are|gets)\s+{DONE}\s*,?\s*B(\d+)\s+{MODAL}{DONE}{end}",
        lambda x: add_pair(x.group(2), x.group(1)),
    )
    m.sub(
        rf"\b(?:A\s+)?{NEG}\s+(?:{VERB})\s+B(\d+)\s+(?:until|before)\s+B(\d+)\s+(?:has|have|had)\s+been\s+{DONE}{end}",
        lambda x: add_pair(x.group(2), x.group(1)),
    )
    m.sub(
        rf"\bB(\d+)\s+(?:(?:must|may|can|should|shall|will|is|are)\s+)?{NEG}\s+be\s+{DONE}\s+(?:until|before)\s+B(\d+)\s+"
        rf"(?:has|have|had)\s+been\s+{DONE}{end}",
        lambda x: add_pair(x.group(2), x.group(1)),
    )

    return out


def read_leaders(m: Marked) -> list[str]:
    """'..., red first', 'with the red block being placed first': a block before the others it is moved
    with (the caller finds the clause)."""
    out: list[str] = []

    def add(match: re.Match[str]) -> str:
        names = m.blocks[int(match.group(1))]
        if len(names) != 1:
            return match.group(0)
        out.append(names[0])
        return " "

    m.sub(r"\b(?:place|put|move|do|handle|take)\s+B(\d+)\s+(?:down\s+)?first\b(?=\s*(?:$|,|\band\b|\)))", add)
    # non-native: "red block first place", "..., first place red block"
    m.sub(r"\bB(\d+)\s+first\s+(?:place|placed|put|goes|go)\b(?=\s*(?:$|,|\band\b|\)))", add)
    m.sub(r"\bfirst\s+(?:place|put|move)\s+B(\d+)(?=\s*(?:$|,|\band\b|\)))", add)
    m.sub(
        rf"(?:\b(?:with|placing|putting|moving|and)\s+)?\bB(\d+)\s+(?:down\s+)?{MODAL}(?:(?:placed|put|moved|set|place)\s+|goe?s?\s+|"
        r"comes?\s+|going\s+|coming\s+)?(?:down\s+|there\s+)?first\b(?=\s*(?:$|,|\band\b|\)))",
        add,
    )
    return out


def read_touch_guards(m: Marked) -> list[tuple[str, str]]:
    """(X, Y): X is not picked up before Y is. 'no arm may touch X until an arm has touched Y', 'until Y
    has been touched, X must not be touched', 'X may only be touched after Y', 'Y must be picked up
    before X', 'leave X alone until Y has been touched'."""
    out: list[tuple[str, str]] = []

    def add(match: re.Match[str]) -> str:
        y = next(match.group(g) for g in ("y1", "y2", "y3", "y4") if match.groupdict().get(g) is not None)
        out.append((one_block(m, match.group("x"), "a touch rule"), one_block(m, y, "a touch rule")))
        return " "

    end = r"(?=\s*(?:$|,|\band\b|\)))"
    # Y's touch, active ("an arm touched Y"), passive ("Y has been touched") or elliptic ("... before Y")
    other = (
        rf"(?:(?:A\s+)?(?:has\s+|have\s+|had\s+)?(?:already\s+)?(?:{TOUCHED}|{TOUCHING}|{TOUCH})\s+B(?P<y1>\d+)|B(?P<y2>\d+)\s+"
        rf"(?:(?:has|have|had)\s+(?:already\s+)?been|is|was|gets|got|being|be)\s+(?:already\s+)?{TOUCHED}(?:\s+by\s+A)?|"
        rf"B(?P<y3>\d+){end}|B(?P<y4>\d+)\s+(?:(?:has|have|had)\s+been|is|was){end})(?:\s+first{end})?"
    )
    may = _MAY
    no_touch = (
        rf"(?:(?:\bA\s+)?{NEG}\s+{TOUCH}|(?:\bwith\s+)?\bno\s+A\s+(?:{may}\s+)?(?:{TOUCH}|{TOUCHED}|{TOUCHING})|"
        rf"\b(?:never|not|without|no)\s+{TOUCHING})"
        r"\s+B(?P<x>\d+)"
    )
    not_touched = (
        rf"(?:\bwith\s+)?\bB(?P<x>\d+)\s+(?:(?:is|are|must|may|can|should|shall|will)\s+)?{NEG}\s+(?:ever\s+)?"
        rf"(?:(?:to\s+)?be\s+|being\s+)?(?:{TOUCHED}|(?<=be\s){TOUCH})(?:\s+by\s+A)?"
    )
    until = r"(?:until|before|unless)"
    after = r"(?:only\s+)?(?:after|once|when)"
    # "while doing so, X may only be touched after Y": a touch rule holds for the whole run anyway
    m.sub(rf"\b(?:{PERIOD_WORDS})\s*,?\s*(?=[^,]*\b(?:{TOUCH}|{TOUCHED}|{TOUCHING})\b)", " ")
    for pattern in (
        rf"{no_touch}\s+{until}\s+{other}",
        rf"{not_touched}\s+{until}\s+{other}",
        rf"\b{until}\s+{other}\s*,?\s*{no_touch}",
        rf"\b{until}\s+{other}\s*,?\s*{not_touched}",
        rf"\bleave\s+B(?P<x>\d+)\s+(?:alone|untouched|be)\s+{until}\s+{other}",
        rf"\b(?:keep|hold)\s+(?:A|your\s+hands|hands)\s+(?:off|away\s+from)\s+B(?P<x>\d+)\s+{until}\s+{other}",
        rf"\bB(?P<x>\d+)\s+(?:is|are|stays?|remains?)\s+off\s+limits\s+{until}\s+{other}",
        rf"\bB(?P<x>\d+)\s+{MODAL}wait\s+{until}\s+{other}",
        rf"\bB(?P<x>\d+)\s+{MODAL}(?:(?:remains?|stays?|remaining|staying|be\s+left|left)\s+)?untouched\s+{until}\s+{other}",
        rf"\b{after}\s+{other}\s*,?\s*(?:only\s+then\s+)?{may}\s+(?:A\s+)?{TOUCH}\s+B(?P<x>\d+)",
        rf"\b{after}\s+{other}\s*,?\s*(?:only\s+then\s+)?{may}\s+B(?P<x>\d+)\s+be\s+{TOUCHED}(?:\s+by\s+A)?",
        rf"(?:\bA\s+)?{may}\s+(?:only\s+)?{TOUCH}\s+B(?P<x>\d+)\s+{after}\s+{other}",
        rf"\bB(?P<x>\d+)\s+{may}\s+(?:only\s+)?be\s+{TOUCHED}(?:\s+by\s+A)?\s+{after}\s+{other}",
        # the positive order of the touches: "Y must be picked up before X (is)"
        rf"\bB(?P<y1>\d+)\s+{MODAL}{TOUCHED}(?:\s+by\s+A)?\s+(?:first\s*,?\s*)?before\s+(?:(?:A\s+)?{TOUCHED}\s+)?B(?P<x>\d+)"
        rf"(?:\s+(?:is|has\s+been|gets)\s+{TOUCHED})?(?P<y2>)(?P<y3>){end}",
        rf"(?:\bA\s+)?(?:{may}\s+)?(?:{TOUCH}|{TOUCHING})\s+B(?P<y1>\d+)\s+(?:first\s*,?\s*)?before\s+(?:touching\s+|picking\s+up\s+|"
        rf"grabbing\s+|{TOUCH}\s+)?B(?P<x>\d+)(?P<y2>)(?P<y3>){end}",
        # terse: "blue only after red has been touched" (Y's touch named, so X's is meant)
        rf"\bB(?P<x>\d+)\s+only\s+(?:after|once)\s+(?:(?:A\s+)?(?:has\s+|have\s+)?{TOUCHED}\s+B(?P<y1>\d+)|B(?P<y2>\d+)\s+"
        rf"(?:(?:has|have)\s+been|is|was|gets|got)\s+{TOUCHED}(?:\s+by\s+A)?)(?P<y3>){end}",
    ):
        m.sub(pattern, add)
    return out


def read_prohibitions(m: Marked) -> list[Prohibition]:
    """(blocks, place, explicit regions, text) per 'no block can be placed on ...' statement."""
    out: list[Prohibition] = []

    def add(match: re.Match[str]) -> str:
        blocks = blocks_of(m, match.group("b")) if match.groupdict().get("b") else []
        place = m.places[int(match.group("p"))]
        if place.kind == "opposite" and "other" in place.text:  # "the other regions": all but the targets
            place = Place("complement", text=place.text)
        explicit = list(place.regions) if place.kind == "regions" else []
        if place.kind not in ("regions", "complement"):
            raise HTTError(f"cannot forbid '{place.text}': name the regions")
        out.append((blocks, None if explicit else place, explicit, match.group(0).strip()))
        return " "

    down = rf"(?:\s+down)?\s+{PREP}\s+P(?P<p>\d+){PERIOD}"
    m.sub(
        rf"\b{PERIOD_WORDS}\s*,?\s*(?=no\s+B|nothing|B\d+\s+{MODAL}{NEG}|(?:A\s+)?{NEG}|keep|leave|P\d)", " "
    )
    may = _MAY
    m.sub(
        rf"\bno\s+B(?P<b>\d+)\s+(?:{may}\s+|is\s+|are\s+|gets\s+|to\s+)?(?:ever\s+)?(?:be\s+)?{DROP}{down}",
        add,
    )
    # "no other region may receive an object", "regions F, G and H cannot receive any object"
    thing = r"(?:an?\s+|any\s+)?(?:(?:block|object|cube|pillar|item|piece)s?|anything)"
    receives = r"(?:receive|get|hold|take|contain)s?"
    receive = rf"{receives}\s+{thing}"
    m.sub(rf"\bno\s+P(?P<p>\d+)\s+(?:{may}\s+)?{receive}\b{PERIOD}", add)
    m.sub(rf"\bP(?P<p>\d+)\s+(?:{may}\s+)?{NEG}\s+{receive}\b{PERIOD}", add)

    # "regions F, G and H cannot have any object placed (on them)": "them" was read as those regions
    def add_same(match: re.Match[str]) -> str:
        again = match.group("q")
        same = again is None or m.places[int(again)] == m.places[int(match.group("p"))]
        return add(match) if same else match.group(0)

    m.sub(
        rf"\bP(?P<p>\d+)\s+(?:{may}\s+)?{NEG}\s+(?:have|get)\s+{thing}\s+{DROP}(?:\s+(?:on|in|onto|into)\s+P(?P<q>\d+))?"
        rf"{PERIOD}",
        add_same,
    )
    # "regions F, G and H shall receive no object"
    m.sub(rf"\bP(?P<p>\d+)\s+(?:{may}\s+)?{receives}\s+nothing{PERIOD}", add)  # "F, G and H receive nothing"
    receive_no = rf"{receives}\s+no"
    m.sub(rf"\bP(?P<p>\d+)\s+(?:{may}\s+)?{receive_no}\s*B(?P<b>\d+){PERIOD}", add)
    # "nothing goes on F, G or H", "no block may go on R"
    m.sub(
        rf"\b(?:no\s+B(?P<b>\d+)|nothing)\s+(?:{may}\s+)?(?:goes|go)\s+(?:on|in|onto|into|to)\s+P(?P<p>\d+){PERIOD}",
        add,
    )
    m.sub(rf"\b{_PUT}\s+nothing{down}", add)  # "put nothing on F, G or H"
    # verbless: "no object on any other region", "nothing on F, G or H in the meantime"
    m.sub(rf"\bno\s+B(?P<b>\d+)\s+(?:on|in|onto|into)\s+P(?P<p>\d+){PERIOD}", add)
    m.sub(rf"\bnothing\s+(?:on|in|onto|into)\s+P(?P<p>\d+){PERIOD}", add)
    # "F/G/H: nothing during this period", "other regions: never"
    m.sub(rf"\bP(?P<p>\d+)\s*:\s*(?:nothing|never|none|forbidden|off\s+limits){PERIOD}", add)
    m.sub(rf"(?:^|(?<=,))\s*P(?P<p>\d+)\s*:?\s*(?:no\s+B(?P<b>\d+)|nothing|none){PERIOD}(?=\s*(?:$|,))", add)
    # a coach's "No other region, ever.", "no F, G or H meanwhile": a clause of its own, no place used
    m.sub(rf"(?:^|(?<=,))\s*no\s+P(?P<p>\d+){PERIOD}(?=\s*(?:$|,))", add)
    modal = r"(?:(?:must|may|can|should|shall|will|is|are)\s+)?"
    m.sub(rf"\bB(?P<b>\d+)\s+{modal}{NEG}\s+(?:ever\s+)?(?:be\s+)?{DROP}{down}", add)
    m.sub(
        rf"(?:(?:\bA\s+(?:(?:must|may|can|should|shall|will)\s+)?)?{NEG}|\bno\s+A\s+{may}?)\s+{_PUT}\s+(?:any\s+(?:one\s+)?of\s+)?"
        rf"B(?P<b>\d+){down}",
        add,
    )
    m.sub(rf"\bnothing\s+(?:{may}\s+)?(?:ever\s+)?(?:be\s+|is\s+|gets\s+)?(?:ever\s+)?{DROP}{down}", add)
    banned = r"(?:not\s+(?:allowed|permitted)|forbidden|prohibited|banned)"
    # "placing any object on R is not allowed"
    m.sub(rf"\b{_PLACING}\s+B(?P<b>\d+){down}\s+(?:is|are)\s+{banned}", add)
    # "objects are not allowed on ...", "no object is allowed on ...", "objects are forbidden on ..."
    m.sub(rf"\bB(?P<b>\d+)\s+(?:is|are)\s+{banned}\s+(?:from\s+)?{PREP}\s+P(?P<p>\d+){PERIOD}", add)
    m.sub(rf"\bno\s+B(?P<b>\d+)\s+(?:is|are)\s+(?:allowed|permitted)\s+{PREP}\s+P(?P<p>\d+){PERIOD}", add)
    # "region F, G and H can not be placed any object (during this period)"
    m.sub(rf"\bP(?P<p>\d+)\s+(?:{may}\s+)?{NEG}\s+(?:be\s+)?{DROP}\s+(?:with\s+)?B(?P<b>\d+){PERIOD}", add)
    # "regions F, G and H must stay empty (meanwhile)", "keep F, G and H free": nothing is put there
    must = r"(?:(?:must|should|will|shall|has\s+to|have\s+to|needs?\s+to)\s+)?"
    stay = rf"{must}(?:stay|remain|be\s+kept|be\s+left)"
    free = rf"{EMPTY}(?:\s+(?:of\s+)?B(?P<b>\d+))?"  # "clear of the red block": of that block only
    m.sub(rf"\bP(?P<p>\d+)\s+{stay}\s+{free}{PERIOD}", add)
    m.sub(rf"\b(?:keep|leave)\s+P(?P<p>\d+)\s+{free}{PERIOD}", add)
    m.sub(rf"(?:\bwith\s+)?\bP(?P<p>\d+)\s+(?:kept|left)\s+{free}{PERIOD}", add)  # "with F, G, H kept empty"
    m.sub(rf"\bP(?P<p>\d+)\s+(?:(?:is|are|stays?|remains?|{stay})\s+)?off\s+limits{PERIOD}", add)
    # verbless, a clause of its own: "F, G, H empty meanwhile", "regions F, G and H: empty"
    m.sub(rf"(?:^|(?<=,))\s*P(?P<p>\d+)\s*:?\s*(?:kept\s+|left\s+)?{EMPTY}{PERIOD}(?=\s*(?:$|,))", add)
    # "regions F, G and H must not be used (during this period)", "do not use F, G or H"
    for_nothing = r"(?:\s+(?:for\s+)?(?:anything|any\s+(?:block|object|pillar)))?"
    be_used = rf"(?:to\s+)?be\s+used{for_nothing}{PERIOD}"
    m.sub(rf"\bP(?P<p>\d+)\s+(?:{may}\s+|(?:is|are)\s+)?{NEG}\s+{be_used}", add)
    m.sub(rf"\b{NEG}\s+use\s+P(?P<p>\d+){for_nothing}{PERIOD}", add)
    m.sub(rf"\bno\s+P(?P<p>\d+)\s+(?:{may}\s+)?be\s+used{PERIOD}", add)  # "no other region may be used"

    return out + _read_only_on(m)


def _read_only_on(m: Marked) -> list[Prohibition]:
    """'objects may only be placed on the target regions / on E, F and G', 'only ever place objects on
    the target regions': every labelled region but those is forbidden."""
    out: list[Prohibition] = []

    def add_only(match: re.Match[str]) -> str:
        keep = m.places[int(match.group("p"))] if match.group("p") else None
        if keep is not None and keep.kind != "regions":
            raise HTTError(f"cannot forbid all but '{keep.text}': name the regions")
        regions = keep.regions if keep is not None else ()
        out.append(
            (
                blocks_of(m, match.group("b")),
                Place("complement", regions, text=match.group(0)),
                [],
                match.group(0),
            )
        )
        return " "

    def goal_only(match: re.Match[str]) -> str:  # "move the pillars to E, F and G only": the goal stays
        keep = m.places[int(match.group("p"))]
        if keep.kind != "regions":  # named regions only: a guard holds for every goal of the sentence
            return match.group(0)
        text = match.group(0).strip()
        out.append((blocks_of(m, match.group("b")), Place("complement", keep.regions, text=text), [], text))
        return f" {match.group('goal')} "

    m.sub(
        rf"(?P<goal>\b(?:(?:{VERB}|{GERUND})\s+)?B(?P<b>\d+)\s+{PREP}\s+P(?P<p>\d+))\s+only\b(?=\s*(?:$|,|\band\b))",
        goal_only,
    )
    target = r"(?:P(?P<p>\d+)|(?P<t>the\s+(?:target|goal)\s+(?:regions?|areas?|zones?)))"
    m.sub(
        rf"\bB(?P<b>\d+)\s+{_MAY}\s+(?:only\s+be\s+{DROP}|be\s+{DROP}\s+only)\s+{PREP}\s+{target}{PERIOD}",
        add_only,
    )
    m.sub(rf"\bB(?P<b>\d+)\s+(?:is|are)\s+only\s+(?:allowed|permitted)\s+{PREP}\s+{target}{PERIOD}", add_only)
    # "objects may be put on those three regions only": "only" after the place it limits
    m.sub(
        rf"\bB(?P<b>\d+)\s+{_MAY}\s+be\s+{DROP}\s+{PREP}\s+{target}\s+only{PERIOD}(?=\s*(?:$|[,.;]))",
        add_only,
    )
    m.sub(  # "only ever put a pillar down on one of those regions": on those
        rf"\b(?:(?:A\s+)?{_MAY}\s+)?only\s+(?:ever\s+)?(?:place|put|drop|set)\s+B(?P<b>\d+)\s+(?:down\s+)?{PREP}\s+"
        rf"(?:one\s+of\s+)?{target}{PERIOD}",
        add_only,
    )
    m.sub(rf"\b{_PLACING}\s+B(?P<b>\d+)\s+only\s+{PREP}\s+{target}{PERIOD}", add_only)

    return out
