"""The action atom `verb(Arg,Arg)`: the one word every stage shares, with one parser and one printer.

A leaf of a hierarchical spec is a list of atoms (`pickup(Apple)`, `put(Apple,Fridge)`); the planner,
the simulator, the language stage and the handover world all read them through `Atom.parse`, and
print them with `str(atom)`. What an atom *means* (which verbs a world knows, how many arguments each
takes, whether `@Red` names a block's place) is for each reader to decide on the typed value; the
syntax is decided here, once.

>>> a = Atom.parse("put(Apple,Fridge)")
>>> a.verb, a.args, str(a)
('put', ('Apple', 'Fridge'), 'put(Apple,Fridge)')
>>> Atom.parse(' "pickup(Apple)" ').args            # quotes (Spot's atom syntax) and blanks allowed
('Apple',)
>>> Atom.parse("put(Apple, Fridge)") == Atom("put", ("Apple", "Fridge"))
True
>>> Atom.find_all('F("pickup(Mug)" & F "put(Mug,SinkBasin)")')
[Atom(verb='pickup', args=('Mug',)), Atom(verb='put', args=('Mug', 'SinkBasin'))]
>>> Atom.parse("grab the apple")
Traceback (most recent call last):
...
nl2hltl2plan.errors.SpecError: 'grab the apple' is not an action atom like verb(Type) or verb(Type,Type)
"""

from __future__ import annotations

import re
from typing import NamedTuple

from nl2hltl2plan.errors import SpecError

# a verb in lower case; each argument a type or instance name (`Apple`, `Apple_1`, `task1.2`) or a
# place reference of the handover worlds (`@Red`)
_VERB = r"[a-z_][a-z0-9_]*"
_ARG = r"@?[A-Za-z0-9_.]+"
_SYNTAX = re.compile(rf"({_VERB})\(\s*({_ARG}(?:\s*,\s*{_ARG})*)\s*\)")
_WHOLE = re.compile(rf"^\s*\"?{_SYNTAX.pattern}\"?\s*$")
# a pattern of atoms (a constraint's "any action on the microwave"): `*` stands for any argument
_PATTERN = re.compile(rf"^\s*\"?({_VERB})\(\s*((?:{_ARG}|\*)(?:\s*,\s*(?:{_ARG}|\*))*)\s*\)\"?\s*$")
_QUOTED = re.compile(rf"\"{_SYNTAX.pattern}\"")


class Atom(NamedTuple):
    """One robot action on named things: `verb(arg1,arg2)`."""

    verb: str
    args: tuple[str, ...]

    @classmethod
    def parse(cls, text: str) -> Atom:
        """The atom `text` spells (surrounding quotes and blanks allowed); SpecError when it is none."""
        atom = cls.read(text)
        if atom is None:
            raise SpecError(f"{text!r} is not an action atom like verb(Type) or verb(Type,Type)")
        return atom

    @classmethod
    def read(cls, text: str) -> Atom | None:
        """The atom `text` spells, or None."""
        m = _WHOLE.match(text)
        return None if m is None else cls._of(m)

    @classmethod
    def read_pattern(cls, text: str) -> Atom | None:
        """The atom pattern `text` spells (an atom whose arguments may be `*`: `put(*,Microwave)`), or None.

        >>> Atom.read_pattern("put(*,Microwave)").covers(Atom.parse("put(Mug,Microwave)"))
        True
        """
        m = _PATTERN.match(text)
        return None if m is None else cls._of(m)

    def covers(self, atom: Atom) -> bool:
        """Does this pattern (`*` for any argument) match `atom`?"""
        return (
            self.verb == atom.verb
            and len(self.args) == len(atom.args)
            and all(p in ("*", a) for p, a in zip(self.args, atom.args, strict=True))
        )

    @classmethod
    def _of(cls, m: re.Match[str]) -> Atom:
        return cls(m.group(1), tuple(a.strip() for a in m.group(2).split(",")))

    @classmethod
    def find_all(cls, formula: str) -> list[Atom]:
        """The quoted atoms of an LTL formula, in order of appearance (repeats kept)."""
        return [cls._of(m) for m in _QUOTED.finditer(formula)]

    def __str__(self) -> str:
        return f"{self.verb}({','.join(self.args)})"
