import pytest

from nl2hltl2plan.errors import SpecError
from nl2hltl2plan.logic.flatten import flattens_exactly, size_report
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec, sequence_formula
from nl2hltl2plan.logic.trace import TraceEvent, check_trace

DISHWASHER = [
    {"task1": "F(task1.1 & F task1.2)"},
    {"task1.1": "F task1.1.1 & F task1.1.2", "task1.2": "F(task1.2.1 & F task1.2.2)"},
    {
        "task1.1.1": ["pickup(Plate)", "put(Plate,DishwasherLowerRack)"],
        "task1.1.2": ["pickup(Mug)", "put(Mug,DishwasherLowerRack)"],
        "task1.2.1": ["pickup(Saucer)", "put(Saucer,DishwasherUpperRack)"],
        "task1.2.2": ["pickup(Cup)", "put(Cup,DishwasherUpperRack)"],
    },
]


def events(*items):
    return [TraceEvent(t, atom, task) for t, (task, atom) in enumerate(items, start=1)]


def place(leaf, obj, rack):
    return [(leaf, f"pickup({obj})"), (leaf, f"put({obj},{rack})")]


def test_structure():
    spec = HierarchicalSpec.from_json(DISHWASHER)
    assert spec.roots == ["task1"]
    assert spec.children("task1") == ["task1.1", "task1.2"]
    assert spec.leaves == ["task1.1.1", "task1.1.2", "task1.2.1", "task1.2.2"]
    assert spec.leaf_actions("task1.1.1") == ["pickup(Plate)", "put(Plate,DishwasherLowerRack)"]
    assert spec.parent("task1.2.2") == "task1.2"
    assert HierarchicalSpec.from_json(spec.to_json()).to_json_obj() == spec.to_json_obj()


def test_trace_respecting_order_is_accepted():
    spec = HierarchicalSpec.from_json(DISHWASHER)
    ok = check_trace(
        spec,
        events(
            *place("task1.1.1", "Plate", "DishwasherLowerRack"),
            *place("task1.1.2", "Mug", "DishwasherLowerRack"),
            *place("task1.2.1", "Saucer", "DishwasherUpperRack"),
            *place("task1.2.2", "Cup", "DishwasherUpperRack"),
        ),
    )
    assert ok.ok and ok.completed["task1.1"] == 4 and ok.completed["task1"] == 8


def test_trace_breaking_order_is_rejected_with_reason():
    spec = HierarchicalSpec.from_json(DISHWASHER)
    bad = check_trace(
        spec,
        events(
            *place("task1.2.2", "Cup", "DishwasherUpperRack"),
            *place("task1.2.1", "Saucer", "DishwasherUpperRack"),
            *place("task1.1.1", "Plate", "DishwasherLowerRack"),
            *place("task1.1.2", "Mug", "DishwasherLowerRack"),
        ),
    )
    assert not bad.ok and "task1" in bad.reasons[0]


def test_events_count_only_for_their_own_leaf():
    spec = HierarchicalSpec.from_json([{"t": "F a & F b"}, {"a": ["pickup(Apple)"], "b": ["pickup(Apple)"]}])
    one = check_trace(spec, [TraceEvent(1, "pickup(Apple)", "a")])
    assert not one.ok and one.completed["b"] is None
    assert check_trace(spec, [TraceEvent(1, "pickup(Apple)", "a"), TraceEvent(2, "pickup(Apple)", "b")]).ok


def test_sequence_formula():
    assert sequence_formula(["pickup(A)", "put(A,B)"]) == 'F("pickup(A)" & F("put(A,B)"))'
    with pytest.raises(SpecError, match="not an action"):
        sequence_formula(["pick up the apple"])


@pytest.mark.parametrize(
    "levels, match",
    [
        ([{"a": "G p"}], "not sc-LTL"),
        ([{"a": "F(p"}], "cannot parse"),
        ([{"a": "F b & F x"}, {"b": "F y"}], "rule 3"),
        ([{"a": "F b"}, {"b": "F y", "c": "F z"}], "rule 2"),
        ([{"a": "F b", "c": "F b"}, {"b": "F y"}], "2 formulas"),
        ([{"a": "F b"}, {"b": "F c"}, {"c": "F y"}, {"d": "F z"}], "rule 2"),
        ([{"a": "F c"}, {"b": "F y"}, {"c": "F z"}], "rule 1"),
        ([{"a": "F b"}, {"a": "F y"}], "again"),
        ([], "non-empty"),
        ([{}], "non-empty"),
        ([{"a": 3}], "formula string"),
    ],
)
def test_definition_2_1_violations_name_the_formula(levels, match):
    with pytest.raises(SpecError, match=match):
        HierarchicalSpec.from_json(levels)


def test_not_json():
    with pytest.raises(SpecError, match="not valid JSON"):
        HierarchicalSpec.from_json("{nope")


def test_size_report_hierarchy_is_smaller_than_flat():
    spec = HierarchicalSpec.from_json(DISHWASHER)
    assert flattens_exactly(spec)
    report = size_report(spec)
    assert report.flat_states is not None and report.hierarchical_states < report.flat_states
