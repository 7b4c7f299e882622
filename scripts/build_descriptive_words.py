"""Build `language/descriptive_words.txt`: the words people put before the name of a household thing (issue
23: colours, sizes, materials, shapes, states, "the small red apple", "the wooden chair", "the dirty mug").

Read from ALFRED's train annotations (task descriptions and step descriptions) of the trials that
`benchmark/training_exclusions.txt` does not exclude; never test50, the excluded trials or the valid
splits. A word is kept when it stands between a determiner (or a placing verb) and a lexicon name
(`unknown_words.modifiers_before`: at most two words, no relation or clause break among them) in at
least `MIN_TRIALS` distinct trials, English knows it, and no word table of the package knows it already
(`spelling.known_word`, `content_words.categories`).

Usage: python scripts/build_descriptive_words.py [--min-trials N] [--print]
"""

from __future__ import annotations

import argparse
import collections
from pathlib import Path

from nl2hltl2plan.config import data_path
from nl2hltl2plan.io import iter_gzip_jsonl
from nl2hltl2plan.language.content_words import categories
from nl2hltl2plan.language.grounding import find_mentions, tokens
from nl2hltl2plan.language.learned.data import excluded_trials
from nl2hltl2plan.language.spelling import english_word, known_word
from nl2hltl2plan.language.unknown_words import modifiers_before

MIN_TRIALS = 2
OUT = Path(__file__).resolve().parent.parent / "src/nl2hltl2plan/language/descriptive_words.txt"
HEADER = """\
# Words people put before the name of a household thing that name nothing the reading uses: colours, sizes,
# materials, shapes, states ("the small red apple", "the wooden chair", "the dirty mug"). Check 1
# (`unknown_words.unknown_modifiers`) passes them over; any other word English knows before a name is
# unread. Built by scripts/build_descriptive_words.py from ALFRED's train annotations of the trials
# training_exclusions.txt does not exclude (never test50, the excluded trials or the valid splits): a
# word before a name in at least {n} trials, that English and no word table of the package knows.
"""


def modifiers_before_names(text: str) -> list[str]:
    """The words between an opening word and a lexicon name in `text` (`unknown_words.modifiers_before`)."""
    toks = tokens(text)
    return [w for m in find_mentions(text) for w in modifiers_before(text, toks, m.start)]


def count_trials(min_trials: int) -> dict[str, int]:
    banned = excluded_trials()
    seen: dict[str, set[str]] = collections.defaultdict(set)
    for _n, row in iter_gzip_jsonl(data_path("alfred", "trials.jsonl.gz"), "ALFRED trials file"):
        if row["split"] != "train" or row["trial"] in banned:
            continue
        for ann in row["annotations"]:
            for text in [ann.get("task_desc", ""), *ann.get("high_descs", [])]:
                for word in modifiers_before_names(text):
                    seen[word].add(row["trial"])
    return {
        w: len(t)
        for w, t in seen.items()
        if len(t) >= min_trials and len(w) > 2 and w.isalpha() and english_word(w)
        and not known_word(w) and not categories(w)
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--min-trials", type=int, default=MIN_TRIALS)
    ap.add_argument("--print", action="store_true", help="print the words with their trial counts")
    args = ap.parse_args()
    counts = count_trials(args.min_trials)
    if args.print:
        for w, n in sorted(counts.items(), key=lambda x: -x[1]):
            print(n, w)
        return
    words = sorted(counts)
    lines = [" ".join(words[i : i + 16]) for i in range(0, len(words), 16)]
    OUT.write_text(HEADER.format(n=args.min_trials) + "".join(f"words: {line}\n" for line in lines))
    print(f"{len(words)} words -> {OUT}")


if __name__ == "__main__":
    main()
