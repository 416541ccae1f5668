#!/usr/bin/env python3
"""Prints the "Summary per clause" table of docs/traceability.md, counted from its
clause tables: one row per table line; MISSING when the check column names MISSING (not
as part of a code such as PROFILE_MISSING); "not checkable" when the check column starts
so; read when the last column is neither "—" nor "rule …"."""

import re
import sys


def main(path):
    text = open(path, encoding="utf-8").read()
    totals = [0] * 5
    for section in re.split(r"^## ", text, flags=re.M):
        title = section.split("\n", 1)[0]
        clause = re.match(r"(\d+) (.+)$", title)
        if not clause:
            continue
        statements = checked = not_checkable = missing = read = 0
        for line in section.split("\n"):
            if not line.startswith("|") or line.startswith(("|---", "| clause")):
                continue
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) < 5:
                continue
            check, read_in = cells[3], cells[-1]
            statements += 1
            if re.search(r"(?<![A-Z_])MISSING(?![A-Z_])", check):
                missing += 1
            elif check.lower().startswith("not checkable"):
                not_checkable += 1
            else:
                checked += 1
            if not (read_in == "—" or read_in.startswith("rule")):
                read += 1
        counts = [statements, checked, not_checkable, missing, read]
        totals = [t + c for t, c in zip(totals, counts)]
        print(f"| {clause.group(1)} | {clause.group(2)} | " + " | ".join(map(str, counts)) + " |")
    print("| **all** | | " + " | ".join(f"**{t}**" for t in totals) + " |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "docs/traceability.md")
