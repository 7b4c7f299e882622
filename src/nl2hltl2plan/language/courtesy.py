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

from nl2hltl2plan.language.content_words import phrase_list_pattern, phrase_words


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
_FRAME = re.compile(rf"(?:,\s*)?\b{_FRAMES}\b(?=\s*(?:[,.;:!?]|$))\s*,?", re.I)


def without_courtesy(text: str) -> str:
    """`text` without its courtesy frames (and the commas around them); the text as it was when nothing
    else is left."""
    out = _FRAME.sub(" ", text)
    out = re.sub(r"\s+([,.;:!?])", r"\1", " ".join(out.split()))
    out = re.sub(r"^[\s,.;:!?]+", "", out)
    return out if re.search(r"\w", out) else text


# a greeting or reply stays before a clause that waits on something ("Hey, when you're done, ..."): what it
# waits on is not said, and the text is read (or refused) as it was
_REQUEST_FOLLOWS = r"(?=\w)(?!(?:when|whenever|once|after|before|while|until|as soon as|if)\b)"
_GREETING = re.compile(
    rf"^\s*(?:{courtesy_pattern('greeting', 'address', 'greeting_with')}\s*)+[!.,]+\s*{_REQUEST_FOLLOWS}",
    re.IGNORECASE,
)
_REPLY = re.compile(rf"^\s*{courtesy_pattern('reply')}\s*[!.,]+\s*{_REQUEST_FOLLOWS}", re.IGNORECASE)
_THANKS = re.compile(rf"(?<=[.!?])\s*{courtesy_pattern('closing')}\s*[!.]*\s*$", re.IGNORECASE)
_SIGN_OFF = re.compile(rf"(?<=[.!?])\s*(?i:{courtesy_pattern('sign_off')})\s*,\s*(?P<name>[A-Z][a-z]+)\W*$")


def without_greetings(text: str, names_a_thing: Callable[[str], bool]) -> str:
    """`text` without a greeting that opens it set apart ("Hi there,", "Good morning!"), an agent's reply
    (`reply`: "No problem!", "Sure thing!"), a closing sentence that only thanks ("Thanks!") and a sign-off
    with a name ("Cheers, Ana") unless `names_a_thing(name)`. A greeting that goes on ("Hey robot put ...")
    and one before a clause that waits on something ("Hey, when you're done, ...") stay, as does a closing
    "thanks" with more to say ("Thanks, but not the orange")."""
    opened = None
    while opened != text:  # "Hi! Sure thing! ..."
        opened = text
        text = _REPLY.sub("", _GREETING.sub("", text))
    sign_off = _SIGN_OFF.search(text)
    if sign_off and not names_a_thing(sign_off["name"]):
        text = text[: sign_off.start()]
    return _THANKS.sub("", text).strip()


# a greeting set apart at any sentence's start, before a request (the household reader's `household_forms`)
_SENTENCE_GREETING = re.compile(
    rf"(?P<lead>^|(?<=[.!?])\s+)(?:{courtesy_pattern('greeting', 'address', 'greeting_with')}\s*)+[!.,]+\s*"
    r"(?=[a-z])",
    re.I,
)


def ungreeted(text: str) -> str:
    """`text` without a greeting set apart ("Hey,", "Hi there!") that opens any of its sentences. Unlike
    `without_greetings` (every reader, the text's opening only), it drops one before a clause that waits
    ("Hey, when you're done, put ..."): the household grammar reads "when you're done" with no task
    before it as waiting on none, while the tabletop reader refuses it (docs/language.md).

    >>> ungreeted("Hey, when you're done, put the mug in the sink. Hi there! Put the egg away.")
    "when you're done, put the mug in the sink. Put the egg away."
    """
    return _SENTENCE_GREETING.sub(lambda m: m["lead"], text)
