"""Random demo instructions: every one gives a plan the checker passes (its own module, so that the
test workers can run it beside the benchmark instances)."""

from __future__ import annotations

import random

from nl2hltl2plan.planning import oracle_spec, plan
from nl2hltl2plan.worlds.checker import check
from nl2hltl2plan.worlds.demo import demo_world
from nl2hltl2plan.worlds.tasks import BaseTask, GTInstance

KINDS = [
    dict(kind="clean_place", object=["Mug"], receptacle=["DishwasherUpperRack"]),
    dict(kind="heat_place", object=["Apple"], receptacle=["DiningTable"]),
    dict(kind="cool_place", object=["Tomato"], receptacle=["CounterTop"]),
    dict(kind="examine_in_light", object=["Book"], light=["FloorLamp"]),
    dict(kind="place_in_container", object=["Fork"], container=["Bowl"], receptacle=["Cabinet"]),
    dict(kind="place_two", object=["Plate"], count=2, receptacle=["DishwasherLowerRack"]),
    dict(kind="place", object=["Bread"], sliced=True, receptacle=["DiningTable"]),
    dict(kind="place", object=["Cup"], receptacle=["Saucer"]),
    dict(kind="place", object=["KeyChain"], receptacle=["Bowl"]),
]


def test_random_demo_instructions_always_give_checked_plans():
    rng = random.Random(7)
    world = demo_world()
    starts = [(0, 0), (9, 13), (0, 13), (9, 0)]
    for trial in range(12):
        picked = rng.sample(KINDS, 3)
        tasks = [BaseTask(id=chr(65 + i), **t) for i, t in enumerate(picked)]
        before = [(a.id, b.id) for a, b in zip(tasks, tasks[1:], strict=False) if rng.random() < 0.5]
        gt = GTInstance(id=f"random{trial}", scene="demo", tasks=tasks, before=before)
        spec = oracle_spec(gt, world).spec
        robots = rng.choice([1, 2, 4])
        objective = rng.choice(["min", "minmax"])  # a small search budget: this checks plans, not quality
        r = plan(world, spec, starts[:robots], objective=objective, timeout_s=60, fast_expansions=300)
        assert r.solved, (trial, r.reason)
        verdict = check(r.execution, gt)
        assert verdict.success, (trial, [t.kind for t in tasks], before, verdict.reasons)
