"""SMART-LLM's benchmark: its tasks, worlds and oracle specs, the job and SMART-LLM's metrics."""
