"""Pictures of the four-arm handover worlds: the layout, the blocks and an execution's paths and handovers."""

from __future__ import annotations

from nl2hltl2plan.io import save_figure
from nl2hltl2plan.worlds.handover_world import ARMS, HandoverExecution, HandoverWorld

ARM_COLOURS = ("#1f77b4", "#2ca02c", "#d62728", "#9467bd")
BLOCK_COLOURS = {"Red": "#e41a1c", "Blue": "#377eb8", "Yellow": "#ffd92f"}


def draw_handover(
    hw: HandoverWorld, path, execution: HandoverExecution | None = None, title: str | None = None
) -> None:
    """The layout (cells tinted by the arms reaching them, shared cells hatched, regions E..J), the
    blocks' start cells and, with an execution, each end effector's path and its handovers (stars)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle

    lay = hw.layout
    rows, cols = lay.shape
    fig, ax = plt.subplots(figsize=(max(5.0, cols * 0.75), max(3.0, rows * 0.9 + 1.2)))
    for cell in sorted(lay.cells):
        r, c = cell
        arms = lay.arms_reaching(cell)
        colour = ARM_COLOURS[arms[0]] if len(arms) == 1 else "#bbbbbb"
        ax.add_patch(
            Rectangle(
                (c - 0.5, r - 0.5),
                1,
                1,
                facecolor=colour,
                alpha=0.18,
                hatch="//" if len(arms) > 1 else None,
                edgecolor="#888888",
            )
        )
        label = lay.region_at.get(cell)
        if label:
            ax.text(c - 0.42, r - 0.38, label, fontsize=11, fontweight="bold", va="top")
    for b, (r, c) in hw.blocks.items():
        ax.add_patch(Rectangle((c - 0.2, r - 0.2), 0.4, 0.4, facecolor=BLOCK_COLOURS[b], edgecolor="black"))
    if execution is not None:
        for a, cells in execution.paths.items():
            xs = [c + (a - 1.5) * 0.06 for _, c in cells]
            ys = [r + (a - 1.5) * 0.06 for r, _ in cells]
            ax.plot(xs, ys, color=ARM_COLOURS[a], lw=1.6, alpha=0.85, label=f"arm {ARMS[a]}")
        for k, ho in enumerate(execution.handovers):
            r, c = ho.cell
            ax.scatter(
                [c], [r], marker="*", s=260, color=BLOCK_COLOURS[ho.block], edgecolors="black", zorder=5
            )
            ax.annotate(
                f"{ARMS[ho.giver]}→{ARMS[ho.taker]}",
                (c, r),
                xytext=(6, -12 - 8 * (k % 2)),
                textcoords="offset points",
                fontsize=7,
            )
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    for a in range(len(ARMS)):
        r, c = hw.arm_starts[a]
        ax.scatter([c], [r], marker="o", s=40, color=ARM_COLOURS[a], edgecolors="black", zorder=6)
    ax.set_xlim(-0.6, cols - 0.4)
    ax.set_ylim(rows - 0.4, -0.6)
    ax.set_aspect("equal")
    ax.set_xticks(range(cols))
    ax.set_yticks(range(rows))
    ax.set_title(
        title or f"{hw.name}: arms a-d (colours), shared cells hatched, handovers starred", fontsize=8
    )
    fig.tight_layout()
    save_figure(fig, path, dpi=110)
    plt.close(fig)
