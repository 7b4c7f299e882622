"""The four prompted stages of the paper (Section III), each one validated LLM call.

1. `decompose`: instruction -> task tree without relations (base tasks with their fields; optional groups)
2. `relations`: one non-leaf node -> temporal relations between its children
3. `rephrase` + `translate`: one non-leaf node -> lifted sentences -> one flat sc-LTL formula over
   the child names (the paper's logical search and translator; optional, the exact compiler is the
   default)
4. `complete_actions`: one leaf -> ordered robot API actions over the scene's object types

Answers are pydantic models; structural checks (known ids, scene types, action syntax) raise
ValueError inside the client's re-ask loop, so the LLM sees what was wrong. Then each answer is
checked against what it answers (`semantic_check`: the decomposition covers every object the
instruction names, relations are acyclic, a leaf's actions act on its own objects and receptacles);
a failed check is re-asked with the reasons (`ask_checked`), and when it persists the stage raises
`SemanticCheckError` naming them: a wrong answer never becomes a silent "solved".
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from typing import Annotated, TypeVar

from pydantic import BaseModel, Field, field_validator, model_validator

from nl2hltl2plan.domain.task_kinds import State
from nl2hltl2plan.errors import LLMError
from nl2hltl2plan.language import semantic_check
from nl2hltl2plan.language.llm.client import LLMClient, Validator
from nl2hltl2plan.language.negations import ALL_VERBS, STATE_VERBS
from nl2hltl2plan.language.prompts import load_prompt
from nl2hltl2plan.language.task_specs import Kind
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.worlds.plan import ACTION_ARITY

MAX_TASKS = 12
MAX_TEXT = 300  # characters of a task's text
MAX_WORD = 40  # characters of an object / receptacle name
NodeId = Annotated[str, Field(max_length=12)]
T = TypeVar("T", bound=BaseModel)


class SemanticCheckError(LLMError):
    """An LLM answer that still does not fit what was asked after the re-asks (the reasons named)."""


def ask_checked(
    client: LLMClient,
    messages: list[dict[str, str]],
    schema: type[T],
    name: str,
    problems_of: Callable[[T], list[str]],
    validate: Validator | None = None,
) -> T:
    """`client.ask`, then the semantic check `problems_of`: re-asked with the problems (at most
    `max_reasks` times), then SemanticCheckError naming them."""
    msgs = list(messages)
    reasks = client.settings.max_reasks
    for attempt in range(reasks + 1):
        answer = client.ask(msgs, schema, name, validate=validate)
        problems = problems_of(answer)
        if not problems:
            return answer
        if attempt == reasks:
            break
        client.stats.reasks += 1
        msgs = msgs + [
            {"role": "assistant", "content": answer.model_dump_json()},
            {
                "role": "user",
                "content": "That answer does not fit the request: " + "; ".join(problems)
                + ". Answer again with only a corrected JSON object.",
            },
        ]
    raise SemanticCheckError(
        f"{name}: the answer does not fit the request after {reasks + 1} attempts: " + "; ".join(problems)
    )


# ----- 1. decomposition ------------------------------------------------------------------------------
class TaskFields(BaseModel):
    """A base task as the LLM states it (words or types; grounded afterwards)."""

    id: str = Field(max_length=12)
    text: str = Field(default="", max_length=MAX_TEXT)
    kind: Kind
    object: str = Field(max_length=MAX_WORD)
    count: int = Field(default=1, ge=1, le=2)
    sliced: bool = False
    container: str | None = Field(default=None, max_length=MAX_WORD)
    receptacle: str | None = Field(default=None, max_length=MAX_WORD)
    light: str | None = Field(default=None, max_length=MAX_WORD)
    state: State | None = None  # set_state only

    @model_validator(mode="after")
    def _fields_of_kind(self) -> TaskFields:
        if self.kind == "set_state":
            if self.state is None:
                raise ValueError(f"task {self.id}: set_state needs a state (on, off, broken, ...)")
            return self
        if self.kind == "examine_in_light" and not self.light:
            raise ValueError(f"task {self.id}: examine_in_light needs a light (the lamp)")
        if self.kind != "examine_in_light" and not self.receptacle:
            raise ValueError(f"task {self.id}: kind {self.kind} needs a receptacle")
        if self.kind == "place_in_container" and not self.container:
            raise ValueError(f"task {self.id}: place_in_container needs a container")
        if self.kind == "place_two":
            self.count = 2
        return self


class DecompNode(BaseModel):
    """A top-level node: a base task (kind, object ...) or a group of base tasks (subtasks)."""

    id: str = Field(max_length=12)
    text: str = Field(default="", max_length=MAX_TEXT)
    kind: Kind | None = None
    object: str | None = Field(default=None, max_length=MAX_WORD)
    count: int = Field(default=1, ge=1, le=2)
    sliced: bool = False
    container: str | None = Field(default=None, max_length=MAX_WORD)
    receptacle: str | None = Field(default=None, max_length=MAX_WORD)
    light: str | None = Field(default=None, max_length=MAX_WORD)
    state: State | None = None
    subtasks: list[TaskFields] = Field(default_factory=list, max_length=MAX_TASKS)

    @model_validator(mode="after")
    def _task_or_group(self) -> DecompNode:
        if not self.subtasks and (self.kind is None or not self.object):
            raise ValueError(
                f"node {self.id}: give either kind and object (a base task) or subtasks (a group)"
            )
        if not self.subtasks:
            TaskFields.model_validate(self.model_dump(exclude={"subtasks"}))
        return self

    def as_task(self) -> TaskFields:
        return TaskFields.model_validate(self.model_dump(exclude={"subtasks"}))


# the actions a negation forbids (`negations`), as the LLM names them ("use": every action on the thing)
CONSTRAINT_VERBS = ("put", *ALL_VERBS, "use", *STATE_VERBS)


class ConstraintWords(BaseModel):
    """A negation as the LLM states it ("never open the fridge"): the words, the forbidden action on an
    object (and place, for put), and the task id whose completion lifts it (until-guards)."""

    text: str = Field(max_length=MAX_TEXT)
    verb: str = Field(json_schema_extra={"enum": list(CONSTRAINT_VERBS)})
    object: str = Field(max_length=MAX_WORD)
    receptacle: str | None = Field(default=None, max_length=MAX_WORD)
    until: str | None = Field(default=None, max_length=12)

    # what the coverage check reads of a task (`semantic_check.TaskWords`): its object and receptacle
    @property
    def kind(self) -> str:
        return "constraint"

    @property
    def sliced(self) -> bool:
        return False

    @property
    def container(self) -> str | None:
        return None

    @property
    def light(self) -> str | None:
        return None

    @field_validator("verb")
    @classmethod
    def _known_verb(cls, verb: str) -> str:
        if verb not in CONSTRAINT_VERBS:
            raise ValueError(f"constraint verb {verb!r}: use one of {', '.join(CONSTRAINT_VERBS)}")
        return verb


class Decomposition(BaseModel):
    tasks: list[DecompNode] = Field(max_length=MAX_TASKS)
    constraints: list[ConstraintWords] = Field(default_factory=list, max_length=MAX_TASKS)

    @model_validator(mode="after")
    def _says_something(self) -> Decomposition:
        # no task is an answer only when the instruction only says what not to do
        if not self.tasks and not self.constraints:
            raise ValueError("the answer names no task and no constraint")
        return self

    @field_validator("tasks")
    @classmethod
    def _numbering(cls, tasks: list[DecompNode]) -> list[DecompNode]:
        for k, t in enumerate(tasks, 1):
            t.id = f"1.{k}"
            for j, s in enumerate(t.subtasks, 1):
                s.id = f"1.{k}.{j}"
        return tasks


def decomposition_tasks(dec: Decomposition) -> list[TaskFields]:
    """Every base task of a decomposition (group members and single tasks)."""
    return [t for n in dec.tasks for t in (n.subtasks or [n.as_task()])]


def decompose(client: LLMClient, instruction: str, objects: list[str]) -> Decomposition:
    """The first stage of an instruction: starts the client's per-instruction deadline."""
    client.start_instruction()
    msgs = load_prompt("decompose").messages(
        instruction=instruction, objects=", ".join(objects) or "(unknown)"
    )
    return ask_checked(
        client,
        msgs,
        Decomposition,
        "decomposition",
        lambda dec: semantic_check.decomposition_problems(
            instruction, [*decomposition_tasks(dec), *dec.constraints]
        ),
    )


# ----- 2. relations -----------------------------------------------------------------------------------
class Relations(BaseModel):
    relations: list[tuple[NodeId, NodeId]] = Field(max_length=MAX_TASKS * 3)


def relations(
    client: LLMClient, instruction: str, parent: str, parent_text: str, children: list[tuple[str, str]]
) -> list[tuple[str, str]]:
    ids = [c for c, _ in children]

    def check(ans: Relations) -> None:
        for a, b in ans.relations:
            bad = [x for x in (a, b) if x not in ids]
            if bad:
                raise ValueError(f"unknown subtask id(s) {bad}; use only {ids}")
            if a == b:
                raise ValueError(f"[{a}, {b}] relates a task to itself")

    def cycle(ans: Relations) -> list[str]:
        problem = semantic_check.cycle_problem(ans.relations)
        return [problem] if problem else []

    msgs = load_prompt("relations").messages(
        instruction=instruction,
        parent=f"{parent}: {parent_text}",
        children="\n".join(f"{c}: {t}" for c, t in children),
    )
    ans = ask_checked(client, msgs, Relations, f"relations of {parent}", cycle, validate=check)
    return [(a, b) for a, b in ans.relations]


# ----- 3. logical search: rephrase + translate ----------------------------------------------------------
class Rephrased(BaseModel):
    sentences: list[str] = Field(min_length=1, max_length=MAX_TASKS * 3)

    @field_validator("sentences")
    @classmethod
    def _short(cls, v: list[str]) -> list[str]:
        if any(len(x) > MAX_TEXT for x in v):
            raise ValueError(f"keep each sentence under {MAX_TEXT} characters")
        return v


class Translation(BaseModel):
    ltl: str = Field(min_length=1, max_length=2000)


def prop_name(node_id: str) -> str:
    """The lifted proposition of a child: "1.2" -> "task1_2"."""
    return "task" + node_id.replace(".", "_")


def rephrase(client: LLMClient, children: list[str], rels: list[tuple[str, str]]) -> list[str]:
    msgs = load_prompt("rephrase").messages(
        children=", ".join(children), relations=json.dumps([list(r) for r in rels])
    )
    return client.ask(msgs, Rephrased, "rephrasing").sentences


def translate(
    client: LLMClient, sentences: list[str], children: list[str], feedback: str | None = None
) -> str:
    names = [prop_name(c) for c in children]

    def check(ans: Translation) -> None:
        used = set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", ans.ltl)) - {
            "F",
            "G",
            "X",
            "U",
            "R",
            "W",
            "M",
            "true",
            "false",
        }
        unknown = sorted(used - set(names))
        if unknown:
            raise ValueError(f"unknown propositions {unknown}; use only {names}")

    msgs = load_prompt("translate").messages(
        names=", ".join(names), sentences=" ".join(s.rstrip(".") + "." for s in sentences)
    )
    if feedback:
        msgs.append({"role": "user", "content": feedback})
    return client.ask(msgs, Translation, "translation", validate=check).ltl


# ----- 4. action completion -----------------------------------------------------------------------------
ACTION_VOCABULARY = ACTION_ARITY  # verb -> number of object arguments
VOCABULARY_TEXT = "\n".join(
    [
        "- pickup(O): pick up an object of type O (hand empty)",
        "- put(O,R): put the held O into/onto receptacle R",
        "- open(R) / close(R): open / close an openable object",
        "- toggle_on(O) / toggle_off(O): switch a lamp, faucet, microwave ...",
        "- slice(O): slice O while holding a Knife or ButterKnife; the pieces have type OSliced",
    ]
)


def _action(text: str) -> Atom | None:
    """An action on object types (letters only: no instance names) with one or two arguments, or None."""
    atom = Atom.read(text)
    ok = atom is not None and len(atom.args) <= 2 and all(x.isalpha() for x in atom.args)
    return atom if ok else None



class Actions(BaseModel):
    actions: list[str] = Field(min_length=1, max_length=30)

    @field_validator("actions")
    @classmethod
    def _short(cls, v: list[str]) -> list[str]:
        if any(len(x) > 2 * MAX_WORD + 12 for x in v):
            raise ValueError("an action is verb(Type) or put(Type,Type)")
        return v


def check_actions(actions: list[str], scene_types: set[str] | None, scene: str = "the scene") -> None:
    """ValueError naming the first malformed action or unknown type."""
    for a in actions:
        m = _action(a)
        if m is None or m.verb not in ACTION_VOCABULARY:
            raise ValueError(
                f"{a!r} is not an action; use only {sorted(ACTION_VOCABULARY)} as verb(Type) or "
                "put(Type,Type)"
            )
        args = list(m.args)
        if len(args) != ACTION_VOCABULARY[m.verb]:
            raise ValueError(f"{a!r}: {m.verb} takes {ACTION_VOCABULARY[m.verb]} argument(s)")
        if scene_types is not None:
            for t in args:
                if t not in scene_types:
                    raise ValueError(f"no {t} in {scene}; use only the scene's object types")


def complete_actions(
    client: LLMClient, leaf_text: str, details: dict, scene_types: set[str] | None, scene: str = "the scene"
) -> list[str]:
    objects = sorted(t for t in (scene_types or set()) if not t.endswith("Sliced")) if scene_types else []
    msgs = load_prompt("actions").messages(
        task=leaf_text,
        details=json.dumps(details),
        vocabulary=VOCABULARY_TEXT,
        objects=", ".join(objects) or "(any)",
    )

    def fits(a: Actions) -> list[str]:
        return semantic_check.action_problems([x.replace(" ", "") for x in a.actions], details, scene_types)

    ans = ask_checked(
        client,
        msgs,
        Actions,
        f"actions of {details.get('id', 'leaf')}",
        fits,
        validate=lambda a: check_actions([x.replace(" ", "") for x in a.actions], scene_types, scene),
    )
    return [a.replace(" ", "") for a in ans.actions]
