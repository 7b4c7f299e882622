"""The structure model: a linear-chain CRF that splits an instruction into task spans and labels each
span's temporal relation to the spans before it (`compose.RELATIONS`).

Tags: `B-<REL>` starts a span, `I` continues it, `O` is a connective or filler word ("then", "once
you've", "in any order"). Features are the word, its neighbours (3 each side), the first words of its
sentence ("before you ..."), and the instruction's last words ("... in that order"), so that a
connective far from the span's first word still labels it, and features of pointing back that do not
depend on the connective's words (`_pointing_features`). Training uses CRFsuite (`python-crfsuite`,
the `train` extra); the artifact holds only numpy arrays (feature strings, a weight matrix, the
transition matrix, the relation head's weights) and inference is numpy Viterbi / forward-backward, so the
core install reads it. A span tagged REF / RPRE (it points back at one earlier span) gets that span from
the relation head (`relation_head.py`).

    >>> m = StructureModel.load()
    >>> [(s.text, s.relation) for s in m.read("Put the mug in the sink. Then put the apple in the fridge.")]
    [('Put the mug in the sink', 'START'), ('put the apple in the fridge', 'SEQ')]
"""

from __future__ import annotations

import io
import re
import zipfile
from collections.abc import Iterator
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

from nl2hltl2plan.errors import DataError
from nl2hltl2plan.io import atomic_path
from nl2hltl2plan.language.learned.relation_head import RelationHead, content_stem
from nl2hltl2plan.language.learned.slot_model import preferred_path, user_path

ARTIFACT = "structure_model.npz"
_TOKEN = re.compile(r"[A-Za-z0-9]+(?:'[A-Za-z]+)?|[^\sA-Za-z0-9]")


def tokenize(text: str) -> list[tuple[str, int, int]]:
    """Words (with their contraction: "you've") and punctuation marks, with character offsets."""
    return [(m.group(), m.start(), m.end()) for m in _TOKEN.finditer(text)]


def _verbs() -> frozenset[str]:
    from nl2hltl2plan.language.learned.compose import VERB_GERUND, VERB_PARTICIPLE

    return frozenset(VERB_GERUND) | frozenset(VERB_GERUND.values()) | frozenset(VERB_PARTICIPLE.values())


_VERBS = _verbs()
# words that name every earlier task ("once everything else is done", "after all previous tasks")
_ALL_WORDS = frozenset("all everything every previous above earlier other rest else preceding".split())
# temporal words whose place in the sentence matters to its span ("X before putting the pan": RPRE)
_TEMPORAL = frozenset(
    "before after until first then finally lastly once when whenever while prior following next".split()
)


def _pointing_features(low: list[str]) -> list[list[str]]:
    """Per token: whether it repeats a content word of an earlier sentence (`rep`: "with the pan done"
    names the pan of an earlier task) and whether such a word comes later / earlier in its sentence
    (`rep>` / `rep<`); where it lies against its sentence's commas; its sentence's temporal words
    (`s:before`) and whether the sentence has a word that names every task (`sall`): features of
    *pointing back* that do not depend on the connective's exact words."""
    out: list[list[str]] = [[] for _ in low]
    earlier: set[str] = set()
    start = 0
    for i, w in enumerate(low + ["."]):
        if w not in (".", "!", "?", ";") and i < len(low):
            continue
        sent = range(start, i)
        stems = [content_stem(low[k]) for k in sent]
        commas = [k for k in sent if low[k] == ","]
        rep = [k for k, st in zip(sent, stems, strict=True) if st and st in earlier]
        tags = sorted({"s:" + low[k] for k in sent if low[k] in _TEMPORAL})
        if any(low[k] in _ALL_WORDS for k in sent):
            tags.append("sall")
        for k in sent:
            out[k] += tags
            if k in rep:
                out[k].append("rep")
            if any(r > k for r in rep):
                out[k].append("rep>")
            if any(r < k for r in rep):
                out[k].append("rep<")
            if commas:
                out[k].append("c<" if k < commas[0] else "c>" if k > commas[-1] else "c=")
        earlier |= {st for st in stems if st}
        start = i + 1
    return out


def features(words: list[str]) -> list[list[str]]:
    """The CRF's string features for each token (identical in training and inference)."""
    low = [w.lower() for w in words]
    n = len(low)
    sent_start, sent_tail = [], []
    start = 0
    for i, w in enumerate(low):
        sent_start.append(start)
        if w in (".", "!", "?", ";") or i == n - 1:
            # the sentence's last words ("Then X and Y in any order."), for each of its tokens
            end = "|".join(x for x in low[max(start, i - 3) : i + 1] if x not in (".", "!", "?", ";"))
            sent_tail += [end] * (i + 1 - start)
            start = i + 1
    tail = "|".join(w for w in low[-4:] if w not in (".", "!"))
    pointing = _pointing_features(low)
    out = []
    for i, w in enumerate(low):
        s = sent_start[i]
        f = [
            "b", "w=" + w, "s3=" + w[-3:], "p=" + str(min(i - s, 4)), "end=" + tail,
            "s0=" + low[s] if s < n else "s0=", "s01=" + "|".join(low[s : s + 2]), "send=" + sent_tail[i],
        ]
        for d in (-3, -2, -1, 1, 2, 3):
            j = i + d
            f.append(f"w{d}=" + (low[j] if 0 <= j < n else "<>"))
        f.append("w-1w=" + (low[i - 1] if i else "<>") + "|" + w)
        f.append("ww1=" + w + "|" + (low[i + 1] if i + 1 < n else "<>"))
        f.append("w-2w-1=" + (low[i - 2] if i > 1 else "<>") + "|" + (low[i - 1] if i else "<>"))
        if i == 0:
            f.append("BOS")
        if w in _VERBS:
            f.append("verb")
        if i + 1 < n and low[i + 1] in _VERBS:
            f.append("verb+1")
        if w in _ALL_WORDS:
            f.append("allw")
        f += pointing[i]
        out.append(f)
    return out


def tags_of(text: str, spans: list[tuple[int, int]], relations: list[str]) -> tuple[list[str], list[str]]:
    """Gold tags for training: a token inside span k is B-<rel k> (its first token) or I, else O."""
    words, tags = [], []
    seen: set[int] = set()
    for w, a, b in tokenize(text):
        words.append(w)
        k = next((k for k, (s, e) in enumerate(spans) if s <= a and b <= e), None)
        if k is None:
            tags.append("O")
        else:
            tags.append("I" if k in seen else "B-" + relations[k])
            seen.add(k)
    return words, tags


def token_ranges(text: str, spans: list[tuple[int, int]]) -> list[tuple[int, int]]:
    """The character spans as token ranges (first token, last token + 1)."""
    toks = tokenize(text)
    out = []
    for s, e in spans:
        inside = [k for k, (_, a, b) in enumerate(toks) if s <= a and b <= e]
        out.append((inside[0], inside[-1] + 1) if inside else (0, 0))
    return out


@dataclass(frozen=True)
class Span:
    """One task span of an instruction: its text, where it is, its relation, the model's confidence."""

    text: str
    start: int
    end: int
    relation: str
    target: int | None = None  # the earlier span a REF / RPRE span points at (the relation head's)


@dataclass(frozen=True)
class Reading:
    """The model's reading of an instruction: its spans and the probability of that whole tagging."""

    spans: list[Span]
    confidence: float

    def __iter__(self) -> Iterator[Span]:
        return iter(self.spans)


class StructureModel:
    """CRF weights as numpy arrays: `index` feature -> row, `weights` (features x tags), `trans`."""

    def __init__(
        self,
        tags: list[str],
        feature_names: list[str],
        weights: np.ndarray,
        trans: np.ndarray,
        head: RelationHead | None = None,
        data_sha: str = "",
    ):
        self.head = head  # which earlier span a REF / RPRE span names (None: a model from before the head)
        self.data_sha = data_sha  # the training data's fingerprint (`data.data_fingerprint`)
        self.tags = tags
        self.index = {f: i for i, f in enumerate(feature_names)}
        self.feature_names = feature_names
        self.weights = weights
        self.trans = trans

    def _emissions(self, feats: list[list[str]]) -> np.ndarray:
        out = np.zeros((len(feats), len(self.tags)), dtype=np.float64)
        for t, fs in enumerate(feats):
            rows = [self.index[f] for f in fs if f in self.index]
            if rows:
                out[t] = self.weights[rows].sum(axis=0)
        return out

    def tag(self, words: list[str]) -> tuple[list[str], float]:
        """Viterbi tags and the probability of that tagging (forward algorithm for the normaliser)."""
        if not words:
            return [], 1.0
        em = self._emissions(features(words))
        n, k = em.shape
        score = em[0].copy()
        back = np.zeros((n, k), dtype=np.int64)
        alpha = em[0].copy()
        for t in range(1, n):
            cand = score[:, None] + self.trans
            back[t] = cand.argmax(axis=0)
            score = cand.max(axis=0) + em[t]
            a = alpha[:, None] + self.trans
            m = a.max(axis=0)
            alpha = m + np.log(np.exp(a - m).sum(axis=0)) + em[t]
        best = [int(score.argmax())]
        for t in range(n - 1, 0, -1):
            best.append(int(back[t, best[-1]]))
        best.reverse()
        top = alpha.max()
        log_z = top + np.log(np.exp(alpha - top).sum())
        return [self.tags[i] for i in best], float(np.exp(score.max() - log_z))

    def read(self, text: str) -> Reading:
        """The instruction's task spans (text order) with their relations; a span that points back at one
        earlier span gets its target from the relation head, whose confidence multiplies the reading's."""
        toks = tokenize(text)
        words = [w for w, _, _ in toks]
        tags, conf = self.tag(words)
        spans: list[list] = []  # [first token, last token + 1, relation]
        for k, tag in enumerate(tags):
            if tag.startswith("B-") or (tag == "I" and not spans):
                spans.append([k, k + 1, tag[2:] if tag.startswith("B-") else "SEQ"])
            elif tag == "I":  # an I after an O continues the span before it
                spans[-1][1] = k + 1
        ranges = [(a, b) for a, b, _ in spans]
        out = []
        for i, (a, b, rel) in enumerate(spans):
            target = None
            if i == 0:  # the first span opens the order, unless it is free ("X at any time. Finally Y")
                rel = "FREE" if rel == "FREE" else "START"
            elif rel == "START" or (rel in ("REF", "RPRE") and self.head is None):
                rel = "SEQ"
            elif rel in ("REF", "RPRE") and self.head is not None:
                target, p = self.head.target(words, ranges, i)
                conf *= p
            out.append(Span(text[toks[a][1] : toks[b - 1][2]], toks[a][1], toks[b - 1][2], rel, target))
        return Reading(out, conf)

    def save(self, path: Path) -> None:
        arrays = {
            "tags": np.array(self.tags),
            "features": np.array(self.feature_names),
            "weights": self.weights.astype(np.float32),
            "trans": self.trans.astype(np.float32),
        }
        if self.head is not None:
            arrays["head"] = np.append(self.head.weights, self.head.bias).astype(np.float32)
        if self.data_sha:
            arrays["data_sha"] = np.array([self.data_sha])
        with (  # a temporary file renamed over `path`: a kill leaves the old model, never a torn one
            atomic_path(path, "structure model") as tmp,
            zipfile.ZipFile(tmp, "w", compression=zipfile.ZIP_DEFLATED) as zf,
        ):
            for name, arr in arrays.items():
                buf = io.BytesIO()
                np.lib.format.write_array(buf, np.ascontiguousarray(arr), allow_pickle=False)
                info = zipfile.ZipInfo(name + ".npy", date_time=(2026, 1, 1, 0, 0, 0))
                zf.writestr(info, buf.getvalue(), compress_type=zipfile.ZIP_DEFLATED)

    @classmethod
    def load(cls, path: Path | None = None) -> StructureModel:
        src = path or default_structure_path()
        try:
            with np.load(src, allow_pickle=False) as z:  # type: ignore[arg-type]
                head = z["head"].astype(np.float64) if "head" in z.files else None
                return cls(
                    [str(t) for t in z["tags"]],
                    [str(f) for f in z["features"]],
                    z["weights"].astype(np.float64),
                    z["trans"].astype(np.float64),
                    RelationHead(head[:-1], float(head[-1])) if head is not None else None,
                    str(z["data_sha"][0]) if "data_sha" in z.files else "",
                )
        except (OSError, KeyError, ValueError) as exc:
            raise DataError(f"cannot read the structure model {src}: {exc}") from exc


def user_structure_path() -> Path:
    """Where `nl2hltl2plan train language` writes the structure model by default (never the package)."""
    return user_path(ARTIFACT)


def default_structure_path() -> Path:
    """The user's retrained structure model when present, else the packaged one."""
    return preferred_path(ARTIFACT)


@lru_cache(maxsize=2)
def load_structure(path: Path | None = None) -> StructureModel:
    return StructureModel.load(path)
