"""Support opens and closes every completion of a node needs (summed-cost bound, `heuristic.py`):
one action each, on top of the events and the walking."""

from __future__ import annotations

from nl2hltl2plan.planning.leaves import DONE, Leaf
from nl2hltl2plan.planning.node import Node, bound
from nl2hltl2plan.planning.state import Expander
from nl2hltl2plan.planning.support import blockers
from nl2hltl2plan.worlds.effects import RUNS_CLOSED
from nl2hltl2plan.worlds.simulator import OPEN, PRESENT


def forced_opens(x: Expander, required: set[int], node: Node) -> int:
    """Support opens every completion needs: closed openables that every candidate of a pending
    event sits in (or, for a put, is) and that no leaf opens itself, one open event each; then
    events all of whose candidates are closed in (a put into any of 19 closed drawers) need an
    open of one of those openables: a family of such events with disjoint openables (and
    disjoint from the first ones) adds one open each."""
    forced: set[int] = set()
    some: list[frozenset[int]] = []
    leaf_opens = {a.types[0] for lf in x.p.leaves if node.q[lf.index] != DONE
                  for a in lf.atoms if a.verb == "open"}
    for lf in x.p.leaves:
        if node.q[lf.index] == DONE or lf.index not in required:
            continue
        per_path = [_path_opens(x, node, lf, path) for path in lf.paths.get(node.q[lf.index]) or []]
        if per_path:
            forced |= set.intersection(*(every for every, _ in per_path))
        if len(per_path) == 1:
            some += per_path[0][1]
    forced = {c for c in forced if x.types[c] not in leaf_opens}
    taken = set(forced)
    extra = 0
    for group in sorted(some, key=lambda g: (len(g), sorted(g))):
        if taken.isdisjoint(group) and not any(x.types[c] in leaf_opens for c in group):
            taken |= group
            extra += 1
    return len(forced) + extra


def _path_opens(x: Expander, node: Node, leaf: Leaf,
                path: tuple[int, ...]) -> tuple[set[int], list[frozenset[int]]]:
    """(openables every candidate of some event of the path needs opened, per event whose every
    candidate needs one: the openables that would do)."""
    sim = node.sim
    out: set[int] = set()
    some: list[frozenset[int]] = []
    moved: set[str] = set()
    for k in path:
        atom = leaf.atoms[k]
        target = atom.types[-1]
        skip = target in moved or atom.verb not in ("pickup", "put")
        if atom.verb in ("pickup", "put"):
            moved.add(atom.types[0])  # where it is now no longer tells what it needs
        if skip:
            continue
        b = bound(node, leaf.index, target)
        cands = [b] if b >= 0 else x.by_type.get(target, [])
        if not cands or any(x.slice_of[o] >= 0 or not sim.flags[o] & PRESENT for o in cands):
            continue
        need: set[int] | None = None
        union: set[int] = set()
        for o in cands:
            got = {c for verb, c in blockers(sim, atom.verb, (o,)) if verb == "open"}
            need = got if need is None else need & got
            if not got:
                union = set()
                break
            union |= got
        out |= need or set()
        if union and not need:
            some.append(frozenset(union))
    return out, some


def forced_closes(x: Expander, required: set[int], node: Node) -> int:
    """Support closes every completion needs, and the opens that follow them: an appliance that
    runs only closed (the microwave) must be closed before a pending `toggle_on` of it when every
    path of the leaf first puts something into it (the put leaves it open) or when every candidate
    is open now. One close per such type at least (two heat tasks may share one close); none for a
    type a leaf closes itself. When every path then takes out what it put in, the appliance,
    closed at the toggle, must be opened again before that pickup: one open more per such type
    (after the close, so no open `forced_opens` counts), none for a type a leaf opens or closes."""
    pending = [lf for lf in x.p.leaves if node.q[lf.index] != DONE]
    leaf_closes = {a.types[0] for lf in pending for a in lf.atoms if a.verb == "close"}
    leaf_opens = {a.types[0] for lf in pending for a in lf.atoms if a.verb == "open"}
    types: set[str] = set()
    reopened: set[str] = set()
    for lf in pending:
        if lf.index not in required:
            continue
        paths = lf.paths.get(node.q[lf.index]) or []
        found = [_needs_close(x, node, lf, path) for path in paths]
        if found and all(t for t, _ in found) and len({t for t, _ in found}) == 1:
            types.add(found[0][0])
            if all(reopen for _, reopen in found):
                reopened.add(found[0][0])
    return len(types - leaf_closes) + len((reopened & types) - leaf_closes - leaf_opens)


def _needs_close(x: Expander, node: Node, leaf: Leaf, path: tuple[int, ...]) -> tuple[str, bool]:
    """(The run-closed appliance type this path must find closed after it is open, or "";
    whether the path then picks up from it something it put into it)."""
    filled: set[str] = set()
    inside: dict[str, str] = {}  # an object type put into the appliance type
    for pos, k in enumerate(path):
        atom = leaf.atoms[k]
        target = atom.types[-1]
        if atom.verb == "put" and target in RUNS_CLOSED:
            inside[atom.types[0]] = target
        if target not in RUNS_CLOSED:
            continue
        if atom.verb == "put":
            filled.add(target)
        elif atom.verb == "close":
            return "", False
        elif atom.verb == "toggle_on":
            b = bound(node, leaf.index, target)
            cands = [b] if b >= 0 else x.by_type.get(target, [])
            if target in filled or (cands and all(node.sim.flags[o] & OPEN for o in cands)):
                return target, _takes_out(leaf, path[pos + 1:], target, inside)
    return "", False


def _takes_out(leaf: Leaf, rest: tuple[int, ...], appliance: str, inside: dict[str, str]) -> bool:
    """Does the rest of the path pick up something the path put into `appliance`, before any open
    or put of its own there?"""
    for k in rest:
        atom = leaf.atoms[k]
        if atom.types[-1] == appliance and atom.verb in ("open", "put"):
            return False
        if atom.verb == "pickup" and inside.get(atom.types[0]) == appliance:
            return True
    return False
