"""GenerateLTL by an LLM or a learned translator (rephrase + translate per non-leaf node), every
answer checked for equivalence against the exact relation compiler: a difference is reported and
re-asked once with the witness trace, then the compiler's formula is used (the closed loop the
paper lists as missing)."""

from __future__ import annotations

import re
from collections.abc import Sequence

from nl2hltl2plan.config.llm_settings import translator_settings
from nl2hltl2plan.errors import FormulaError
from nl2hltl2plan.language import stages
from nl2hltl2plan.language.llm.client import LLMClient
from nl2hltl2plan.language.spec_builder import GenerateLTL
from nl2hltl2plan.logic.relations import check_translation, compile_relations


def translator_client() -> LLMClient:
    """The learned translator (the paper's fine-tuned model over lifted sentences), served by any
    OpenAI-compatible server: NL2HLTL2PLAN_TRANSLATOR_BASE_URL / _MODEL / _API_KEY."""

    settings = translator_settings()
    return LLMClient(settings)


def lifted_sentences(children: list[str], relations: list[tuple[str, str]]) -> list[str]:
    """Deterministic rephrasing of children + relations into lifted sentences (no LLM needed)."""
    out = [f"task {a} must be completed before task {b}" for a, b in relations]
    free = [c for c in children if not any(c in r for r in relations)]
    out += [f"task {c} can be completed at any time" for c in free]
    return out or [f"complete task {children[0]}"]


def _node_id(name: str) -> str:
    return name[4:] if name.startswith("task") else name


def llm_generate_ltl(client: LLMClient | None, translator: LLMClient, notes: list[str]) -> GenerateLTL:
    """GenerateLTL of Algorithm 1 by an LLM or learned translator (rephrase + translate), each answer
    checked against the exact compiler; a difference is reported and re-asked once with the witness
    trace, then the compiler's formula is used (the closed loop the paper lists as missing)."""

    def generate(children: Sequence[str], relations: Sequence[tuple[str, str]]) -> str:
        names = list(children)
        ids = [_node_id(c) for c in names]
        rels = [(_node_id(a), _node_id(b)) for a, b in relations]
        lifted = {stages.prop_name(i): n for i, n in zip(ids, names, strict=True)}
        sentences = stages.rephrase(client, ids, rels) if client is not None else lifted_sentences(ids, rels)
        feedback = None
        for attempt in range(2):
            text = stages.translate(translator, sentences, ids, feedback=feedback)
            candidate = _unlift(text, lifted)
            try:
                check = check_translation(candidate, names, list(relations))
            except FormulaError as exc:
                notes.append(f"{'/'.join(ids)}: translation {text!r} rejected: {exc}")
                feedback = f"Your formula {text} is not valid sc-LTL over the given propositions: {exc}"
                continue
            if check.equivalent:
                return check.candidate
            notes.append(f"{'/'.join(ids)}: {check.describe()}")
            feedback = (
                f"Your formula {text} does not match the constraints {rels}: {check.describe()}. "
                "Give a corrected formula."
            )
            if attempt == 1:
                break
        notes.append(f"{'/'.join(ids)}: using the compiler's formula")
        return compile_relations(names, list(relations))

    return generate


def _unlift(text: str, names: dict[str, str]) -> str:
    return re.sub(r"task\d+(?:_\d+)*", lambda m: f'"{names.get(m.group(0), m.group(0))}"', text)
