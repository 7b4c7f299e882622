"""What a planning call may spend, and why it stopped: one `Budget` type and one `StopReason` enum
for both engines (the search planner, `api.py`, and the cooperative handover planner, `coop.py`).

Every limit counts machine-independent work (expansions, generated successors, heuristic work,
replays), so the same input gives the same plan on any machine under any load; the wall clock is
only a last resort, reported as `StopReason.TIMEOUT`.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum


class StopReason(StrEnum):
    """Why a search stopped (a str, so `result.stopped == "bound"` works)."""

    NONE = ""  # not stopped by a search (infeasible before search, or no search ran)
    TRIVIAL = "trivial"
    EXHAUSTED = "exhausted"
    BOUND = "bound"
    BUDGET = "budget"
    STALLED = "stalled"
    MEMORY = "memory"
    TIMEOUT = "timeout"

    @property
    def sentence(self) -> str:
        """The reason in words, as `PlanResult.stop_reason` reports it."""
        return _SENTENCES[self]


_SENTENCES = {
    StopReason.NONE: "",
    StopReason.TRIVIAL: "the specification holds before any action",
    StopReason.EXHAUSTED: "search space exhausted (proven optimal)",
    StopReason.BOUND: "incumbent proven within the requested factor",
    StopReason.BUDGET: "expansion budget spent",
    StopReason.STALLED: "the proven bound stopped rising (fast mode's budget)",
    StopReason.MEMORY: "node limit reached (memory bound)",
    StopReason.TIMEOUT: "wall-clock timeout (last resort)",
}


@dataclass(frozen=True)
class Budget:
    """Machine-independent limits of one planning call. The search planner reads every field; the
    cooperative planner reads `expansions` (all its A* searches together)."""

    expansions: int | None = None  # expansions (the search planner's: its AWA*'s; None: no limit)
    generated: int | None = None  # AWA* successors generated (None: no limit)
    work: int | None = None  # AWA* heuristic work (`Heuristic.work`; None: no limit)
    improve_evals: int = 0  # local-search candidate replays
    lns_evals: int = 0  # large-neighbourhood-search candidate replays
    w_stop: float = 1.0  # stop once the incumbent is proven within this factor
    w_order: float = 1.0  # the weight of the A* ordering
    max_nodes: int | None = None  # memory bound of the A* (nodes held at once)
    free_stands: bool = False  # stand cells part of the A* search (the grid optimum of the summed cost)
    light_seeds: bool = False  # greedy and team beams rank children by the assignment bound alone (cheaper)
    # AWA*: past this much heuristic work, stop once the bound has not risen for STALL_SHARE of the
    # work spent (None: never)
    stall_work: int | None = None
