"""The `plurals` setting every stage and front end shares (docs/language.md, "Plurals"): how a bare
plural of more things than a task takes ("the forks" of three) is read: refused naming it (`ask`), or
by the world's convention where it has one (`two`: ALFRED's pick-two, `worlds.world.PluralConvention`);
a world's `always` convention applies under both. Typing only, so the CLI takes its `--plurals`
choices from here at start-up without importing the language stage.

>>> PLURALS
('ask', 'two')
"""

from __future__ import annotations

from typing import Literal, get_args

Plurals = Literal["ask", "two"]
PLURALS: tuple[str, ...] = get_args(Plurals)
