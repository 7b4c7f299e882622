"""Every command, driven with the bad inputs a new user or a tester tries: each must end with one line
on stderr naming the problem and the documented exit status (2 bad input, 1 a definite "no"), never a
traceback (an exception escaping `main` fails the test) and never a silent success."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from nl2hltl2plan.cli.main import main

EXAMPLE_HTT = str(Path(__file__).resolve().parents[1] / "examples" / "dishwasher_htt.json")
PLATES = "Put the plates in the lower rack"
DISHWASHER = (
    "Put the plates, mugs and utensils in the lower rack in any order; after that, first the saucers, "
    "then the cups, in the upper rack"
)


@pytest.fixture(scope="module")
def files(tmp_path_factory: pytest.TempPathFactory) -> dict[str, str]:
    d = tmp_path_factory.mktemp("bad")
    out = {
        "binary": d / "binary.json",
        "deep": d / "deep.json",
        "torn": d / "torn.json",
        "not_spec": d / "not_spec.json",
        "invalid_spec": d / "invalid_spec.json",
        "cyclic_htt": d / "cyclic_htt.json",
    }
    out["binary"].write_bytes(b"\x00\x01\xff\xfe\x80")
    out["deep"].write_text("[" * 10_000 + "]" * 10_000)
    out["torn"].write_text('{"a": ')
    out["not_spec"].write_text(json.dumps({"hello": 1}))
    out["invalid_spec"].write_text(json.dumps([{"task1": "G a"}]))
    htt = json.loads(Path(EXAMPLE_HTT).read_text())
    kids = [n["id"] for n in htt["nodes"] if n["id"].count(".") == 1]
    htt["relations"] = [[kids[0], kids[1]], [kids[1], kids[0]]]
    out["cyclic_htt"].write_text(json.dumps(htt))
    return {k: str(v) for k, v in out.items()}


def _case_id(case: object) -> str:
    values = getattr(case, "values", case)
    return str(values[0])  # type: ignore[index]


CASES = [
    # (id, argv with {placeholders}, exit status, words the one-line error must contain)
    ("spec-missing", ["spec", "/nonexistent/htt.json"], 2, "no such file"),
    ("spec-folder", ["spec", "/tmp"], 2, "folder"),
    ("spec-binary", ["spec", "{binary}"], 2, "not UTF-8"),
    ("spec-deep", ["spec", "{deep}"], 2, "nested deeper"),
    ("spec-torn", ["spec", "{torn}"], 2, "not valid JSON"),
    ("spec-dev-zero", ["spec", "/dev/zero"], 2, "character device, not a regular file"),
    ("spec-cyclic-relations", ["spec", "{cyclic_htt}"], 2, "cyclic"),
    ("check-binary", ["check", "{binary}"], 2, "not UTF-8"),
    ("check-deep", ["check", "{deep}"], 2, "nested deeper"),
    ("check-dev-zero", ["check", "/dev/zero"], 2, "character device, not a regular file"),
    ("check-invalid", ["check", "{invalid_spec}"], 1, "not sc-LTL"),
    ("show-deep", ["show", "{deep}", "-o", "{tmp}/x.png"], 2, "nested deeper"),
    ("show-format", ["show", EXAMPLE_HTT, "-o", "{tmp}/x.xyz"], 2, "unknown format"),
    ("show-unwritable", ["show", EXAMPLE_HTT, "-o", "/proc/nl2/x.png"], 2, "cannot write"),
    ("show-not-a-spec", ["show", "{not_spec}", "-o", "{tmp}/x.png"], 2, "list of levels"),
    ("world-unknown", ["world", "FloorPlan99999"], 2, "FloorPlan99999"),
    ("world-format", ["world", "demo", "-o", "{tmp}/x.xyz"], 2, "unknown format"),
    ("world-gif-needs-run", ["world", "demo", "--gif", "{tmp}/x.gif"], 2, "--run"),
    ("plan-no-task", ["plan", "hello there", "--world", "demo"], 2, "understood no task"),
    ("plan-empty", ["plan", "   ", "--world", "demo"], 2, "empty instruction"),
    ("plan-missing-object", ["plan", "put the statue in the sink", "--world", "demo"], 2, "no Statue"),
    (
        "plan-contradictory-order",
        [
            "plan",
            "Put the saucers in the upper rack before the cups. Put the cups in the upper rack before the "
            "saucers.",
        ],
        2,
        "contradictory ordering",
    ),
    ("plan-robots-0", ["plan", PLATES, "--robots", "0"], 2, "--robots"),
    ("plan-robots-huge", ["plan", PLATES, "--robots", "1000000"], 2, "at most"),
    pytest.param(
        "plan-robots-unknown-profile",
        ["plan", PLATES, "--robots", "two"],
        2,
        "unknown robot profile",
        marks=pytest.mark.data,
    ),
    ("plan-timeout-nan", ["plan", PLATES, "--timeout", "nan"], 2, "--timeout"),
    ("plan-timeout-inf", ["plan", PLATES, "--timeout", "inf"], 2, "--timeout"),
    ("plan-timeout-negative", ["plan", PLATES, "--timeout", "-1"], 2, "--timeout"),
    ("plan-llm-timeout-0", ["plan", PLATES, "--llm-timeout", "0"], 2, "--llm-timeout"),
    ("plan-unknown-world", ["plan", PLATES, "--world", "Kitchen9"], 2, "Kitchen9"),
    ("plan-starts-bad", ["plan", PLATES, "--starts", "a,b"], 2, "r,c"),
    ("plan-starts-count", ["plan", PLATES, "--robots", "2", "--starts", "0,0"], 2, "start cell"),
    ("plan-starts-blocked", ["plan", PLATES, "--starts=999,999"], 2, "not a free cell"),
    ("plan-out-unwritable", ["plan", PLATES, "-o", "/proc/nl2/out"], 2, "cannot write"),
    ("plan-out-is-file", ["plan", PLATES, "-o", "{binary}"], 2, "is a file"),
    ("plan-timeout-no-plan", ["plan", DISHWASHER, "--robots", "2", "--timeout", "0.01"], 1, "no plan"),
    ("bench-no-source", ["bench", "alfred", "-o", "{tmp}/b"], 2, "--oracle"),
    ("bench-timeout-0", ["bench", "alfred", "--oracle", "--timeout", "0", "-o", "{tmp}/b"], 2, "--timeout"),
    ("bench-workers-0", ["bench", "alfred", "--oracle", "--workers", "0", "-o", "{tmp}/b"], 2, "--workers"),
    ("bench-robots-bad", ["bench", "alfred", "--oracle", "--robots", "1,x", "-o", "{tmp}/b"], 2, "--robots"),
    ("bench-out-unwritable", ["bench", "alfred", "--oracle", "-o", "/proc/nl2/b"], 2, "cannot write"),
    pytest.param(
        "bench-gt-binary",
        ["bench", "alfred", "--oracle", "--gt", "{binary}", "-o", "{tmp}/b"],
        2,
        "not UTF-8",
        marks=pytest.mark.data,
    ),
    ("bench-unknown-suite", ["bench", "nosuch", "-o", "{tmp}/b"], 2, "invalid choice"),
    ("unknown-command", ["frobnicate"], 2, "invalid choice"),
]


@pytest.mark.whole  # each case is another input's refusal, not one path read many times
@pytest.mark.parametrize(("name", "argv", "code", "words"), CASES, ids=[_case_id(c) for c in CASES])
def test_bad_input_gives_one_line_error(
    name: str,
    argv: list[str],
    code: int,
    words: str | None,
    files: dict[str, str],
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    args = [a.format(tmp=tmp_path, **files) for a in argv]
    assert main(args) == code
    err = capsys.readouterr().err
    lines = [line for line in err.splitlines() if line.strip() and not line.startswith("note:")]
    assert len(lines) == 1, err
    assert lines[0].startswith("error:"), err
    if words is not None:
        assert words.lower() in lines[0].lower(), err
    assert "Traceback" not in err


def _gt_file(tmp_path: Path, **update: object) -> Path:
    from nl2hltl2plan.config import data_dir

    if data_dir(required=False) is None:
        pytest.skip("needs ../shared/data")
    from nl2hltl2plan.suites.alfred.ground_truth import load_gt

    base = next(g for g in load_gt() if g.n_base == 2 and g.feasible)
    a, b = base.tasks[0].id, base.tasks[1].id
    row = base.model_dump(mode="json")
    if update.get("cyclic"):
        row.update(id="cyclic", before=[[a, b], [b, a]])
    if update.get("count"):
        row["tasks"][0]["count"] = update["count"]
    path = tmp_path / "gt.jsonl"
    path.write_text(json.dumps(row) + "\n")
    return path


def test_bench_with_a_cyclic_ground_truth_row_errors_that_row_and_exits_1(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A contradiction in a ground-truth row is refused (an errored scenario naming the cycle), and the
    run exits non-zero: never planned without the ordering, never a silent 0."""
    gt = _gt_file(tmp_path, cyclic=True)
    argv = [
        "bench",
        "alfred",
        "--oracle",
        "--gt",
        str(gt),
        "--robots",
        "1",
        "--quiet",
        "--workers",
        "1",
        "-o",
        str(tmp_path / "out"),
    ]
    assert main(argv) == 1
    assert "1 of 1 scenarios errored" in capsys.readouterr().err
    row = json.loads((tmp_path / "out" / "scenarios.jsonl").read_text())
    assert row["status"] == "error" and "cyclic ordering" in row["reason"]


def test_bench_refuses_an_absurd_count_before_any_work(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    gt = _gt_file(tmp_path, count=1_000_000)
    assert main(["bench", "alfred", "--oracle", "--gt", str(gt), "-o", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("error:") and "count" in err and "\n" not in err


def test_a_bug_is_one_line_with_its_own_status(monkeypatch: pytest.MonkeyPatch, capsys) -> None:
    from nl2hltl2plan.cli import main as cli_main

    def broken(args: object) -> int:
        raise ValueError("zero-size array\nto reduction operation")

    real = cli_main.build_parser

    def build(command: str | None = "*"):  # type: ignore[no-untyped-def]
        parser = real(command)  # the `check` command, its handler replaced by one with a bug
        sub = next(a for a in parser._actions if a.dest == "command")
        sub.choices["check"].set_defaults(func=broken)
        return parser

    monkeypatch.setattr(cli_main, "build_parser", build)
    monkeypatch.delenv("NL2HLTL2PLAN_DEBUG", raising=False)
    assert main(["check", "x.json"]) == 4
    err = capsys.readouterr().err.strip()
    assert err.startswith("internal error: ValueError: zero-size array | to reduction operation")
    assert len(err.splitlines()) == 1
    monkeypatch.setenv("NL2HLTL2PLAN_DEBUG", "1")  # developers get the traceback
    with pytest.raises(ValueError):
        main(["check", "x.json"])
