"""One parser for the action atom: `logic.atom.Atom`. No other module may parse atoms with its own
regular expression (the architecture issue found seven that disagreed)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from nl2hltl2plan.errors import SpecError
from nl2hltl2plan.logic.atom import Atom

SRC = Path(__file__).resolve().parents[2] / "src" / "nl2hltl2plan"
# a compiled pattern with a lower-case verb class followed by an escaped "(": an atom parser of its own
ATOM_REGEX = re.compile(r"re\.compile\(.*\[a-z.*\\\(")


def test_atoms_print_as_they_parse() -> None:
    for text in ("pickup(Apple)", "put(Apple,Fridge)", "at(Blue,@Red)", "toggle_on(Faucet_1)"):
        assert str(Atom.parse(text)) == text
    assert Atom.parse(' "put( Mug , SinkBasin )" ') == Atom("put", ("Mug", "SinkBasin"))
    for bad in ("", "pickup", "pickup()", "Put(Apple)", "put(Apple,)", "put(Apple))", "grab apple"):
        assert Atom.read(bad) is None
        with pytest.raises(SpecError, match="is not an action atom"):
            Atom.parse(bad)


def test_no_module_parses_atoms_with_a_regex_of_its_own() -> None:
    offenders = [
        f"{path.relative_to(SRC)}:{n}"
        for path in SRC.rglob("*.py")
        if path.name != "atom.py"
        for n, line in enumerate(path.read_text().splitlines(), start=1)
        if ATOM_REGEX.search(line)
    ]
    assert offenders == []
