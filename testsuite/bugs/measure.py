#!/usr/bin/env python3
"""Measures the bug catalogue: which mistakes the checker catches, and which
correct shaders it accepts (docs/typechecker.md, "What the checker catches").

    testsuite/bugs/measure.py build/bin/safegi_check_file            # print the table
    testsuite/bugs/measure.py build/bin/safegi_check_file --write docs/typechecker.md
    testsuite/bugs/measure.py build/bin/safegi_check_file --check docs/typechecker.md   # ctest: the page is current

Per class of mutants.py: its mutants (one mistake each, the checker must
reject them), its escapes (one mistake each that keeps the types right), and
what the class cannot express. Correct shaders are the catalogue's correct.*
and paper/ shaders and every other annotated shader of the repository that is
meant to check clean (examples, preview, compiler and runtime_gl test data).
Nothing here is timed: the counts are exact.
"""
import argparse
import pathlib
import subprocess
import sys

import mutants

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "scripts"))
import generated_section  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
BEGIN, END = "<!-- catalogue-measure:begin -->", "<!-- catalogue-measure:end -->"
# Annotated shaders outside the catalogue that are meant to check clean.
OTHER_CORRECT = ["examples/shaders", "preview/shaders", "compiler/testdata", "symbol_table/testdata"]
STAGES = ("vert", "frag", "geom", "comp", "tesc", "tese")


def diagnostics(check_file: str, shader: pathlib.Path) -> str:
    """What the checker prints for `shader` (run from its catalogue folder)."""
    run = subprocess.run([check_file, str(shader)], cwd=shader.parent, capture_output=True, text=True)
    if run.returncode not in (0, 1):
        sys.exit(f"{shader}: safegi_check_file failed ({run.returncode}): {run.stderr}")
    return run.stdout + run.stderr


def rejected(check_file: str, shader: pathlib.Path) -> bool:
    return ": error:" in diagnostics(check_file, shader)


def first_error(output: str) -> str:
    """The first error's message and help lines (not its source lines or notes)."""
    lines = output.splitlines()
    start = next((i for i, line in enumerate(lines) if ": error:" in line), None)
    if start is None:
        return ""
    text = [lines[start]]
    for line in lines[start + 1:]:
        if ": error:" in line or ": note:" in line or ": warning:" in line:
            break
        if line.startswith("help:"):
            text.append(line)
    return "\n".join(text)


def names_cause(check_file: str, folder: str, name: str, shader: pathlib.Path) -> bool:
    cause = mutants.CAUSES.get(folder, {}).get(name)
    if cause is None:
        sys.exit(f"{folder}/{name}: no entry in mutants.CAUSES (what the mistake is, as the diagnostic should name it)")
    return cause.lower() in first_error(diagnostics(check_file, shader)).lower()


def shader_of(folder: pathlib.Path, name: str) -> pathlib.Path:
    found = [p for p in folder.glob(f"{name}.sgl.*") if p.suffix[1:] in STAGES]
    if len(found) != 1:
        sys.exit(f"{folder / name}: expected one shader, found {len(found)} (run mutants.py first)")
    return found[0]


def measure(check_file: str) -> str:
    rows = []
    caught_total = mutant_total = escape_total = mutants_caught = mutants_total = 0
    correct_ok = correct_total = named_total = 0
    classes = list(dict.fromkeys(list(mutants.MUTANTS) + list(mutants.ESCAPES)))
    for folder in classes:
        path = HERE / folder
        caught = sum(rejected(check_file, shader_of(path, name)) for name, _, _ in mutants.MUTANTS.get(folder, []))
        named = sum(names_cause(check_file, folder, name, shader_of(path, name)) for name, _, _ in mutants.MUTANTS.get(folder, []))
        named_total += named
        escapes = mutants.ESCAPES.get(folder, [])
        missed = [e for e in escapes if not rejected(check_file, shader_of(path, "escape_" + e[0]))]
        correct = not rejected(check_file, shader_of(path, "correct"))
        n = len(mutants.MUTANTS.get(folder, []))
        mutants_caught += caught
        mutants_total += n
        caught_total += caught + (len(escapes) - len(missed))
        mutant_total += n + len(escapes)
        escape_total += len(missed)
        correct_ok += correct
        correct_total += 1
        cannot = [e[3] for e in missed]
        if folder in mutants.LIMITS:
            cannot.append(mutants.LIMITS[folder])
        rows.append(f"| {folder} | {caught + len(escapes) - len(missed)} of {n + len(escapes)} | {named} of {n} | "
                    f"{'yes' if correct else '**no**'} | {'; '.join(cannot) or '—'} |")
    others = sorted(p for p in (HERE / "paper").glob("*.sgl.*"))
    for folder in OTHER_CORRECT:
        others += sorted(p for p in (ROOT / folder).glob("*.sgl.*") if p.suffix[1:] in STAGES)
    false_positives = [p for p in others if rejected(check_file, p)]
    correct_ok += len(others) - len(false_positives)
    correct_total += len(others)
    lines = [
        f"Mistakes rejected: **{caught_total} of {mutant_total}** ({100.0 * caught_total / mutant_total:.1f} %): "
        f"{mutants_caught} of the {mutants_total} mutants (type errors by design) and "
        f"{mutant_total - mutants_total - escape_total} of the {mutant_total - mutants_total} escapes (right types, wrong value).",
        f"Correct shaders accepted: **{correct_ok} of {correct_total}** ({100.0 * correct_ok / correct_total:.1f} %): "
        f"the {len(classes)} classes' correct shaders, the paper's {len(list((HERE / 'paper').glob('*.sgl.*')))} "
        f"and the {len(others) - len(list((HERE / 'paper').glob('*.sgl.*')))} annotated shaders of "
        + ", ".join(f"`{f}/`" for f in OTHER_CORRECT) + ".",
    ]
    lines.append(f"Diagnostics that name the actual cause: **{named_total} of {mutants_total}** mutants "
                 f"({100.0 * named_total / mutants_total:.1f} %): the first error's message or help contains the "
                 "phrase `mutants.CAUSES` records for the mistake.")
    if false_positives:
        lines.append("Rejected although correct: " + ", ".join(str(p.relative_to(ROOT)) for p in false_positives) + ".")
    lines += ["", "| class | mistakes rejected | cause named | correct accepted | what the language cannot express (right types, wrong value) |",
              "|---|---|---|---|---|"] + rows
    return "\n".join(lines) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("check_file", help="path to safegi_check_file")
    parser.add_argument("--write", help="replace the table between the markers in this file")
    parser.add_argument("--check", help="fail unless the table between the markers in this file is current")
    args = parser.parse_args()
    check_file = str(pathlib.Path(args.check_file).resolve())
    table = measure(check_file)
    if not args.write and not args.check:
        sys.stdout.write(table)
        return 0
    doc = pathlib.Path(args.write or args.check)
    return generated_section.update(doc, BEGIN, END, table, bool(args.check),
                                    f"testsuite/bugs/measure.py <safegi_check_file> --write {doc}")

if __name__ == "__main__":
    sys.exit(main())
