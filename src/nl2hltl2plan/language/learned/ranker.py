"""Which of the several scene types a word fits is meant ("the table": a dining table or a side table?).

A linear model over (candidate type x word of the clause) features plus the slot model's own probability:
it learns, from ALFRED's train annotations whose word fitted several scene types, which type annotators
meant given the rest of the clause ("a cup with a knife" is a Knife, "a clean knife in a drawer" a
ButterKnife, "a watch on the table" a side table). Trained on ALFRED's labels (the task each annotation
was written for); scored as a softmax over the candidates, whose probabilities are the confidences
reported with the ambiguity.

Chosen over the per-floor-plan count prior it replaces by a group 5-fold check on the train cases,
whole task families held out as test50's are (`rank_check.py`, docs/learned.md): top candidate =
ALFRED's label in 66.5 % of 1,414 words, against 60.0 % for the slot model alone and 57-58 % with the
count prior.

    >>> r = TypeRanker({"Knife|cup": 2.0, "logq": 1.0})
    >>> [t for t, _ in r.order("put a cup with a knife on the table", [("ButterKnife", 0.6), ("Knife", 0.4)])]
    ['Knife', 'ButterKnife']
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np

from nl2hltl2plan.errors import DataError
from nl2hltl2plan.language.grounding import find_mentions, lexicon

C = 1.0  # inverse regularisation, chosen by the group 5-fold check (0.1-3 within 1.5 points)
_FLOOR = 1e-3  # the slot model's probability is clipped here (confidences are reported to 3 decimals)
_SIZE_WORDS = Path(__file__).with_name("size_words.txt")
_LANDMARK_WORDS = Path(__file__).with_name("landmark_words.txt")
_BEFORE = 2  # a size word this many words before the name at most ("the little brown table")


@dataclass(frozen=True)
class RankCase:
    """One word with several scene types: the clause, the candidates with the slot model's probabilities,
    and the type the annotation was written for."""

    clause: str
    candidates: tuple[tuple[str, float], ...]
    label: str


def _words(clause: str) -> set[str]:
    return set(re.findall(r"[a-z]+", clause.lower()))


ExtraFeatures = Callable[[str, str], dict[str, float]]  # (clause, candidate) -> more features


def features(
    words: set[str], candidate: str, prob: float, extra: dict[str, float] | None = None
) -> dict[str, float]:
    """A candidate's features: its type, its type with each word of the clause (`_words`), the model's
    log-prob, and any `extra` ones (the pretrained encoder's, `encoder_features.py`, when measured)."""
    out = {f"{candidate}|": 1.0, "logq": math.log(max(prob, _FLOOR))}
    out.update({f"{candidate}|{w}": 1.0 for w in words})
    out.update(extra or {})
    return out


@cache
def _size_words() -> dict[str, tuple[str, ...]]:
    """word -> the types it means, best first (`size_words.txt`)."""
    out: dict[str, tuple[str, ...]] = {}
    for line in _SIZE_WORDS.read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            words, types = line.split(":")
            out.update(dict.fromkeys(words.split(), tuple(types.split())))
    return out


def size_said(clause: str, ranked: list[tuple[str, float]]) -> list[tuple[str, float]]:
    """`ranked` (best first) with the types a size word before the candidates' name means ranked first, the
    confidences kept in their order ("the little table": the SideTable before the DiningTable).

    >>> size_said("put it on the little table", [("DiningTable", 0.7), ("SideTable", 0.3)])
    [('SideTable', 0.7), ('DiningTable', 0.3)]
    """
    types = {t for t, _ in ranked}
    sizes = _size_words()
    for m in find_mentions(clause):
        if len(types & set(m.entry.types)) < 2:
            continue
        before = re.findall(r"[a-z]+", clause[: m.char_start].lower())[-_BEFORE:]
        meant = [t for w in reversed(before) for t in sizes.get(w, ()) if t in types]
        if meant:
            others = [t for t, _ in ranked if t not in meant]
            order = list(dict.fromkeys(meant)) + others
            return list(zip(order, [q for _, q in ranked], strict=True))
    return ranked


def stray_modifiers(clause: str, types: set[str]) -> set[str]:
    """The words of a compound name of the ambiguous word ("end" of "end table", "coffee" of "coffee table")
    said apart from it, in another phrase ("the table at the end of the bed", "the table by the coffee
    machine"): a landmark's words build no compound across its boundary, so they are no evidence for the
    compound's type.

    >>> sorted(stray_modifiers("put it on the table at the end of the bed", {"SideTable", "DiningTable"}))
    ['end']
    >>> stray_modifiers("put it on the end table", {"SideTable", "DiningTable"})
    set()
    """
    out: set[str] = set()
    for m in find_mentions(clause):
        if len(types & set(m.entry.types)) < 2:
            continue
        after = re.findall(r"[a-z]+", clause[m.char_end :].lower())
        opens = next((k for k, w in enumerate(after) if w in _landmark_words()), None)
        if opens is None:  # no landmark phrase after the name ("a bottle of hand soap": one thing)
            continue
        beyond = set(after[opens + 1 :])
        for compound in _compounds(m.entry.phrase.split()[-1], m.entry.canonical):
            out.update(w for w in compound[:-1] if w in beyond)
    return out


@cache
def _landmark_words() -> frozenset[str]:
    """The words that open a landmark or place phrase (`landmark_words.txt`)."""
    text = _LANDMARK_WORDS.read_text()
    return frozenset(w for line in text.splitlines() if not line.startswith("#") for w in line.split())


@cache
def _compounds(head: str, canonical: str) -> tuple[tuple[str, ...], ...]:
    """The lexicon's names of other entries that end in `head` ("end table", "coffee table" for "table")."""
    return tuple(
        words for words, (entry, _) in lexicon().items()
        if len(words) > 1 and words[-1] == head and entry.canonical != canonical
    )  # fmt: skip


class TypeRanker:
    """feature -> weight; `order` needs only the dictionary, `fit` scikit-learn."""

    def __init__(self, weights: dict[str, float], extra: ExtraFeatures | None = None) -> None:
        self.weights = weights
        self.extra = extra

    def _features(self, clause: str, words: set[str], candidate: str, prob: float) -> dict[str, float]:
        return features(words, candidate, prob, self.extra(clause, candidate) if self.extra else None)

    def order(self, clause: str, candidates: list[tuple[str, float]]) -> list[tuple[str, float]]:
        """The candidates (type, slot-model probability) re-ranked, with softmax confidences."""
        if len(candidates) < 2:
            return candidates
        total = sum(q for _, q in candidates) or 1.0
        words = _words(clause) - stray_modifiers(clause, {t for t, _ in candidates})
        scores = [
            sum(self.weights.get(f, 0.0) * v for f, v in self._features(clause, words, t, q / total).items())
            for t, q in candidates
        ]
        top = max(scores)
        exp = [math.exp(s - top) for s in scores]
        z = sum(exp)
        ranked = [(t, e / z) for (t, _), e in zip(candidates, exp, strict=True)]
        return size_said(clause, sorted(ranked, key=lambda tq: -tq[1]))

    @classmethod
    def fit(
        cls, cases: list[RankCase], seed: int = 0, c: float = C, extra: ExtraFeatures | None = None
    ) -> TypeRanker:
        """A logistic regression on (case, candidate) rows, label = the candidate is the annotation's type."""
        try:
            from sklearn.feature_extraction import DictVectorizer
            from sklearn.linear_model import LogisticRegression
        except ImportError as exc:
            raise DataError("training the type ranker needs scikit-learn: pip install scikit-learn") from exc
        rows, labels = [], []
        blank = cls({}, extra)
        for case in cases:
            words = _words(case.clause)
            for t, q in case.candidates:
                rows.append(blank._features(case.clause, words, t, q))
                labels.append(int(t == case.label))
        if len(set(labels)) < 2:
            raise DataError("no ambiguous words with a known type to train the type ranker on")
        vec = DictVectorizer()
        clf = LogisticRegression(C=c, max_iter=2000, random_state=seed).fit(vec.fit_transform(rows), labels)
        names = vec.get_feature_names_out()
        return cls({str(n): float(w) for n, w in zip(names, clf.coef_[0], strict=True) if w != 0.0}, extra)

    def arrays(self) -> dict[str, np.ndarray]:
        names = sorted(self.weights)
        return {
            "ranker_features": np.array(names),
            "ranker_weights": np.array([self.weights[n] for n in names], dtype=np.float32),
        }

    @classmethod
    def from_arrays(cls, d: dict[str, np.ndarray]) -> TypeRanker | None:
        if "ranker_features" not in d:
            return None
        names = d["ranker_features"].tolist()
        return cls({str(n): float(w) for n, w in zip(names, d["ranker_weights"].tolist(), strict=True)})
