"""The learned slot model: one clause of text -> task kind, slot types ranked, sliced.

Features are TF-IDF word 1-2-grams and character 2-5-grams (inside word boundaries, so unseen
spellings and compounds still share pieces); one multinomial logistic regression per output (kind,
object, container, receptacle, light, sliced). At inference the slot distributions are restricted to the
scene's object types and renormalised, which is the grounding: a type the scene lacks is never chosen
while one it has is, and the probabilities are the confidence reported with ambiguous words.
"""

from __future__ import annotations

import gzip
import pickle
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from nl2hltl2plan.errors import DataError
from nl2hltl2plan.language.learned.data import SLOTS, Example

ARTIFACT = "slot_model.pkl.gz"
FORMAT = 1
HEADS = ("kind", *SLOTS, "sliced")


@dataclass
class SlotPrediction:
    """The model's reading of one clause: kind probabilities and, per slot, types ranked by probability."""

    kind: list[tuple[str, float]]
    slots: dict[str, list[tuple[str, float]]] = field(default_factory=dict)
    sliced: float = 0.0  # probability that the object must be a slice

    @property
    def top_kind(self) -> str:
        return self.kind[0][0]


def _label(e: Example, head: str) -> str:
    if head == "sliced":
        return "yes" if e.sliced else "no"
    return e.slot(head)


class SlotModel:
    """Vectorizers and one classifier per head; `fit` needs scikit-learn, prediction uses the same objects."""

    def __init__(self, vectorizers: list[Any], heads: dict[str, Any], meta: dict[str, Any]) -> None:
        self.vectorizers = vectorizers
        self.heads = heads
        self.meta = meta

    @classmethod
    def fit(cls, examples: list[Example], seed: int = 0, c: float = 8.0) -> SlotModel:
        try:
            from sklearn.feature_extraction.text import TfidfVectorizer
            from sklearn.linear_model import LogisticRegression
        except ImportError as exc:  # training only; a committed model needs it too (pickled estimators)
            raise DataError("training the language model needs scikit-learn: pip install scikit-learn") from exc
        texts = [e.text.lower() for e in examples]
        vecs = [
            TfidfVectorizer(ngram_range=(1, 2), min_df=2, sublinear_tf=True, max_features=30000,
                            dtype=np.float32),
            TfidfVectorizer(analyzer="char_wb", ngram_range=(2, 5), min_df=3, sublinear_tf=True,
                            max_features=40000, dtype=np.float32),
        ]
        x = _stack([v.fit_transform(texts) for v in vecs])
        heads: dict[str, Any] = {}
        for head in HEADS:
            rows = [i for i, e in enumerate(examples) if head in ("kind", "sliced", "object") or e.slot(head)]
            y = [_label(examples[i], head) for i in rows]
            clf = LogisticRegression(C=c, max_iter=300, random_state=seed)
            clf.fit(x[rows], y)
            clf.coef_ = clf.coef_.astype(np.float32)
            heads[head] = clf
        return cls(vecs, heads, {"format": FORMAT, "seed": seed, "C": c, "n_train": len(examples)})

    def features(self, texts: list[str]) -> Any:
        return _stack([v.transform([t.lower() for t in texts]) for v in self.vectorizers])

    def predict(self, texts: list[str], types: set[str] | None = None) -> list[SlotPrediction]:
        """Per text: kinds and slot types ranked; slot types limited to `types` (the scene) when given."""
        x = self.features(texts)
        probs = {h: clf.predict_proba(x) for h, clf in self.heads.items()}
        out = []
        for i in range(len(texts)):
            kinds = _ranked(self.heads["kind"].classes_, probs["kind"][i], None)
            slots = {s: _ranked(self.heads[s].classes_, probs[s][i], types) for s in SLOTS}
            classes = list(self.heads["sliced"].classes_)
            sliced = float(probs["sliced"][i][classes.index("yes")]) if "yes" in classes else 0.0
            out.append(SlotPrediction(kinds, slots, sliced))
        return out

    def save(self, path: Path) -> None:
        blob = pickle.dumps({"vectorizers": self.vectorizers, "heads": self.heads, "meta": self.meta},
                            protocol=4)
        with open(path, "wb") as fh:  # mtime 0: the same model gives the same bytes
            with gzip.GzipFile(fileobj=fh, mode="wb", mtime=0, compresslevel=9) as gz:
                gz.write(blob)

    @classmethod
    def load(cls, path: Path | None = None) -> SlotModel:
        src = path or Path(str(resources.files("nl2hltl2plan.language.learned") / ARTIFACT))
        if not src.exists():
            raise DataError(f"no learned language model at {src}; build it with `nl2hltl2plan train language`")
        try:
            with gzip.open(src, "rb") as fh:
                d = pickle.load(fh)  # our own committed artifact (see docs/learned.md)
        except ImportError as exc:
            raise DataError("the learned language model needs scikit-learn: pip install scikit-learn") from exc
        except (OSError, pickle.UnpicklingError, EOFError) as exc:
            raise DataError(f"cannot read the learned language model {src}: {exc}") from exc
        if d.get("meta", {}).get("format") != FORMAT:
            raise DataError(f"{src} has an old model format; rebuild it with `nl2hltl2plan train language`")
        return cls(d["vectorizers"], d["heads"], d["meta"])


def _stack(mats: list[Any]) -> Any:
    from scipy.sparse import hstack

    return hstack(mats, format="csr")


def _ranked(classes: Any, p: Any, types: set[str] | None) -> list[tuple[str, float]]:
    pairs = [(str(c), float(q)) for c, q in zip(classes, p, strict=True) if c]
    if types is not None:
        pairs = [(c, q) for c, q in pairs if c in types]
    total = sum(q for _, q in pairs) or 1.0
    return sorted(((c, q / total) for c, q in pairs), key=lambda cq: -cq[1])
