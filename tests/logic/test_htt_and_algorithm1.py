"""HTT validation, Algorithm 1, and the exactness of the hierarchy's semantics and flattening."""

import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.htt import HTT
from nl2hltl2plan.language.spec_builder import build_spec
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.flatten import flatten
from nl2hltl2plan.logic.trace import TraceEvent, check_trace

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_example_1_dishwasher_matches_the_paper():
    spec = build_spec(HTT.load(EXAMPLES / "dishwasher_htt.json"))
    paper = {  # Example 1, with the paper's phi and pi renamed to the HTT's task ids
        "task1": "F(task1.1 & F task1.2)",
        "task1.1": "F task1.1.1 & F task1.1.2 & F task1.1.3",
        "task1.2": "F(task1.2.1 & F task1.2.2)",
    }
    for name, formula in paper.items():
        assert sb.equivalent(spec.formula(name), sb.parse(formula)), name
    assert [len(level) for level in spec.levels] == [1, 2, 5]
    assert spec.leaf_actions("task1.2.2") == ["pickup(Cup)", "put(Cup,DishwasherUpperRack)"]


def node(i, text="t", children=(), actions=None):
    d = {"id": i, "text": text, "children": list(children)}
    if actions:
        d["actions"] = actions
    return d


@pytest.mark.parametrize(
    "data, match",
    [
        (
            {
                "nodes": [node("1", children=["1.1", "1.2"]), node("1.1"), node("1.2")],
                "relations": [["1.1", "1.2"], ["1.2", "1.1"]],
            },
            "cyclic",
        ),
        (
            {
                "nodes": [
                    node("1", children=["1.1", "1.2"]),
                    node("1.1", children=["1.1.1"]),
                    node("1.2"),
                    node("1.1.1"),
                ],
                "relations": [["1.1.1", "1.2"]],
            },
            "not between siblings",
        ),
        (
            {"nodes": [node("1", children=["1.1", "1.2"]), node("1.1", children=["1.2"]), node("1.2")]},
            "2 parents",
        ),
        ({"nodes": [node("1"), node("2")]}, "exactly one root"),
        ({"nodes": [node("1", children=["1.1"]), node("1.1", children=["1"])]}, "root|cycle"),
        ({"nodes": [node("1", children=["1.9.9"]), node("1.9.9")]}, "should be 1.<k>"),
        ({"nodes": [node("1", children=["1.1"])]}, "not a node"),
        ({"nodes": [node("1"), node("1")]}, "more than once"),
        ({"nodes": "x"}, "expected fields"),
    ],
)
def test_malformed_htt_gives_clear_error(data, match):
    with pytest.raises(HTTError, match=match):
        HTT.from_json(data)


def test_htt_json_round_trip():
    htt = HTT.load(EXAMPLES / "dishwasher_htt.json")
    assert HTT.from_json(htt.to_json()) == htt
    with pytest.raises(HTTError, match="not valid JSON"):
        HTT.from_json("{")


def test_leaf_without_actions_is_reported():
    htt = HTT.from_json({"nodes": [node("1", children=["1.1"]), node("1.1", "wash it")]})
    with pytest.raises(HTTError, match="no actions"):
        build_spec(htt)


@st.composite
def random_htt(draw):
    """A random tree (depth <= 3, <= 6 leaves) with random acyclic sibling relations."""
    nodes, relations, leaves = [], [], []

    def grow(nid, depth):
        k = draw(st.integers(0 if depth > 1 else 1, 3 if depth < 3 else 0)) if len(leaves) < 5 else 0
        kids = [f"{nid}.{i + 1}" for i in range(k)]
        nodes.append({"id": nid, "text": nid, "children": kids})
        if not kids:
            leaves.append(nid)
            nodes[-1]["actions"] = [f"act(L{nid.replace('.', '_')})"]
        order = draw(st.permutations(kids)) if kids else []
        relations.extend([a, b] for i, a in enumerate(order) for b in order[i + 1 :] if draw(st.booleans()))
        for c in kids:
            grow(c, depth + 1)

    grow("1", 1)
    htt = HTT.from_json({"nodes": nodes, "relations": relations})
    steps = {leaf: draw(st.one_of(st.none(), st.integers(1, 5))) for leaf in leaves}
    return htt, steps


def expected_completion(htt, steps):
    """Completion step of every node by direct reading of the HTT (None: never)."""
    done = {}

    def visit(nid):
        n = htt.node(nid)
        if not n.children:
            done[nid] = steps[nid]
            return done[nid]
        times = [visit(c) for c in n.children]
        ok = all(t is not None for t in times) and all(
            done[a] <= done[b] for a, b in htt.sibling_relations(nid)
        )
        done[nid] = max(times) if ok else None
        return done[nid]

    visit("1")
    return done


@settings(max_examples=120, deadline=None)
@given(random_htt())
def test_spec_of_random_htt_accepts_exactly_the_traces_that_respect_every_relation(case):
    htt, steps = case
    spec = build_spec(htt)
    trace = [
        TraceEvent(t, htt.node(leaf).actions[0], f"task{leaf}") for leaf, t in steps.items() if t is not None
    ]
    result = check_trace(spec, trace)
    expected = expected_completion(htt, steps)
    assert result.ok == (expected["1"] is not None)
    if result.ok:
        assert result.completed["task1"] == expected["1"]
    # the exact flat formula (attributed atoms) agrees with the hierarchy
    if len(steps) <= 4:
        flat = sb.dfa(sb.parse(flatten(spec)), timeout_s=60)
        horizon = max([t for t in steps.values() if t] + [1])
        word = [
            {f"task{leaf}:{htt.node(leaf).actions[0]}" for leaf, t in steps.items() if t == s}
            for s in range(1, horizon + 1)
        ]
        assert flat.accepts(word) == result.ok


def test_cli_spec_json_round_trips(tmp_path, capsys):
    from nl2hltl2plan.cli.main import main

    assert main(["spec", str(EXAMPLES / "dishwasher_htt.json"), "--json"]) == 0
    levels = json.loads(capsys.readouterr().out)["levels"]
    spec_file = tmp_path / "spec.json"
    spec_file.write_text(json.dumps(levels))
    assert main(["check", str(spec_file)]) == 0
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps([{"a": "G b"}]))
    assert main(["check", str(bad)]) == 1
    assert "G (always)" in capsys.readouterr().out
    (tmp_path / "junk.json").write_text("nope")
    assert main(["check", str(tmp_path / "junk.json")]) == 2
    assert main(["show", str(EXAMPLES / "dishwasher_htt.json"), "-o", str(tmp_path / "t.png")]) == 0
    assert main(["show", str(spec_file), "-o", str(tmp_path / "s.png")]) == 0
    assert (tmp_path / "t.png").stat().st_size > 1000 and (tmp_path / "s.png").stat().st_size > 1000


def test_cli_reports_bad_htt_without_traceback(tmp_path, capsys):
    from nl2hltl2plan.cli.main import main

    f = tmp_path / "cyclic.json"
    f.write_text(
        json.dumps(
            {
                "nodes": [
                    node("1", children=["1.1", "1.2"]),
                    node("1.1", actions=["a(X)"]),
                    node("1.2", actions=["b(X)"]),
                ],
                "relations": [["1.1", "1.2"], ["1.2", "1.1"]],
            }
        )
    )
    assert main(["spec", str(f)]) == 2
    assert "cyclic" in capsys.readouterr().err
