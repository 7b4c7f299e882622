"""Summaries of benchmark rows and the Table I style printout (with the paper's numbers beside)."""

from __future__ import annotations

import json
import math
import statistics
from collections.abc import Sequence
from importlib import resources
from typing import Any

from nl2hltl2plan.suites.rows import ScenarioRow


def paper_table1() -> dict[tuple[int, int], dict[str, Any]]:
    """The paper's Table I rows by (n_base, robots)."""
    text = resources.files("nl2hltl2plan.suites.alfred").joinpath("paper_table1.json").read_text()
    return {(r["n_base"], r["robots"]): r for r in json.loads(text)["rows"]}


def percentile(values: Sequence[float], q: float) -> float:
    """Nearest-rank percentile (the smallest value with at least q % of the values at or below)."""
    if not values:
        return float("nan")
    ordered = sorted(values)
    k = max(0, math.ceil(q / 100 * len(ordered)) - 1)
    return ordered[k]


def _median(values: list[float | None]) -> float | None:
    vals = [float(v) for v in values if v is not None]
    return round(statistics.median(vals), 4) if vals else None


def mean_std(values: list[float]) -> tuple[float | None, float | None]:
    """Mean and population standard deviation (None, None for no values)."""
    if not values:
        return None, None
    return statistics.fmean(values), statistics.pstdev(values)


def _mean_std(values: list[float]) -> tuple[float | None, float | None]:
    mean, std = mean_std(values)
    return (None, None) if mean is None or std is None else (round(mean, 3), round(std, 3))


def pm(mean: float | None, std: float | None, digits: int = 1) -> str:
    """"m ± s" for a report table, "—" when nothing was measured."""
    return "—" if mean is None else f"{mean:.{digits}f} ± {(std or 0.0):.{digits}f}"


def summarize(rows: Sequence[ScenarioRow]) -> dict[str, Any]:
    """The summary.json object: counts, planning times, and one row per (n_base, robots)."""
    times = [r.plan_time_s for r in rows if r.plan_time_s is not None]
    feasible = [r for r in rows if r.feasible]
    groups: dict[tuple[int, int], list[ScenarioRow]] = {}
    for r in rows:
        groups.setdefault((r.n_base, r.robots), []).append(r)
    table = []
    for (n, k), grp in sorted(groups.items()):
        ok = [r for r in grp if r.success]
        feas = [r for r in grp if r.feasible]
        travel = _mean_std([r.travel_m for r in ok if r.travel_m is not None])
        steps = _mean_std([float(r.steps) for r in ok if r.steps is not None])
        table.append(
            {
                "n_base": n,
                "robots": k,
                "scenarios": len(grp),
                "feasible": len(feas),
                "solved": sum(1 for r in grp if r.status == "solved"),
                "success": len(ok),
                "success_rate": round(len(ok) / len(feas), 4) if feas else None,
                "success_rate_all": round(len(ok) / len(grp), 4) if grp else None,
                "travel_m_mean": travel[0],
                "travel_m_std": travel[1],
                "steps_mean": steps[0],
                "steps_std": steps[1],
                "plan_time_s_median": _median([r.plan_time_s for r in grp]),
            }
        )
    statuses: dict[str, int] = {}
    for r in rows:
        statuses[r.status] = statuses.get(r.status, 0) + 1
    infeasible_right = sum(1 for r in rows if not r.feasible and r.status == "infeasible")
    return {
        "scenarios": len(rows),
        "feasible": len(feasible),
        "solved": sum(1 for r in rows if r.status == "solved"),
        "success": sum(1 for r in rows if r.success),
        "feasible_success": sum(1 for r in feasible if r.success),
        "errored": sum(1 for r in rows if r.status == "error" or r.killed),
        "partial": sum(1 for r in rows if r.partial),  # part of the instruction not understood (a failure)
        "infeasible_reported": infeasible_right,
        "statuses": statuses,
        "plan_time_s": {
            "median": round(statistics.median(times), 4) if times else None,
            "p95": round(percentile(times, 95), 4) if times else None,
            "max": round(max(times), 4) if times else None,
            "mean": round(statistics.fmean(times), 4) if times else None,
        },
        "rows": table,
    }


def _pm(mean: float | None, std: float | None) -> str:
    return "-" if mean is None else f"{mean:.1f}±{std:.1f}"


def format_table(summary: dict[str, Any], title: str = "") -> str:
    """Table I layout: ours (oracle specs, so planning alone) beside the paper's HLTL planner."""
    paper = paper_table1()
    lines = []
    if title:
        lines.append(title)
    head = (
        f"{'tasks-robots':>12} {'feasible':>8} {'success':>8} {'rate %':>7} {'travel (m)':>11} "
        f"{'completion':>11} | {'paper PL %':>10} {'travel (m)':>11} {'completion':>11}"
    )
    lines += [head, "-" * len(head)]
    for r in summary["rows"]:
        p = paper.get((r["n_base"], r["robots"]))
        rate = "-" if r["success_rate"] is None else f"{100 * r['success_rate']:.1f}"
        label = f"{r['n_base']}-{r['robots']}"
        ours = (
            f"{label:>12} {r['feasible']:>8} {r['success']:>8} {rate:>7} "
            f"{_pm(r['travel_m_mean'], r['travel_m_std']):>11} "
            f"{_pm(r['steps_mean'], r['steps_std']):>11}"
        )
        if p:
            o = p["ours"]
            theirs = f"{o['planning']:>10} {_pm(*o['travel_m']):>11} {_pm(*o['steps']):>11}"
        else:
            theirs = f"{'':>10} {'':>11} {'':>11}"
        lines.append(f"{ours} | {theirs}")
    t = summary["plan_time_s"]
    lines.append("-" * len(head))
    lines.append(
        f"scenarios {summary['scenarios']}, feasible {summary['feasible']}, solved {summary['solved']}, "
        f"success {summary['success']} "
        f"(feasible and checked: {summary['feasible_success']}/{summary['feasible']}), "
        f"infeasible reported {summary['infeasible_reported']}"
    )
    lines.append(
        f"planning time s: median {t['median']}, p95 {t['p95']}, max {t['max']} "
        f"(statuses {summary['statuses']})"
    )
    lines.append(
        "paper PL % = the paper's planning success rate (its planner on its own converted specs);"
        " rate % here = success / feasible"
    )
    return "\n".join(lines)
