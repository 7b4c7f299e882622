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
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

from nl2hltl2plan.errors import WorldError  # noqa: E402
from nl2hltl2plan.io import atomic_path, save_figure  # noqa: E402
from nl2hltl2plan.worlds.simulator import Execution  # noqa: E402
from nl2hltl2plan.worlds.world import CELL_M, World  # noqa: E402

ROBOT_COLOURS = [plt.get_cmap("tab10")(k) for k in range(10)]
REGION_COLOURS = [plt.get_cmap("Set2")(k) for k in range(8)]


def _base(world: World, ax=None, size: float = 7.0):
    if ax is None:
        xs = [world.xz(c)[0] for c in world.cells] + [o.position[0] for o in world.objects.values()]
        zs = [world.xz(c)[1] for c in world.cells] + [o.position[2] for o in world.objects.values()]
        w, h = max(xs) - min(xs) + 1, max(zs) - min(zs) + 1
        fig, ax = plt.subplots(figsize=(size * min(1.6, max(0.6, w / h)) + 2.5, size))
    squares = [Rectangle((x - CELL_M / 2, z - CELL_M / 2), CELL_M, CELL_M)
               for x, z in (world.xz(cell) for cell in world.cells)]  # fmt: skip
    ax.add_collection(PatchCollection(squares, fc="#eeeeee", ec="#cccccc", lw=0.4))  # one artist: fast
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("z (m)")
    return ax.figure, ax


def _objects(world: World, ax, labels: bool | Iterable[str] = True) -> None:
    """Objects as markers (a legend explains them); `labels`: all fixed objects, none, or these ids."""
    unreachable = set(world.unreachable)
    present = [o for o in world.objects.values() if o.present]
    movable = [o.xz for o in present if o.pickupable]
    fixed = [o for o in present if not o.pickupable]
    if movable:
        ax.plot(*zip(*movable, strict=True), "o", ms=3, color="#555555", zorder=3, ls="none",
                label="movable object")  # fmt: skip
    for approx, name in ((False, "fixed object"), (True, "fixed object, estimated position")):
        pts = [o.xz for o in fixed if o.approximate == approx]
        if pts:
            ax.plot(*zip(*pts, strict=True), "s", ms=6, ls="none", mec="#8c564b", zorder=3,
                    mfc="white" if approx else "#8c564b", label=name)  # fmt: skip
    bad = [world.objects[i].xz for i in unreachable if world.objects[i].present]
    if bad:
        ax.plot(*zip(*bad, strict=True), "x", ms=10, color="red", ls="none", zorder=4, label="unreachable")
    if labels is True:
        chosen = [o.id for o in fixed]
    else:
        chosen = [] if labels is False else [i for i in labels if i in world.objects]
    place_labels(ax, [(world.objects[i].xz, i) for i in chosen], avoid=[o.xz for o in present])


def place_labels(
    ax,
    items: list[tuple[tuple[float, float], str]],
    avoid: Iterable[tuple[float, float]] = (),
    fontsize: float = 6.5,
) -> list:
    """Label points so that no two labels overlap and none covers a marker (adjustText moves them
    apart; a label moved away from its point gets a leader line); returns the label texts."""
    if not items:
        return []
    from adjustText import adjust_text

    ax.autoscale_view()
    texts = [ax.text(x, y, text, fontsize=fontsize, zorder=6, ha="center", va="center",
                     bbox={"fc": "white", "ec": "none", "alpha": 0.9, "pad": 0.3})
             for (x, y), text in items]  # fmt: skip
    marks = list(avoid)
    adjust_text(texts, x=[p[0] for p in marks], y=[p[1] for p in marks], ax=ax, expand=(1.15, 1.35),
                force_text=(0.4, 0.6), ensure_inside_axes=True,
                iter_lim=60)  # as good as the default's few hundred here, at half the time  # fmt: skip
    _separate(ax, texts)
    _leader_lines(ax, texts, [xy for xy, _ in items])
    return texts


def _leader_lines(ax, texts: list, points: list[tuple[float, float]]) -> None:
    """A thin line from each point to its label where the label moved away (drawn under the label's
    white box, so it ends at the box; plain lines, not arrows clipped to the box: fast)."""
    to_px = ax.transData.transform
    for t, (x, y) in zip(texts, points, strict=True):
        tx, ty = t.get_position()
        (px, py), (qx, qy) = to_px((x, y)), to_px((tx, ty))
        if abs(px - qx) + abs(py - qy) > 10:
            ax.plot([x, tx], [y, ty], color="0.45", lw=0.5, zorder=5)


def _separate(ax, texts: list) -> None:
    """adjustText minimises overlaps but does not promise none: move any label that still touches
    an earlier one to the nearest free spot around where it is (the leader line stays)."""
    renderer = ax.figure.canvas.get_renderer()
    to_data = ax.transData.inverted()
    placed: list = []
    steps = [(dx * r, dy * r) for r in (6, 12, 18, 24, 32) for dx, dy in
             ((0, 1), (0, -1), (1, 0), (-1, 0), (1, 1), (-1, 1), (1, -1), (-1, -1))]  # fmt: skip
    for t in texts:
        box = t.get_window_extent(renderer)
        if any(box.overlaps(b) for b in placed):
            x, y = ax.transData.transform(t.get_position())
            for dx, dy in steps:
                moved = box.translated(dx, dy)
                if not any(moved.overlaps(b) for b in placed):
                    t.set_position(to_data.transform((x + dx, y + dy)))
                    box = moved
                    break
        placed.append(box)


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
        save_figure(fig, path, dpi=130, bbox_inches="tight")
        plt.close(fig)
    return fig


def draw_execution(execution: Execution, path: str | Path | None = None, ax=None, upto: int | None = None):
    """Robot trajectories in their own colours, start (circle) to end (triangle); each action is a
    numbered marker on the map, explained in a numbered list beside it (no stacked labels)."""
    world = execution.world
    fig, ax = _base(world, ax)
    upto = execution.plan.horizon if upto is None else upto
    events = sorted((e for e in execution.events if e.t <= upto), key=lambda e: (e.t, e.robot))
    _objects(world, ax, labels=sorted({o for e in events for o in e.objects}))
    colours = {}
    for k, (robot, traj) in enumerate(sorted(execution.trajectories.items())):
        colour = colours[robot] = ROBOT_COLOURS[k % len(ROBOT_COLOURS)]
        pts = [world.xz(c) for c in traj[: upto + 1]]
        jitter = (k - len(execution.trajectories) / 2) * 0.02  # keep overlapping paths apart
        xs = [p[0] + jitter for p in pts]
        zs = [p[1] + jitter for p in pts]
        ax.plot(xs, zs, "-", color=colour, lw=2, alpha=0.85, label=f"robot {robot}", zorder=4)
        ax.plot(xs[0], zs[0], "o", color=colour, ms=8, zorder=5)
        ax.plot(xs[-1], zs[-1], "^", color=colour, ms=9, zorder=5)
    ax.plot([], [], "o", color="0.3", ms=7, ls="none", label="start")
    ax.plot([], [], "^", color="0.3", ms=8, ls="none", label="position now" if upto < execution.plan.horizon
            else "end")  # fmt: skip
    lines = _numbered_events(ax, execution, events, colours)
    ax.set_title(
        f"{world.name}: t={upto}, travel {execution.travel_m:.2f} m, completion time {execution.steps} steps"
        + ("" if execution.ok else f", {len(execution.violations)} failed steps")
    )
    legend = ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=8)
    ax.autoscale_view()
    _action_list(ax, legend, lines)
    if path is not None:
        save_figure(fig, path, dpi=130, bbox_inches="tight")
        plt.close(fig)
    return fig


def _numbered_events(ax, execution: Execution, events: list, colours: dict) -> list[tuple[str, tuple]]:
    """Number the actions in time order on the map: each marker takes the first slot up and to the right
    of its cell that no other marker occupies; return the numbered list's lines with their colours."""
    world = execution.world
    ax.autoscale_view()
    ax.apply_aspect()
    to_pt = 72.0 / ax.figure.dpi
    taken: list[tuple[float, float]] = []
    lines = []
    for n, ev in enumerate(events, start=1):
        x, z = world.xz(execution.trajectories[ev.robot][ev.t])
        px, pz = (v * to_pt for v in ax.transData.transform((x, z)))
        for slot in range(60):
            offset = (9 + 13 * (slot % 6), 9 + 13 * (slot // 6))
            centre = (px + offset[0], pz + offset[1])
            if all(abs(centre[0] - a) >= 12.5 or abs(centre[1] - b) >= 12.5 for a, b in taken):
                break
        taken.append(centre)
        ax.annotate(str(n), (x, z), xytext=offset, textcoords="offset points", ha="center",
                    va="center", fontsize=7, color="white", fontweight="bold", zorder=8,
                    bbox={"boxstyle": "circle,pad=0.25", "fc": colours[ev.robot], "ec": "black", "lw": 0.5},
                    arrowprops={"arrowstyle": "-", "color": colours[ev.robot], "lw": 0.6})  # fmt: skip
        lines.append((f"{n:>2}. t={ev.t} robot {ev.robot}: {instance_words(ev)}", colours[ev.robot]))
    return lines


def instance_words(ev) -> str:
    """`put(Plate_1, DishwasherLowerRack_0)`: an action with the object ids that the text output, the
    map and the Gantt chart all use (one name for each object)."""
    verb = ev.atom.partition("(")[0]
    return f"{verb}({', '.join(ev.objects)})" if ev.objects else ev.atom


def _action_list(ax, legend, lines: list[tuple[str, tuple]]) -> None:
    """The numbered actions under the legend, in up to three columns."""
    if not lines:
        return
    ax.apply_aspect()
    box = legend.get_window_extent(ax.figure.canvas.get_renderer()).transformed(ax.transAxes.inverted())
    top = box.y0 - 0.05
    ncol = min(3, -(-len(lines) // 30))
    per_col = -(-len(lines) // ncol)
    width = max(len(text) for text, _ in lines) * 0.0085
    for k, (text, colour) in enumerate(lines):
        col, row = divmod(k, per_col)
        ax.text(1.02 + width * col, top - 0.032 * row, text, transform=ax.transAxes, fontsize=7, color=colour,
                va="top", family="monospace")  # fmt: skip
    ax.text(1.02, top + 0.01, "actions (numbered on the map)", transform=ax.transAxes, fontsize=8,
            va="bottom", fontweight="bold")  # fmt: skip


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
    w, h = fig.get_size_inches()
    fig.set_size_inches(w + 3.0, h)  # frames are not cropped: keep room for the legend and action list
    fig.subplots_adjust(left=0.06, right=(w - 1.5) / (w + 3.0), bottom=0.08, top=0.93)

    def update(t: int):
        ax.clear()
        draw_execution(execution, ax=ax, upto=t)
        return []

    anim = FuncAnimation(fig, update, frames=frames, blit=False)
    path = Path(path)
    with atomic_path(path, "animation") as tmp:
        anim.save(tmp, writer=PillowWriter(fps=fps))
    plt.close(fig)
    return path
