"""Hand-written plans: per-robot action scripts turned into timed `Plan`s by walking shortest paths.

A script line is `verb ids... [:task]`, e.g. "pickup Apple_0 :A", "put Apple_0 Fridge_0 :A",
"wait 3" (wait 3 steps), "until 20" (wait until step 20 is over), "goto 4 5" (walk to cell (4, 5)).
Before each action the robot walks (shortest 4-neighbour path) to the nearest cell of the target's
current interaction region (the receptacle's for `put`). Scripts are laid out robot after robot, each
on its own clock, using one shared simulated state, so a script that depends on another robot's effect
must wait for it (`until`). Used by tests, the README demo and the CLI; not a planner.
"""

from __future__ import annotations

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.logic.action_sequences import formula_sequences
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.worlds.plan import ACTION_ARITY, Plan, RobotPlan, Step
from nl2hltl2plan.worlds.simulator import OPEN, SimState
from nl2hltl2plan.worlds.world import Cell, World


def parse_line(line: str) -> tuple[str, list[str], str | None]:
    task = None
    if ":" in line:
        line, task = line.rsplit(":", 1)
        task = task.strip() or None
    words = line.split()
    if not words:
        raise WorldError("empty script line")
    return words[0], words[1:], task


def scripted_plan(world: World, scripts: dict[int, tuple[Cell, list[str]]], check: bool = True) -> Plan:
    """Plan from {robot: (start cell, [script lines])}; WorldError on an action that cannot be done."""
    state = SimState(world)
    robots = []
    for robot, (start, lines) in sorted(scripts.items()):
        start = (start[0], start[1])
        if start not in world.cell_set:
            start = world.cell_of(*world.xz(start))
        state.place_robot(robot, start)
        cur: Cell = start  # type: ignore[assignment]
        t = 0
        steps: list[Step] = []
        for line in lines:
            verb, args, task = parse_line(line)
            if verb == "wait":
                t += int(args[0]) if args else 1
                continue
            if verb == "until":
                t = max(t, int(args[0]))
                continue
            if verb == "goto":
                goal: Cell = (int(args[0]), int(args[1]))
                for cell in world.path(cur, goal)[1:]:
                    t += 1
                    steps.append(Step(t=t, verb="move", cell=cell))
                cur = goal
                state.place_robot(robot, cur)
                continue
            if verb not in ACTION_ARITY:
                raise WorldError(f"robot {robot}: unknown script verb {verb!r} in {line!r}")
            region = state.region(args[-1]) if args and args[-1] in world.objects else ()
            if region and cur not in region:
                dist = world.distances_from(cur)
                target = min((c for c in region if c in dist), key=lambda c: (dist[c], c), default=None)
                if target is None:
                    raise WorldError(f"robot {robot}: cannot reach {args[-1]} from {cur}")
                for cell in world.path(cur, target)[1:]:
                    t += 1
                    steps.append(Step(t=t, verb="move", cell=cell))
                cur = target
                state.place_robot(robot, cur)
            t += 1
            why = state.apply(robot, verb, args)
            if why and check:
                raise WorldError(f"robot {robot}, {line!r}: {why}")
            steps.append(Step(t=t, verb=verb, objects=args, task=task))
        robots.append(RobotPlan(robot=robot, start=start, steps=steps))
    return Plan(robots=robots)


# ---------------------------------------------------------------- recipes, executed greedily
def parse_atom(atom: str) -> tuple[str, list[str]]:
    """`put(Apple,Fridge)` -> ("put", ["Apple", "Fridge"])."""
    parsed = Atom.read(atom)
    if parsed is None:
        raise WorldError(f"not an action atom: {atom!r}")
    return parsed.verb, list(parsed.args)


class _Greedy:
    """Performs leaf action lists with one robot, binding each type to the nearest usable instance."""

    def __init__(self, world: World, robot: int, start: Cell) -> None:
        self.w = world
        self.robot = robot
        self.state = SimState(world)
        self.state.place_robot(robot, start)
        self.cur = start
        self.used: set[str] = set()  # manipulated instances earlier tasks relied on
        self.lines: list[str] = []

    def _cost(self, oid: str) -> int | None:
        dist = self.w.distances_from(self.cur)
        return min((dist[c] for c in self.state.region(oid) if c in dist), default=None)

    def save(self) -> tuple:
        return (self.state.copy(), self.cur, set(self.used), len(self.lines))

    def restore(self, saved: tuple) -> None:
        self.state, self.cur, self.used, n = saved
        del self.lines[n:]

    def _closed_in(self, oid: str) -> bool:
        return any(
            self.w.objects[a].affordances.openable and not self.state.flags[self.state.c.index[a]] & OPEN
            for a in _state_ancestors(self.state, oid)
        )

    def _pick(self, type_: str, avoid: set[str]) -> str:
        idx = self.state.c.index
        best = None
        for o in self.w.instances(type_):
            i = idx[o.id]
            if o.id in avoid or not self.state.flags[i] & 1 or self.state.holder[i] >= 0:
                continue
            cost = self._cost(o.id)
            if cost is not None:
                key = (self._closed_in(o.id), cost, o.id)  # prefer what needs no opening
                if best is None or key < best:
                    best = key
        if best is None:
            raise WorldError(f"no usable {type_} left in {self.w.name} (reachable from {self.cur})")
        return best[2]

    def run_leaf(self, actions: list[str], task: str | None) -> None:
        bound: dict[str, str] = {}
        slices: list[str] = []
        parsed = [parse_atom(a) for a in actions]
        for k, (verb, types) in enumerate(parsed):
            if verb == "open" and types[0] not in bound:
                # open the openable that holds the object picked next, when there is one
                nxt = next((ts[0] for v, ts in parsed[k + 1 :] if v in ("pickup", "slice")), None)
                if nxt and nxt not in bound and not self.w.instances(nxt)[0].slice_of:
                    inside = {
                        o.id
                        for o in self.w.instances(nxt)
                        if not any(
                            self.w.objects[a].type == types[0] for a in _state_ancestors(self.state, o.id)
                        )
                    }
                    try:  # prefer an instance this open makes reachable
                        bound[nxt] = self._pick(nxt, self.used | inside)
                    except WorldError:
                        bound[nxt] = self._pick(nxt, self.used)
                    anc = [
                        a
                        for a in _state_ancestors(self.state, bound[nxt])
                        if self.w.objects[a].type == types[0]
                    ]
                    if anc:
                        bound[types[0]] = anc[0]
            if verb == "toggle_on" and types[0] == "Faucet" and "SinkBasin" in bound:
                for f in self.w.instances("Faucet"):
                    if f.serves == bound["SinkBasin"]:
                        bound["Faucet"] = f.id
            ids: list[str] = []
            for typ in types:
                if typ not in bound:
                    free_slices = [s for s in slices if self.w.objects[s].type == typ and s not in self.used]
                    if verb == "pickup" and free_slices:
                        bound[typ] = free_slices[0]
                    else:
                        bound[typ] = self._pick(typ, self.used | set(ids))
                ids.append(bound[typ])
            self._do(verb, ids, task)
            if verb == "slice":
                slices = list(self.w.objects[ids[0]].slices)
        manipulated = {bound[ts[0]] for v, ts in parsed if v in ("pickup", "slice")}
        self.used |= manipulated

    def free_hand(self) -> None:
        """Put down what the robot still holds (after examine_in_light) on the nearest open surface."""
        held = self.state.held_by(self.robot)
        if held is None:
            return
        typ = self.w.objects[held].type
        best = None
        for o in self.w.objects.values():
            if typ in o.affordances.accepts and not o.affordances.openable and not o.pickupable:
                cost = self._cost(o.id)
                if cost is not None and not self._closed_in(o.id) and (best is None or (cost, o.id) < best):
                    best = (cost, o.id)
        if best is None:
            raise WorldError(f"nowhere to put {held} down in {self.w.name}")
        self._do("put", [held, best[1]], None)

    def _do(self, verb: str, ids: list[str], task: str | None) -> None:
        region = self.state.region(ids[-1])
        if region and self.cur not in region:
            dist = self.w.distances_from(self.cur)
            goal = min((c for c in region if c in dist), key=lambda c: (dist[c], c))
            self.lines.append(f"goto {goal[0]} {goal[1]}")
            self.cur = goal
            self.state.place_robot(self.robot, goal)
        why = self.state.apply(self.robot, verb, ids)
        if why:
            raise WorldError(f"{verb}({','.join(ids)}): {why}")
        self.lines.append(f"{verb} {' '.join(ids)}" + (f" :{task}" if task else ""))


def _state_ancestors(state: SimState, oid: str) -> list[str]:
    out = []
    x = state.parent[state.c.index[oid]]
    while x >= 0:
        out.append(state.c.ids[x])
        x = state.parent[x]
    return out


def sequential_plan(world: World, tasks: list, before: list | None = None, start: Cell | None = None) -> Plan:
    """One robot doing each task's recipe (`BaseTask.leaf_specs`, first alternative) in an order that
    respects `before`, binding types to the nearest usable instances. A baseline and a test oracle,
    not an optimiser."""
    import networkx as nx

    graph = nx.DiGraph()
    graph.add_nodes_from(t.id for t in tasks)
    graph.add_edges_from(tuple(p) for p in before or [])
    by_id = {t.id: t for t in tasks}
    start = start or (world.default_starts[0] if world.default_starts else world.cells[0])
    greedy = _Greedy(world, 0, start)
    for tid in nx.lexicographical_topological_sort(graph):
        for leaf in by_id[tid].leaf_specs(world, others=tasks, support=True):
            alternatives = [leaf] if isinstance(leaf, list) else formula_sequences(leaf)
            for k, actions in enumerate(alternatives):
                saved = greedy.save()
                try:
                    greedy.run_leaf(actions, tid)
                    break
                except WorldError:
                    greedy.restore(saved)
                    if k == len(alternatives) - 1:
                        raise
            greedy.free_hand()
    return scripted_plan(world, {0: (start, greedy.lines)})
