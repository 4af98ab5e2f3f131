#!/usr/bin/env python3
"""Every path of the tree that the documentation names exists.

    testsuite/docs_examples/check_doc_paths.py [ROOT]

Scans README.md and docs/**/*.md for paths that start with a top-level folder
of the tree (`cpu_renderer/src/accel/bvh.cpp`, `typechecker/src/builtins.def`,
`testsuite/golden/`): a file name (its last part has a dot) or a folder
(written with a trailing slash, or in backticks) must exist, so a recipe that
names a moved or deleted file fails here, not in a reader's hands. Globs and
placeholders (`*`, `<…>`, `NAME`-style words in capitals) are skipped, and a
name that is a prefix of files (`ply.*`) counts when some file starts with it.
"""
import glob
import os
import re
import sys


def main() -> int:
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
    os.chdir(root)
    top = sorted(d for d in os.listdir(".") if os.path.isdir(d) and not d.startswith((".", "build")))
    path = re.compile(r"(?<![\w./-])((?:" + "|".join(map(re.escape, top)) + r")/[\w./-]*[\w/])")
    docs = sorted(glob.glob("docs/**/*.md", recursive=True)) + ["README.md"]
    missing = []
    checked = 0
    for doc in docs:
        with open(doc, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                for m in path.finditer(line):
                    token = m.group(1)
                    after = line[m.end():m.end() + 2]
                    if after.startswith(("*", "<", ".*", "-*")) or "*" in token:
                        continue
                    last = token.rstrip("/").rsplit("/", 1)[-1]
                    backticked = m.start() > 0 and line[m.start() - 1] == "`"
                    if "." not in last and not token.endswith("/") and not backticked:
                        continue  # prose such as "preview/CPU"
                    if re.fullmatch(r"[A-Z_]+", last):
                        continue  # a placeholder: testsuite/golden/cases/NAME
                    checked += 1
                    if os.path.exists(token) or glob.glob(glob.escape(token) + "*"):
                        continue
                    missing.append(f"{doc}:{number}: {token}")
    for m in missing:
        print(m)
    print(f"{checked} paths named by {len(docs)} documents; {len(missing)} missing")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
