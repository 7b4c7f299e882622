"""The forms of reported, relayed and received speech around a handover command, which
`handover_discourse.unreported` reads: a speaker and a verb of saying or asking before a command ("The
supervisor said to ...", "Kim told us to ..."), or before a clause ("She says: ..."); a source said first
("According to Dana, ..."); a command received by the team ("we were asked to ...", "our instructions are to
..."); a need ("she wanted X put back on G"); and the past tense of reported speech put back in the present
("had to" -> "must").
"""

from __future__ import annotations

import re

_SPEAKER = r"(?P<speaker>(?:the|our|my|your)\s+(?:[a-z]+\s+)?[a-z]+|he|she|they|someone|(?-i:[A-Z][a-z]+))"
# what a speaker wrote: "Kim's message", "the foreman's note"
_WRITING = r"(?:\s*['’]s\s+(?:message|note|e-?mail|text|memo|reply|notes))?"
_RECIPIENT = r"(?:us|me|you|them|everyone|everybody|(?:all\s+)?(?:the\s+)?(?:arms|robots|team|crew))"
_SAY = r"(?:said|says|say|mentioned|explained|insisted|added|stated|wrote|writes|reads|read)"
_ASK = (
    r"(?:told|tells|asked|asks|wants|wanted|instructed|instructs|reminded|reminds|needs|needed|"
    r"(?:is|was|are|were)\s+(?:asking|telling))"
)
_TELL_ON = rf"(?:\s+to\s+tell\s+{_RECIPIENT})?"  # "Sam told me to tell you to ..."
# "X said / says (to us) to VERB", "X told us to VERB", "X said not to VERB": the command
REPORTED_COMMAND = re.compile(
    rf"(?i)(?P<start>^|,\s*|\band\s+){_SPEAKER}\s+(?:{_SAY}(?:\s+to\s+{_RECIPIENT})?|{_ASK}\s+{_RECIPIENT}{_TELL_ON})"
    rf"\s+(?P<neg>not\s+)?to\s+"
)
# "X said (that) CLAUSE", "X says: CLAUSE", "X told us (that) CLAUSE": the clause
REPORTED_CLAUSE = re.compile(
    rf"(?i)(?P<start>^|,\s*|\band\s+){_SPEAKER}{_WRITING}\s+(?:{_SAY}|told\s+{_RECIPIENT})(?:\s+that\b|\s*:)?\s+"
)
# the source said before what it says: "According to the supervisor, ...", "Per Dana, ...", "As the manager
# put it, ...", "Quote from the lead: ...", "Word from the lead is to ...", "Just heard from Priya: ..."
SOURCE = re.compile(
    rf"(?i)(?P<start>^)\s*(?:according\s+to|per|as|(?:a\s+)?(?:quote|message|note|word)\s+from|"
    rf"(?:just\s+)?heard\s+from)\s+{_SPEAKER}"
    r"(?:\s*,|\s+(?:put\s+it|said|says|wrote)\s*,|\s*:|\s+is\s+(?:that\s+|to\s+(?=\w)))\s*"
)
# the command received, said by the team that is to do it: "we were asked to ...", "we have been told not to
# ...", "our instructions are to ...", "plan how the arms move ..." (an exam's or a brief's question)
RECEIVED = re.compile(
    r"(?i)(?P<start>^|,\s*|\band\s+)(?:(?:we|the\s+(?:arms|robots|team))\s+(?:were|are|have\s+been|['’]ve\s+been)\s+"
    r"(?:asked|told|instructed|requested|directed)\s+|(?:our|the|my|your)\s+(?:instructions|orders)\s+(?:are|were)\s+|"
    r"(?:plan|work\s+out|figure\s+out)\s+how\s+(?:the\s+(?:arms|robots)|we|you|to)\s+(?:can\s+|could\s+|should\s+)?|"
    # a support agent saying the request back: "(just to confirm,) you'd like the arms to ..."
    r"you\s*(?:['’]d|\s+would)\s+(?:like|want)\s+(?:the\s+(?:arms|robots)|us)\s+)"
    r"(?P<neg>not\s+)?(?:to\s+)?(?=[a-z])"
)
# "and said / and told us (that) CLAUSE" (the speaker said before): the clause
AND_SAID = re.compile(rf"(?i)\band\s+(?:{_SAY}|told\s+{_RECIPIENT})(?:\s+that\b)?\s+")
# "she wanted the yellow block put back on G": a need
WANTED = re.compile(
    rf"(?i)(?P<start>^|,\s*|\band\s+){_SPEAKER}\s+(?:wants?|wanted|needs?|needed)\s+(?!{_RECIPIENT}\b|to\b)"
)
# the past tense of reported speech, back in the present
BACKSHIFT = tuple(
    (re.compile(rf"(?i)\b{pattern}\b"), replacement)
    for pattern, replacement in (
        (r"had\s+to", "must"),
        (r"was\s+to", "is to"),
        (r"were\s+to", "are to"),
        (r"could", "can"),
        (r"had\s+(?=been\b|touched\b|picked\b|grabbed\b|handled\b|moved\b|lifted\b|placed\b)", "has "),
    )
)
