"""Statements of a handover sentence that are not commands, read as clauses over the marked sentence
(blocks `B<k>` and places `P<k>` already resolved by `handover_phrases.mark`):

- a scene statement says where blocks are now: "the pillars sit on H, I and J (but belong in ...)",
  "take the three pillars, which are standing on regions H, I and J at the moment, and ...". It asks for
  nothing, so it gives no goal, but it is checked against the world: a statement the layout contradicts
  is refused (the writer and the reader would disagree about the scene). A statement that introduces the
  blocks ("here we have three blocks", "there are three objects on the table") must name every block of
  the scene, or it is refused; it gives no goal, and "them" in what follows is its group;
- a target statement names the goal regions before the goal: "regions H, I and J are the targets (and
  each can only hold one object), so the blocks should end up spread over them". It is dropped only when
  a later clause of the sentence names the same regions; a region list left alone is refused;
- a need states a goal as a wish, and a command after it that names no place says the same goal again:
  "we need the blocks on the other side, so carry all three of them across" moves the blocks once. The
  command must name the same blocks (or none); otherwise it stays unread;
- a question inverts its modal ("could the red and blue blocks each go to an empty region?"): read as
  the statement ("the red and blue blocks could each go ...");
- a labelled heading puts the place first ("Target: region I, all three blocks, one after another"):
  read as "all three blocks to region I, one after another";
- a verb pair names the blocks twice ("take the pillars and bring them over to E, F and G", "arrange the
  blocks so that G, H and I each end up holding one of them"): read once, when both name the same blocks;
  a bare "opposite" after the blocks ("transfer all blocks opposite") is the opposite side.

Each reader consumes only what it reads; the rest stays for the rules and goal readers, and whatever no
reader uses is refused by the caller, naming it.
"""

from __future__ import annotations

import re

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.handover_scene import NOUN, Marked, Scene
from nl2hltl2plan.language.handover_words import PREP, VERB

# when a scene statement holds: "now", "at the moment"; `_NOW` (after the verb) also "initially", "at first"
_NOW_WORDS = r"(?:at\s+the\s+moment|right\s+now|now|currently|at\s+present)"
_NOW = rf"(?:\s+(?:{_NOW_WORDS}|at\s+first|initially|to\s+begin\s+with))?"
_LIE = r"(?:sitting|standing|lying|resting|located|placed)"
_MODAL_Q = r"(?:could|can|would|will|should|may|shall)"


def read_statements(m: Marked, scene: Scene) -> None:
    """Read the sentence's scene, target, need and question clauses, place headings, verb pairs and a bare
    "opposite" in place (see the module docstring)."""
    _read_scene(m, scene)
    _read_targets(m)
    _read_needs(m)
    _read_questions(m)
    _read_place_headings(m)
    _read_verb_pairs(m)
    # terse: "transfer all blocks opposite": the bare adverb is the opposite side
    m.sub(
        rf"\b({VERB})\s+B(\d+)\s+P(\d+)(?=\s*(?:$|,))",
        lambda x: (
            f" {x.group(1)} B{x.group(2)} to P{x.group(3)} "
            if m.places[int(x.group(3))].kind == "opposite" and m.places[int(x.group(3))].text == "opposite"
            else x.group(0)
        ),
    )


def _holds(m: Marked, scene: Scene, b: str, p: str) -> bool:
    """Whether every block of `B<b>` starts on a region of `P<p>` (named regions only)."""
    place = m.places[int(p)]
    starts = [scene.starts[block] for block in m.blocks[int(b)]]
    regions = [scene.layout.region_at.get(cell) for cell in starts]
    return place.kind == "regions" and all(r in place.regions for r in regions)


def _said(m: Marked, text: str) -> str:
    """A marked clause in the writer's words (for an error that names it)."""
    said = re.sub(r"\bB(\d+)\b", lambda x: m.block_text[int(x.group(1))], text)
    said = re.sub(r"\bP(\d+)\b", lambda x: m.places[int(x.group(1))].text, said)
    return " ".join(said.strip(" ,").split())


def _refuse_scene(m: Marked, scene: Scene, b: str, text: str) -> HTTError:
    where = scene.layout.region_at
    starts = ", ".join(f"{x.lower()} on {where.get(scene.starts[x], '?')}" for x in m.blocks[int(b)])
    return HTTError(f"'{_said(m, text)}' does not hold in this scene ({starts}); say where the blocks go")


def _read_scene(m: Marked, scene: Scene) -> None:
    def present(match: re.Match[str]) -> str:
        group = m.blocks[int(match.group("b"))]
        if sorted(group) != sorted(scene.starts):
            raise HTTError(
                f"'{_said(m, match.group(0))}' does not hold in this scene (its blocks: "
                f"{', '.join(x.lower() for x in sorted(scene.starts))}); say which blocks go where"
            )
        return match.group("lead")

    # "here we have three blocks", "there are three pillars on the table": every block of the scene, or
    # refused; a statement that asks nothing, it gives no goal ("them" in the next sentence is the group)
    m.sub(
        r"(?P<lead>^|,|;)\s*(?:so\s+)?(?:(?:here|there)\s+(?:we\s+have|you\s+have|are|is)|we\s+(?:have\s+got|have|got))"
        r"\s+B(?P<b>\d+)\s*(?:(?:here|there|on\s+the\s+(?:table|workspace)|in\s+(?:the\s+)?(?:scene|workspace)|"
        r"in\s+front\s+of\s+(?:you|us))\s*)?(?=,|;|$)",
        present,
    )

    def relative(match: re.Match[str]) -> str:
        if not _holds(m, scene, match.group(1), match.group(2)):
            raise _refuse_scene(m, scene, match.group(1), match.group(0))
        return f" B{match.group(1)} "

    # "the pillars, which are standing on H, I and J at the moment, ...": the blocks, as they are now
    m.sub(
        rf"\bB(\d+)\s*,?\s*(?:which|that)\s+(?:are|is)\s+(?:now\s+|currently\s+)?(?:{_LIE}\s+)?(?:on|in|at)\s+P(\d+)"
        rf"{_NOW}\s*(?:,|$)",
        relative,
    )

    def main(match: re.Match[str]) -> str:
        b, p = match.group("b"), match.group("p") or match.group("p2")
        timed = any(match.group(g) for g in ("now0", "now", "at", "t1", "t2"))
        if match.group("p2") and not timed:  # "the blocks are on E, F and G" may state the goal
            return match.group(0)
        if not _holds(m, scene, b, p):
            # with its time ("now", "at the moment") it states the scene, wrongly; without, "the blocks
            # rest on the opposite side" may state the goal: left to the goal readers
            if timed:
                raise _refuse_scene(m, scene, b, match.group(0))
            return match.group(0)
        # "the pillars sit on H, I and J but belong in E, F and G": the subject goes on to the next verb
        return f"{match.group('lead')} B{b} " if match.group("link") else match.group("lead")

    # a clause of its own: "the pillars sit on H, I and J", "the red block is now on G", "the pillars are
    # on H, I and J right now" (with a plain "is/are", only with its time)
    m.sub(
        rf"(?P<lead>^|,|;)\s*(?P<now0>{_NOW_WORDS}\s*,?\s*)?"
        rf"B(?P<b>\d+)\s+(?P<now>(?:now|currently)\s+)?(?:(?:are|is)\s+(?:now\s+|currently\s+)?)?"
        rf"(?:(?:sits?|sitting|stands?|standing|lies?|lying|rests?|resting|starts?|located)\s+(?:on|in|at)\s+P(?P<p>\d+)"
        rf"(?P<at>{_NOW})|"
        rf"(?:are|is)\s+(?P<t1>{_NOW_WORDS}\s+)?(?:on|in|at)\s+P(?P<p2>\d+)(?P<t2>\s+{_NOW_WORDS})?)"
        rf"\s*(?:(?P<link>\bbut\b|\band\b)|(?=,|$))",
        main,
    )


def _read_targets(m: Marked) -> None:
    """'regions H, I and J are the targets (and each can only hold one object), ...', 'region I is the drop
    point, so ...', 'use region I as a drop-off: ...': dropped where a later clause names the same regions
    (the note of the one-block rule is kept)."""

    def drop(match: re.Match[str]) -> str:
        named = m.places[int(match.group(1))]
        later = [int(k) for k in re.findall(r"\bP(\d+)\b", m.text[match.end() :])]
        if not any(m.places[k].regions == named.regions and m.places[k].kind == named.kind for k in later):
            return match.group(0)
        if match.group("rule"):
            m.notes.append("one block per region (the world's rule: a cell holds one block)")
        return " "

    targets = (
        r"(?:targets?|goals?|destinations?|(?:goal|target)\s+(?:regions?|areas?)|(?:drop|collection|gathering)\s+"
        r"(?:off|point|spot|area|region)s?)"
    )
    rule = (
        rf"(?P<rule>\s*,?\s*and\s+each\s+(?:(?:can|may|will)\s+)?(?:only\s+)?(?:hold|take|fit|accept)s?\s+"
        rf"(?:only\s+)?(?:one|a\s+single)\s+{NOUN})?"
    )
    m.sub(rf"^\s*P(\d+)\s+(?:are|is)\s+(?:the|our|your|a)\s+{targets}{rule}\s*[,:]", drop)
    m.sub(rf"^\s*(?:please\s+)?use\s+P(\d+)\s+as\s+(?:the|our|your|a)\s+{targets}{rule}\s*[,:]", drop)


def _read_needs(m: Marked) -> None:
    """'we need the blocks on the other side, so carry all three of them across', 'the blocks belong on the
    opposite side, so move all three of them there': one goal, said as a need or a target state, then
    again as a command that names no other place and no other blocks."""

    def once(match: re.Match[str]) -> str:
        b, again, there = match.group("b") or match.group("b2"), match.group("again"), match.group("there")
        if again is not None and sorted(m.blocks[int(again)]) != sorted(m.blocks[int(b)]):
            return match.group(0)
        if there is not None and m.places[int(there)] != m.places[int(match.group("p"))]:
            return match.group(0)
        return f" put B{b} on P{match.group('p')} "

    need = (
        r"(?:(?:we|i)\s+(?:need|want|would\s+like)\s+B(?P<b>\d+)\s+(?:to\s+be\s+)?|"
        r"B(?P<b2>\d+)\s+(?:(?:should|must|need\s+to|has\s+to|have\s+to)\s+(?:be|end\s+up|go)|belongs?)\s+)"
    )
    m.sub(
        rf"^\s*{need}{PREP}\s+P(?P<p>\d+)\s*,\s*(?:so\s+|and\s+)?(?:please\s+)?{VERB}\s+(?:B(?P<again>\d+)\s+)?"
        rf"(?:over\s+there|across|over|there|to\s+P(?P<there>\d+))(?=\s*(?:$|,))",
        once,
    )


def _read_questions(m: Marked) -> None:
    """'could the red and blue blocks each go to an empty region': the modal after its subject."""
    m.sub(
        rf"(^|,|\band\b|\bat\s+any\s+time\b\s*,?)\s*({_MODAL_Q})\s+B(\d+)\s+(?=(?:each|all|both|also|be|go|get|{VERB})\b)",
        r"\1 B\3 \2 ",
    )


def _read_place_headings(m: Marked) -> None:
    """'Target: region I, all three blocks, one after another': the blocks to the place; 'Red and blue
    blocks: relocate to any empty region': the verb after the blocks' heading."""
    m.sub(rf"^\s*B(\d+)\s*:\s*({VERB})\s+(?=(?:to|onto|on|into|in)\s+P\d)", r" \2 B\1 ")
    m.sub(
        r"^\s*(?:please\s+)?(?:targets?|destinations?|where)\s*:\s*P(\d+)\s*,\s*B(\d+)"
        r"(?=\s*(?:$|,|one\s+(?:after\s+another|by\s+one|at\s+a\s+time)|in\s+turn|separately|at\s+any\s+time))",
        r" B\2 to P\1 ",
    )


def _read_verb_pairs(m: Marked) -> None:
    """'take the pillars and bring them over to E, F and G': the first verb only picks up what the second
    moves (the same blocks); 'arrange the blocks so that G, H and I each end up holding one of them': the
    verb's object is what the state that follows places."""

    def same(match: re.Match[str]) -> str:
        first, second = [g for g in match.groups() if g is not None]
        if sorted(m.blocks[int(first)]) != sorted(m.blocks[int(second)]):
            return match.group(0)
        return " "

    m.sub(rf"\b(?:take|pick\s+up|grab|lift)\s+B(\d+)\s*,?\s+and\s+(?={VERB}\s+B(\d+)\s)", same)
    # (also "share out the blocks so that ..." and the passive "the blocks are to be shared out so that ...")
    m.sub(
        r"(?:\b(?:arrange|distribute|spread|place|put|share\s+out)\s+B(\d+)|\bB(\d+)\s+(?:must|should|will|can|are\s+to)\s+be\s+"
        r"(?:arranged|distributed|spread|placed|put|shared\s+out))\s+(?:so\s+that\s+)?(?=(?:each\s+of\s+)?P\d+\s+(?:each\s+)?"
        r"(?:(?:should|will|must|can)\s+)?(?:each\s+)?(?:end\s+up\s+(?:holding|with)|holds?|gets?|receives?|contains?)\s+"
        r"(?:exactly\s+)?one\s+of\s+B(\d+)\b)",
        same,
    )
