"""Pictures of worlds and executions (matplotlib; Agg backend, files only).

- `draw_world`: free cells, objects (static ones as squares with labels, movable ones as dots),
  interaction regions of chosen objects, unreachable objects crossed out.
- `draw_execution`: the robots' trajectories, each in its own colour, with the actions they did
  (the style of the paper's Fig. 1); `animate_execution` writes an animated GIF (pillow writer).
Coordinates are metres: x to the right, z up, one square per 0.25 m cell.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

from nl2hltl2plan.errors import WorldError  # noqa: E402
from nl2hltl2plan.worlds.model import CELL_M, World  # noqa: E402
from nl2hltl2plan.worlds.simulator import Execution  # noqa: E402

ROBOT_COLOURS = [plt.get_cmap("tab10")(k) for k in range(10)]
REGION_COLOURS = [plt.get_cmap("Set2")(k) for k in range(8)]


def _base(world: World, ax=None, size: float = 7.0):
    if ax is None:
        xs = [world.xz(c)[0] for c in world.cells] + [o.position[0] for o in world.objects.values()]
        zs = [world.xz(c)[1] for c in world.cells] + [o.position[2] for o in world.objects.values()]
        w, h = max(xs) - min(xs) + 1, max(zs) - min(zs) + 1
        fig, ax = plt.subplots(figsize=(size * min(1.6, max(0.6, w / h)) + 2.5, size))
    for cell in world.cells:
        x, z = world.xz(cell)
        ax.add_patch(
            Rectangle((x - CELL_M / 2, z - CELL_M / 2), CELL_M, CELL_M, fc="#eeeeee", ec="#cccccc", lw=0.4)
        )
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("z (m)")
    return ax.figure, ax


def _objects(world: World, ax, labels: bool = True) -> None:
    unreachable = set(world.unreachable)
    for obj in world.objects.values():
        if not obj.present:
            continue
        x, z = obj.xz
        if obj.pickupable:
            ax.plot(x, z, "o", ms=3, color="#555555", zorder=3)
            continue
        ax.plot(x, z, "s", ms=6, mfc="white" if obj.approximate else "#8c564b", mec="#8c564b", zorder=3)
        if obj.id in unreachable:
            ax.plot(x, z, "x", ms=10, color="red", zorder=4)
        if labels:
            ax.annotate(obj.id, (x, z), fontsize=6, xytext=(3, 3), textcoords="offset points", zorder=5)


def _resolve(world: World, regions: Iterable[str] | str | None) -> list[str]:
    if regions is None:
        return []
    if isinstance(regions, str):
        regions = [regions]
    ids = []
    for r in regions:
        if r in world.objects:
            ids.append(r)
        elif world.instances(r):
            ids.extend(o.id for o in world.instances(r) if o.present)
        else:
            raise WorldError(f"no object or type {r!r} in {world.name} to draw the region of")
    return ids


def draw_world(world: World, path: str | Path | None = None, regions=None, ax=None, title: str | None = None):
    """Draw the grid, objects and the interaction regions of `regions` (ids or types); save to `path`."""
    fig, ax = _base(world, ax)
    for k, oid in enumerate(_resolve(world, regions)):
        colour = REGION_COLOURS[k % len(REGION_COLOURS)]
        for cell in world.objects[oid].interaction_cells:
            x, z = world.xz(cell)
            ax.add_patch(
                Rectangle(
                    (x - CELL_M / 2, z - CELL_M / 2), CELL_M, CELL_M, fc=colour, alpha=0.35, lw=0, zorder=1
                )
            )
        ax.plot([], [], "s", color=colour, alpha=0.6, label=f"region of {oid}")
    _objects(world, ax)
    summary = world.summary()
    ax.set_title(
        title
        or f"{world.name}: {summary['grid']['rows']}x{summary['grid']['cols']} grid, "
        f"{summary['free_cells']} free cells, {summary['objects']} objects"
    )
    if ax.get_legend_handles_labels()[0]:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=7)
    ax.autoscale_view()
    if path is not None:
        fig.savefig(path, dpi=130, bbox_inches="tight")
        plt.close(fig)
    return fig


def draw_execution(execution: Execution, path: str | Path | None = None, ax=None, upto: int | None = None):
    """Robot trajectories in their own colours, start (circle) to end (triangle), actions labelled."""
    world = execution.world
    fig, ax = _base(world, ax)
    _objects(world, ax, labels=False)
    upto = execution.plan.horizon if upto is None else upto
    for k, (robot, traj) in enumerate(sorted(execution.trajectories.items())):
        colour = ROBOT_COLOURS[k % len(ROBOT_COLOURS)]
        pts = [world.xz(c) for c in traj[: upto + 1]]
        jitter = (k - len(execution.trajectories) / 2) * 0.02  # keep overlapping paths apart
        xs = [p[0] + jitter for p in pts]
        zs = [p[1] + jitter for p in pts]
        ax.plot(xs, zs, "-", color=colour, lw=2, alpha=0.85, label=f"robot {robot}", zorder=4)
        ax.plot(xs[0], zs[0], "o", color=colour, ms=8, zorder=5)
        ax.plot(xs[-1], zs[-1], "^", color=colour, ms=9, zorder=5)
        for ev in execution.events:
            if ev.robot == robot and ev.t <= upto:
                x, z = world.xz(traj[ev.t])
                ax.annotate(
                    f"t={ev.t} {ev.atom}", (x + jitter, z + jitter), fontsize=6, color=colour,
                    xytext=(4, -8 - 7 * (ev.t % 3)), textcoords="offset points", zorder=6,
                )  # fmt: skip
    ax.set_title(
        f"{world.name}: t={upto}, travel {execution.travel_m:.2f} m, completion time {execution.steps} steps"
        + ("" if execution.ok else f", {len(execution.violations)} failed steps")
    )
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=8)
    ax.autoscale_view()
    if path is not None:
        fig.savefig(path, dpi=130, bbox_inches="tight")
        plt.close(fig)
    return fig


def animate_execution(execution: Execution, path: str | Path, fps: int = 4, max_frames: int = 400) -> Path:
    """An animated GIF of the execution, one frame per time step (at most `max_frames`)."""
    from matplotlib.animation import FuncAnimation, PillowWriter

    horizon = execution.plan.horizon
    stride = max(1, -(-(horizon + 1) // max_frames))
    frames = list(range(0, horizon + 1, stride))
    if frames[-1] != horizon:
        frames.append(horizon)
    fig = draw_execution(execution, upto=0)
    ax = fig.axes[0]

    def update(t: int):
        ax.clear()
        draw_execution(execution, ax=ax, upto=t)
        return []

    anim = FuncAnimation(fig, update, frames=frames, blit=False)
    path = Path(path)
    anim.save(path, writer=PillowWriter(fps=fps))
    plt.close(fig)
    return path
