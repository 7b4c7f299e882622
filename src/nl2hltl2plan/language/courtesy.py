"""Courtesy frames that carry nothing ("if you don't mind", "if it isn't too much trouble", "when you have a
moment", "while you're at it"; the list is `courtesy.txt`): removed before the parser backends read, so
that a politeness frame is never read as a condition, a negation or an order.

>>> without_courtesy("If you don't mind, put the apple in the fridge.")
'put the apple in the fridge.'
>>> without_courtesy("put the mug and, while you're at it, the cup in the sink")
'put the mug and the cup in the sink'
>>> without_courtesy("if you don't mind the mess, put the apple in the fridge")
"if you don't mind the mess, put the apple in the fridge"

Every reader takes its courtesy words from `courtesy.txt` through `courtesy_pattern` and `courtesy_words`
(one list each of greetings, forms of address, thanks and sign-offs). `without_greetings` removes what
only greets, replies or thanks around a request, for the household and tabletop readers alike:

>>> without_greetings("Hi team, put the apple in the fridge. Much appreciated!", lambda name: False)
'put the apple in the fridge.'
"""

from __future__ import annotations

import re
from collections.abc import Callable
from functools import cache
from typing import NamedTuple

from nl2hltl2plan.language.content_words import (
    ROOM_WORDS,
    Unread,
    categories,
    phrase_list_pattern,
    phrase_words,
)


def courtesy_pattern(*kinds: str) -> str:
    """The phrases of these kinds of `courtesy.txt` as one regular expression (no context, no flags)."""
    return "(?:" + "|".join(phrase_list_pattern("courtesy.txt", kind) for kind in kinds) + ")"


@cache
def courtesy_words(kind: str) -> frozenset[str]:
    """The words of one kind of `courtesy.txt` ("courtesy_word" takes in the greetings and addresses)."""
    words = phrase_words("courtesy.txt", kind)
    if kind == "courtesy_word":
        return words | courtesy_words("greeting") | courtesy_words("address")
    return words

# a frame with the comma after it, where its clause ends (a comma, a sentence's end or the text's end)
_FRAMES = courtesy_pattern("clause", "time")
# (or before the request it frames, asked as a question: "when you get a sec could you put ...", h202)
_FRAME = re.compile(
    rf"(?:,\s*)?\b{_FRAMES}\b(?=\s*(?:[,.;:!?]|$)|\s+(?:could|can|would|will)\s+(?:you|u)\b)\s*,?", re.I
)


# an afterthought set off by "oh" inside a sentence ("A and then B oh and put C too"): a new request, not a
# step of the clause before it, so it is a sentence of its own ("A and then B. Also put C too", where C takes
# no order from B); one that opens a sentence ("... B. Oh and put C") is one already, and stays as written
_AFTERTHOUGHT = re.compile(
    rf"(?<=\w)\s*,?\s+oh\s*,?\s+{courtesy_pattern('afterthought')}\s*,?\s+(?=[a-z])", re.I
)
# the same "oh" opening a sentence with no verb ("... B. oh and the towel in the tub too", users_h195dev):
# "Also", as inside one (its "oh" was read as a thing: "put oh in the tub"); before a verb it is "At any
# time," ("... B. Oh, and look at the CD too", users_h200dev, left "Oh" unread after some sentences): an
# afterthought added to what was said takes no order from it ("First, A. ... Oh and move D": D is no later
# than A), unless an order word follows ("oh, and then ...", "oh and after that ..."), which the rules read
_OH_OPENS = rf"(?<=[.;!?])(\s*)oh\s*,?\s+{courtesy_pattern('afterthought')}\s*,?\s+"
_OPENING_OH = re.compile(rf"{_OH_OPENS}(?=(?:the|a|an|both|two|\d)\s)", re.I)
_OPENING_OH_VERB = re.compile(
    rf"{_OH_OPENS}(?!(?:then|after|afterwards|before|first|finally|lastly|next|once|when|while)\b)(?=[a-z])",
    re.I,
)
# "don't forget to put ...", "remember to", "make sure you put ...": a reminder, which asks as "please" asks
# (never a negation); a reminder of a negation is the negation ("remember not to put", "make sure you never
# put": `_reminded`); "don't forget the mug" and "make sure the mug ends up ..." stay, to be read as written
_REMINDER = re.compile(
    rf"\b{courtesy_pattern('reminder', 'reminded')}(?:\s*[,:]\s*|\s+(?:"
    r"(?P<not>not\s+to|to\s+not|to\s+never|never)\s+|to\s+|"
    r"(?:that\s+)?(?:you|u)\s+(?:(?P<neg>don't|dont|do\s+not|never|won't)\s+)?))(?=[a-z])",
    re.I,
)


# "don't forget the spatula - it goes in the sink", "remember the mug: it goes ...": the thing reminded of is
# the subject of the placing said after it ("the spatula goes in the sink"); a reminder of a thing with no
# placing after it ("don't forget the mug") stays, to be read or refused
_REMINDED_THING = re.compile(
    rf"\b{courtesy_pattern('reminder', 'reminded')}\s+(?:about\s+)?"
    r"(?P<np>(?:the|a|an|your|my|two|both)\s+[a-z]+(?:\s+[a-z]+){0,3}?)\s*(?:-+|–|—|,|:)\s*"
    r"(?P<pron>it|they|that|that\s+one|this\s+one)\s+(?P<verb>goes|go|belongs|belong|needs\s+to\s+go|should\s+go)\b",
    re.I,
)


def _reminded_thing(m: re.Match[str]) -> str:
    """ "the spatula - it goes" -> "the spatula goes"; "the mug and the cup - it goes" stays: "it" is one of
    two, and which one the text does not say."""
    if m["pron"].lower() != "they" and re.search(r"\b(?:and|two|both)\b", m["np"], re.I):
        return m[0]
    return f"{m['np']} {m['verb']}"


def _reminded(m: re.Match[str]) -> str:
    """A reminder's replacement: nothing before a request, the negation it reminds of before one."""
    said = (m["not"] or m["neg"] or "").lower()
    return "" if not said else "never " if "never" in said else "do not "
# the fillers a text message ends a request with ("and yeah", "or whatever", "k thx", "lol"), one or more
# after the last word of a sentence: the sentence's end or the text's end must follow, so "or whatever is
# left" and "yeah, put the mug ..." stay as written
_TRAILING = re.compile(
    rf"(?:\s*,?\s*\b{courtesy_pattern('trailing')})+\b(?=\s*(?:[.!?]+(?:\s|$)|$))", re.I
)


# a reason after a request, up to its clause's end: a sentence's end, a comma, "(and) then" or "and" before a
# verb that asks again ("put the mug in the sink because it's dirty and put ..."); `_keeps_reason` decides
_REASON = re.compile(
    rf"\s*,?\s+{courtesy_pattern('reason')}\s+(?P<why>{courtesy_pattern('reason_subject')}\b[^.;!?,]*?)"
    r"(?=\s*(?:[.;!?]|$)|\s*,|\s+(?:and\s+)?then\b|\s+and\s+(?:put|place|set|move|take|bring|grab|get|wash|rinse|"
    r"clean|heat|cool|chill|slice|cut|throw|turn)\b)",
    re.I,
)
# the content-word kinds of a treatment ("washed": verb_clean_place) that a reason may ask for
_TREATMENTS = frozenset({"verb_heat_place", "verb_cool_place", "verb_clean_place", "verb_sliced"})
_KEPT = re.compile(rf"\b{courtesy_pattern('kept')}\b", re.I)


def _keeps_reason(why: str) -> bool:
    """Does a reason stay in the text: it speaks to "you" ("so you can wash it later": a request), or names
    a treatment other than a state the place keeps ("so it gets washed" may ask for the washing), unless it
    is the speaker's own purpose ("so I can wash it later")?"""
    if re.search(r"\b(?:you|u|your|yourself)\b", why, re.I):
        return True
    if re.match(r"(?:i|i'm)\b", why, re.I):
        return False  # the speaker's own purpose ("so I can wash it later"): the speaker does it
    return any(categories(w) & _TREATMENTS for w in re.findall(r"[a-z]+", _KEPT.sub(" ", why).lower()))


# the writer's own later step, after a comma to its sentence's end, naming nothing but a pronoun of what
# was asked ("..., i'll wash them later", "..., i'll deal with it tomorrow"): `courtesy.txt`, `promise`
_PROMISE = re.compile(
    rf"\s*,\s*{courtesy_pattern('promise')}\s+(?:[a-z]+\s+){{1,2}}?(?:it|them|those|these|that|em|'em|both)"
    rf"(?:\s+{courtesy_pattern('promise_when')})?(?=\s*(?:[.;!?]|$))",
    re.I,
)


def without_reasons(text: str) -> str:
    """`text` without the reasons said after its requests (`courtesy.txt`, `reason`), which ask for nothing.

    >>> without_reasons("put the pear in the fridge so it stays cold, then the cup in the sink because it is")
    'put the pear in the fridge, then the cup in the sink'
    >>> without_reasons("put the cup in the sink so it gets washed. put the pen away so you can use it")
    'put the cup in the sink so it gets washed. put the pen away so you can use it'
    >>> without_reasons("two forks in the sink please, i'll wash them later")
    'two forks in the sink please'
    """
    return _PROMISE.sub("", _REASON.sub(lambda m: m[0] if _keeps_reason(m["why"]) else "", text))


def _afterthought(m: re.Match[str]) -> str:
    """ "Oh, and put C" -> "At any time, put C"; "Also" where an order word follows later in the sentence
    ("Oh, and put C first", "... before that"): "At any time" would contradict it and hide it from the check
    of order words (h205); the sentence is then read, or refused by name, as if said with no "oh, and"."""
    rest = re.split(r"[.;!?]", m.string[m.end() :], maxsplit=1)[0]
    ordered = any("order" in categories(w) for w in re.findall(r"[a-z]+", rest.lower()))
    return m[1] + ("" if ordered else "At any time, ")


def without_courtesy(text: str) -> str:
    """`text` without its courtesy frames (and the commas around them) and reminders, an afterthought after
    "oh" a sentence of its own; the text as it was when nothing else is left.

    >>> without_courtesy("put the mug in the sink and then the egg in the fridge, oh and the cup in the sink")
    'put the mug in the sink and then the egg in the fridge. Also the cup in the sink'
    >>> without_courtesy("Robot, don't forget to put the spatula in the drawer!")
    'Robot, put the spatula in the drawer!'
    >>> without_courtesy("put the pear in the fridge and yeah that's it. the cup in the sink or whatever lol")
    'put the pear in the fridge. the cup in the sink'
    """
    out = _OPENING_OH_VERB.sub(_afterthought, _OPENING_OH.sub(r"\1Also ", _TRAILING.sub("", text)))
    out = _AFTERTHOUGHT.sub(". Also ", out)
    out = _REMINDED_THING.sub(_reminded_thing, out)
    out = _FRAME.sub(" ", _REMINDER.sub(_reminded, out))
    out = re.sub(r"\s+([,.;:!?])", r"\1", " ".join(out.split()))
    out = re.sub(r"^[\s,.;:!?]+", "", out)
    return out if re.search(r"\w", out) else text


# what only greets or replies, set apart at a sentence's start before more words ("Hi there,", "Good
# morning!", "No problem!"): it carries nothing, so it goes wherever it stands and whatever clause follows it
# ("Hey, when you're done, put ..."): each reader then reads, or refuses, the words after it as it reads them
# with no greeting (docs/language.md, "Courtesy")
_OPENS = r"(?P<lead>^|(?<=[.!?])\s+)"
# a spoken opener may lead it ("okay so robot, uh, put ..."); an address set apart by a colon or a dash
# ("Robot: ...") may be a speaker's label in a dialogue, which the household grammar alone drops
_GREETING = re.compile(
    rf"{_OPENS}(?:{courtesy_pattern('spoken_opener')}\s*,?\s*)*"
    rf"(?:{courtesy_pattern('greeting', 'address', 'greeting_with')}\s*)+"
    rf"(?:{courtesy_pattern('endearment')}\s*)?[!.,]+\s*(?=\w)",  # "Hi sweetheart," (h261)
    re.I,
)
# a note's heading, the one pattern of it: "Note:", "A message for the robot:" (an address; `without_call`
# drops it), "Note for Sam:", "Note for whoever's home first:" (a name or whoever comes: `without_greetings`
# drops it, unless the name is a thing): it only says who the text is for and names no task
_NOTE_HEADING = (
    rf"(?:a\s+)?{courtesy_pattern('note')}(?:\s+(?:for|to)\s+(?:(?P<name>(?-i:[A-Z][a-z]+))|"
    rf"(?P<whoever>{courtesy_pattern('note_for', 'note_reader')})|(?:the\s+)?{courtesy_pattern('address')}))?"
    r"\s*:\s*"
)
# a call run on into the request at a sentence's start, or set apart by a colon or a dash ("Robot: after you
# put ..."), a note's heading ("Note for the robot:"), which
# only says who the text is for, or a spoken opener before a name ("so the tomato goes ...") (`without_call`)
_CALLED = re.compile(
    rf"{_OPENS}(?:(?:{courtesy_pattern('spoken_opener', 'greeting', 'greeting_with')}\s*,?\s*)+"
    rf"{courtesy_pattern('address')}\s+|{courtesy_pattern('address')}\s*(?::|\s[-\u2013\u2014]+)\s*|"
    rf"{courtesy_pattern('address')}\s+(?=(?:can|could|would|will)\s+you\b|please\b)|"
    rf"{_NOTE_HEADING}|"
    rf"(?:{courtesy_pattern('spoken_opener')}\s+)+(?=(?:the|a|an)\s))"
    r"(?=[a-z])",
    re.I,
)
_REPLY = re.compile(rf"{_OPENS}{courtesy_pattern('reply')}\s*[!.,]+\s*(?=\w)", re.I)
# closing thanks and farewells, one or more, where the text ends ("Thanks!", "Love you, bye.", "Over.")
_THANKS = re.compile(
    rf"(?<=[.!?])(?:\s*{courtesy_pattern('closing', 'farewell', 'praise')}\s*[!.,]*)+\s*$", re.IGNORECASE
)
# a recorded message's opening ("Voicemail:", "Message after the beep:") and a radio call ("Kitchen unit, do
# you read?", "Base to kitchen unit, come in."), each at a sentence's start: they ask for no task (h261)
_CALL_OPENING = re.compile(
    rf"{_OPENS}(?:{courtesy_pattern('voicemail')}\s*(?::|[!.](?=\s)|\s[-\u2013\u2014]+)|"
    rf"{courtesy_pattern('radio_to')}\s*,?\s*{courtesy_pattern('radio_ask')}\s*[?.!]+)\s*(?=\w)",
    re.I,
)
# a note's heading naming who it is for ("Note for Sam:", "Note for whoever's home first:"), `_NOTE_HEADING`
_NOTE_FOR = re.compile(rf"{_OPENS}{_NOTE_HEADING}(?=\S)", re.I)
# (a name may come with a title: "Fondly, Aunt Jo"; or after a closing thanks set off by a stop or a dash:
# "Thanks!! Priya", "Thanks! - Priya")
_SIGN_OFF = re.compile(
    rf"(?<=[.!?])\s*(?i:{courtesy_pattern('sign_off')}\s*,|"
    rf"{courtesy_pattern('sign_off', 'closing')}\s*(?:[!.]+|[!.]*\s*[-\u2013\u2014]+))"
    r"\s*(?P<name>[A-Z][a-z]+(?:\s+[A-Z][a-z]+)?)\W*$"
)


# a closing thanks or sign-off before a lone name that is also a thing ("Cheers, Mug", "Thanks! - Bread",
# "Thank you mug!"): `greeted` keeps it and reports it (the grammar would read the thing as one more item)
_THING_SIGN_OFF = re.compile(
    rf"(?<=[.!?])\s*(?i:{courtesy_pattern('sign_off')}|{courtesy_pattern('closing')})\s*[!.,:]*\s*(?:[-\u2013\u2014]+\s*)?"
    r"(?i:the\s+)?(?P<name>[A-Za-z]+)\W*$"
)


# "Thanks for putting the egg in the fridge": done already, or thanks in advance? no reading can tell (h208)
# ("Thank you for helping": help in general, no step said done)
_THANKED_FOR = re.compile(
    r"\b(?:thanks|thank\s+you|cheers)\s+(?:so\s+much\s+)?for\s+(?!help)[a-z]+ing\b", re.I
)


def thanked_for(text: str) -> list[str]:
    """The thanks for an action in `text` ("Thanks for putting"), which the reader names unread.

    >>> thanked_for("Put the mug in the sink. Thanks for putting the egg away!")
    ['Thanks for putting']
    """
    return [m[0] for m in _THANKED_FOR.finditer(text)]


SIGNED_THING_WHY = "a sign-off's name that is also a thing: say the thing in a request of its own"


def courtesy_unread(text: str, names_a_thing: Callable[[str], bool]) -> list[Unread]:
    """The courtesy no reading can tell the meaning of, named unread: a sign-off's name that is also a thing
    (`greeted` keeps it) and thanks for an action (`thanked_for`)."""
    signed = _signed_thing(text, names_a_thing)  # the sign-off `greeted` kept: no second pass of greeted
    thanks_why = "thanks for what may be done already: say what is still to do"
    thanked = [Unread(words, "action", thanks_why) for words in thanked_for(text)]
    return [*([Unread(signed, "object", SIGNED_THING_WHY)] if signed else []), *thanked]


class Greeted(NamedTuple):
    """A text as `greeted` leaves it, and the sign-off it kept because its name is also a thing ("Cheers,
    Mug", "Thanks! - Bread", "Thank you mug!": a name or one more item, no reading can tell)."""

    text: str
    signed_thing: str | None


def greeted(text: str, names_a_thing: Callable[[str], bool]) -> Greeted:
    """`text` without a greeting set apart at any sentence's start ("Hi there,", "Good morning!"), before
    any clause ("Hey, when you're done, put ..." is "when you're done, put ..."), an agent's reply set apart
    there (`reply`: "No problem!", "Sure thing!"), a closing sentence that only thanks ("Thanks!") and a
    sign-off with a name ("Cheers, Ana"); a closing thanks or sign-off before a name that is a thing
    (`names_a_thing(name)`) stays, and is reported. A greeting that goes on ("Hey robot put ...") stays, as
    does a closing "thanks" with more to say ("Thanks, but not the orange").

    >>> greeted("Put the egg in the fridge. Cheers, Mug", lambda name: name.lower() == "mug")
    Greeted(text='Put the egg in the fridge. Cheers, Mug', signed_thing='Cheers, Mug')
    >>> greeted("Put the egg in the fridge. Cheers, Ana", lambda name: name.lower() == "mug")
    Greeted(text='Put the egg in the fridge.', signed_thing=None)
    """
    signed = _signed_thing(text, names_a_thing)
    opened = None
    while opened != text:  # "Hi! Sure thing! ..."
        opened = text
        text = _REPLY.sub(lambda m: m["lead"], _GREETING.sub(lambda m: m["lead"], text))
        text = _CALL_OPENING.sub(lambda m: m["lead"], text)
    text = _NOTE_FOR.sub(lambda m: m["lead"] if _for_someone(m, names_a_thing) else m[0], text)
    sign_off = _SIGN_OFF.search(text)
    if sign_off and not names_a_thing(sign_off["name"]):
        text = text[: sign_off.start()]
    return Greeted(_THANKS.sub("", text).strip(), signed)


def _signed_thing(text: str, names_a_thing: Callable[[str], bool]) -> str | None:
    """A closing thanks or sign-off before a name that is also a thing ("Cheers, Mug"), which `greeted`
    keeps; None where there is none."""
    kept = _THING_SIGN_OFF.search(text)
    return kept[0].strip() if kept and names_a_thing(kept["name"]) else None


def without_greetings(text: str, names_a_thing: Callable[[str], bool]) -> str:
    """`text` as `greeted` leaves it: the one greeting policy of every reader that removes greetings
    (household, tabletop).

    >>> without_greetings("Hey, when you're done, put the mug in the sink. Hi there! Put the egg away.", bool)
    "when you're done, put the mug in the sink. Put the egg away."
    """
    return greeted(text, names_a_thing).text


def _for_someone(m: re.Match[str], names_a_thing: Callable[[str], bool]) -> bool:
    """Does a note's heading name a person (a name that is no thing) or whoever comes?"""
    return bool(m["whoever"] or (m["name"] and not names_a_thing(m["name"])))


def without_call(text: str) -> str:
    """`text` without a call at any sentence's start: a greeting or opener before an address ("hey robot
    could you put ...", "okay so robot put ..."), an address before a request ("robot can you grab ...") or
    set apart by a colon or a dash ("Robot: after you ..."), a note's heading ("Note for the robot:") and an
    opener before a name ("so the ..."). `without_greetings` leaves these to each reader (in a tabletop
    dialogue "Robot:" labels a speaker); the household grammar reads the request after them as a request
    with no call (its clauses then open with their verb or their name).

    >>> without_call("hey robot could you put the mug in the sink. Okay robot put the egg away.")
    'could you put the mug in the sink. put the egg away.'
    >>> without_call("robot arms must not touch the mug")
    'robot arms must not touch the mug'
    """
    # a note's heading for a name `without_greetings` kept (a thing: "Note for Mug:") stays
    return _CALLED.sub(lambda m: m[0] if m["name"] else m["lead"], text)


# a request passed on ("Mom says put ...", "she also says chill ..."), a note's "P.S." opening a sentence, a
# wish around a request ("It'd be great if you could put ...", "I was hoping you could ...") and a sentence
# that only announces a request ("Could you do me a favour?"): the household reader's framing
_RELAYED = re.compile(rf"{_OPENS}{courtesy_pattern('relayed')}\s*[:,]?\s+(?=[a-z])", re.I)
_POSTSCRIPT = re.compile(rf"{_OPENS}{courtesy_pattern('postscript')}(?:\s*[:,-])?\s+(?=\w)", re.I)
_WISH = re.compile(rf"\b{courtesy_pattern('wish')}\s+(?:(?:also|please)\s+)?(?=[a-z])", re.I)
_SOFTENED = re.compile(
    rf"\b((?:could|can|would|will)\s+(?:you|u)|(?:you|u)\s+(?:could|can|would|might))\s+{courtesy_pattern('softened')}\b",
    re.I,
)
# "it would be great if both phones were in the safe": the state wished for, a goal (`grammar/restated` reads
# "make sure X is in Y"); a wish for anything else stays, and its "if" is refused as a condition
_STATE_WISH = re.compile(
    rf"\b{courtesy_pattern('state_wish')}\s+(?P<x>(?:the|a|an|both|two|all)\s[^.;!?,]+?)\s+"
    r"(?P<be>were|are|was|is)\s+(?=(?:on|in|into|onto|inside)\s)",
    re.I,
)
_ARE = {"were": "are", "was": "is"}
# "no rush, but put ...", "put ..., no hurry": the user's own time, which asks and forbids nothing
_UNHURRIED = re.compile(
    rf"{_OPENS}{courtesy_pattern('unhurried')}\s*[,.!:-]*\s*(?:but\s+)?(?=[a-z])|"
    rf"\s*[,;-]\s*{courtesy_pattern('unhurried')}\b(?=\s*(?:[.;!?]|$))",
    re.I,
)
# who is asked or who writes, opening a sentence ("Sweetie, ...", "Mum here - ..."), spoken openers before an
# order word ("ok so first ...") and a tag where a sentence ends (", ta.", ", okay?": a statement, "."): h202
_ADDRESSED = re.compile(
    rf"{_OPENS}(?:(?:{courtesy_pattern('endearment')}\s*,|"
    rf"{courtesy_pattern('speaker')}\s*(?:[:,]|[!.](?=\s)|\s[-\u2013\u2014]+))\s*(?=\w)|"
    rf"(?:{courtesy_pattern('spoken_opener')}\s*,?\s*)+(?={courtesy_pattern('opened')}\b))",
    re.I,
)
_TAGGED = re.compile(rf"\s*,\s*{courtesy_pattern('tag')}\s*(?P<end>[.!?]+|$)(?=\s|$)", re.I)
_ASIDE_SENTENCE = re.compile(rf"{_OPENS}{courtesy_pattern('aside')}\s*[?.!:]+\s*(?=\w)", re.I)
# an apology for the message or the asking opening a sentence ("Sorry to bother you again!", h261)
_APOLOGY = re.compile(
    rf"{_OPENS}{courtesy_pattern('apology')}\s*(?:[?.!:]+|\s[-\u2013\u2014]+)\s*(?=\w)", re.I
)
# a bare apology closing a sentence, for how things are ("..., sorry!", "..., sorry - could the robot ...",
# h295): nothing it could correct follows it, so it is no self-correction's "sorry"
_APOLOGY_CLOSING = re.compile(
    rf"\s*,?\s*\b{courtesy_pattern('apology_closing')}(?=\s*(?:[.!]+(?:\s|$)|$)|"
    rf"\s*(?:,|\s[-\u2013\u2014]+)\s*{courtesy_pattern('apology_request')}\b)",
    re.I,
)


def without_apologies(text: str, names_a_thing: Callable[[str], bool]) -> str:
    """`text` without a bare apology that closes a sentence that names no thing, for how things are, not
    for a step (`apology_closing`, h295): it takes nothing back, so it is no self-correction's "sorry". After
    a request ("put the wine bottle in the fridge, sorry") it stays, a correction with nothing after it.

    >>> mug = lambda said: "mug" in said
    >>> without_apologies("Max knocked stuff over, sorry!! Could the robot put the mug in the sink?", mug)
    'Max knocked stuff over!! Could the robot put the mug in the sink?'
    >>> without_apologies("Put the mug in the sink, sorry.", mug)
    'Put the mug in the sink, sorry.'
    """

    def dropped(m: re.Match[str]) -> str:
        said = re.split(r"[.!?]\s", text[: m.start()])[-1]
        return m[0] if names_a_thing(said) else ""

    return _APOLOGY_CLOSING.sub(dropped, text)


# a channel's patter to its audience as a sentence of its own, or closing one after a comma or "and" (h295)
_PATTER = re.compile(
    rf"(?:{_OPENS}|(?<=:)\s*){courtesy_pattern('patter')}\s*(?:[.!?]+|$)\s*|"
    rf"\s*,\s*(?:and\s+)?{courtesy_pattern('patter')}\s*(?=[.!?]|$)",
    re.I,
)
# a record's credit, "Checked by: Dave." (a name of one to three words, initials too) where a sentence starts
_CREDIT = re.compile(
    rf"{_OPENS}[-\u2013\u2014]?\s*(?i:{courtesy_pattern('credit')})\s+by\s*:\s*"
    r"[A-Z][A-Za-z'.-]*(?:\s+(?:(?:and|&|of)\s+)?[A-Z][A-Za-z'.-]*){0,3}\s*(?:[.!]+|$)\s*",
)


def without_patter(text: str) -> str:
    """`text` without a channel's patter and a record's credit (`patter`, `credit`, h295): they name no
    thing and ask the robot for nothing.

    >>> without_patter("Put the book on the table. Smash that like button! Checked by: T. Ward.")
    'Put the book on the table. '
    """
    for _ in range(2):  # a patter clause may close a patter sentence ("If you enjoyed this, rate and review")
        text = _PATTER.sub(lambda m: m["lead"] or "", text)
    return _CREDIT.sub(lambda m: m["lead"], text)


def without_framing(text: str, labels_ordered: bool = False) -> str:
    """`text` without the framing a household request comes in that carries no task, no order and no
    negation: a relayed request's "Mom says", a "P.S.", a wish frame (a wished state is a goal), a sentence
    that only announces a request and "no rush" (`courtesy.txt`: `relayed`, `postscript`, `wish`,
    `state_wish`, `aside`, `unhurried`), a hedge after "could you" (`softened`), a form of address, the
    note's writer, a tag, spoken openers before an order word, a numbered list's markers (unless
    `labels_ordered`: a sentence orders the items by them, `numbered_steps.orders_by_label`) and a heading
    that places every item (`endearment`, `speaker`, `tag`, `opened`, `place_heading`). Words no list holds
    stay, to be read or refused by name (docs/language.md, "Courtesy").

    >>> without_framing("Could you do me a favour? Mom says put the mug in the sink. P.S. the egg goes away")
    'put the mug in the sink. the egg goes away'
    >>> without_framing("It'd be great if you could put the mug in the sink.")
    'put the mug in the sink.'
    >>> without_framing("It would be great if both mugs were in the sink. Mom's mug goes in the sink.")
    "make sure both mugs are in the sink. Mom's mug goes in the sink."
    >>> without_framing("Mum here - everything below goes in the sink: the mug, then the cup, okay?")
    'put the mug in the sink, then put the cup in the sink.'
    """
    text = _TAGGED.sub(lambda m: "." if m["end"] else "", text)
    # an address again after the others ("P.S. Sweetie, ...", "Love, ok so first ...")
    for framing in (_ADDRESSED, _APOLOGY, _RELAYED, _POSTSCRIPT, _ASIDE_SENTENCE, _UNHURRIED, _ADDRESSED):
        text = framing.sub(lambda m: m["lead"] or "", text)
    text = text if labels_ordered else _unnumbered(text)  # ("(1) A (2) B. Do (3) first.": `numbered_steps`')
    text = _PLACE_GETS_HEADING.sub(_each_placed, _PLACE_HEADING.sub(_each_placed, text))
    return _WISH.sub("", _STATE_WISH.sub(_wished, _SOFTENED.sub(r"\1", text))).strip()


def _wished(m: re.Match[str]) -> str:
    """ "it would be great if X were in Y" -> "make sure X are in Y" (the state wished for, as a goal)."""
    return f"make sure {m['x']} {_ARE.get(m['be'].lower(), m['be'])} "


# "in this order" said of a list before its colon ("..., one by one in this order: A, B"): the items in turn
IN_THIS_ORDER = (
    r"\s*,?\s*(?:one\s+(?:by|after)\s+(?:one|the\s+other)\s*,?\s*)?in\s+(?:this|that|the\s+following)\s+order"
)
# a heading that gives one place to every item of its list ("Everything below goes on the desk: A, B, C"):
# each item, up to the sentence's end, with no place of its own ("A on the shelf") is put there (h202); the
# place alone may head it ("Into the cabinet: A and B", "For the dresser: A, B"), and "in this order" before
# the colon orders the items (h238)
_PLACE_HEADING = re.compile(
    rf"{_OPENS}(?:please\s+)?(?:{courtesy_pattern('place_heading', 'place_heading_verb')}\s+)?"
    r"(?P<prep>on|onto|in|into|inside|to|for)\s+"
    rf"(?P<place>(?:the|a|an|my|your)\s+[a-z -]+?)(?P<order>{IN_THIS_ORDER})?\s*:\s*(?P<items>[^.;!?]+)",
    re.I,
)
# the place first ("The nightstand gets three things: A, B and C", "the shelf should get the following: ..."):
# the same list, each item put on it (h238); a count said must be the items'
_PLACE_GETS_HEADING = re.compile(
    r"(?P<lead>^|(?<=[.!?])\s+)(?P<place>(?:the|my|your)\s+[a-z -]+?)\s+"
    r"(?:gets|receives|(?:should|will|can)\s+get)\s+"
    r"(?:(?P<count>two|three|four|five|a\s+few|some)\s+(?:things|items)|the\s+following|these)(?P<prep>)(?P<order>)"
    r"\s*:\s*(?P<items>[^.;!?]+)",
    re.I,
)
_COUNTS = {"two": 2, "three": 3, "four": 4, "five": 5}
_ITEM_SEP = re.compile(r"(\s*,\s*(?:and\s+)?(?:then\s+)?|\s+and\s+(?:then\s+)?|\s+then\s+)", re.I)
# an item that says a place of its own, or that it stays ("..., the mug stays put": `negations.unmoved_said`
# reads it; made "put the mug stays put in the fridge", at exit 0, h205), keeps its words
_HAS_PLACE = re.compile(r"\b(?:on|onto|in|into|inside|goes|go|stays?|remains?)\b", re.I)
# what a container item holds is no place of its own ("a mug with a pen in it": the mug goes there, h212)
_CONTENT = re.compile(
    r"\b(?:with|containing|holding|(?:that|which)(?:'s|\s+has|\s+holds)(?:\s+got)?)\s+(?:[a-z]+\s+){1,4}?"
    r"(?:(?:in|on|inside)\s+(?:it|them)|inside)\b",
    re.I,
)


def _each_placed(m: re.Match[str]) -> str:
    """ "Everything below goes on the desk: a book, then the clock" -> "put a book on the desk, then put the
    clock on the desk"; an item with a place of its own keeps it."""
    parts = _ITEM_SEP.split(m["items"].strip())
    said = _COUNTS.get((m.groupdict().get("count") or "").lower())
    if said is not None and said != (len(parts) + 1) // 2:
        return m[0]  # "gets three things:" and two said: left as it is
    if m["order"]:  # "..., in this order: A, B and C": each item after the one before
        parts = [", then " if i % 2 else part for i, part in enumerate(parts)]
    if m["prep"].lower() == "for" and m["place"].split(None, 1)[-1].lower() in ROOM_WORDS:
        return m[0]  # "For the kitchen: ...": a room, no place to put things
    prep = "on" if m["prep"].lower() in ("for", "") else m["prep"]  # "For the dresser: A"; "X gets: A"
    placed = [
        part
        if i % 2 or _HAS_PLACE.search(_CONTENT.sub("", part))
        else f"put {part} {prep} {m['place']}"
        for i, part in enumerate(parts)
    ]
    return m["lead"] + "".join(placed)


# a numbered list's markers ("Note for Sam: (1) A, (2) B (3) C"), read as a list's ";" (h202): only where they
# count on from (1) or (a), so "(2 of them)" or a lone "(b)" stays
_MARKER = re.compile(r"(?P<before>[:;,]?)\s*\((?P<n>\d|[a-h])\)\s*", re.I)


def _unnumbered(text: str) -> str:
    """`text` with the markers of a numbered list, (1), (2), ... or (a), (b), ..., read as items' ";"."""
    marks = [m["n"].lower() for m in _MARKER.finditer(text)]
    if len(marks) < 2 or marks not in (list("123456789"[: len(marks)]), list("abcdefgh"[: len(marks)])):
        return text
    return _MARKER.sub(lambda m: ": " if m["before"] == ":" else "; ", text).lstrip("; ")
