"""Prompt files of the four LLM stages (Markdown with `## system`, `## example` / `### user` /
`### assistant`, and a final `## user` template with `$placeholders`)."""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache
from importlib import resources
from string import Template

from nl2hltl2plan.errors import LLMError

STAGES = ("decompose", "relations", "rephrase", "translate", "actions")


@dataclass(frozen=True)
class Prompt:
    name: str
    system: Template
    examples: tuple[tuple[str, str], ...]
    user: Template

    def messages(self, **values: object) -> list[dict[str, str]]:
        """Chat messages: system, the few-shot examples as user/assistant turns, then the request."""
        vals = {k: str(v) for k, v in values.items()}
        try:
            msgs = [{"role": "system", "content": self.system.substitute(vals).strip()}]
            for u, a in self.examples:
                msgs += [{"role": "user", "content": u}, {"role": "assistant", "content": a}]
            msgs.append({"role": "user", "content": self.user.substitute(vals).strip()})
        except KeyError as exc:
            raise LLMError(f"prompt {self.name} needs the value {exc}") from None
        return msgs


@cache
def load_prompt(name: str) -> Prompt:
    try:
        text = resources.files(__name__).joinpath(f"{name}.md").read_text()
    except FileNotFoundError:
        raise LLMError(f"no prompt file {name}.md") from None
    text = re.sub(r"<!--.*?-->", "", text, flags=re.S)
    system, user = "", ""
    examples: list[tuple[str, str]] = []
    for block in re.split(r"^## ", text, flags=re.M)[1:]:
        head, _, body = block.partition("\n")
        head = head.strip().lower()
        if head == "system":
            system = body
        elif head == "user":
            user = body
        elif head == "example":
            parts = re.split(r"^### (user|assistant)\s*$", body, flags=re.M)
            turns = dict(zip(parts[1::2], (p.strip() for p in parts[2::2]), strict=False))
            examples.append((turns.get("user", ""), turns.get("assistant", "")))
    if not user:
        raise LLMError(f"prompt {name}.md has no '## user' section")
    return Prompt(name, Template(system), tuple(examples), Template(user))
