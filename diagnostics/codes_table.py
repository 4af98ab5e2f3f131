#!/usr/bin/env python3
"""Keeps the diagnostic codes as data (diagnostics/include/safegi/diagnostics/codes.def).

    diagnostics/codes_table.py --write docs/typechecker.md    # the table between the codes markers
    diagnostics/codes_table.py --check docs/typechecker.md    # ctest: the page lists exactly codes.def
    diagnostics/codes_table.py --sources .                     # ctest: every code the sources spell is declared

--sources reads every C++ source of the repository (tests too) and fails on a
string literal "E-…"/"W-…" or a constant code::E_… that codes.def lacks, and
on a declared code no source emits.
"""
import argparse
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "scripts"))
import generated_section  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
DEF = HERE / "include/safegi/diagnostics/codes.def"
BEGIN, END = "<!-- diagnostic-codes:begin -->", "<!-- diagnostic-codes:end -->"
ENTRY = re.compile(r'^CODE\((\w+), "([EW]-[A-Z0-9-]+)", "(.*)"\)\s*$')
# Sample codes of tests that are no codes (the engine's and the renderer's tests, and codes_test's unknown ones).
NOT_CODES = {"E-X", "E-DIM-MISMATCH", "E-NOPE"}


def codes():
    out = []
    for line in DEF.read_text().splitlines():
        m = ENTRY.match(line)
        if m:
            out.append((m.group(1), m.group(2), m.group(3)))
        elif line.startswith("CODE("):
            sys.exit(f"{DEF}: cannot read {line!r}")
    return out


def table():
    rows = ["| code | when |", "|---|---|"] + [f"| {code} | {meaning} |" for _, code, meaning in codes()]
    return "\n".join(rows) + "\n"


def check_sources(root: pathlib.Path) -> int:
    declared = {code for _, code, _ in codes()}
    identifiers = {ident for ident, _, _ in codes()}
    used, bad = set(), []
    for path in sorted(root.rglob("*")):
        parts = path.relative_to(root).parts
        if path.suffix not in (".cpp", ".hpp", ".h", ".cc") or parts[0].startswith("build"):
            continue
        if any(part.startswith(".") for part in parts):
            continue
        text = path.read_text(errors="replace")
        for m in re.finditer(r'"([EW]-[A-Z][A-Z0-9-]*)"', text):
            if m.group(1) in NOT_CODES:
                continue
            used.add(m.group(1))
            if m.group(1) not in declared:
                bad.append(f"{path.relative_to(root)}: \"{m.group(1)}\" is not in codes.def")
        for m in re.finditer(r"\bcode::([EW]_[A-Z0-9_]+)", text):
            used.add(m.group(1).replace("_", "-"))
            if m.group(1) not in identifiers:
                bad.append(f"{path.relative_to(root)}: code::{m.group(1)} is not in codes.def")
    for code in sorted(declared - used):
        bad.append(f"codes.def: {code} is declared but no source emits it")
    for line in bad:
        print(line)
    return 1 if bad else 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--write")
    parser.add_argument("--check")
    parser.add_argument("--sources")
    args = parser.parse_args()
    if args.sources:
        return check_sources(pathlib.Path(args.sources).resolve())
    doc = pathlib.Path(args.write or args.check)
    return generated_section.update(doc, BEGIN, END, table(), bool(args.check),
                                    f"diagnostics/codes_table.py --write {doc}")

if __name__ == "__main__":
    sys.exit(main())
