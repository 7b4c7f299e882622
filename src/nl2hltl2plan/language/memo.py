"""A memo for the pure judgements of a reading that one instruction asks several times.

Check 1 (`accounting.account`) is asked of one instruction about five times as it is read (the grammar's
parse, the learned parser's arbitration, the state reader's rereading, the final result), about half of
them with the same tasks. `reading_memo` keeps each answer by the value of its arguments: strings and
numbers as they are, models (`BaseTaskSpec`, `ConstraintSpec`) by their JSON, lists, tuples, sets and
mappings by what they hold and their type, so a list of lists never shares an answer with a list of
tuples. An argument of any other kind, or a call that raises, is not kept: it is computed every time. The
answer is kept as a tuple and handed out as a fresh list, so a caller may change what it gets.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Hashable, Mapping
from functools import wraps
from typing import ParamSpec, TypeVar

from pydantic import BaseModel

P = ParamSpec("P")
T = TypeVar("T")
_KEPT = 2048  # readings' answers kept per function (a few KB each); the oldest go first


class _Unkeyable(Exception):
    """An argument whose value cannot be told from its kind (a world, a callable): not memoized."""


def _frozen(value: object) -> Hashable:
    """The value of an argument as a key: equal keys for equal values of the same types."""
    if value is None or isinstance(value, str):
        return value
    if isinstance(value, int | float):  # 1, 1.0 and True are equal keys, and not one value here
        return type(value).__qualname__, value
    if isinstance(value, BaseModel):
        return type(value).__qualname__, value.model_dump_json()
    if isinstance(value, list | tuple):
        return type(value).__qualname__, tuple(_frozen(v) for v in value)
    if isinstance(value, set | frozenset):
        return type(value).__qualname__, frozenset(_frozen(v) for v in value)
    if isinstance(value, Mapping):
        items = sorted(((_frozen(k), _frozen(v)) for k, v in value.items()), key=repr)
        return type(value).__qualname__, tuple(items)
    raise _Unkeyable(type(value).__qualname__)


def reading_memo(fn: Callable[P, list[T]]) -> Callable[P, list[T]]:
    """`fn`, a pure function of its arguments' values returning a list, answered once per value."""
    kept: dict[Hashable, tuple[T, ...]] = {}
    lock = threading.Lock()  # the web server reads instructions on several threads

    @wraps(fn)
    def memo(*args: P.args, **kwargs: P.kwargs) -> list[T]:
        try:
            key = _frozen(args), _frozen(kwargs)
        except _Unkeyable:
            return fn(*args, **kwargs)
        if (answer := kept.get(key)) is None:
            answer = tuple(fn(*args, **kwargs))
            with lock:
                if len(kept) >= _KEPT:
                    del kept[next(iter(kept))]
                kept[key] = answer
        return list(answer)

    return memo
