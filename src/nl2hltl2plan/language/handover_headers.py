"""The layout of a handover message around its commands (issue 24): a memo's or e-mail's headers and a
role's sign-off, a dialogue of two speakers, a work order's labelled fields and a game's numbered rules.
`headed(text)` says the message as the plain lines the handover reader reads; words in
`handover_headers.txt`, the labels and titles in `heading_heads.txt` (`headings.heading_words`). Each
form is read only where all of it is what it claims to be; a line that holds any other word stays as it
was, to be read or refused by name.

- Headers opening the message: "Subject:" / "Re:" is a title, dropped where every word of it that
  names something is said again in the body, in the same order ("Subject: block moves for Tuesday"
  over "Move the three blocks ..."); "To:" / "From:" / "CC:" name only people (a team, a role, a
  capitalised name) and "Date:" only a day. A title line "Work order" is dropped.
- A sign-off that is a role, on the last line: "- Shift lead", "Lee, line supervisor".
- A dialogue: every line (or sentence) a turn "Name: ...", two speakers taking turns, three turns or
  more, one of them a question. The labels go; a question for the place ("Where to?", "Which
  regions?") puts its answer into the command before it ("Move the three blocks. / Where to? / To
  the opposite side." is "Move the three blocks to the opposite side."); any other question stays
  before its answer for `handover_answers`. (The labels "A:" / "B:" are also arms' names; a spec
  never says which arm acts, so dropping them changes no spec.)
- A work order: "Task: transfer", "Objects: the three blocks", "Destination: the opposite side", in
  any order, are one command at the first of them; "Order:", "Constraint:", "Note:" ... are
  sentences of their own, and "Final step:" is "Finally, ...". A work order said as a title and
  sentences ("Work order #12 - move the three blocks ... . Constraints: red before blue; no block on
  H.") loses its title, and its remark line's parts become sentences of their own.
- "Rule 1:" opening a line is a bullet (rules are not steps: no order between them).
"""

from __future__ import annotations

import re
from functools import lru_cache

from nl2hltl2plan.language.content_words import stems, word_categories
from nl2hltl2plan.language.handover_discourse import MEANING, frame_words
from nl2hltl2plan.language.headings import heading_pattern, heading_words

# the labels of the headers and fields, and a record's title: headings' words (`heading_heads.txt`)
_HEADINGS = (
    "topic_label", "people_label", "day_label", "title", "task_field", "object_field", "place_field",
    "remark_field", "last_field", "rule_label",
)  # fmt: skip


@lru_cache(maxsize=1)
def _words() -> dict[str, frozenset[str]]:
    heads = heading_words()
    return word_categories("handover_headers.txt") | {kind: heads[kind] for kind in _HEADINGS}


_FIELD = re.compile(r"^\s*([A-Za-z][A-Za-z ]{0,20}?)\s*:\s*(.*?)\s*$")


def _label(line: str, *kinds: str) -> tuple[str, str] | None:
    """(the label's kind, the value) of a line 'Label: value' whose label is of one of `kinds`."""
    m = _FIELD.match(line)
    if m is None:
        return None
    key = "_".join(m[1].lower().split())
    kind = next((k for k in kinds if key in _words()[k]), None)
    return (kind, m[2]) if kind else None


def _tokens(text: str) -> list[str]:
    return re.findall(r"[a-z]+|\d+", text.lower())


def _stem(word: str) -> str:
    """'moves', 'moving', 'move' -> 'mov'; 'swapping' -> 'swap': enough to match a title's words (the
    shortest of the project's `stems`, less a final 'e')."""
    return min(stems(word), key=lambda s: (len(s), s)).removesuffix("e")


def _restated(title: str, body: str) -> bool:
    """Every word of the title that is not a function, topic or day word is said again in the body, in
    the title's order."""
    kept = frame_words()["function"] | _words()["topic"] | _words()["day"] | frame_words()["month"]
    kinds = {_stem(w) for w in _words()["kind"]}  # "regions", "blocks": said anywhere in the body
    body_words = [_stem(w) for w in _tokens(body)]
    wanted = [_stem(w) for w in _tokens(title) if w not in kept]
    said = iter(body_words)
    return all(w in body_words for w in wanted if w in kinds) and all(
        any(w == s for s in said) for w in wanted if w not in kinds
    )


def _people(value: str) -> bool:
    """'Dana, shift lead', 'all robots', 'floor supervisor': a team, a role or a capitalised name only."""
    words = _words()
    allowed = words["people"] | words["role"] | words["role_qualifier"] | frame_words()["function"]
    tokens = re.findall(r"[A-Za-z]+", value)
    return bool(tokens) and all(
        t.lower() in allowed or (len(t) > 1 and t[0].isupper() and not MEANING.fullmatch(t.lower()))
        for t in tokens
    )


def _day(value: str) -> bool:
    allowed = _words()["day"] | frame_words()["month"] | _words()["topic"] | frame_words()["function"]
    return all(t.isdigit() or t in allowed for t in _tokens(value))


def _signed_by_role(line: str) -> bool:
    """'- Shift lead', 'Lee, line supervisor': a role (and a name), nothing else."""
    text = re.sub(r"^\s*[-–—~]+\s*|[.!\s]+$", "", line)
    roles = _words()["role"]
    return any(t.lower() in roles for t in re.findall(r"[A-Za-z]+", text)) and _people(text)


def _unheaded(lines: list[str]) -> list[str]:
    """The lines without the title line, the header lines that open them and a role's sign-off; a header
    that is not only a title, people or a day stays as it was said (it is refused by its words)."""
    out = list(lines)
    while out and "_".join(_tokens(out[0])[:2]) in _words()["title"] and len(_tokens(out[0])) <= 3:
        out.pop(0)
    headers: list[tuple[str, str, str]] = []
    while out and (field := _label(out[0], "topic_label", "people_label", "day_label")):
        headers.append((out.pop(0), *field))
    if len(out) > 1 and _signed_by_role(out[-1]):
        out.pop()
    body = "\n".join(out)
    said = {"topic_label": lambda v: _restated(v, body), "people_label": _people, "day_label": _day}
    return [line for line, kind, value in headers if not said[kind](value)] + out


_PREPOSITION = re.compile(r"(?i)^(?:to|on|onto|into|in|at|over\s+to)\b")
_RULE = re.compile(r"(?im)^\s*rule\s*#?\s*(?:\d+|one|two|three|four|five)\s*(?::|\.|\)|\s[-–—]+)\s*")


def _work_order(lines: list[str]) -> list[str]:
    """'Task: transfer / Objects: the three blocks / Destination: the opposite side / Order: red before
    blue' as 'transfer the three blocks to the opposite side.' and 'red before blue.'."""
    kinds = ("task_field", "object_field", "place_field", "remark_field", "last_field")
    fields = [_label(line, *kinds) for line in lines]
    found = {f[0]: f[1] for f in fields if f}
    if "object_field" not in found or sum(f is not None for f in fields) < 2:
        return lines
    verb = found.get("task_field", "move")
    main = [f[0] for f in fields if f and f[0] in kinds[:3]]
    if len(verb.split()) != 1 or len(main) != len(set(main)):
        return lines  # a task said in words of its own, or a field said twice: left as it is
    place = found.get("place_field", "")
    if place and not _PREPOSITION.match(place):
        place = f"to {place}"
    goal = " ".join(f"{verb} {found['object_field']} {place}".split()) + "."
    out: list[str] = []
    for line, field in zip(lines, fields, strict=True):
        if field is None:
            out.append(line)
        elif field[0] in kinds[:3]:
            out += [goal] if goal not in out else []
        else:
            out.append(("Finally, " if field[0] == "last_field" else "") + field[1].rstrip(".") + ".")
    return out


_TURN = re.compile(r"(?:^|(?<=[.!?])\s+|\n\s*)(?P<who>[A-Za-z]+)\s*:\s*")
_PLACE_QUESTION = re.compile(
    r"(?i)^(?:and\s+)?(?:(?:over|to|going)\s+)?where(?:\s+(?:to|do\s+(?:they|those|these|it)\s+go|should\s+"
    r"(?:they|it)\s+go))?\s*\?$|^(?:and\s+)?(?:which|what)\s+(?:regions?|places?|spots?|destination)\s*\?$"
)


def _dialogue(text: str) -> list[str] | None:
    """The turns of a two-speaker dialogue as sentences (see the module docstring), or None."""
    turns = list(_TURN.finditer(text))
    if len(turns) < 3 or text[: turns[0].start()].strip():
        return None
    said = [(m["who"].lower(), text[m.end() : nxt.start() if nxt else None].strip())
            for m, nxt in zip(turns, [*turns[1:], None], strict=True)]
    labels = {who for who, _ in said}
    known = set().union(*(_words()[k] for k in _words() if k.endswith(("label", "field"))))
    alternate = all(a[0] != b[0] for a, b in zip(said, said[1:], strict=False))
    if len(labels) != 2 or labels & known or not alternate or not any(w.endswith("?") for _, w in said):
        return None
    out: list[str] = []
    for k, (_, words) in enumerate(said):
        answer = said[k + 1][1] if k + 1 < len(said) else ""
        if out and out[-1] is _ASKED:
            out.pop()
        elif answer and _PLACE_QUESTION.match(words) and out:
            out[-1] = _with_place(out[-1], answer)
            out.append(_ASKED)
        elif answer and (_STEP_QUESTION.match(words) and _ORDER_OPENS.match(answer) or _NO_BUT.match(answer)):
            continue  # the answer says it all: "Then? / Then put it on G.", "Else? / No, never on H."
        elif answer and (about := _ABOUT.match(words)) and _PRONOUN.search(answer):
            said[k + 1] = (said[k + 1][0], _PRONOUN.sub(about["blocks"], answer, count=1))
        else:
            out.append(_NO_BUT.sub("", words) if k and _NO_BUT.match(words) else words)
            out[-1] += "" if words[-1:] in ".!?" else "."
    return [w for w in out if w is not _ASKED]


_ASKED = "<asked>"  # the place question's answer, already said in the command before it
_STEP_QUESTION = re.compile(r"(?i)^(?:and\s+)?(?:what\s+)?(?:then|next|after\s+that|afterwards)\s*\?$")
_ORDER_OPENS = re.compile(
    r"(?i)^(?:and\s+)?(?:then|next|after\s+(?:that|all\s+of\s+that|this)|afterwards|finally)\b"
)
# "No, never on any other region.": a "no" that says the rule again in full (not "No, nothing.")
_NO_BUT = re.compile(r"(?i)^no\s*,\s*(?=(?:\S+\s+){2,}\S)(?=.*\b(?:regions?|side|[e-j])\b)")
_ABOUT = re.compile(
    r"(?i)^(?:and\s+)?(?:(?:anything|what)\s+(?:else\s+)?about|what\s+(?:do\s+(?:we|i|you)\s+do|happens|should\s+"
    r"happen)\s+(?:with|to))\s+(?P<blocks>[^?]+?)\s*\?$"
)
_PRONOUN = re.compile(r"(?i)\b(?:it|them)\b")


def _with_place(command: str, answer: str) -> str:
    """'Move the three pillars, please.' + 'To E, F and G.' -> 'Move the three pillars to E, F and G,
    please.'"""
    place = answer.rstrip(".!")
    place = place if _PREPOSITION.match(place) else f"to {place}"
    place = place[0].lower() + place[1:]
    end = command[-1] if command[-1:] in ".!?" else "."
    body = command.rstrip(".!?")
    if re.search(r"\bsomewhere\b", body):
        return re.sub(r"\bsomewhere\b", place, body, count=1) + end
    head, comma, tail = body.partition(", ")
    return f"{head} {place}{comma}{tail}{end}"


def _titled(text: str) -> str:
    """'Work order #12 - move ... . Constraints: red before blue; no block on H.' as 'move ... .' then
    'red before blue.' and 'no block on H.': a title said on the command's line goes, and a remark field
    after a sentence becomes its parts (joined by semicolons) as sentences of their own."""
    opening = re.match(
        rf"(?i)^\s*{heading_pattern('title')}\s*(?:(?:#|no\.?)\s*\d+|\d+)?\s*(?::|[-–—]+)\s*(?=\S)", text
    )
    if opening is None:
        return text
    body = text[opening.end() :]
    remark = re.search(rf"(?im)(?<=[.!?])[ \t]+{heading_pattern('remark_field')}[ \t]*:[ \t]*(.*)$", body)
    if remark is None:
        return body
    said = [r.strip().rstrip(".") for r in remark[1].split(";")]
    sentences = " ".join(r[:1].upper() + r[1:] + "." for r in said if r)
    return f"{body[: remark.start()]} {sentences}{body[remark.end() :]}"


def headed(text: str) -> str:
    """The message said as the plain lines the handover reader reads (see the module docstring)."""
    turns = _dialogue(text)
    if turns is not None:
        return " ".join(turns)
    lines = _unheaded(_titled(text).splitlines())
    lines = [_RULE.sub("- ", line) for line in lines]
    return "\n".join(_work_order(lines))
