"""The grammar's reading of an instruction as the style tests compare it: the task summaries, the
closure of the order as summary pairs, and what the grammar or the word accounting (check 1) left unread."""

from __future__ import annotations

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grammar import parse_instruction
from nl2hltl2plan.language.learned.inference import parse_instruction as offline_parse
from nl2hltl2plan.language.task_specs import transitive_closure

Reading = tuple[list[str], set[tuple[str, str]], list[str]]


def sorted_reading(text: str, types: set[str]) -> Reading:
    """Tasks sorted, unread as the words check 1 names (no affordances: every type takes every task)."""
    r = parse_instruction(text, types, "kitchen", affordances=lambda t: None)
    name = {t.id: t.summary() for t in r.tasks}
    order = {(name[a], name[b]) for a, b in transitive_closure(r.before, list(name))}
    unread = list(r.unparsed) + [u.words for u in account(text, r.tasks, r.before)]
    return sorted(name.values()), order, unread


def offline_reading(text: str, types: set[str], scene: str = "room") -> Reading:
    """The offline backend's reading (grammar and learned model, not strict): tasks in the order said, the
    order's closure, unread as the parser and check 1 say it."""
    p = offline_parse(text, types, scene, strict=False)
    name = {t.id: t.summary() for t in p.tasks}
    order = {(name[a], name[b]) for a, b in transitive_closure(p.before, list(name))}
    unread = list(p.unparsed) + [str(u) for u in account(text, p.tasks, p.before)]
    return [t.summary() for t in p.tasks], order, unread
