"""`nl2hltl2plan show FILE -o out.png`: draw an HTT or a specification hierarchy graph."""

from __future__ import annotations

import argparse
import json
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import networkx as nx  # noqa: E402

from nl2hltl2plan.io import PICTURE_FORMATS, check_output_file, read_json  # noqa: E402
from nl2hltl2plan.language.htt import HTT  # noqa: E402
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec  # noqa: E402


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "show",
        help="draw an HTT or a hierarchical spec as a tree picture",
        description="Draw a Hierarchical Task Tree (decomposition edges black, temporal "
        "relations red) or a specification hierarchy graph (one node per flat formula).",
    )
    p.add_argument("file", help="HTT JSON or hierarchical spec JSON")
    p.add_argument("-o", "--out", required=True, help="output picture (.png, .svg, .pdf)")
    p.add_argument("--json", action="store_true", help="print what was drawn as JSON")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    check_output_file(args.out, PICTURE_FORMATS, "picture")
    data = read_json(args.file, "HTT or specification file")
    if isinstance(data, dict) and "nodes" in data:
        htt = HTT.from_json(data)
        g = htt.graph()
        labels = {n.id: f"{n.id}\n" + textwrap.fill(n.text, 22) for n in htt.nodes}
        kind, root = "htt", htt.root.id
    else:
        spec = HierarchicalSpec.from_json(data)
        g = nx.DiGraph()
        for n in spec.names:
            g.add_node(n)
            for c in spec.children(n):
                g.add_edge(n, c, kind="decomposition")
        labels = {n: f"{n}\n" + textwrap.fill(spec.text(n), 26) for n in spec.names}
        kind, root = "spec", None
    draw_tree(g, labels, args.out, root)
    if args.json:
        print(
            json.dumps(
                {
                    "kind": kind,
                    "nodes": list(g.nodes),
                    "out": args.out,
                    "edges": [[a, b, d.get("kind")] for a, b, d in g.edges(data=True)],
                },
                indent=2,
            )
        )
    else:
        print(f"wrote {args.out} ({kind}, {g.number_of_nodes()} nodes)")
    return 0


def draw_tree(g: nx.DiGraph, labels: dict[str, str], out: str, root: str | None = None) -> None:
    """Layered top-down layout: depth from the decomposition edges, leaves spread evenly."""
    tree = nx.DiGraph([(a, b) for a, b, d in g.edges(data=True) if d.get("kind") == "decomposition"])
    tree.add_nodes_from(g.nodes)
    roots = [root] if root else [n for n in tree if tree.in_degree(n) == 0]
    pos: dict[str, tuple[float, float]] = {}
    next_x = [0.0]

    def place(n: str, depth: int) -> float:
        kids = list(tree.successors(n))
        x = sum(place(c, depth + 1) for c in kids) / len(kids) if kids else next_x[0]
        if not kids:
            next_x[0] += 1.0
        pos[n] = (x, -depth)
        return x

    for r in roots:
        place(r, 0)
    width = max(4.0, 2.6 * next_x[0])
    height = max(3.0, 2.0 * (1 + max(-y for _, y in pos.values())))
    fig, ax = plt.subplots(figsize=(width, height))
    dec = [(a, b) for a, b, d in g.edges(data=True) if d.get("kind") == "decomposition"]
    rel = [(a, b) for a, b, d in g.edges(data=True) if d.get("kind") == "before"]
    nx.draw_networkx_edges(g, pos, edgelist=dec, ax=ax, arrows=False, edge_color="black")
    nx.draw_networkx_edges(
        g,
        pos,
        edgelist=rel,
        ax=ax,
        edge_color="tab:red",
        style="dashed",
        connectionstyle="arc3,rad=0.3",
        arrowsize=15,
    )
    for n, (x, y) in pos.items():
        ax.text(
            x,
            y,
            labels.get(n, n),
            ha="center",
            va="center",
            fontsize=7,
            bbox={
                "boxstyle": "round",
                "fc": "lightyellow" if tree.out_degree(n) else "lightblue",
                "ec": "gray",
            },
        )
    ax.set_axis_off()
    ax.margins(0.15)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
