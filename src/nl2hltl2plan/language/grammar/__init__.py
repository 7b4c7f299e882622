"""The offline backend: a deterministic grammar-based parser (no model, no network)."""

from nl2hltl2plan.language.grammar.parser import OfflineParse, parse_instruction

__all__ = ["OfflineParse", "parse_instruction"]
