"""Pictures and text views of an HTT (for `nl2hltl2plan plan -o DIR` and the terminal)."""

from __future__ import annotations

import textwrap
from pathlib import Path
from typing import Any

from nl2hltl2plan.io import save_figure
from nl2hltl2plan.language.htt import HTT


def htt_lines(htt: HTT, actions: bool = True, leaf_specs: dict | None = None) -> list[str]:
    """An indented text tree: `1.2 text` per node, relations under their parent, actions of leaves."""
    out: list[str] = []

    def walk(node_id: str, depth: int) -> None:
        n = htt.node(node_id)
        out.append(f"{'  ' * depth}{n.id}  {n.text}")
        rels = htt.sibling_relations(node_id) if n.children else []
        if n.any_of:
            out.append(f"{'  ' * (depth + 1)}one of: " + " | ".join(n.children))
        elif rels:
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


FONT_PT = 7.0
CHAR_IN = FONT_PT * 0.58 / 72  # generous average glyph width, so boxes never clip their text
LINE_IN = FONT_PT * 1.3 / 72
H_GAP_IN, V_GAP_IN, MARGIN_IN = 0.5, 0.7, 0.3
STACK_INDENT_IN, STACK_GAP_IN = 0.3, 0.22  # a turned level: leaves in a column under their parent
DPI, MAX_PX = 120, 1600  # a tree is saved at 120 dpi, or less where that keeps it within 1,600 px
MAX_WIDTH_IN = MAX_PX / DPI


def htt_orderings(htt: HTT) -> list[tuple[str, str]]:
    """The HTT's temporal relations as pairs of spec names (`task<id>`), the names plan steps carry
    (input for `present.gantt.draw_gantt(before=...)`)."""
    from nl2hltl2plan.language.spec_builder import spec_name

    return [(spec_name(a), spec_name(b)) for a, b in htt.relations]


def htt_task_words(htt: HTT) -> dict[str, str]:
    """What each task says, by the name plan steps carry (`task1.2` -> "put the mugs in the rack"),
    for a Gantt legend in words (`present.gantt.draw_gantt(words=...)`)."""
    from nl2hltl2plan.language.spec_builder import spec_name

    return {spec_name(n.id): n.text for n in htt.nodes}


def htt_labels(htt: HTT, max_actions: int = 8) -> dict[str, str]:
    """Box texts: id, the wrapped sentence (all of it) and, for leaves, the actions."""
    labels = {}
    for n in htt.nodes:
        width = 40 if n.id == htt.root.id else 28
        text = [n.id, *textwrap.wrap(n.text, width)]
        if n.actions:
            shown = n.actions[:max_actions]
            more = len(n.actions) - len(shown)
            text += ["actions:", *shown] + ([f"... {more} more"] if more else [])
        labels[n.id] = "\n".join(text)
    return labels


def draw_htt(htt: HTT, path: str | Path, title: str | None = None) -> Path:
    """Draw the tree (decomposition edges grey, temporal relations red arrows) to an image file."""
    return draw_tree(
        {n.id: list(n.children) for n in htt.nodes}, htt_labels(htt), list(htt.relations), path, title=title
    )


def htt_figure(htt: HTT, title: str | None = None) -> Any:
    """The HTT picture as a matplotlib figure (the caller saves and closes it)."""
    return tree_figure(
        {n.id: list(n.children) for n in htt.nodes}, htt_labels(htt), list(htt.relations), title=title
    )


def _box(label: str) -> tuple[float, float]:
    lines = label.split("\n")
    return max(len(line) for line in lines) * CHAR_IN + 0.25, len(lines) * LINE_IN + 0.2


def tree_layout(
    children: dict[str, list[str]], labels: dict[str, str], stacked: frozenset[str] = frozenset()
) -> tuple[dict[str, tuple[float, float]], dict[str, tuple[float, float]]]:
    """Tidy top-down layout in inches: each subtree gets the width of its widest level, parents sit
    centred over their children, rows are as tall as their tallest box. The children of a node in
    `stacked` (all leaves) hang in a column under it instead of side by side. Returns centre
    positions (x, y down from the top) and box sizes."""
    size = {n: _box(labels.get(n, n)) for n in children}
    has_parent = {c for kids in children.values() for c in kids}
    roots = [n for n in children if n not in has_parent]
    depth: dict[str, int] = {}

    def set_depth(n: str, d: int) -> None:
        depth[n] = d
        for c in children.get(n, []):
            set_depth(c, d + 1)

    for r in roots:
        set_depth(r, 0)
    span: dict[str, float] = {}

    def width(n: str) -> float:
        kids = children.get(n, [])
        if n in stacked:
            below = STACK_INDENT_IN + max(width(c) for c in kids)
        else:
            below = sum(width(c) for c in kids) + H_GAP_IN * max(0, len(kids) - 1)
        span[n] = max(size[n][0], below)
        return span[n]

    row_h = [0.0] * (max(depth.values(), default=0) + 1)
    for n, d in depth.items():
        if not any(n in children.get(p, []) for p in stacked):  # a column's boxes are not a row's
            row_h[d] = max(row_h[d], size[n][1])
    row_top = [MARGIN_IN + sum(row_h[:d]) + V_GAP_IN * d for d in range(len(row_h))]
    pos: dict[str, tuple[float, float]] = {}

    def place(n: str, left: float) -> None:
        kids = children.get(n, [])
        if n in stacked:
            pos[n] = (left + span[n] / 2, row_top[depth[n]] + size[n][1] / 2)
            y = row_top[depth[n]] + size[n][1] + V_GAP_IN / 2
            x = pos[n][0] - size[n][0] / 2 + STACK_INDENT_IN  # the column starts under the box
            for c in kids:
                pos[c] = (x + size[c][0] / 2, y + size[c][1] / 2)
                y += size[c][1] + STACK_GAP_IN
            return
        below = sum(span[c] for c in kids) + H_GAP_IN * max(0, len(kids) - 1)
        x = left + (span[n] - below) / 2
        for c in kids:
            place(c, x)
            x += span[c] + H_GAP_IN
        centre = (pos[kids[0]][0] + pos[kids[-1]][0]) / 2 if kids else left + span[n] / 2
        pos[n] = (centre, row_top[depth[n]] + size[n][1] / 2)

    left = MARGIN_IN
    for r in roots:
        width(r)
        place(r, left)
        left += span[r] + H_GAP_IN
    return pos, size


def _extent(pos: dict, size: dict) -> tuple[float, float]:
    return (max((pos[n][0] + size[n][0] / 2 for n in pos), default=1.0) + MARGIN_IN,
            max((pos[n][1] + size[n][1] / 2 for n in pos), default=1.0) + MARGIN_IN)  # fmt: skip


def fitted_layout(
    children: dict[str, list[str]], labels: dict[str, str], max_width_in: float = MAX_WIDTH_IN
) -> tuple[dict[str, tuple[float, float]], dict[str, tuple[float, float]], frozenset[str]]:
    """The tidy layout, or, when it is wider than `max_width_in`, the one with every last level
    turned into columns (leaves under their parent); returns positions, sizes and turned parents."""
    pos, size = tree_layout(children, labels)
    if _extent(pos, size)[0] <= max_width_in:
        return pos, size, frozenset()
    stacked = frozenset(n for n, kids in children.items() if kids and not any(children.get(c) for c in kids))
    pos, size = tree_layout(children, labels, stacked)
    return pos, size, stacked


def draw_tree(
    children: dict[str, list[str]],
    labels: dict[str, str],
    relations: list[tuple[str, str]],
    path: str | Path,
    title: str | None = None,
) -> Path:
    """Draw a forest (`children`: node -> ordered children; every node a key) with boxes sized to
    their text, decomposition edges and `a before b` relations as red arrows; png/svg/pdf by suffix."""
    import matplotlib.pyplot as plt

    fig = tree_figure(children, labels, relations, title)
    out = Path(path)
    save_figure(fig, out, dpi="figure", bbox_inches="tight")
    plt.close(fig)
    return out


def tree_figure(
    children: dict[str, list[str]],
    labels: dict[str, str],
    relations: list[tuple[str, str]],
    title: str | None = None,
) -> Any:
    """The figure `draw_tree` saves."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    pos, size, stacked = fitted_layout(children, labels)
    total_w, total_h = _extent(pos, size)
    width = max(total_w, 3.0)
    fig = plt.figure(figsize=(width, total_h), dpi=min(DPI, MAX_PX / (width + 0.2)))  # 0.2: tight bbox pad
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, max(total_w, 3.0))
    ax.set_ylim(total_h, 0)  # y grows downwards, in inches
    ax.axis("off")
    for n, kids in children.items():
        x0, y0 = pos[n]
        for c in kids:
            x1, y1 = pos[c]
            if n in stacked:  # an elbow down the column's left side, then across to the box
                xe = x1 - size[c][0] / 2 - STACK_INDENT_IN / 2
                xs, ys = [xe, xe, x1 - size[c][0] / 2], [y0 + size[n][1] / 2, y1, y1]
                ax.plot(xs, ys, color="0.55", lw=1, zorder=1)
            else:
                ax.plot([x0, x1], [y0 + size[n][1] / 2, y1 - size[c][1] / 2], color="0.55", lw=1, zorder=1)
    siblings = {c: kids for kids in children.values() for c in kids}
    column = {c for n in stacked for c in children[n]}
    for a, b in relations:
        _relation_arrow(ax, pos, size, a, b, siblings.get(a, []), a in column)
    from matplotlib.patches import FancyBboxPatch

    for n, (x, y) in pos.items():
        w, h = size[n]
        ax.add_patch(FancyBboxPatch((x - w / 2, y - h / 2), w, h, boxstyle="round,pad=0,rounding_size=0.06",
                                    ec="0.45", fc="lightyellow" if children.get(n) else "honeydew",
                                    zorder=2))  # fmt: skip
        ax.text(x, y, labels.get(n, n), ha="center", va="center", fontsize=FONT_PT, zorder=3,
                linespacing=1.1)  # fmt: skip
    if relations:
        ax.plot([], [], color="tab:red", lw=1.3, label="a before b")
        ax.legend(loc="lower right", fontsize=7, frameon=False)
    if title:
        fig.suptitle("\n".join(textwrap.wrap(title, max(40, int(total_w / CHAR_IN / 1.2)))), fontsize=8,
                     y=1.0, va="bottom")  # fmt: skip
    return fig


def _relation_arrow(ax, pos: dict, size: dict, a: str, b: str, siblings: list[str], in_column: bool) -> None:
    """`a` just before its sibling `b`: a straight arrow across the gap (nothing lies between them in
    a tidy layout; in a column, the gap below `a`); otherwise a dashed arc over the boxes."""
    (xa, ya), (xb, yb) = pos[a], pos[b]
    style = {"arrowstyle": "-|>", "color": "tab:red", "lw": 1.3, "shrinkA": 2, "shrinkB": 2}
    consecutive = a in siblings and b in siblings and siblings.index(b) == siblings.index(a) + 1
    if consecutive and in_column:
        ax.annotate("", xy=(xb, yb - size[b][1] / 2), xytext=(xa, ya + size[a][1] / 2), arrowprops=style,
                    zorder=4)  # fmt: skip
        return
    if consecutive:
        y = max(ya - size[a][1] / 2, yb - size[b][1] / 2) + min(size[a][1], size[b][1]) / 2  # level
        ax.annotate("", xy=(xb - size[b][0] / 2, y), xytext=(xa + size[a][0] / 2, y), arrowprops=style,
                    zorder=4)  # fmt: skip
        return
    bend = 0.25 if xb < xa else -0.25  # either way the arc bulges upwards
    ax.annotate("", xy=(xb, yb - size[b][1] / 2), xytext=(xa, ya - size[a][1] / 2), zorder=4,
                arrowprops={**style, "ls": "--", "connectionstyle": f"arc3,rad={bend}"})  # fmt: skip
