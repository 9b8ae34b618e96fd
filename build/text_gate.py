#!/usr/bin/env python3
"""The text gate of `make test`: the comments of `src/` and the design documents (ARCHITECTURE.md,
documentation/design/) say what is true and why, in the present tense. History (what was tried, what ran before,
what a stop changed) belongs in CHANGELOG.md and the commit messages; design and seed numbers of the random families belong in the tests that pin them
(tests/crank_train/random_designs.rs), with one line of what each pins.

    python3 build/text_gate.py        prints every offending line as path:line: text, exits 1 if there is one
"""

import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

#: Words that tell history rather than what is true now. Each is matched case-insensitively as whole words.
HISTORY = [
    r"tried and",
    r"was tried",
    r"were tried",
    r"we tried",
    r"not kept",
    r"last stop",
    r"this stop",
    r"before:",
    r"\(before",
    r"as before",
    r"than before",
    r"before these changes",
    r"now runs",
    r"now run",
    r"was seen",
    r"were seen",
    r"used to be",
    r"first version",
    r"first try",
    r"previously",
    r"formerly",
    r"earlier versions?",
    r"the old",
]
#: A design or seed number of the random families: "design 1189", "seeds 0–59", "random design 14".
NUMBERS = r"(design|seed)s? [0-9]+"

PATTERN = re.compile(r"(?<![\w-])(" + "|".join(HISTORY + [NUMBERS]) + r")(?![\w])", re.IGNORECASE)
COMMENT = re.compile(r"(^|\s)//[/!]?(.*)$")


def comments(path):
    """(line number, comment text) of each line of a Rust file that carries a `//` comment."""
    for number, line in enumerate(path.read_text().splitlines(), 1):
        found = COMMENT.search(line)
        if found:
            yield number, found.group(2)


def offences():
    for path in sorted((ROOT / "src").rglob("*.rs")):
        for number, text in comments(path):
            if PATTERN.search(text):
                yield path, number, text.strip()
    for path in [ROOT / "ARCHITECTURE.md", *sorted((ROOT / "documentation" / "design").glob("*.md"))]:
        for number, text in enumerate(path.read_text().splitlines(), 1):
            if PATTERN.search(text):
                yield path, number, text.strip()


def main():
    found = list(offences())
    for path, number, text in found:
        print(f"{path.relative_to(ROOT)}:{number}: {text}")
    scanned = "src/ comments, ARCHITECTURE.md and documentation/design/"
    if found:
        print(f"text gate: {len(found)} lines of history or design/seed numbers in {scanned}", file=sys.stderr)
        return 1
    print(f"text gate: no history words or design/seed numbers in {scanned}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
