"""The default offline backend on the benchmark (needs ../shared/data): floors on the measured rates."""

from __future__ import annotations

import pytest

from nl2hltl2plan.suites.alfred.conversion import evaluate, load_benchmark, offline_generator, table

pytestmark = pytest.mark.data


def test_offline_match_rates_on_the_benchmark(shared_data):
    rows = load_benchmark()
    assert len(rows) == 200
    records = evaluate(rows, offline_generator)
    by_n = {n: [r for r in records if r["n_base"] == n] for n in (1, 2, 3, 4)}
    rate = {n: sum(r["ok"] for r in rs) / len(rs) for n, rs in by_n.items()}
    # a refused or partial conversion (issue 23) is a failure: measured 88 / 72 / 48 / 48 % here
    # (results/language_trust/report.md); keep a margin
    assert rate[1] >= 0.82 and rate[2] >= 0.66 and rate[3] >= 0.42 and rate[4] >= 0.42, rate
    assert sum(r["ok"] for r in records) / len(records) >= 0.6
    clean = [r for r in records if r["clean"]]
    assert len(clean) == 150 and sum(r["ok"] for r in clean) / len(clean) >= 0.66
    assert "| all | 200 |" in table(records)
    assert all(not r["error"] for r in records if r["ok"])
