"""The paper's four-arm handover study (Table III): tasks with written specs, the LLM-as-planner
baseline, the job and the report."""
