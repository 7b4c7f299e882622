"""Gantt chart of a multi-robot plan: *when* each robot does what (matplotlib, Agg backend).

One lane per robot, time steps on the x axis. Runs of moves are grey bars ("move x6"), each action
is a bar coloured by the task it serves and labelled with its verb and objects, waits inside a
robot's plan are hatched, and the time after a robot's last step is left empty. Ordering
constraints `a before b` are drawn as arrows from the end of the last step serving `a` to the
start of the first step serving `b` (green when the plan keeps the order, red when it does not).
Failed steps of an execution are crossed out.
"""

from __future__ import annotations

import textwrap
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

from nl2hltl2plan.domain.plan_events import PlanEvent  # noqa: E402
from nl2hltl2plan.errors import WorldError  # noqa: E402
from nl2hltl2plan.io import save_figure  # noqa: E402
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.worlds.plan import Plan, RobotPlan  # noqa: E402
from nl2hltl2plan.worlds.simulator import Execution  # noqa: E402
from nl2hltl2plan.worlds.world import CELL_M  # noqa: E402

TASK_COLOURS = [plt.get_cmap("tab20")(k) for k in range(0, 20, 2)] + [
    plt.get_cmap("tab20")(k) for k in range(1, 20, 2)
]
MOVE_COLOUR = "#b0b0b0"
NO_TASK_COLOUR = "#8c8c8c"
BAR_Y, BAR_H = 0.22, 0.36  # bar centre offset and height inside a lane (lane i spans i-0.5..i+0.5)
LABEL_PT = 6.5  # action labels' font size
LABEL_ROOM = 0.5 - (BAR_Y - BAR_H / 2) - 0.02  # lane units between a bar's top and its lane's top


@dataclass(frozen=True)
class Segment:
    """A bar of one lane: steps start..end (inclusive) of one robot."""

    robot: int
    start: int
    end: int
    kind: str  # "move", "wait" or "action"
    label: str
    task: str | None = None
    failed: bool = False


def segments(robot_plan: RobotPlan, failed: frozenset[tuple[int, int]] = frozenset()) -> list[Segment]:
    """The lane's bars: merged runs of moves and of waits (gaps count as waits), one bar per action."""
    by_t = {s.t: s for s in robot_plan.steps}
    out: list[Segment] = []
    run_kind, run_start = "", 0

    def close(t_end: int) -> None:
        if run_kind:
            n = t_end - run_start + 1
            label = f"move x{n}" if run_kind == "move" else f"wait x{n}"
            out.append(Segment(robot_plan.robot, run_start, t_end, run_kind, label))

    for t in range(1, robot_plan.end + 1):
        step = by_t.get(t)
        kind = (
            "wait" if step is None or step.verb == "wait" else ("move" if step.verb == "move" else "action")
        )
        if kind != run_kind or kind == "action":
            close(t - 1)
            run_kind, run_start = ("", 0) if kind == "action" else (kind, t)
        if kind == "action" and step is not None:
            label = f"{step.verb}({', '.join(step.objects)})"  # the ids the text and the map use
            out.append(
                Segment(robot_plan.robot, t, t, "action", label, step.task, (robot_plan.robot, t) in failed)
            )
    close(robot_plan.end)
    return out


def _covers(name: str, task: str | None) -> bool:
    """A task name covers the leaf tasks of its subtree: `task1.2` covers `task1.2` and `task1.2.3`."""
    return task is not None and (task == name or task.startswith(name + "."))


def _ordering_arrows(
    segs: Sequence[Segment], before: Iterable[tuple[str, str]]
) -> list[tuple[Segment, Segment, bool]]:
    """(last segment serving a, first segment serving b, kept?) for every pair whose tasks occur."""
    arrows = []
    actions = [s for s in segs if s.kind == "action"]
    for a, b in before:
        sa = [s for s in actions if _covers(a, s.task)]
        sb = [s for s in actions if _covers(b, s.task)]
        if sa and sb:
            last = max(sa, key=lambda s: s.end)
            first = min(sb, key=lambda s: s.start)
            arrows.append((last, first, last.end < first.start))
    return arrows


def _as_plan(plan: Plan | Execution) -> tuple[Plan, frozenset[tuple[int, int]]]:
    if isinstance(plan, Execution):
        return plan.plan, frozenset((v.t, v.robot) for v in plan.violation_list)
    if isinstance(plan, Plan):
        return plan, frozenset()
    raise WorldError(f"draw_gantt needs a Plan or an Execution, got {type(plan).__name__}")


def draw_gantt(
    plan: Plan | Execution,
    path: str | Path | None = None,
    before: Iterable[tuple[str, str]] = (),
    title: str | None = None,
    words: Mapping[str, str] | None = None,
):
    """Draw the plan's Gantt chart and save it to `path` (png/svg/pdf); returns the figure.

    `before` holds ordering constraints as pairs of task names as the plan's steps name them
    (`("task1.1", "task1.2")`); a name also covers its subtree (`task1` covers `task1.2`). Use
    `present.htt_pictures.htt_orderings(htt)` to get them from an HTT. `words`: what each task name says
    (`present.htt_pictures.htt_task_words(htt)`), for a legend in words rather than task ids.
    """
    plan_obj, failed_rt = _as_plan(plan)
    failed = frozenset((r, t) for t, r in failed_rt)
    robots = sorted(plan_obj.robots, key=lambda r: r.robot)
    segs = [s for rp in robots for s in segments(rp, failed)]
    return _chart(
        segs,
        [rp.robot for rp in robots],
        plan_obj.horizon,
        list(before),
        title or _default_title(plan, plan_obj),
        path,
        words,
    )


def segments_from_events(events: Sequence[PlanEvent], robots: int) -> list[Segment]:
    """Bars from a plan's events (a benchmark row's or the planner's; `travel_m` walked before the
    action): as the planner lays plans out, a robot walks right after its previous action, then
    waits for the action's step."""
    out: list[Segment] = []
    for robot in range(robots):
        last = 0
        for e in sorted((e for e in events if e.robot == robot), key=lambda e: e.t):
            moves = min(round(e.travel_m / CELL_M), e.t - last - 1)
            if moves > 0:
                out.append(Segment(robot, last + 1, last + moves, "move", f"move x{moves}"))
            if e.t - last - 1 > moves:
                n = e.t - last - 1 - moves
                out.append(Segment(robot, last + moves + 1, e.t - 1, "wait", f"wait x{n}"))
            out.append(Segment(robot, e.t, e.t, "action", _instance_label(e), e.task))
            last = e.t
    return out


def _instance_label(event: PlanEvent) -> str:
    """The action with the objects it acted on (`put(Mug_1,Sink_0)`), the names the text output and
    the map use; the type-level atom when the row did not record them."""
    atom, objects = Atom.read(event.atom), event.objects
    if atom is None or len(objects) != len(atom.args):
        return event.atom
    return str(Atom(atom.verb, tuple(objects)))


def draw_gantt_events(
    events: Sequence[PlanEvent],
    robots: int,
    path: str | Path | None = None,
    before: Iterable[tuple[str, str]] = (),
    title: str | None = None,
):
    """The Gantt chart of a benchmark row (its `events`, no plan needed); see `draw_gantt`."""
    segs = segments_from_events(events, robots)
    horizon = max((s.end for s in segs), default=0)
    team = f"{robots} robot" + ("" if robots == 1 else "s")
    return _chart(segs, list(range(robots)), horizon, list(before), title or f"{team}, {horizon} steps", path)


def _chart(
    segs: list[Segment],
    robot_ids: list[int],
    horizon: int,
    before: list[tuple[str, str]],
    title: str,
    path: str | Path | None,
    words: Mapping[str, str] | None = None,
):
    horizon = max(horizon, 1)
    lanes = {r: i for i, r in enumerate(robot_ids)}
    tasks = sorted({s.task for s in segs if s.task})
    colour = {t: TASK_COLOURS[k % len(TASK_COLOURS)] for k, t in enumerate(tasks)}
    width = min(40.0, max(8.0, 0.32 * horizon + 3))
    label_actions = width / horizon >= 0.25  # room for a vertical label above a one-step bar
    longest = max((len(line) for s in segs if s.kind == "action" for line in _lines(s.label)), default=0)
    label_in = longest * LABEL_PT * 0.62 / 72 if label_actions else 0.0
    lane_in = max(2.1, (label_in + 0.15) / LABEL_ROOM)  # the labels fit inside their lane
    fig, ax = plt.subplots(figsize=(width, 0.9 + lane_in * max(1, len(robot_ids))))
    for s in segs:
        _draw_segment(ax, s, lanes[s.robot], colour, label_actions)
    for r in set(robot_ids) - {s.robot for s in segs}:
        ax.text(1, lanes[r] + BAR_Y, "idle (no steps)", va="center", fontsize=8, color="0.4")
    for last, first, kept in _ordering_arrows(segs, before):
        y0, y1 = lanes[last.robot] + BAR_Y + BAR_H / 2, lanes[first.robot] + BAR_Y + BAR_H / 2
        ax.annotate(
            "",
            xy=(first.start, y1),
            xytext=(last.end, y0),
            arrowprops={"arrowstyle": "-|>", "color": "tab:green" if kept else "tab:red", "lw": 1.6,
                        "connectionstyle": "arc3,rad=0.35", "shrinkA": 2, "shrinkB": 2},
            zorder=6,
        )  # fmt: skip
    ax.set_yticks([k + BAR_Y for k in range(len(robot_ids))], [f"robot {r}" for r in robot_ids])
    ax.set_ylim(len(robot_ids) - 0.5 + 0.08, -0.5)  # robot 0 on top; room below for order arrows
    for k in range(1, len(robot_ids)):
        ax.axhline(k - 0.5, color="0.8", lw=0.8)
    ax.set_xlim(0.3, horizon + 0.7)
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax.set_xlabel("time step")
    ax.grid(axis="x", alpha=0.3)
    ax.set_title(title, fontsize=10)
    ax.legend(handles=_legend_handles(tasks, colour, bool(before), words or {}), loc="upper left",
              bbox_to_anchor=(1.01, 1), fontsize=7.5, frameon=False)  # fmt: skip
    if path is not None:
        save_figure(fig, path, dpi=120, bbox_inches="tight")
        plt.close(fig)
    return fig


def _draw_segment(ax, s: Segment, lane: int, colour: dict, label_actions: bool) -> None:
    left, length = s.start - 0.5, s.end - s.start + 1
    y, top, bottom = lane + BAR_Y, lane + BAR_Y - BAR_H / 2, lane + BAR_Y + BAR_H / 2
    if s.kind in ("move", "wait"):
        style = {"color": MOVE_COLOUR, "edgecolor": "white"} if s.kind == "move" else {
            "color": "white", "edgecolor": "0.5", "hatch": "///"}  # fmt: skip
        ax.barh(y, length, left=left, height=BAR_H * 0.5, lw=0.5, **style)
        if length >= 3:
            ax.text(left + length / 2, y, s.label, ha="center", va="center", fontsize=7,
                    bbox={"fc": "white", "ec": "none", "pad": 0.3, "alpha": 0.8})  # fmt: skip
        return
    fc = colour.get(s.task, NO_TASK_COLOUR)
    ax.barh(y, length, left=left, height=BAR_H, color=fc, edgecolor="black", lw=0.6, zorder=3)
    if s.failed:
        ax.plot([left, left + length], [top, bottom], color="red", lw=2, zorder=5)
        ax.plot([left, left + length], [bottom, top], color="red", lw=2, zorder=5)
    if label_actions:
        ax.text(s.start, top - 0.02, "\n".join(_lines(s.label)), rotation=90, ha="center", va="bottom",
                fontsize=LABEL_PT, linespacing=0.9, zorder=7)  # fmt: skip


def _lines(label: str) -> list[str]:
    """An action label on one line, or one object per line when it is long."""
    if len(label) <= 18:
        return [label]
    head, _, rest = label.partition("(")
    objects = rest.split(", ")
    return [f"{head}({objects[0]}" + ("," if len(objects) > 1 else "")] + [
        o + ("," if k < len(objects) - 2 else "") for k, o in enumerate(objects[1:])
    ]


def _legend_handles(tasks: list[str], colour: dict, with_orders: bool, words: Mapping[str, str]) -> list:
    handles: list = [Patch(fc=colour[t], ec="black", label=_task_words(t, words)) for t in tasks]
    handles += [
        Patch(fc=MOVE_COLOUR, label="moving"),
        Patch(fc="white", ec="0.5", hatch="///", label="waiting"),
    ]
    if with_orders:
        from matplotlib.lines import Line2D

        handles += [
            Line2D([], [], color="tab:green", lw=1.6, label="a before b (kept)"),
            Line2D([], [], color="tab:red", lw=1.6, label="a before b (broken)"),
        ]
    return handles


def _task_words(task: str, words: Mapping[str, str]) -> str:
    """`1.1.2 put mugs in the lower rack (object 1 of 2)`, wrapped; the bare name without words."""
    said = words.get(task)
    if not said:
        return task
    return "\n".join(textwrap.wrap(f"{task.removeprefix('task')} {said}", 38))


def _default_title(plan: Plan | Execution, plan_obj: Plan) -> str:
    n = len(plan_obj.robots)
    team = f"{n} robot" + ("" if n == 1 else "s")
    if isinstance(plan, Execution):
        extra = "" if plan.ok else f", {len(plan.violation_list)} failed steps"
        return (f"{plan.world.name}: {team}, completion time {plan.steps} steps, "
                f"travel {plan.travel_m:.2f} m{extra}")  # fmt: skip
    return f"plan of {team}, {plan_obj.horizon} steps"
