"""Chat forms in the tabletop world (issue 28): how people write to a robot in a chat window.

Read before any reader sees the text (`TabletopReader.as_read`), each as the plain words it stands for:

- "n", "&" and "+" between words are "and" ("green apple n orange on the yellow plate"), "u" is "you";
- "(any / whatever) order you find convenient / easiest" is "order you like" (the shared free-order phrase):
  the "find" of a leave is no action;
- "when / once / after both are on it": "it" is the plate just named, read as "there" ("once both are
  there"), which the readers resolve to it;
- a greeting that opens the text and is set apart ("Hi there,", "Good morning!") and an agent's reply
  (`courtesy.txt`'s `reply`: "No problem!", "Sure thing!") ask for nothing and are removed, as are a
  closing sentence that only thanks ("Thanks!", "Thank you so much!") and a sign-off with a name ("Cheers,
  Ana") whose name is no object or plate. Greetings and replies must stand apart ("Hi, ..."), so a clause
  that goes on ("Hey robot put ...") is left as written, and stay before a clause that waits on something
  ("Hey, when you're done, ..."), which is refused as before; a closing "thanks" with other words
  ("Thanks, but not the orange") is left too.

The words are `tabletop_chat.txt`'s.

>>> chat_read("Hi, can u put the green apple n the orange on the blue plate? Thanks!", {"blue plate": True})
'can you put the green apple and the orange on the blue plate?'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import phrase_list_pattern

_AND = re.compile(r"(?<=\w)\s+(?:n|&|\+)\s+(?=\w)|\s*&\s*(?=\w)")
_YOU = re.compile(r"(?<![\w'-])[uU](?![\w'-])")
_FIND = re.compile(
    rf"\b(?P<order>order|ordering|sequence)\s+(?:that\s+)?you\s+find\s+(?:it\s+)?"
    rf"{phrase_list_pattern('tabletop_chat.txt', 'easy')}\b",
    re.IGNORECASE,
)
# "when both are on it": "it" is the plate just named, as "there" says it ("once both are there")
_ON_IT = re.compile(
    r"\b(?P<head>(?:when|once|after|as soon as)\s+(?:both|they|those|these|the two|all)(?:\s+of them)?\s+"
    r"(?:are|have been|'re|are both|are all)\s+)(?:on|in|onto)\s+it\b",
    re.IGNORECASE,
)
# a greeting or reply stays before a clause that waits on something ("Hey, when you're done, ..."): what it
# waits on is not said, and the text is refused as it was
_REQUEST_FOLLOWS = r"(?=\w)(?!(?:when|whenever|once|after|before|while|until|as soon as|if)\b)"
_GREETING = re.compile(
    rf"^\s*(?:{phrase_list_pattern('tabletop_chat.txt', 'greeting')}\s*)+[!.,]+\s*{_REQUEST_FOLLOWS}",
    re.IGNORECASE,
)
_REPLY = re.compile(
    rf"^\s*{phrase_list_pattern('courtesy.txt', 'reply')}\s*[!.,]+\s*{_REQUEST_FOLLOWS}", re.IGNORECASE
)
_THANKS = re.compile(
    rf"(?<=[.!?])\s*{phrase_list_pattern('tabletop_chat.txt', 'thanks')}\s*[!.]*\s*$", re.IGNORECASE
)
_SIGN_OFF = re.compile(
    rf"(?<=[.!?])\s*(?i:{phrase_list_pattern('courtesy.txt', 'sign_off')})\s*,\s*(?P<name>[A-Z][a-z]+)\W*$"
)


def chat_read(text: str, kinds: dict[str, bool]) -> str:
    """`text` with its chat forms read as plain words (see the module docstring); `kinds`: each object or
    plate name in words -> is it a plate (a sign-off's name that is a word of one stays)."""
    text = _FIND.sub(lambda m: f"{m['order']} you like", _YOU.sub("you", _AND.sub(" and ", text)))
    text = _ON_IT.sub(r"\g<head>there", text)
    opened = None
    while opened != text:  # "Hi! Sure thing! ..."
        opened = text
        text = _REPLY.sub("", _GREETING.sub("", text))
    sign_off = _SIGN_OFF.search(text)
    if sign_off and not any(sign_off["name"].lower() in name.split() for name in kinds):
        text = text[: sign_off.start()]
    return _THANKS.sub("", text).strip()
