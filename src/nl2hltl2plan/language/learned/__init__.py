"""The learned language backend: the grammar's clauses and relations, a slot model trained on ALFRED."""

from nl2hltl2plan.language.learned.inference import LearnedParse, Policy, parse_instruction

__all__ = ["LearnedParse", "Policy", "parse_instruction"]
