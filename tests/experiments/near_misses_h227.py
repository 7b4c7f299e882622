"""h227's held-out near misses of h220's frame rules (tabletop and handover), written before any probe or rule
change and scored once at the end. Each: (sentence, what a careful reader means). A tabletop meaning is a
plain instruction with the same tasks and order, or None where the sentence must be refused (a negation the
tabletop reader cannot state); a handover meaning is the Table III task whose written spec the sentence
states."""

from __future__ import annotations

HELD_TABLETOP: list[tuple[str, str | None]] = [
    # labels that name real objects (the plates), not the document
    (
        "Yellow plate: the green apple and the orange. Blue plate: the carrot and the red apple.",
        "Place the green apple and the orange in the yellow plate and the carrot and the red apple in the "
        "blue plate, in any order.",
    ),
    # a chatty aside that holds a negation
    (
        "Good luck, and don't put the carrot on the yellow plate! Place the green apple in the blue plate "
        "and the orange in the yellow plate.",
        None,
    ),
    # a chatty free-order remark that frees only some tasks
    (
        "Place the green apple in the pink plate, the orange in the yellow plate and the red apple in the "
        "blue plate. It's all the same to me, but the orange goes last.",
        "Place the green apple in the pink plate and the red apple in the blue plate in any order, then "
        "place the orange in the yellow plate.",
    ),
]

HELD_HANDOVER: list[tuple[str, int]] = [
    # a free-order remark with an order kept in the same sentence
    (
        "Start wherever you like, but the red block goes before the blue block. Please place the three "
        "objects separately to region G, H and I.",
        6,
    ),
]
