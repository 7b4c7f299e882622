"""Where a voice's request starts and ends (issue 28, h287): a small learned classifier of each unit of a
message (a line, a sentence, a label before a colon) as REQUEST (it holds or continues the task text) or
FRAME (greeting, sign-off, name, stamp, heading, aside, chit-chat, scene-setting).

Session 33's word-level try (h272: the CRF trained on framed compositions) read held-out frames better but
moved committed readings; this decides over whole units instead, from features that carry across voices:
the unit's place in the message, whether it names a scene thing, an action, a count, a negation or an order
word by the package's lexicon (`grounding.find_mentions`, `content_words.categories`), its length,
punctuation and capitals, the same of its neighbours, and its first and last words. A logistic regression
(numpy, no extra dependency) is trained on compositions (`messages`): first-family compositions, most in a
frame of `compose_frames`' train pools, with whole frame sentences of `request_frames.txt`'s train pools
put between sentences; a unit is REQUEST when it overlaps a task span. The held pools of both files are the
validation (`report`).

The reading side (`frames_classified`) drops a unit only where the model is sure it is FRAME and no word of
it names an object, action, count, negation or order (check 1's content: such a unit is kept, and check 1
refuses it as before). It is measured and on by default (`config.reading_settings`, which documents
`NL2HLTL2PLAN_REQUEST_UNITS`; results/language/h287.md).
"""

from __future__ import annotations

import random
import re
import time
from dataclasses import dataclass, replace
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from nl2hltl2plan.config.reading_settings import request_units_on
from nl2hltl2plan.io import atomic_path
from nl2hltl2plan.language.content_words import categories, check1_categories, frame_keeps, names_content
from nl2hltl2plan.language.grounding import find_mentions

if TYPE_CHECKING:
    from nl2hltl2plan.language.learned.compose import Synth
    from nl2hltl2plan.language.learned.compose_frames import Pools

ARTIFACT = "request_model.npz"
SENTENCES_FILE = Path(__file__).with_name("request_frames.txt")
THRESHOLD = 0.9  # P(FRAME) at or above which a unit is dropped
N_MESSAGES = 4000

# a unit ends at a line break or after a sentence's end (not a list's number, "1. Carrot")
_BREAK = re.compile(r"\n+|(?<=[A-Za-z0-9)\]][.!?])\s+")
_LABEL = re.compile(r"^(.{1,40}?):\s+(?=\S)")  # a label before a colon, "Note 3: ...", "[10:20] Sam: ..."
_WORD = re.compile(r"[a-z0-9']+")
_ORDER_CATS = ("order", "any_order", "delay", "condition")
_SIZES = ((1, "1"), (2, "2"), (3, "3"), (6, "4-6"), (12, "7-12"), (10**9, "13+"))  # a unit's words


def units(text: str) -> list[tuple[int, int]]:
    """The character ranges of `text`'s units: lines, sentences, and a short label before a colon."""
    out, start = [], 0
    for m in [*_BREAK.finditer(text), None]:
        end = m.start() if m else len(text)
        piece = text[start:end]
        lead = len(piece) - len(piece.lstrip())
        label = _LABEL.match(piece[lead:])
        if label and len(label[1].split()) <= 6 and piece[lead + label.end() :].strip():
            out.append((start + lead, start + lead + label.end(1) + 1))
            lead += label.end()
        if piece[lead:].strip():
            out.append((start + lead, start + len(piece.rstrip())))
        start = m.end() if m else len(text)
    return out


@lru_cache(maxsize=16384)
def _kinds(unit: str) -> frozenset[str]:
    """What a unit names by the package's lexicon: thing, verb, count, negation, order, person, time."""
    out = {"thing"} if find_mentions(unit.lower()) else set()
    for w in _WORD.findall(unit.lower()):
        cats = categories(w) | check1_categories(w)
        out |= {c.split("_")[0] for c in cats if c.startswith(("verb_", "count_", "noun_"))}
        out |= {"order" for c in cats if c in _ORDER_CATS}
        out |= {c for c in cats if c in ("negation", "person", "person_relation", "time", "hedge")}
    return frozenset(out)


@lru_cache(maxsize=1)
def _keeps() -> frozenset[str]:
    """The words that point at the tasks or their order (`request_frames.txt`'s `keeps`: "Do them in that
    order.")."""
    return frozenset(w for line in _sentence_pools()["keeps"].get("words", []) for w in line.split())


def content(unit: str) -> bool:
    """Whether a unit names an object, an action, a count (a number too, unless a clock's), a negation or
    an order (check 1's content: the kinds `content_words.names_content` asks with `refused_only`), or
    holds a word that keeps a fragment (`frame_keeps.txt`) or points at the tasks (`_keeps`)."""
    said = re.sub(r"\d+:\d\d", " ", unit.lower())
    if re.search(r"\d", said) or set(_WORD.findall(said)) & (frame_keeps() | _keeps()):
        return True
    words = _WORD.findall(unit.lower())
    return bool(find_mentions(unit.lower())) or any(names_content(w, refused_only=True) for w in words)


def _shape(unit: str) -> list[str]:
    words = _WORD.findall(unit.lower())
    n = len(words)
    size = next(name for top, name in _SIZES if n <= top)
    end = unit.rstrip()[-1:]
    out = [f"len={size}", f"end={end if end in '.!?:,' else 'w'}", *(f"k={k}" for k in sorted(_kinds(unit)))]
    out += ["digit"] * bool(re.search(r"\d", unit)) + ["clock"] * bool(re.search(r"\d:\d\d", unit))
    out += ["caps"] * (unit[:1].isupper()) + ["allcaps"] * (unit.isupper() and n > 0)
    out += ["bare"] * (not _kinds(unit))
    return out


def unit_features(text: str, ranges: list[tuple[int, int]]) -> list[list[str]]:
    """Each unit's features: its own shape and words at its edges, its place, and its neighbours' shape."""
    shapes = [_shape(text[a:b]) for a, b in ranges]
    out = []
    for i, (a, b) in enumerate(ranges):
        words = _WORD.findall(text[a:b].lower()) or ["_"]
        last = len(ranges) - 1
        where = "only" if last == 0 else "first" if i == 0 else "last" if i == last else "mid"
        f = ["bias", f"pos={where}", f"w0={words[0]}", f"wn={words[-1]}", *shapes[i]]
        f += [f"{where}&{s}" for s in shapes[i] if s.startswith(("k=", "len=", "bare"))]
        for side, j in (("prev", i - 1), ("next", i + 1)):
            near = shapes[j] if 0 <= j <= last else ["none"]
            f += [f"{side}:{s}" for s in near if s.startswith(("k=", "bare", "none"))]
        out.append(f)
    return out


@dataclass
class RequestModel:
    """A logistic regression over unit features: P(FRAME)."""

    vocab: dict[str, int]
    weights: np.ndarray
    data_sha: str = ""

    def frame_probability(self, text: str, ranges: list[tuple[int, int]]) -> list[float]:
        out = []
        for f in unit_features(text, ranges):
            z = sum(float(self.weights[self.vocab[x]]) for x in f if x in self.vocab)
            out.append(1.0 / (1.0 + np.exp(-z)))
        return out

    def save(self, path: Path) -> None:
        names = sorted(self.vocab, key=self.vocab.__getitem__)
        with atomic_path(path, "request model") as tmp:
            np.savez_compressed(tmp, names=np.array(names), weights=self.weights, sha=np.array(self.data_sha))

    @classmethod
    def load(cls, path: Path) -> RequestModel:
        z = np.load(path)
        return cls({str(n): i for i, n in enumerate(z["names"])}, z["weights"], str(z["sha"]))

    @classmethod
    def fit(cls, rows: list[tuple[list[str], bool]], l2: float = 1e-3, steps: int = 400) -> RequestModel:
        """Full-batch gradient descent (Adam) on the log loss; `rows` are (features, is FRAME)."""
        from scipy.sparse import csr_matrix

        vocab: dict[str, int] = {}
        cols = [[vocab.setdefault(x, len(vocab)) for x in dict.fromkeys(f)] for f, _ in rows]
        indptr = np.cumsum([0, *map(len, cols)])
        x = csr_matrix((np.ones(indptr[-1]), np.concatenate(cols), indptr), shape=(len(rows), len(vocab)))
        y = np.array([float(label) for _, label in rows])
        w, m, v = np.zeros(len(vocab)), np.zeros(len(vocab)), np.zeros(len(vocab))
        for t in range(1, steps + 1):
            p = 1.0 / (1.0 + np.exp(-(x @ w)))
            g = x.T @ (p - y) / len(rows) + l2 * w
            m, v = 0.9 * m + 0.1 * g, 0.999 * v + 0.001 * g * g
            w -= 0.1 * (m / (1 - 0.9**t)) / (np.sqrt(v / (1 - 0.999**t)) + 1e-8)
        return cls(vocab, w)


def _sentence_pools() -> dict[str, dict[str, list[str]]]:
    out: dict[str, dict[str, list[str]]] = {"train": {}, "held": {}, "keeps": {}}
    for line in SENTENCES_FILE.read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            head, _, text = line.partition(" | ")
            which, kind = head.split()
            out[which].setdefault(kind, []).append(text)
    return out


def frame_sentence(which: Pools, rng: random.Random) -> str:
    """One whole frame sentence drawn from the `which` pools ("Hi, Sam!", "Bit nervous about the exam.")."""
    pools = _sentence_pools()[which]
    return re.sub(r"\{(\w+)\}", lambda m: rng.choice(pools[m[1]]), rng.choice(pools["sentence"]))


def _with_sentences(s: Synth, which: Pools, rng: random.Random) -> Synth:
    """`s` with 0-2 frame sentences put at its start, its end or between two of its sentences (never in a
    span), the spans moved to match."""
    for _ in range(rng.choice([0, 1, 1, 2])):
        gaps = [0, len(s.text)] + [m.end() for m in re.finditer(r"[.!?]\s+", s.text)
                                    if not any(a < m.end() < b for a, b in s.spans)]
        at = rng.choice(gaps)
        said = frame_sentence(which, rng)
        text = f"{said} {s.text}" if at == 0 else f"{s.text[:at].rstrip()} {said} {s.text[at:].lstrip()}"
        shift = len(text) - len(s.text)
        s = replace(s, text=text, spans=[(a + shift, b + shift) if a >= at else (a, b) for a, b in s.spans])
    return s


def messages(split: str, n: int, which: Pools, seed: int) -> list[tuple[str, list[bool]]]:
    """`n` composed messages of `split`'s annotations, three in four framed by `which` pools, with frame
    sentences put in; each with its units' labels (True: FRAME, no task span in it)."""
    from nl2hltl2plan.language.learned.compose import TRAIN_STYLE, synthesise
    from nl2hltl2plan.language.learned.compose_frames import framed
    from nl2hltl2plan.language.learned.train import text_faithful_items

    rng = random.Random(seed)
    out = []
    for s in synthesise(text_faithful_items(split), n, TRAIN_STYLE, seed, said_only=False):
        s = _with_sentences(framed(s, which, rng) if rng.random() < 0.75 else s, which, rng)
        ranges = units(s.text)
        out.append((s.text, [not any(a < e and c < b for c, e in s.spans) for a, b in ranges]))
    return out


def _rows(data: list[tuple[str, list[bool]]]) -> list[tuple[list[str], bool]]:
    return [r for text, labels in data for r in zip(unit_features(text, units(text)), labels, strict=True)]


def training_data(n: int = N_MESSAGES, seed: int = 0) -> list[tuple[str, list[bool]]]:
    return messages("train", n, "train", seed)


def accuracy(model: RequestModel, data: list[tuple[str, list[bool]]]) -> dict[str, float]:
    """Units right, FRAME units called FRAME at THRESHOLD (recall), and REQUEST units called FRAME at
    THRESHOLD (the harm: a request unit dropped)."""
    right = frames = caught = requests = lost = 0
    for text, labels in data:
        for p, frame in zip(model.frame_probability(text, units(text)), labels, strict=True):
            right += (p >= 0.5) == frame
            frames, requests = frames + frame, requests + (not frame)
            caught += frame and p >= THRESHOLD
            lost += (not frame) and p >= THRESHOLD
    n = frames + requests
    return {"units": n, "right": right / n, "frame_recall": caught / max(frames, 1),
            "request_dropped": lost / max(requests, 1)}


def train_and_report(out: Path, seed: int = 0) -> str:
    from nl2hltl2plan.language.learned.data import data_fingerprint

    t0 = time.monotonic()
    data = training_data(seed=seed)
    model = RequestModel.fit(_rows(data))
    model.data_sha = data_fingerprint(data)
    model.save(out)
    lines = [f"request units: {len(data)} messages in {time.monotonic() - t0:.0f} s (seed {seed}) -> {out}"]
    pool_sets: tuple[Pools, ...] = ("train", "held")
    for which in pool_sets:
        name = f"{which} pools, valid_unseen"
        acc = accuracy(model, messages("valid_unseen", 400, which, seed + 7))
        said = (f"{k} {v:.0f}" if k == "units" else f"{k} {v:.3f}" for k, v in acc.items())
        lines.append(f"{name}: " + ", ".join(said))
    return "\n".join(lines)


def request_model_path() -> Path:
    from nl2hltl2plan.language.learned.slot_model import preferred_path

    return preferred_path(ARTIFACT)


@lru_cache(maxsize=1)
def load_request_model() -> RequestModel:
    return RequestModel.load(request_model_path())


def frames_classified(text: str, names: frozenset[str], dropped: list[str]) -> str:
    """`text` without the units the model calls FRAME at THRESHOLD that name nothing check 1 asks about
    (`content`, nor a word of the world's `names`); each dropped unit is added to `dropped` (the result's
    assumptions). Unchanged with NL2HLTL2PLAN_REQUEST_UNITS=0 (`config.reading_settings`: on by default),
    and when every unit would go."""
    ranges = units(text)
    if len(ranges) < 2 or not request_units_on():
        return text
    probs = load_request_model().frame_probability(text, ranges)
    kept: list[str] = []
    gone: list[str] = []
    # labels of several parts ("Leo: ... Mia: ..."): whose part each is, which an order may name
    labels = sum(text[a:b].endswith(":") for a, b in ranges) > 1
    for (a, b), p in zip(ranges, probs, strict=True):
        unit = text[a:b]
        named = set(_WORD.findall(unit.lower())) & names
        # a name said again elsewhere is pointed at ("Tom: ... Ella: ... Tom before Ella."): kept
        rest = text[:a] + text[b:]
        again = any(re.search(rf"\b{w}\b", rest) for w in re.findall(r"\b[A-Z][a-z]+\b", unit))
        keep = content(unit) or named or again or labels and unit.endswith(":")
        (gone if p >= THRESHOLD and not keep else kept).append(unit)
    if not kept or not gone:
        return text
    dropped.extend(u.strip(" ,.!?;:") for u in gone)
    return " ".join(kept)
