"""A reference said as the state of a thing, rewritten onto the forms the sentence rules read ("With the
bat done, Y", "The moment the apple is on the table, Y", "once the bottle is on it"): "once X is done" /
"once X is there" (steps of `sentences.normalize` and `everyday`; the order phrasings are `order_phrases`)."""

from __future__ import annotations

import re

from nl2hltl2plan.language.order_words import WITH_DONE

_DONE = frozenset({"done", "finished", "complete", "completed"})


def finished_thing(text: str) -> str:
    """ "With the bat done, Y" / "Whenever the vase is sorted, Y" -> "Once the bat is done, Y" ("whenever"
    with no state is a freedom, `word_tables.WHENEVER`; "with the bat" alone is no reference)."""

    def once(m: re.Match[str]) -> str:
        if m["lead"].lower() == "with" and m["verb"]:  # "with the mug is done": not the absolute form
            return m[0]
        if m["lead"].lower() in ("once", "when", "after") and (not m["verb"] or m["done"].lower() in _DONE):
            return m[0]  # "Once the mug is done, Y" is read as it is; "Once the table is sorted, Y" is that
        plural = (m["verb"] or "").lower() in {"are", "have been", "get"}
        return f"{'O' if m['lead'][0].isupper() else 'o'}nce {m['np']} {'are' if plural else 'is'} done, "

    return WITH_DONE.sub(once, text)


# "The moment the apple is on the table, Y" / "Y the instant you've put the mug away": "as soon as", a
# reference ("once"); only where a clause follows (a subject), so "at the moment" / "wait a minute" stay
_THE_MOMENT = re.compile(
    r"(?:(?<=^)|(?<=\s))(?<!at\s)(?<!a\s)(?P<the>the)\s+(?:very\s+)?(?:moment|instant|minute|second)\s+"
    r"(?=(?:the|your|you|you've|you're|it|it's|they|they're|we|i|that|this|both|all|each|every)\s)",
    re.I,
)


def the_moment(text: str) -> str:
    """ "The moment the apple is on the table, Y" -> "Once the apple is on the table, Y"."""
    return _THE_MOMENT.sub(lambda m: "Once " if m["the"][0] == "T" else "once ", text)


# "put the sponge there too once the bottle is on it", "once they're in": the state of a thing put in the
# place just named, "once the bottle is there", the reference the rules read (h190); "is in the fridge" stays
_ON_IT = re.compile(
    r"\b(?P<lead>once|after|when)\s+(?P<np>(?:the|that|those|both|all)\s+[a-z]+(?:\s+[a-z]+)?|they|it)\s*"
    r"(?P<verb>is|are|'s|'re)\s+(?:now\s+)?(?:on|in|inside|onto)(?:\s+(?:it|there))?(?=\s*(?:[,.;!?]|$))",
    re.I,
)


def state_on_it(text: str) -> str:
    """ "once the bottle is on it" / "once they're in" -> "once the bottle is there" / "once they are
    there"."""

    def there(m: re.Match[str]) -> str:
        verb = {"'s": "is", "'re": "are"}.get(m["verb"].lower(), m["verb"])
        return f"{m['lead']} {m['np']} {verb} there"

    text = _ON_IT.sub(there, text)
    # "A, and B there too once the bottle is there": the condition is B's, said as a sentence of its own
    return _AND_THEN_STATE.sub(lambda m: f". {m['lead'].capitalize()} {m['state']}, {m['clause']}", text)


_AND_THEN_STATE = re.compile(
    r",\s+and\s+(?P<clause>[^,.;!?]+?\bthere\b[^,.;!?]*?)\s+(?P<lead>once|after|when)\s+"
    r"(?P<state>(?:(?:the|that|those|both|all)\s+[a-z]+(?:\s+[a-z]+)?|they|it)\s+(?:is|are)\s+there)(?=\s*(?:[.;!?]|$))",
    re.I,
)
