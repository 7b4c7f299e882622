"""`nl2hltl2plan show FILE -o out.png`: draw an HTT or a specification hierarchy graph."""

from __future__ import annotations

import argparse
import json
import textwrap

import networkx as nx

from nl2hltl2plan.cli.commands import COMMANDS
from nl2hltl2plan.io import PICTURE_FORMATS, check_output_file, read_json
from nl2hltl2plan.language.htt import HTT
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "show",
        help=COMMANDS["show"],
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
    """The package's one tree drawing (`present.htt_pictures.draw_tree`) on a graph with decomposition
    edges and `before` relations."""
    from nl2hltl2plan.present.htt_pictures import draw_tree as render_tree

    children: dict[str, list[str]] = {n: [] for n in g.nodes}
    relations = []
    for a, b, d in g.edges(data=True):
        if d.get("kind") == "decomposition":
            children[a].append(b)
        elif d.get("kind") == "before":
            relations.append((a, b))
    render_tree(children, labels, relations, out)
