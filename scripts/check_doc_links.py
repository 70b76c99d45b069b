#!/usr/bin/python3
"""Checks that every relative link of README.md and docs/**/*.md resolves to a file inside the
repository (ctest docs.links). Prints each broken link; exit code 1 if there is one."""
import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LINK = re.compile(r"\]\(([^)\s]+)\)")


def broken_links(path):
    """The links of a Markdown file that leave the repository or name no file there."""
    with open(path) as f:
        text = re.sub(r"```.*?```", "", f.read(), flags=re.S)  # not links in code blocks
    bad = []
    for target in LINK.findall(text):
        if re.match(r"[a-z]+:", target) or target.startswith("#"):
            continue  # a web address or an anchor in the same file
        resolved = os.path.realpath(os.path.join(os.path.dirname(path), target.split("#")[0]))
        if not resolved.startswith(ROOT + os.sep) or not os.path.exists(resolved):
            bad.append(target)
    return bad


def main():
    files = [os.path.join(ROOT, "README.md")] + sorted(
        glob.glob(os.path.join(ROOT, "docs", "**", "*.md"), recursive=True))
    failures = [(f, t) for f in files for t in broken_links(f)]
    for f, t in failures:
        print(f"{os.path.relpath(f, ROOT)}: broken link {t}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
