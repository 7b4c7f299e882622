"""Every picture's labels can be read: no two label boxes overlap, none leaves the picture, the demo's
HTT fits 1,600 px, the Gantt legend speaks in words, and one object has one name everywhere."""

from __future__ import annotations

import pytest
from PIL import Image

from nl2hltl2plan.pipeline import run
from nl2hltl2plan.present.gantt import draw_gantt
from nl2hltl2plan.present.htt_pictures import draw_htt, fitted_layout, htt_labels, htt_task_words
from nl2hltl2plan.present.pictures import draw_execution, draw_world
from nl2hltl2plan.worlds import load_world
from nl2hltl2plan.worlds.demo import demo_world

DEMO = (
    "Put the plates, mugs and utensils in the lower rack in any order; after that, first the saucers, "
    "then the cups, in the upper rack."
)


def label_boxes(fig, texts=None) -> list:
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    texts = [t for t in (texts if texts is not None else fig.axes[0].texts) if t.get_text().strip()]
    return [(t.get_text(), t.get_window_extent(renderer)) for t in texts]


def overlapping(boxes) -> list[tuple[str, str]]:
    return [(a, b) for i, (a, ba) in enumerate(boxes) for b, bb in boxes[i + 1 :] if ba.overlaps(bb)]


@pytest.fixture(scope="module")
def demo_outcome():
    return run(DEMO, demo_world(), robots=2)


@pytest.mark.parametrize(
    "name", ["demo", "tabletop", "handover-line", pytest.param("FloorPlan1", marks=pytest.mark.data)]
)
def test_map_labels_do_not_overlap(name):
    world = load_world(name)
    fig = draw_world(world)
    boxes = label_boxes(fig)
    fixed = {o.id for o in world.objects.values() if o.present and not o.pickupable}
    assert {text for text, _ in boxes} == fixed  # every receptacle, appliance and region is named
    assert overlapping(boxes) == []
    inside = fig.bbox
    assert all(
        inside.x0 <= b.x0 and b.x1 <= inside.x1 and inside.y0 <= b.y0 and b.y1 <= inside.y1 for _, b in boxes
    )


def test_gantt_labels_inside_the_frame_and_a_legend_in_words(demo_outcome):
    htt = demo_outcome.language.htt
    fig = draw_gantt(demo_outcome.result.execution, words=htt_task_words(htt))
    ax = fig.axes[0]
    boxes = label_boxes(fig)
    frame = ax.get_window_extent()
    assert len(boxes) >= 20
    assert all(
        frame.x0 <= b.x0 and b.x1 <= frame.x1 and frame.y0 <= b.y0 and b.y1 <= frame.y1 for _, b in boxes
    )
    assert overlapping(boxes) == []
    title = ax.title.get_window_extent()
    assert not any(b.overlaps(title) for _, b in boxes)
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any(t.startswith("1.1.1.1 Put the plates in the lower") for t in legend)
    assert not any(t.startswith("task1.") for t in legend)


def test_one_name_for_each_object(demo_outcome):
    execution = demo_outcome.result.execution
    ids = {o for e in execution.events for o in e.objects}
    gantt = " ".join(t for t, _ in label_boxes(draw_gantt(execution)))
    plan = " ".join(t.get_text() for t in draw_execution(execution).axes[0].texts)
    steps = {o for r in demo_outcome.to_json()["plan"]["robots"] for s in r["steps"] for o in s["objects"]}
    assert steps == ids
    for oid in ids:  # Plate_1 is Plate_1 in the JSON, on the Gantt chart and in the map's action list
        assert oid in gantt and oid in plan


def test_demo_htt_fits_1600_px(demo_outcome, tmp_path):
    htt = demo_outcome.language.htt
    children = {n.id: list(n.children) for n in htt.nodes}
    pos, size, stacked = fitted_layout(children, htt_labels(htt))
    assert stacked  # too wide side by side: the last level turns into columns
    ids = list(pos)
    apart = [
        abs(pos[a][0] - pos[b][0]) >= (size[a][0] + size[b][0]) / 2
        or abs(pos[a][1] - pos[b][1]) >= (size[a][1] + size[b][1]) / 2
        for i, a in enumerate(ids)
        for b in ids[i + 1 :]
    ]
    assert all(apart)
    draw_htt(htt, tmp_path / "htt.png", title=DEMO)
    with Image.open(tmp_path / "htt.png") as im:
        assert im.size[0] <= 1600
