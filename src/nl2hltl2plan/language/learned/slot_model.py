"""The learned slot model: one clause of text -> task kind, slot types ranked, sliced.

Features are TF-IDF word 1-2-grams and character 2-5-grams (inside word boundaries, so unseen
spellings and compounds still share pieces); one multinomial logistic regression per output (kind,
object, container, receptacle, light, sliced), fitted with scikit-learn. The artifact holds only numpy
arrays (vocabularies, idf weights, coefficients) and prediction is plain numpy, so using the model needs
neither scikit-learn nor pickle and loads fast. At inference the slot distributions are restricted to the
scene's object types and renormalised, which is the grounding: a type the scene lacks is never chosen,
and the probabilities are the confidence reported with ambiguous words.
"""

from __future__ import annotations

import io
import math
import re
import threading
import zipfile
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from nl2hltl2plan.config import user_cache_dir
from nl2hltl2plan.domain.task_kinds import SLOTS
from nl2hltl2plan.errors import DataError
from nl2hltl2plan.io import atomic_path, require_regular_file
from nl2hltl2plan.language.learned.data import Example, states_kind
from nl2hltl2plan.language.learned.ranker import TypeRanker

ARTIFACT = "slot_model.npz"
_KEPT = 4096  # texts whose head outputs a model keeps (a few KB each); the oldest go first


def packaged_path(artifact: str) -> Path:
    """A model file shipped inside the package (never written by default)."""
    return Path(str(resources.files("nl2hltl2plan.language.learned") / artifact))


def user_path(artifact: str) -> Path:
    """Where `nl2hltl2plan train language` writes a model file by default, and what the loaders prefer."""
    return user_cache_dir() / "models" / artifact


def preferred_path(artifact: str) -> Path:
    """The user's retrained model file when present, else the packaged one."""
    user = user_path(artifact)
    return user if user.exists() else packaged_path(artifact)


def packaged_model_path() -> Path:
    return packaged_path(ARTIFACT)


def user_model_path() -> Path:
    return user_path(ARTIFACT)


def default_model_path() -> Path:
    """The slot model `SlotModel.load()` reads (`preferred_path`)."""
    return preferred_path(ARTIFACT)
FORMAT = 3
DenseFeatures = Callable[[list[str]], np.ndarray]  # texts -> (texts, d): the pretrained encoder's, measured
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


def _trains(head: str, e: Example) -> bool:
    if head == "kind":
        return states_kind(e)
    return head == "sliced" or bool(e.slot(head))


def _label(e: Example, head: str) -> str:
    if head == "sliced":
        return "yes" if e.sliced else "no"
    return e.slot(head)


_WORD = re.compile(r"(?u)\b\w\w+\b")  # scikit-learn's default token pattern
_SPACES = re.compile(r"\s\s+")


@dataclass
class Vectorizer:
    """TF-IDF over word or char_wb n-grams, as scikit-learn's TfidfVectorizer (sublinear tf, l2 norm)."""

    analyzer: str  # "word" or "char_wb"
    lo: int
    hi: int
    vocab: dict[str, int]
    idf: np.ndarray

    def grams(self, text: str) -> list[str]:
        text = text.lower()
        out: list[str] = []
        if self.analyzer == "word":
            toks = _WORD.findall(text)
            for n in range(self.lo, self.hi + 1):
                out += [" ".join(toks[i : i + n]) for i in range(len(toks) - n + 1)]
            return out
        for w in _SPACES.sub(" ", text).split():
            w = f" {w} "
            for n in range(self.lo, self.hi + 1):
                out += [w[i : i + n] for i in range(max(1, len(w) - n + 1))]
                if len(w) <= n:
                    break
        return out

    def transform(self, text: str) -> tuple[np.ndarray, np.ndarray]:
        """Sparse row as (indices, values)."""
        counts = Counter(self.vocab[g] for g in self.grams(text) if g in self.vocab)
        if not counts:
            return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.float32)
        idx = np.fromiter(counts.keys(), dtype=np.int64, count=len(counts))
        val = np.array([1.0 + math.log(c) for c in counts.values()], dtype=np.float32) * self.idf[idx]
        return idx, val / np.float32(np.linalg.norm(val) or 1.0)


@dataclass
class Head:
    """One logistic regression: classes, coefficients (classes x features, one row when binary), bias."""

    classes: list[str]
    coef: np.ndarray
    intercept: np.ndarray

    def proba(self, idx: np.ndarray, val: np.ndarray) -> np.ndarray:
        z = self.coef[:, idx] @ val + self.intercept
        if len(self.classes) == 2 and self.coef.shape[0] == 1:
            p1 = 1.0 / (1.0 + math.exp(-float(z[0])))
            return np.array([1.0 - p1, p1])
        e = np.exp(z - z.max())
        return np.asarray(e / e.sum())


class SlotModel:
    """Two vectorizers and one head per output; `fit` needs scikit-learn, prediction only numpy."""

    def __init__(
        self,
        vectorizers: list[Vectorizer],
        heads: dict[str, Head],
        meta: dict[str, Any],
        ranker: TypeRanker | None = None,
        dense: DenseFeatures | None = None,
    ) -> None:
        self.vectorizers = vectorizers
        self.heads = heads
        self.meta = meta
        self.ranker = ranker  # orders the several scene types a word fits (`ranker.py`)
        self.dense = dense  # more features after the TF-IDF ones (`encoder_features.py`); None by default
        # each head's probabilities per text: a reading asks for the same clause about twice (the
        # grammar-first reading, the arbitration), and the suites read the same texts again
        self._probs: dict[str, dict[str, np.ndarray]] = {}
        self._lock = threading.Lock()  # the web server reads instructions on several threads

    def without_ranker(self) -> SlotModel:
        """The same slot model with no type ranker (its candidates keep the slot model's order)."""
        return SlotModel(self.vectorizers, self.heads, self.meta, dense=self.dense)

    @classmethod
    def fit(
        cls, examples: list[Example], seed: int = 0, c: float = 8.0, dense: DenseFeatures | None = None
    ) -> SlotModel:
        try:
            from scipy.sparse import csr_matrix, hstack
            from sklearn.feature_extraction.text import TfidfVectorizer
            from sklearn.linear_model import LogisticRegression
        except ImportError as exc:
            raise DataError(
                "training the language model needs scikit-learn: pip install scikit-learn"
            ) from exc
        texts = [e.text.lower() for e in examples]
        specs = [("word", 1, 2, 2, 30000), ("char_wb", 2, 5, 3, 40000)]
        vecs, mats = [], []
        for analyzer, lo, hi, min_df, cap in specs:
            v = TfidfVectorizer(
                analyzer=analyzer,
                ngram_range=(lo, hi),
                min_df=min_df,
                sublinear_tf=True,
                max_features=cap,
                dtype=np.float32,
            )
            mats.append(v.fit_transform(texts))
            vocab = {str(k): int(i) for k, i in v.vocabulary_.items()}
            vecs.append(Vectorizer(analyzer, lo, hi, vocab, v.idf_.astype(np.float32)))
        if dense is not None:
            mats.append(csr_matrix(dense(texts)))
        x = hstack(mats, format="csr")
        heads: dict[str, Head] = {}
        for head in HEADS:
            rows = [i for i, e in enumerate(examples) if _trains(head, e)]
            clf = LogisticRegression(C=c, max_iter=300, random_state=seed)
            clf.fit(x[rows], [_label(examples[i], head) for i in rows])
            heads[head] = Head(
                [str(k) for k in clf.classes_],
                clf.coef_.astype(np.float32),
                clf.intercept_.astype(np.float32),
            )
        meta: dict[str, Any] = {"format": FORMAT, "seed": seed, "C": c, "n_train": len(examples)}
        model = cls(vecs, heads, meta, dense=dense)
        model.check_features(texts[:: max(1, len(texts) // 200)], x[:: max(1, len(texts) // 200)])
        return model

    def check_features(self, texts: list[str], x: Any) -> None:
        """The numpy features must equal scikit-learn's (else the artifact would predict differently)."""
        for text, row in zip(texts, x, strict=False):
            idx, val = self.features(text)
            dense = np.zeros(row.shape[1], dtype=np.float32)
            dense[idx] = val
            if np.abs(dense - row.toarray()[0]).max() > 1e-4:
                raise DataError(f"numpy features differ from scikit-learn's for {text!r}")

    def features(self, text: str) -> tuple[np.ndarray, np.ndarray]:
        parts, offset = [], 0
        for v in self.vectorizers:
            idx, val = v.transform(text)
            parts.append((idx + offset, val))
            offset += len(v.idf)
        if self.dense is not None:
            extra = self.dense([text])[0]
            parts.append((offset + np.arange(len(extra)), extra.astype(np.float32)))
        return np.concatenate([p[0] for p in parts]), np.concatenate([p[1] for p in parts])

    def predict(self, texts: list[str], types: set[str] | None = None) -> list[SlotPrediction]:
        """Per text: kinds and slot types ranked; slot types limited to `types` (the scene) when given."""
        out = []
        for text in texts:
            probs = self.probabilities(text)
            kinds = _ranked(self.heads["kind"].classes, probs["kind"], None)
            slots = {s: _ranked(self.heads[s].classes, probs[s], types) for s in SLOTS}
            classes = self.heads["sliced"].classes
            sliced = float(probs["sliced"][classes.index("yes")]) if "yes" in classes else 0.0
            out.append(SlotPrediction(kinds, slots, sliced))
        return out

    def probabilities(self, text: str) -> dict[str, np.ndarray]:
        """Each head's class probabilities for `text`, computed once per text (the arrays are shared:
        callers only read them)."""
        if (probs := self._probs.get(text)) is None:
            idx, val = self.features(text)
            probs = {h: head.proba(idx, val) for h, head in self.heads.items()}
            with self._lock:
                if len(self._probs) >= _KEPT:
                    self._probs.pop(next(iter(self._probs)), None)
                self._probs[text] = probs
        return probs

    def arrays(self) -> dict[str, np.ndarray]:
        out: dict[str, np.ndarray] = {"meta": np.array([f"{k}={v}" for k, v in self.meta.items()])}
        for i, v in enumerate(self.vectorizers):
            words = sorted(v.vocab, key=v.vocab.__getitem__)
            out[f"vec{i}_spec"] = np.array([v.analyzer, str(v.lo), str(v.hi)])
            out[f"vec{i}_vocab"] = np.array(words)
            out[f"vec{i}_idf"] = v.idf
        if self.ranker is not None:
            out.update(self.ranker.arrays())
        for name, h in self.heads.items():
            out[f"head_{name}_classes"] = np.array(h.classes)
            out[f"head_{name}_coef"] = h.coef
            out[f"head_{name}_intercept"] = h.intercept
        return out

    def save(self, path: Path) -> None:
        """An .npz file (no pickle) with fixed zip timestamps: the same model gives the same bytes.
        Written to a temporary file and renamed: a kill leaves the old model, never a torn one."""
        with (
            atomic_path(path, "language model") as tmp,
            zipfile.ZipFile(tmp, "w", compression=zipfile.ZIP_DEFLATED, compresslevel=9) as zf,
        ):
            for name, arr in self.arrays().items():
                buf = io.BytesIO()
                np.lib.format.write_array(buf, np.ascontiguousarray(arr), allow_pickle=False)
                zf.writestr(
                    zipfile.ZipInfo(f"{name}.npy", date_time=(1980, 1, 1, 0, 0, 0)),
                    buf.getvalue(),
                    compress_type=zipfile.ZIP_DEFLATED,
                )

    @classmethod
    def load(cls, path: Path | None = None) -> SlotModel:
        """The model at `path`; by default the user's retrained one (`user_model_path`) when it exists,
        else the packaged one. A damaged file is a `DataError` naming it."""
        src = path or default_model_path()
        if not src.exists():
            raise DataError(
                f"no learned language model at {src}; build it with `nl2hltl2plan train language`"
            )
        try:
            with np.load(require_regular_file(src, "language model"), allow_pickle=False) as z:
                d = {k: z[k] for k in z.files}
            meta = dict(str(s).split("=", 1) for s in d["meta"])
        except (OSError, ValueError, EOFError, KeyError, zipfile.BadZipFile) as exc:
            raise DataError(
                f"cannot read the learned language model {src} (damaged? rebuild it with `nl2hltl2plan "
                f"train language`): {type(exc).__name__}: {exc}"
            ) from None
        if meta.get("format") != str(FORMAT):
            raise DataError(f"{src} has another model format; rebuild it with `nl2hltl2plan train language`")
        vecs = []
        for i in range(2):
            analyzer, lo, hi = (str(x) for x in d[f"vec{i}_spec"])
            vocab = {str(w): j for j, w in enumerate(d[f"vec{i}_vocab"].tolist())}
            vecs.append(Vectorizer(analyzer, int(lo), int(hi), vocab, d[f"vec{i}_idf"]))
        heads = {
            h: Head([str(c) for c in d[f"head_{h}_classes"]], d[f"head_{h}_coef"], d[f"head_{h}_intercept"])
            for h in HEADS
        }
        ranker = TypeRanker.from_arrays(d)
        if "encoder_sha256" not in meta:
            return cls(vecs, heads, meta, ranker)
        # a model trained with the pretrained encoder's features (`train language --encoder`): only
        # such a file loads the encoder (the `encoder` extra), so the default path never does
        from nl2hltl2plan.language.learned.encoder_features import EncoderFeatures

        return cls(vecs, heads, meta, ranker, dense=EncoderFeatures.for_model(meta).slot_features)


def _ranked(classes: Any, p: Any, types: set[str] | None) -> list[tuple[str, float]]:
    pairs = [(str(c), float(q)) for c, q in zip(classes, p, strict=True) if c]
    if types is not None:
        pairs = [(c, q) for c, q in pairs if c in types]
    total = sum(q for _, q in pairs) or 1.0
    return sorted(((c, q / total) for c, q in pairs), key=lambda cq: -cq[1])
