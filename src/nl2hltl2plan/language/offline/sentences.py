"""Step 1, sentences: normalise the text, split it into sentences, strip their order markers."""

from __future__ import annotations

import re

from nl2hltl2plan.language.offline import grammar as G


def normalize(text: str) -> str:
    text = text.replace("\u2019", "'").replace("\u2018", "'").replace("\u201c", '"').replace("\u201d", '"')
    text = re.sub(r"(?<=[a-z])\.(?=[A-Za-z])", ". ", text)
    text = re.sub(r"\s*\([^)]*\)", "", text)  # parenthetical remarks: "(where the red block is now)"
    return re.sub(r"\s+", " ", text).strip()


def split_sentences(text: str) -> list[tuple[str, int]]:
    out: list[tuple[str, int]] = []
    pos = 0
    for m in re.finditer(r"[.;!?]+(?:\s+|$)", text):
        chunk = text[pos : m.start()].strip()
        if chunk:
            out.append((chunk, pos + (len(text[pos : m.start()]) - len(text[pos : m.start()].lstrip()))))
        pos = m.end()
    rest = text[pos:].strip()
    if rest:
        out.append((rest, pos))
    return out


def after_ref(body: str) -> tuple[str, str] | None:
    """ "After placing the plunger, soap bottle, and towel, put ...": (reference, rest) split at the comma
    that is followed by a verb (references may contain commas)."""
    m = re.match(r"^(?:only\s+)?(?:after|once|when|following|upon)\s+", body, flags=re.I)
    if not m or re.match(
        r"^(?:completing|finishing|doing|all|these|those|the\s+previous|the\s+above|both|"
        r"everything|each|every|that|this|it|done|finished|complete|completed|over|through|you|we)\b",
        body[m.end() :],
        flags=re.I,
    ):
        return None
    for c in re.finditer(r",\s*", body):
        rest = body[c.end() :]
        first = re.match(r"(?:then\s+|please\s+|now\s+|you\s+should\s+|we\s+)?([A-Za-z]+)", rest)
        if c.start() > m.end() and first and first.group(1).lower() in G.VERBS:
            return body[m.end() : c.start()], rest
    return None


