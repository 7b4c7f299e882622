"""The relation head: which earlier span a span that points back (REF / RPRE) names.

The CRF (`structure.py`) says that a span points back ("with the pan done, Y", "Y, but only once you've
put the pan"); this head scores each earlier span as its target from features of the pair that do not
depend on the connective's words, so they carry over to phrasings never trained on: the content words
the later span's sentence has outside any span (its *reference words*: "the pan", "is on the table")
shares with the earlier span's words, whether the earlier span's verb appears there in any form
("having put", "putting"), whether the earlier span is the only one or the best one sharing words, and
the distance. A logistic regression (numpy weights) scores each pair; the target is the best-scoring
earlier span and its softmax probability is the head's confidence.

    >>> spans = [(0, 6), (7, 13), (19, 22)]  # token ranges of three spans
    >>> words = "put the pan on the stove . wash the mug in the sink .".split()
    >>> words += "with the pan done , slice an apple".split()
    >>> ref_words(words, spans, 2)
    ['pan']
"""

from __future__ import annotations

import re

import numpy as np

from nl2hltl2plan.language.learned.compose import VERB_GERUND, VERB_PARTICIPLE

FEATURES = (
    "share0", "share1", "share2+", "best", "only", "verb", "d1", "d2", "d3", "d4+", "first", "nearest_best",
)
_STOP = frozenset(
    "the a an of to in on into onto at by with from and or is are was be been it its them this that then "
    "you your you've you're i me my we our up off out for so once when after before as do done did has "
    "have had".split()
)
# one training case: the instruction's words, its spans (token ranges), a span that points back, its target
HeadCase = tuple[list[str], list[tuple[int, int]], int, int]
_BASE = {v: k for k, v in VERB_PARTICIPLE.items()} | {v: k for k, v in VERB_GERUND.items()}
_END = {".", "!", "?", ";"}


def _stem(word: str) -> str:
    w = word.lower()
    w = _BASE.get(w, w)
    return re.sub(r"(es|s)$", "", w) if len(w) > 3 and w not in VERB_GERUND else w


def content_stem(word: str) -> str | None:
    """The word's stem ("placed" -> place, "mugs" -> mug), or None for a stop word or punctuation."""
    return _stem(word) if word.isalpha() and len(word) > 2 and word.lower() not in _STOP else None


def _sentence_of(words: list[str], k: int) -> tuple[int, int]:
    """The token range of the sentence around token `k`."""
    a = k
    while a > 0 and words[a - 1] not in _END:
        a -= 1
    b = k
    while b < len(words) and words[b] not in _END:
        b += 1
    return a, b


def ref_words(words: list[str], spans: list[tuple[int, int]], i: int) -> list[str]:
    """Span `i`'s reference words: the content words of its sentence that lie in no span."""
    a, b = _sentence_of(words, spans[i][0])
    inside = {k for s, e in spans for k in range(s, e)}
    return [
        words[k].lower() for k in range(a, b)
        if k not in inside and words[k].isalpha() and words[k].lower() not in _STOP
    ]


def pair_features(words: list[str], spans: list[tuple[int, int]], i: int) -> np.ndarray:
    """One row of `FEATURES` per earlier span j < i."""
    ref = {_stem(w) for w in ref_words(words, spans, i)}
    shares = []
    verbs = []
    for s, e in spans[:i]:
        own = {_stem(w) for w in words[s:e] if w.isalpha() and w.lower() not in _STOP}
        shares.append(len(ref & own))
        verbs.append(bool(words[s:e]) and _stem(words[s]) in ref)
    top = max(shares, default=0)
    nearest = max((j for j in range(i) if shares[j] == top), default=-1)
    rows = []
    for j in range(i):
        d = i - j
        f = {
            "share0": shares[j] == 0, "share1": shares[j] == 1, "share2+": shares[j] >= 2,
            "best": shares[j] == top > 0, "only": shares[j] > 0 and sum(x > 0 for x in shares) == 1,
            "verb": verbs[j], "d1": d == 1, "d2": d == 2, "d3": d == 3, "d4+": d >= 4, "first": j == 0,
            "nearest_best": j == nearest and top > 0,
        }
        rows.append([float(f[name]) for name in FEATURES])
    return np.array(rows, dtype=np.float64).reshape(i, len(FEATURES))


class RelationHead:
    """Logistic-regression weights over `FEATURES` (numpy only at inference)."""

    def __init__(self, weights: np.ndarray, bias: float):
        self.weights = weights
        self.bias = bias

    def target(self, words: list[str], spans: list[tuple[int, int]], i: int) -> tuple[int, float]:
        """The earlier span that span `i` names, and the softmax probability of that choice."""
        if i == 0:
            return -1, 0.0
        logits = pair_features(words, spans, i) @ self.weights + self.bias
        p = np.exp(logits - logits.max())
        p /= p.sum()
        j = int(p.argmax())
        return j, float(p[j])

    @classmethod
    def fit(cls, cases: list[HeadCase]) -> RelationHead:
        """Fit on (words, spans, i, the gold target of span i): every earlier span is a candidate, the
        gold one positive (scikit-learn, lbfgs: deterministic)."""
        from sklearn.linear_model import LogisticRegression

        xs, ys = [], []
        for words, spans, i, gold in cases:
            x = pair_features(words, spans, i)
            xs.append(x)
            ys += [int(j == gold) for j in range(i)]
        lr = LogisticRegression(C=1.0, max_iter=500)
        lr.fit(np.vstack(xs), np.array(ys))
        return cls(lr.coef_[0].astype(np.float64), float(lr.intercept_[0]))
