"""Records, headings and references of a tabletop instruction read as the placements they say (issue 28),
on the instruction's lines as `tabletop_lines.lines_joined` gives them:

- a record of labelled fields, a thing and then where it goes ("Object: green apple. Target: blue plate.",
  "Thing: carrot. Where: blue plate."): each pair is "put THING on PLATE". The labels are the headings'
  (`heading_heads.txt`: `record_thing`, `record_place`); a record is read only where every such field
  pairs up, each thing's label first ("Plate: blue plate. Item: orange. Plate: ..." is left as it is:
  which plate goes with which thing is not said by the order alone), and each value is names and nothing
  else;
- a collective noun that names the things listed after "as follows" ("Arrange the fruit as follows:
  ..."): the list is what is asked, as after "Arrange:";
- Markdown parts whose headings say that each comes after the one before ("### Phase A ... ### Phase B
  (after A) ..."): "then" between them; headings that order otherwise, or not at all, are left as they are;
- "Don't put X on P until then." after a sentence: "Then put X on P." ("until then", "until that's
  done": the sentence before);
- an order label that any order will do ("Order: any", "Order - whatever", "Sequence: free"): "In any
  order.", which the readers read as that (and refuse beside "then", as they refuse "..., then ..., in any
  order");
- a label that announces the list of placements after its colon ("Here's today's feeding chart: green
  apple in the pink plate, ...", "Per the ledger, two entries to post: ..."): dropped, and said in the
  result's notes, where it names no thing or plate of the world, says no order, negation or stage, and
  any count it says is the list's length (`_list_labels_dropped`, h262);
- step labels that each free their own step ("Step 1 (any order): ... Step 2, after step 1 (any order):
  ..."): `tabletop_steps.label_remarks_read`.

>>> kinds = {"green apple": False, "orange": False, "blue plate": True, "yellow plate": True}
>>> fields_read("Object: green apple. Target: blue plate. Object: orange. Target: yellow plate.", kinds)
'put the green apple on the blue plate. put the orange on the yellow plate.'
>>> fields_read("Put the orange on the yellow plate. Don't put the green apple on the blue plate until then.",
...             kinds)
'Put the orange on the yellow plate. Then put the green apple on the blue plate.'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import free_order_phrase, phrase_category, phrase_words
from nl2hltl2plan.language.headings import counted_headings, heading_pattern, heading_words
from nl2hltl2plan.language.spelling import english_lemmas
from nl2hltl2plan.language.tabletop_steps import label_remarks_read
from nl2hltl2plan.language.tabletop_wording import kind_pattern, mention_pattern

_WHAT = heading_words()["record_thing"]
_WHERE = heading_words()["record_place"]
_LABEL = re.compile(r"(?:^|(?<=[.;|,!?])|(?<=\s))(?P<label>[A-Za-z]+)\s*:\s*", re.IGNORECASE)


def fields_read(text: str, kinds: dict[str, bool], dropped: list[str] | None = None) -> str:
    """`text` with its records of labelled fields, "as follows" lists, labels that announce a list, ordered
    Markdown parts and "don't ... until then" read (see the module docstring); `kinds`: each name in words
    -> is it a plate; a label dropped is added to `dropped`."""
    text = _records_paired(_qualifiers_dropped(text, kinds, dropped), kinds)
    text = _list_labels_dropped(text, kinds, dropped)
    text = _AS_FOLLOWS.sub(lambda m: f"{m['verb']}{m['free'] or ''}:", text)
    text = _ORDER_LABEL.sub(_any_order_label, text)
    return label_remarks_read(_UNTIL_THEN.sub(_then_put, _parts_ordered(text)))


# "Order: any" / "Order: none" as a sentence of its own (`headings` has made "Order - any" a colon): a label
# and value that the shared free-order list says as one phrase ("order : any", free_order.txt), a value that
# is a free-order phrase itself ("Order: any order"), or one that says nothing is asked (content_words.txt's
# `empty_value`, as `headings` reads other labels)
_ORDER_LABEL = re.compile(
    r"(?:^|(?<=[.;!?(]\s)|(?<=[.;!?(]))\s*(?P<label>order(?:ing)?|sequence)\s*:\s*(?P<value>[^.;:!?()]*?)"
    r"\s*(?=[.;!?)]|$)",
    re.IGNORECASE,
)
_FREE_LABEL = re.compile(
    rf"(?:{free_order_phrase('whole')})|(?P<value>{free_order_phrase('adverb')}|{phrase_category('empty_value')})",
    re.IGNORECASE,
)


def _any_order_label(m: re.Match[str]) -> str:
    """ "In any order" for an order label whose value leaves the order free; the label as it is otherwise."""
    free = _FREE_LABEL.fullmatch(f"{m['label']} : {m['value']}") or _FREE_LABEL.fullmatch(m["value"])
    return "In any order" if free else m[0]


def _records_paired(text: str, kinds: dict[str, bool]) -> str:
    """Each "WHAT-LABEL: things. WHERE-LABEL: plate." pair as "put things on the plate."; the text as it
    is unless every field of a record's label (`heading_heads.txt`) pairs up so."""
    names = mention_pattern(kinds, re.IGNORECASE).pattern
    things = rf"(?:the\s+)?{names}(?:\s*(?:,|\+|&|\band\b)\s*(?:the\s+)?{names})*"
    what = "|".join(sorted(_WHAT, key=len, reverse=True))
    where = "|".join(sorted(_WHERE, key=len, reverse=True))
    pair = re.compile(
        rf"(?<![\w:])(?:{what})\s*:\s*(?P<things>{things})\s*[.;,|]?\s*(?:{where})\s*:\s*"
        rf"(?P<plate>(?:the\s+)?{names})\s*(?P<end>[.;,|!]+|$)",
        re.IGNORECASE,
    )
    pairs = list(pair.finditer(text))
    fields = [m for m in _LABEL.finditer(text) if m["label"].lower() in _WHAT | _WHERE]
    if not pairs or len(fields) != 2 * len(pairs):
        return text
    if any(not all(kinds.get(_name(n)) is False for n in _names_in(m["things"], kinds)) for m in pairs):
        return text  # a plate among the things
    if any(kinds.get(_name(m["plate"])) is not True for m in pairs):
        return text
    return pair.sub(_put, text)


# a sentence's label before its colon, and the list after it up to the sentence's end
_ANNOUNCED = re.compile(
    r"(?:^|(?<=[.!?]\s))(?P<label>[^.!?:;]{1,80}?)\s*:\s+(?P<list>[^.!?:]+?)\s*(?=[.!?]|$)"
)
_LABEL_KEEPS = phrase_words("tabletop_fields.txt", "announce_not")
_COUNT = {w: n for n, w in enumerate("zero one two three four five six seven eight nine ten".split())}


# "Step one of the regimen:", "Phase two of the voyage -": a step label's qualifier ("of" and one word) that
# names no thing or plate is the voice's; it is dropped (said in the notes) and the label left (h267)
_QUALIFIED = re.compile(
    r"(?P<label>\b[a-z]+\s+(?:\d|one|two|three|four|first|second|third|fourth))"
    r"(?P<of>\s+of\s+(?:the|this|our|my|your|today's)\s+[a-z]+)\s*(?=[:\-\u2013\u2014])",
    re.IGNORECASE,
)


def _qualifiers_dropped(text: str, kinds: dict[str, bool], dropped: list[str] | None) -> str:
    names = mention_pattern(kinds, re.IGNORECASE)

    def label(m: re.Match[str]) -> str:
        if names.search(m["of"]):
            return m[0]
        if dropped is not None:
            dropped.append(m["of"].strip())
        return m["label"]

    return _QUALIFIED.sub(label, text)


def _list_labels_dropped(text: str, kinds: dict[str, bool], dropped: list[str] | None) -> str:
    """`text` without the labels that announce the list of placements after their colon (see the module
    docstring): each part of the list is one thing, at most two words that name nothing, "in" / "on" /
    "to" and one plate ("green apple posted to the blue plate", "put the carrot in the blue plate")."""
    things = kind_pattern(kinds, plates=False).pattern
    plates = kind_pattern(kinds, plates=True).pattern
    item = re.compile(
        rf"(?:(?:put|place|move|drop|set|transfer|deliver)\s+)?(?:the\s+|one\s+|an?\s+)?{things}"
        rf"(?P<between>(?:\s+[a-z']+){{0,2}}?)\s+(?:in|on|into|onto|to)\s+(?:the\s+)?{plates}",
        re.IGNORECASE,
    )
    names = mention_pattern(kinds, re.IGNORECASE)

    def dropped_label(m: re.Match[str]) -> str:
        words = re.findall(r"[a-z0-9'-]+", m["label"].lower())  # ("year-end": one word)
        parts = [p for p in re.split(r"\s*(?:[,;]\s*(?:and\s+)?|\s+and\s+)\s*", m["list"]) if p]
        fits = [item.fullmatch(p) for p in parts]
        counts = {_COUNT.get(w, int(w) if w.isdigit() else None) for w in words} - {None}
        turns = re.findall(rf"(?:^|[.!?]\s+){re.escape(m['label'].strip())}\s*:", text, re.IGNORECASE)
        if (
            not words
            or len(turns) > 1  # a speaker's or a field's label, said again ("User: ... User: ...")
            or not all(fits)
            or counted_headings(f"{m['label']}:")  # "Four items:": `tabletop_headings` reads and checks it
            or names.search(m["label"])
            or any(w in _LABEL_KEEPS or w.endswith("n't") or _how(w) for w in words)
            # a part's name: "Plan A", "Step 2"
            or re.fullmatch(r"[a-z]|\d+", words[-1]) or words[-1] in _COUNT
            or any(w in _LABEL_KEEPS for f in fits if f for w in f["between"].lower().split())
            or counts - {len(parts)}
        ):
            return m[0]
        if dropped is not None:
            dropped.append(" ".join(m["label"].split()))
        return m["list"]

    return _ANNOUNCED.sub(dropped_label, text)


def _how(word: str) -> bool:
    """A word that says how or in what order ("alphabetically", "respectively")."""
    return word.endswith("ly") and "ADV" in english_lemmas(word)


def _put(m: re.Match[str]) -> str:
    things = re.sub(r"^(?!the\b)", "the ", m["things"].strip(), flags=re.IGNORECASE)
    plate = re.sub(r"^(?!the\b)", "the ", m["plate"].strip(), flags=re.IGNORECASE)
    return f"put {things} on {plate}."


def _names_in(part: str, kinds: dict[str, bool]) -> list[str]:
    return mention_pattern(kinds, re.IGNORECASE).findall(part)


def _name(found: str) -> str:
    return " ".join(re.sub(r"^the\s+", "", found.strip(), flags=re.IGNORECASE).lower().split())


# "Arrange the fruit as follows[, in any order]:" -> "Arrange[, in any order]:"
_AS_FOLLOWS = re.compile(
    r"\b(?P<verb>arrange|sort|place|put|set|lay\s+out|organi[sz]e|distribute)\s+(?:all\s+)?(?:the|your|these|"
    r"those)\s+(?:fruits?|foods?|produce|things|items|objects|pieces|stuff)\s+as\s+follows\s*(?P<free>,[^:.;]*?)?"
    r"\s*:",
    re.IGNORECASE,
)

_PART_WORD = heading_pattern("part_label")
# a part's heading: "### Phase A", "## Part 2 (after part 1)", "Phase B (after A)" (a part word, or hashes)
_HEADING = re.compile(
    rf"(?:^|(?<=[.!?:])\s*)(?:(?P<hashes>#{{1,6}})\s*(?:{_PART_WORD}\s+)?|{_PART_WORD}\s+)(?P<id>[A-Za-z0-9]+)"
    rf"\s*(?:\(\s*after\s+(?:{_PART_WORD}\s+)?(?P<after>[A-Za-z0-9]+)\s*\))?\s*:?\s*",
    re.IGNORECASE,
)


def _parts_ordered(text: str) -> str:
    """Markdown parts, each heading after the first saying "(after X)" of the part just before: the first
    heading dropped, the others "then"; the text as it is otherwise."""
    heads = list(_HEADING.finditer(text))
    if len(heads) < 2 or heads[0].start() != 0 or heads[0]["after"] or not any(h["hashes"] for h in heads):
        return text
    for before, head in zip(heads, heads[1:], strict=False):
        if (head["after"] or "").lower() != before["id"].lower():
            return text
    out, pos = "", 0
    for i, head in enumerate(heads):
        out += text[pos : head.start()].rstrip()
        if i:
            out += ". then " if not out.endswith(".") else " then "
        pos = head.end()
    return out + text[pos:]


# "Don't put X on P until then." after a sentence: "Then put X on P." (the sentence before is "then")
_UNTIL_THEN = re.compile(
    r"(?<=[.!?;]\s)(?P<not>don't|dont|do\s+not)\s+(?:start\s+(?:putting|placing)|begin\s+(?:putting|placing)|put|"
    r"place)\s+(?P<rest>[^.;!?]+?)\s+until\s+(?:then|that's\s+done|that\s+is\s+done|you've\s+done\s+that)"
    r"\s*(?P<end>[.!?]|$)",
    re.IGNORECASE,
)


def _then_put(m: re.Match[str]) -> str:
    if re.search(r"\b(?:not|don't|never|until|unless|before|after)\b", m["rest"], re.IGNORECASE):
        return m[0]
    return f"Then put {m['rest']}{m['end']}"
