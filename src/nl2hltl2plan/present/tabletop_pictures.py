"""Pictures of the tabletop world: items, plates and each plan's end-effector path."""

from __future__ import annotations

from nl2hltl2plan.io import save_figure
from nl2hltl2plan.worlds.tabletop_world import COLS, HOME, PLATES, ROWS
from nl2hltl2plan.worlds.world import World

_COLOURS = {"GreenApple": "#5cb85c", "RedApple": "#d9534f", "Orange": "#f0ad4e", "Carrot": "#e8710a",
            "BluePlate": "#337ab7", "YellowPlate": "#f7e463", "PinkPlate": "#f4a6c8", "GreenPlate": "#2e8b57"}


def draw_trajectories(world: World, plans: dict, path, title: str | None = None) -> None:
    """Items (circles), plates (squares) and each plan's end-effector path (one panel per plan)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = max(1, len(plans))
    fig, axes = plt.subplots(1, n, figsize=(5.2 * n, 4.6), squeeze=False)
    for ax, (label, plan) in zip(axes[0], plans.items() or [("", None)], strict=False):
        ax.set_xlim(-0.5, COLS - 0.5)
        ax.set_ylim(-0.5, ROWS - 0.5)
        ax.set_aspect("equal")
        ax.set_xticks(range(0, COLS, 5))
        ax.set_yticks(range(0, ROWS, 5))
        ax.grid(True, color="#eeeeee")
        for oid, obj in world.objects.items():
            r, c = obj.interaction_cells[0]
            plate = obj.type in PLATES
            ax.scatter([c], [r], s=260 if plate else 120, marker="s" if plate else "o",
                       color=_COLOURS[obj.type], edgecolors="black", zorder=3)
            ax.annotate(oid.rsplit("_", 1)[0], (c, r), textcoords="offset points", xytext=(0, 9),
                        ha="center", fontsize=6)
        ax.scatter([HOME[1]], [HOME[0]], marker="^", s=120, color="black", zorder=4)
        if plan is not None:
            rp = plan.robots[0]
            cells = [tuple(rp.start)] + [tuple(s.cell) for s in rp.steps if s.verb == "move"]
            xs = [c for _, c in cells]
            ys = [r for r, _ in cells]
            ax.plot(xs, ys, color="#444444", lw=1.4, zorder=2)
            for k in range(0, len(cells) - 1, 6):
                ax.annotate("", (xs[k + 1], ys[k + 1]), (xs[k], ys[k]),
                            arrowprops={"arrowstyle": "->", "color": "#444444"})
        ax.set_title(label, fontsize=9)
    if title:
        fig.suptitle(title, fontsize=8)
    fig.tight_layout()
    save_figure(fig, path, dpi=110)
    plt.close(fig)
