"""Pictures and text views of an HTT (for `nl2hltl2plan plan -o DIR` and the terminal)."""

from __future__ import annotations

import textwrap
from pathlib import Path

from nl2hltl2plan.language.htt import HTT


def htt_lines(htt: HTT, actions: bool = True, leaf_specs: dict | None = None) -> list[str]:
    """An indented text tree: `1.2 text` per node, relations under their parent, actions of leaves."""
    out: list[str] = []

    def walk(node_id: str, depth: int) -> None:
        n = htt.node(node_id)
        out.append(f"{'  ' * depth}{n.id}  {n.text}")
        rels = htt.sibling_relations(node_id) if n.children else []
        if rels:
            out.append(f"{'  ' * (depth + 1)}order: " + ", ".join(f"{a} < {b}" for a, b in rels))
        elif len(n.children) > 1:
            out.append(f"{'  ' * (depth + 1)}order: any")
        if actions and n.actions:
            out.append(f"{'  ' * (depth + 1)}actions: " + " ; ".join(n.actions))
        elif actions and leaf_specs and isinstance(leaf_specs.get(n.id), str):
            out.append(f"{'  ' * (depth + 1)}formula: {leaf_specs[n.id]}")
        for c in n.children:
            walk(c, depth + 1)

    walk(htt.root.id, 0)
    return out


def draw_htt(htt: HTT, path: str | Path, title: str | None = None) -> Path:
    """Draw the tree (decomposition edges solid, temporal relations dashed red arrows) to an image file."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    pos: dict[str, tuple[float, float]] = {}
    counter = [0.0]

    def place(node_id: str, depth: int) -> float:
        n = htt.node(node_id)
        if not n.children:
            x = counter[0]
            counter[0] += 1.0
        else:
            xs = [place(c, depth + 1) for c in n.children]
            x = sum(xs) / len(xs)
        pos[node_id] = (x, -depth)
        return x

    place(htt.root.id, 0)
    width = max(6.0, 2.2 * counter[0])
    depth = max(-y for _, y in pos.values()) + 1
    fig, ax = plt.subplots(figsize=(width, 1.8 * depth + 1))
    for n in htt.nodes:
        for c in n.children:
            (x0, y0), (x1, y1) = pos[n.id], pos[c]
            ax.plot([x0, x1], [y0, y1], color="0.55", lw=1, zorder=1)
    for a, b in htt.relations:
        (x0, y0), (x1, y1) = pos[a], pos[b]
        ax.annotate(
            "",
            xy=(x1, y1 + 0.18),
            xytext=(x0, y0 + 0.18),
            arrowprops={
                "arrowstyle": "->",
                "color": "tab:red",
                "ls": "--",
                "connectionstyle": "arc3,rad=-0.3",
            },
        )
    for n in htt.nodes:
        x, y = pos[n.id]
        label = n.id + "\n" + "\n".join(textwrap.wrap(n.text, 22)[:3])
        if n.actions:
            label += "\n" + "\n".join(n.actions[:4]) + ("\n..." if len(n.actions) > 4 else "")
        ax.text(
            x,
            y,
            label,
            ha="center",
            va="top",
            fontsize=7,
            zorder=2,
            bbox={"boxstyle": "round", "fc": "lightyellow" if n.children else "honeydew", "ec": "0.5"},
        )
    ax.set_xlim(-0.8, counter[0] - 0.2)
    ax.set_ylim(-depth + 0.1, 0.6)
    ax.axis("off")
    if title:
        ax.set_title("\n".join(textwrap.wrap(title, 120)), fontsize=8)
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return out
