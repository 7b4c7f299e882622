"""The default offline backend on a composed validation set of ours (needs ../shared/data): floors on the
measured rates. Never on test50: the benchmark's test set is measured once per round, by the lead, after
every choice is frozen (docs/evaluation.md), so no test may look at it."""

from __future__ import annotations

import pytest

from nl2hltl2plan.suites.alfred.conversion import evaluate, offline_generator, table
from nl2hltl2plan.suites.alfred.structure_validation import rows_of_set

pytestmark = pytest.mark.data


def test_offline_match_rates_on_a_validation_set_of_ours(shared_data):
    # the benchmark generator's templates over ALFRED valid_unseen annotations (seed 201), 50 per count
    rows = rows_of_set("faithful_unseen:201", 200)
    # 200 drawn, less those holding an annotation whose label names what its text does not (faithful.py)
    assert 160 <= len(rows) <= 200  # 172 since h127
    records = evaluate(rows, offline_generator)
    by_n = {n: [r for r in records if r["n_base"] == n] for n in (1, 2, 3, 4)}
    rate = {n: sum(r["ok"] for r in rs) / len(rs) for n, rs in by_n.items()}
    # a refused or partial conversion (issue 23) is a failure: measured 96 / 86 / 74 / 86 % in session 11
    # (results/language/session11_merged.md); keep a margin of about four instructions per count
    assert rate[1] >= 0.88 and rate[2] >= 0.78 and rate[3] >= 0.66 and rate[4] >= 0.78, rate
    assert sum(r["ok"] for r in records) / len(records) >= 0.8
    assert f"| all | {len(rows)} |" in table(records)
    assert all(not r["error"] for r in records if r["ok"])
