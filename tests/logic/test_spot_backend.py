
import pytest

from nl2hltl2plan.errors import FormulaError
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.automaton import distinguishing_word


def test_paper_syntax_and_dotted_and_quoted_names_parse():
    f = sb.parse('<>(task1.1 && <> "put(Apple,Fridge)") || [](a)')
    assert set(f.atoms) == {"task1.1", "put(Apple,Fridge)", "a"}
    assert sb.parse("F(task1.1 & F task1.2)") == sb.parse("<>(task1.1 && <> task1.2)")


def test_malformed_formula_reports_spot_pointer():
    with pytest.raises(FormulaError) as exc:
        sb.parse("F(a &")
    msg = str(exc.value)
    assert msg == "cannot parse formula 'F(a &': syntax error, unexpected end of formula at character 6"
    for junk in ("F(a\x00b)", "\xff\xfe\x00", "F(" * 3 + "a", "a U U b"):
        with pytest.raises(FormulaError, match="cannot parse formula") as exc:
            sb.parse(junk)
        assert "\n" not in str(exc.value)


@pytest.mark.parametrize(
    "text, fragment",
    [
        ("G a", "G (always)"),
        ("a R b", "R (release)"),
        ("a W b", "W (weak until)"),
        ("a M b", "M (strong"),
        ("!(a & b)", "negation is only allowed"),
        ("a -> F b", "->"),
        ("F !F a", "negation"),
    ],
)
def test_non_sc_ltl_is_rejected_with_reason(text, fragment):
    problems = sb.sc_ltl_problems(sb.parse(text))
    assert problems and any(fragment in p for p in problems)
    with pytest.raises(FormulaError, match="not sc-LTL"):
        sb.dfa(sb.parse(text))


@pytest.mark.parametrize("text", ["F a", "a U b", "F(a & X b)", "!a U (b | c)", "F(a & F(b & F c))"])
def test_sc_ltl_accepted(text):
    assert sb.sc_ltl_problems(sb.parse(text)) == []


def test_dfa_reads_good_prefixes():
    d = sb.dfa(sb.parse("F(a & F b)"))
    assert d.accepts([{"a"}, set(), {"b"}])
    assert d.accepts([{"a", "b"}])
    assert not d.accepts([{"b"}, {"a"}])
    assert not d.accepts([])
    u = sb.dfa(sb.parse("!b U a"))
    assert u.accepts([set(), {"a"}]) and not u.accepts([{"b"}, {"a"}])
    assert u.is_dead(u.run([{"b"}]))


def test_dfa_size_of_independent_eventualities_is_exponential():
    for n in (2, 4, 6):
        d = sb.dfa(sb.parse(" & ".join(f"F p{i}" for i in range(n))))
        assert d.num_states == 2**n


def test_large_translation_is_guarded_by_a_time_limit():
    big = sb.parse(" & ".join(f"F p{i}" for i in range(24)))
    with pytest.raises(FormulaError, match="longer than"):
        sb.dfa(big, timeout_s=1.0)


def test_equivalence_and_distinguishing_word():
    assert sb.equivalent(sb.parse("F(a & F b)"), sb.parse("<>(a && <>b)"))
    f, g = sb.dfa(sb.parse("F a & F b")), sb.dfa(sb.parse("F(a & F b)"))
    word = distinguishing_word(f, g)
    assert word is not None
    assert f.accepts(word) != g.accepts(word)
    assert distinguishing_word(f, sb.dfa(sb.parse("F b & F a"))) is None


# ----- bounded resources (issue 10.4) --------------------------------------------------------------
@pytest.mark.parametrize(
    "steps", [["a"], ["a", "b"], ["a", "b", "a"], ["a", "a", "b"], ["c", "b", "a", "b", "c"]]
)
def test_linear_sequences_are_built_directly_and_agree_with_spot(steps):
    text = "F(" + " & F(".join(steps) + ")" * len(steps)
    f = sb.parse(text)
    assert sb.linear_sequence(f._f) == steps
    direct = sb.sequence_dfa(steps)
    via_spot = sb._to_dfa(sb._translate(f._f, small=True))
    assert distinguishing_word(direct, via_spot) is None
    assert direct.accepts([set(steps)]) and not direct.accepts([set(steps) - {steps[-1]}])


def test_next_chains_read_goals_off_accepting_components():
    d = sb.dfa(sb.parse("X " * 12 + "a"))  # 13 temporal operators: the guarded, transition-based path
    assert d.accepts([set()] * 12 + [{"a"}]) and not d.accepts([set()] * 12)
    assert not d.accepts([{"a"}] * 5)


def test_thirty_step_sequence_translates_within_a_one_second_limit():
    from nl2hltl2plan.logic.hierarchical import sequence_formula

    f = sb.parse(sequence_formula([f"pickup(A{i})" for i in range(30)]))
    d = sb.dfa(f, timeout_s=1.0)  # a slower translation raises at its limit: no wall clock here
    assert d.num_states == 31
    assert d.accepts([{f"pickup(A{i})"} for i in range(30)])
    assert not d.accepts([{f"pickup(A{i})"} for i in range(29, -1, -1)])


def test_few_atoms_many_next_operators_is_bounded_by_memory_with_one_line_error():
    f = sb.parse("F(a & " + "X " * 22 + "b)")  # 2 atoms, 2^22 + 1 states: 4.9 GB in-process before
    with pytest.raises(FormulaError) as exc:
        sb.dfa(f, timeout_s=20.0, memory_mb=256)
    msg = str(exc.value)
    assert "\n" not in msg and ("memory limit of 256 MiB" in msg or "time limit" in msg)


def test_automaton_size_limit_names_the_limit():
    f = sb.parse("F(a & " + "X " * 12 + "b)")
    with pytest.raises(FormulaError, match=r"has 4097 states, more than the limit of 1000"):
        sb.dfa(f, max_states=1000)
    assert sb.dfa(f).num_states >= 4097  # within the default limit it translates


@pytest.mark.parametrize("bad", [float("nan"), 0.0, -1.0, float("inf")])
def test_invalid_time_limits_are_refused(bad):
    big = sb.parse(" & ".join(f"F q{i}" for i in range(9)))
    with pytest.raises(FormulaError, match="time limit must be a finite number"):
        sb.dfa(big, timeout_s=bad)


def test_the_formula_caches_answer_as_spot_does_and_share_nothing_mutable():
    """`equivalent`, `atoms` and `sc_ltl_problems` remember their answers per Spot formula (h70): the
    cached answer equals a fresh one from Spot, and a caller that edits a returned list edits a copy."""
    import spot

    pairs = [("F(a & F b)", "F(a & F b)"), ("F a & F b", "F b & F a"), ("F(a & F b)", "F(b & F a)"),
             ("F a | F b", "F(a | b)"), ("a U b", "F b")]  # fmt: skip
    for _ in range(2):  # the second round answers from the caches
        for x, y in pairs:
            fx, fy = sb.parse(x), sb.parse(y)
            assert sb.equivalent(fx, fy) == bool(spot.are_equivalent(spot.formula(x), spot.formula(y)))
            names = {str(g) for g in spot.atomic_prop_collect(spot.formula(x))}
            assert isinstance(fx.atoms, tuple) and set(fx.atoms) == names
    assert sb.equivalent(sb.parse("F a & F b"), sb.parse("F b & F a"))
    assert not sb.equivalent(sb.parse("F(a & F b)"), sb.parse("F(b & F a)"))
    problems = sb.sc_ltl_problems(sb.parse("G a"))
    assert problems and "G (always)" in problems[0]
    problems.append("edited by a caller")
    assert sb.sc_ltl_problems(sb.parse("G a")) == problems[:-1]
    assert sb.sc_ltl_problems(sb.parse("F a")) == []
    for text in ("G a", "!F a", "F(a & X b)"):  # the same as the functions without their caches
        f = sb.parse(text)
        assert tuple(sb.sc_ltl_problems(f)) == sb._sc_ltl_problems.__wrapped__(f._f)
        assert f.atoms == sb._atoms.__wrapped__(f._f)
