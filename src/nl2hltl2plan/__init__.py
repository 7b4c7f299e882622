"""Nl2Hltl2Plan: natural language -> Hierarchical Task Tree -> hierarchical sc-LTL -> multi-robot plan."""

__version__ = "0.1.0"
