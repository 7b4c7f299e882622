"""Language stage: instruction -> Hierarchical Task Tree -> hierarchical LTL (paper Section III).

Entry point: `pipeline.translate(instruction, world, backend, client)` -> `LanguageResult`; backends
`offline` (grammar parser, `grammar/`), `local` (llama.cpp server, `llm/local_server.py`) and `openai`
(any OpenAI-compatible server, `llm/client.py`). See docs/language.md.
"""
