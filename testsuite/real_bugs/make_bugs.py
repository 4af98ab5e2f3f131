#!/usr/bin/env python3
"""Writes each real bug's bug.sgl.<stage> from its fixed.sgl.<stage> and the
"edits" of bugs.json: each edit (from, to) replaces text that occurs exactly
once in the fixed program, so the bug program is the fixed one with only the
original mistake put back. Run from anywhere after editing a fixed program or
bugs.json; measure.py refuses a bug program that differs from this.
"""
import sys

import measure


def main() -> int:
    for bug in measure.load():
        fixed = measure.shader(bug, "fixed")
        measure.shader(bug, "bug").write_text(measure.apply_edits(bug, fixed.read_text()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
