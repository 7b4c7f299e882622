"""Where the robots start: the one place that decides it for the CLI, the web app and the benchmarks.

>>> from nl2hltl2plan.worlds.demo import demo_world
>>> start_cells(demo_world(), 2)   # the demo kitchen's default starts
[(0, 0), (0, 13)]
"""

from __future__ import annotations

from collections.abc import Sequence

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.worlds.tasks import GTInstance
from nl2hltl2plan.worlds.world import Cell, World


def parse_cells(text: str) -> list[Cell]:
    """Cells written 'r,c;r,c' (the CLI's --starts)."""
    try:
        cells = [tuple(int(x) for x in part.split(",")) for part in text.split(";") if part.strip()]
    except ValueError:
        raise WorldError(f"start cells must look like 'r,c;r,c', got {text!r}") from None
    if not cells or any(len(c) != 2 for c in cells):
        raise WorldError(f"start cells must look like 'r,c;r,c', got {text!r}")
    return [(c[0], c[1]) for c in cells]


def start_cells(
    world: World,
    robots: int,
    *,
    given: Sequence[Cell] | None = None,
    gt: GTInstance | None = None,
    draw: int = 0,
) -> list[Cell]:
    """One free start cell per robot.

    `given`: exactly these cells (each must be free). `gt`: the benchmark instance's `init_pos` draw
    (x, z metres, drawn on AI2-THOR's reachable positions) snapped to the nearest free cell of the
    grid's largest connected component. Otherwise the world's default starts, then free cells spread
    evenly over the grid (deterministic). More robots than the world has free cells is an error (the
    team is planned for exactly as many robots as asked, never silently fewer).
    """
    if robots < 1:
        raise WorldError(f"a team needs at least 1 robot, got {robots}")
    if given is not None:
        cells = [tuple(c) for c in given]
        if len(cells) != robots:
            raise WorldError(f"{len(cells)} start cell(s) given for {robots} robot(s)")
        free = set(world.cells)
        bad = [c for c in cells if c not in free]
        if bad:
            raise WorldError(f"start cell {bad[0]} is not a free cell of {world.name}")
        return [(c[0], c[1]) for c in cells]
    if gt is not None:
        return _gt_starts(world, gt, robots, draw)
    if robots > len(world.cells):
        raise WorldError(
            f"{world.name} has {len(world.cells)} free cells: at most that many robots, not {robots}"
        )
    defaults = list(world.default_starts)
    if len(defaults) >= robots:
        return defaults[:robots]
    step = max(1, len(world.cells) // robots)
    spread = [c for c in sorted(world.cells)[::step] if c not in defaults]
    spread += [c for c in sorted(world.cells) if c not in defaults and c not in spread]
    return defaults + spread[: robots - len(defaults)]


def _gt_starts(world: World, gt: GTInstance, robots: int, draw: int) -> list[Cell]:
    if not gt.init_pos:
        raise WorldError(f"{gt.id} has no init_pos")
    if not 0 <= draw < len(gt.init_pos):
        raise WorldError(f"{gt.id}: init_pos draw {draw} out of range 0..{len(gt.init_pos) - 1}")
    positions = gt.init_pos[draw]
    if robots > len(positions):
        raise WorldError(f"{gt.id}: only {len(positions)} start positions for {robots} robots")
    return [world.cell_of(x, z, main=True) for x, z in positions[:robots]]
