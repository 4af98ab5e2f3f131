#!/usr/bin/env python3
"""Keeps the diagnostic codes as data (diagnostics/include/safegi/diagnostics/codes.def).

    diagnostics/codes_table.py --write docs/typechecker.md    # the table between the codes markers
    diagnostics/codes_table.py --check docs/typechecker.md    # ctest: the page lists exactly codes.def
    diagnostics/codes_table.py --sources .                     # ctest: sources emit codes through code::
    diagnostics/codes_table.py --goldens DIR...                # ctest: every located diagnostic has a code

--sources reads every C++ source of the repository (and its .def, .inc and .in
files) and fails on a code spelled as a string literal ("E-…"/"W-…") outside
codes.def and tests (call sites use the constants, code::E_…), on a constant
code::E_… that codes.def lacks, and on a declared code no source emits. Tests
may spell codes: they are expected values.

--goldens reads the expected outputs (*.expected) under each DIR and fails on
a diagnostic line of any stage that has no code, or one codes.def lacks: the
checker's (`file:line:col: error: … [E-…]`), the driver's (`safeglslc: error:
… [E-COMMAND-LINE]`) and glslang's for SPIR-V (`file:line: error: … [E-SPIRV]`),
and every error or warning of --diagnostics-format=json.
"""
import argparse
import json
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


def is_test(path: pathlib.Path) -> bool:
    return path.stem.endswith("_test") or "test_support" in path.stem or "testsuite" in path.parts


def check_sources(root: pathlib.Path) -> int:
    declared = {code for _, code, _ in codes()}
    identifiers = {ident for ident, _, _ in codes()}
    used, bad = set(), []
    for path in sorted(root.rglob("*")):
        parts = path.relative_to(root).parts
        if path.suffix not in (".cpp", ".hpp", ".h", ".cc", ".def", ".inc", ".in") or parts[0].startswith("build"):
            continue
        if path == DEF:
            continue
        if any(part.startswith(".") for part in parts):
            continue
        text = path.read_text(errors="replace")
        for m in re.finditer(r'"([EW]-[A-Z][A-Z0-9-]*)"', text):
            if m.group(1) in NOT_CODES:
                continue
            where = f"{path.relative_to(root)}:{text.count(chr(10), 0, m.start()) + 1}"
            if m.group(1) not in declared:
                bad.append(f"{where}: \"{m.group(1)}\" is not in codes.def")
            elif not is_test(path.relative_to(root)):
                bad.append(f"{where}: the literal \"{m.group(1)}\"; use code::{m.group(1).replace('-', '_')} (codes.def)")
        for m in re.finditer(r"\bcode::([EW]_[A-Z0-9_]+)", text):
            used.add(m.group(1).replace("_", "-"))
            if m.group(1) not in identifiers:
                bad.append(f"{path.relative_to(root)}: code::{m.group(1)} is not in codes.def")
    for code in sorted(declared - used):
        bad.append(f"codes.def: {code} is declared but no source emits it")
    for line in bad:
        print(line)
    return 1 if bad else 0


# A diagnostic line as a stage prints it (colour codes removed): `file:line:col:`, glslang's
# `file:line:` or `file:`, the driver's `safeglslc:`. Excerpts of source lines start with a blank.
DIAGNOSTIC = re.compile(r"^\S.*?: (error|warning): ")
ANSI = re.compile(r"\x1b\[[0-9;]*m")
CODE_AT_END = re.compile(r"\[([EW]-[A-Z0-9-]+)\]$")


def check_goldens(folders) -> int:
    declared = {code for _, code, _ in codes()}
    bad = []
    for path in sorted(p for folder in folders for p in pathlib.Path(folder).rglob("*.expected")):
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            line = ANSI.sub("", line).rstrip()
            if line.startswith('{"diagnostics":'):  # --diagnostics-format=json
                for d in json.loads(line)["diagnostics"]:
                    if d.get("severity") in ("error", "warning") and d.get("code") not in declared:
                        bad.append(f"{path}:{number}: a diagnostic without a declared code: {d.get('message')}")
                continue
            if not DIAGNOSTIC.match(line):
                continue
            m = CODE_AT_END.search(line)
            if not m:
                bad.append(f"{path}:{number}: a diagnostic without a code: {line}")
            elif m.group(1) not in declared:
                bad.append(f"{path}:{number}: {m.group(1)} is not in codes.def")
    for line in bad:
        print(line)
    return 1 if bad else 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--write")
    parser.add_argument("--check")
    parser.add_argument("--sources")
    parser.add_argument("--goldens", nargs="+", metavar="DIR")
    args = parser.parse_args()
    if args.goldens:
        return check_goldens(args.goldens)
    if args.sources:
        return check_sources(pathlib.Path(args.sources).resolve())
    doc = pathlib.Path(args.write or args.check)
    return generated_section.update(doc, BEGIN, END, table(), bool(args.check),
                                    f"diagnostics/codes_table.py --write {doc}")

if __name__ == "__main__":
    sys.exit(main())
