"""Constraints beside a hierarchical spec: what a plan must never do (G ¬p) or not do before a task
is complete (an until-guard ¬p U q).

The spec's nodes are sc-LTL (positive normal form: every accepted trace has a finite good prefix);
G ¬p is a safety formula, which has no such prefix, so a constraint is not a node of the hierarchy.
It sits beside the nodes and is judged on the whole attributed trace: every action event is matched
against the constraint's atom patterns (`put(*,Microwave)`: `*` for any argument); an until-guard is
lifted once its spec node `until` is complete (strictly after that node's completion step, as the
hierarchy orders completions). The planner generates no event a constraint forbids
(`planning.model.Problem.forbidden_by`); the plan validator rejects a trace that breaks one.

>>> c = Constraint("never open the fridge", ("open(Fridge)",))
>>> c.formula
'G!"open(Fridge)"'
>>> print(*violations([c], [(3, "pickup(Apple)"), (5, "open(Fridge)")], {}))
t=5 open(Fridge) breaks the constraint 'never open the fridge' (G!"open(Fridge)")
>>> g = Constraint("do not open the fridge until the cups are in the rack", ("open(Fridge)",), "task1.1")
>>> g.formula
'!"open(Fridge)" U task1.1'
>>> violations([g], [(5, "open(Fridge)")], {"task1.1": 4})
[]
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from nl2hltl2plan.errors import SpecError
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.atom import Atom


@dataclass(frozen=True)
class Constraint:
    """G ¬(p1 | p2 ...) over action-atom patterns, or, with `until`, ¬(p1 | ...) U until."""

    text: str  # the instruction's words that state it: "never open the fridge"
    forbid: tuple[str, ...]  # atom patterns, `*` for any argument: "put(*,Microwave)"
    until: str | None = None  # a spec node whose completion lifts the ban (None: never lifted)

    def __post_init__(self) -> None:
        if not self.forbid:
            raise SpecError(f"constraint {self.text!r} forbids nothing")
        for p in self.forbid:
            if Atom.read_pattern(p) is None:
                raise SpecError(
                    f"constraint {self.text!r}: {p!r} is not an action atom (pattern) like "
                    "open(Fridge) or put(*,Microwave)"
                )
        object.__setattr__(self, "forbid", tuple(sorted(set(self.forbid))))  # canonical order

    @cached_property
    def patterns(self) -> tuple[Atom, ...]:
        return tuple(Atom.read_pattern(p) for p in self.forbid)  # type: ignore[misc]

    @cached_property
    def formula(self) -> str:
        """The constraint in LTL, as Spot prints it."""
        bad = " | ".join(f'"{p}"' for p in self.forbid)
        text = f"G !({bad})" if self.until is None else f"!({bad}) U {self.until}"
        return sb.parse(text).text

    @cached_property
    def _verdicts(self) -> dict[str, bool]:
        """atom -> `forbids(atom)`: the planner asks about the same few atoms at every successor."""
        return {}

    def forbids(self, atom: str) -> bool:
        """Does some pattern match the action atom `atom` (type level: `put(Mug,SinkBasin)`)?"""
        verdict = self._verdicts.get(atom)
        if verdict is None:
            a = Atom.read(atom)
            verdict = self._verdicts[atom] = a is not None and any(p.covers(a) for p in self.patterns)
        return verdict

    def lifted(self, completed_at: int | None, t: int) -> bool:
        """Is the ban lifted for an event at step t, when `until` completed at `completed_at`?"""
        return self.until is not None and completed_at is not None and completed_at < t

    def describe(self) -> str:
        return f"{self.text}: {self.formula}"

    def to_json(self) -> dict[str, Any]:
        return {"text": self.text, "forbid": list(self.forbid), "until": self.until}

    @classmethod
    def from_json(cls, data: Any) -> Constraint:
        if not isinstance(data, dict) or not isinstance(data.get("forbid"), list):
            raise SpecError(
                'a constraint is an object {"text": ..., "forbid": ["open(Fridge)"], "until": null}'
            )
        until = data.get("until")
        return cls(
            str(data.get("text", "")),
            tuple(str(p) for p in data["forbid"]),
            None if until is None else str(until),
        )


def violations(
    constraints: Sequence[Constraint],
    events: Iterable[tuple[int, str]],
    completed: Mapping[str, int | None],
) -> list[str]:
    """Why a trace of (step, type-level atom) events breaks the constraints (empty: it keeps them).
    `completed`: spec node -> the step it completed (None: never), for the until-guards."""
    out = []
    for t, atom in events:
        c = breach(constraints, atom, t, lambda node: completed.get(node))
        if c is not None:
            out.append(f"t={t} {atom} breaks the constraint {c.text!r} ({c.formula})")
    return out


def breach(
    constraints: Sequence[Constraint], atom: str, t: int, completed: Callable[[str], int | None]
) -> Constraint | None:
    """The first constraint that an event `atom` at step t breaks (None: it breaks none); `completed`
    gives a spec node's completion step (None: not complete). The planner and the validator share it."""
    for c in constraints:
        if c.forbids(atom) and not c.lifted(completed(c.until) if c.until else None, t):
            return c
    return None
