"""Everyday ways of asking for a treatment or an order (issue 28, users_h173dev.txt), rewritten onto the
imperative the grammar reads. Each rule rewrites only where the thing is a name the scene's lexicon knows
(`find_mentions`) and the verb is one of the grammar's treatment verbs (`word_tables`: clean, heat, cool,
slice), so a sentence about anything else, or a negated one, is left as it is:

- a treatment said as a need: "the plate needs a (good) wash", "needs washing (up)", "needs to be (or
  get) chilled" is "wash / chill the plate"; "the plate doesn't need a wash" has no subject right before
  the need, and is left (the grammar refuses it as a negation); a duty in the passive ("has to be washed",
  "should be chilled", a note's "to be rinsed") is the same, and "... and put / left on the counter" after it
  puts the same thing ("wash the plate and put it on the counter"), as does "needs washing and putting";
- "would you mind V-ing" (`courtesy.txt`, `minded`) is the request, each "and V-ing" after it its base form;
- a causative: "have the bread cut up", "get the potato sliced" is "cut the bread", "slice the potato",
  and "have the robot slice the bread", "get someone to wash the plate", "tell / ask the robot to put the
  mug ..." is "slice the bread", "wash the plate", "put the mug ..." (the grammar's verbs only);
- an end state of a pronoun after a clause: "wash the plate, it should end up in the cabinet" is "..., put
  it in the cabinet" ("it should end up somewhere" names no place, and is left);
- a treatment said as a purpose right after the thing, or after the treatment's own appliance: "slice an
  apple to be cooked in the microwave ..." is "slice an apple and cook it in the microwave ...", "put a
  mug in the sink to be washed" is "put a mug in the sink and wash it" (after another place, "put a mug
  in the cabinet to be heated", which comes first is not said, and it is left: refused);
- "id like" as texted is "I'd like" (which the grammar reads as a request);
- a terse order: a bare "mug first" about a thing moved in a request said before ("the mug", "mug in
  the sink"; not a place, "on the yellow plate", nor a label, "Target: yellow plate.", which the grammar
  and the tabletop reader read themselves) is "the mug first", a courtesy word after it ("the pan first
  pls") is dropped, and "the mug first, then the bowl" (or "first the mug, then
  the bowl", after a comma or as the next sentence) closing a request of two placements (every other
  name in it follows a place preposition: "put the mug and the bowl in the sink") is ", the mug before
  the bowl". With more placements "then the bowl" also orders the bowl before the rest, which no rewrite
  here says, so it is left to the grammar (which refuses it).
"""

from __future__ import annotations

import re
from functools import lru_cache

from nl2hltl2plan.language.content_words import phrase_list_pattern
from nl2hltl2plan.language.courtesy import courtesy_pattern
from nl2hltl2plan.language.grammar.frames import APPLIANCE_OF
from nl2hltl2plan.language.grammar.treated_lists import PARTICLE, treated_lists
from nl2hltl2plan.language.grammar.word_tables import VERB_PAST, VERBS
from nl2hltl2plan.language.grounding import find_mentions

_TREATMENTS = frozenset({"clean", "heat", "cool", "slice"})


def _forms(table: dict[str, tuple[str, str]]) -> str:
    words = sorted((w for w, (cls, _) in table.items() if cls in _TREATMENTS), key=len, reverse=True)
    return "|".join(re.escape(w) for w in words)


def _base(word: str) -> str | None:
    """The treatment verb a noun, gerund or participle stands for ("washing", "chilled": wash, chill)."""
    found = VERBS.get(word.lower()) or VERB_PAST.get(word.lower())
    return found[1] if found and found[0] in _TREATMENTS else None


# (an order word before a passive's thing, "first the tomato is to be chilled ...", "after that the mug needs
# heating ...", h260: the word stays, before the imperative)
_LEAD = (
    r"(?P<lead>^|(?<=[,.;:!?])\s*|\b(?:and|then|please|pls|so|first|next|last|finally|lastly|after\s+that)\s+)"
)
# (a note's "one bar of soap to be rinsed ...", h239)
_THING = r"(?P<thing>(?:the|that|this|my|your|a|an|one|another)\s+[a-z]+(?:\s+[a-z]+){0,2}?)"


@lru_cache(maxsize=1)
def _patterns() -> tuple[re.Pattern[str], ...]:
    verbs, past = _forms(VERBS), _forms(VERB_PAST)
    need = re.compile(
        rf"{_LEAD}{_THING}\s+(?:(?:needs?|wants?|could\s+(?:use|do\s+with))\s+"
        rf"(?:(?:a|an)\s+(?:(?:good|quick|proper|little|bit\s+of\s+a)\s+)?(?P<noun>{verbs})"
        rf"|to\s+(?:be|get)\s+(?P<part>{past})|(?P<ger>{verbs}))|{_DUTY}\s+(?P<duty>{past})){PARTICLE}"
        rf"(?:\s+and\s+(?:then\s+)?(?P<then>{_PLACED}|{_GOES_VERB})(?:\s+(?P<adv>away|back|down))?"
        r"(?=\s+(?:in|into|on|onto|inside|upon|atop)\s)"
        rf"|{_GOES})?(?![\w'])",
        re.I,
    )
    causative = re.compile(
        rf"{_LEAD}(?:have|get)\s+{_THING}\s+(?P<part>{past}){PARTICLE}(?![\w'])", re.I
    )
    purpose = re.compile(
        rf"(?P<head>\b[a-z]+\s+{_THING}(?:\s+(?:in|into|inside)\s+(?:the|a)\s+(?P<place>[a-z]+))?)"
        rf"\s+to\s+(?:be|get)\s+(?P<part>{past}){PARTICLE}(?![\w'])",
        re.I,
    )
    # two things with one need, the place said of both: "the soap and a cloth both need washing, and both
    # go back on the rack", "the cup and the plate need to be washed and put in the fridge" (h239)
    thing = r"(?:the|that|this|my|your|a|an|one)\s+[a-z]+(?:\s+[a-z]+){0,3}?"
    pair = re.compile(
        rf"{_LEAD}(?P<a>{thing})\s+and\s+(?P<b>{thing})\s+(?:both\s+)?(?:need|want)\s+"
        rf"(?:to\s+(?:be|get)\s+(?P<part>{past})|(?P<ger>{verbs})){PARTICLE}(?![\w'])"
        rf"(?P<then>(?:\s*,?\s+and\s+(?:(?:both|they)\s+)?(?:go|belong)\s+|\s+and\s+{_PLACED}\s+(?:(?:it|them)\s+)?)"
        rf"(?:(?:back|away|down)\s+)?(?=(?:in|into|on|onto|inside)\s))?",
        re.I,
    )
    inverted = re.compile(rf"{_LEAD}{_INVERTED}\s+(?P<be>be|get)\s+(?=(?:{past})(?![\w']))", re.I)
    return need, causative, purpose, pair, inverted


# the place said after a need as where the thing goes next (h231's "the lettuce needs chilling and then on
# the table", "The loaf of bread wants chilling too, then back on the white table"; "the cup wants chilling
# and then goes on the table"): "then" or "goes" must be said, so "needs washing and in the sink ..." is left
_GOES = (
    r"(?P<goes_to>(?P<too>\s+(?:too|as\s+well|also))?\s*,?\s+(?:(?:and\s+)?then(?:\s+(?:it|they))?(?:\s+(?:goes|go))?"
    r"|and(?:\s+(?:it|they))?\s+(?:goes|go))(?:\s+(?P<back>back|away))?)(?=\s+(?:in|into|on|onto|inside)\s)"
)
# a duty said in the passive ("has to be washed", "should be chilled", a note's "to be rinsed", h223), and the
# placing said after it in the same voice ("... and put / left / placed on the counter"), of the same thing
# (and in the present, "the soap gets rinsed", or as a question's inverted order, `_INVERTED`, h260)
_DUTY = (
    r"(?:(?:has|have|is|are|ought)\s+to\s+(?:be|get)|(?:should|must|will|shall|can|could)\s+(?:be|get)|to\s+be"
    r"|gets)"
)
_PLACED = (  # (a decree's "shall be washed and laid on the toilet", paper_h301)
    r"(?:put|putting|placed|placing|set|setting|left|leaving|dropped|dropping|stored|storing|kept|keeping|laid|"
    r"laying)"
)
# the placing said as where the thing goes ("... and (then) goes / ends up / belongs on the counter", h260)
_GOES_VERB = r"(?:go|goes|belongs?|ends?\s+up|be\s+(?:put|placed|left|set|stored|kept))"
# a question in the passive ("can the spoon be washed and put ...?", "could the pot get chilled ...?"): the
# statement's order ("the spoon can be washed ..."), which `need` reads; only before a treatment's participle
_INVERTED = (
    r"(?P<aux>can|could|should|will|would)\s+(?P<it>(?:the|that|this|my|your|a|an|one)\s+[a-z]+(?:\s+[a-z]+)?)"
)
# (and a request passed on: "tell / ask the robot to put ...", h299; a robot singled out, "the second
# robot", is no match: `vague_words` refuses it)
_WHO = r"(?:(?:the|a|one|my|your|our)\s+robots?|one\s+of\s+(?:the\s+)?robots|someone|somebody)"
# a contract's "The Contractor shall wash X and shall thereafter place it on Y" (paper_h301): the imperative,
# "wash X and then place it on Y"; the modal said again after "and" only where a doer was so named
_DECREED = re.compile(rf"\b{courtesy_pattern('decreed')}\s+(?P<verb>[a-z]+)\b", re.I)
_DECREED_AGAIN = re.compile(
    r"(?P<join>\band|,)\s+(?:shall|must|will)\s+(?:(?P<then>thereafter|then|afterwards|subsequently|next)\s+)?"
    r"(?P<verb>[a-z]+)\b",
    re.I,
)
# (and its "place the said spoon upon ...": the thing just named, "it", where its noun was said before in the
# sentence; left, "wash the spoon ... and place the said spoon" was read as two tasks of one spoon)
_THE_SAID = re.compile(
    r"\b(?P<verb>[a-z]+)\s+the\s+(?:said|aforesaid|aforementioned)\s+(?:[a-z]+\s+)??(?P<noun>[a-z]+)\b",
    re.I,
)
_PLACING = frozenset("place put set move bring return store take carry transfer lay".split())
_AGENT = re.compile(
    rf"{_LEAD}(?:(?:have|get|let)\s+{_WHO}\s+(?:to\s+)?|(?:tell|ask)\s+{_WHO}\s+to\s+)(?P<verb>[a-z]+)\b",
    re.I,
)


# "would you mind washing the mug and putting it away?" (`courtesy.txt`, `minded`): the request, each verb of
# its sentence said in the -ing form after the frame or after "and" / "then" / a comma in its base form (h223)
_MINDED = re.compile(rf"\b{courtesy_pattern('minded')}\s+(?P<ger>[a-z]+ing)\b", re.I)
_NEXT_GERUND = re.compile(r"(?P<lead>(?:\band|\bthen|,)\s+(?:then\s+)?)(?P<ger>[a-z]+ing)\b", re.I)


def _minded(text: str) -> str:
    """ "Would you mind chilling a mug and leaving it in the sink?" -> "chill a mug and leave it in the
    sink?"; a frame before a word that is no verb of the grammar's stays, to be read or refused."""
    out, pos = [], 0
    for m in _MINDED.finditer(text):
        found = VERBS.get(m["ger"].lower())
        if found is None or m.start() < pos:
            continue
        stop = re.compile(r"[.?!;]").search(text, m.end())
        end = stop.start() if stop else len(text)
        rest = _NEXT_GERUND.sub(_base_form, text[m.end() : end])
        out += [text[pos : m.start()], found[1], rest]
        pos = end
    return "".join(out) + text[pos:]


def _base_form(g: re.Match[str]) -> str:
    found = VERBS.get(g["ger"].lower())
    return g["lead"] + found[1] if found else g[0]


# "wash the plate, it should end up in the cabinet": a pronoun's end state after a clause is a placement of it
_PRONOUN_GOAL = re.compile(
    r"(?P<lead>[,;.]\s*(?:and\s+)?(?:then\s+)?|\s(?:and|then)\s+)(?P<it>it|they)\s+"
    r"(?:(?:should|must|will|has\s+to|have\s+to|needs?\s+to|is\s+to|are\s+to)\s+(?:end\s+up|go|be\s+put)|"
    r"ends?\s+up|goes|go)\s+(?P<prep>in|into|on|onto|inside)\s+(?=(?:the|a|an)\s)",
    re.I,
)
# "make it cold", "make cold the bowl", "tomato make it cold" (a non-native speaker's causative, h195dev):
# the treatment's verb; a name said bare before it is the thing ("tomato make it cold": chill the tomato)
_MAKE_STATE = re.compile(
    r"(?P<lead>(?:^|(?<=[,.;:!?])\s*|\b(?:and|then|you|please)\s+))(?:(?P<topic>[a-z]+(?:\s+[a-z]+)?)\s+)?"
    r"make\s+(?:(?P<it>it|them|(?:(?:the|a|an|one)\s+)?[a-z]+(?:\s+[a-z]+)?)\s+(?P<adj>cold|cool|hot|warm|clean)"
    r"|(?P<adj2>cold|cool|hot|warm|clean))(?![\w'])",
    re.I,
)
_MADE = {"cold": "chill", "cool": "chill", "hot": "heat", "warm": "heat", "clean": "wash"}
# a non-native speaker's placement (users_h195dev): "after put ..." is "then put ...", "give it on the
# table" is "put it on the table", and "put inside the drawer" after a clause puts the thing of that clause
_STEP = r"(?:put|place|set|leave|throw|toss|drop|wash|rinse|clean|heat|warm|cool|chill|look|hold|slice|cut)"
_AFTER_STEP = re.compile(rf"(?:(?<=^)|(?<=[,.;!?]\s)|(?<=\band\s))after\s*,?\s+(?={_STEP}\b)", re.I)
# "you put two soap bottle inside drawer", "then you wash the cloth": a request said with its subject (never
# after "once", "after", "when", "before" or "if": "once you put X" is a clause of its own)
_YOU_STEP = re.compile(rf"(?P<lead>(?:^|[.;!?]\s*|\bthen\s+|\bplease\s+))you\s+(?={_STEP}\b)", re.I)
_GIVE_ON = re.compile(r"\bgive\s+(?P<it>it|them)\s+(?=(?:on|in|into|onto|inside)\s)", re.I)
_PUT_BARE = re.compile(
    r"(?<=\S)(?<!\bbe)(?P<lead>\s+(?:and\s+|then\s+)*)(?P<verb>put|place)\s+(?=(?:inside|into|in|onto|on|to)\s)",
    re.I,
)
_TEXTED_ID = re.compile(r"\bid\s+(?=(?:like|love|prefer|want)\b)", re.I)  # "id like" as texted: "I'd like"
_COURTESY_AFTER_FIRST = re.compile(r"\bfirst\s*,?\s*(?:please|pls|plz)\s*(?=[.!]?\s*$)", re.I)
_BARE_FIRST = re.compile(r"(?P<lead>(?:^|[,.;:]|\bthen)\s*)(?P<name>[a-z]+(?:\s+[a-z]+)?)\s+first\b", re.I)
_NAME = r"(?:the\s+)?[a-z]+(?:\s+[a-z]+)?"
_FIRST_THEN = re.compile(
    rf"[,.;]\s*(?:(?P<x>{_NAME})\s+first|first\s+(?P<x2>{_NAME}))\s*,?\s*(?:and\s+)?then\s+(?P<y>{_NAME})"
    r"\s*(?P<end>[.!]?\s*)$",
    re.I,
)
# (a slice named by its whole: "a slice of lettuce", "a tomato slice" is one thing, h223)
_DETERMINER = re.compile(
    r"\s*(?:(?:the|that|this|my|your|a|an|one|another)\s+)?(?:(?:slice|piece)s?\s+of\s+(?:the\s+)?)?", re.I
)
_SLICE_AFTER = re.compile(r"\s*(?:slices?)?\s*", re.I)
# a thing said in a request ("the mug", "watch on the table"), not a bare label ("Target: yellow plate.")
_DET_BEFORE = re.compile(r"\b(?:the|a|an|my|your|this|that)\s+$", re.I)
_PREP_AFTER = re.compile(r"\s+(?:in|into|on|onto|inside)\s", re.I)
_PLACE_BEFORE = re.compile(r"\b(?:in|into|on|onto|inside|on\s+top\s+of)\s+(?:the|a|an)\s+$", re.I)


@lru_cache(maxsize=1)
def _give() -> re.Pattern[str]:
    """A treatment said as a noun given to the thing (users_h271's C3): "give the sponge a rinse", "give a
    slice of bread a good chill", "give it a quick warm up", "give one slice a heat"."""
    thing = r"(?:it|them|(?:the|that|this|my|your|a|an|one|another)\s+[a-z]+(?:\s+[a-z]+){0,3}?)"
    return re.compile(
        rf"\bgive\s+(?P<thing>{thing})\s+an?\s+(?:(?:good|quick|proper|little|nice|short|thorough)\s+)?"
        rf"(?P<noun>{_forms(VERBS)}){PARTICLE}(?![\w'-])",
        re.I,
    )


def _given(m: re.Match[str]) -> str:
    """ "give X a rinse" -> "rinse X" where X is "it", a slice said before ("one slice") or one name the
    lexicon knows; anything else ("give the kid a wash") as it was."""
    verb, thing = _base(m["noun"]), m["thing"]
    slice_ = re.fullmatch(r"(?:one|a|an|another)\s+(?:slice|piece)", thing, re.I)
    if verb is None or not (thing.lower() in ("it", "them") or slice_ or _names_thing(thing)):
        return m[0]
    return f"{verb} {thing}"


def treatments_said(text: str) -> str:
    """The text with the needs, causatives and terse orders above rewritten (see the module docstring)."""
    need, causative, purpose, pair, inverted = _patterns()
    text = _TEXTED_ID.sub("I'd ", _minded(text))
    text = treated_lists(text)  # lists, outcomes, things said first (treated_lists)
    text = _give().sub(_given, _MAKE_STATE.sub(_made, text))
    text = _AFTER_STEP.sub("then ", _GIVE_ON.sub(r"put \g<it> ", _YOU_STEP.sub(r"\g<lead>", text)))
    text = _PUT_BARE.sub(r"\g<lead>\g<verb> it ", text)
    text = _PRONOUN_GOAL.sub(_put_pronoun, text)
    text = _AGENT.sub(lambda m: f"{m['lead']}{m['verb']}" if m["verb"].lower() in VERBS else m[0], text)
    text = _decreed(text)
    text = pair.sub(_both_treated, text)
    text = inverted.sub(_uninverted, text)
    text = need.sub(_imperative, text)
    text = causative.sub(_imperative, text)
    text = purpose.sub(_treated_next, text)
    text = _COURTESY_AFTER_FIRST.sub("first", text)
    text = _BARE_FIRST.sub(lambda m: _named_first(text, m), text)
    return _FIRST_THEN.sub(lambda m: _first_then(text, m), text)


def _decreed(text: str) -> str:
    """ "The Contractor shall wash X and shall thereafter place it" -> "wash X and then place it"."""
    said = _DECREED.sub(lambda m: m["verb"] if m["verb"].lower() in VERBS else m[0], text)
    if said == text:
        return text

    def again(m: re.Match[str]) -> str:
        then = "then " if m["then"] else ""
        return f"{m['join']} {then}{m['verb']}" if m["verb"].lower() in VERBS else m[0]

    return _THE_SAID.sub(_said_thing, _DECREED_AGAIN.sub(again, said))


def _said_thing(m: re.Match[str]) -> str:
    """ "place the said spoon upon ..." -> "place it upon ..." where a placing verb takes it and "spoon" was
    said earlier in the sentence."""
    before = re.split(r"[.;!?]", m.string[: m.start()])[-1]
    named = re.search(rf"\b{re.escape(m['noun'])}\b", before, re.I)
    return f"{m['verb']} it" if named and m["verb"].lower() in _PLACING else m[0]


def _made(m: re.Match[str]) -> str:
    """ "make it cold" -> "chill it", "make mug cold" -> "chill the mug", "make cold the bowl" -> "chill the
    bowl", "tomato make it cold" -> "chill the tomato" (a name alone before it); anything else as it was."""
    verb, topic, it = _MADE[(m["adj"] or m["adj2"]).lower()], m["topic"], m["it"]
    if topic and it and it.lower() == "it" and _names_thing(f"the {topic}"):
        return f"{m['lead']}{verb} the {topic}"
    lead = f"{m['lead']}{topic} " if topic else m["lead"]
    if it and it.lower() not in ("it", "them"):
        if not find_mentions(it):
            return m[0]
        it = it if re.match(r"(?:the|a|an|one)\s", it, re.I) else f"the {it}"
    return f"{lead}{verb}" + (f" {it}" if it else "")


def _put_pronoun(m: re.Match[str]) -> str:
    """ ", it should end up in the X" -> ", put it in the X" where a name is said before the pronoun."""
    if not find_mentions(m.string[: m.start()]):
        return m[0]
    return f"{m['lead']}put {'them' if m['it'].lower() == 'they' else 'it'} {m['prep']} "


def _imperative(m: re.Match[str]) -> str:
    forms = m.groupdict()
    verb = _base(forms.get("noun") or forms.get("part") or forms.get("ger") or forms.get("duty") or "")
    if verb is None or not _names_thing(m["thing"]) or _state_said(m):
        return m[0]
    thing = re.sub(r"^(?:that|this|my|your)\b", "the", m["thing"], flags=re.I)
    adv = forms.get("adv") or forms.get("back")
    placed = f" and put it{' ' + adv if adv else ''}" if forms.get("then") else ""
    if forms.get("goes_to"):  # "needs chilling (too), then back on the": the place after it
        placed = f"{forms.get('too') or ''} and put it{' ' + adv if adv else ''}"
    return f"{m['lead']}{verb} {thing}{placed}"


def _state_said(m: re.Match[str]) -> bool:
    """Whether the treatment's word is followed by what says its state is already so or someone else's job
    ("should be washed already", "gets washed by someone else": `states_said.txt`, h264): no duty."""
    said = max(m.end(g) for g in ("noun", "part", "ger", "duty") if m.groupdict().get(g))
    return _STATE_SAID.match(m.string, said) is not None


_STATE_SAID = re.compile(
    rf"{PARTICLE}\s*,?\s+{phrase_list_pattern('states_said.txt', 'done')}(?![\w'])", re.I
)


def _uninverted(m: re.Match[str]) -> str:
    """ "can the spoon be washed" -> "the spoon can be washed" where the thing is a name the lexicon knows."""
    return f"{m['lead']}{m['it']} {m['aux'].lower()} {m['be']} " if _names_thing(m["it"]) else m[0]


def _both_treated(m: re.Match[str]) -> str:
    """ "the soap and a cloth both need washing, and both go back on the" -> "wash the soap and a cloth and
    put them on the"; the text as it was unless each ends on the one name the lexicon knows in it."""
    verb = _base(m["part"] or m["ger"])
    if verb is None or not (_ends_on_name(m["a"]) and _ends_on_name(m["b"])):
        return m[0]
    a, b = (re.sub(r"^(?:that|this|my|your)\b", "the", t, flags=re.I) for t in (m["a"], m["b"]))
    return f"{m['lead']}{verb} {a} and {b}{' and put them ' if m['then'] else ''}"


def _treated_next(m: re.Match[str]) -> str:
    """ "slice an apple to be cooked" -> "slice an apple and cook it"; "put a mug in the sink to be washed" ->
    "put a mug in the sink and wash it" (a place other than the treatment's appliance: left)."""
    verb = _base(m["part"])
    if verb is None or verb == "slice" or m["head"].split()[0].lower() not in VERBS:
        return m[0]
    if not _names_thing(m["thing"]):
        return m[0]
    if m["place"] is not None:
        said = find_mentions(m["place"])
        if not said or APPLIANCE_OF.get(VERBS[verb][0]) not in said[0].entry.types:  # washed in the sink
            return m[0]
    return f"{m['head']} and {verb} it"


def _ends_on_name(phrase: str) -> bool:
    """Does the phrase end on the one name the lexicon knows in it ("the pink bar of soap")?"""
    found = find_mentions(phrase)
    return len(found) == 1 and _SLICE_AFTER.fullmatch(phrase[found[0].char_end :]) is not None


def _names_thing(phrase: str) -> bool:
    """Is the phrase a determiner and one name the lexicon knows, and nothing else?"""
    found = find_mentions(phrase)
    if len(found) != 1 or not _SLICE_AFTER.fullmatch(phrase[found[0].char_end :]):
        return False
    return _DETERMINER.fullmatch(phrase[: found[0].char_start]) is not None


def _named_first(text: str, m: re.Match[str]) -> str:
    """ "mug first" -> "the mug first", where the mug is named earlier in the text."""
    name = m["name"]
    if re.match(r"(?:the|a|an|and|then|that|this|it|them)\b", name, re.I) or not _names_thing(name):
        return m[0]
    said = text[: m.start()]
    earlier = {
        x.surface.lower()
        for x in find_mentions(said)
        if not _PLACE_BEFORE.search(said[: x.char_start])
        and (_DET_BEFORE.search(said[: x.char_start]) or _PREP_AFTER.match(said[x.char_end :]))
    }
    return f"{m['lead']}the {name} first" if name.lower() in earlier else m[0]


def _first_then(text: str, m: re.Match[str]) -> str:
    """ ", the mug first, then the bowl" closing a request of two placements: ", the mug before the bowl"."""
    x, y = (re.sub(r"^(?!the\s)", "the ", w, flags=re.I) for w in (m["x"] or m["x2"], m["y"]))
    said = text[: m.start()]
    if not (_names_thing(x) and _names_thing(y)):
        return m[0]
    named = find_mentions(said)
    surfaces = [n.surface.lower() for n in named]
    x_name, y_name = find_mentions(x)[0].surface.lower(), find_mentions(y)[0].surface.lower()
    if x_name == y_name or surfaces.count(x_name) != 1 or surfaces.count(y_name) != 1:
        return m[0]
    others = [n for n in named if n.surface.lower() not in (x_name, y_name)]
    if not others or not all(_PLACE_BEFORE.search(said[: n.char_start]) for n in others):
        return m[0]
    return f", {x} before {y}{m['end']}"
