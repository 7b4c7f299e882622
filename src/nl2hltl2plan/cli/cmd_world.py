"""`nl2hltl2plan world`: summarise and draw a world (demo, an ALFRED floor plan, a benchmark instance)."""

from __future__ import annotations

import argparse
import json

from nl2hltl2plan.cli.commands import COMMANDS
from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.io import PICTURE_FORMATS, check_output_file

DEMO_TASKS = [  # the paper's dishwasher example, one base task per item
    {"id": "A", "kind": "place", "object": ["Plate"], "receptacle": ["DishwasherLowerRack"]},
    {"id": "B", "kind": "place", "object": ["Mug"], "receptacle": ["DishwasherLowerRack"]},
    {"id": "C", "kind": "place", "object": ["Fork"], "receptacle": ["DishwasherLowerRack"]},
    {"id": "D", "kind": "place", "object": ["Saucer"], "receptacle": ["DishwasherUpperRack"]},
    {"id": "E", "kind": "place", "object": ["Cup"], "receptacle": ["DishwasherUpperRack"]},
]
DEMO_BEFORE = [["A", "D"], ["B", "D"], ["C", "D"], ["D", "E"]]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "world",
        help=COMMANDS["world"],
        description=(
            "Print a world's summary (grid size, free cells, objects by type, what could not be placed) "
            "and optionally draw it. NAME is 'demo' (built in, no data), an ALFRED floor plan such as "
            "FloorPlan17 (movable objects from its first trial, or --trials), or a benchmark instance id "
            "such as FloorPlan17.tasks_2.compose_0.fintune_1 (objects from its source trials)."
        ),
    )
    p.add_argument("name", help="demo | FloorPlanN | benchmark instance id")
    p.add_argument("--trials", nargs="+", metavar="TRIAL", help="ALFRED trial ids whose object poses to use")
    p.add_argument("--json", action="store_true", help="print JSON instead of text")
    p.add_argument(
        "-o",
        "--out",
        metavar="PICTURE",
        help="draw the world (or, with --run, the execution) to this .png/.svg/.pdf (default: none)",
    )
    p.add_argument(
        "--regions",
        nargs="+",
        metavar="ID_OR_TYPE",
        help="draw the interaction regions of these objects/types",
    )
    p.add_argument(
        "--objects", action="store_true", help="also list every object (id, type, cell count, parent)"
    )
    p.add_argument(
        "--run",
        action="store_true",
        help="execute a one-robot greedy plan of the tasks (benchmark: its ground truth; demo: the paper's "
        "dishwasher example) and check it",
    )
    p.add_argument(
        "--gif", metavar="GIF", help="with --run: also write an animated GIF of the execution (default: none)"
    )
    p.set_defaults(func=run)


def _load(args):
    from nl2hltl2plan.worlds import load_world
    from nl2hltl2plan.worlds.tasks import GTInstance

    if ".tasks_" in args.name:
        from nl2hltl2plan.suites.alfred.ground_truth import gt_instance
        from nl2hltl2plan.worlds.floor_plans import build_benchmark_world
        from nl2hltl2plan.worlds.starts import start_cells

        if args.trials:
            raise WorldError("a benchmark instance brings its own trials; drop --trials")
        gt = gt_instance(args.name)
        world = build_benchmark_world(gt)
        return world, gt, start_cells(world, 1, gt=gt)[0]
    world = load_world(args.name, args.trials)
    demo_gt: GTInstance | None = None
    if world.kind == "demo":
        demo_gt = GTInstance.model_validate(
            {"id": "demo.dishwasher", "scene": "demo", "tasks": DEMO_TASKS, "before": DEMO_BEFORE}
        )
    start = world.default_starts[0] if world.default_starts else None
    return world, demo_gt, start


def run(args: argparse.Namespace) -> int:
    from nl2hltl2plan.worlds import check, execute
    from nl2hltl2plan.worlds.floor_plans import benchmark_issues

    if args.gif and not args.run:
        raise WorldError("--gif needs --run")
    if args.out:
        check_output_file(args.out, PICTURE_FORMATS, "picture")
    if args.gif:
        check_output_file(args.gif, ("gif",), "animation")
    world, gt, start = _load(args)
    out = world.summary()
    if args.objects:
        out["object_list"] = [o.to_dict() for o in world.objects.values()]
    if gt is not None and world.kind != "demo":
        out["instance"] = {"id": gt.id, "instruction": gt.instruction, "issues": benchmark_issues(world, gt)}
    execution = None
    if args.run:
        if gt is None:
            raise WorldError("--run needs tasks: use 'demo' or a benchmark instance id")
        issues = benchmark_issues(world, gt)
        if issues:
            raise WorldError(f"{gt.id} cannot be done in this world: {'; '.join(issues)}")
        from nl2hltl2plan.worlds.scripted import sequential_plan

        plan = sequential_plan(world, gt.tasks, gt.before, start=start)
        execution = execute(world, plan)
        result = check(execution, gt)
        out["run"] = {**execution.to_dict(), "check": result.model_dump()}
    if args.out:
        from nl2hltl2plan.present.pictures import draw_execution, draw_world

        if execution is not None:
            draw_execution(execution, args.out)
        else:
            draw_world(world, args.out, regions=args.regions)
        out["picture"] = args.out
    if args.gif and execution is not None:
        from nl2hltl2plan.present.pictures import animate_execution

        animate_execution(execution, args.gif)
        out["gif"] = args.gif
    if args.json:
        print(json.dumps(out, indent=2))
    else:
        print(_text(out))
    return 0


def _text(s: dict) -> str:
    g = s["grid"]
    lines = [
        f"world {s['name']} ({s['kind']}): grid {g['rows']} x {g['cols']} cells of {g['cell_m']} m, "
        f"{s['free_cells']} free cells"
        + (f" in {len(s['components'])} components {s['components']}" if len(s["components"]) > 1 else ""),
        f"objects: {s['objects']} in {len(s['objects_by_type'])} types"
        + (f" (+ slice types {', '.join(s['slice_types'])})" if s["slice_types"] else ""),
    ]
    items = [f"{t} {n}" for t, n in s["objects_by_type"].items()]
    for k in range(0, len(items), 6):
        lines.append("  " + ", ".join(items[k : k + 6]))
    if s["approximate"]:
        lines.append(f"approximate positions: {', '.join(s['approximate'])}")
    if s["unreachable"]:
        lines.append(f"unreachable (no free cell within 1.5 m): {', '.join(s['unreachable'])}")
    if s["unplaced"]:
        lines.append(f"listed but not placed: {', '.join(s['unplaced'])}")
    if s["source_trials"]:
        lines.append(f"movable objects from: {', '.join(s['source_trials'])}")
    for note in s["notes"]:
        lines.append(f"note: {note}")
    for o in s.get("object_list", []):
        where = f" in {o['parent']}" if o["parent"] else ""
        state = "" if o["present"] else " (appears when sliced)"
        lines.append(f"  {o['id']:<28} {len(o['interaction_cells']):>3} cells{where}{state}")
    if "instance" in s:
        inst = s["instance"]
        lines.append(f"instance {inst['id']}: {inst['instruction']}")
        lines.append(f"  issues: {'; '.join(inst['issues']) if inst['issues'] else 'none (feasible here)'}")
    if "run" in s:
        r = s["run"]
        c = r["check"]
        lines.append(
            f"run: {len(r['events'])} actions, travel {r['travel_m']} m, completion time {r['steps']} steps, "
            f"{'no' if r['ok'] else len(r['violations'])} failed steps; goals "
            + ("reached in order" if c["success"] else "NOT reached: " + "; ".join(c["reasons"]))
            + f" {c['goal_steps']}"
        )
    if "picture" in s:
        lines.append(f"wrote {s['picture']}")
    if "gif" in s:
        lines.append(f"wrote {s['gif']}")
    return "\n".join(lines)
