"""What the language stage returns for one instruction (the typed boundary to the pipeline)."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field

from nl2hltl2plan.language.htt import HTT
from nl2hltl2plan.language.task_specs import BaseTaskSpec, ConstraintSpec
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec, LeafOrFormula, format_spec


class Ambiguity(BaseModel):
    """A word that several scene types fit, ranked: the first candidate is used unless a user picks."""

    task: str  # base-task id
    role: str  # object / container / receptacle / light
    word: str
    candidates: list[str]
    confidence: list[float] = Field(default_factory=list)  # one per candidate, same order


class LanguageResult(BaseModel):
    """Everything the language stage produced for one instruction: the HTT, the structured base tasks
    next to it (`task_node` / `leaf_task` link them), the leaf actions and the hierarchical spec."""

    model_config = ConfigDict(arbitrary_types_allowed=True)

    backend: str
    instruction: str
    scene: str | None = None
    htt: HTT
    tasks: list[BaseTaskSpec] = Field(default_factory=list)
    before: list[tuple[str, str]] = Field(default_factory=list)  # between base-task ids
    task_node: dict[str, str] = Field(default_factory=dict)  # base-task id -> HTT node id
    leaf_task: dict[str, str] = Field(default_factory=dict)  # HTT leaf id -> base-task id
    leaf_specs: dict[str, LeafOrFormula] = Field(default_factory=dict)  # HTT leaf -> actions or formula
    spec: HierarchicalSpec | None = Field(default=None, exclude=True)
    ltl_checks: list[str] = Field(default_factory=list)  # LLM translations that differed from the compiler
    ambiguities: list[Ambiguity] = Field(default_factory=list)
    unparsed: list[str] = Field(default_factory=list)
    issues: list[str] = Field(default_factory=list)
    warnings: list[str] = Field(default_factory=list)
    # what the text left open and the world's convention read ("'the forks': read as 2 of FloorPlan5's 3,
    # ALFRED's pick-two"): shown with the plan, never silent
    assumptions: list[str] = Field(default_factory=list)
    # the constraints as text, sorted: the negations' "words: formula" beside the spec; on the handover
    # worlds their guards and joint goals
    constraints: list[str] = Field(default_factory=list)
    constraint_specs: list[ConstraintSpec] = Field(default_factory=list)  # the negations, typed
    llm_calls: dict[str, int] = Field(default_factory=dict)

    @property
    def partial(self) -> bool:
        """Part of the instruction was not understood (`unparsed` names it, with the reason)."""
        return bool(self.unparsed)

    @property
    def spec_text(self) -> str | None:
        return format_spec(self.spec) if self.spec is not None else None

    def summary_lines(self) -> list[str]:
        return [f"{t.id} [{self.task_node.get(t.id, '?')}] {t.summary()}" for t in self.tasks]
