"""Order words in word accounting (`accounting.account`): a sequence word needs an ordering between the
base tasks, a phrase that frees an order needs an unordered pair, an order said of named things ("prior
to putting the pillows, put a vase ...") must be the parse's order, and "X before Y ... Y before X" is a
cycle (an input error).

>>> from nl2hltl2plan.language.grounding import tokens
>>> from nl2hltl2plan.language.parse_usage import ParseUsage
>>> from nl2hltl2plan.language.task_specs import BaseTaskSpec
>>> two = [BaseTaskSpec(id=i, kind="place", object=["Mug"], receptacle=["Sink"]) for i in "AB"]
>>> text = "put a mug in the sink, then another - either order is ok"
>>> [u.words for u in unordered_steps(tokens(text), set(), ParseUsage(two, [("A", "B")]))]
['either order is ok']
"""

from __future__ import annotations

import re

import networkx as nx

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.content_words import DETERMINERS, FreeOrder, Unread, categories, free_order_remarks
from nl2hltl2plan.language.grounding import Mention, camel_words, find_mentions, sentence_start, tokens
from nl2hltl2plan.language.parse_usage import ParseUsage
from nl2hltl2plan.language.task_specs import BaseTaskSpec, transitive_closure

# "Until the plate is on the shelf, don't put X on the shelf": the guide's "Do not Y until X" with the
# reference first (the negated task was dropped at exit 0); the negation reader leaves it to
# `grammar.order_phrases.not_before_as_after`, which reads it as "After X, Y"
UNTIL_FIRST = re.compile(
    r"(?:^|(?<=[.;!?]\s))[Uu]ntil\s+(?:you(?:'ve|\s+have)?\s+)?(?P<ref>[^,.;!?]+?)\s*,\s*(?:please\s+)?"
    r"(?:do\s+not|don't|dont)\s+(?P<task>(?:put|place|move|set|bring|take|throw|drop|carry)\b[^.;!?]+)"
)


def until_first_at(text: str, at: int) -> bool:
    """Does the sentence around `at` open with "Until X, don't put Y" (`UNTIL_FIRST`)?"""
    start = sentence_start(text, at)
    start += len(text[start:]) - len(text[start:].lstrip())
    return UNTIL_FIRST.match(text, start) is not None

# "With the bat done, Y" / "Whenever the vase is sorted, Y" / "Once the black table is sorted, Y" / "With
# the mug out of the way, Y": a thing's task said to be finished opens a reference, as "Once the bat is
# done, Y" does (the words that say a step is finished: done, sorted, handled, taken care of ...;
# `grammar.state_references.finished_thing` reads it)
_FINISHED = (
    r"(?:done|finished|complete|completed|sorted(?:\s+out)?|handled|settled|taken\s+care\s+of|dealt\s+with|"
    r"out\s+of\s+the\s+way|squared\s+away|in\s+place)"
)
WITH_DONE = re.compile(
    rf"(?:(?<=^)|(?<=[.;!?]\s))(?P<lead>with|whenever|once|when|after)\s+(?P<np>(?:the|your|that|this)\s+[a-z]+"
    r"(?:\s+(?!(?:is|are|has|have|gets?)\b)[a-z]+)?)\s+"
    rf"(?:(?P<verb>is|are|has\s+been|have\s+been|gets|get)\s+)?(?P<done>{_FINISHED})\s*,\s*",
    re.I,
)


def finished_words(text: str) -> set[int]:
    """Where the words that say a thing's task is finished begin ("sorted" of "whenever the vase is sorted,"):
    a state of the step, not a request to sort it."""
    return {m.start("done") for m in WITH_DONE.finditer(text)}


# a phrase that frees the order of some pair of tasks ("in either order", "the order is up to you",
# "in no particular order"; content_words.free_order_remarks): "then B - either order is ok" frees nothing
# when the parse orders every pair (the phrase was not read); "at any time" / "meanwhile" free one task from
# the tasks before it, and a later "after this" may still order it, so they are `any_order` words instead;
# a phrase that frees the order within each group only ("each pair in either order") leaves the order
# words between the groups asked


def _not_a_step(words: list[str], i: int, in_mention: set[int]) -> bool:
    """An order word that names no step: "next to the sink" (a place), "go ahead and", "the second drawer"
    and "in second drawer" (an ordinal of a place), "your first job: X, Y" (a heading of the list, read so
    by the grammar's openers)."""
    ordinal = words[i] in ("first", "second", "third")
    return (
        words[i : i + 2] == ["next", "to"]
        or words[i - 1 : i + 1] == ["go", "ahead"]
        or (ordinal and i > 0 and words[i - 1] in ("the", "a", "its"))
        or (ordinal and i + 1 in in_mention and i > 0 and words[i - 1] in _PLACE_PREPOSITIONS)
        or (words[i - 1 : i + 1] == ["your", "first"] and words[i + 1 : i + 2] in (["job"], ["task"]))
    )


_PLACE_PREPOSITIONS = frozenset({"in", "into", "on", "onto", "inside", "from", "to"})


def unordered_steps(
    toks: list[tuple[str, int, int]], in_mention: set[int], parse: ParseUsage, per_group_only: bool = False
) -> list[Unread]:
    """Order words: with several base tasks and no word that frees the order, a sequence word needs an
    ordering between them; a phrase that frees an order ("in either order", "the order is up to you")
    needs a pair of base tasks the parse leaves unordered. `per_group_only`: the text as written frees the
    order within each group only (its phrases are read so whatever a rewriting made of them)."""
    plain = [w for w, _, _ in toks]
    text = " ".join(plain)
    remarks = _remarks(text, per_group_only)
    words = [
        w
        for i, w in enumerate(plain)
        if i not in in_mention
        and "order" in categories(w)
        and not _not_a_step(plain, i, in_mention)
        and not _inside_one_task(plain, i, parse)
        and not _treated_first(plain, i, parse)
    ]
    words += [p for p in ("in that order", "in this order") if f" {p} " in f" {text} "]
    words += [p for p in ("at the end", "in the end") if re.search(rf"\b{p}\b(?! of\b)", text)]
    free = frees_an_order(toks, in_mention, per_group_only)
    if len(parse.tasks) >= 2 and remarks and _totally_ordered(parse):
        return [Unread(remarks[0].words, "order", "it leaves an order free, but every base task is ordered")]
    if len(parse.tasks) == 1 and (late := _closing_delay(plain)):
        why = "one base task, nothing said before it: a later time no plan made now keeps; say what to do now"
        return [Unread(late, "time", why)]
    if not words or len(parse.tasks) < 2 or parse.before or free:
        return []
    return [Unread(", ".join(dict.fromkeys(words)), "order", "the base tasks are not ordered")]


_AFTER_DELAY = frozenset({"on", "please", "thanks", "thank", "you", "ok", "okay"})


def _closing_delay(words: list[str]) -> str | None:
    """The `delay` word ("later", "afterwards") that closes the request, only courtesy after it ("put the
    remote on the sofa later, please"); inside, it orders a task's own steps ("chill it and later put
    ...")."""
    late = [i for i, w in enumerate(words) if "delay" in categories(w)]
    if not late or words[late[-1] - 1] == "for":  # "leave the bread out for later": kept for a later use
        return None
    return words[late[-1]] if set(words[late[-1] + 1 :]) <= _AFTER_DELAY else None


def frees_an_order(
    toks: list[tuple[str, int, int]], in_mention: set[int], per_group_only: bool = False
) -> bool:
    """Whether a word or phrase of the text (`toks`; the words of `in_mention` name things) leaves the order
    of some pair of tasks free: a phrase that frees it across the groups ("in any order", "the order is up to
    you"), or an `any_order` word outside such phrases and outside things' names ("whenever you like"); a
    phrase that frees the order within each group only ("each pair in either order") frees none of them.
    The one test, for check 1 and for the model readings `learned.structured` accepts."""
    plain = [w for w, _, _ in toks]
    remarks = _remarks(" ".join(plain), per_group_only)
    # the word "any" of "each pair in any order" frees only within the groups, as its phrase does
    in_remark = {i for i, at in enumerate(_starts(plain)) if any(r.start <= at < r.end for r in remarks)}
    return any(not r.per_group for r in remarks) or any(
        "any_order" in categories(w)
        for i, w in enumerate(plain)
        if i not in in_mention | in_remark and not _while_held(plain, i)
    )


def _while_held(words: list[str], i: int) -> bool:
    """ "turn the lamp on while you hold it": the "while" of one examination under a lamp (the holding and the
    light at once), which frees no order between tasks (session 35: it let "..., but they can wait till you've
    done the lamp" pass with no order)."""
    after = words[i + 1 : i + 4]
    held = after[:1] == ["holding"] or after[:2] in (["you", "hold"], ["you're", "holding"])
    return words[i] == "while" and held


def _remarks(text: str, per_group_only: bool) -> list[FreeOrder]:
    """The phrases of `text` (words joined by blanks) that free an order; `per_group_only`: each frees the
    order within each group only."""
    said = free_order_remarks(text)
    return [FreeOrder(r.words, r.start, r.end, r.per_group or per_group_only) for r in said]


def _inside_one_task(words: list[str], i: int, parse: ParseUsage) -> bool:
    """Does the order word at `i` order the steps of one base task, its words on both sides in the task's
    own text and the thing named again by a pronoun after it ("chill the lettuce then return it to the
    counter"), or its container named on both sides ("put the pen in the bowl. then put the bowl on ...")?"""
    for task in parse.tasks:
        own = [w for w, _, _ in tokens(task.text or "")]
        held = _container_words(task)
        for at in range(max(0, i - len(own) + 1), i):
            k = i - at  # the order word's place in the task's words
            again = _PRONOUNS | (held & set(own[:k]))
            if words[at : at + len(own)] == own and 0 < k < len(own) - 1 and again & set(own[k + 1 :]):
                return True
    return False


def _treated_first(words: list[str], i: int, parse: ParseUsage) -> bool:
    """Is the order word a treatment's own, "wash it first" / "heat it up before (that)" / "only after rinsing
    it", where a task treats its thing so: before that task's placing, which the task's kind says (h236)?"""
    kinds = {f"verb_{t.kind}" for t in parse.tasks}
    if words[i] == "after" and i >= 1 and words[i - 1] == "only" and i + 2 < len(words):
        return bool(categories(words[i + 1]) & kinds) and words[i + 2] in _PRONOUNS
    at = i - 1 - (i >= 3 and words[i - 1] in ("up", "off", "down"))
    return (
        words[i] in ("first", "before", "beforehand")
        and at >= 1
        and words[at] in _PRONOUNS
        and bool(categories(words[at - 1]) & kinds)
        and (i + 1 == len(words) or words[i + 1] in ("that", ".", ",", "!", ";"))
    )


def _container_words(task: BaseTaskSpec) -> set[str]:
    """The last words of the phrases that name a place-in-container task's container in its text ("bowl")."""
    if not task.container:
        return set()
    said = find_mentions(task.text or "")
    return {m.surface.lower().split()[-1] for m in said if set(m.entry.types) & set(task.container)}


_PRONOUNS = frozenset({"it", "them"})


def _starts(words: list[str]) -> list[int]:
    """Where each word begins in the words joined by blanks."""
    out, at = [], 0
    for w in words:
        out.append(at)
        at += len(w) + 1
    return out


def _totally_ordered(parse: ParseUsage) -> bool:
    ids = [t.id for t in parse.tasks]
    closure = transitive_closure(list(parse.before), ids)
    return all((a, b) in closure or (b, a) in closure for k, a in enumerate(ids) for b in ids[k + 1 :])


def check_cycles(
    instruction: str, toks: list[tuple[str, int, int]], mentions: list[Mention], parse: ParseUsage
) -> None:
    """'X ... before the Y' / 'X ... after the Y' between object nouns of one sentence: a cycle is an
    input error."""
    objects = {t for _, role, st in parse.slots() if role == "object" for t in st}
    objs = [m for m in mentions if set(m.entry.types) & objects or not objects]
    g = nx.DiGraph()
    for i, (w, _, _) in enumerate(toks):
        if w not in ("before", "after"):
            continue
        j = i + 1
        while j < len(toks) and toks[j][0] in DETERMINERS:
            j += 1
        right = [m for m in objs if m.start == j]
        left = [
            m for m in objs if m.end <= i and not re.search(r"[.;!?]", instruction[m.char_end : toks[i][1]])
        ]
        if not left or not right:
            continue
        a, b = left[-1].entry.canonical, right[0].entry.canonical
        if a != b:
            g.add_edge(*((a, b) if w == "before" else (b, a)))
    try:
        cycle = nx.find_cycle(g)
    except nx.NetworkXNoCycle:
        return
    names = [camel_words(a) for a, _ in cycle] + [camel_words(cycle[0][0])]
    raise HTTError(f"cyclic order in the instruction: {' before '.join(names)}")


def misordered(
    instruction: str, toks: list[tuple[str, int, int]], mentions: list[Mention], parse: ParseUsage
) -> list[Unread]:
    """An order said of named things that the reading does not keep: "Prior to putting the pillows, put
    a vase in the safe" needs the vase's task before the pillows' task, "Y after you put the X" and "the
    moment the X is in the P, Y" the X's before Y's. The connective opens a clause whose object is named
    right after it (over "you", "you've", one verb and determiners); the other clause is the rest of the
    sentence after the comma that closes it, or before the connective."""
    objects = {o for t in parse.tasks for o in [*t.object, *(t.container or [])]}
    closure = transitive_closure(list(parse.before), [t.id for t in parse.tasks])
    lowered, out = instruction.lower(), []
    for conn in _CONNECTIVE.finditer(lowered):
        j = next((k for k, t in enumerate(toks) if t[1] >= conn.end()), len(toks))
        named = _named_after(toks, j, mentions)
        if named is None or not set(named.entry.types) & objects:
            continue
        if re.search(r"[,;:.!?]", instruction[conn.end() : named.char_start]):
            continue  # "Once finished, move the plunger": the plunger is the main clause's
        sentence = _sentence_span(instruction, conn.start())
        before_it = lowered[sentence[0] : conn.start()]
        if any("negation" in categories(w) for w in re.findall(r"[\w']+", before_it)):
            continue  # "do not put X before Y": X after Y (the negation's reading)
        if _LEADS.fullmatch(before_it.rsplit(",", 1)[-1]):  # "Prior to X, Y": Y after the comma
            comma = instruction.find(",", named.char_end, sentence[1])
            if comma < 0:
                continue  # no other clause in the sentence
            other, clause = (comma, sentence[1]), (conn.start(), comma)
        else:  # "Y before you put the X": Y before the connective
            other, clause = (sentence[0], conn.start()), (conn.start(), sentence[1])
        firsts = _tasks_of(parse, named, mentions, clause)
        seconds = _tasks_in(instruction, parse, other, mentions, objects) - firsts
        if not firsts or not seconds:
            continue
        after = conn.group("before") is None
        pairs = {(a, b) if after else (b, a) for a in firsts for b in seconds}
        if not pairs & closure:
            words = instruction[conn.start() : named.char_end]
            out.append(Unread(words, "order", "the reading does not order the tasks as these words say"))
    return out + _first_not_first(instruction, mentions, parse, objects, closure) + _turned_round(instruction)


# "first" opening a sentence, after a courtesy word at most ("Please, first you put ..."), not set off by a
# comma ("First, ..." opens the whole sentence) nor after an order phrase ("after that, first the saucers")
_OPENING_FIRST = re.compile(
    r"(?:^|[.;!?]\s+)(?:(?:please|ok|okay|so|now|alright|right|well)\s*,?\s*)?(?P<first>first)\b(?!\s*,)",
    re.I,
)


def _first_not_first(
    instruction: str,
    mentions: list[Mention],
    parse: ParseUsage,
    objects: set[str],
    closure: set[tuple[str, str]],
    strict: bool = False,
) -> list[Unread]:
    """ "First A, and after you put B ..." read with B before A: the tasks of the clause "first" opens
    (to its first comma) must not come after another task of the same sentence; nor those of a clause
    "first" closes ("A, put B first, then C"). `strict` (`first_and_last_kept`): they must come before
    every other task of the sentence, and a clause "last" / "lastly" / "finally" closes after every one."""
    out = []
    for m in _OPENING_FIRST.finditer(instruction):
        end = _sentence_span(instruction, m.start("first"))[1]
        comma = instruction.find(",", m.end(), end)
        if comma < 0:
            continue
        firsts = _tasks_in(instruction, parse, (m.start("first"), comma), mentions, objects)
        others = _tasks_in(instruction, parse, (comma, end), mentions, objects) - firsts
        if _out_of_place(firsts, others, closure, strict):
            out.append(Unread(m["first"], "order", "the reading puts another task before what 'first' opens"))
    for m in _CLOSING_ORDER.finditer(instruction):  # "A, put B first, then C": B before A too
        word = m["word"].lower()
        if word != "first" and not strict:
            continue
        start, end = _sentence_span(instruction, m.start())
        opens = max(instruction.rfind(",", start, m.start()), instruction.rfind(";", start, m.start()), start)
        said = _tasks_in(instruction, parse, (opens, m.start()), mentions, objects)
        others = _tasks_in(instruction, parse, (start, end), mentions, objects) - said
        held, why = closure, "the reading puts another task before the one said first"
        if word != "first":  # "... and put the bread in the fridge last": after every other task
            held = {(b, a) for a, b in closure}
            why = f"the reading puts another task after the one said {word}"
        if said and _out_of_place(said, others, held, strict):
            out.append(Unread(m["word"], "order", why))
    return out


def first_and_last_kept(instruction: str, tasks: list[BaseTaskSpec], before: list[tuple[str, str]]) -> bool:
    """Whether a reading keeps what "first" opening or closing a clause, and "last" / "lastly" / "finally"
    closing one, say of its tasks, strictly (`_first_not_first`): the structure model's reading is held to
    it before it may replace the grammar's (`learned.structured.decide`)."""
    parse = ParseUsage(tasks, before)
    objects = {o for t in tasks for o in [*t.object, *(t.container or [])]}
    closure = transitive_closure(list(before), [t.id for t in tasks])
    mentions = find_mentions(instruction)
    return not _first_not_first(instruction, mentions, parse, objects, closure, strict=True)


def _out_of_place(firsts: set[str], others: set[str], closure: set[tuple[str, str]], strict: bool) -> bool:
    """Whether a task of `others` comes before one of `firsts` (`strict`: or any is not after them all)."""
    if any((b, a) in closure for a in firsts for b in others):
        return True
    return strict and any((a, b) not in closure for a in firsts for b in others)


# "first" closing a clause ("put the mug in the sink first, then ...", "... in the sink first."), and
# "last" / "lastly" / "finally" closing one
_CLOSING_ORDER = re.compile(r"(?<=\w)\s+(?P<word>first|last|lastly|finally)\b(?=\s*(?:[,;.!?]|$))", re.I)


_CONNECTIVE = re.compile(
    r"\b(?:(?P<before>before|prior to|ahead of)|after|once|following|the moment|as soon as)\b"
)
_SUBJECT = frozenset(
    {"you", "you've", "you're", "we", "we've", "i", "i've", "have", "having", "done", "finished"}
)


def _named_after(toks: list[tuple[str, int, int]], j: int, mentions: list[Mention]) -> Mention | None:
    """The thing named right after a connective at token `j`: over a subject, one verb and determiners."""
    while j < len(toks) and toks[j][0] in _SUBJECT:
        j += 1
    starts = {m.start: m for m in mentions}
    if j < len(toks) and j not in starts and _a_verb(toks[j][0]):
        j += 1  # the verb ("putting", "you put", "chilling")
    while j < len(toks) and toks[j][0] in DETERMINERS - _DEMONSTRATIVES:
        j += 1
    return starts.get(j)


_DEMONSTRATIVES = frozenset({"that", "this", "those", "these"})  # "after that the mug ...": that step


def _a_verb(word: str) -> bool:
    return word.endswith("ing") or any(c.startswith("verb_") for c in categories(word))


# what may stand between a clause's start (the sentence's, or a comma's) and a connective that opens it
_LEADS = re.compile(r"\s*(?:(?:and|then|but|so|right|just|only)\s*)*")


def _sentence_span(text: str, at: int) -> tuple[int, int]:
    end = _SENTENCE_END.search(text, at)
    return sentence_start(text, at), end.start() if end else len(text)


_SENTENCE_END = re.compile(r"[.;!?]")
# words that turn round what was said, which the grammar does not read (it reads "..., in reverse order"
# and "..., reversed" closing a sentence of tasks): "vice versa" and "the other way round" may swap the
# places as well as the order, and "Reversed." on its own names no tasks
_TURNED_ROUND = re.compile(
    r"\b(?:vice[\s-]+versa|(?:the\s+)?other\s+way\s+a?round|the\s+opposite\s+(?:order|way|sequence))\b|"
    r"(?:^|[.;!?]\s*)(?P<alone>(?:and\s+|then\s+)*(?:reversed|backwards|(?:in\s+)?reverse(?:\s+order)?))"
    r"\s*[.;!?]*\s*$",
    re.I,
)


def _turned_round(instruction: str) -> list[Unread]:
    return [
        Unread(m["alone"] or m.group(0), "order", "what it turns round is not read: say the order it means")
        for m in _TURNED_ROUND.finditer(instruction)
    ]


def _tasks_of(
    parse: ParseUsage, named: Mention, mentions: list[Mention], clause: tuple[int, int]
) -> set[str]:
    """The tasks of the thing named after a connective: of its type, and, where the clause names a place
    one of them uses ("once the soap is on the toilet"), those that use it."""
    types = set(named.entry.types)
    ids = {t.id for t in parse.tasks if set(t.object) & types or set(t.container or []) & types}
    places = {p for m in mentions if named.char_end <= m.char_start < clause[1] for p in m.entry.types}
    there = {t.id for t in parse.tasks if t.id in ids and set(t.receptacle or []) & places}
    return there or ids


def _tasks_in(
    instruction: str, parse: ParseUsage, span: tuple[int, int], mentions: list[Mention], objects: set[str]
) -> set[str]:
    """The tasks said in a clause: those whose own words lie in it, else those of the things it names."""
    lowered = instruction.lower()
    said = {t for m in mentions if span[0] <= m.char_start < span[1] for t in m.entry.types} & objects
    own = set()
    for t in parse.tasks:
        at = lowered.find(t.text.lower()) if t.text else -1
        if at >= 0 and at < span[1] and at + len(t.text) > span[0] and set(t.object) & said:
            own.add(t.id)
    return own or {t.id for t in parse.tasks if set(t.object) & said or set(t.container or []) & said}
