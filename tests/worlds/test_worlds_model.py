import numpy as np
import pytest

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.worlds import CELL_M, VISIBILITY_M, World, WorldObject, load_world
from nl2hltl2plan.worlds.world import Affordances


def test_cell_xz_roundtrip(demo):
    for cell in demo.cells[::7]:
        assert demo.cell_of(*demo.xz(cell)) == cell
    # a point off the grid snaps to the nearest free cell
    assert demo.cell_of(-5.0, -5.0) == (0, 0)


def test_grid_and_blocked_cells(demo):
    assert demo.shape == (10, 14)
    assert len(demo.cells) == 10 * 14 - 8
    assert not demo.free[4, 6] and demo.free[0, 0]
    assert (4, 6) not in demo.neighbours((3, 6))


def test_distances_and_path(demo):
    d = demo.distances_from((0, 0))
    assert d[(0, 0)] == 0 and d[(9, 13)] == 22
    assert demo.distances_from((0, 0)) is d  # cached
    path = demo.path((3, 5), (6, 5))
    assert path[0] == (3, 5) and path[-1] == (6, 5)
    assert len(path) - 1 == demo.distance((3, 5), (6, 5)) == 5  # around the table
    for a, b in zip(path, path[1:], strict=False):
        assert abs(a[0] - b[0]) + abs(a[1] - b[1]) == 1
    dm = demo.distance_matrix
    assert dm[demo.cell_index[(0, 0)], demo.cell_index[(9, 13)]] == 22
    with pytest.raises(WorldError):
        demo.distances_from((4, 6))


def test_interaction_region_rule(demo):
    fridge = demo.objects["Fridge_0"]
    cells = fridge.interaction_cells
    dists = [np.hypot(*(np.subtract(demo.xz(c), fridge.xz))) for c in cells]
    assert all(d <= VISIBILITY_M + 1e-9 for d in dists)
    assert dists == sorted(dists)  # nearest first
    outside = [c for c in demo.cells if c not in cells]
    assert all(np.hypot(*(np.subtract(demo.xz(c), fridge.xz))) > VISIBILITY_M for c in outside)


def test_agent_pose_cell_first_and_unreachable():
    aff = Affordances(openable=True, receptacle=True)
    objs = [
        WorldObject("Cabinet_0", "Cabinet", (0.0, 0.4, 0.0), aff, agent_pose=(1.0, 0.0)),
        WorldObject("Far_0", "Far", (9.0, 0.0, 9.0), Affordances()),
    ]
    w = World.create("tiny", [(x * CELL_M, 0.0) for x in range(6)], objs)
    assert w.objects["Cabinet_0"].interaction_cells[0] == w.cell_of(1.0, 0.0)
    assert w.unreachable == ["Far_0"]


@pytest.mark.data
def test_regions_of_many_points_equal_region_of_each(demo):
    """World.create computes every object's region in one pass (`_regions`); it must give what
    `region_of` gives point by point, order and agent-pose cell first included."""
    rng = np.random.default_rng(3)
    for world in (demo, load_world("FloorPlan1"), load_world("FloorPlan301")):
        objs = list(world.objects.values())
        points = [o.xz for o in objs] + [tuple(p) for p in rng.uniform(-2.0, 8.0, size=(40, 2))]
        poses = [o.agent_pose for o in objs] + [None] * 20 + [tuple(p) for p in rng.uniform(0, 5, (20, 2))]
        one_by_one = [world.region_of(p, q) for p, q in zip(points, poses, strict=True)]
        assert world._regions(points, poses) == one_by_one
        assert any(world._regions(points, poses)) and world._regions([], []) == []


def test_objects_types_instances_slices(demo):
    assert {"Plate", "DishwasherLowerRack", "AppleSliced"} <= demo.object_types()
    assert [o.id for o in demo.instances("Plate")] == ["Plate_0", "Plate_1"]
    apple = demo.objects["Apple_0"]
    assert apple.slices and all(not demo.objects[s].present for s in apple.slices)
    assert demo.objects[apple.slices[0]].slice_of == "Apple_0"
    assert demo.closed_ancestor("Apple_1") == "Fridge_0"
    assert demo.closed_ancestor("DishwasherLowerRack_0") == "Dishwasher_0"


def test_summary_and_load(demo):
    s = load_world("demo").summary()
    assert s["free_cells"] == len(demo.cells) and s["objects_by_type"]["Plate"] == 2
    with pytest.raises(WorldError):
        load_world("demo", trials=["x"])
