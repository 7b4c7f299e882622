"""Order phrasings rewritten onto the forms the sentence rules read (a step of `sentences.normalize`), and
the references that several connectives after one clause state (`clause_refs`): which clause an order word
is about (issue 23)."""

from __future__ import annotations

import re

from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.phrases import tokens
from nl2hltl2plan.language.grounding import sentence_start
from nl2hltl2plan.language.order_words import UNTIL_FIRST
from nl2hltl2plan.language.statements import REFERENCE

# "Y before X, but after Z" / "Y after X and before Z": a second connective after the first reference opens
# a reference of its own, about the same main clause Y (not about X, the nearer clause)
_NEXT_REF = re.compile(
    r"\s*,?\s+(?:but|and|yet)\s+(?:(?:only|right|just|immediately)\s+)?"
    r"(?P<rel>after|before|once|prior\s+to|following)\s+(?=\S)",
    re.I,
)
# "Y after X, and W after Z": a clause of its own, with its own reference, after the first reference
_SECOND_CLAUSE = re.compile(
    r",\s+and\s+(?!(?:only|right|just|immediately|after|before|once|prior|following)\b)[^,]*?\s"
    r"(?:after|before|once)\s",
    re.I,
)


def not_one_reference(ref: str) -> bool:
    """Does a trailing reference run on into "then" or into a clause with a reference of its own?"""
    return re.search(r"\bthen\b", ref, re.I) is not None or _SECOND_CLAUSE.search(ref) is not None


# "A after the egg is in the sink, and (or ", but") put the bread ...": a reference to a state ends where a
# command of its own begins; that command is a sentence of its own (its order is not A's)
_STATE_THEN_COMMAND = re.compile(
    rf"(?<=\w )(?P<ref>{REFERENCE}\s+(?:the|a|an|your|my)\s+[^,.;!?]*?\b"
    r"(?:is|are|has\s+been|have\s+been)\b[^,.;!?]*?)(?:,?\s+and|\s*,\s*(?P<but>but))\s+"
    r"(?P<adv>(?:finally|lastly|next)\s*,?\s+)?"
    r"(?=(?:(?:please|also)\s+)?(?P<verb>[a-z]+)\b(?P<thing>\s+(?:the|a|an|your|my)\b)?)",
    re.I,
)


# "A before you put X in B, and finally C": the last step is no part of the trailing reference; it comes
# after every task before it, the referred one too
_REF_THEN_LAST = re.compile(
    r"(?<=\w )(?P<ref>(?:before|after|once|when|until)\s+[^,.;!?]*?)\s*,?\s+and\s+"
    r"(?P<adv>finally|lastly)\s*,?\s+(?=[a-z])",
    re.I,
)


def command_after_state(text: str) -> str:
    """ "A after the egg is in the sink, and put the bread ..." -> "A after the egg is in the sink. put the
    bread ..." (a state said of a thing takes no command into its reference); "..., and finally put the
    bread ..." -> "... . finally put the bread ..." (the last step, after every task before it), also after
    a reference to a task ("A before you put X in B, and finally C")."""
    text = _STATE_THEN_COMMAND.sub(lambda m: f"{m['ref']}. {m['adv'] or ''}" if _a_command(m) else m[0], text)
    return _REF_THEN_LAST.sub(lambda m: f"{m['ref']}. {m['adv']} ", text)


def _a_command(m: re.Match[str]) -> bool:
    """Does a state reference's ", and ..." / ", but ..." open a command of its own? After "but", only one
    that names its thing ("but put the bread ...": "but put it there carefully" says how, of its clause)."""
    return m["verb"].lower() in G.VERBS and (not m["but"] or m["thing"] is not None)


def clause_refs(rel: str, ref: str) -> list[tuple[str, str]]:
    """The references of one main clause, leading or trailing: "before you put the egg in the fridge, but
    after the tomato goes in the sink" -> a BEFORE_REF and an AFTER_REF, each about the clause stated."""
    out: list[tuple[str, str]] = []
    for part in reversed(list(_NEXT_REF.finditer(ref))):
        out.append((_ref_kind(part["rel"]), ref[part.end() :]))
        ref = ref[: part.start()]
    return [(_ref_kind(rel), ref), *reversed(out)]


def _ref_kind(rel: str) -> str:
    """The marker of a connective: "before" / "prior to" / "ahead of" -> BEFORE_REF; "after" / "once" ->
    AFTER_REF."""
    return G.BEFORE_REF if rel.lower().split()[0] in {"before", "prior", "ahead"} else G.AFTER_REF


# "Do not put Y in B before X": the same order as "until" for a task's own verb ("do not open the fridge
# before ..." forbids an action, a constraint that `negations` reads)
_NOT_BEFORE_TASK = re.compile(
    r"\b([Dd])(?:o not|on't) ((?:put|place|move|set|heat|cool|chill|wash|rinse|clean|slice|cut|bring|take|"
    r"throw|drop)\b[^.;!?]+?) (?:before|prior to) (?:you )?([^.;!?]+)"
)


# "until then" / "until that is done": "after that"
_THAT = re.compile(r"^(?:then|(?:that|this|it)(?:'s|\s+is)\s+(?:done|finished|complete))$", re.I)


# an order said after its task (paper_h301): "Y once you're done with those two" closing its sentence is "Y
# once both are done" (the two tasks said before Y)
_THOSE_TWO_AFTER = re.compile(
    r"\b(?P<lead>once|when|after)\s+(?:you(?:'ve|\s+have|'re|\s+are)?\s+(?:done|finished)\s+(?:with\s+)?"
    r"(?:those|these|the)\s+two|(?:those|these|the)\s+two\s+(?:are|have\s+been)\s+(?:done|finished))(?=\s*(?:[.;!?]|$))",
    re.I,
)


def not_before_as_after(text: str) -> str:
    """ "Do not put X in A before Y" -> "After Y, put X in A"; "Until Y, don't put X in A" -> the same."""
    text = _THOSE_TWO_AFTER.sub(r"\g<lead> both are done", text)
    text = UNTIL_FIRST.sub(lambda m: f"After {_THAT.sub('that', m['ref'])}, {m['task']}", text)
    return _NOT_BEFORE_TASK.sub(lambda m: f"{'After' if m[1] == 'D' else 'after'} {m[3]}, {m[2]}", text)


# "A. B. Do these in either order, then C": C after all of them (the sentence ends at the free order)
_FREED_THEN = re.compile(
    r"\b((?:do|handle|complete|finish)\s+(?:these|those|them|both(?:\s+of\s+them)?|all\s+of\s+(?:them|these|those)|"
    r"the\s+(?:two|three|four)(?:\s+(?:tasks|things|jobs))?)(?:\s+first)?\s*,?\s+in\s+(?:any|either|whatever)\s+order)"
    r"\s*,?\s+"
    r"(?:and\s+)?(?:then|after\s+that|afterwards?)\s*,?\s+(?=[a-z])",
    re.IGNORECASE,
)


# "A, after which B" inside a sentence: "A, then B" (a leading "After which, B" is a table's "then")
_AFTER_WHICH = re.compile(r"(?<=\w)\s*,\s*(?:and\s+)?after\s+which\s*,?\s+(?=[a-z])", re.IGNORECASE)


# "A, then B, and at the (very) end C", "..., and last of all C" ("all" counts nothing), "..., and to
# finish, C": "finally" where a clause opens inside a sentence ("at the end of the counter" is a place, "to
# finish the job," a purpose; a leading "At the end," is the tables' own)
_AT_THE_END = re.compile(
    r"(?:(?<=,\s)|(?<=\band\s))(?:at\s+the\s+(?:very\s+)?end\b(?!\s+of\b)|last\s+of\s+all\b"
    r"|to\s+(?:finish(?:\s+up)?|end|wrap\s+(?:it\s+|things\s+)?up|conclude)(?=\s*,))",
    re.IGNORECASE,
)


# "A, and only after that B" / "and right after that" / "and only then": the focus word adds nothing to
# the order the connective states (inside a sentence, where `sentences` reads the connective alone)
_FOCUS_CONNECTIVE = re.compile(
    r"(?<=\w)(?P<join>\s*,?\s+(?:and\s+)?)(?:only|just|right|immediately)\s+"
    r"(?=(?:after\s+(?:that|this)|once\s+(?:that|this|it)|then)\b)",
    re.I,
)

# "Once both are in, and not before, B" (h312): the aside says again the wait it follows
_NOT_BEFORE = re.compile(r"(?<=\w)\s*,\s*and\s+not\s+(?:before|sooner|earlier)\s*(?=,)", re.I)


# "A. Only after that, B" / "Only then, B" / "Only once the mug is in, B": a sentence opened by the focus word
# (it was read as a word of its own, "Only, then B": partial)
_FOCUS_OPENER = re.compile(
    r"(?:^|(?<=[.;!?]\s))(?:only|just|right|immediately)\s+(?=(?:after|once|when|then)\b)", re.I
)


# "After that, though, Y" / "Before you do that, however, Y": a contrast word set off by commas after a
# leading order phrase says nothing of the order (left in, the learned structure model took "though" for
# "though first" and put Y first); "First, though, Y" is "but first" (Y before what was said), kept
_INTERJECTED = re.compile(
    r"(?P<lead>(?:^|(?<=[.;!?])\s+)(?:and\s+)?(?:after|before|once|when|then|next|finally|lastly|"
    r"afterwards?|later)\b[^,.;!?]*?)\s*,\s*(?:though|however|anyway)\s*,\s+(?=[a-z])",
    re.I,
)


# "A, then B, and the C on D last": "last" closing a list item whose verb is left out is about that item
# alone (left at the clause's end, it made every item of the list last, B not before C)
_LAST_ITEM = re.compile(
    r"(?<=\w)(?P<join>\s*,?\s+and\s+)(?P<item>(?:the|a|an|your|my)\s[^,.;!?]*?)\s+(?:last|lastly)"
    r"(?=\s*(?:[.;!?]|$))",
    re.I,
)


# "Before doing anything else, X" / "X before doing anything else": "before anything else", which the
# tables read (the gerund was taken for a reference naming no task)
_BEFORE_DOING_ANYTHING = re.compile(r"\b(before)\s+doing\s+(?=anything\s+else\b)", re.I)
_BEFORE_YOU_START = re.compile(r"\b(before)\s+you\s+(?:start|begin|get\s+started)(?=\s*,)", re.I)
# "Before you start on any of this, D" / "before you do any of that": "before any of this", which the tables
# read (the writer's own doing was taken for a reference to the sentence before only: D went in its middle)
_BEFORE_YOU_START_ANY = re.compile(
    r"(?:^|(?<=[.;!?]\s))(before)\s+you\s+(?:start|begin|get\s+started)?\s*(?:on|with|doing|do|tackle)?\s*"
    r"(?=(?:any|all)\s+of\s+(?:this|that|these|those|it)\s*,)",
    re.I,
)


# "Put D on E at the very end." / "... last of all" / "... as the final step" / "... when you're all done": a
# closing phrase that makes its clause the last step, as "last" does (only "at the end" and "last" were
# read; the others were left over and the task lost its order, a wrong reading). A closing "to finish" is
# not one of them: "A and B to finish" does not say which is last (refused, test_tabletop_lines)
_CLOSING_LAST = re.compile(
    r"\s*,?\s+(?:at\s+the\s+very\s+(?:end|last)|last\s+of\s+all|as\s+(?:the|a|your)\s+(?:very\s+)?(?:last|final)\s+"
    r"(?:thing|step|task|job|one)|(?:once|when)\s+you(?:'re|\s+are|'ve|\s+have)?\s+all\s+(?:done|finished))(?=\s*(?:[.;!?]|$))",
    re.I,
)


# "Put two phones on the dresser to finish." after other sentences: a sentence of one clause (no "and", no
# comma) closed by "to finish" is its task done last, as "last" (it was left unread at exit 0, a wrong
# reading); "A and B to finish" still does not say which is last, and "to finish the job" is a purpose
_ONE_CLAUSE_TO_FINISH = re.compile(
    r"(?:^|(?<=[.;!?]\s))(?P<clause>(?:(?!\band\b)[^,.;!?])+?)\s+to\s+(?:finish(?:\s+up)?|wrap\s+(?:it\s+|things\s+)?up|"
    r"conclude)(?=\s*(?:[.!?]|$))",
    re.I,
)


# "The last thing is to heat X" / "The last thing to do is chill X" / "The final step is to put X": a
# sentence that names its step's place opens with that order word ("Finally, heat X"; the frame was left
# unread, partial or refused); a verb must follow ("The last thing I need is the egg ..." is no step)
_THE_NTH_THING = re.compile(
    r"(?:^|(?<=[.;!?]\s))the\s+(?:very\s+)?(?P<nth>first|last|final)\s+(?:thing|step|task|job)\s+"
    r"(?:(?:to\s+do|you\s+(?:do|need\s+to\s+do))\s+)?is\s+(?:to\s+)?(?=(?P<verb>[a-z]+)\b)",
    re.I,
)


# "A, and B; those two can be done in any order, but only after X": the subject names the tasks just said,
# as a trailing ", in any order" does (left, "those two can be done" was a clause with no task, and X was
# lost: partial)
_THOSE_CAN_BE_FREE = re.compile(
    r"\s*[;,]\s*(?:those|these|the|both)(?:\s+(?:two|three|four))?(?:\s+(?:tasks|things|steps|jobs))?\s+"
    r"(?:can|may|could)\s+(?:be\s+done|happen|go)\s+(?=in\s+(?:any|either|whatever|whichever)\s+order\b)",
    re.I,
)


# "Put a book on the chair. As soon as it's there, Y" / "once they're in place" / "when it's inside": the
# thing of the task just said, where it was put: "once that is done" (the grammar could not tell which task
# "it's there" names)
_IT_IS_THERE = re.compile(
    r"\b(?P<lead>once|when|as\s+soon\s+as|after|now\s+that)\s+(?:it|they)(?:'s|'re|\s+is|\s+are)\s+"
    r"(?:there|in\s+place|done|finished|inside|in\s+there|on\s+there|in|on|down|away)(?=\s*,)",
    re.I,
)


# "Put a book on the desk whenever you want, but put the two books there only after X": the free task's
# clause ends at the free phrase; the trailing reference is about the clause after "but" alone (it ordered
# the free book after X too, a wrong reading)
_FREE_BUT = re.compile(rf"\b(?P<free>{G.WHENEVER}|at\s+any\s+time)\s*,\s*but\s+(?=[a-z])", re.I)


# "when you have done both, Y" / "once you've finished those two things" / "when you're done with both of
# them": "when both are done", the reference to the two tasks before that the sentence rules read (the
# writer's own doing was not read: "could not tell which tasks 'you have done both' refers to")
_YOU_DID_BOTH = re.compile(
    r"\b(?P<lead>once|when|after|as\s+soon\s+as)\s+you(?:'ve|\s+have|'re|\s+are)?\s+(?:done|finished|completed)\s+"
    r"(?:with\s+)?(?P<what>both(?:\s+of\s+(?:them|those|these))?|(?:those|these|the)\s+two"
    r"(?:\s+(?:things|tasks|steps|jobs))?)\b",
    re.I,
)


# "A, and at any point put B in C." -> "A, and put B in C at any point.": a time phrase that opens the
# sentence's last clause frees that clause alone, as it does closing it (`drafts`' closing time phrase)
_OPENS_LAST_CLAUSE = re.compile(
    r"(?P<join>,?\s+and\s+)(?P<free>at\s+(?:any|some)\s+(?:time|point)|any\s*time|whenever\s+you\s+(?:like|want))"
    r"\s*,?\s+(?P<clause>(?P<verb>[a-z]+)\b[^.;!?,]*?)(?=\s*(?:[.;!?]|$))",
    re.I,
)


# "First put the mug in the sink, second the bowl, third the plate" / "... . Second the bowl.": a list of
# steps counted from a "first" that opens a clause; each later ordinal opens a step of its own ("; second,
# the bowl"), the form the leading order words read (left, "second the bowl" was no step, or no order)
_FIRST_STEP = re.compile(r"(?:^|[.;!?,:]\s*|\bthen\s+)first(?:ly)?\b", re.I)
_NTH_STEP = re.compile(
    r"(?P<sep>[,;.!?])?\s*(?P<and>\band\s+)?\b(?P<nth>second|third|fourth|fifth)(?:ly)?\b(?!\s+(?:from|one|time|of)\b)\s*,?\s+(?=\w)",
    re.I,
)


def ordinal_steps(text: str) -> str:
    """Each ordinal after a clause-opening "first" made a step of its own (see `_NTH_STEP`)."""
    first = _FIRST_STEP.search(text)
    if first is None:
        return text

    def step(m: re.Match[str]) -> str:
        if m["sep"] is None and m["and"] is None:
            return m[0]  # "the second shelf": no step
        sep = ";" if m["sep"] in {",", None} else m["sep"]
        return f"{sep} {m['nth']}, "

    return text[: first.end()] + _NTH_STEP.sub(step, text[first.end() :])


def _free_clause_closed(m: re.Match[str]) -> str:
    if m["verb"].lower() not in G.VERBS:
        return m[0]
    return f"{m['join']}{m['clause']} {m['free']}"


def _nth_step(m: re.Match[str]) -> str:
    """ "The last thing is to put X" -> "Finally, put X" ("The last thing I need is X" says no step)."""
    if m["verb"].lower() not in G.VERBS:
        return m[0]
    return "First, " if m["nth"].lower() == "first" else "Finally, "


def after_the_step(text: str) -> str:
    """ "..., do these (first,) in either order, then C" -> "... Once all that is done, C" (C after every task
    before it; "..., and after those two C" is `everyday`'s reference to every task before); "A, after which
    B" -> "A, then B"; "and at the very end C" -> "and finally C"; "and only after that B" -> "and after that
    B"; "Once both are in, and not before, B" -> "Once both are in, B"; "After that, though, B" -> "After
    that, B"; "A, then B, and the C on D last" -> "..., and finally the C on D"; "before doing anything
    else" / "before you start," -> "before anything else";
    "before you start on any of this" -> "before any of this"; "..., D at the very end." / "D to finish." ->
    "..., D last."; "when you have done both" -> "when both are done"; "..., and at any point B." -> "..., and
    B at any point."."""
    text = _ONE_CLAUSE_TO_FINISH.sub(r"\g<clause> last", _CLOSING_LAST.sub(" last", ordinal_steps(text)))
    text = _FREE_BUT.sub(r"\g<free>. ", text)
    text = _IT_IS_THERE.sub(r"\g<lead> that is done", _THOSE_CAN_BE_FREE.sub(", ", text))
    text = _THE_NTH_THING.sub(_nth_step, text)
    text = _YOU_DID_BOTH.sub(lambda m: f"{m['lead']} {m['what']} are done", text)
    text = _FOCUS_OPENER.sub("", _NOT_BEFORE.sub("", text))
    text = _INTERJECTED.sub(r"\g<lead>, ", _FOCUS_CONNECTIVE.sub(r"\g<join>", text))
    text = _BEFORE_YOU_START_ANY.sub(r"\1 ", _BEFORE_DOING_ANYTHING.sub(r"\1 ", text))
    text = _BEFORE_YOU_START.sub(r"\1 anything else", text)
    text = _LAST_ITEM.sub(r"\g<join>finally \g<item>", text)
    text = _AFTER_WHICH.sub(", then ", _FREED_THEN.sub(r"\1. Once all that is done, ", text))
    text = _OPENS_LAST_CLAUSE.sub(_free_clause_closed, text)
    return _AT_THE_END.sub("finally", text)


# "put X in A, and once the mug is done put Y in B" / "..., and before you put Z in C put Y in B": a
# subordinate clause inside a sentence that opens the next main clause; it starts a sentence of its own
# ("Once the mug is done, put Y in B."), which the leading references read
_AND_SUBORDINATE = re.compile(
    r"(?<=\w)(?:\s*,?\s+and\s+(?P<then>then\s*,?\s+)?|\s*,?\s+(?P<then2>then)\s*,\s*)"
    r"(?=(?:once|after|before|when)\s)",
    re.IGNORECASE,
)
# words after which a verb is the subordinate clause's own ("after you put ...", "once it is put ...")
_SUBJECT_OR_AUX = frozenset(
    {"you", "we", "i", "it", "they", "to", "is", "are", "was", "were", "be", "been", "has", "have", "had",
     "and", "or", "then", "that", "this", "not"}
)


# "Once both are done put the pen in the box": a sentence that opens with a clause saying the tasks before
# are done, and no comma before its main verb; "both" / "they" would otherwise be read with the main
# clause ("both ... pens") and the order lost. The comma sets the clause apart, as the writer meant.
_DONE_OPENER = re.compile(
    r"(?P<clause>(?:^|(?<=[.;!?]\s))(?:once|after|when)\s+"
    r"(?:both(?:\s+of\s+(?:them|those|these))?|they|those|these|(?:those|these|the)\s+two|all(?:\s+of)?"
    r"(?:\s+(?:that|this|those|them))?|everything|that|this|it)"
    r"\s+(?:are|is|'re|'s|have\s+been|has\s+been)\s+(?:all\s+)?(?:done|finished|there|in\s+place|sorted))"
    r"\s+(?=(?:put|place|move|set|take|bring|then|go)\b)",
    re.IGNORECASE,
)


def done_opener_closed(text: str) -> str:
    """ "Once both are done put Y" -> "Once both are done, put Y" (see above).

    >>> done_opener_closed("Put A in B. once both are done put the pen in the box")
    'Put A in B. once both are done, put the pen in the box'
    """
    return _DONE_OPENER.sub(lambda m: f"{m['clause']}, ", text)


# "before you put the plunger in the cabinet put the soap on the counter" / "after you wash the mug put it
# in the sink": a sentence that opens with a subordinate clause and has no comma before its main verb (as
# people type); without one the clause's reference swallowed the main clause and no task was read. The
# main verb is the first base-form verb after the clause's own (not after a subject, an auxiliary or an
# article: "before you put the clean mug ..."), as `subordinate_first` finds it.
_SUBORDINATE_OPENER = re.compile(r"(?:^|(?<=[.;!?]\s))(?:before|after|once|when)\s+(?=you\b|we\b|i\b)", re.I)
_ARTICLES = frozenset({"the", "a", "an", "some", "my", "your", "this", "that", "its", "their"})


def opener_closed(text: str) -> str:
    """ "before you put X in Y put Z in W" -> "before you put X in Y, put Z in W" (see above).

    >>> opener_closed("before you put the mug in the sink put the egg in the fridge")
    'before you put the mug in the sink, put the egg in the fridge'
    >>> opener_closed("Before you sing: chill the tomato")
    'Before you sing, chill the tomato'
    """
    out, pos = [], 0
    for m in _SUBORDINATE_OPENER.finditer(text):
        end = re.search(r"[,:.;!?]|$", text[m.end() :])
        if end is not None and end[0] == ":":  # set apart by a colon (h278): the clause ends there, as at
            # a comma; read on, its reference took the main clause's task and ordered it against itself
            out.append(text[pos : m.end() + end.start()].rstrip() + ",")
            pos = m.end() + end.end()
            continue
        if end is None or (end[0] == "," and end.start() > 0):
            continue  # the writer set the clause apart: the rules read it
        words = tokens(text[m.end() : m.end() + end.start()])
        main = next(
            (w for k, w in enumerate(words[2:], 2)
             if w[0] in G.VERBS and G.VERBS[w[0]][1] == w[0]
             and words[k - 1][0] not in _SUBJECT_OR_AUX | _ARTICLES),
            None,
        )  # fmt: skip
        if main is not None:
            out.append(text[pos : m.end() + main[1]].rstrip() + ", ")
            pos = m.end() + main[1]
    return "".join(out) + text[pos:]


# "once that's done": "then" (`sentences`); "..., and once all that is done, Y" / "once everything is done"
# open a sentence as other references do (left in, the clause took Y into its reference and put Y first)
_NO_CLAUSE = frozenset({"that", "this", "it"})
_LEADS = re.compile(r"\s*(?:(?:only|right|just)\s+)?(?:after|before|once|when|until|while)\b", re.IGNORECASE)


def subordinate_first(text: str) -> str:
    """ "X, and once the mug is done put Y" -> "X. Once the mug is done, put Y" (see above), where a main
    clause (an imperative verb, not the subordinate clause's own) follows the subordinate clause before the
    sentence ends."""
    out, pos = [], 0
    for m in _AND_SUBORDINATE.finditer(text):
        end = re.search(r"[.;!?]|$", text[m.end() :])
        words = tokens(text[m.end() : m.end() + (end.start() if end else 0)])
        main = next(
            (w for k, w in enumerate(words[2:], 2)
             if w[0] in G.VERBS and G.VERBS[w[0]][1] == w[0] and words[k - 1][0] not in _SUBJECT_OR_AUX),
            None,
        )
        opener = text[sentence_start(text, m.start()) : m.start()]
        if main is None or words[1][0] in _NO_CLAUSE or (_LEADS.match(opener) and "," not in opener):
            continue  # "after X and before Y, Z": both are about Z ("Before that, Y, and when ..." is not)
        sub_end = m.end() + main[1]
        sub = text[m.end() : sub_end].rstrip(" ,")
        then = "Then, " if m["then"] or m["then2"] else ""  # "X, then, after Y, Z": Z after X too
        out.append(f"{text[pos : m.start()]}. {then}{sub[0].upper() if not then else sub[0]}{sub[1:]}, ")
        pos = sub_end
    return "".join(out) + text[pos:]


# "put the egg in the fridge and the apple in the fridge, the egg before the apple" / "..., but do the egg
# first": an order between tasks named by their objects, closing a sentence, is a sentence of its own (a
# relation sentence, `relation_sentence` / `first_last_sentence`)
_NP_WORDS = r"(?:the|that|this)\s+[a-z]+(?:\s+[a-z]+)?"
_CLOSING_RELATION = re.compile(
    rf",\s+(?:but\s+)?(?P<a>{_NP_WORDS})\s+(?P<rel>before|after)\s+(?P<b>{_NP_WORDS})\s*(?=[.;!?]|$)",
    re.IGNORECASE,
)
_CLOSING_FIRST = re.compile(
    rf",\s+(?:but\s+)?(?P<s>(?:(?:do|handle)\s+)?{_NP_WORDS}\s+(?:first|last))\s*(?=[.;!?]|$)", re.IGNORECASE
)

# "Do the tomato first and the fork last" (which `everyday` has made "... and finally the fork"): two orders,
# each a sentence of its own ("Do the tomato first. Do the fork last.")
_FIRST_AND_LAST = re.compile(
    rf"(?P<lead>(?:^|[.;!?])\s*)(?:do|handle)\s+(?P<a>{_NP_WORDS})\s+first\s*,?\s+and\s+(?:(?:do|handle)\s+)?"
    rf"(?:(?P<b>{_NP_WORDS})\s+last|(?:finally|lastly)\s*,?\s+(?:(?:do|handle)\s+)?(?P<b2>{_NP_WORDS}))\s*(?=[.;!?]|$)",
    re.IGNORECASE,
)

# "look at the box and a pillow in that order, and put a clock on the desk": "in that order" closes the
# clauses before it, and what follows is a sentence of its own (its order free, or said by its own words)
_IN_ORDER_MID = re.compile(
    r"(?<=[a-z]\s)(?P<said>in\s+(?:that|this|the\s+same|the\s+given|the\s+listed)\s+(?:order|sequence))"
    r"\s*[,;]\s*(?:and\s+)?(?!(?:please|pls|thanks|thank|ok|okay|thx|cheers)\b)(?=[a-z])",
    re.IGNORECASE,
)


def closing_orders(text: str) -> str:
    """ "..., the egg before the apple" / "..., but do the egg first" -> a sentence of its own; so is what
    follows a mid-sentence "in that order"."""
    text = _IN_ORDER_MID.sub(lambda m: f"{m['said']}. ", text)
    text = _FIRST_AND_LAST.sub(lambda m: f"{m['lead']}Do {m['a']} first. Do {m['b'] or m['b2']} last", text)
    text = _CLOSING_RELATION.sub(lambda m: f". {m['a']} should be done {m['rel']} {m['b']}", text)
    return _CLOSING_FIRST.sub(lambda m: f". {m['s']}", text)


# A leading connective no table names ("From there,", "Up next,", "At a moment of your choosing,", "With
# all of the above out of the way,"): read by what its words say. Each word is either a signal of one
# order (a sequence, a freedom, a last or first step, a reference to everything before, a step done) or a
# word that says none (a preposition, an article, "point", "way"). A phrase with a word of neither kind,
# or with signals of two orders, is not read (its words stay unread, and check 1 refuses them).
_SIGNALS = {
    "seq": {"next", "there", "here", "thereafter", "afterwards", "afterward", "subsequently", "later", "then",
            "after", "following", "onwards", "onward"},
    "free": {"any", "anytime", "whenever", "whatever", "whichever", "choosing", "choice", "convenience",
             "leisure", "regardless", "irrespective", "meanwhile", "simultaneously", "concurrently",
             "parallel", "free", "freely"},
    "last": {"final", "finally", "last", "lastly", "end", "ending", "conclusion", "close", "closing"},
    "first": {"first", "firstly", "initially", "beginning", "start", "outset"},
    "all": {"all", "everything", "above", "listed", "mentioned", "previous", "preceding", "earlier", "rest",
            "both", "else"},
    "done": {"done", "finished", "complete", "completed", "over", "way", "handled", "sorted", "settled",
             "dealt", "behind", "through", "care"},
}
_NEUTRAL = frozenset(
    "from up with of the that that's this it it's is are has have been be out on at a an to your you "
    "you're you've we in by for point moment time stage step steps thing things task tasks one ones order "
    "sequence just right now so only once when as and taken matter no like want wish suits prefer "
    "choose".split()
)
_LEADING_PHRASE = re.compile(r"^(?P<phrase>[a-z' ]{2,70}?)\s*,\s*(?=[a-z])", re.I)


def leading_connective(body: str) -> tuple[str, str, int] | None:
    """The order a leading phrase says, read by its words: (kind, reference, where the clause starts)."""
    m = _LEADING_PHRASE.match(body)
    if m is None:
        return None
    words = m["phrase"].lower().split()
    said = {kind for w in words for kind, signal in _SIGNALS.items() if w in signal}
    if len(words) > 9 or not said or any(w not in _NEUTRAL and not any(w in s for s in _SIGNALS.values())
                                         for w in words):
        return None
    kind = _connective_kind(said, words)
    return (kind, m["phrase"] if kind == G.AFTER_ALL else "", m.end()) if kind else None


def _connective_kind(said: set[str], words: list[str]) -> str | None:
    """One order from the signals, or None where they say two ("then, at any time")."""
    if said == {"free"}:
        return G.FREE
    if said == {"last"}:
        return G.FINALLY
    if said == {"first"}:
        return G.FIRST
    if "all" in said and said <= {"all", "done", "seq"} and ("done" in said or "after" in words):
        return G.AFTER_ALL  # "with all of the above out of the way", "after everything listed"
    if said <= {"seq", "done"} and ("seq" in said or {"that", "this", "that's", "it"} & set(words)):
        return G.THEN  # "from there", "up next", "with that out of the way"
    return None


def one_last_step(markers: list[tuple[str, str]]) -> list[tuple[str, str]]:
    """ "Then, lastly, Y" / "And then finally Y": one connective, the last step (after every task not left
    free, ANNOTATION_GUIDE.md), not also "after the clause before" (which may be a free one)."""
    kinds = [kind for kind, _ in markers]
    if G.FINALLY in kinds and G.THEN in kinds and kinds.index(G.THEN) < kinds.index(G.FINALLY):
        return [(kind, ref) for kind, ref in markers if kind != G.THEN]
    return markers


# "A and B - the end table ones go first": a closing order set off by a dash is a sentence of its own, which
# names its tasks (`order_remarks.FIRST_LAST_SENTENCE`; h190)
_DASHED_FIRST = re.compile(
    r"\s+[-\u2013\u2014]\s+(?=(?:do\s+)?(?:the|that|this)\s+[a-z][a-z\s]*?\s+(?:first|last)\s*[.!]?\s*$)",
    re.I,
)


def dashed_first(text: str) -> str:
    """ "A and B - the end table ones go first." -> "A and B. the end table ones go first."."""
    return _DASHED_FIRST.sub(". ", text)
