"""Pictures: Gantt chart, map, HTT tree and benchmark plots write valid images and handle edge cases."""

from __future__ import annotations

import pytest
from PIL import Image

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.language.htt import HTT
from nl2hltl2plan.present.gantt import _ordering_arrows, draw_gantt, segments
from nl2hltl2plan.present.htt_pictures import draw_htt, htt_labels, htt_orderings, tree_layout
from nl2hltl2plan.present.pictures import draw_execution
from nl2hltl2plan.suites.alfred.alfred_report import (
    _points,
    _team,
    pipeline_summary,
    plot_cost_time,
    plot_success,
)
from nl2hltl2plan.suites.summaries import summarize
from nl2hltl2plan.worlds import execute
from nl2hltl2plan.worlds.demo import demo_world
from nl2hltl2plan.worlds.plan import Plan, RobotPlan, Step
from nl2hltl2plan.worlds.scripted import scripted_plan


def _image(path) -> tuple[int, int]:
    with Image.open(path) as im:
        im.verify()
    with Image.open(path) as im:
        return im.size


@pytest.fixture(scope="module")
def world():
    return demo_world()


@pytest.fixture(scope="module")
def two_robot_execution(world):
    plan = scripted_plan(
        world,
        {
            0: ((0, 0), ["pickup Mug_0 :task1.1", "put Mug_0 CounterTop_0 :task1.1"]),
            1: ((9, 13), ["wait 2", "goto 5 12", "pickup Apple_0 :task1.2"]),
        },
    )
    return execute(world, plan)


def test_gantt_segments_merge_moves_and_waits():
    rp = RobotPlan(
        robot=1,
        start=(0, 0),
        steps=[
            Step(t=1, verb="move", cell=(0, 1)),
            Step(t=2, verb="move", cell=(0, 2)),
            Step(t=5, verb="pickup", objects=["Apple_3"], task="task1.1"),
            Step(t=6, verb="wait"),
            Step(t=7, verb="put", objects=["Apple_3", "Fridge_0"], task="task1.1"),
        ],
    )
    segs = segments(rp)
    assert [(s.kind, s.start, s.end, s.label) for s in segs] == [
        ("move", 1, 2, "move x2"),
        ("wait", 3, 4, "wait x2"),
        ("action", 5, 5, "pickup(Apple_3)"),  # the ids the text output and the map use
        ("wait", 6, 6, "wait x1"),
        ("action", 7, 7, "put(Apple_3, Fridge_0)"),
    ]


def test_gantt_marks_kept_and_broken_orders(two_robot_execution, tmp_path):
    segs = [s for rp in two_robot_execution.plan.robots for s in segments(rp)]
    kept = {(a.task, b.task): ok for a, b, ok in _ordering_arrows(segs, [("task1.1", "task1.2")])}
    broken = {(a.task, b.task): ok for a, b, ok in _ordering_arrows(segs, [("task1.2", "task1.1")])}
    t11 = [s.end for s in segs if s.task == "task1.1"]
    t12 = [s.start for s in segs if s.task == "task1.2"]
    assert kept[("task1.1", "task1.2")] == (max(t11) < min(t12))
    assert broken[("task1.2", "task1.1")] is False  # both cannot hold at once
    # a parent name covers its subtree; unknown names draw nothing
    assert len(_ordering_arrows(segs, [("task1", "task9")])) == 0
    out = draw_gantt(two_robot_execution, tmp_path / "g.png", before=[("task1.1", "task1.2")])
    assert out is not None and _image(tmp_path / "g.png")[0] > 500


def test_gantt_edge_cases(world, tmp_path):
    empty = Plan(robots=[])
    draw_gantt(empty, tmp_path / "empty.png")
    idle = Plan(robots=[RobotPlan(robot=0, start=(0, 0))])
    draw_gantt(idle, tmp_path / "idle.png", before=[("task1", "task2")])
    long_ids = Plan(
        robots=[
            RobotPlan(
                robot=0,
                start=(0, 0),
                steps=[
                    Step(t=k, verb="put", objects=["DishwasherLowerRack_0", "DishwasherUpperRack_0"])
                    for k in range(1, 80)
                ],
            )  # fmt: skip
        ]
    )
    draw_gantt(long_ids, tmp_path / "long.svg")
    assert _image(tmp_path / "empty.png")[0] > 100 and _image(tmp_path / "idle.png")[0] > 100
    assert (tmp_path / "long.svg").read_text().startswith("<?xml")
    with pytest.raises(WorldError, match="Plan or an Execution"):
        draw_gantt("not a plan", tmp_path / "x.png")  # type: ignore[arg-type]


def test_map_numbers_every_action(two_robot_execution, tmp_path):
    fig = draw_execution(two_robot_execution)
    texts = [t.get_text() for t in fig.axes[0].texts]
    n = len(two_robot_execution.events)
    assert n == 3
    assert [str(k) for k in range(1, n + 1)] == [t for t in texts if t.isdigit()]
    assert sum(1 for t in texts if ". t=" in t) == n  # the numbered list beside the map
    labels = fig.axes[0].get_legend_handles_labels()[1]
    assert {"movable object", "fixed object", "robot 0", "robot 1", "start", "end"} <= set(labels)
    draw_execution(two_robot_execution, tmp_path / "m.png")
    assert _image(tmp_path / "m.png")[0] > 500


def _overlaps(pos, size, a, b) -> bool:
    (xa, ya), (xb, yb) = pos[a], pos[b]
    return abs(xa - xb) < (size[a][0] + size[b][0]) / 2 and abs(ya - yb) < (size[a][1] + size[b][1]) / 2


def test_htt_layout_has_no_overlap_or_truncation(tmp_path):
    long_text = "Put every plate, mug and fork into the lower rack of the dishwasher, then " * 3
    htt = HTT.from_json(
        {
            "instruction": long_text,
            "nodes": [
                {"id": "1", "text": long_text, "children": ["1.1", "1.2", "1.3"]},
                {"id": "1.1", "text": "wash the mug", "children": [], "actions": ["pickup(Mug)"] * 12},
                {
                    "id": "1.2",
                    "text": "x" * 60,
                    "children": [],
                    "actions": ["put(Plate,DishwasherLowerRack)"],
                },
                {"id": "1.3", "text": "put the fork away", "children": [], "actions": ["pickup(Fork)"]},
            ],
            "relations": [["1.1", "1.2"], ["1.3", "1.1"]],
        }
    )
    labels = htt_labels(htt)
    assert " ".join(labels["1"].split("\n")[1:]) == long_text.strip()  # the whole root sentence
    assert "... 4 more" in labels["1.1"]
    pos, size = tree_layout({n.id: list(n.children) for n in htt.nodes}, labels)
    ids = list(pos)
    assert not any(_overlaps(pos, size, a, b) for i, a in enumerate(ids) for b in ids[i + 1 :])
    assert all(pos[c][1] > pos["1"][1] for c in ("1.1", "1.2", "1.3"))
    assert htt_orderings(htt) == [("task1.1", "task1.2"), ("task1.3", "task1.1")]
    draw_htt(htt, tmp_path / "htt.png", title=long_text)
    assert _image(tmp_path / "htt.png")[0] > 300


def _row(n_base, robots, draw, travel, steps, success=True):
    from nl2hltl2plan.suites.rows import ScenarioRow

    fields = {"instance": f"i{n_base}-{draw}", "n_base": n_base, "robots": robots, "draw": draw,
              "key": f"i{n_base}|r{robots}|d{draw}", "success": success, "status": "solved",
              "feasible": True, "conversion_ok": True, "planning_ok": True, "travel_m": travel,
              "steps": steps, "plan_time_s": 0.1}  # fmt: skip
    return ScenarioRow.model_validate(fields)


def test_bench_plots_integer_axes_plurals_and_bars_inside_data(tmp_path):
    rows = [_row(2, 1, 0, 0.25, 4), _row(2, 1, 1, 5.0, 30), _row(2, 1, 2, 0.5, 6)]
    summary = pipeline_summary(rows)
    assert _team(1) == "1 robot" and _team(3) == "3 robots"
    # mean 1.92 m, std 2.2 m: mean - std < 0, but the percentile bars stay inside [min, max]
    for metric, lo, hi in (("travel_m", 0.25, 5.0), ("steps", 4, 30)):
        ((n, mid, below, above),) = _points(summary, rows, 1, metric)
        assert n == 2 and mid - below >= lo and mid + above <= hi and below >= 0 and above >= 0
    ((_, mean, below, _),) = _points(summarize(rows), None, 1, "travel_m")
    assert mean - below >= 0  # without rows: mean ± std cut at zero
    plot_success({"all": summary}, tmp_path / "s.png")
    plot_cost_time(summary, tmp_path / "c.png", rows=rows)
    plot_cost_time(pipeline_summary([_row(3, 2, 0, 1.0, 9, success=False)]), tmp_path / "none.png")
    assert all(_image(tmp_path / n)[0] > 300 for n in ("s.png", "c.png", "none.png"))


def test_gantt_from_benchmark_events_and_report_example(tmp_path):
    from nl2hltl2plan.domain.plan_events import PlanEvent
    from nl2hltl2plan.present.gantt import draw_gantt_events, segments_from_events
    from nl2hltl2plan.suites.alfred.alfred_report import plot_gantt_example

    events = [
        PlanEvent(t=4, robot=0, atom="pickup(Apple)", task="task1.1", travel_m=0.5),
        PlanEvent(t=5, robot=0, atom="put(Apple,Fridge)", task="task1.1", travel_m=0.0),
        PlanEvent(t=3, robot=1, atom="open(Fridge)", task="task1.2", travel_m=0.75),
    ]
    segs = segments_from_events(events, robots=3)
    assert [(s.robot, s.kind, s.start, s.end) for s in segs] == [
        (0, "move", 1, 2),  # walks right after its previous action (here: the start) ...
        (0, "wait", 3, 3),  # ... then waits for the action's step
        (0, "action", 4, 4),
        (0, "action", 5, 5),
        (1, "move", 1, 2),  # 0.75 m is 3 cells, but only 2 steps fit before t=3
        (1, "action", 3, 3),
    ]
    draw_gantt_events(events, 3, tmp_path / "ev.png", before=[("task1.2", "task1.1")])
    rows = [
        _row(2, 3, 0, 1.25, 5).model_copy(update={"events": events}),
        _row(2, 3, 1, 1.0, 5).model_copy(update={"events": events[:1]}),
        _row(2, 3, 2, 1.0, 5, success=False).model_copy(
            update={"events": events * 2}
        ),
    ]
    assert plot_gantt_example(rows, tmp_path / "example.png") is rows[0]  # most robots at work
    assert (
        plot_gantt_example(rows[2:], tmp_path / "none.png") is None and not (tmp_path / "none.png").exists()
    )
    assert _image(tmp_path / "ev.png")[0] > 300 and _image(tmp_path / "example.png")[0] > 300


def test_map_markers_do_not_overlap(world):
    from nl2hltl2plan.pipeline import run

    instruction = (
        "Put the apple in the fridge and put the mug in the cabinet. Then put the bread on the dining table."
    )
    execution = run(instruction, world, robots=2).result.execution
    fig = draw_execution(execution)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    boxes = [
        t.get_bbox_patch().get_window_extent(renderer) for t in fig.axes[0].texts if t.get_text().isdigit()
    ]
    assert len(boxes) == len(execution.events) >= 8
    assert not any(a.overlaps(b) for i, a in enumerate(boxes) for b in boxes[i + 1 :])
