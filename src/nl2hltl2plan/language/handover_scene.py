"""What a handover sentence is read against and into (`handover_phrases`, `handover_places`): the word
classes of blocks and places, the instance's layout and block starts (`Scene`: "the opposite" of a
block, the side of some arms, where a block starts), the place phrases (`Place`) and the sentence with
its phrases replaced by placeholders (`Marked`)."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Literal

from nl2hltl2plan.errors import HTTError, WorldError
from nl2hltl2plan.language.handover_regex import sub
from nl2hltl2plan.worlds.handover_world import REGIONS, Layout, layout
from nl2hltl2plan.worlds.world import Cell, World

COLOURS = ("red", "blue", "yellow")
COUNTS = {"two": 2, "three": 3, "four": 4, "both": 2, "2": 2, "3": 3, "4": 4}
NOUN = r"(?:block|cube|pillar|object|item|piece|one)"
GROUP_NOUNS = r"(?:blocks|cubes|pillars|objects|items|pieces)"
NOUNS = r"(?:blocks|cubes|pillars|objects|items|pieces|ones)"
COLOUR = r"(?:red|blue|yellow)"
LETTER = r"\b[e-j]\b"
PLACE_NOUN = r"(?:regions?|areas?|zones?|places?|spots?|positions?|cells?|sides?|locations?)"
# words that carry no meaning here (articles, modal verbs, the agent; the courtesy words of `courtesy.txt` are
# dropped before: `handover_phrases.normalise`)
FILLER = frozenset(
    "plan a an the solution to for you we should shall can could would will must now "
    "also so it is are be that i want need make sure this task , ( ) : and however additionally moreover "
    "furthermore independently since".split()
)


@dataclass(frozen=True)
class Place:
    """A place phrase: labelled regions, per-block opposite side, any empty region, a block's start,
    or (only in prohibitions) the labelled regions other than a goal's targets or, when `regions` is
    given, other than those; a landmark ("next to arm a and arm b") only describes a place named beside
    it and must agree with it."""

    kind: Literal["regions", "opposite", "away", "start_of", "complement", "landmark"]
    regions: tuple[str, ...] = ()
    block: str = ""  # start_of: whose start
    text: str = ""
    within: bool = False  # a landmark that the place named beside it lies within ("next to the arms")


@dataclass
class Scene:
    """What the handover phrases need of a world: its layout and where each block starts."""

    layout: Layout
    starts: dict[str, Cell]  # "Red" -> cell

    @classmethod
    def of(cls, world: World) -> Scene:
        config = world.name.split("-", 1)[1] if "-" in world.name else ""
        try:
            lay = layout(config)
        except WorldError:
            raise HTTError(f"{world.name} is not a handover world (square or line)") from None
        starts = {
            o.type[: -len("Block")]: o.interaction_cells[0]
            for o in world.objects.values()
            if o.type.endswith("Block") and o.interaction_cells
        }
        return cls(lay, starts)

    @property
    def blocks(self) -> list[str]:
        return [c.capitalize() for c in COLOURS if c.capitalize() in self.starts]

    def side(self, cell: Cell) -> int | None:
        """0: only arms a/b reach the cell; 1: only c/d; None: both sides (a shared middle cell)."""
        arms = set(self.layout.arms_reaching(cell))
        if arms <= {0, 1}:
            return 0
        if arms <= {2, 3}:
            return 1
        return None

    def opposite(self, block: str) -> tuple[str, ...]:
        side = self.side(self.starts[block])
        if side is None:
            raise HTTError(
                f"'the opposite' is unclear for the {block.lower()} block: it starts between the sides"
            )
        return tuple(
            r for r in REGIONS if r in self.layout.regions and self.side(self.layout.regions[r]) == 1 - side
        )

    def arms_side(self, arms: list[int]) -> tuple[str, ...]:
        return tuple(r for r in REGIONS if set(self.layout.arms_reaching(self.layout.regions[r])) & set(arms))

    def start_region(self, block: str) -> str:
        cell = self.starts[block]
        if cell not in self.layout.region_at:
            raise HTTError(f"the {block.lower()} block does not start on a labelled region")
        return self.layout.region_at[cell]

    def block(self, colour: str) -> str:
        name = colour.capitalize()
        if name not in self.starts:
            raise HTTError(f"there is no {colour} block in this world; blocks: {', '.join(self.blocks)}")
        return name


@dataclass
class Marked:
    """A sentence with its phrases replaced by placeholders (`B0`, `P0`, `A`)."""

    text: str
    blocks: list[list[str]] = field(default_factory=list)  # B<k> -> block names
    block_text: list[str] = field(default_factory=list)
    places: list[Place] = field(default_factory=list)  # P<k>
    notes: list[str] = field(default_factory=list)  # one-per-region statements, read as the world's rule
    last_one: str = ""  # the last single block the sentence names (what "it" means in the next)
    last_regions: tuple[str, ...] = ()  # the last regions it names ("regions other than these" in the next)
    last_group: tuple[str, ...] = ()  # its one group of several blocks, if one ("move them" in the next)
    last_place: Place | None = None  # the last place a block may go to ("move them there" in the next)

    def copy(self) -> Marked:
        """A copy whose lists the rules may change (places are frozen, the rest is immutable)."""
        return replace(
            self,
            blocks=[list(b) for b in self.blocks],
            block_text=list(self.block_text),
            places=list(self.places),
            notes=list(self.notes),
        )

    def sub(self, pattern: str, make) -> None:  # make(match) -> replacement text
        self.text = sub(pattern, make, self.text)
