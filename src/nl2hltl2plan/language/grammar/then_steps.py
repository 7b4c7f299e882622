"""The steps of a sentence's clauses and the clause a "then" inside the sentence comes after
(ANNOTATION_GUIDE.md: "Then Y" -> [previous task, Y], the one stated in the immediately preceding clause)."""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import phrase_list_pattern
from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.draft_tasks import Tasks, Unit
from nl2hltl2plan.language.grammar.frames import IN_SENTENCE

# "in any order" / "order doesn't matter" said of a sentence: its clauses are one group
ANY_ORDER = re.compile(r"\b(?:any|either|whatever|whichever|no\s+particular)\s+order\b", re.I)
_ORDER_FREE = re.compile(r"\border\s+(?:doesn'?t|does\s+not|isn'?t|is\s+not)\s+(?:matter|important)\b", re.I)


def sentence_steps(units: list[Unit]) -> list[int]:
    """The step of each unit. Every sentence opens a step, and so does a clause joined to the one before by
    "then" ("..., then", "and once that's done", "and finally"): "A and B, then C" is the steps {A, B} and
    {C}; "A, B, then C" too (ANNOTATION_GUIDE.md: "A, B" states no order; `order_relations` orders C after B,
    the clause before "then", only)."""
    said = [k == 0 or u.sentence != units[k - 1].sentence or _follows_a_step(u) for k, u in enumerate(units)]
    out: list[int] = []
    for k in range(len(units)):
        out.append(out[-1] + 1 if out and said[k] else out[-1] if out else 0)
    return out


def _follows_a_step(u: Unit) -> bool:
    """Is the unit joined to the clauses before it in its sentence by "then" or "finally"?"""
    return u.seq_after_prev or (G.FINALLY, IN_SENTENCE) in u.markers


def clause_before(tasks: Tasks, steps: list[int], opener: int, texts: tuple[str, str]) -> list[int]:
    """What "then" opening unit `opener` comes after: the step before it, or its last clause alone where a
    comma alone joins that clause to the step ("A, B, then C" / "A, B, and then C": [B, C], the guide's
    "previous task ... stated in the immediately preceding clause"), a verbless item too ("put X in A, Y in
    B, then Z in C"), and so where "and" joins it ("A and B then C", below). `texts`: the instruction as
    read (its shared verbs restated) and as written."""
    text, written = texts
    units = tasks.units
    last = units[opener - 1]
    same = [j for j in range(opener) if steps[j] == steps[opener - 1]]
    step = [t for j in same for t in units[j].tasks]
    if len(same) > 1 and not last.joiner:
        return list(last.tasks)
    said, own = (tasks.specs[t].text for t in last.tasks[-2:]) if len(last.tasks) > 1 else ("", "")
    if own and _comma_alone(said, own, text):
        return [last.tasks[-1]]
    if len(step) < 2 or _open_step(tasks, [units[j] for j in same]):
        return step
    if len(same) < 2 or _shared(tasks, step[-2], step[-1], written):
        return step
    if _added(tasks, step[-2], step[-1], text):
        return step
    # "A and B then C" / "A and B and when you're done C" (no comma): B a clause of its own, the guide's
    # "immediately preceding clause", as "A, B, then C". The committed truths keep C after both where a
    # comma sets "then" apart ("A and B, then C") and after a verbless item ("A in X and B in Y then C")
    return step if _comma_before(tasks, last.tasks[-1], units[opener].tasks[0], written) else list(last.tasks)


def _open_step(tasks: Tasks, units: list[Unit]) -> bool:
    """Does the step leave its tasks one clause for "then": "first A and B, then C" (the guide's "First X,
    then Y" with X the two) or "A and B in any order, then C"?"""
    return any(kind == G.FIRST for u in units for kind, _ in u.markers) or any(
        says_any_order(tasks.specs[t].text) for u in units for t in u.tasks
    )


def _shared(tasks: Tasks, a: int, b: int, written: str) -> bool:
    """May tasks `a` and `b` be one clause's restated items ("put the apple and the mug in the sink" reads
    "put the apple in the sink and put the mug in the sink"): the same words but for their objects, and
    not both said in full ("rinse the plate and put it on the shelf and rinse the cup and put it on the
    shelf")?"""
    frames, low = [], " ".join(written.lower().split())
    for t in (a, b):
        np, words = tasks.nps[t], tasks.specs[t].text.lower()
        frames.append(" ".join(words.replace(np.text.lower(), " ", 1).split()) if np is not None else words)
    said = [tasks.specs[t].text.lower() in low for t in (a, b)]
    return frames[0] == frames[1] and not all(said)


def _added(tasks: Tasks, a: int, b: int, text: str) -> bool:
    """Is task `b` added to `a`'s step by an additive word or after a semicolon ("B; also C, and when
    finished D": D after both, h156's reading and the composer's "; also {x}", a PAR of B's step)?"""
    low = text.lower()
    said, own = tasks.specs[a].text.lower(), tasks.specs[b].text.lower()
    at = low.find(said)
    end = low.find(own, at + len(said)) if at >= 0 else -1
    return end >= 0 and joins_to_the_step(low[at + len(said) : end])


def joins_to_the_step(between: str) -> bool:
    """Do the words `between` two tasks add the second to the first's step ("; also", ", plus", ", as well
    as"): a "then" after them follows both (`clause_before`, `span_order.then_after_last`)?"""
    return ";" in between or _ADDITIVE.match(between.lower()) is not None


def _comma_before(tasks: Tasks, a: int, b: int, written: str) -> bool:
    """Is there a comma between task `a`'s words and task `b`'s as written ("A and B, then C"; the read
    text has "and after that" as ", then")? Words not found as written: yes (the whole step, as before)."""
    low = " ".join(written.lower().split())
    said, own = tasks.specs[a].text.lower(), tasks.specs[b].text.lower()
    at = low.find(said)
    end = low.find(own, at + len(said)) if at >= 0 else -1
    return end < 0 or "," in low[at + len(said) : end]


def _comma_alone(said: str, own: str, text: str) -> bool:
    """Is the item `own` joined to the item `said` before it by a comma alone (no "and", no word)? A verbless
    item's text carries the verb its list shares ("put a cold egg in the microwave"): found without it."""
    low = text.lower()
    end, spans = 0, []
    for item in (said.lower(), own.lower()):
        at, form = low.find(item, end), item
        if at < 0:
            form = item.split(" ", 1)[-1]
            at = low.find(form, end)
        if at < 0:
            return False
        spans.append((at, at + len(form)))
        end = at + len(form)
    return re.fullmatch(r"\s*,\s*", text[spans[0][1] : spans[1][0]]) is not None


_ADDITIVE = re.compile(rf"^\W*(?:and\s+)?(?:{phrase_list_pattern('order_scope.txt', 'additive')})\b")


def own_clause(k: int, tasks: Tasks, text: str) -> bool:
    """Is unit `k` a clause of its own after the one before it, set apart by a comma and a verb of its own
    ("Then B, and rinse C too")? The reader restates a shared verb ("Then look at the pen and the watch"
    reads "look at the pen ..., and look at the watch ..."; "wash these: X, Y and Z"), so a clause with the
    verb of the one before it may be that clause's second task: "then" is for both (left open)."""
    low, units = text.lower(), tasks.units
    said, own = tasks.specs[units[k - 1].tasks[-1]].text.lower(), tasks.specs[units[k].tasks[0]].text.lower()
    if said.split(" ", 1)[0] == own.split(" ", 1)[0]:  # ", <the same verb> ...": maybe restated
        return False
    at = low.find(said)
    end = low.find(own, at + len(said)) if at >= 0 else -1
    between = low[at + len(said) : end]
    # "After that, B; also C" / "B, plus C": an additive word joins C to B's step (the composed sets' form)
    return end >= 0 and "," in between and _ADDITIVE.match(between) is None


_ADDED_LAST = re.compile(rf"\b{phrase_list_pattern('order_scope.txt', 'added_last')}\W*$", re.I)
# a sentence that opens with "then" and no comma: "then" opens its first clause only (the committed sets'
# truths: "X. Then B, C, and D." -> [X, B]); "After that, B, and C." sets the marker apart: the sentence
_BARE_THEN = re.compile(r"^\W*(?:and\s+)?then\b(?!\s*,)", re.I)


def said_for_an_earlier_clause(
    marker: tuple[str, str], k: int, tasks: Tasks, written: tuple[str, list[str]], freed: bool
) -> bool:
    """Is a sentence's leading marker on unit `k` one that an earlier clause of the sentence carries (it was
    said once, before that clause), and `k` a clause of its own (`own_clause`) outside the marker's scope:
    after a bare "Then" ("X. Then B, and C." -> [X, B]: C's clause has no order word, ANNOTATION_GUIDE.md),
    one that adds a task ("..., and C too"), or one its own words free (`freed`: "..., and C whenever")?
    Otherwise a marker set apart by a comma opens the whole sentence ("After that Y" -> [previous task, Y],
    Y all it introduces: "X. After that, B, and C." orders B and C after X), as where the sentence leaves
    its clauses' order open ("Then B and C in any order": both after, the benchmark's form)."""
    text, sentences = written
    units = tasks.units
    u = units[k]
    if u.seq_after_prev or leaves_order_open(u, sentences) or not own_clause(k, tasks, text):
        return False
    said = sentences[u.sentence] if u.sentence < len(sentences) else ""
    if not (freed or _BARE_THEN.match(said) or _ADDED_LAST.search(tasks.specs[u.tasks[-1]].text)):
        return False
    return any(v.sentence == u.sentence and marker in v.markers for v in units[:k])


def leaves_order_open(u: Unit, sentences: list[str]) -> bool:
    """Does `u`'s sentence (of the instruction's `sentences`, `split_sentences` once for all its units) say
    "in any order" / "order doesn't matter" (one group: "then" is for all)?"""
    return says_any_order(sentences[u.sentence] if u.sentence < len(sentences) else "")


def says_any_order(said: str) -> bool:
    """Does `said` say "in any order" / "order doesn't matter"?"""
    return ANY_ORDER.search(said) is not None or _ORDER_FREE.search(said) is not None
