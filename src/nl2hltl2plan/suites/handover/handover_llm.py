"""The LLM-as-planner baseline of the handover study (the paper's Section IV-C): the LLM gets the
instance's coordinates (blocks, regions, every arm's reachable cells and start), the API and the
instruction, and must answer with the whole plan as API calls; the answer is turned into a timed
plan (one call after another, each arm walking a shortest path inside its reach), executed by the
handover simulator and checked against the task's written spec — exactly as our plans are judged.
A call the arm cannot carry out (a cell out of reach, a block it does not hold) is a failure with the
reason, never silently repaired.
"""

from __future__ import annotations

import time
from collections import deque
from typing import Any, Literal

from pydantic import BaseModel, Field

from nl2hltl2plan.errors import LLMError, Nl2Hltl2PlanError, WorldError
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.worlds.handover_world import ARMS, HandoverWorld, check_handover, execute_handover
from nl2hltl2plan.worlds.plan import Plan, RobotPlan, Step
from nl2hltl2plan.worlds.world import Cell


class ArmCall(BaseModel):
    arm: Literal["a", "b", "c", "d"]
    api: Literal["pick", "place"]
    block: str = Field(description="Red, Blue or Yellow")
    place: str = Field(description="where: a region E..J or a cell written r<row>c<col>, e.g. r2c1")


class HandoverAnswer(BaseModel):
    calls: list[ArmCall] = Field(min_length=1, max_length=80)


def handover_prompt(hw: HandoverWorld, instruction: str) -> list[dict[str, str]]:
    """Coordinates, the API and the request to minimise the arms' trajectories (the paper's prompt)."""
    lay = hw.layout
    arms = [
        f"- arm {ARMS[a]}: starts at r{hw.arm_starts[a][0]}c{hw.arm_starts[a][1]}; reaches "
        + ", ".join(f"r{r}c{c}" for r, c in sorted(lay.reach[a]))
        for a in range(len(ARMS))
    ]
    blocks = [f"- {b} block at {lay.place_name(cell)}" for b, cell in hw.blocks.items()]
    regions = [f"- region {name} = r{r}c{c}" for name, (r, c) in sorted(lay.regions.items())]
    system = (
        "You plan for four fixed robot arms. Answer with a JSON object "
        '{"calls": [{"arm": "a", "api": "pick", "block": "Red", "place": "E"}, '
        '{"arm": "a", "api": "place", "block": "Red", "place": "r2c1"}, ...]}.'
    )
    user = (
        "Cells are written r<row>c<col>. Each arm's end effector moves one cell per step, only within its "
        "reach; two end effectors never share a cell; a cell holds one block.\nArms:\n"
        + "\n".join(arms)
        + "\nBlocks:\n"
        + "\n".join(blocks)
        + "\nRegions:\n"
        + "\n".join(regions)
        + "\n"
        "API: pick(arm, block, place) moves the arm to the block's place and grasps it; place(arm, block, "
        "place) moves the arm holding the block there and releases it. A block passes from one arm to "
        "another only by being placed on a cell both reach.\n"
        f"Instruction: {instruction}\n"
        "Give the calls, in the order they are executed, that carry out the instruction, respect every "
        "constraint it states and minimise the total trajectory length of the end effectors."
    )
    return [{"role": "system", "content": system}, {"role": "user", "content": user}]


def _path(hw: HandoverWorld, arm: int, start: Cell, goal: Cell, blocked: set[Cell]) -> list[Cell]:
    """Shortest walk inside the arm's reach, around the other end effectors (cells after `start`)."""
    reach = hw.layout.reach[arm]
    if goal not in reach:
        raise WorldError(f"arm {ARMS[arm]} cannot reach {hw.layout.place_name(goal)}")
    prev: dict[Cell, Cell | None] = {start: None}
    queue = deque([start])
    while queue:
        cell = queue.popleft()
        if cell == goal:
            out: list[Cell] = []
            step: Cell | None = cell
            while step is not None and step != start:
                out.append(step)
                step = prev[step]
            return out[::-1]
        for dr, dc in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            nxt = (cell[0] + dr, cell[1] + dc)
            if nxt in reach and nxt not in prev and nxt not in blocked:
                prev[nxt] = cell
                queue.append(nxt)
    raise WorldError(f"arm {ARMS[arm]} cannot get to {hw.layout.place_name(goal)} past the other arms")


def _walk(
    hw: HandoverWorld, arm: int, goal: Cell, arm_cells: list[Cell], steps: dict[int, list[Step]], t: int
) -> int:
    """Move `arm` to `goal`; an idle end effector standing in the way is first parked at its start
    (the API has no move call, so the executor clears the way; parking counts in the cost)."""
    free_path = _path(hw, arm, arm_cells[arm], goal, set())
    for other, cell in enumerate(arm_cells):
        if other != arm and (cell in free_path or cell == arm_cells[arm]) and cell != hw.arm_starts[other]:
            blocked = {c for a, c in enumerate(arm_cells) if a != other}
            for step in _path(hw, other, cell, hw.arm_starts[other], blocked):
                t += 1
                steps[other].append(Step(t=t, verb="move", cell=step))
            arm_cells[other] = hw.arm_starts[other]
    others = {c for a, c in enumerate(arm_cells) if a != arm}
    for cell in _path(hw, arm, arm_cells[arm], goal, others):
        t += 1
        steps[arm].append(Step(t=t, verb="move", cell=cell))
    arm_cells[arm] = goal
    return t


def answer_plan(hw: HandoverWorld, answer: HandoverAnswer) -> Plan:
    """The calls one after another: the arm walks to the place, then picks or puts there."""
    arm_cells = list(hw.arm_starts)
    steps: dict[int, list[Step]] = {a: [] for a in range(len(ARMS))}
    t = 0
    for call in answer.calls:
        arm, block = ARMS.index(call.arm), call.block.capitalize()
        goal = hw.layout.cell_of(call.place)
        t = _walk(hw, arm, goal, arm_cells, steps, t)
        t += 1
        objects = [block] if call.api == "pick" else [block, hw.layout.place_name(goal)]
        steps[arm].append(Step(t=t, verb="pickup" if call.api == "pick" else "put", objects=objects))
    return Plan(robots=[RobotPlan(robot=a, start=hw.arm_starts[a], steps=steps[a]) for a in range(len(ARMS))])


def llm_handover(hw: HandoverWorld, spec: HierarchicalSpec, instruction: str, client: Any) -> dict[str, Any]:
    """Ask the LLM for the plan, execute it and check it against the spec; a bad answer is a failure."""
    t0 = time.perf_counter()
    try:
        answer = client.ask(handover_prompt(hw, instruction), HandoverAnswer, "handover_llm_planner")
        plan = answer_plan(hw, answer)
    except LLMError as exc:  # a dead LLM is an error of the run, not a failure of the baseline
        reasons = [f"LLM failed: {exc}"]
        return {"success": False, "errored": True, "cost": None, "runtime_s": time.perf_counter() - t0,
                "reasons": reasons}
    except Nl2Hltl2PlanError as exc:
        return {"success": False, "cost": None, "runtime_s": time.perf_counter() - t0, "reasons": [str(exc)]}
    execution = execute_handover(hw, plan, sorted(spec.atoms()))
    verdict = check_handover(spec, execution)
    ok = execution.ok and verdict.ok
    return {
        "success": ok,
        "cost": execution.travel + execution.actions if ok else None,
        "runtime_s": time.perf_counter() - t0,
        "reasons": execution.violations[:2] + verdict.reasons[:2],
    }
