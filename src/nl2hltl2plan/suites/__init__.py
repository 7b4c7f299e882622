"""Evaluation: benchmark scenarios, a parallel runner with hard time limits, summaries and tables.

`run_scenarios(scenarios, job, out, workers, hard_timeout_s)` (runner.py) runs any job per scenario;
`alfred.oracle_job(...)` plans from oracle specs; `report.summarize` / `report.format_table` give
summary.json and the Table I printout (paper numbers in paper_table1.json).
"""
