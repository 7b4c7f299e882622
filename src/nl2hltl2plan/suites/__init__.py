"""Benchmark suites, one package each (alfred, smartllm, tabletop, handover), above `pipeline`: each holds
its ground truth or tasks, oracle specs, jobs and report; the modules here are what they share.

`run_scenarios(scenarios, job, out, workers, hard_timeout_s)` (runner.py) runs any job per scenario;
`alfred.alfred_bench.oracle_job(...)` plans from oracle specs; `summaries.summarize` /
`summaries.format_table` give summary.json and the Table I printout (paper numbers in
alfred/paper_table1.json).
"""
