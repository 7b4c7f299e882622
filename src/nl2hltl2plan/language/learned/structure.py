"""The structure model: a linear-chain CRF that splits an instruction into task spans and labels each
span's temporal relation to the spans before it (`compose.RELATIONS`).

Tags: `B-<REL>` starts a span, `I` continues it, `O` is a connective or filler word ("then", "once
you've", "in any order"). Features are the word, its neighbours (3 each side), the first words of its
sentence ("before you ..."), and the instruction's last words ("... in that order"), so that a
connective far from the span's first word still labels it, and features that do not depend on the
connective's words: of pointing back (`_pointing_features`), of the word's shape and of its clause
(`_clause_features`: a clause that only names earlier objects is a reference, not a task). Training
uses CRFsuite (`python-crfsuite`, the `train` extra); the artifact holds only numpy arrays (feature
strings, a weight matrix, the transition matrix, the relation head's weights) and inference is numpy
Viterbi / forward-backward, so the core install reads it. A span tagged REF / RPRE (it points back at
one earlier span) gets that span from the relation head (`relation_head.py`).

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


# words that say an earlier task is over ("once you're done putting the pan", "when that's complete")
_DONE_WORDS = frozenset("done finished finish complete completed through over ready dealt sorted".split())
_CLAUSE_END = frozenset({",", ".", "!", "?", ";", ":"})


def _shape(w: str) -> str:
    """The word's shape, independent of its letters: a gerund, a participle, a number, punctuation."""
    if not w[:1].isalnum():
        return "sh=p"
    if w.isdigit():
        return "sh=n"
    if len(w) > 4 and w.endswith("ing"):
        return "sh=ing"
    if len(w) > 3 and w.endswith("ed"):
        return "sh=ed"
    return "sh=w"


@lru_cache(maxsize=1)
def _object_words() -> frozenset[str]:
    """The words of the lexicon's names of objects and places ("mug", "counter"), less the words that
    name every task ("everything")."""
    from nl2hltl2plan.language.grounding import lexicon

    return frozenset(w for phrase in lexicon() for w in phrase if content_stem(w) and w not in _ALL_WORDS)


def _clause_features(low: list[str]) -> list[list[str]]:
    """Per token, of its clause (the words between two of , . ; : ! ?): whether the clause has a verb,
    a word saying something is done, a temporal word, an object word (`_object_words`) repeated from an
    earlier clause and one that is new, what follows it, and the kinds of the clauses before and after
    it in its sentence. A clause with a temporal word whose object words all repeat earlier ones ("once
    you're done putting the pan,") names an earlier task, it is no task of its own, whatever its words;
    a clause with no verb ("your first job:") is no task either."""
    nouns = _object_words()
    out: list[list[str]] = [[] for _ in low]
    earlier: set[str] = set()
    start = 0
    kinds: list[tuple[range, str, str]] = []  # each clause, its kind, the mark that ends it
    for i, w in enumerate(low + ["."]):
        if w not in _CLAUSE_END and i < len(low):
            continue
        clause = range(start, i)
        stems = [content_stem(low[k]) if low[k] in nouns else None for k in clause]
        found = [st for st in stems if st]
        rep = any(st in earlier for st in found)
        new = any(st not in earlier for st in found)
        tags = ["cv" if any(low[k] in _VERBS for k in clause) else "cnov"]
        if any(low[k] in _DONE_WORDS for k in clause):
            tags.append("cdone")
        if any(low[k] in _TEMPORAL for k in clause):
            tags.append("ctemp")
        tags.append("crep" + ("+new" if new else "") if rep else "cnew" if new else "cnone")
        if "ctemp" in tags or "cdone" in tags:
            tags.append(tags[-1] + "&t")
        tags.append("cnext=" + (low[i] if i < len(low) else "<>"))
        for pos, k in enumerate(clause):
            out[k] += tags + ["cp=" + str(min(pos, 3)), "c0=" + low[start]]
        kinds.append((clause, tags[-2], low[i] if i < len(low) else "."))
        earlier |= set(found)
        start = i + 1
    # the kind of the clause before and after in the same sentence: the task after "having put the pan,"
    # points back, whatever word opens that clause
    for n, (clause, _, _) in enumerate(kinds):
        prev = kinds[n - 1][1] if n and kinds[n - 1][2] in (",", ":") else "<s>"
        nxt = kinds[n + 1][1] if n + 1 < len(kinds) and kinds[n][2] in (",", ":") else "</s>"
        for k in clause:
            out[k] += ["pc=" + prev, "nc=" + nxt]
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
    words_only = [w for w in low if w[:1].isalnum()]
    last = words_only[-2:] if words_only else ["<>"]
    pointing = _pointing_features(low)
    clauses = _clause_features(low)
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
        f += pointing[i] + clauses[i]
        f += [_shape(w), "elast=" + last[-1], "elast2=" + "|".join(last)]
        sent_words = [x for x in sent_tail[i].split("|") if x[:1].isalnum()]
        f.append("slast=" + (sent_words[-1] if sent_words else "<>"))
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
