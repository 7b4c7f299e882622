"""Counts against the scene (check 1, issue 23): a count before a noun must be the count of the task on
that noun ("put two mugs ...": a `place_two` of 2), never zero and never more than the scene holds; "all
the mugs" / "every mug" takes every instance the scene holds."""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.content_words import DETERMINERS, LOCATIVE, Unread, categories
from nl2hltl2plan.language.grammar.counted_refs import counted_references
from nl2hltl2plan.language.grammar.word_tables import STATE_WORDS
from nl2hltl2plan.language.grounding import Mention, camel_words, find_mentions, tokens
from nl2hltl2plan.language.parse_usage import ParseUsage
from nl2hltl2plan.language.task_specs import BaseTaskSpec

# nouns that make a thing's name a description of tasks ("both bowl jobs", "the lamp ones")
_TASK_NOUNS = frozenset({"job", "jobs", "ones", "task", "tasks", "chores"})


def count_value(cats: frozenset[str], word: str) -> int | None:
    if word.isdigit():
        return int(word)
    for c in cats:
        if c.startswith("count_"):
            return int(c.removeprefix("count_"))
    return None


def counted(m: Mention, toks: list[tuple[str, int, int]]) -> bool:
    """Is the mention counted by a number or "both" up to three words before it ("two glasses", "both grey
    glasses")? A counted word names things one can count: "two glasses" are drinking glasses, never a pair
    of spectacles (ALFRED's train annotations: the Cup or Glassbottle in 19 of 19; see h184's report)."""
    for w, _, _ in toks[max(0, m.start - 3) : m.start][::-1]:
        if count_value(categories(w), w) is not None or w == "both":
            return True
    return False


def _next_mention(mentions: list[Mention], words: list[str], i: int, within: int = 3) -> Mention | None:
    """The noun a count word counts: the next mention, with only non-content words between, and no
    preposition ("put both in the fridge": "both" counts what was named before, not fridges)."""
    for m in mentions:
        if i < m.start <= i + within:
            between = words[i + 1 : m.start]
            # a state word may stand between ("three cold eggs": read before as 3 eggs of 2, at exit 0, h205)
            counted = all(w in DETERMINERS or w in STATE_WORDS or not categories(w) for w in between)
            counted = counted or _every_single(words, i, between)
            return m if counted and not set(between) & _PLACE_PREPS else None
    return None


_PLACE_PREPS = (LOCATIVE - {"of"}) | {"to", "into", "onto"}


def _every_single(words: list[str], i: int, between: list[str]) -> bool:
    """ "every single candle", "every last candle": the word after "every" stresses it, and counts nothing
    (read as one candle, at exit 0, h313's held probe)."""
    return words[i] in ("every", "each") and between in (["single"], ["last"])


# "all but": the one owner of a whole said with what it leaves out. After a counted noun, "all (of) the mugs
# but one / except the first / save two" (read as every mug, at exit 0: a vague count); before anything, "put
# all but the mug in the sink", "every item but the apple" (an exclusion no rule reads: the grammar moved the
# mug itself, h208), `all_but_said`
_ALL_BUT = re.compile(r"\s+(?:but|except|save|apart\s+from)\s+(?:for\s+)?(?:one|two|three|the\s+\w+)\b", re.I)
_WHOLE_BUT = re.compile(
    r"\b(?:everything|anything|every\s+[a-z]+|all(?:\s+(?:the|of))?(?:\s+[a-z]+)?)\s+but\b", re.I
)


def all_but_said(text: str) -> list[str]:
    """The words of each whole said with an exclusion ("all but", "every item but") in `text`, which the
    household reader names unread (`negations.exclusions_unread`).

    >>> all_but_said("Put all but the mug away, and every item but the egg in the fridge.")
    ['all but', 'every item but']
    """
    return [m[0].strip() for m in _WHOLE_BUT.finditer(text)]


def _both_of_more(words: list[str], i: int) -> str | None:
    """The count other than two that "both" is said of ("both three cups", "both of the four"), if any."""
    said = [w for w in words[i + 1 : i + 4] if w not in ("of", "the")][:1]
    return said[0] if said and count_value(categories(said[0]), said[0]) not in (None, 2) else None


def _of_all(words: list[str], i: int) -> bool:
    """ "..., and last of all a tomato in the sink", "first of all": the idiom's "all" counts nothing (it
    read as every tomato of the scene, at exit 0)."""
    return words[i] == "all" and i >= 2 and words[i - 1] == "of" and words[i - 2] in ("last", "first", "best")


def _both_before_a_list(w: str, instruction: str, start: int, m: Mention) -> bool:
    """ "both the mug and the apple": "both" names the pair of the list, not two mugs (as the grammar reads
    it, `sentences._BOTH_BEFORE_LIST`)."""
    between = instruction[start + len(w) : m.char_start]
    det = r"\s+(?:the|a|an|my|your|this|that)\s"
    return (
        w == "both"
        and re.match(det, between, re.I) is not None
        and re.match(r"\s+and" + det, instruction[m.char_end :], re.I) is not None
    )


# the words after a cut into N that take its pieces together, as a count
_PIECES_TAKEN = frozenset("them they all both those these".split())
_PIECE_PLURALS = frozenset("slices pieces wedges chunks halves quarters".split())


def _cut_into(words: list[str], i: int, cats: frozenset[str], parse: ParseUsage) -> Unread | None:
    """ "cut the bread into three slices (and put them ...)": how many slices a cut makes is no count a task
    takes (AI2-THOR's knife makes its own), unless the slices taken add up to it (read at exit 0, h282)."""
    n = count_value(cats, words[i])
    if n is None or i == 0 or words[i - 1] not in ("into", "in") or i + 1 == len(words):
        return None
    if "verb_sliced" not in categories(words[i + 1]):
        return None
    took = [max(1, t.count) for t in parse.tasks if t.sliced]
    if n in took or n == sum(took):
        return None
    # "cut the apple into three slices and put a slice (two slices) in the fridge": the count names the
    # pieces a cut makes, and the tasks take the ones they say (h307); "... put them / both / the slices"
    # takes the cut's pieces together, a count no task keeps
    after = words[i + 2 :]
    the_pieces = any(a == "the" and b in _PIECE_PLURALS for a, b in zip(after, after[1:], strict=False))
    if took and not _PIECES_TAKEN.intersection(after) and not the_pieces:
        return None
    took_said = " + ".join(map(str, took)) or "no"
    why = f"the base tasks take {took_said} slices: a cut into {n} is no count a task keeps"
    return Unread(" ".join(words[i - 1 : i + 2]), "count", why)


def count_unread(
    instruction: str,
    toks: list[tuple[str, int, int]],
    i: int,
    cats: frozenset[str],
    mentions: list[Mention],
    parse: ParseUsage,
    instances: Mapping[str, int] | None,
    scene: str,
) -> Unread | None:
    """A count before a noun: the task on that noun takes exactly so many (every one for "all")."""
    w, start, _ = toks[i]
    words = [t[0] for t in toks]
    if i > 0 and _every_single(words, i - 1, words[i : i + 1]):
        return None  # "every single candle": "every" counts them
    m = _next_mention(mentions, words, i)
    if m is None and (cut := _cut_into(words, i, cats, parse)):
        return cut
    if m is None and w == "both" and (more := _both_of_more(words, i)):  # "both (of) the three cups"
        return Unread(f"both {more}", "count", "'both' of more than two: say how many")
    if m is None or re.search(r"[,.;:!?]", instruction[start : m.char_start]):
        return None
    if _both_before_a_list(w, instruction, start, m) or (i > 0 and toks[i - 1][0] in ("those", "these")):
        return None  # "both the mug and the apple"; "after those two, the fork": tasks, not forks
    if m.end < len(words) and words[m.end] in _TASK_NOUNS:
        return None  # "until both bowl jobs are done": two tasks named by their thing, not two bowls (h190)
    if _of_all(words, i):
        return None
    types = set(m.entry.types)
    held = None
    if instances is not None:
        present = [t for t in m.entry.types if instances.get(t)]
        types = set(present if m.entry.all_ else present[:1]) or types
        held = sum(instances.get(t, 0) for t in types)
    n = count_value(cats, w)
    phrase = instruction[start : m.char_end]
    if n == 0:
        raise HTTError(f"a count of zero ({phrase!r}): there is nothing to do; say how many")
    if n is not None and held is not None and n > held:
        raise HTTError(f"{phrase!r}: {scene} holds only {held} {camel_words(m.entry.canonical)}")
    counts = [max(1, t.count) for t in parse.tasks if set(t.object) & types]
    if not counts and "quantifier_all" in cats and held is not None and held > 1:
        if any(set(t.receptacle or ()) & types for t in parse.tasks):  # "a pillow on each armchair"
            return Unread(phrase, "count", f"one task for each of {held} places: say each as its own task")
    if not counts:  # a count of places ("one of the drawers"), or of a noun the noun check reports
        return None
    if "quantifier_all" in cats:
        n = held
        if n is None:
            return None
        if but := _ALL_BUT.match(instruction, m.char_end):  # "all of the mugs but one": not every mug
            return Unread(phrase + but[0], "count", "'all' but some: say how many")
        if "other" in (t[0] for t in toks[i + 1 : m.start]):  # "all the other mugs": what the rest leave
            took = " + ".join(map(str, counts))
            if sum(counts) != n:
                return Unread(phrase, "count", f"the base tasks take {took}, not {n}")
            return None
    elif "quantifier_vague" in cats:
        return Unread(phrase, "count", "a vague count: say how many")
    if n in counts or (n == 2 and w in ("both", "pair", "couple") and len(counts) >= 2):
        return None
    if n == 1 and 2 in counts and i > 0 and toks[i - 1][0] == "and":
        return None  # "an empty and one full roll of toilet paper": one of the pair the task takes
    got = " + ".join(map(str, counts)) or "none"
    return Unread(phrase, "count", f"the base tasks take {got}, not {n}")


def take_every_instance(
    instruction: str, tasks: Sequence[BaseTaskSpec], instances: Mapping[str, int]
) -> list[BaseTaskSpec]:
    """ "all the mugs" / "every mug" / "each mug": the task on that noun takes every instance the scene
    holds (a `place` of several becomes `place_two` with that count; of one, a `place`); "all the other
    mugs" (`grammar.counted_refs`: "the rest of the mugs"): the last task on mugs takes what the others
    leave."""
    instruction = counted_references(instruction)
    toks = tokens(instruction)
    words = [w for w, _, _ in toks]
    mentions = [m for m in find_mentions(instruction) if not m.entry.generic]
    out = [t.model_copy() for t in tasks]
    for i, w in enumerate(words):
        if "quantifier_all" not in categories(w) or _of_all(words, i):
            continue
        m = _next_mention(mentions, words, i)
        if m is None or re.search(r"[,.;:!?]", instruction[toks[i][1] : m.char_start]):
            continue
        of_type = [k for k, t in enumerate(out) if set(t.object) & set(m.entry.types)]
        other = "other" in words[i + 1 : m.start]
        for k in of_type[-1:] if other else of_type:
            t = out[k]
            held = sum(instances.get(o, 0) for o in t.object if o in m.entry.types)
            held -= sum(out[j].count for j in of_type if j != k) if other else 0
            if held < 1 or t.count == held:
                continue
            kind = ("place_two" if held > 1 else "place") if t.kind in ("place", "place_two") else t.kind
            out[k] = t.model_copy(update={"kind": kind, "count": held})
    return out


# a count said as a multiplier after the thing's name ("pillows x2", "candles x 2", h295)
_MULTIPLIER = re.compile(r"[x×](\d{1,2})")


def multipliers_unread(
    toks: list[tuple[str, int, int]], mentions: list[Mention], parse: ParseUsage
) -> list[Unread]:
    """Each multiplier after a thing's name ("pillows x2") that no task on that thing takes: never left
    unread as a word of no kind (a task on one pillow is no reading of "pillows x2")."""
    out = []
    for i, (word, _, _) in enumerate(toks):
        times = _MULTIPLIER.fullmatch(word)
        named = [m for m in mentions if m.end == i]
        if times is None or not named:
            continue
        n, types = int(times[1]), set(named[-1].entry.types)
        counts = [max(1, t.count) for t in parse.tasks if set(t.object) & types]
        if counts and n not in counts:
            why = f"the base tasks take {counts[0]}, not {n}"
            out.append(Unread(f"{named[-1].surface} {word}", "count", why))
    return out


_ONE_SAID = re.compile(r"\b(?:one|single)\b", re.I)


def plural_as_one(
    instruction: str, m: Mention, tasks: Sequence[BaseTaskSpec], instances: Mapping[str, int], scene: str
) -> None:
    """A bare plural (`m`) that is the only word of the text naming its types, read as the one task of
    that type taking one whole thing where the scene holds more ("need the tisue boxes on the table" read
    as one box, h293): the plural lost in the reading, refused naming it, whichever backend read it. Not
    "the apples ... a slice", "the forks ... a fork" nor "the spoons. put one ...": a word names the one."""
    alone = all(o.char_start == m.char_start or not set(o.entry.types) & set(m.entry.types)
                for o in find_mentions(instruction)) and not _ONE_SAID.search(instruction, m.char_end)
    mine = [t for t in tasks if set(t.object) & set(m.entry.types)]
    if _head_shared(instruction, m, tasks, mine):
        return
    total = sum(instances.get(t, 0) for t in m.entry.types)
    if alone and len(mine) == 1 and mine[0].count == 1 and not mine[0].sliced and total > 1:
        raise HTTError(
            f"{m.surface!r}: {scene} has {total} of them and the task would take 1 (a plural read as one): "
            f"say how many ('two {m.surface}', 'all the {m.surface}'), or 'the {m.entry.phrase}' for one"
        )


def _head_shared(
    instruction: str, m: Mention, tasks: Sequence[BaseTaskSpec], mine: Sequence[BaseTaskSpec]
) -> bool:
    """Whether the plural is the head a list shares ("the salt and pepper shakers": one of each, as
    `grammar.phrases.one_of_each_under_a_shared_plural` reads it): said right after "and" / "or" / "&", with
    another task's type of the same head word."""
    if not re.search(r"\b(?:and|or|&)\s*$", instruction[: m.char_start], re.I):
        return False
    heads = {camel_words(o).split()[-1] for t in mine for o in t.object}
    return any(camel_words(o).split()[-1] in heads for t in tasks if t not in mine for o in t.object)
