"""Heterogeneous robot teams: skills and mass capacity, as per-robot planner capabilities.

A `RobotProfile` has AI2-THOR skills (SMART-LLM's `resources/robots.py`, shared data
`smartllm/robots.json`: GoToObject, OpenObject, SliceObject, SwitchOn, PickupObject, ...) and a mass
capacity in kg (None: no limit). The planner takes per robot a set of verbs or atoms
(`planning.plan(capabilities=...)`); `Team.capabilities(world)` turns each profile into one:
- OpenObject -> open, CloseObject -> close, SwitchOn -> toggle_on, SwitchOff -> toggle_off,
  SliceObject -> slice, BreakObject -> break, PickupObject -> pickup, PutObject -> put,
  ThrowObject -> put(X,GarbageCan) for every pickupable X (throwing into the trash);
  GoToObject, DropHandObject, PushObject, PullObject and CleanObject have no verb of their own
  (moving is free to every robot; cleaning is a running faucet).
- mass: a robot whose capacity is below an object type's mass (a `masses` table, kg) gets
  `pickup(T)` only for the types it can carry; types of unknown mass are not limited.
One robot carries an object alone (no joint carrying), and the robot that slices holds the knife.
`Team.problems(spec, world)` names what no robot of the team can do before any planning:
"no robot in the team can slice (SliceObject)".

`parse_team(text)` reads what `plan --robots` accepts: a number ("3": unrestricted robots), profile
names ("robot1,robot5"), or a JSON file (a list of profile names and/or {"name", "skills",
"mass_capacity"} objects).
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from nl2hltl2plan.argtypes import MAX_ROBOTS
from nl2hltl2plan.config import data_path
from nl2hltl2plan.errors import DataError, PlanningError
from nl2hltl2plan.io import read_json
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.worlds.world import KNIFE_TYPES, World

SKILL_VERBS = {
    "OpenObject": "open",
    "CloseObject": "close",
    "SwitchOn": "toggle_on",
    "SwitchOff": "toggle_off",
    "SliceObject": "slice",
    "BreakObject": "break",
    "PickupObject": "pickup",
    "PutObject": "put",
}
NO_VERB_SKILLS = frozenset(
    {"GoToObject", "DropHandObject", "PushObject", "PullObject", "CleanObject", "ThrowObject"}
)
KNOWN_SKILLS = frozenset(SKILL_VERBS) | NO_VERB_SKILLS
VERB_SKILL = {v: k for k, v in SKILL_VERBS.items()}
VERB_WORDS = {"pickup": "pick up", "toggle_on": "switch on", "toggle_off": "switch off"}
TRASH = "GarbageCan"


@dataclass(frozen=True)
class RobotProfile:
    name: str
    skills: frozenset[str]
    mass_capacity: float | None = None  # kg; None: carries anything

    @classmethod
    def from_dict(cls, d: Mapping, where: str = "") -> RobotProfile:
        try:
            name = str(d["name"])
            skills = frozenset(str(s) for s in d["skills"])
        except (KeyError, TypeError):
            raise DataError(
                f"{where}robot profile needs 'name' and a list of 'skills', got {dict(d)!r}"
            ) from None
        unknown = sorted(skills - KNOWN_SKILLS)
        if unknown:
            raise DataError(
                f"{where}robot {name}: unknown skill(s) {', '.join(unknown)} "
                f"(known: {', '.join(sorted(KNOWN_SKILLS))})"
            )
        cap = d.get("mass_capacity", d.get("mass"))
        if cap is not None and (
            isinstance(cap, bool) or not isinstance(cap, int | float) or not math.isfinite(cap) or cap <= 0
        ):  # JSON files may hold NaN and Infinity
            raise DataError(
                f"{where}robot {name}: mass capacity must be a positive number of kg, got {cap!r}"
            )
        return cls(name, skills, None if cap is None else float(cap))

    def verbs(self) -> frozenset[str]:
        return frozenset(SKILL_VERBS[s] for s in self.skills if s in SKILL_VERBS)

    def can_carry(self, type_: str, masses: Mapping[str, float]) -> bool:
        mass = masses.get(type_)
        return self.mass_capacity is None or mass is None or mass <= self.mass_capacity


@cache
def smartllm_profiles() -> dict[str, RobotProfile]:
    """SMART-LLM's 28 robot profiles by name (robot1..robot28), from the shared data."""
    path = data_path("smartllm", "robots.json")
    raw = read_json(path, "SMART-LLM robot profiles file")
    if not isinstance(raw, dict):
        raise DataError(f"{path}: expected an object of robot profiles by name")
    return {k: RobotProfile.from_dict(v, f"{path.name}: ") for k, v in raw.items()}


@dataclass(frozen=True)
class Team:
    """A robot team. `profiles` None: `size` robots that can do everything (the planner's default)."""

    size: int
    profiles: tuple[RobotProfile, ...] | None = None

    @classmethod
    def of(cls, profiles: Sequence[RobotProfile]) -> Team:
        if not profiles:
            raise PlanningError("a team needs at least one robot")
        return cls(len(profiles), tuple(profiles))

    def describe(self) -> str:
        if self.profiles is None:
            return f"{self.size} robot(s) with every skill"
        return ", ".join(p.name for p in self.profiles)

    def capabilities(self, world: World, masses: Mapping[str, float] | None = None) -> list[set[str] | None]:
        """Per robot: the verbs/atoms it may do in this world (None: everything)."""
        if self.profiles is None:
            return [None] * self.size
        masses = masses or {}
        pickupable = sorted({o.type for o in world.objects.values() if o.pickupable})
        out: list[set[str] | None] = []
        for p in self.profiles:
            caps = set(p.verbs())
            if "pickup" in caps and any(not p.can_carry(t, masses) for t in pickupable):
                caps.discard("pickup")
                caps |= {f"pickup({t})" for t in pickupable if p.can_carry(t, masses)}
            if "ThrowObject" in p.skills and "put" not in caps and TRASH in world.object_types():
                caps |= {f"put({t},{TRASH})" for t in pickupable}
            out.append(caps)
        return out

    def problems(
        self, atoms: Iterable[str], world: World, masses: Mapping[str, float] | None = None
    ) -> list[str]:
        """What no robot of the team can do among the spec's action atoms ("put(Apple,Fridge)"),
        one readable reason each (empty: every atom has a robot). Carrying is checked with the
        whole chain: the robot that puts X must have picked it up, and the slicer holds a knife."""
        if self.profiles is None:
            return []
        masses = masses or {}
        caps = self.capabilities(world, masses)
        out: list[str] = []
        for atom in dict.fromkeys(atoms):
            verb, _, rest = atom.partition("(")
            types = rest.rstrip(")").split(",")
            needs = [atom]
            if verb == "put":
                needs = [f"pickup({types[0]})", atom]
            elif verb == "slice":
                needs = [atom]
            if any(all(_allowed(c, a) for a in needs) for c in caps):
                if verb != "slice" or any(
                    _allowed(c, atom) and any(_allowed(c, f"pickup({k})") for k in KNIFE_TYPES) for c in caps
                ):
                    continue
                out.append(f"no robot in the team can both hold a knife and slice ({atom})")
                continue
            out.append(self._why(verb, types, needs, caps, masses))
        return list(dict.fromkeys(out))

    def _why(
        self,
        verb: str,
        types: list[str],
        needs: list[str],
        caps: list[set[str] | None],
        masses: Mapping[str, float],
    ) -> str:
        assert self.profiles is not None
        for a in needs:
            v = a.partition("(")[0]
            if any(_allowed(c, a) for c in caps):
                continue
            if v == "pickup" and any("pickup" in p.verbs() for p in self.profiles):
                t = a[len("pickup(") : -1]
                strongest = max((p.mass_capacity or 0.0) for p in self.profiles if "pickup" in p.verbs())
                return (
                    f"no robot in the team can carry a {t} ({masses.get(t)} kg; the strongest "
                    f"robot that picks up carries {strongest:g} kg)"
                )
            skill = VERB_SKILL.get(v, v)
            if v == "put" and a.endswith(f",{TRASH})"):
                skill = "PutObject or ThrowObject"
            return f"no robot in the team can {VERB_WORDS.get(v, v)} ({skill}), needed for {a}"
        return f"no single robot in the team can do all of {', '.join(needs)} (one robot carries an object)"


def spec_atoms(spec: HierarchicalSpec) -> list[str]:
    """The action atoms ("put(Apple,Fridge)") of a hierarchical spec's leaves, in order of appearance."""
    found = (str(a) for leaf in spec.leaves for a in Atom.find_all(spec.text(leaf)))
    return list(dict.fromkeys(found))


def team_problems(
    team: Team, spec: HierarchicalSpec, world: World, masses: Mapping[str, float] | None = None
) -> list[str]:
    """For `plan --robots`: why the team cannot carry out the spec in the world (empty: it may)."""
    return team.problems(spec_atoms(spec), world, masses)


def _allowed(caps: set[str] | None, atom: str) -> bool:
    return caps is None or atom in caps or atom.partition("(")[0] in caps


def parse_team(text: str | int) -> Team:
    """A team from `plan --robots`: a number, profile names ("robot1,robot5") or a JSON file."""
    if isinstance(text, int) or re.fullmatch(r"\s*[-+]?[0-9]+\s*", str(text)):  # ASCII digits ('²' is none)
        n = int(text)
        if not 1 <= n <= MAX_ROBOTS:
            raise PlanningError(
                f"--robots must be at least 1 and at most {MAX_ROBOTS} (a team's largest size), got {n}"
            )
        return Team(n)
    text = str(text).strip()
    path = Path(text)
    if text.endswith(".json") or _exists(path):  # a path: read_json refuses what is not a regular file
        return _team_file(path)
    profiles = smartllm_profiles()
    names = [n.strip() for n in text.split(",") if n.strip()]
    if len(names) > MAX_ROBOTS:
        raise PlanningError(f"--robots names {len(names)} robots; a team has at most {MAX_ROBOTS}")
    unknown = [n for n in names if n not in profiles]
    if unknown:
        raise PlanningError(
            f"unknown robot profile(s) {', '.join(unknown)}; use a number, names robot1..robot"
            f"{len(profiles)} from smartllm/robots.json, or a JSON file"
        )
    return Team.of([profiles[n] for n in names])


def _exists(path: Path) -> bool:
    try:
        return path.exists()
    except OSError:  # a name too long to be a file: profile names
        return False


def _team_file(path: Path) -> Team:
    return team_from_json(read_json(path, "team file"), f"team file {path}")


def team_from_json(raw: object, where: str = "team") -> Team:
    """A team from a team file's content: a list (or `{"robots": [...]}`) of profile names and/or
    `{"name", "skills", "mass_capacity"}` objects (the web page's uploaded team file too)."""
    if isinstance(raw, dict) and "robots" in raw:
        raw = raw["robots"]
    if not isinstance(raw, list) or not raw:
        raise DataError(f"{where}: expected a non-empty list of robots (names or profiles)")
    if len(raw) > MAX_ROBOTS:
        raise DataError(f"{where}: {len(raw)} robots; a team has at most {MAX_ROBOTS}")
    out = []
    for k, entry in enumerate(raw):
        if isinstance(entry, str):
            profiles = smartllm_profiles()
            if entry not in profiles:
                raise DataError(f"{where}: robot {k}: unknown profile {entry!r}")
            out.append(profiles[entry])
        elif isinstance(entry, dict):
            out.append(RobotProfile.from_dict(entry, f"{where}: robot {k}: "))
        else:
            raise DataError(f"{where}: robot {k} must be a profile name or an object, got {entry!r}")
    return Team.of(out)


def smartllm_team(robot_ids: Sequence[int]) -> Team:
    """The team of a SMART-LLM task's "robot list" (1-based profile numbers)."""
    profiles = smartllm_profiles()
    names = [f"robot{i}" for i in robot_ids]
    missing = [n for n in names if n not in profiles]
    if missing:
        raise DataError(f"robot list names unknown profile(s) {', '.join(missing)}")
    return Team.of([profiles[n] for n in names])
