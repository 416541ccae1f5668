#!/usr/bin/env python3
"""The summary table of docs/traceability.md, recounted from its per-clause tables.

Usage: python3 docs/traceability_counts.py [docs/traceability.md]

Prints one summary row per clause section and the total. A row counts as MISSING when its
check column says MISSING as a word (not inside a code such as PROFILE_MISSING), as "not
checkable" when that column starts so, else as checked; it counts as read when its last
column is neither `—` nor starts with `rule`.
"""
import re
import sys

MISSING = re.compile(r"(?<![A-Z_])MISSING(?![A-Z_])")


def main(path):
    text = open(path, encoding="utf-8").read()
    totals = [0] * 5
    for section in re.split(r"^## ", text, flags=re.M):
        heading = re.match(r"(\d+) (.*)\n", section)
        if not heading or section.startswith("11, 12"):
            continue
        counts = [0] * 5
        for line in section.splitlines():
            if not line.startswith("| ") or line.startswith("| clause"):
                continue
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) < 5:
                continue
            check, read_in = cells[-2], cells[-1]
            counts[0] += 1
            if MISSING.search(check):
                counts[3] += 1
            elif check.lower().startswith("not checkable"):
                counts[2] += 1
            else:
                counts[1] += 1
            if not (read_in == "—" or read_in.startswith("rule")):
                counts[4] += 1
        totals = [t + c for t, c in zip(totals, counts)]
        print("| {} | {} | {} |".format(*heading.groups(), " | ".join(map(str, counts))))
    print("| **all** | | " + " | ".join(f"**{t}**" for t in totals) + " |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "docs/traceability.md")
