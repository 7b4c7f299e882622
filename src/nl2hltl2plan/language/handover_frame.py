"""The frame around a handover instruction's commands, which `unframed` and `FRAME` drop: a letter's
greeting before the command ("Dear team,", "Hi robots!", "Good morning everyone.") and sign-off after it
("Thanks!", "Cheers", "Best regards, Ana", "Thanks in advance", "Done."), and the labels that announce
the command ("Procedure:", "Operator instructions:", "Here's the job:", "Here's what needs doing:").
They address, thank and announce, and carry no block, place, count, order or time. A greeting or
sign-off is dropped only at the instruction's edges: a greeting before the first command, a sign-off
after the last one (with the writer's name after it). A sentence that only cheers or starts the work
("Great!", "Okay, awesome!", "Here we go!") is dropped wherever it stands. A greeting that names one
arm ("Hi arm a,") says who is to act and is left to be refused; so is a "thanks" in the middle of the
instruction that the word tables do not read, and a signature that is a word the reader knows ("Thanks,
Red"). Two labels
say something and are rewritten rather than dropped: "Here's what I want:" (a need: "I want ...") and
"Scope:" / "You will need:" (the blocks the instruction is about, read as the scene statement "we have
...", which must name every block of the scene).

    >>> unframed(["Dear team, put the red block on G", "Thanks so much", "Ana"])
    ['put the red block on G']
    >>> unframed(["Hi arm a, put the red block on G"])
    ['Hi arm a, put the red block on G']
"""

from __future__ import annotations

import re

# who a greeting addresses: everyone, never one arm ("arm a" would say who acts)
_ADDRESSEE = (
    r"(?:all|everyone|everybody|folks|guys|gang|team|crew|people|there|friends|colleagues|both|you\s+two|"
    r"y\s*'?\s*all|(?:the\s+)?(?:robots?|robot\s+team|arms))"
)
_GREETING = (
    rf"(?:(?:hi|hello|hey|hiya|howdy|greetings|good\s+(?:morning|afternoon|evening|day)|morning|afternoon|evening)"
    rf"(?:\s+(?:and\s+)?{_ADDRESSEE}){{0,2}}|dear\s+{_ADDRESSEE}(?:\s+(?:and\s+)?{_ADDRESSEE})?)"
)
_OPENING = re.compile(rf"(?i)^\s*{_GREETING}\s*(?:[,:!.\-–—]+\s*|$)")
_THANKS = (
    r"(?:(?:many|big|huge)\s+)?(?:thanks|thank\s+you|thx|ty|cheers|ta)"
    r"(?:\s+(?:so|very)\s+much|\s+a\s+lot|\s+a\s+bunch|\s+heaps|\s+in\s+advance|\s+again)?"
    rf"(?:\s*,?\s*{_ADDRESSEE})?"
)
_REGARDS = (
    r"(?:(?:best|kind|warm|warmest)\s+)?regards|best(?:\s+wishes)?|all\s+the\s+best|sincerely|"
    r"yours(?:\s+(?:truly|sincerely|faithfully))?|much\s+appreciated|(?:i\s+)?appreciate\s+it|"
    r"have\s+a\s+(?:nice|good|great)\s+(?:day|one|evening)|talk\s+(?:soon|later)|bye|"
    r"(?:all\s+)?done|that\s*(?:'\s*)?s\s+(?:it|all)|the\s+end|over\s+and\s+out"
)
# a whole sentence of sign-off, with the writer's name after it ("Best, Ana")
_CLOSING = re.compile(rf"^\s*(?i:{_THANKS}|{_REGARDS})(?:\s*[,\-–—]?\s*(?P<name>[A-Z][a-z]+))?\s*[,.!]*\s*$")
_NAME = re.compile(r"^\s*[A-Z][a-z]+\s*$")
# a thanks that ends the last sentence: "..., cheers"
_TRAILING_THANKS = re.compile(rf"(?i)\s*,\s*{_THANKS}\s*[.!]*\s*$")
# a sentence that only cheers or starts the work ("Great!", "Okay, awesome!", "Alright, here we go!")
_CHEER = (
    r"(?:great|awesome|cool|sweet|perfect|nice|excellent|wonderful|fantastic|brilliant|super|lovely|good|"
    r"okay|ok|alright|all\s+right|right|yay|woo+hoo+|"
    r"let\s*(?:'\s*)?s\s+(?:go|do\s+(?:this|it)|get\s+(?:started|going)|begin|start)|here\s+we\s+go)"
)
_EXCLAMATION = re.compile(rf"(?i)^\s*(?:{_CHEER}\s*[,!.]*\s*)+$")
# a name that the reader would read as something (a colour, a region or arm letter)
_KNOWN = re.compile(r"(?i)^(?:red|blue|yellow|[a-j]|one|two|three|both|all|first|then|last)$")


def _closing(sentence: str) -> bool:
    match = _CLOSING.match(sentence)
    if match is None:
        return False
    return not (match.group("name") and _KNOWN.match(match.group("name")))


def _signature(sentence: str) -> bool:
    return bool(_NAME.match(sentence)) and not _KNOWN.match(sentence.strip())


def unframed(sentences: list[str]) -> list[str]:
    """The sentences without the greeting before the first command and the sign-off after the last one
    (see the module docstring)."""
    out = list(sentences)
    while out and not _OPENING.sub("", out[0], count=1).strip():  # "Good afternoon", "Hi robots"
        out.pop(0)
    if out:
        out[0] = _OPENING.sub("", out[0], count=1)
    while out:
        if _closing(out[-1]):
            out.pop()
        elif len(out) > 1 and _signature(out[-1]) and _closing(out[-2]):
            del out[-2:]  # "Thanks,\nAna"
        else:
            break
    if out:
        out[-1] = _TRAILING_THANKS.sub("", out[-1])
    return [s for s in out if s.strip() and not _EXCLAMATION.match(s)]


# labels and presentative headings of the lower-cased sentence ("here's" is "here s" by then), applied by
# `handover_phrases.normalise` before the word tables' rewrites
FRAME: tuple[tuple[re.Pattern[str], str], ...] = tuple(
    (re.compile(pattern), replacement)
    for pattern, replacement in (
        (r"^\s*(?:scope|you\s+(?:will\s+)?need|what\s+you\s+need|materials|equipment)\s*:\s*", "we have "),
        (
            r"^\s*here\s*(?:s|is)\s+(?:(?:the|my|our|your)\s+(?:idea|plan|deal|thing|job|task|brief|request)|"
            r"what\s+(?:needs\s+(?:doing|to\s+be\s+done|to\s+happen)|to\s+do|you\s+(?:do|will\s+do)))\s*:",
            " ",
        ),
        (r"^\s*here\s*(?:s|is)\s+what\s+(i|we)\s+(?:want|need|would\s+like)\s*:", r"\1 want "),
        (
            r"^\s*(?:(?:operator|operating|work|standard|general)\s+)?(?:steps|procedure|instructions?|plan|"
            r"to\s*do|method|actions?)\s*:\s*",
            " ",
        ),
    )
)
