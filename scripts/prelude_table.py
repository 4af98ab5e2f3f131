#!/usr/bin/env python3
"""docs/language.md's table of the shader prelude, made from the vocabulary
(typed/include/safegi/typed/vocabulary.def, the file the build makes the prelude from:
cmake/SafeGIPrelude.cmake).

    scripts/prelude_table.py --write docs/language.md   # the table between the prelude-table markers
    scripts/prelude_table.py --check docs/language.md   # ctest docs.prelude_table_is_current
"""
import argparse
import pathlib
import re
import sys

import generated_section

ROOT = pathlib.Path(__file__).resolve().parents[1]
DEF = ROOT / "typed/include/safegi/typed/vocabulary.def"
BEGIN, END = "<!-- prelude-table:begin -->", "<!-- prelude-table:end -->"
NAME = r"([a-z_][a-z0-9_]*)"


def table() -> str:
    bases, ratios, derived, units, aliases = [], [], [], {}, []
    formula, unit_dimension = {}, {}
    for line in DEF.read_text().splitlines():
        if m := re.match(rf"VOCABULARY_BASE\({NAME}\)", line):
            bases.append(m.group(1))
        elif m := re.match(rf"VOCABULARY_RATIO_BASE\({NAME}\)", line):
            ratios.append(m.group(1))
        elif m := re.match(rf'VOCABULARY_DIMENSION\({NAME},[-0-9, ]*"([^"]+)"\)', line):
            formula[m.group(1)] = m.group(2)
            derived.append(m.group(1))
        elif m := re.match(rf"VOCABULARY_SYNONYM\({NAME}, *{NAME}\)", line):
            formula[m.group(1)] = formula[m.group(2)]
            derived.append(m.group(1))
        elif m := re.match(rf'VOCABULARY_UNIT\({NAME}, *"[^"]*", *{NAME},', line):
            units.setdefault(m.group(2), []).append(m.group(1))
            unit_dimension[m.group(1)] = m.group(2)
        elif m := re.match(rf"VOCABULARY_UNIT_ALIAS\({NAME}, *{NAME}\)", line):
            aliases.append((m.group(1), m.group(2)))
        elif line.startswith("VOCABULARY_") and not line.startswith("VOCABULARY_CXX_UNIT("):
            sys.exit(f"{DEF}: cannot read {line!r}")

    def code(names):
        return ", ".join(f"`{n}`" for n in names)

    rows = [
        "| kind | names |",
        "|---|---|",
        f"| base dimensions | {code(bases)}; the ratios {code(ratios)} |",
        "| derived | " + ", ".join(f"`{n} = {formula[n]}`" for n in derived) + " |",
        "| units | " + "; ".join(f"{code(names)} ({dimension})" for dimension, names in units.items()) + " |",
        "| other spellings (the same unit, printed as the first) | "
        + ", ".join(f"`{alias}` ({of})" for alias, of in aliases) + " |",
    ]
    return "\n".join(rows) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--write")
    group.add_argument("--check")
    args = parser.parse_args()
    doc = pathlib.Path(args.write or args.check)
    return generated_section.update(doc, BEGIN, END, table(), bool(args.check), f"scripts/prelude_table.py --write {doc}")


if __name__ == "__main__":
    sys.exit(main())
