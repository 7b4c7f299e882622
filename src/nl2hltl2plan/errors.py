"""The one exception family of the package: every error a user can cause is one of these.

The CLI catches `Nl2Hltl2PlanError` and prints its message (never a traceback); anything else
escaping is a bug.
"""


class Nl2Hltl2PlanError(Exception):
    """Base class: a problem with the user's input or environment, with a readable message."""

    exit_status = 2  # the CLI's status for it: bad input, unless a subclass is a definite "no"


class FormulaError(Nl2Hltl2PlanError):
    """An LTL formula that cannot be parsed, is not sc-LTL, or cannot be translated in time."""


class FormulaTooLargeError(FormulaError):
    """A formula beyond what Spot can represent (more than 65,535 operands of one operator...): the input
    cannot be checked at all, which is bad input (exit 2), not an invalid specification (exit 1)."""


class SpecError(Nl2Hltl2PlanError):
    """A hierarchical specification that breaks Definition 2.1 (or is malformed JSON)."""


class HTTError(Nl2Hltl2PlanError):
    """A Hierarchical Task Tree that is not a tree, relates non-siblings, or has cyclic relations."""


class DataError(Nl2Hltl2PlanError):
    """Missing or malformed input data (shared data folder, scene files, JSON files)."""


class WorldError(Nl2Hltl2PlanError):
    """A world/scene problem: unknown floor plan, object not in the scene, unreachable object."""


class NoPlaceError(WorldError):
    """None of the places a choice allows ("the fridge or the microwave") can be taken in the world: a
    definite "no" (exit 1), as an infeasible plan is."""

    exit_status = 1


class PlanningError(Nl2Hltl2PlanError):
    """The planner could not be run on the given problem (bad robots, bad spec atoms...)."""


class LLMError(Nl2Hltl2PlanError):
    """An LLM backend failed: unreachable server, invalid answers after all retries, timeouts."""
