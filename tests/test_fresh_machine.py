"""What a new user meets first: a CLI that starts without importing the pipeline, help lines that match
the commands, data errors that say where to put the data, a README whose two commands CI runs."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from nl2hltl2plan.cli.commands import COMMANDS
from nl2hltl2plan.cli.main import build_parser, main
from nl2hltl2plan.config import DATA_ENV, data_dir, data_path
from nl2hltl2plan.errors import DataError

ROOT = Path(__file__).resolve().parents[1]


def test_top_level_help_imports_no_command() -> None:
    # the heavy modules (pipeline, scipy, Spot) load only for the command that needs them
    code = (
        "import sys; from nl2hltl2plan.cli.main import main\n"
        "try:\n    main(['--help'])\nexcept SystemExit:\n    pass\n"
        "heavy = [m for m in ('nl2hltl2plan.pipeline', 'scipy', 'spot', 'pydantic', 'networkx')\n"
        "         if m in sys.modules]\n"
        "print('heavy:' + ','.join(heavy))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert "COMMAND" in out.stdout and out.stdout.strip().splitlines()[-1] == "heavy:"


def test_every_command_is_listed_with_the_help_it_registers() -> None:
    parser = build_parser("*")
    sub = next(a for a in parser._actions if a.dest == "command")
    registered = {c.dest: c.help for c in sub._choices_actions}  # type: ignore[attr-defined]
    assert registered == COMMANDS
    for name in COMMANDS:  # the stub of every other command keeps its help line
        stubbed = next(a for a in build_parser(name)._actions if a.dest == "command")
        assert {c.dest: c.help for c in stubbed._choices_actions} == COMMANDS  # type: ignore[attr-defined]


def test_a_command_runs_with_only_its_own_module(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", "--help"]) == 0
    assert "usage: nl2hltl2plan check" in capsys.readouterr().out
    assert main(["nonsense"]) == 2
    assert "invalid choice: 'nonsense'" in capsys.readouterr().err


def test_missing_data_names_the_setting_the_folder_and_its_contents(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(DATA_ENV, str(tmp_path / "nowhere"))
    with pytest.raises(DataError) as err:
        data_dir()
    assert DATA_ENV in str(err.value) and str(tmp_path / "nowhere") in str(err.value)
    assert "alfred/" in str(err.value) and "benchmark/" in str(err.value)
    monkeypatch.setenv(DATA_ENV, str(tmp_path))  # the folder exists, a file does not
    with pytest.raises(DataError, match="missing data file .*layouts.* in the data folder") as err:
        data_path("alfred", "layouts")
    assert DATA_ENV in str(err.value)


def _readme_command(n: int) -> str:  # as .ci/run reads it: the line under "# n."
    lines = (ROOT / "README.md").read_text().splitlines()
    return next(lines[i + 1] for i, line in enumerate(lines) if line.startswith(f"# {n}."))


def test_the_readme_is_an_entry_point_whose_commands_ci_runs() -> None:
    readme = (ROOT / "README.md").read_text()
    assert len(readme.splitlines()) <= 200
    install, tests = _readme_command(1), _readme_command(2)
    assert install.startswith("python3 -m pip install") and "nl2hltl2plan plan" in install
    assert tests == "python3 -m pytest -q"
    ci = (ROOT / ".ci" / "run").read_text()
    assert 'eval "$install_line"' in ci and 'eval "$test_line"' in ci and "python3 -m venv" in ci
    assert "deptry" in ci
    assert 'sweep_line="python3 -m pytest -q -m sweep"' in ci and 'eval "$sweep_line"' in ci


def test_an_idle_robot_is_explained() -> None:
    # one task, two robots: the summed-travel objective leaves the far robot idle, and says why
    from nl2hltl2plan.pipeline import PipelineOptions, run
    from nl2hltl2plan.worlds import load_world

    out = run("put a cup in the upper rack", load_world("demo"), robots=2)
    assert out.ok
    note = out.idle_note()
    assert note is not None and "stays idle" in note and "'minmax'" in note
    assert out.to_json()["idle_note"] == note
    team = run("put a cup in the upper rack", load_world("demo"), robots=1,
               options=PipelineOptions(objective="minmax"))
    assert team.idle_note() is None  # a single robot is never "idle beside the others"
