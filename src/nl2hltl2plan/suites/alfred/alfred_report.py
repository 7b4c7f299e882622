"""The end-to-end benchmark report: DIR/report.md with the paper's Table I and Table IV layouts,
for all instances and for the clean ones (feasible and unambiguous), plus plots.

Rates follow the paper's Table I: per (base tasks, robots) row, the overall success rate over all
scenarios of the row, then in parentheses the conversion rate (the generated spec's base tasks and
order match the ground truth) and the planning rate (a plan found, among the converted scenarios).
Travel cost and completion time are mean ± std over the successful scenarios.
"""

from __future__ import annotations

import statistics
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from nl2hltl2plan.io import save_figure, write_text  # noqa: E402
from nl2hltl2plan.suites.alfred.alfred_language import STAGES  # noqa: E402
from nl2hltl2plan.suites.rows import ScenarioRow  # noqa: E402
from nl2hltl2plan.suites.summaries import paper_table1, percentile, summarize  # noqa: E402


def _rate(num: int, den: int) -> float | None:
    return round(num / den, 4) if den else None


def pipeline_summary(rows: Sequence[ScenarioRow]) -> dict[str, Any]:
    """`report.summarize` plus conversion and planning rates per row and overall."""
    summary = summarize(rows)
    groups: dict[tuple[int, int], list[ScenarioRow]] = {}
    for r in rows:
        groups.setdefault((r.n_base, r.robots), []).append(r)
    for row in summary["rows"]:
        grp = groups[(row["n_base"], row["robots"])]
        row.update(_rates(grp))
    summary.update(_rates(rows))
    summary["failures"] = failure_breakdown(rows)
    return summary


def _rates(rows: Sequence[ScenarioRow]) -> dict[str, Any]:
    converted = [r for r in rows if r.conversion_ok]
    return {
        "conversion_rate": _rate(len(converted), len(rows)),
        # part of the instruction not understood (refused by `plan`; a conversion failure here)
        "partial_rate": _rate(sum(1 for r in rows if r.partial), len(rows)),
        "planning_rate": _rate(sum(1 for r in converted if r.planning_ok), len(converted)),
        "overall_rate": _rate(sum(1 for r in rows if r.success), len(rows)),
    }


def failure_breakdown(rows: Sequence[ScenarioRow]) -> dict[str, Any]:
    """Failed scenarios by the first stage that went wrong (Table IV plus planning and execution)."""
    counts = {s: 0 for s in STAGES}
    for r in rows:
        if not r.success and r.stage:
            counts[r.stage] = counts.get(r.stage, 0) + 1
    return {
        "scenarios": len(rows),
        "counts": counts,
        "rates": {s: _rate(c, len(rows)) for s, c in counts.items()},
    }


def _pct(x: float | None) -> str:
    return "-" if x is None else f"{100 * x:.0f}"


def _pm(mean: float | None, std: float | None) -> str:
    return "-" if mean is None else f"{mean:.1f} ± {std:.1f}"


def table1_markdown(summary: dict[str, Any]) -> str:
    paper = paper_table1()
    lines = [
        "| tasks-robots | scenarios | ours: overall (conversion, planning) % | travel (m) "
        "| completion (steps) | paper: overall (conv, PL) % | paper travel (m) | paper completion "
        "| paper SMART-LLM % |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for r in summary["rows"]:
        p = paper.get((r["n_base"], r["robots"]))
        ours = f"**{_pct(r['overall_rate'])}** ({_pct(r['conversion_rate'])}, {_pct(r['planning_rate'])})"
        theirs = ["-"] * 4
        if p:
            o = p["ours"]
            theirs = [
                f"{o['success']} ({o['conversion']}, {o['planning']})",
                _pm(*o["travel_m"]),
                _pm(*o["steps"]),
                str(p["smartllm"]["success"]),
            ]
        lines.append(
            f"| {r['n_base']}-{r['robots']} | {r['scenarios']} | {ours} | "
            f"{_pm(r['travel_m_mean'], r['travel_m_std'])} | {_pm(r['steps_mean'], r['steps_std'])} | "
            + " | ".join(theirs)
            + " |"
        )
    lines.append(
        f"| all | {summary['scenarios']} | **{_pct(summary['overall_rate'])}** "
        f"({_pct(summary['conversion_rate'])}, {_pct(summary['planning_rate'])}) | | | | | | |"
    )
    lines.append(
        f"\nPartly understood instructions (refused by `plan`, conversion failures here): "
        f"{_pct(summary['partial_rate'])} % of the scenarios."
    )
    return "\n".join(lines)


def failures_markdown(summary: dict[str, Any]) -> str:
    f = summary["failures"]
    lines = ["| first failing stage | scenarios | % of all scenarios |", "| --- | --- | --- |"]
    for stage in STAGES:
        lines.append(f"| {stage} | {f['counts'].get(stage, 0)} | {100 * (f['rates'].get(stage) or 0):.1f} |")
    return "\n".join(lines)


def _team(k: int) -> str:
    return f"{k} robot" if k == 1 else f"{k} robots"


def _integer_x(ax, xs: Sequence[int]) -> None:
    """Whole numbers of base tasks only, with half a unit of room either side."""
    if xs:
        ax.set_xticks(range(min(xs), max(xs) + 1))
        ax.set_xlim(min(xs) - 0.5, max(xs) + 0.5)


def plot_success(summaries: dict[str, dict[str, Any]], out: Path) -> None:
    """Overall success vs number of base tasks, one line per team size (paper dashed)."""
    paper = paper_table1()
    fig, axes = plt.subplots(1, len(summaries), figsize=(5.5 * len(summaries), 4), squeeze=False)
    for ax, (name, summary) in zip(axes[0], summaries.items(), strict=True):
        robots = sorted({r["robots"] for r in summary["rows"]})
        all_x: list[int] = []
        for j, (k, color) in enumerate(
            zip(robots, ["tab:blue", "tab:orange", "tab:green", "tab:red"], strict=False)
        ):
            rows = sorted((r for r in summary["rows"] if r["robots"] == k), key=lambda r: r["n_base"])
            xs = [r["n_base"] for r in rows]
            all_x += xs
            shift = 0.06 * (j - (len(robots) - 1) / 2)  # equal rates of two teams stay visible
            ys = [100 * (r["overall_rate"] or 0) for r in rows]
            ax.plot([x + shift for x in xs], ys, "o-", color=color, label=f"ours, {_team(k)}")
            px = [n for n in xs if (n, k) in paper]
            if px:
                ax.plot([x + shift for x in px], [paper[(n, k)]["ours"]["success"] for n in px], "s--",
                        color=color, alpha=0.5, label=f"paper, {_team(k)}")  # fmt: skip
        _integer_x(ax, all_x)
        ax.set_xlabel("base tasks per instruction")
        ax.set_ylabel("overall success (%)")
        ax.set_ylim(0, 105)
        ax.set_title(name)
        ax.grid(alpha=0.3)
        if robots:
            ax.legend(fontsize=7)
    fig.tight_layout()
    save_figure(fig, out, dpi=110)
    plt.close(fig)


def _spread(
    summary_row: dict[str, Any], values: list[float] | None, metric: str
) -> tuple[float, float, float] | None:
    """(centre, below, above) of one point: median with the 10th-90th percentile range of the
    successful scenarios' values when known, else mean ± std cut at zero (no negative metres)."""
    if values:
        mid = statistics.median(values)
        return mid, mid - percentile(values, 10), percentile(values, 90) - mid
    mean, std = summary_row.get(f"{metric}_mean"), summary_row.get(f"{metric}_std")
    if mean is None:
        return None
    return mean, min(std or 0.0, mean), std or 0.0


def _points(
    summary: dict[str, Any], rows: Sequence[ScenarioRow] | None, team: int, metric: str
) -> list[tuple[int, float, float, float]]:
    """(base tasks, centre, below, above) per summary row of this team size that has successes."""
    pts = []
    for r in sorted((r for r in summary["rows"] if r["robots"] == team), key=lambda r: r["n_base"]):
        vals = None
        if rows is not None:
            vals = [
                float(getattr(x, metric))
                for x in rows
                if x.success
                and x.robots == team
                and x.n_base == r["n_base"]
                and getattr(x, metric) is not None
            ]
        spread = _spread(r, vals, metric)
        if spread is not None:
            pts.append((r["n_base"], *spread))
    return pts


def plot_cost_time(summary: dict[str, Any], out: Path, rows: Sequence[ScenarioRow] | None = None) -> None:
    """Travel cost and completion time vs base tasks per team size. With `rows`: medians with
    10th-90th percentile bars over the successful scenarios (asymmetric, inside the data); without:
    mean ± std with the lower bar cut at zero."""
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    teams = sorted({r["robots"] for r in summary["rows"]})
    all_x: list[int] = []
    for j, k in enumerate(teams):
        for ax, metric in ((axes[0], "travel_m"), (axes[1], "steps")):
            pts = _points(summary, rows, k, metric)
            if not pts:
                continue
            all_x += [p[0] for p in pts]
            xs = [p[0] + 0.1 * (j - (len(teams) - 1) / 2) for p in pts]  # side by side, same integer tick
            ax.errorbar(xs, [p[1] for p in pts], yerr=[[p[2] for p in pts], [p[3] for p in pts]], fmt="o-",
                        capsize=3, label=_team(k))  # fmt: skip
    stat = "median, bars 10th-90th percentile" if rows is not None else "mean ± std"
    for ax, label in zip(axes, ["travel cost (m)", "completion time (steps)"], strict=True):
        _integer_x(ax, all_x)
        ax.set_xlabel("base tasks per instruction")
        ax.set_ylabel(label)
        ax.set_ylim(bottom=0)
        ax.set_title(f"{label.split(' (')[0]} of successful scenarios ({stat})", fontsize=9)
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend()
    fig.tight_layout()
    save_figure(fig, out, dpi=110)
    plt.close(fig)


def plot_gantt_example(rows: Sequence[ScenarioRow], out: Path) -> ScenarioRow | None:
    """The Gantt chart of one successful scenario (the most robots at work, then the most actions), drawn
    from its row's events; returns that row, or None (nothing drawn) when no scenario succeeded."""
    from nl2hltl2plan.present.gantt import draw_gantt_events

    ok = [r for r in rows if r.success and r.events]
    if not ok:
        return None
    row = max(ok, key=lambda r: (len({e.robot for e in r.events}), len(r.events), r.key))
    title = (
        f"example: {row.instance or row.key}, {_team(row.robots)}, "
        f"travel {row.travel_m or 0:.2f} m, completion {row.steps} steps"
    )
    draw_gantt_events(row.events, row.robots, out, title=title)
    return row


def write_report(
    rows: Sequence[ScenarioRow], out_dir: Path, title: str, command: str, machine: str
) -> dict[str, Any]:
    """Write report.md, summary.json content (returned) and the plots; all and clean subsets."""
    clean_rows = [
        r for r in rows if (r.feasible if r.gt_feasible is None else r.gt_feasible) and not r.ambiguous
    ]
    summary = pipeline_summary(rows)
    clean = pipeline_summary(clean_rows) if clean_rows else None
    summary["clean"] = clean
    times = summary["plan_time_s"]
    plot_success(
        {"all instructions": summary, **({"clean instructions": clean} if clean else {})},
        out_dir / "success_vs_base_tasks.png",
    )
    plot_cost_time(summary, out_dir / "cost_and_time.png", rows=rows)
    n_inst = len({r.instance for r in rows}) or len(rows)
    parts = [
        f"# {title}",
        "",
        f"Command: `{command}`  ",
        f"Machine: {machine}",
        "",
        f"## Table I layout: all {n_inst} instructions ({len(rows)} scenarios)",
        "",
        table1_markdown(summary),
    ]
    if clean:
        n_clean = len({r.instance for r in clean_rows})
        parts += [
            "",
            f"## Clean instructions: feasible and unambiguous ({n_clean} instructions, "
            f"{len(clean_rows)} scenarios)",
            "",
            table1_markdown(clean),
        ]
    parts += [
        "",
        "Overall = the executed plan meets every ground-truth goal and order (goal checker), over all "
        "scenarios of the row; conversion = generated base tasks within the accepted types and the same "
        "closure of `before`; planning = a checked plan found, among converted scenarios (the paper's PL). "
        "Travel and completion: mean ± std over successful scenarios. Paper columns: the paper's Table I "
        "(GPT-4 and its planner; SMART-LLM = its baseline).",
        "",
        "## Failures by stage (Table IV layout, all scenarios)",
        "",
        failures_markdown(summary),
        "",
        f"Planning time per scenario (s): median {times['median']}, p95 {times['p95']}, max {times['max']}.",
        "",
        "![success](success_vs_base_tasks.png)",
        "",
        "![cost and time](cost_and_time.png)",
        "",
    ]
    example = plot_gantt_example(rows, out_dir / "gantt_example.png")
    if example is not None:
        parts += [
            f"An example plan over time ({example.key}):",
            "",
            "![an example plan](gantt_example.png)",
            "",
        ]
    write_text(out_dir / "report.md", "\n".join(parts), "report")
    return summary


def machine_description() -> str:
    import os
    import platform

    cores = os.cpu_count()
    return f"{platform.system()} {platform.machine()}, {cores} cores, Python {platform.python_version()}"
