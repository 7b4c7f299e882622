"""Everyday styles normalised before the grammar's rules (issue 28), each step removing or rewriting only
words that carry no object, place, count, negation or order in the place where it applies:

- misspelt words ("tomatoe", "coffe table", "woould") as the lexicon or English writes them
  (`spelling.respelt`), and texting forms: "ur done" is "you're done", another "ur" is "your";
- counted and ordinal references to things named before ("the remaining two", "the other one", "remotes,
  two of them") written out (`counted_refs.py`);
- "one more" said of a thing ("a remote on the sofa and one more on the armchair", "one more mug") is
  "another" (`drafts` reads "another" as a second thing of the type just placed), and a verbless "then
  another apple" is "then one more apple", the task before again (`counted_refs.another_said`);
- places and things said first: "put the egg (in) there" names the last destination before it, and "the
  mug that's on the counter, put it in the sink" takes the mug first;
- terse notation: "green apple -> blue plate" is "green apple onto blue plate" (the placement verb is
  then supplied as for any verbless placement), "first: A" / "then: B" lose the colon, and a
  parenthetical free-order remark "(any order)" is kept as ", in any order" (other parentheticals are
  dropped later by `normalize`);
- spoken fillers and hedges: hesitations ("um", "uh", "er"), an interjection opening the request or a
  clause ("ok so", "alright,", "so basically"), ", like," between commas, a tag at the end (", yeah"),
  and "just" before a placement verb ("just put ..."; "just the orange" is left, and read or refused);
- goals stated as need or belonging: a heading before a colon that says the listed things need places
  ("four things need plates:", "each fruit gets its own plate:") is dropped when its count, if it says
  one, is the number of placements listed after it; "..., so please put them there" after placements
  stated as belonging repeats them and is dropped;
- a free-order remark about the last group ("the order of those two doesn't matter") is the plain
  "order doesn't matter", which the rules read as freeing the order inside the last group only; closing
  a one-sentence request (", order doesn't matter", "; any order"), it is ", in any order". After
  several sentences its scope is left to the rules, which read it or refuse it.
"""

from __future__ import annotations

import re
from functools import lru_cache

from nl2hltl2plan.language.content_words import DETERMINERS, categories, free_order_phrase
from nl2hltl2plan.language.courtesy import courtesy_pattern
from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.counted_refs import another_said, counted_references
from nl2hltl2plan.language.grammar.lamp_phrases import carried_to_lamp, items_under_lamp
from nl2hltl2plan.language.grammar.one_and_other import one_and_the_other
from nl2hltl2plan.language.grammar.order_phrases import dashed_first
from nl2hltl2plan.language.grammar.order_remarks import remarks_said_plainly
from nl2hltl2plan.language.grammar.places_again import places_named_again
from nl2hltl2plan.language.grammar.repeats import order_word_first, repeated_for_another
from nl2hltl2plan.language.grammar.restated import count_fits, restated
from nl2hltl2plan.language.grammar.sentence_joins import container_again
from nl2hltl2plan.language.grammar.state_references import state_on_it
from nl2hltl2plan.language.grammar.treatments_said import treatments_said
from nl2hltl2plan.language.grammar.use_names import named_by_use
from nl2hltl2plan.language.grammar.word_tables import VERBS
from nl2hltl2plan.language.grounding import (
    Mention,
    find_mentions,
    phrase_lines,
    plural_name,
    tokens,
)
from nl2hltl2plan.language.landmarks import places_stated, where_things_are
from nl2hltl2plan.language.piece_words import slices_said
from nl2hltl2plan.language.spelling import respelt
from nl2hltl2plan.language.statements import RELATIVE_PLACE

# hesitations, the one list of them (the handover reader's spoken step uses it too)
HESITATION = r"(?:u+h+m*|u+m+|e+r+m*|hmm+|mm+)"
_HESITATION = re.compile(rf"(?:^|(?<=[\s,]))(?:{HESITATION}|basically)(?=[\s,.;!?]|$)", re.I)
# (the rules read an opener at the very start themselves, "ok so put ...": there it is taken only before
# a comma, "so, um, the ...")
_OPENER = re.compile(
    r"([,;:.]\s*|\band\s+)(?:(?:ok|okay|alright|all\s+right|so(?!\s+(?:that|as)\b)|well)\b\s*,?\s*|right\s*,\s*)+"
    r"(?=[a-z])",
    re.I,
)
# "first tho put X" as texted is "first, though, put X", which the rules read as "but first" (X before what
# was just said: `order_phrases`); "then tho put X": "though" after another order word carries nothing. Left,
# the order word was no marker and the order was lost
_ORDER_THO = re.compile(r"\b(first|then|next|lastly|last|finally)\s+(?:tho|though)\b(?!\s*,)", re.I)
# "A, and B when you're done (with that)": a done-clause closing the clause of B, with nothing after it, says
# B comes after the clause before ("A, and then B"); left, its "when" was an order nobody read. Inside a
# sentence only ("when you're done, put ..." opens a clause the rules read)
_DONE_AT_END = re.compile(
    r"(?P<join>,\s*(?:and\s+)?|\s+and\s+)(?!then\b)(?P<y>[a-z](?:(?!\band\b)[^,.;!?])*?)\s+(?:when|once|after)\s+"
    r"(?:you're|you\s+are|you've|you\s+have|it's|that's)\s+(?:done|finished|through)"
    r"(?:\s+with\s+(?:that|it|this|those|them))?\s*(?=[.;!?]|$)",
    re.I,
)


# "Both candles go in the cabinet, but they can wait till you've put the soap in the tub" (paper_h301): the
# clause's task after the one that follows, as "..., but not until you've put ..." says (left, the wait was
# read as nothing). Not "till you've done the lamp": a task named by its thing, which that form does not read
_CAN_WAIT_TILL = re.compile(
    r"\s*,\s*(?:but\s+)?(?:they|it|those|these|both)\s+(?:can|could|may)\s+wait\s+(?:till|until)\s+"
    r"(?=you(?:'ve|\s+have)?\s+(?!(?:done|finished|completed|dealt)\b)[a-z]+\s)",
    re.I,
)


def _order_tho(m: re.Match[str]) -> str:
    return f"{m[1]}, though," if m[1].lower() == "first" else m[1]


def _done_at_end(m: re.Match[str]) -> str:
    """ "A and B when you're done" -> "A and then B"; after a list ("A, B, and C when you're done with that")
    which clauses "that" is is not plain (and "A, B, and then C" reads a sequence), so it is left."""
    head = re.split(r"[.;!?]", m.string[: m.start()])[-1]
    return m[0] if "," in head else f"{m['join']}then {m['y']}"


_START_OPENER = re.compile(
    r"^\s*(?:(?:ok|okay|alright|all\s+right|so|well|right)\b\s*,?\s*)*(?:ok|okay|alright|all\s+right|so|well|right)\s*,\s*",
    re.I,
)
_LIKE = re.compile(r",\s*like\s*,", re.I)
# the verbs a step opens with (a filler "like" before one, "go on to" before one)
_STEP_VERB = (
    r"(?:put|place|move|set|drop|take|bring|carry|grab|pick|get|wash|rinse|clean|heat|warm|cool|chill|slice|cut|"
    r"throw|toss|turn|switch|examine|look|hold|open|close|stick|leave)"
)
# a spoken "like" with no commas (users_h195dev): after "then" / "and" / "so" before a step or a thing
# ("then like put ...", "and then like both soap bars ..."), after "you" before a verb ("can you like hold
# ..."); left, "then like put X" was read as "then do the like (the same) with X". "whenever you like",
# "like the mug", "do it like this" stay
_LIKE_SPOKEN = re.compile(
    rf"(?:(?<=\bthen\s)|(?<=\band\s)|(?<=\bso\s))like\s*,?\s+(?=(?:{_STEP_VERB}|the|a|an|both|two|all)\b)"
    rf"|(?:(?<=\byou\s)|(?<=\bu\s))like\s+(?={_STEP_VERB}\b)",
    re.I,
)
_TAG = re.compile(r",\s*(?:yeah|yep|ok|okay|alright|right)\s*(?=[.!?]?\s*$)", re.I)
_JUST = re.compile(r"\bjust\s+(?=(?:put|place|move|pop|drop|set|stick|leave)\b)", re.I)
# connectives written around a step (issue 28, users_h128dev.txt): "then go on to put X" is "then put X"
# (the "then" belongs to the put, not to a clause of going), "in the meantime" is "meanwhile", "start off
# by" is "start by", and "..., and finish by putting Y" after an opening step is a sentence of its own
_GO_ON = re.compile(rf"\b(?:(?:go|move|carry)\s+on|proceed|continue)\s+(?:to|and)\s+(?={_STEP_VERB}\b)", re.I)
_FIRST_STEP = re.compile(r"^\s*(?:start|begin|first(?:ly)?|to\s+(?:start|begin))\b", re.I)
_MEANTIME = re.compile(r"\bin\s+the\s+meantime\b", re.I)
# "past the skillet step, Y" is "after the skillet step, Y" (a step passed, never a place walked past)
_PAST_STEP = re.compile(r"\b(?:past|beyond)(?=\s+the\s+(?:[a-z]+\s+){1,3}(?:step|task|part|job)\b)", re.I)
_START_OFF = re.compile(r"\b(start|begin)\s+off\s+(?=(?:by|with)\b)", re.I)
_AND_FINISH = re.compile(
    r"\s*,?\s*\band\s+(?:then\s+)?(?=(?:finish|end)\s+(?:up\s+|off\s+)?(?:by|with)\s+[a-z]+ing\b)", re.I
)
_ARROW = re.compile(r"\s*->\s*")
# a checklist item's state said after its thing, "lettuce, chilled -> table", "a plate, chilled, on the shelf"
# (h260): the state before the thing ("a chilled plate on the shelf"), as a verbless placement says it
_STATE_AFTER = re.compile(
    rf"\b(?P<x>[a-z]+)\s*,\s*(?P<s>{'|'.join(sorted(G.STATE_WORDS, key=len, reverse=True))})\s*,?\s+"
    r"(?=(?:onto|into|in|on|to)\s)",
    re.I,
)
_STEP_COLON = re.compile(r"\b(first|then|next|after\s+that|finally|lastly)\s*:\s*", re.I)
# a free-order phrase ("any order", "the order doesn't matter"; content_words.free_order_phrase) in brackets
_FREE_ORDER = free_order_phrase()
_PAREN_FREE_ORDER = re.compile(rf"\s*\(\s*{_FREE_ORDER}\s*\)", re.I)
_LAST_GROUP_ORDER = re.compile(
    r"\b(?:the\s+)?order\s+of\s+(?:those|these|them|the\s+last)(?:\s+(?:two|three|four|ones?))?\s+"
    r"(?=(?:does\s*n[o']?t|does\s+not)\s+matter\b)",
    re.I,
)
_NEED_HEADING = re.compile(
    r"^\s*(?:(?P<count>two|three|four|five|six|\d)\s+|each\s+|every\s+)?[a-z]+\s+"
    r"(?:needs?|gets?)\s+(?:(?:a|its|their)\s+(?:own\s+)?)?(?:plates?|places?|spots?|homes?)\s*:\s*",
    re.I,
)
_PLACEMENT = re.compile(r"\b(?:in|into|on|onto|to)\s+the\s+", re.I)
_PUT_THEM_THERE = re.compile(
    r",?\s*(?:and\s+)?so\s+(?:please\s+)?(?:put|place|move)\s+(?:them|it|those)\s+there(?=\s*[.;!?]?\s*$)",
    re.I,
)
_BELONGS = re.compile(r"\bbelongs?\s+(?:in|on|to)\b", re.I)
# a free-order remark closing the request, after a comma or as its own clause: ", order doesn't matter",
# "; any order", "; I don't care about the order", "the order is your call" (read as the ", in any order"
# that the rules read), a closing courtesy after it too (", doesn't matter which first please", ", order
# doesn't matter, thanks!")
_THANKS_LAST = rf"(?:\s*,?\s*(?:please|{courtesy_pattern('closing')}))?"
# (two said one after the other are one remark: "Whichever you start with, I'm not bothered.")
_CLOSING_FREE_ORDER = re.compile(
    rf"\s*[,;.]\s*{_FREE_ORDER}(?:\s*,\s*{_FREE_ORDER})?{_THANKS_LAST}\s*[.!]?\s*$", re.I
)


# contractions typed without the apostrophe ("when thats done", "dont"); not "its", "lets", "well", "were"
_BARE_CONTRACTION = {
    "thats": "that's", "whats": "what's", "dont": "don't", "doesnt": "doesn't", "didnt": "didn't",
    "cant": "can't", "wont": "won't", "isnt": "isn't", "arent": "aren't", "youre": "you're",
    "theyre": "they're", "shouldnt": "shouldn't", "wouldnt": "wouldn't", "couldnt": "couldn't",
    "youve": "you've", "ive": "I've", "ur": "your",
}  # fmt: skip
_UR_DONE = re.compile(r"\bur\s+(?=(?:done|finished|through)\b)", re.I)  # "ur done": "you're"; else "your"
_BARE = re.compile(rf"\b({'|'.join(_BARE_CONTRACTION)})\b", re.I)
# "A, B, and after both of those put C", "A, then B, and after those two C", "A and B, and once both are done
# C": a reference to every task before, which the rules read where it opens a sentence and ends at a comma
# ("A, B. After both of those, put C"); the one list of these references. The short forms ("after both",
# "after those two") only inside a sentence: "After both are there, ..." opens a clause of its own
_REFERENCE_TO_ALL = re.compile(
    r"(?:(?P<lead>(?<=\w)\s*,?\s+(?:and\s+)?|^\s*|(?<=[.!?])\s+)"
    r"(?P<ref>(?:after|once|when)\s+(?:both|all|each)\s+of\s+(?:those|these|them)"
    r"(?:\s+(?:are|is)\s+(?:done|finished))?)(?!\s+(?:are|is)\s+[a-z]+\s*(?:[.;!?]|$))"  # not closing it
    r"|(?<=\w)\s*,?\s+(?:and\s+)?(?P<short>(?:after|once)\s+(?:those|these|the)\s+(?:two|three|four)"
    r"(?:\s+(?:are|have\s+been)\s+(?:done|finished))?"
    r"|once\s+both\s+(?:of\s+(?:them|those)\s+)?(?:are|have\s+been)\s+(?:done|finished)"
    # not "after both pen jobs are done": the tasks named by their thing (`references.ref_targets`; h190)
    r"|after\s+both(?:\s+of\s+(?:them|those))?(?!\s+(?:[a-z]+\s+){1,2}(?:jobs?|ones|tasks?|chores)\b))"
    r"(?=\s*,?\s+[a-z]))\s*,?\s+",
    re.I,
)


def _reference_sentence(m: re.Match[str]) -> str:
    """The reference opens a sentence of its own and ends at a comma."""
    said = m["ref"] or m["short"]
    ref = said[0].upper() + said[1:]
    inside = m.start() > 0 and m.string[m.start() - 1].isalnum()  # after a clause of the same sentence
    return f". {ref}, " if inside else f"{m['lead']}{ref}, "


@lru_cache(maxsize=1)
def _names() -> tuple[re.Pattern[str], dict[str, str]]:
    """`everyday_names.txt` as one pattern (longest names first) and each name's lexicon name."""
    table = {name: fields[0] for names, fields in phrase_lines("everyday_names.txt") for name in names}
    longest_first = sorted(table, key=len, reverse=True)
    alternatives = "|".join(re.escape(n).replace(r"\ ", r"\s+") for n in longest_first)
    return re.compile(rf"(?<![\w'-])(?:{alternatives})(?![\w'-])", re.I), table


def everyday_names(text: str) -> str:
    """The everyday names of scene types that the lexicon does not list ("the freezer", "the cabbage",
    "the soap dispenser") written as the lexicon's names (`everyday_names.txt`)."""
    pattern, table = _names()
    return pattern.sub(lambda m: table[" ".join(m[0].lower().split())], text)


def _cased(word: str, like: str) -> str:
    """`word` with the first letter of `like` as it was written."""
    return word.capitalize() if like[:1].isupper() else word


# a list pasted from a phone's notes app (users_h195dev): its heading ("bathroom:", "to do:") opening the text
_NOTE_HEADING = re.compile(  # ... or when it is for ("A few things before you leave:", "While I'm away:")
    rf"^\s*(?:{courtesy_pattern('note_heading')}(?:\s+{courtesy_pattern('note_when')})?|"
    rf"{courtesy_pattern('note_when')})\s*:\s*(?=[\w-])",
    re.I,
)
# an item of the list with no determiner ("..., toilet paper roll on the holder")
_ITEM = re.compile(r"(?<=[,;])(?P<sp>\s*)(?P<item>[a-z][^,;.!?]*)", re.I)
# "wash a cloth, cloth in the drawer": the thing treated, said again bare with its place, is put there
_THING_AGAIN = re.compile(
    r"\b(?P<verb>wash|rinse|clean|heat|warm|cool|chill)\s+(?:a|an|the)\s+(?P<x>[a-z]+(?:\s+[a-z]+)?)\s*,\s*"
    r"(?:the\s+)?(?P=x)\s+(?:goes\s+)?(?P<prep>in|into|on|onto|inside)\s+",
    re.I,
)


def _noted(text: str) -> str:
    """A notes-app list onto the forms the rules read: its heading dropped, an item's bare name given "the",
    a treated thing said again with its place put there."""
    text = re.sub(r"\s+/\s+", "; ", _NOTE_HEADING.sub("", text))  # "A / B": items, as ";" says
    text = _THING_AGAIN.sub(lambda m: f"{m['verb']} the {m['x']} and put it {m['prep']} ", text)
    return container_again(_ITEM.sub(_item_named, text))


def _item_named(m: re.Match[str]) -> str:
    """ "toilet paper roll on the holder" -> "the toilet paper roll on the holder" (a name, then a place)."""
    item = m["item"]
    named = find_mentions(item)
    first = item.split()[0].lower()  # a verb opens a clause ("..., switch on the lamp"), not an item
    if not named or named[0].char_start != 0 or first in DETERMINERS or first in VERBS:
        return m[0]
    if not re.match(r"\s+(?:in|into|on|onto|inside)\s", item[named[0].char_end :], re.I):
        return m[0]
    return f"{m['sp']}the {item}"


def _without_fillers(text: str) -> str:
    """The text without its spoken fillers: hesitations, ", like," between commas and a spoken "like"."""
    text = re.sub(r"(\s*,)+", ",", _HESITATION.sub(" ", text))  # the commas left where fillers were
    return re.sub(r"\band\s*,\s*", "and ", _LIKE_SPOKEN.sub("", _LIKE.sub(",", text)))


@lru_cache(maxsize=1024)  # check 1 asks again for every reading it judges (about five per instruction)
def everyday(text: str) -> str:
    """The text with the everyday styles above rewritten onto the forms the grammar reads (a pure function
    of the text)."""
    text = _BARE.sub(lambda m: _BARE_CONTRACTION[m[1].lower()], _UR_DONE.sub("you're ", text))
    text = _noted(_without_fillers(text))  # first: "and, like, the box on there too" finds its place
    text = remarks_said_plainly(text)  # "Save the mug for last.": "the mug last." (order_remarks.py)
    text = another_said(_as_well_as_doing(text))  # "one more" said of a thing (counted_refs.py)
    if _FREE_REMARK.search(text):  # "1. X. 2. Y. Any order is fine.": the numbers only list the steps
        text = _NUMBERED.sub(lambda m: m["lead"], text)
    text = named_by_use(everyday_names(respelt(text)))  # misspelt names, everyday names, names by use
    # a source split over two things first (`landmarks.where_things_are`): "both X, the one by A and ..."
    # "a round of tomato" is "a slice of tomato" before "one slice ... the other" reads it (piece_words.py)
    text = one_and_the_other(where_things_are(slices_said(text)))  # before "the other one" is "the other X"
    text = places_stated(text, VERBS)  # "my phone is on the desk, bring it ...": "my phone on the desk, ..."
    text = counted_references(text)  # "the remaining two", "remotes, two of them" (counted_refs.py)
    text = _LAMP_WITH_IT_ON.sub(r"\g<lamp>", text)  # before a repeat copies the sentence
    # "... The cup too.": the task before, for the cup (repeats.py); "carry X to the lamp and turn it on"
    # first written as the examination it is, which a repeat can copy
    text = dashed_first(order_word_first(text))  # "Do the same with X after that.": "After that do ..."
    text = repeated_for_another(items_under_lamp(carried_to_lamp(state_on_it(text))))
    text = _REFERENCE_TO_ALL.sub(_reference_sentence, text)
    text = _PAREN_FREE_ORDER.sub(", in any order", text)
    text = _STEP_COLON.sub(r"\1 ", _ARROW.sub(" onto ", text))
    text = _STATE_AFTER.sub(lambda m: f"{m['s']} {m['x']} " if find_mentions(m["x"]) else m[0], text)
    if _BELONGS.search(text):
        text = _PUT_THEM_THERE.sub("", text)
    text = _THEN_UNDER_LAMP.sub(_each_under_lamp, text)
    text = places_named_again(text)  # "there", "on it", "that table", "along with" (places_again.py)
    text = _COUNT_LEFT.sub(_count_named, _TOPIC.sub(_topic_counted, text))
    text = _THING_FIRST.sub(lambda m: f"{m['lead']}take {m['np']}, ", text)
    text = _ORDER_THO.sub(_order_tho, text)
    text = _CAN_WAIT_TILL.sub(", but not until ", _DONE_AT_END.sub(_done_at_end, text))
    text = _TAG.sub("", text)
    text = _START_OPENER.sub("", _OPENER.sub(r"\1", text))
    text = _JUST.sub("", text)
    text = _START_OFF.sub(r"\1 ", _MEANTIME.sub("meanwhile", _GO_ON.sub("", text)))
    text = _PAST_STEP.sub(lambda m: _cased("after", m[0]), text)
    if _FIRST_STEP.match(text):  # "start by X, and finish by Y": the last step is read as a sentence
        text = _AND_FINISH.sub(". ", text)
    text = re.sub(r"\band\s*,\s*", "and ", re.sub(r"^\s*,\s*", "", text))
    text = _without_need_heading(text)
    text = _LAST_GROUP_ORDER.sub("order ", text)
    text = _ALSO_THERE.sub(lambda m: f"{m['head']} and {m['y'] or m['y2']} {m['dest']}", text)
    if not re.search(r"[.!?]\s+\S", text):  # in one sentence: what the remark is about is plain
        text = _CLOSING_FREE_ORDER.sub(", in any order", text)
    elif (last := _LAST_SENTENCE_FREE.search(text)) and not _ORDER_WORD.search(text[: last.start()]):
        text = text[: last.start()] + "."  # "A. B. C. Any order.": no sentence orders another
    text = treatments_said(re.sub(r"\s+", " ", text).strip())  # needs, causatives, terse orders
    return restated(text)  # places and end states restated (restated.py)


# "put the apple in the fridge and the tomato too", "..., also the ladle", "the pencil as well": a second
# object for the same place (read as "put the apple and the tomato in the fridge"); the second phrase names
# no place of its own; either may say where it is now ("move the two books from the bed to the dresser, and
# the keys from the nightstand as well": the keys go to the dresser too, h239)
_WORD = r"(?!(?:in|into|on|onto|to|inside|and|also|plus|too|as|then|from)\b)[a-z]+"
_NP = rf"(?:the|a|an|my|your|that|this|two|three)\s+{_WORD}(?:\s+{_WORD}){{0,2}}"
_FROM = rf"(?:\s+from\s+(?:the|a|an|my|your)\s+{_WORD}(?:\s+{_WORD})?)?"
_ALSO_THERE = re.compile(
    rf"(?P<head>\b(?:put|place|move|set|stick|pop|drop|throw|toss|leave)\s+{_NP}{_FROM})\s+"
    rf"(?P<dest>(?:in|into|on|onto|inside|to)\s+{_NP})\s*,?\s+"
    rf"(?:(?:and\s+)?(?:also|plus)\s+(?P<y>{_NP}{_FROM})(?:\s*,?\s+(?:too|as\s+well|also))?"
    rf"|(?:and\s+)?(?P<y2>{_NP}{_FROM})\s*,?\s+(?:too|as\s+well|also))"
    r"\s*(?=[.;!?]|$)",
    re.I,
)


_LAST_SENTENCE_FREE = re.compile(rf"[.!?]\s+{_FREE_ORDER}\s*[.!]?\s*$", re.I)
_ORDER_WORD = re.compile(
    r"\b(?:then|first|firstly|next|after|afterwards|before|finally|lastly|once|when|until|later)\b", re.I
)
# "1. X. 2. Y." / "1) X 2) Y": list numbers; without a free-order remark they stay, and are refused as
# counts of nothing (a numbered list may mean a sequence)
_NUMBERED = re.compile(r"(?P<lead>^|(?<=[.;!?:])\s+|\n)\s*\d{1,2}\s*[.)]\s+(?=[a-z])", re.I)
_FREE_REMARK = re.compile(rf"\b{_FREE_ORDER}\b", re.I)


# "put the mug in the sink, as well as putting the apple in the fridge": one more clause, as "and putting"
# (the clause rules took ", as well" for a second place of the mug); not after a clause its own words free
# ("X whenever you can, as well as Y, and then Z": whether Z comes after X is the rules' open question,
# where the structure model follows the generator's step)
_AS_WELL_AS_DOING = re.compile(r",?\s+as\s+well\s+as\s+(?=[a-z]+ing\b)", re.I)
_CLAUSE_FREED = re.compile(rf"(?:\b{_FREE_ORDER}|\b{G.WHENEVER}|\bat\s+any\s+time)[^.;!?]*$", re.I)


def _as_well_as_doing(text: str) -> str:
    """Each ", as well as <verb>ing" written ", and <verb>ing", unless the sentence before frees an order."""
    def one(m: re.Match[str]) -> str:
        return m[0] if _CLAUSE_FREED.search(text[: m.start()]) else ", and "

    text = _AS_WELL_AS_DOING.sub(one, text)

    def thing(m: re.Match[str]) -> str:
        if _CLAUSE_FREED.search(text[: m.start()]):
            return m[0]
        if m["end"] is not None and not _PLACE_WORD.search(m["y"]):
            return f", and {m['y']} too"
        return f"{m[0][: m[0].index('as')].rstrip()} and {m['y'] or ''}"

    return _AS_WELL_AS_THING.sub(thing, text)


# "put two boxes on the table, as well as two tissue boxes": a thing joined to the task before, put where it
# goes ("..., and two tissue boxes too"); "put X as well as Y on Z": "X and Y" (h293). Never a thing dropped
_AS_WELL_AS_THING = re.compile(
    r",?\s+as\s+well\s+as\s+(?=(?:the|a|an|two|three|four|\d+|some|both|my|another|one)\s)"
    r"(?:(?P<y>[^.;!?,]+?)(?P<end>(?=\s*(?:[.;!?]|$))))?",
    re.I,
)
_PLACE_WORD = re.compile(r"\b(?:on|onto|in|into|under|to|inside|next)\b", re.I)


# "look at a credit card and then a phone under the floor lamp": the lamp of both, the second after the first
# (without "then", "look at the X and the Y under the lamp" is read as a list already)
_THEN_UNDER_LAMP = re.compile(
    r"\b(?P<verb>look\s+at|examine|inspect|check\s+out)\s+(?P<a>(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+){0,2}?)"
    r"\s*,?\s+and\s+then\s+(?P<b>(?:the|a|an|another)\s+[a-z]+(?:\s+[a-z]+){0,2}?)\s+"
    r"(?P<lamp>(?:under|by|beneath|in)\s+(?:the\s+light\s+of\s+)?(?:the|a)\s+(?:[a-z]+\s+){0,2}?(?:lamp|light))"
    r"(?=\s*(?:[.;!?,]|$))",
    re.I,
)


# "hold the pillow under the desk lamp with it on": the lamp on is what looking under it is, so "with it on"
# says nothing more (users_h195dev); left, the sentence was no plain one, and "then do the same with the cd"
# after it had no task to repeat
_LAMP_WITH_IT_ON = re.compile(
    r"(?P<lamp>\b(?:under|by|beneath)\s+(?:the|a)\s+(?:[a-z]+\s+)?(?:lamp|light))\s+with\s+(?:it|the\s+lamp)\s+"
    r"(?:turned\s+|switched\s+)?on\b",
    re.I,
)


def _each_under_lamp(m: re.Match[str]) -> str:
    """ "look at A and then B under the lamp": "look at A under the lamp, and then look at B under it"."""
    verb = m["verb"].lower()
    return f"{m['verb']} {m['a']} {m['lamp']}, and then {verb} {m['b']} {m['lamp']}"


# "a spray bottle on the toilet and two more in the cabinet", "then one more", "a third one on the tank", "one
# on the sofa and two on the armchair": a count whose noun is left out counts the thing named last before it,
# which is written out ("two more spray bottles"); with none, or one that has no plural form, it stays
_COUNT_LEFT = re.compile(
    r"\b(?P<count>(?:one|two|three)\s+more|a\s+(?:third|fourth)(?:\s+one)?|(?:(?<=\band\s)|(?<=,\s))(?:one|two|three))"
    r"(?=\s+(?:in|into|inside|on|onto|to|under|next\s+to|there)\b|\s*(?:[,.;!?]|$|too\b|as\s+well\b))",
    re.I,
)
# the words that put a noun phrase in a place ("in the cabinet", "by the sink"): the thing named is no thing
# moved ("of" only after a part: "the back of the toilet"; "two of the bottles" counts bottles)
_PLACE_WORDS = frozenset("in into inside on onto to under at by near from beside behind next with".split())
_PARTS = frozenset("back top side edge front lid bottom end".split())


# a topic that heads a list of counts ("sponges: wash one and put it in the tub, ...", "tissue boxes: two go
# in the trash, two on ..."): its first count whose noun is left out names it, and the heading goes (h293);
# the counts after it count the thing named last (`_COUNT_LEFT`)
_TOPIC = re.compile(
    r"(?:^|(?<=[.;!?]\s))(?P<topic>[a-z]+(?:\s+[a-z]+)?)\s*:\s*(?P<pre>(?:[a-z]+\s+)?)"
    r"(?P<n>one|two|three)\b(?!\s+(?:of|more)\b)(?=\s+(?:go|goes|in|into|on|onto|and)\b|\s*,)",
    re.I,
)


def _topic_counted(m: re.Match[str]) -> str:
    named = find_mentions(m["topic"])
    if len(named) != 1 or not named[0].plural or named[0].char_end != len(m["topic"]) or named[0].char_start:
        return m[0]
    noun = named[0].entry.phrase if m["n"].lower() == "one" else named[0].surface
    return f"{m['pre']}{m['n']} {noun}"


def _count_named(m: re.Match[str]) -> str:
    """ "two more": "two more spray bottles", the last thing moved before it named, in the count's number."""
    named = [x for x in find_mentions(m.string[: m.start()]) if not x.entry.generic]
    toks = tokens(m.string[: m.start()])
    things = [x for x in named if not _placed(x, toks)]
    if not things:
        return m[0]
    count = re.sub(r"\s+one$", "", m[0])  # "a third one": "a third spray bottle"
    if count.lower().split()[0] in ("one", "a"):
        return f"{count} {things[-1].entry.phrase}"
    plural = plural_name(things[-1].entry.phrase)
    return f"{count} {plural}" if plural else m[0]


def _placed(x: Mention, toks: list[tuple[str, int, int]]) -> bool:
    """Is the mention a place ("in the cabinet", "on the back of the toilet") rather than a thing moved?"""
    i = x.start - 1
    describing = DETERMINERS | {w for w, _, _ in toks if not categories(w)}
    while i >= 0 and toks[i][0] not in _PLACE_WORDS and toks[i][0] in describing:
        i -= 1  # determiners and describing words ("the grey", "two of the")
        if i >= 0 and toks[i][0] == "of":
            return i > 0 and toks[i - 1][0] in _PARTS
    return i >= 0 and toks[i][0] in _PLACE_WORDS


# "the mug that's on the counter, put it in the sink": the thing named first, then what to do with "it"
# (a fronted object with where it is): "take the mug that's on the counter, put it in the sink"
_THING_FIRST = re.compile(
    rf"(?P<lead>^\s*|[.;!?]\s+)(?P<np>(?:the|a|an|that|this)\s+[a-z]+(?:\s+[a-z]+)?\s+{RELATIVE_PLACE}\s+"
    r"(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?)\s*,\s*(?=[a-z]+\s+(?:it|them)\b)",
    re.I,
)


def _without_need_heading(text: str) -> str:
    """A heading "four things need plates:" dropped when the placements after it are as many as it says."""
    m = _NEED_HEADING.match(text)
    if not m:
        return text
    if not count_fits(m["count"], len(_PLACEMENT.findall(text[m.end() :]))):
        return text
    return text[m.end() :]
