"""The relation head: spans that point back at an earlier span, the order decoded from them, and
deterministic training."""

from __future__ import annotations

import random
from pathlib import Path

import networkx as nx
import pytest

from nl2hltl2plan.language.learned.compose import RELATIONS
from nl2hltl2plan.language.learned.relation_head import RelationHead, pair_features, ref_words
from nl2hltl2plan.language.learned.span_order import before_pairs, drop_cycles
from nl2hltl2plan.language.learned.structure import load_structure, tokenize


def test_any_relations_and_targets_decode_to_a_partial_order() -> None:
    rng = random.Random(5)
    for _ in range(2000):
        n = rng.randrange(1, 7)
        rels = [rng.choice(RELATIONS) for _ in range(n)]
        targets = [rng.randrange(-1, n + 1) if rng.random() < 0.7 else None for _ in range(n)]
        pairs = before_pairs(rels, targets)
        g = nx.DiGraph(pairs)
        assert nx.is_directed_acyclic_graph(g), (rels, targets, pairs)
        assert all(0 <= a < n and 0 <= b < n for a, b in pairs)


def test_a_pair_that_closes_a_cycle_is_dropped_and_the_rest_kept() -> None:
    assert drop_cycles([(0, 1), (1, 2), (2, 0), (2, 3)]) == {(0, 1), (1, 2), (2, 3)}


def test_pointing_relations_order_the_named_span() -> None:
    # A. B at any time. After putting the A-object, C. Before the B-object, D. Once everything is done, E.
    rels = ["START", "FREE", "REF", "RPRE", "ALL"]
    pairs = set(before_pairs(rels, [None, None, 0, 1, None]))
    assert (0, 2) in pairs and (3, 1) in pairs
    assert {(x, 4) for x in range(4)} <= set(nx.transitive_closure(nx.DiGraph(pairs)).edges)
    assert (1, 2) not in pairs and (2, 3) not in pairs  # nothing else is ordered


def _words(text: str) -> list[str]:
    return [w for w, _, _ in tokenize(text)]


def test_the_features_see_the_object_the_later_sentence_shares() -> None:
    words = _words("put a pan on the stove. wash the mug in the sink. once the pan sits there, cool a pear")
    spans = [(0, 6), (7, 13), (20, 23)]
    assert ref_words(words, spans, 2) == ["pan", "sits", "there"]
    rows = pair_features(words, spans, 2)
    assert rows.shape == (2, 12)
    assert rows[0].tolist() != rows[1].tolist()


def test_the_committed_head_points_at_the_span_named_three_sentences_back() -> None:
    model = load_structure()
    assert model.head is not None
    text = (
        "Put the pan on the stove. Wash the mug in the sink. Put the apple in the fridge. "
        "Once the pan is sitting on the stove, put the bread on the table."
    )
    words = _words(text)
    reading = model.read(text)
    spans = [s.text for s in reading.spans]
    assert spans[-1] == "put the bread on the table", spans
    assert reading.spans[-1].relation == "REF" and reading.spans[-1].target == 0
    j, p = model.head.target(words, [(0, 6), (7, 13), (14, 20), (31, 37)], 3)
    assert j == 0 and p > 0.5


def test_the_head_learns_the_shared_object_and_rebuilds_identically(tmp_path: Path) -> None:
    pytest.importorskip("pycrfsuite")
    from nl2hltl2plan.language.learned.structure_train import fit

    texts = [
        ("put the pan on the stove. wash the mug in the sink. after the pan, chill an apple", 0),
        ("put the cup on the desk. wash the pan in the sink. after the pan, chill an apple", 1),
    ]
    cases = []
    for text, gold in texts * 3:
        words = _words(text)
        cases.append((words, [(0, 6), (7, 13), (18, 21)], 2, gold))
    head = RelationHead.fit(cases)
    for text, gold in texts:
        assert head.target(_words(text), [(0, 6), (7, 13), (18, 21)], 2)[0] == gold
    from nl2hltl2plan.language.learned.structure import features, tags_of

    text = "put the mug in the sink, then put the apple in the fridge."
    words, tags = tags_of(text, [(0, 23), (30, 57)], ["START", "SEQ"])
    for name in ("a", "b"):
        fit([(features(words), tags)] * 5, cases, iterations=20).save(tmp_path / f"{name}.npz")
    assert (tmp_path / "a.npz").read_bytes() == (tmp_path / "b.npz").read_bytes()
