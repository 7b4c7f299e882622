"""Span relations (`compose.RELATIONS`) -> `before` pairs between spans, by text position.

The spans are read left to right into chains of steps. START opens the first chain; SEQ opens a new
step after the current one; PAR joins the current step (no order inside a step: "X and Y"); ANY joins
it too, with the order explicitly left open ("X and Y in any order"); PRE opens a new step just before
the current one ("before you X, Y": Y first), and a PAR or ANY span right after it joins that new step
("B, but before that C and D": C and D before B; ANNOTATION_GUIDE.md's "X before Y" over the clause "C
and D"); FREE opens a chain of its own (no order with anything so
far); BARE (a new sentence with no temporal word: "X. Y.", "X. Also Y.") opens a chain of its own too,
unordered like FREE but not free of a later "finally". Every span of a step comes before every span of
a later step of its chain. LAST ("finally Y", the benchmark's annotation guide) comes after every
earlier span that is not allowed in any order or at any time: after every span of the last step of
each chain that has no ANY span and is not FREE (the earlier steps are before it already). The
relations that point back open a chain of their own: REF after the one earlier span its target names
("after putting the pan, Y"), RPRE before it ("before you put the pan, Y"), ALL after every earlier
span.

Every pair goes from a span to a later one, except PRE's and RPRE's, which go from the new span (that
nothing comes before yet) to earlier ones; a pair that would still close a cycle is dropped
(`drop_cycles`), so the order is always a partial order.

>>> before_pairs(["START", "SEQ", "PAR", "SEQ"])
[(0, 1), (0, 2), (1, 3), (2, 3)]
>>> before_pairs(["START", "PRE"])
[(1, 0)]
>>> before_pairs(["START", "PRE", "PAR", "SEQ"])
[(0, 3), (1, 0), (2, 0)]
>>> before_pairs(["START", "ANY", "LAST"])
[]
>>> before_pairs(["START", "PAR", "LAST"])
[(0, 2), (1, 2)]
>>> before_pairs(["FREE", "PAR", "LAST"])
[(1, 2)]
>>> before_pairs(["START", "SEQ", "BARE", "LAST"])
[(0, 1), (1, 3), (2, 3)]
>>> before_pairs(["START", "SEQ", "FREE", "REF"], [None, None, None, 0])
[(0, 1), (0, 3)]
>>> before_pairs(["START", "FREE", "RPRE", "ALL"], [None, None, 0, None])
[(0, 3), (1, 3), (2, 0), (2, 3)]
"""

from __future__ import annotations

import re
from functools import cache
from pathlib import Path

from nl2hltl2plan.language.content_words import categories, free_order_remarks
from nl2hltl2plan.language.courtesy import courtesy_words

POINTING = ("REF", "RPRE", "ALL")  # relations to a named earlier span, or to all of them
_AFTERTHOUGHT = re.compile(r"\boh\b", re.I)  # "Oh and Z": a request of its own (`courtesy.without_courtesy`)


def before_pairs(relations: list[str], targets: list[int | None] | None = None) -> list[tuple[int, int]]:
    """The `before` pairs (span indices) that the relations (and, for REF / RPRE, the earlier span each
    points at, `targets`) state; acyclic."""
    chains: list[list[list[int]]] = []
    current = 0  # the current step's index in the last chain
    free = {i for i, rel in enumerate(relations) if rel == "FREE"}  # allowed at any time
    any_order = {i for i, rel in enumerate(relations) if rel == "ANY"}  # its step in any order
    last: list[int] = []
    pre_open = False  # the spans since the last PRE are all PAR / ANY
    for i, rel in enumerate(relations):
        pre_open = rel == "PRE" or (pre_open and rel in ("PAR", "ANY"))
        if rel == "LAST" and chains:
            last.append(i)
        elif not chains or rel in ("START", "FREE", "LAST", "BARE") + POINTING:
            chains.append([[i]])
            current = 0
        elif rel in ("PAR", "ANY"):  # after a PRE (and its PARs): in the step PRE put before the current one
            chains[-1][current - 1 if pre_open else current].append(i)
        elif rel == "PRE":
            chains[-1].insert(current, [i])
            current += 1  # the step read so far stays the current one
        else:  # SEQ
            chains[-1].insert(current + 1, [i])
            current += 1
    pairs = _pointed(relations, targets or [None] * len(relations))
    for steps in chains:
        for a, b in zip(steps, steps[1:], strict=False):
            pairs += [(x, y) for x in a for y in b]
    for y in last:
        for steps in chains:
            # a step with an ANY span is open as a whole; in the others the spans that are not FREE are firm
            firm = [[x for x in s if x not in free] for s in steps if s[0] < y and not any_order & set(s)]
            firm = [s for s in firm if s]
            if firm:  # the chain's last firm step: the earlier ones are before it already
                pairs += [(x, y) for x in firm[-1]]
    return sorted(drop_cycles(pairs))


def leading_first(
    text: str, spans: list[tuple[int, int]], relations: list[str], pairs: list[tuple[int, int]]
) -> list[tuple[int, int]]:
    """`pairs` with what a leading "First X" states where no sequencing word follows it ("First X. Also Y",
    "First X, and Y, and also Z"): X before every later span not allowed at any time or in any order and not
    stated before X, as "Finally Y" is after every such span (ANNOTATION_GUIDE.md); the opening step as a
    whole where more follows it ("First X and Y. Also Z": X and Y before Z). "First X, then Y" (or "First X.
    Once X is done, Y") states only what its order word does; an afterthought ("Oh and Z") takes no order from
    it (`courtesy`). `spans`: the spans' character ranges in `text` (the grammar's own "first" openers before
    the first).

    >>> leading_first("First A, B. Also C", [(6, 7), (9, 10), (17, 18)], ["START", "PAR", "BARE"], [])
    [(0, 2), (1, 2)]
    >>> leading_first("First, A. B", [(7, 8), (10, 11)], ["START", "BARE"], [])
    [(0, 1)]
    """
    from nl2hltl2plan.language.grammar.then_steps import says_any_order
    from nl2hltl2plan.language.grammar.word_tables import FIRST, LEADING

    # "First, A, B and C. Do these in any order.": the remark no span carries frees the list
    if len(relations) < 2 or says_any_order(text[spans[-1][1] :]):
        return pairs
    if len(relations) < 2 or relations[0] != "START" or relations[1] in ("SEQ", "ANY", "REF", "ALL"):
        return pairs
    if not any(kind == FIRST and rx.match(text[: spans[0][0]].strip() + " ") for rx, kind in LEADING):
        return pairs
    groups: list[list[int]] = []  # a span and the PAR / ANY spans joined to it
    for i, rel in enumerate(relations):
        if i and rel in ("PAR", "ANY"):
            groups[-1].append(i)
        else:
            groups.append([i])
    firsts = groups[0] if len(groups) > 1 else [0]
    succ: dict[int, set[int]] = {}
    for x, y in pairs:
        succ.setdefault(x, set()).add(y)
    # a group with an ANY span is open as a whole ("C and D in any order"), as for "finally"
    open_ = {i for g in groups if any(relations[j] == "ANY" for j in g) for i in g}
    open_ |= {i for i in range(1, len(spans)) if _AFTERTHOUGHT.search(text[spans[i - 1][1] : spans[i][0]])}
    skip = set(firsts) | open_
    later = [i for i in range(1, len(relations)) if i not in skip and relations[i] != "FREE"]
    out = pairs + [(x, y) for x in firsts for y in later if not _reaches(succ, y, x)]
    return sorted(drop_cycles(out))


def _pointed(relations: list[str], targets: list[int | None]) -> list[tuple[int, int]]:
    """The pairs of the relations that point back (a REF / RPRE without a valid target states none)."""
    out = []
    for i, (rel, j) in enumerate(zip(relations, targets, strict=True)):
        if rel == "ALL":
            out += [(x, i) for x in range(i)]
        elif rel in ("REF", "RPRE") and j is not None and 0 <= j < i:
            out.append((j, i) if rel == "REF" else (i, j))
    return out


def drop_cycles(pairs: list[tuple[int, int]]) -> set[tuple[int, int]]:
    """The pairs in their order, each kept unless it closes a cycle with those kept before it."""
    kept: set[tuple[int, int]] = set()
    succ: dict[int, set[int]] = {}
    for a, b in pairs:
        if (a, b) in kept or a == b or _reaches(succ, b, a):
            continue
        kept.add((a, b))
        succ.setdefault(a, set()).add(b)
    return kept


def _reaches(succ: dict[int, set[int]], src: int, dst: int) -> bool:
    stack, seen = [src], {src}
    while stack:
        x = stack.pop()
        if x == dst:
            return True
        for y in succ.get(x, set()) - seen:
            seen.add(y)
            stack.append(y)
    return False


_SENTENCE_END = re.compile(r"[.!?;\n]")
_FIRST_BEFORE = re.compile(r"\bfirst\W*$", re.I)
# a span that opens with its object: its verb left out ("and the mug in the sink")
_VERBLESS = re.compile(r"\W*(?:the|a|an|one|two|three|four|\d+|some|another|both|my|your)\b", re.I)


def then_after_last(
    text: str, spans: list[tuple[int, int]], relations: list[str], pairs: list[tuple[int, int]]
) -> list[tuple[int, int]]:
    """`pairs` less those an in-sentence "then" does not state: "A and B then C" / "A and B and when you're
    done C" orders C after B only, ANNOTATION_GUIDE.md's "Then Y" -> [previous task, Y], "the one stated in
    the immediately preceding clause" (the grammar's `then_steps.clause_before`). A step that a leading
    "first" opens ("first A and B, then C"), a new sentence ("A and B. Then C") or an additive word ("A,
    plus B, then C") keeps its whole step.

    >>> rels, pairs = ["START", "PAR", "SEQ"], [(0, 2), (1, 2)]
    >>> then_after_last("A and B then C", [(0, 1), (6, 7), (13, 14)], rels, pairs)
    [(1, 2)]
    >>> then_after_last("A and B. Then C", [(0, 1), (6, 7), (14, 15)], rels, pairs)
    [(0, 2), (1, 2)]
    """
    from nl2hltl2plan.language.grammar.then_steps import joins_to_the_step

    drop: set[tuple[int, int]] = set()

    def joined(i: int) -> bool:  # span i joined to span i - 1 inside one sentence
        return _SENTENCE_END.search(text[spans[i - 1][1] : spans[i][0]]) is None

    for i, rel in enumerate(relations):
        if rel != "SEQ" or i < 2 or relations[i - 1] != "PAR" or not joined(i):
            continue
        if joins_to_the_step(text[spans[i - 2][1] : spans[i - 1][0]]):  # "B, plus C, then D": after both
            continue
        # as the grammar: a comma before "then" ("A and B, then C") or a verbless B ("A in X and B in Y
        # then C") keeps the whole step (the committed truths)
        said = text[spans[i - 1][0] : spans[i - 1][1]]
        if "," in text[spans[i - 1][1] : spans[i][0]] or _VERBLESS.match(said):
            continue
        j = i - 1
        while relations[j] == "PAR" and joined(j):
            j -= 1
        if relations[j] not in ("START", "SEQ") or _FIRST_BEFORE.search(text[: spans[j][0]]):
            continue
        k = i + 1
        while k < len(relations) and relations[k] == "PAR":
            k += 1
        drop |= {(x, y) for x in range(j, i - 1) for y in range(i, k)}
    return [p for p in pairs if p not in drop]


_SENTENCE = re.compile(r"[^.!?;\n]+[.!?;]*")


def sentences_left_out(text: str, spans: list[tuple[int, int]]) -> list[str]:
    """The sentences of `text` that no span (start, end) touches and that are more than a plain courtesy
    formula ("Thanks!", "please."): the structure model's reading drops them, so its reader names them in
    the assumptions ("Go Rovers!", "Miss you loads.", h299); check 1 has already found no content word in
    them.

    >>> sentences_left_out("Put the egg in the fridge. Go Rovers! Thanks.", [(0, 25)])
    ['Go Rovers']
    """
    plain = courtesy_words("courtesy_word") | courtesy_words("word") | courtesy_words("closing")
    left = []
    for m in _SENTENCE.finditer(text):
        touched = any(a < m.end() and m.start() < b for a, b in spans)
        words = re.findall(r"[a-z0-9']+", m[0].lower())
        # a sentence with an order, a count, a negation or a free order ("Any order works.", "Until
        # that's done, ...") may be what the reading's order says: not frame; a verb alone ("go") names
        # no step
        said = {c for w in words for c in categories(w)} - _NO_STEP
        ordered = free_order_remarks(m[0]) or _order_nouns() & set(words)  # ("In that order please.")
        if not touched and not said and not ordered and any(w not in plain for w in words):
            left.append(m[0].strip(" .!?;"))
    return left


# a verb's kinds that name no step alone ("Go Rovers!", "Miss you loads.": check 1 reads no task in them)
_NO_STEP = frozenset({"verb_step", "verb_any"})
_ORDER_NOUNS = Path(__file__).with_name("order_nouns.txt")


@cache
def _order_nouns() -> frozenset[str]:
    """The nouns that name an order ("in that order", "in this sequence": `order_nouns.txt`)."""
    text = _ORDER_NOUNS.read_text()
    return frozenset(w for line in text.splitlines() if not line.startswith("#") for w in line.split())
