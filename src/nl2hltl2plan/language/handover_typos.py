"""Typos of the handover reader's words (`handover_phrases.normalise` mends them before any rewrite): a
table from each common misspelling of a word that carries a meaning to the word."""

# Common typos of the words that carry the meaning: a transposed, dropped or doubled letter (not the
# first) of a word of five letters or more; forms that are English words themselves are left alone.
TYPO_WORDS = (
    "block blocks region regions opposite place placed transfer before after yellow pillar pillars object "
    "objects separately another empty touch touched exchange position positions should until during period "
    "please first other across three placement touching picked finish finished target targets nothing "
    "anything meanwhile whenever touches other"
).split()
# four-letter words: only their transposed letters (not the first), which are no English words ("mvoe")
FOUR_LETTER_WORDS = "move side time back swap each then this that blue".split()
REAL_WORDS = frozenset(
    "pace paced touche fist firs pease pleas there tree piked finnish blacks placid daring packed pecked "
    "pocked".split()
)
VOWELS = "aeiou"


# short words, too short for the table's rules, in their commonest misspellings
SHORT_TYPOS = {
    "thsi": "this",
    "sied": "side",
    "sdie": "side",
    "bcak": "back",
    "bakc": "back",
    "tmie": "time",
    "tiem": "time",
    "tihs": "this",
    "teh": "the",
    "hte": "the",
    "adn": "and",
    "nad": "and",
    "taht": "that",
    "bleu": "blue",
    "bule": "blue",
    # clipped in texting
    "nothin": "nothing",
    "anythin": "anything",
    "obj": "object",
    "objs": "objects",
}  # ("u" for "you" is every world's chat shorthand, read before: `spelling.shorthand_read`)


def typo_table() -> dict[str, str]:
    """misspelling -> word, for the words of `TYPO_WORDS` (a misspelling that two words share is left out):
    a transposed, dropped or doubled letter (not the first), and in a word of six letters or more one vowel
    for another; for `FOUR_LETTER_WORDS`, a transposed letter (not the first)."""
    seen: dict[str, set[str]] = {}
    for word in (w for w in TYPO_WORDS if len(w) >= 5):
        forms = {word[:i] + word[i + 1] + word[i] + word[i + 2 :] for i in range(1, len(word) - 1)}
        forms |= {word[:i] + word[i + 1 :] for i in range(1, len(word))}
        forms |= {word[:i] + word[i] + word[i:] for i in range(1, len(word))}
        if len(word) >= 6:  # one vowel written for another: "seperately", "pleese"
            vowels = [i for i in range(1, len(word)) if word[i] in VOWELS]
            forms |= {word[:i] + v + word[i + 1 :] for i in vowels for v in VOWELS}
        for form in forms - set(TYPO_WORDS) - REAL_WORDS:
            seen.setdefault(form, set()).add(word)
    for word in FOUR_LETTER_WORDS:
        for i in range(1, len(word) - 1):
            form = word[:i] + word[i + 1] + word[i] + word[i + 2 :]
            if form != word and form not in REAL_WORDS:
                seen.setdefault(form, set()).add(word)
    return {form: next(iter(words)) for form, words in seen.items() if len(words) == 1} | SHORT_TYPOS
