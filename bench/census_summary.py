#!/usr/bin/python3
"""census_summary.py CENSUS.tsv [LISTING]: the counts of a real-file census as Markdown tables.

CENSUS.tsv has one row per file, tab-separated: path, render exit (0, 3 refused input, 4 missing
asset, 1 internal error, timeout), exit with --allow-missing (when the first was 4, else -), image
class (lit, dark, empty, nonfinite, -), seconds, whether stderr named file:line:column (yes/no),
the first error line. LISTING (one path a line) is the set the census was asked to run: files of it
without a row are counted as not run. Paths are shown relative to the directory holding the
repositories' trees (the part up to "src/" is dropped); the repository is the first component.
"""
import collections
import re
import sys


def shown(path):
    return path.split("/src/", 1)[-1]


def outcome(rc, allow, image):
    if rc == "0":
        return "renders (" + image + ")"
    if rc == "4" and allow == "0":
        return "renders with --allow-missing (" + image + ")"
    if rc == "4":
        return "refused: missing asset (exit 4, then " + allow + ")"
    if rc == "3":
        return "refused: input (exit 3)"
    if rc == "timeout":
        return "timeout"
    return "exit " + rc


def cause(line):
    """The first error line with what varies per file (paths, names, numbers) blanked."""
    text = re.sub(r"^fluence: (error|warning): ", "", line)
    text = re.sub(r"\S*/src/\S+", "FILE", text)
    text = re.sub(r"'[^']*'", "'…'", text)
    text = re.sub(r"<[^>]*>|@[^@]*@", "…", text)
    text = re.sub(r"(^|\s)/\S*", r"\1PRIM", text)
    text = re.sub(r"\d+(\.\d+)?", "N", text)
    return text[:150].replace("|", "/")


def examples(rows):
    return ", ".join("`" + shown(r[0]) + "`" for r in rows[:2])


def main():
    rows = [line.rstrip("\n").split("\t") for line in open(sys.argv[1]) if line.strip()]
    listed = [line.strip() for line in open(sys.argv[2]) if line.strip()] if len(sys.argv) > 2 else []
    done = {r[0] for r in rows}
    print(f"{len(rows)} files run" + (f" of {len(listed)} listed; {sum(p not in done for p in listed)} not run." if listed else "."))

    repositories = collections.Counter(shown(r[0]).split("/", 1)[0] for r in rows)
    print("\n| repository | files run |\n|---|---|")
    for name, count in repositories.most_common():
        print(f"| {name} | {count} |")

    by_outcome = collections.defaultdict(list)
    for r in rows:
        by_outcome[outcome(r[1], r[2], r[3])].append(r)
    print("\n| outcome | files | examples |\n|---|---|---|")
    for name, group in sorted(by_outcome.items(), key=lambda item: -len(item[1])):
        print(f"| {name} | {len(group)} | {examples(group)} |")

    refused = [r for r in rows if r[1] != "0" and not (r[1] == "4" and r[2] == "0")]
    by_cause = collections.defaultdict(list)
    for r in refused:
        by_cause[(r[1], cause(r[6]))].append(r)
    print("\n| exit | cause (first error line) | files | file:line:col | examples |\n|---|---|---|---|---|")
    for (rc, text), group in sorted(by_cause.items(), key=lambda item: -len(item[1])):
        located = sum(r[5] == "yes" for r in group)
        print(f"| {rc} | {text} | {len(group)} | {located} | {examples(group)} |")


if __name__ == "__main__":
    main()
