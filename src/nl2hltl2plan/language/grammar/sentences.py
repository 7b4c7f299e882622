"""Step 1, sentences: normalise the text, split it into sentences, strip their order markers."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache

from nl2hltl2plan.language.content_words import phrase_list_pattern
from nl2hltl2plan.language.courtesy import courtesy_pattern, without_call
from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.everyday import everyday
from nl2hltl2plan.language.grammar.lamp_phrases import lamp_phrasing
from nl2hltl2plan.language.grammar.order_phrases import (
    after_the_step,
    clause_refs,
    closing_orders,
    command_after_state,
    done_opener_closed,
    leading_connective,
    not_before_as_after,
    not_one_reference,
    one_last_step,
    opener_closed,
    subordinate_first,
)
from nl2hltl2plan.language.grammar.order_remarks import (
    FIRST_LAST_SENTENCE,
    NO_ORDER_SENTENCE,
    REL_SENTENCE,
    order_remark,
)
from nl2hltl2plan.language.grammar.phrases import match_prep, parse_np, tokens
from nl2hltl2plan.language.grammar.sentence_joins import (
    both_of_two_sentences,
    container_steps,
    content_goes,
    holder_named,
    joined_treatments,
)
from nl2hltl2plan.language.grammar.state_references import finished_thing, the_moment
from nl2hltl2plan.language.grammar.subordinate import after_ref, placed_after, treated_before, treatment_of_it
from nl2hltl2plan.language.grammar.verbless_items import (
    names_holder_before,
    names_object_before,
    verbless_placement,
    verbs_written,
)
from nl2hltl2plan.language.grounding import find_mentions, sentence_start
from nl2hltl2plan.language.headings import wish_heading
from nl2hltl2plan.language.landmarks import subject_sources, wished_put
from nl2hltl2plan.language.statements import RELATIVE_PLACE


@dataclass
class Sentence:
    """One sentence that states tasks: its text, where it starts in the normalised instruction, the body
    left after its order markers were stripped, and those markers as (kind, reference) pairs."""

    index: int  # position among all sentences of the instruction (relation sentences included)
    text: str
    start: int
    body: str
    markers: list[tuple[str, str]] = field(default_factory=list)  # leading ("Then,", "After X-ing the Z,")
    trailing: list[tuple[str, str]] = field(default_factory=list)  # trailing ("at any time", "first")

    @property
    def offset(self) -> int:
        """Where the body starts in the normalised instruction."""
        return self.start + self.text.index(self.body) if self.body in self.text else self.start


@dataclass
class RelationSentence:
    """ "The red block should be placed before the blue block": an order between tasks named by objects."""

    kind: str  # "before" or "after"; "first" / "last": `a` before / after every other task (`b` empty);
    # "in_order" / "in_reverse": the tasks stated before sentence `sentence` ("Do them in that order.")
    a: str
    b: str
    sentence: int = -1


@dataclass
class Sentences:
    """The result of step 1: the sentences that state tasks and the relation sentences."""

    sentences: list[Sentence] = field(default_factory=list)
    relations: list[RelationSentence] = field(default_factory=list)


def read_sentences(text: str) -> Sentences:
    """Split a normalised instruction into sentences and strip their order markers. Sentences that only say
    that the order is free ("The order does not matter.") are dropped: the absence of relations says it."""
    out = Sentences()
    for index, (sentence, start) in enumerate(split_sentences(text)):
        markers, body = strip_leading(sentence)
        # with its index: "That one first." names the task of the sentence before
        if (one := first_last_sentence(sentence)) is not None:
            out.relations.append(RelationSentence(one.kind, one.a, one.b, index))
            continue
        rel = relation_sentence(body)
        if rel is not None:
            out.relations.append(rel)
            continue
        # "Soap bottles first, toilet paper last."; "The CD whenever." of a CD named before
        if (remark := order_remark(sentence, text[:start])) is not None:
            out.relations += [RelationSentence(f"remark_{k}", a, b, index) for k, a, b in remark]
            continue
        trailing, body = strip_trailing(body)
        body = body.strip(" ,")
        if not body:
            continue
        if _DO_THEM.match(body) and [kind for kind, _ in trailing] in ([G.IN_ORDER], [G.IN_REVERSE]):
            out.relations.append(RelationSentence(trailing[0][0], "", "", index))
            continue
        rel = relation_sentence(body)
        if rel is not None:
            out.relations.append(rel)
            continue
        if NO_ORDER_SENTENCE.search(body) and not any(w in G.VERBS for w, _, _ in tokens(body)[:1]):
            continue
        out.sentences.append(Sentence(index, sentence, start, body, markers, trailing))
    return out


# "Do them in that order.": a sentence whose order is about the tasks stated before it
_DO_THEM = re.compile(
    r"^(?:(?:please|now)\s+)?(?:go|(?:do|perform|complete|handle|carry\s+out)\s+(?:them|these|those|it(?:\s+all)?|"
    r"all\s+of\s+(?:them|these|those|it)|everything|the\s+(?:tasks|steps|jobs)))(?:\s+please)?$",
    re.IGNORECASE,
)


def strip_leading(body: str) -> tuple[list[tuple[str, str]], str]:
    """Leading order markers ("Then,", "Finally,", "After placing the statue,", "First,") and the rest."""
    markers: list[tuple[str, str]] = []
    changed = True
    while changed:
        changed = False
        split = after_ref(body)
        if split is not None:
            markers += clause_refs("after", split[0])
            body = split[1]
            changed = True
            continue
        for pat, kind in G.LEADING:
            m = pat.match(body)
            if m and m.end() > 0:
                ref = m.groupdict().get("ref") or (m.group(0) if kind == G.AFTER_ALL else "")
                if kind in (G.AFTER_REF, G.BEFORE_REF):  # "After X and before Y, Z": both about Z
                    markers += clause_refs("after" if kind == G.AFTER_REF else "before", ref)
                elif kind:
                    markers.append((kind, ref))
                body = body[m.end() :]
                changed = True
                break
        if not changed and (said := leading_connective(body)) is not None:  # a phrase no table names
            markers.append(said[:2])
            body = body[said[2] :]
            changed = True
    return one_last_step(markers), body


def strip_trailing(body: str) -> tuple[list[tuple[str, str]], str]:
    """Trailing order markers ("at any time", "first", "after moving the X") and the rest."""
    trailing: list[tuple[str, str]] = []
    changed = True
    while changed and body:
        changed = False
        for pat, kind in G.TRAILING:
            m = pat.search(body)
            # "Y after X-ing Z, and then W": the reference ends before "then" (no trailing reference); "Y
            # after X, and W after Z": a clause of its own with its own reference follows (none either)
            if m and kind == "ref" and not_one_reference(m["ref"]):
                continue
            # "Y after heating it in the microwave": the treatment of Y's own object, no reference
            if m and kind == "ref" and m.group("rel").lower() == "after" and treatment_of_it(m.group("ref")):
                continue
            if m and m.start() > 0:
                if kind == "ref":
                    trailing += clause_refs(m.group("rel"), m.group("ref"))
                elif kind:  # a courtesy ("cheers") has no kind: only dropped
                    trailing.append((kind, ""))
                body = body[: m.start()]
                changed = True
                break
    return trailing, body


# "Do the candle before the soap.": an order between the tasks of two named objects; also tasks named by a
# description ("Do the roll ones before the others", "The washing jobs before the potato", "do the first two
# before the lamp ones": h190; `references.ref_targets` reads the descriptions), the verb left out only where
# the first words name tasks ("ones", "jobs") or their position ("the first two")
_TASKS_SAID = r"(?:ones?|jobs?|tasks?|chores?|parts?|first\s+(?:two|three)|last\s+(?:two|three))"
_DO_BEFORE = re.compile(
    r"^(?:(?:please\s+)?(?:do|handle)\s+(?P<a>(?:the|that|this)\s+[a-z]+(?:\s+[a-z]+){0,2})"
    rf"|(?P<a2>(?:the|that|this)\s+(?:[a-z]+\s+){{0,2}}{_TASKS_SAID}))"
    r"\s+(?P<rel>before|after)\s+"
    r"(?P<b>(?:the|that|this|all\s+the)\s+[a-z]+(?:\s+[a-z]+){0,2}|everything\s+else|the\s+rest)$",
    re.IGNORECASE,
)


def relation_sentence(body: str) -> RelationSentence | None:
    """ "The red block should be placed before the blue block" (a sentence that starts with no verb), "Do the
    candle before the soap"."""
    if one := _DO_BEFORE.match(body):
        return RelationSentence(one["rel"].lower(), one["a"] or one["a2"], one["b"])
    rel = REL_SENTENCE.match(body)
    if rel and not any(w in G.VERBS for w, _, _ in tokens(rel.group("a"))[:1]):
        return RelationSentence(rel.group("rel").lower(), rel.group("a"), rel.group("b"))
    return None


def first_last_sentence(sentence: str) -> RelationSentence | None:
    """ "Do the fork first." / "Start with the fork." / "The mug last.": the task of one object named by
    another sentence comes before (after) every other task."""
    if one := FIRST_LAST_SENTENCE.match(sentence.strip(" .!")):
        return RelationSentence((one["rel"] or "first").lower(), one["a"] or one["start"], "")
    return None


# "Y after you to heat X" (a clause written as an infinitive, "To heat X.", put after a connective): the
# "to" is the clause's own, "after you heat X"
_CONNECTIVE_TO = re.compile(r"\b(after|before|until|once|when)\s+(you\s+)?to\s+(?=[a-z])", re.I)


def without_connective_to(text: str) -> str:
    """ "Y after you to heat X" -> "Y after you heat X" (the structure model reads it so too)."""
    return _CONNECTIVE_TO.sub(lambda m: f"{m.group(1)} {m.group(2) or ''}", text)


# "as soon as you've X" is "once you've X"
_AS_SOON_AS = re.compile(r"\bas\s+soon\s+as\b(?!\s+(?:possible|you\s+can)\b)", re.I)
# "once you've put X" after a connective: "once you have put X" (the form the references read; no rule
# after this one, nor the leading markers, sees "you've" after a connective)
_CONNECTIVE_YOUVE = re.compile(r"\b(after|once|when|before|until)\s+you've\b", re.I)
# "Only after you've X should you Y" (the clause after the connective, then an inverted "should you"):
# "After you have X, Y"
_ONLY_AFTER_SHOULD = re.compile(
    r"\bonly\s+(after|once|when)\s+([^,.;!?]+?),?\s+(?:should|can|may|must|do|will)\s+you\s+(?=[a-z])", re.I
)
# "both the mug and the apple", "the mug and the apple both in the sink", "the cup and the bowl all in the
# sink": the quantifier names the listed things, it is no count of the last one
_DET = r"(?:the|a|an|my|your|this|that)"  # the words that open a listed object's noun phrase
_BOTH_BEFORE_LIST = re.compile(rf"\bboth\s+(?={_DET}\s+[^,.;!?]+?\s+and\s+{_DET}\s)", re.I)
_BOTH_AFTER_LIST = re.compile(
    rf"(\band\s+{_DET}\s+[a-z]+(?:\s+[a-z]+)?)\s+(?:both|all)\s+"
    r"(?=(?:in|into|on|onto|inside|to|back|away)\b)",
    re.I,
)
# "A and B, both before C" / "..., all of them after C": the quantifier says the reference is the whole
# list's, as a reference closing a sentence already is
_ALL_OF_THEM_BEFORE = re.compile(
    r",\s*(?:both|all|each)(?:\s+of\s+(?:them|these|those))?\s+(?=(?:before|after|once|until|when)\b)", re.I
)


def _lists_before(text: str, at: int) -> bool:
    """Does the sentence that runs up to `at` join two things with "and" (what "both" / "all" sum up)?"""
    return re.search(r"\band\b", re.split(r"[.;!?]", text[:at])[-1], re.I) is not None


# "X, but not before Y-ing Z" / "X not until Y": X only after Y
_NOT_BEFORE = re.compile(r",?\s+(?:but\s+)?not\s+(?:before|until)\s+", re.I)
# "the mug that is on the counter": where the mug is now, a source ("the mug from the counter"), not where
# it goes
_WHERE_IT_IS = re.compile(rf"\b{RELATIVE_PLACE}\s+(?=(?:the|a|an)\s)", re.I)
_UNTIL = re.compile(r"\b([Dd])(?:o not|on't) ([^.;!?]+?) until (?:you )?([^.;!?]+)")
# "Once (you are) done (with the task to) X, Y" names what is done: "After X, Y" (not "Then Y")
_DONE_WITH = re.compile(
    r"\b([Oo]nce|[Ww]hen|[Aa]fter) (?:you(?:'re| are| have| have been)? )?(?:done|finished|through) "
    r"(?:with )?(?:the (?:task|job) (?:of |to ))?"
    r"(?!with\b|(?:that|this|it|these|those|everything|all|both)\b)"
    r"(?=[a-z][^,.;!?]* [^,.;!?]+,)"
)


_OFF = re.compile(
    r"\b((?:rins|wash|clean|wip|cool|warm|heat|chill)(?:e|ed|es|ing)?) off\b(?! of\b)", re.IGNORECASE
)


_BACK = re.compile(r",\s+back (in|into|on|onto|to)\b", re.IGNORECASE)
# "place the pan in the fridge to go back on the stove": the pan goes back there next (a robot goes to
# a place, not on or in it)
_TO_GO_BACK = re.compile(r"\s+to go back (in|into|on|onto)\b", re.IGNORECASE)


# "a mug that's got a pencil in it": a container, as "a mug with a pencil in it"
_HAS_IN_IT = re.compile(
    r"\b(?:that|which)(?:'s| has| is holding| holds)(?: got)? "
    r"(?=(?:a|an|the|some|two) [^,.;]*? in (?:it|them)\b)",
    re.IGNORECASE,
)
# "move soap to the sink, followed by moving to the cupboard": one more stop, the same object
_FOLLOWED_TO = re.compile(
    r",?\s+followed by (?:moving|taking|bringing|carrying|putting|placing) "
    r"(?:it |them )?(to|into|onto|in|on)\b",
    re.IGNORECASE,
)
# "cool some bread and the place it on the counter", "put two apples on a counter the cut them": "the"
# typed for "then" (a verb and "it"/"them" follow it, so it opens no noun phrase)
_THE_FOR_THEN = re.compile(r"\b(?<!of )the (?=([a-z]+) (?:it|them)\b)", re.IGNORECASE)
# "X, but before you do that, Y" / "X, but first Y" / "X, and before that, Y" inside a sentence: Y comes
# first ("Before that, Y."); "and first" is left alone ("rinse it and first ..." is no such marker)
_BEFORE_THAT = r"before\s+(?:that|this|(?:you\s+do|doing)\s+(?:that|this|so|it))"
_BUT_BEFORE = re.compile(
    rf"(?<=\w)\s*,?\s+(?:(?:but|though|although)\s+(?:{_BEFORE_THAT}|first)|and\s+{_BEFORE_THAT})\s*,?\s+"
    r"(?=[a-z])",
    re.IGNORECASE,
)
# "X, before that Y" / "X; before you do that Y" / "X - before that tho Y" / "X. oh and before that Y" with
# no "but" (a sentence opening "Before that" is the grammar's own): Y comes first as well (users_h271's W3:
# read as a following "then", at exit 0), where a verb or a request opens Y (not "before that mug is ...")
_BARE_BEFORE = re.compile(
    rf"(?<=\w)(?:\s*[,;]\s*(?:oh\s*,?\s+(?:and\s+)?)?|\s+[-\u2013]\s*|[.!?]\s*oh\s*,?\s+(?:and\s+)?)"
    rf"{_BEFORE_THAT}"
    r"(?:\s*,?\s*(?:though|tho))?\s*,?\s+(?=(?:please\s+|pls\s+|can\s+you\s+|just\s+)?([a-z]+))",
    re.IGNORECASE,
)
# "X, but make sure you first Y" is "X, but first Y" (`order_scope.txt`'s `first_before`; before `everyday`
# reads "make sure" as a wish)
_BUT_SURE_FIRST = re.compile(
    r"(?<=\w)(\s*,?\s+(?:but|though|although)\s+)"
    rf"{phrase_list_pattern('order_scope.txt', 'first_before')}\s+",
    re.IGNORECASE,
)
_FIRST_OPENER = re.compile(r"^\s*(?:first|firstly)\b", re.IGNORECASE)  # "begin by A, though first B": B, A
# ("next to the stove" is a place, not "next")
_LATER_WORD = re.compile(
    r"\b(?:then|finally|lastly|after\s+that|afterwards?|next(?!\s+to\b))\b", re.IGNORECASE
)


# "X, Y and Z, one after the other": a sequence in the order they are named, "in that order" (read before
# "after the other" can be taken for a reference to a task)
_ONE_AFTER_THE_OTHER = re.compile(
    r"\s*,?\s*one\s+after\s+(?:the\s+other|another)(?=\s*(?:[.;!?]|$))", re.IGNORECASE
)
# "X, then Y, and last Z": "last" after a comma or "and", before a noun phrase or a verb, is the adverb
# "lastly" (the grammar's word for it); "the last shelf" is left alone
_LAST_ADVERB = re.compile(
    r"(,\s*(?:and\s+)?|\band\s+)last(?:\s+of\s+all)?\s*,?\s+(?=(?:the|a|an|your|my|put|place|move|set|take|"
    r"bring|leave|drop|throw|heat|cool|chill|wash|rinse|clean|slice|cut|examine|look)\b)",
    re.IGNORECASE,
)


# "on the small table, left of the tomato", "on the counter right of the sink": a side of a landmark after
# a place is where on it, "to the left of" ("on the left of the counter" is the counter's side: left as is)
_SIDE_OF = re.compile(
    r"\b(?P<pre>(?!(?:the|a|an|to|on|in|at)\b)[a-z]+)(?P<sep>\s*,\s*|\s+)(?P<side>left|right)\s+of\s+"
    r"(?=(?:the|a|an)\s)",
    re.IGNORECASE,
)
# "place two bottles o the toilet": "o" before an article is "on" typed without its "n"
_O_FOR_ON = re.compile(r"(?<=[a-z] )o (?=(?:the|a|an) )", re.IGNORECASE)


# "put a metal pot a potato slice in it on the table": a container, then what is "in it", its "with" left
# out ("a pot with a potato slice in it")
_CONTENT_IN_IT = re.compile(
    r"\b(?P<holder>(?:a|an|the)\s+(?:[a-z]+\s+){0,2}?[a-z]+)\s+"
    r"(?=(?P<content>(?:a|an|the)\s+[a-z]+(?:\s+[a-z]+){0,2})\s+in\s+(?:it|them)\b)",
    re.IGNORECASE,
)


def _with_left_out(m: re.Match[str]) -> str:
    """ "a metal pot " -> "a metal pot with " where the holder names a movable container and what follows
    is one noun phrase (no preposition, no verb) of a thing."""
    holder, content = parse_np(m["holder"]), m["content"]
    words = [w for w, _, _ in tokens(content)]
    one_np = all(
        match_prep(words, k) is None and (w not in G.VERBS or w in G.SLICE_NOUNS) for k, w in enumerate(words)
    )
    if holder.is_movable_receptacle() and one_np and find_mentions(content):
        return f"{m['holder']} with "
    return m[0]


# "arrange cushion one and two on the couch": two things counted off by number are two of them
_NUMBERED_PAIR = re.compile(r"\b(?P<noun>[a-z]+) (?:one|1) and (?:two|2)\b", re.IGNORECASE)


def _two_of(m: re.Match[str]) -> str:
    noun = m["noun"]
    if not find_mentions(noun) or noun.lower() in G.VERBS:
        return m[0]
    return f"two {noun if noun.endswith('s') else noun + 's'}"


def _keeps_but_first(text: str, m: re.Match[str]) -> bool:
    """Is "but first" better left to the sentence's other order words: the sentence opens with "first" /
    "start by", or goes on with "then" / "finally" after it (the structure model reads those whole)?"""
    start = sentence_start(text, m.start())
    rest = re.split(r"[.;!?]", text[m.end() :], maxsplit=1)[0]
    return _FIRST_OPENER.match(text[start : m.start()]) is not None or _LATER_WORD.search(rest) is not None


# "grab the apple and the tomato and put them (both) in the fridge": the plural pronoun is the list, so
# "put the apple and the tomato in the fridge" (each one a task, as a listed object is)
_TAKE_LIST_THEN_PUT = re.compile(
    r"\b(?:grab|take|pick\s+up|get|collect|gather|fetch)\s+(?P<objs>[^,.;!?]+?\s+and\s+[^,.;!?]+?)\s*,?\s+"
    r"(?:and\s+)?(?:then\s+)?(?P<verb>put|place|set|move|bring|carry|throw|drop|take|leave|store|stack|return)\s+"
    r"(?:them(?:\s+(?:both|all))?|both(?:\s+of\s+them)?|all\s+of\s+them)\s+"
    r"(?=(?:in|into|on|onto|to|inside|away|back|down)\b)",
    re.IGNORECASE,
)
# "a rinse off bar of soap", "the rinse soap": the rinsed one (ALFRED's annotators' adjective)
_RINSE_ADJ = re.compile(r"\b(a|an|the)\s+rinse(?:\s+off)?\s+(?=[a-z])", re.IGNORECASE)
# Inside a sentence, a marker that the step before is done is "then" (at its start the leading markers
# read it): "put X in A, and once that's done put Y in B", "... and when you're done put Y ...",
# "put X in A, and after that put Y in B", "..., and once you've done that, put Y in B" (its "that" first:
# left after "done", it read ", then that, put Y" and lost the order)
_THEN_INSIDE = re.compile(
    r"(?<=\w)\s*,?\s+(?:and\s+)?(?:"
    r"(?:once|when|after)\s+you\s+have\s+(?:done|finished|completed)\s+(?:that|this|it|so)|"
    r"(?:once|when|after)\s+(?:that's|that\s+is|it's|it\s+is|this\s+is|you're|you\s+are|you\s+have)?"
    r"\s*(?:done|finished|through|there|in\s+place|handled|taken\s+care\s+of|out\s+of\s+the\s+way)"
    r"(?:\s+with\s+(?:that|it|this))?"
    r"|after\s+(?:that|this)|afterwards?|following\s+that|only\s+then"
    r")(?!\s*,?\s+(?:and|then)\b)\s*,?\s+(?=[a-z])",  # "X afterwards, and Y": the word closes X (h226)
    re.IGNORECASE,
)
# "Y when you're done putting X in A", "Y when done heating it": what is done is named, a reference ("Y
# after putting X in A")
_DONE_GERUND = re.compile(
    r"\b(after|once|when)\s+(?:you(?:'re|\s+are|'ve|\s+have)?\s+)?(?:done|finished|through)\s+(?:with\s+)?"
    r"(?=[a-z]*[aeiouy][a-z]*ing\b)",  # a gerund's stem has a vowel: "bring" is none
    re.IGNORECASE,
)
# "on the middle shelf in the fridge", "the top shelf of the cabinet": a shelf that is part of an appliance
# or a cabinet is that receptacle (the world has no shelf object inside it)
_SHELF_OF = re.compile(
    r"\b(?:the|a)\s+(?:(?:top|middle|bottom|upper|lower|first|second|third|left|right)\s+)?"
    r"shel(?:f|ves)\s+(?:in|of|inside)\s+(?=(?:the|a)\s+(?:fridge|refrigerator|freezer|cabinet|cupboard|"
    r"microwave|safe)\b)",
    re.IGNORECASE,
)
# "the second from the bottom shelf", "the drawer second from the top": a position counted from a side is
# said after the noun it picks ("the second shelf from the bottom"), as the rules read it
_COUNTED_FROM_BEFORE = re.compile(
    r"\b(?P<det>the|a)\s+(?P<nth>(?:first|second|third|fourth|last|top|bottom|\d(?:st|nd|rd|th)))\s+"
    r"(?P<side>from\s+the\s+(?:top|bottom|left|right|end|front|back))\s+(?P<noun>[a-z]+)\b",
    re.IGNORECASE,
)
_COUNTED_FROM_AFTER = re.compile(
    r"\b(?P<det>the|a)\s+(?P<noun>[a-z]+)\s+(?P<nth>(?:first|second|third|fourth|last|\d(?:st|nd|rd|th)))\s+"
    r"(?P<side>from\s+the\s+(?:top|bottom|left|right|end|front|back))\b",
    re.IGNORECASE,
)
_STATE_ALT = "|".join(sorted(G.STATE_WORDS))
# "a chilled, cut slice", "a cleaned, filled bowl of water": states listed before one noun
_STATES_LISTED = re.compile(rf"\b({_STATE_ALT}),\s+(?=(?:{_STATE_ALT}|filled)\b)", re.IGNORECASE)
# "a chilled and sliced tomato", "put washed and dried mugs ...": after an article or a placing verb, two
# states joined by "and" describe one noun ("cut and cool the apple" stays two verbs)
_STATES_JOINED = re.compile(
    rf"\b((?:a|an|the|some|two|put|place|set|move|bring|take)\s+(?:{_STATE_ALT}))\s+and\s+"
    rf"(?=(?:{_STATE_ALT}|dried)\s+[a-z])",
    re.IGNORECASE,
)


def _as_cased(word: str, replaced: str) -> str:
    """`word` with a capital where the words it replaces start with one (the start of a sentence)."""
    return word.capitalize() if replaced[:1].isupper() else word


@lru_cache(maxsize=1024)  # a pure function of the text, asked again by each reading of one instruction
def normalize(text: str) -> str:
    """The text as the rules read it: straight quotes, a space after a full stop, no parenthetical remarks,
    each phrasing above rewritten onto the one the rules read (its comment says which), single spaces and
    the placement verb a terse request leaves out (`supply_put`)."""
    text = text.replace("\u2019", "'").replace("\u2018", "'").replace("\u201c", '"').replace("\u201d", '"')
    text = re.sub(r"(?<=[a-z])\.(?=[A-Za-z])", ". ", text)
    text = _BUT_SURE_FIRST.sub(r"\1first ", text)
    text = without_call(everyday(text))  # terse, spoken and need styles, "hey robot put" (issue 28)
    text = joined_treatments(text)  # "Heat the egg. Then put it in the fridge.": one task (sentence_joins.py)
    text = holder_named(text)  # "examine the mug ..., then put a pen in it": the mug (sentence_joins.py)
    text = _O_FOR_ON.sub("on ", text)
    text = _SIDE_OF.sub(r"\g<pre>\g<sep>to the \g<side> of ", text)
    text = _CONTENT_IN_IT.sub(_with_left_out, text)
    text = _NUMBERED_PAIR.sub(_two_of, text)
    text = re.sub(r"\s*\([^)]*\)", "", text)  # parenthetical remarks: "(where the red block is now)"
    text = without_connective_to(text)
    text = _AS_SOON_AS.sub(lambda m: _as_cased("once", m[0]), the_moment(text))
    text = _CONNECTIVE_YOUVE.sub(r"\1 you have", text)
    text = _BOTH_AFTER_LIST.sub(r"\1 ", _BOTH_BEFORE_LIST.sub("", text))
    text = both_of_two_sentences(text)  # "A. B too, both before C": A and B (sentence_joins.py)
    text = _ALL_OF_THEM_BEFORE.sub(lambda m: " " if _lists_before(text, m.start()) else m[0], text)
    text = _WHERE_IT_IS.sub("from ", text)
    text = _ONLY_AFTER_SHOULD.sub(lambda m: f"{_as_cased('after', m[0])} {m[2]}, ", text)
    # "Do not Y until (you) X" states the order of "After X, Y" (ANNOTATION_GUIDE.md)
    text = _UNTIL.sub(lambda m: f"{_as_cased('after', m[1])} {m[3]}, {m[2]}", text)
    text = not_before_as_after(text)
    text = command_after_state(text)
    text = _NOT_BEFORE.sub(", but only after ", text)
    text = _STATES_LISTED.sub(r"\1 ", text)  # "a chilled, cut slice": one noun phrase, not two clauses
    text = _STATES_JOINED.sub(r"\1 ", text)
    text = _OFF.sub(r"\1", text)  # "a rinsed off knife", "cool off a plate": the state, not a direction
    text = _BACK.sub(r", then back \1", _TO_GO_BACK.sub(r", back \1", text))  # "put it in the fridge, back in
    # the microwave": a sequence
    text = _HAS_IN_IT.sub("with ", text)
    text = _COUNTED_FROM_BEFORE.sub(r"\g<det> \g<nth> \g<noun> \g<side>", text)
    text = _COUNTED_FROM_AFTER.sub(r"\g<det> \g<nth> \g<noun> \g<side>", text)
    text = _SHELF_OF.sub("", text)
    text = _TAKE_LIST_THEN_PUT.sub(lambda m: f"{m['verb']} {m['objs']} ", text)
    text = _BARE_BEFORE.sub(lambda m: ". Before that, " if m[1].lower() in G.VERBS else m[0], text)
    text = _BUT_BEFORE.sub(lambda m: m.group(0) if _keeps_but_first(text, m) else ". Before that, ", text)
    text = _THE_FOR_THEN.sub(lambda m: "then " if m.group(1).lower() in G.VERBS else m.group(0), text)
    text = _RINSE_ADJ.sub(r"\1 rinsed ", lamp_phrasing(text))
    text = _FOLLOWED_TO.sub(r" and finally \1", text)
    text = _LAST_ADVERB.sub(r"\1lastly ", text)
    text = re.sub(r";\s+(?=(?:and|also|plus)\s)", ", ", text)  # "Next, D; and E" / "D; also E": E goes with D
    text = _ONE_AFTER_THE_OTHER.sub(", in that order", text)
    text = placed_after(treated_before(text))  # before `_DONE_GERUND`: "when done heating it" is no reference
    text = _DONE_GERUND.sub(r"\1 ", text)
    text = after_the_step(text)
    text = _THEN_INSIDE.sub(", then ", text)
    text = _DONE_WITH.sub(lambda m: _as_cased("after ", m[1]), text)
    text = closing_orders(subordinate_first(finished_thing(done_opener_closed(opener_closed(text)))))
    text = content_goes(re.sub(r"\s+", " ", text).strip())  # "a spoon in a glass goes ...": its container
    return container_steps(supply_put(text))  # after the verbs are written


# The placement verb a terse or conversational request leaves out (issue 24's tabletop styles):
# "I'd like the apple to go in the plate", "we need the apple on the plate" -> "put the apple in ...";
# "the apple goes in the plate" / "the apple in the plate" (a sentence with no verb) -> "put the apple
# in the plate"; "start with the apple in the plate" -> "first put the apple in the plate".
_WISH = re.compile(  # also a cleft: "what I'd love is for you to put ..." (h220)
    r"\b(?:what\s+(?:I|we)(?:'d|\s+would)\s+(?:like|love)\s+is\s+for\s+you\s+to\s+|"
    # a heading that says a list of goals: "What I need: a warm apple slice in the fridge, ..." (h231)
    + wish_heading()
    + r"|(?:(?:I|we)(?:'d|\s+would|\s+will)?\s+|(?:^|(?<=[.!?;]\s))(?=(?:need|want)\s+(?:the|an?|my|two)\s))"
    + courtesy_pattern("wish_verb")  # the wish verbs (`courtesy.txt`); subject left out: "need the X on Y"
    + r"\s+(?:(?:for\s+)?you\s+to\s+)?)",
    re.I,
)
_TO_GO = re.compile(
    r"\s+(?:(?:needs?\s+|has\s+|have\s+)?to\s+(?:go|be(?:\s+(?:put|placed|moved|set))?)|goes|go|belongs?|"
    r"(?:should|must)\s+(?:go|be)|(?:is|are)\s+going|ends?\s+up)"
    r"\s+(?=(?:in|into|on|onto|to)\s)",
    re.I,
)
# the same verbs with no destination after them: a place in the subject is still where the thing is ("the
# mug in the sink should go.", "... goes next to the stove" read the sink as the destination)
_TO_GO_NOWHERE = re.compile(
    _TO_GO.pattern.rsplit(r"\s+(?=", 1)[0]
    + r"(?=\s*(?:[.;!?,]|$)|\s+(?:next\s+to|close\s+to|beside|by|near|behind|in\s+front\s+of)\s)",
    re.I,
)
_START_WITH = re.compile(r"\b(?:start|begin)\s+with\s+(?=(?:the|a|an)\s)", re.I)
_PLACE_AFTER = re.compile(r"[^.;!?]*\b(?:in|into|on|onto|to)\s", re.I)


def supply_put(text: str) -> str:
    """The text with the placement verb its requests leave out written in (see above); a sentence with
    a verb, or whose words before the place name no object, is left as it is."""
    text = subject_sources(wished_put(text, _WISH), _TO_GO, names_object_before)  # where the thing is
    text = subject_sources(text, _TO_GO_NOWHERE, names_object_before, near_too=False)
    text = _WISH.sub(lambda m: "" if _verb_follows(text, m.end()) else "put ", text)
    text = _TO_GO.sub(lambda m: " " if names_holder_before(text, m.start()) else m.group(0), text)
    # "start with the apple on the plate" is "first put ..."; "Start with the fork." alone names a task of
    # another sentence (`first_last_sentence`)
    text = _START_WITH.sub(lambda m: "first put " if _PLACE_AFTER.match(text, m.end()) else m[0], text)
    out, pos = [], 0
    for sentence, start in split_sentences(text):
        _, body = strip_leading(sentence)
        at = start + len(sentence) - len(body)
        if (said := verbs_written(body)) is not None:  # a list with the verbs left out (verbless_items.py)
            out.append(text[pos:at] + said)
            pos = at + len(body)
        elif verbless_placement(body):
            out.append(text[pos:at] + "put ")
            pos = at
    return "".join(out) + text[pos:]


def _verb_follows(text: str, at: int) -> bool:
    first = tokens(text[at:])[:1]
    return bool(first) and first[0][0] in G.VERBS


def split_sentences(text: str) -> list[tuple[str, int]]:
    """(sentence, start) for each sentence, split at `.`, `;`, `!`, `?`."""
    out: list[tuple[str, int]] = []
    pos = 0
    for m in re.finditer(r"[.;!?]+(?:\s+|$)", text):
        chunk = text[pos : m.start()].strip()
        if chunk:
            out.append((chunk, pos + (len(text[pos : m.start()]) - len(text[pos : m.start()].lstrip()))))
        pos = m.end()
    rest = text[pos:].strip()
    if rest:
        out.append((rest, pos))
    return out
