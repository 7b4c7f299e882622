"""SMART-LLM's metrics exactly as its scripts compute them, beside the project's definitions.

SMART-LLM (github.com/SMARTlab-Purdue/SMART-LLM @ be42930) scores a run in
`data/aithor_connect/end_thread.py`, with `no_trans` counted by `scripts/execute_plan.py`:

- GCR: one "task" per ground-truth entry (`{"name", "state", "contains"}`, raw names); for every
  object of the final state whose name contains `name`, +1 per satisfied state among SLICED, OFF,
  ON, HOT, COOKED, OPENED, CLOSED, PICKED (BROKEN and FILLED are never checked), and +1 per
  received object whose id contains an entry of `contains`. GCR = completions / entries (1 without
  entries): two matching objects count twice, so GCR can exceed 1; an entry with no state and no
  contents still counts as a task that nothing completes.
- TC = 1 iff GCR == 1 exactly (so a GCR above 1 is not complete).
- RU: `no_trans` = the number of top-level call blocks of the LLM's script (its sequential
  stages); RU = 1 when max_trans == trans == no_trans - 1, 0 when max_trans == trans otherwise, else
  (max_trans + 1 - no_trans) / (max_trans - trans), not clipped (it can fall below 0 or exceed 1).
- SR = 1 iff TC == 1 and RU == 1. Exe = successful / attempted actions.

Our plans have no script: a plan's sequential stages (`suites.smartllm.smartllm_bench.stages`) stand for its
top-level blocks (a script of the plan would run one block per stage). Object names: AI2-THOR's
names start with the type, so an object's type stands for its name and a received object's type for
its id; a sliced object is the original whose slices exist.
"""

from __future__ import annotations

from collections.abc import Sequence

from nl2hltl2plan.worlds.effects import COOKED
from nl2hltl2plan.worlds.simulator import HOT, ON, OPEN, PRESENT, Snapshot
from nl2hltl2plan.worlds.world import World

Entry = tuple[str, str | None, tuple[str, ...]]  # raw name, state, contains


def script_gcr(world: World, snap: Snapshot, entries: Sequence[Entry]) -> float:
    """end_thread.py's GCR on a final snapshot (see the module docstring)."""
    objs = [world.objects[i] for i in world.ids]
    complete = 0
    for name, state, contains in entries:
        for k, obj in enumerate(objs):
            if name not in obj.type:
                continue
            complete += _state_count(world, snap, k, state)
            for rec in contains:
                complete += sum(
                    1
                    for j, other in enumerate(objs)
                    if snap.parent[j] == k and snap.flags[j] & PRESENT and rec in other.type
                )
    return complete / len(entries) if entries else 1.0


def _state_count(world: World, snap: Snapshot, k: int, state: str | None) -> int:
    obj, flags = world.objects[world.ids[k]], snap.flags[k]
    if state == "SLICED":
        return int(bool(obj.slices) and any(snap.flags[world.index[s]] & PRESENT for s in obj.slices))
    checks = {
        "OFF": not flags & ON,
        "ON": bool(flags & ON),
        "HOT": bool(flags & HOT),
        "COOKED": bool(flags & COOKED),
        "OPENED": bool(flags & OPEN),
        "CLOSED": not flags & OPEN,
        "PICKED": snap.holder[k] >= 0,
    }  # no BROKEN, no FILLED: the script never checks them
    return int(checks.get(state or "", False))


def script_ru(no_trans: int, trans: int | None, max_trans: int | None) -> float | None:
    """end_thread.py's RU, unclipped; None where the task has no stage annotation."""
    if trans is None or max_trans is None:
        return None
    worst, gt = max_trans + 1, trans + 1
    if worst == gt and gt == no_trans:
        return 1.0
    if worst == gt:
        return 0.0
    return (worst - no_trans) / (worst - gt)


def script_metrics(
    world: World,
    snap: Snapshot,
    entries: Sequence[Entry],
    no_trans: int,
    trans: int | None,
    max_trans: int | None,
    exe: float,
) -> dict[str, float | None]:
    """SR, TC, GCR, RU, Exe as SMART-LLM's script computes them (SR None without a stage annotation)."""
    gcr = script_gcr(world, snap, entries)
    tc = 1.0 if gcr == 1.0 else 0.0
    ru = script_ru(no_trans, trans, max_trans)
    sr = None if ru is None else (1.0 if tc == 1.0 and ru == 1.0 else 0.0)
    return {"SR": sr, "TC": tc, "GCR": gcr, "RU": ru, "Exe": exe}
