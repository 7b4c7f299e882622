"""Conversion scoring: do generated base tasks and their order match the benchmark ground truth?

A generated task matches a ground-truth task when the kinds are equal, the count and `sliced` agree,
and every type the generated task would accept for the object / container / receptacle / lamp is one
the ground truth accepts (strict, "within the accepted types"; the lenient variant only asks for one
common type). An instruction matches when a one-to-one assignment of generated to ground-truth tasks
exists under which both `before` relations have the same transitive closure.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from itertools import permutations
from typing import Any

from pydantic import BaseModel, Field

from nl2hltl2plan.language.task_specs import BaseTaskSpec, transitive_closure


class MatchResult(BaseModel):
    tasks_ok: bool  # a one-to-one field match exists
    order_ok: bool  # ... and under one of them the closures agree (implies tasks_ok)
    mapping: dict[str, str] = Field(default_factory=dict)  # generated id -> ground-truth id
    reasons: list[str] = Field(default_factory=list)

    @property
    def ok(self) -> bool:
        return self.order_ok


def _within(pred: Sequence[str] | None, gt: Sequence[str] | None, strict: bool) -> bool:
    if not gt:
        return not pred
    if not pred:
        return False
    return set(pred) <= set(gt) if strict else bool(set(pred) & set(gt))


def task_problems(pred: BaseTaskSpec, gt: BaseTaskSpec, strict: bool = True) -> list[str]:
    """Why `pred` does not match `gt` (empty list: it matches)."""
    out = []
    if pred.kind != gt.kind:
        out.append(f"kind {pred.kind} != {gt.kind}")
    if not _within(pred.object, gt.object, strict):
        out.append(f"object {pred.object} not within {gt.object}")
    if pred.count != gt.count:
        out.append(f"count {pred.count} != {gt.count}")
    if pred.sliced != gt.sliced:
        out.append(f"sliced {pred.sliced} != {gt.sliced}")
    if gt.kind == "place_in_container" and not _within(pred.container, gt.container, strict):
        out.append(f"container {pred.container} not within {gt.container}")
    if gt.kind == "examine_in_light":
        if not _within(pred.light, gt.light, strict):
            out.append(f"light {pred.light} not within {gt.light}")
    elif not _within(pred.receptacle, gt.receptacle, strict):
        out.append(f"receptacle {pred.receptacle} not within {gt.receptacle}")
    return out


def _as_specs(tasks: Iterable[Any]) -> list[BaseTaskSpec]:
    return [t if isinstance(t, BaseTaskSpec) else BaseTaskSpec.model_validate(t) for t in tasks]


def match(
    pred_tasks: Iterable[Any],
    pred_before: Iterable[Sequence[str]],
    gt_tasks: Iterable[Any],
    gt_before: Iterable[Sequence[str]],
    strict: bool = True,
) -> MatchResult:
    """Compare generated tasks/order with the ground truth (tasks as BaseTaskSpec or GT dicts)."""
    pred = _as_specs(pred_tasks)
    gt = _as_specs(gt_tasks)
    pb = {(a, b) for a, b in pred_before}
    gb = {(a, b) for a, b in gt_before}
    if len(pred) != len(gt):
        return MatchResult(
            tasks_ok=False,
            order_ok=False,
            reasons=[f"{len(pred)} tasks generated, {len(gt)} in the ground truth"],
        )
    ok = [[not task_problems(p, g, strict) for g in gt] for p in pred]
    gt_closure = transitive_closure(gb, [g.id for g in gt])
    found_tasks = False
    best: dict[str, str] = {}
    candidates: Iterator[tuple[int, ...]] = (
        permutations(range(len(gt))) if len(pred) <= 8 else iter([tuple(range(len(gt)))])  # large: greedy
    )
    for perm in candidates:
        if not all(ok[i][perm[i]] for i in range(len(pred))):
            continue
        found_tasks = True
        mapping = {pred[i].id: gt[perm[i]].id for i in range(len(pred))}
        best = best or mapping
        mapped = {(mapping[a], mapping[b]) for a, b in pb if a in mapping and b in mapping}
        if transitive_closure(mapped, [g.id for g in gt]) == gt_closure:
            return MatchResult(tasks_ok=True, order_ok=True, mapping=mapping)
    if not found_tasks:
        reasons = []
        for p in pred:
            probs = [task_problems(p, g, strict) for g in gt]
            if all(probs):
                best_g = min(range(len(gt)), key=lambda j: len(probs[j]))
                reasons.append(f"{p.id} ({p.summary()}) vs {gt[best_g].id}: " + "; ".join(probs[best_g]))
        return MatchResult(
            tasks_ok=False, order_ok=False, reasons=reasons or ["no one-to-one task assignment"]
        )
    mapped_pairs = sorted((best[a], best[b]) for a, b in pb if a in best and b in best)
    return MatchResult(
        tasks_ok=True,
        order_ok=False,
        mapping=best,
        reasons=[f"order {mapped_pairs} (closure differs from ground truth {sorted(gb)})"],
    )
