"""The structure model's third training family: composed instructions wrapped in a voice's frame (issue 28,
h272), from `compose_frames.txt`.

Fresh held-out style sets fail first on the frame of a voice (results/language/h249.md: 22 of 73 failing
lines): greetings, names, sign-offs, headings, page / ticket numbers, times and asides read as people,
actions or counts. This family teaches the CRF that such words lie in no task span (tag O). A frame is
drawn from combinatorial pools (a template of slots, each slot from its own pool, numbers drawn), so no
single wording is learned; `held` pools (disjoint templates and words) are never trained and make the
validation set `framed_unseen` (`suites.alfred.structure_validation`). A frame changes no task, span
relation or order: the composed instruction's spans move by the frame's prefix, and a voice note's
fillers go only between spans, after a gap's comma or stop.
"""

from __future__ import annotations

import random
import re
from collections import defaultdict
from dataclasses import replace
from pathlib import Path
from typing import Literal

from nl2hltl2plan.language.learned.compose import Synth

FRAMES_FILE = Path(__file__).with_name("compose_frames.txt")
Pools = Literal["train", "held"]


def _pools() -> dict[str, dict[str, list[str]]]:
    """The file's entries by pool set ("train", "held") and kind ("name", "frame", ...)."""
    out: dict[str, dict[str, list[str]]] = defaultdict(lambda: defaultdict(list))
    for line in FRAMES_FILE.read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            head, _, text = line.partition(" | ")
            which, kind = head.split()
            out[which][kind].append(text.replace("\\n", "\n"))
    return out


POOLS = _pools()


def _fill(template: str, pools: dict[str, list[str]], rng: random.Random) -> str:
    num = rng.randint(1, 12)

    def slot(m: re.Match[str]) -> str:
        key = m.group(1)
        if key in ("num", "num2"):  # "Message 3 of 5": the second number is never the smaller
            return str(num if key == "num" else num + rng.randint(0, 6))
        return rng.choice(pools["name" if key == "sender" else key])

    return re.sub(r"\{(\w+)\}", slot, template)


def _fillers(s: Synth, pools: dict[str, list[str]], rng: random.Random) -> Synth:
    """A voice note's fillers between spans ("... sink. um, then ..."), the spans moved to match."""
    text, spans, shift, last = "", [], 0, 0
    for i, (a, b) in enumerate(s.spans):
        gap = s.text[last:a]
        if i and (m := re.search(r"[,.;] ", gap)) and rng.random() < 0.5:
            gap = gap[: m.end()] + rng.choice(pools["filler"]) + ", " + gap[m.end() :]
        text += gap
        shift = len(text) - a
        spans.append((a + shift, b + shift))
        text += s.text[a:b]
        last = b
    return replace(s, text=text + s.text[last:], spans=spans)


def framed(s: Synth, which: Pools, rng: random.Random) -> Synth:
    """`s` wrapped in a frame drawn from the `which` pools; its tasks, relations and order are unchanged."""
    pools = POOLS[which]
    template = rng.choice(pools["frame"])
    if "{filler}" in template:
        s = _fillers(s, pools, rng)
    head, _, tail = template.partition("{body}")
    body = s.text.rstrip(".!") if tail[:1] in (".", ",") else s.text
    head, tail = _fill(head, pools, rng), _fill(tail, pools, rng)
    if rng.random() < 0.2:  # a voice typed in lower case, frame and all
        head, tail = head.lower(), tail.lower()
    spans = [(a + len(head), b + len(head)) for a, b in s.spans]
    return replace(s, text=head + body + tail, spans=spans)


def frame_all(synth: list[Synth], which: Pools, seed: int) -> list[Synth]:
    """Every composition in a frame of the `which` pools, deterministic for a seed."""
    rng = random.Random(seed)
    return [framed(s, which, rng) for s in synth]
