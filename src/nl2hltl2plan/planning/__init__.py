"""Planning: simultaneous task allocation and planning for robot teams under hierarchical sc-LTL.

Entry points: `plan(world, spec, starts, objective="min", mode="fast", timeout_s=300.0)` ->
`PlanResult` (status a `PlanStatus`), `validate(world, spec, plan)` -> `Validation` (execute a plan
and judge it against the spec), and `oracle_spec(gt, world)` (the spec a perfect translator would
give for a benchmark instance). See docs/planning.md.
"""

from __future__ import annotations

from nl2hltl2plan.planning.api import plan
from nl2hltl2plan.planning.oracle import OracleSpec, oracle_spec
from nl2hltl2plan.planning.results import PlanResult, PlanStatus, Validation, validate

__all__ = ["OracleSpec", "PlanResult", "PlanStatus", "Validation", "oracle_spec", "plan", "validate"]
