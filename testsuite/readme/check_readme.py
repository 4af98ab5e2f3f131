#!/usr/bin/env python3
"""README.md's tour quotes real files and real compiler output; this keeps it true.

A marker comment names what the fenced block after it must be:

  <!-- readme-check: shader FILE -->
      the block is FILE (relative to the repository root), verbatim;
  <!-- readme-check: diagnostic FILE replace "OLD" "NEW" -->
      the block is what `safeglslc FILE` prints on stderr, run from the root,
      after OLD is replaced by NEW in FILE (a bug planted in a copy), and
      safeglslc must exit with 1.

  check_readme.py SAFEGLSLC ROOT [--update]    (--update rewrites the blocks; review git diff)
"""
import pathlib
import re
import subprocess
import sys
import tempfile

MARKER = re.compile(r'<!-- readme-check: (shader|diagnostic) (\S+)(?: replace "([^"]*)" "([^"]*)")? -->\n')
FENCE = re.compile(r"```[a-z]*\n(.*?)```\n", re.S)


def diagnostic(safeglslc, root, path, old, new):
    source = (root / path).read_text()
    if old not in source:
        sys.exit(f"check_readme: {path} has no {old!r} to replace")
    with tempfile.TemporaryDirectory() as scratch:
        copy = pathlib.Path(scratch) / path
        copy.parent.mkdir(parents=True)
        copy.write_text(source.replace(old, new, 1))
        run = subprocess.run([safeglslc, path, "--color=never"], cwd=scratch, capture_output=True, text=True)
    if run.returncode != 1:
        sys.exit(f"check_readme: safeglslc exited {run.returncode} on {path} with the planted bug, expected 1")
    return run.stderr


def main():
    safeglslc, root = str(pathlib.Path(sys.argv[1]).resolve()), pathlib.Path(sys.argv[2])
    update = "--update" in sys.argv[3:]
    readme_path = root / "README.md"
    readme = readme_path.read_text()
    out, at, checked, failures = [], 0, 0, []
    for marker in MARKER.finditer(readme):
        fence = FENCE.match(readme, marker.end())
        if not fence:
            sys.exit(f"check_readme: no fenced block right after {marker.group(0).strip()}")
        kind, path, old, new = marker.groups()
        expected = (root / path).read_text() if kind == "shader" else diagnostic(safeglslc, root, path, old, new)
        if fence.group(1) != expected:
            failures.append(f"README.md: the {kind} block for {path} is not what it quotes; expected:\n{expected}")
        out.append(readme[at:fence.start(1)] + expected)
        at = fence.end(1)
        checked += 1
    out.append(readme[at:])
    if checked == 0:
        sys.exit("check_readme: no readme-check markers in README.md")
    if update:
        readme_path.write_text("".join(out))
        print(f"check_readme: {checked} blocks written")
        return
    for f in failures:
        print(f, file=sys.stderr)
    if failures:
        sys.exit(f"check_readme: {len(failures)} of {checked} blocks differ (run with --update, then review)")
    print(f"check_readme: {checked} blocks are what they quote")


main()
