"""What no spec says at all, judged in word accounting (`accounting.account`): a question, a vague amount
or place, a time, waiting on a state or an event, an optional step, an instruction given before. Apart from
`unsupported_steps` (steps that no base task does): these words name no step at all. The phrases of a
repetition, a condition and a duration's numbers and units are in `vague_words.txt` (h311)."""

from __future__ import annotations

import re
from functools import cache

from nl2hltl2plan.language.content_words import Unread, phrase_list_pattern, phrase_words
from nl2hltl2plan.language.grounding import Mention, sentence_start
from nl2hltl2plan.language.piece_words import unsure_pieces

# "some apples", "half of the mugs", "every other mug", "the rest": how many is not said
# "three quarters of the eggs", "a third of the apples", "50% of the mugs" too (read as every egg, h297)
_VAGUE_AMOUNT = re.compile(
    r"\b(?:some|most|half|every other|a (?:bunch|number|handful|lot) of|lots of|plenty of"
    r"|(?:a|one|two|three|four)\s+(?:quarters?|thirds?|fifths?)|\d+\s*(?:%|percent|per\s+cent))"
    r"(?:\b|(?<=%))(?: of)?"
)
# "half the lettuce", "a quarter of an apple": a part of one thing, which no base task moves (a slice is a
# task's own word: "a slice of lettuce")
_PART = re.compile(
    r"\b(?:(?:a|one)\s+half\s+of|half(?:\s+of)?|(?:a|one)\s+(?:quarter|third)\s+of|(?:a\s+)?(?:part|portion)\s+of)"
    r"\s+(?:the\s+|an?\s+|your\s+|my\s+)?"
)
_PART_OF_ONE = "a part of one thing: no base task moves a part; say 'a slice of' or the whole thing"
# not "the roll ones before the others": the other tasks (h190)
_THE_REST = re.compile(r"(?<!\bbefore )(?<!\bafter )\bthe (?:rest|remaining(?: ones)?|others)\b")
# "A. When the rest is done, B" names the tasks said before (`grammar.references.said_before`), not an amount
_REST_DONE = re.compile(r" (?:is|are|has been|have been|gets|get) (?:done|finished|complete)")
_VAGUE_PIECES = re.compile(  # "a few slices": pieces are no mention, so the count check never sees them
    r"\b(?:some|most|half|a few|few|several|many|multiple|a couple of)(?: of)?(?: the)? "
    r"(?:slices|pieces|bits|chunks)\b"
)
# "put it away", "anywhere but the sofa", "somewhere": where is not said
_VAGUE_PLACE = re.compile(
    r"\b(?:(?:put|tidy|store|stow|pack|clear)\s+(?:\w+\s+){0,3}?away|anywhere|somewhere|elsewhere|everywhere|"
    r"wherever)\b"
)
# "then clean up.", "and wash up after": a chore with no thing, which no base task does; the readers drop it
# or give its verb to the thing before ("put the apple in the fridge, then wash up": a washed apple), so it
# is named (h246); "clean up the pencils" (collect them) has its thing and is left to the readers
_CHORE = re.compile(
    r"\b(?:clean|wash|tidy|neaten|straighten)(?:\s+(?:it|things|everything))?\s+up\b"
    r"(?=\s*(?:[,.;!?]|$|(?:and|then|after|afterwards|please|too|as\s+well)\b))"
)
_PLACE_AFTER = re.compile(r"[^,.;!?]*?\b(?:in|into|on|onto|inside|under|to)\b")
# "in a second box": the ordinal before a thing ("another box"), no time (h190); "in a second, put ..." stays
_ORDINAL_SECOND = r"(?<!\ba second)|(?<=\ba second)(?!\s+(?!(?:and|or|then|to|so|please)\b)[a-z])"
_CLOCK_TIME = (
    r"|for a (?:little\s+|short\s+)?(?:while|bit|moment)"
    r"|(?:at|for|by|until)\s+\d{1,2}(?::\d\d)?(?:\s*(?:am|pm|o'clock))?"
    r"|(?:before|after|around)\s+\d{1,2}(?::\d\d(?:\s*[ap]m)?|\s*(?:am|pm|o'clock))"
    r"|(?:in\s+the|during\s+the|this|every|each|tomorrow|at)\s+(?:morning|afternoon|evening|night)"
    r"|(?:every|each)\s+(?:single\s+|other\s+)?(?:day|week|month|weekday|weekend|hour|time))\b"
)


@cache
def counted() -> str:
    """A count in digits or spelled number words (vague_words.txt: "ninety", "forty-five", "one hundred"),
    "and a half" after it, as a regular expression with no context and no flags."""
    spelled = "|".join(sorted(phrase_words("vague_words.txt", "number"), key=len, reverse=True))
    return rf"(?:\d+(?:\.\d+)?|(?:{spelled})(?:[-\s]+(?:{spelled}))*)(?:\s+and\s+a\s+half)?"


@cache
def _time() -> re.Pattern[str]:
    """A duration or a wait counted in units of time ("for two minutes", "for ninety seconds", "in twenty
    mins", "for half an hour", "for a minute or two", "for another ten minutes"), or a clock time. A count
    in digits or number words needs no opener ("microwave it forty-five seconds"); "a", "a few" do ("for a
    minute": "wait a minute" is no duration)."""
    units = "|".join(sorted(phrase_words("vague_words.txt", "unit"), key=len, reverse=True))
    loose = r"a|an|half\s+an?|a\s+half|a\s+few|a\s+couple(?:\s+of)?|several|a\s+number\s+of"
    amount = rf"(?:{loose}|{counted()})(?:\s+(?:more|extra|additional|further|full|whole|good))?"
    # "for another minute", "for an extra ten minutes", "for the next hour"
    more = r"(?:another|an?\s+(?:extra|additional|further|full|whole|good)|the\s+(?:next|whole|entire|full))"
    tail = r"(?:\s+(?:and\s+a\s+half|or\s+(?:so|two|three|more|\d+)))?"
    opener = r"(?:for|in|within|after|about|around|roughly|approximately)"
    opened = rf"{opener}\s+(?:{more}(?:\s+{amount})?|{amount})"
    return re.compile(
        rf"\b(?:(?:{opened}|{counted()})\s+(?:{units})\b{tail}(?:{_ORDINAL_SECOND}){_CLOCK_TIME}", re.I
    )


@cache
def _phrases(kind: str) -> re.Pattern[str]:
    """The phrases of one kind of vague_words.txt (`repetition`, `condition`), each a whole word sequence; a
    `_closing` kind's only where it closes its clause ("rinse and repeat.", not "repeat with the cup")."""
    closing = r"(?=\s*(?:[,.;:!?)]|$))" if kind.endswith("_closing") else r"\b"
    return re.compile(rf"\b{phrase_list_pattern('vague_words.txt', kind)}{closing}", re.I)


# "when the microwave is free", "once the drawer is empty": a state no task brings about
_STATE_CONDITION = re.compile(
    r"\b(?:when|whenever|once|while|as soon as|until)\s+(?:the|a|an|my|your|it|they)\b[^,.;!?]{0,30}?"
    r"(?:\b(?:is|are|gets|becomes)|['’](?:s|re))\s+(?:not\s+)?(?:free|empty|full|open|opened|closed|shut|ready|"
    r"available|dirty|busy|occupied|wet|dry|off|on)\b(?!\s+(?:the|a|an|top)\b)"
)
# "when the movie ends", "before the guests arrive": an event of something that is no thing of the world (a
# named thing's event, "after the apple finishes cooling", is left to the readers)
_EVENT = re.compile(
    r"\b(?:when|whenever|once|after|before|until|till|as soon as)\s+"
    r"(?:the|a|an|my|your|our|his|her|their)?\s*"
    r"(?P<who>[a-z]+(?:\s+[a-z]+)?)\s+(?:ends?|starts?|begins?|finish(?:es)?|arrives?|leaves?|comes?|returns?"
    r"|wakes?(?:\s+up)?|rings?|stops?|is\s+over|gets?\s+(?:home|back|here|up))\b"
)
# who may end or finish a step of the task itself ("after you finish", "when both are done")
_DOERS = frozenset("you we i it they that this these those both each all everything robot robots".split())
# "Optional: put X on Y", "optionally", "time permitting": a step the spec would have to leave to the robot's
# choice, which no hierarchical spec says (every task of it is required), so the words are refused; "the
# order is optional" is a freedom of the order (the free-order phrases), not of a step
# "in the fridge, or the sink, whichever": a choice left to the robot ("whichever order": a free order)
_CHOICE = re.compile(
    r"\bwhichever\b(?=\s*(?:[,.;!?]|$|(?:is|one|works|suits)\b|you\s+(?:like|prefer|want)\s*(?:[,.;!?]|$)))"
)
_OPTIONAL = re.compile(r"\b(?:optional(?:ly)?|time permitting|if you feel like it)\b")
_ORDER_TOPIC = re.compile(r"\b(?:order|ordering|sequence)\b")
# "same as yesterday", "like last time", "the usual", "as always": an instruction given before, which the
# system never saw, so what it asks is unknown and refused; "as before" / "like before" may point at an
# earlier step of this same instruction (ALFRED's annotators write it so) and are not listed
_PAST = r"(?:yesterday|last\s+(?:time|week|night)|the\s+other\s+day|usual|always)"
# "the way you always do", "like you usually do", "like you did before" too (h297; "as before" may point at
# a step of this instruction)
_HABIT = (
    r"(?:the\s+way|like|as)\s+(?:you|we)\s+(?:(?:always|usually|normally|generally)\s+(?:do|did)(?:\s+it)?"
    r"|did\s+(?:it\s+)?(?:before|earlier|last\s+time|yesterday))"
)
_UNSEEN_INSTRUCTION = re.compile(
    rf"\b(?:(?:the\s+)?same\s+as\s+{_PAST}|(?:just\s+)?like\s+{_PAST}|{_HABIT}|as\s+(?:usual|always|last\s+time|yesterday)"
    r"|the\s+usual|(?:do|repeat)\s+(?:that|the\s+same)\s+again|what\s+you\s+did\s+(?:yesterday|last\s+time))\b"
)
# "in its own cabinet", "one per drawer", "in separate drawers", "on a different armchair": a place for each
# thing, while a base task names a kind of place, never which one (h297); the place must be a thing of the
# world, so the tabletop's "its own region" (no household mention) is left to its reader
_EACH_ITS_OWN = re.compile(
    r"\b(?:(?:in|into|on|onto|inside|to)\s+(?:(?:its|their|his|her)\s+own|(?:an?\s+|the\s+|two\s+|three\s+|\d+\s+)?"
    r"(?:separate|different|distinct|individual))|per|apiece\s+(?:in|on))\s+"
)
_OF_ITS_OWN = re.compile(r"\s+of\s+(?:its|their|his|her)\s+own\b")  # "into a drawer of its own"
_EACH_ITS_OWN_WHY = "a place for each thing: a base task names a kind of place, never which one"
# "have the second robot put ...", "robot one should ...", "the robot on the left ...": a task given to one
# robot, while the planner shares the tasks among the robots itself (h297); "Robot one, cleared to ...": an
# address
_ONE_ROBOT = re.compile(
    r"\b(?:(?:the|a|an|your)\s+(?:first|second|third|fourth|other|another|left|right|\w+est|next)\s+(?:robot|bot)\b"
    r"|another\s+(?:robot|bot)\b|(?:robot|bot)\s+(?:one|two|three|four|no\.?\s*\d+|#?\d+)\b(?!\s*,)"
    r"|(?:one|each|either|both|neither|all)\s+of\s+(?:the\s+|you\s+)?(?:robots|bots)"
    r"|(?:robot|bot)\s+(?:on\s+the\s+(?:left|right)|nearest|closest)\b)"
)
_ONE_ROBOT_WHY = "a task given to one robot: the planner shares the tasks among the robots itself"
# "between putting the apple in the fridge and putting the bread on the counter, put the mug in the sink":
# a task said between two others, which no order rule reads (h297), or "A and B, and between those, C",
# "halfway through that, C"; "between the lamps", "onto the counter between them." are places, and "no
# dependencies between them, so ..." frees an order
_BETWEEN_TASKS = re.compile(
    r"\b(?:in\s+)?between\s+(?:\w+ing|the\s+\w+\s+(?:task|job|step)s?)\b|\bin\s+between\b(?=\s*[,.;:])"
    r"|(?:^|(?<=[,.;:]\s)|(?<=\band\s))between\s+(?:those|these|them|both|the\s+two)(?=\s*,)"
    r"|\b(?:halfway|midway|partway)\s+through\b|\bin\s+the\s+middle\s+of\s+(?:that|this|it|\w+ing)\b"
)
_BETWEEN_WHY = "a task said between or during others, which no order rule reads: say 'after A, do C, then B'"
# "put the apple in the fridge, failing that the counter" / ", else the counter" / ", as a backup ...": a
# place to fall back on, which the grammar read as a cooled apple on the counter (exit 0, h297); no base
# task tries one place and then another ("anything else", "somewhere else" are no fallback)
_FALLBACK = re.compile(
    r"\b(?:failing\s+(?:that|this|which|it)|as\s+a\s+(?:fallback|backup|last\s+resort)|if\s+(?:that|this|it)\s+"
    r"(?:fails|doesn't\s+work|does\s+not\s+work|won't\s+work))\b|(?:,\s*|\bor\s+)else\b(?!\s+(?:do|to)\b)"
)
# "a second time", "once more", "after each apple goes in": a step done again, which no base task is (h297)
_AGAIN = re.compile(
    r"\b(?:(?:a\s+(?:second|third|fourth)|one\s+more|another)\s+time|once\s+(?:more|again)"
    r"|(?:after|before|following)\s+(?:each|every)\s+(?!other\b|time\b|rule\b)\w+)\b"
)
# "the white mug ... rather than the black one": two things of one type told apart by a word that no spec
# says (its atoms name types, h297); "not the red one, the blue one" is a correction's
_ONE_OF_A_KIND = re.compile(
    r"\b(?:rather\s+than|instead\s+of)\s+the\s+(?!other\b|same\b|first\b)\w+\s+ones?\b"
)
# "is the apple in the fridge", "what is in the fridge", "which plate should it go on?"; not "what I need
# is ...", a need said as a pseudo-cleft
_QUESTION = re.compile(
    r"^\s*(?:(?:is|are|was|were|does|did|how many|how much)\b|(?:where|what|which|who|whose|why)\s+"
    r"(?:(?:is|are|was|were|do|does|did|can|could|should|would|will|has|have)\b|.*\?\s*$))"
)


def vague_words(instruction: str, mentions: list[Mention], chosen: bool = False) -> list[Unread]:
    """What no base task can take: a question ("is the apple in the fridge?"), a vague amount of a plural
    ("some apples", "the rest"), a vague place ("put it away", "anywhere but the sofa"), a duration or a
    clock time ("for two minutes", "set it for 7"), waiting on a state ("when the microwave is
    free"), a step made optional ("Optional: put ...") and an instruction given before ("same as
    yesterday", "the usual")."""
    lowered = instruction.lower()
    out = [
        Unread(q.strip(), "action", "a question, not a request: say what to do")
        for q in re.findall(r"[^.;!?]*[.;!?]?", lowered)
        if q.strip() and _QUESTION.match(q)
    ]
    for m in _VAGUE_AMOUNT.finditer(lowered):
        named = next((x for x in mentions if m.end() <= x.char_start <= m.end() + 12), None)
        if named is not None and (named.plural or m.group(0) == "every other"):
            out.append(Unread(lowered[m.start() : named.char_end], "count", "a vague count: say how many"))
    out += [
        Unread(lowered[m.start() : named.char_end], "count", _PART_OF_ONE)
        for m in _PART.finditer(lowered)
        for named in [next((x for x in mentions if x.char_start == m.end()), None)]
        if named is not None and not named.plural
    ]
    out += unsure_pieces(lowered)  # "a leaf of lettuce": maybe no slice (piece_words.py)
    out += [
        Unread(m.group(0), "count", "a vague count: say how many")
        for m in (*_THE_REST.finditer(lowered), *_VAGUE_PIECES.finditer(lowered))
        if not (_REST_DONE.match(lowered, m.end()) and re.search(r"[,.;!?]", lowered[: m.start()]))
    ]
    out += [
        Unread(m.group(0), "place", "a vague place: name it")
        for m in _VAGUE_PLACE.finditer(lowered)
        if not (m.group(0).endswith("away") and _PLACE_AFTER.match(lowered, m.end()))  # "away in a cabinet"
    ]
    chore = "a chore with no thing: say what to put where"
    out += [Unread(m[0], "action", chore) for m in _CHORE.finditer(lowered)]
    out += [Unread(m.group(0), "count", "no base task takes a time") for m in _time().finditer(lowered)]
    out += [
        Unread(m[0], "place", "a choice left open: say which one")
        for m in _CHOICE.finditer(lowered)
        # "in the sink or on the counter, whichever": the choice a task reads (`place_choices`, `chosen`)
        if not (chosen and re.search(r"\bor\b", lowered[sentence_start(lowered, m.start()) : m.start()]))
    ]
    out += [
        Unread(m.group(0), "condition", "an optional step: the spec requires every task; say it or drop it")
        for m in _OPTIONAL.finditer(lowered)
        if not _ORDER_TOPIC.search(lowered[sentence_start(lowered, m.start()) : m.start()])
    ]
    out += [
        Unread(m.group(0), "action", "it points at an instruction this one does not contain: say the tasks")
        for m in _UNSEEN_INSTRUCTION.finditer(lowered)
    ]
    out += [
        Unread(m[0], "condition", "no base task waits for an event: say what to do")
        for m in _EVENT.finditer(lowered)
        if m["who"].split()[0] not in _DOERS
        and not any(m.start("who") <= x.char_start < m.end("who") for x in mentions)
    ]
    out += [
        Unread(lowered[m.start() : named.char_end].strip(), "place", _EACH_ITS_OWN_WHY)
        for m in _EACH_ITS_OWN.finditer(lowered)
        for named in [next((x for x in mentions if x.char_start == m.end()), None)]
        if named is not None
    ]
    out += [
        Unread(lowered[named.char_start : m.end()], "place", _EACH_ITS_OWN_WHY)
        for m in _OF_ITS_OWN.finditer(lowered)
        for named in [next((x for x in mentions if x.char_end == m.start()), None)]
        if named is not None
    ]
    out += [Unread(m[0], "action", _ONE_ROBOT_WHY) for m in _ONE_ROBOT.finditer(lowered)]
    out += [Unread(m[0], "order", _BETWEEN_WHY) for m in _BETWEEN_TASKS.finditer(lowered)]
    again = "no base task is done more than once: say each time as its own task"
    repeated = (*_AGAIN.finditer(lowered), *_phrases("repetition").finditer(lowered))
    repeated += (*_phrases("repetition_closing").finditer(lowered),)
    out += [Unread(m[0], "count", again) for m in repeated]
    waits = "no base task waits on a condition: say what to do"
    out += [Unread(m[0], "condition", waits) for m in _phrases("condition").finditer(lowered)]
    kind = "a thing told from another of its type by a word no spec says (its atoms name types)"
    out += [Unread(m[0], "object", kind) for m in _ONE_OF_A_KIND.finditer(lowered)]
    fallback = "a place to fall back on: no base task tries one place and then another; say which"
    out += [Unread(m[0].strip(" ,"), "condition", fallback) for m in _FALLBACK.finditer(lowered)]
    return out + [
        Unread(m.group(0), "condition", "no base task waits on a state: say what to do")
        for m in _STATE_CONDITION.finditer(lowered)
    ]
