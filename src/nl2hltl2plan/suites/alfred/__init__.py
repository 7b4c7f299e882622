"""The ALFRED benchmark (the paper's Table I): ground truth, oracle and language jobs, the report, and the
language stage's measurement drivers on ALFRED's own validation splits."""
