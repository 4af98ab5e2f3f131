#!/usr/bin/env python3
"""Annotates the corpus as a user relying on inference would (docs/language.md,
"Gradual typing": an unannotated local with an initialiser takes its
initialiser's type).

    testsuite/real_bugs/minimize_annotations.py build/bin/safegi_check_file [--dry-run] [--bug NAME]

For each bug, each annotated LOCAL declaration with an initialiser inside a
function body (`point<world> x = …`, `direction<world, away> v = …`,
`mat3<A, B, rigid> m = …`) is tried, one at a time, with its plain GLSL
representation type instead (the "erases to" column of docs/language.md's
type table: `vec3 x = …`). The drop is kept only if the checker's verdicts do
not move: the fixed program accepted or rejected, the bug program caught or
missed (and rejected or not), whether the first error names the cause, and
the outcome after the bug's "rewrite". The same replacement is applied to the
"edits" and "rewrite" strings of bugs.json that contain the declaration, and
the bug program is regenerated as make_bugs.py does.

Kept whatever the verdicts: interface variables, globals, constants (`const`
locals too), function signatures, struct fields and block members (none of
them is a local with an initialiser), and the program's claim, the last
annotated local whose value is written to an output (`fragColor =
vec4(color, 1.0)` keeps `spectrum<radiance> color`).
"""
import argparse
import json
import pathlib
import re
import sys

import measure

HERE = measure.HERE

# The representation of each annotated type word (docs/language.md, "Annotated types").
ERASES_TO = {"spectrum": "vec3", "point": "vec3", "vector": "vec3", "direction": "vec3", "normal": "vec3",
             "hpoint": "vec4", "map": "mat4", "rigidmap": "mat4", "projmap": "mat4"}
GLSL_WORD = re.compile(r"(?:float|double|u?int|[dbiu]?vec[234]|d?mat[234](?:x[234])?)$")
DECL_START = re.compile(r"^(\s*)(?!const\b|return\b|uniform\b|in\b|out\b|buffer\b|shared\b)"
                        r"(?:(?:highp|mediump|lowp|precise)\s+)*([A-Za-z_]\w*)\s*<")
OUTPUT_DECL = re.compile(r"^\s*(?:layout\s*\([^)]*\)\s*)?(?:(?:flat|smooth|noperspective|centroid|sample|"
                         r"highp|mediump|lowp)\s+)*out\s+[\w<>, ]+?\s(\w+)\s*(?:\[[^\]]*\])?\s*;")
BUILTIN_OUTPUTS = {"gl_FragColor", "gl_FragData", "gl_Position", "gl_FragDepth"}


def strip_comments(line: str, in_block: bool):
    """The line with comments blanked (same length), and whether a block comment continues."""
    out, i = [], 0
    while i < len(line):
        if in_block:
            end = line.find("*/", i)
            if end < 0:
                out.append(" " * (len(line) - i))
                return "".join(out), True
            out.append(" " * (end + 2 - i))
            i, in_block = end + 2, False
        elif line.startswith("//", i):
            out.append(" " * (len(line) - i))
            break
        elif line.startswith("/*", i):
            in_block = True
        else:
            out.append(line[i])
            i += 1
    return "".join(out), in_block


def annotation_end(text: str, start: int) -> int:
    """Index after the `>` closing the `<` at `start` (nested lists allowed)."""
    depth = 0
    for i in range(start, len(text)):
        if text[i] == "<":
            depth += 1
        elif text[i] == ">":
            depth -= 1
            if depth == 0:
                return i + 1
        elif text[i] in ";={}":
            return -1
    return -1


def candidates(text: str):
    """(line index, annotated type, plain type, name) of each annotated local with an initialiser."""
    found, depth, in_block = [], 0, False
    for index, raw in enumerate(text.splitlines()):
        code, in_block = strip_comments(raw, in_block)
        if depth > 0 and not code.lstrip().startswith("#"):
            m = DECL_START.match(code)
            if m:
                word = m.group(2)
                plain = ERASES_TO.get(word) or (word if GLSL_WORD.match(word) else None)
                lt = code.index("<", m.end(2))
                end = annotation_end(code, lt)
                if plain and end > 0:
                    rest = re.match(r"\s+([A-Za-z_]\w*)\s*(?:\[[^\]]*\]\s*)?=(?!=)", code[end:])
                    if rest:
                        found.append((index, code[m.start(2):end], plain, rest.group(1)))
        depth += code.count("{") - code.count("}")
    return found


def claim(text: str, cands) -> str:
    """The name of the last annotated local whose value is written to an output, or ''."""
    outputs = set(BUILTIN_OUTPUTS)
    for line in text.splitlines():
        m = OUTPUT_DECL.match(line)
        if m:
            outputs.add(m.group(1))
    lines = text.splitlines()
    written = set()
    for line in lines:
        code = line.split("//", 1)[0]
        m = re.match(r"^\s*(\w+)\s*(?:\[[^\]]*\])?\s*(?:\.\w+\s*)?[-+*/]?=(?!=)(.*)", code)
        if m and m.group(1) in outputs:
            written |= set(re.findall(r"[A-Za-z_]\w*", m.group(2)))
    names = [c for c in cands if c[3] in written]
    return max(names, key=lambda c: c[0])[3] if names else ""


def verdict(check_file: str, bug: dict) -> dict:
    r = measure.judge(check_file, bug)
    return {k: r[k] for k in ("fixed", "bug", "bug_rejected", "cause_named", "after_rewrite")}


def drop(text: str, index: int, annotated: str, plain: str, name: str):
    """The program with the declaration on line `index` unannotated, and the (old, new) replacement."""
    lines = text.splitlines(keepends=True)
    old = re.search(re.escape(annotated) + r"\s+" + re.escape(name) + r"\b", lines[index]).group(0)
    new = plain + " " + name
    lines[index] = lines[index].replace(old, new, 1)
    return "".join(lines), (old, new)


def replace_in_bug(bug: dict, old: str, new: str) -> dict:
    copy = json.loads(json.dumps(bug))
    for key in ("edits", "rewrite"):
        for pair in copy.get(key, []):
            pair[0], pair[1] = pair[0].replace(old, new), pair[1].replace(old, new)
    return copy


def minimize(check_file: str, bug: dict, dry_run: bool):
    fixed_path, bug_path = measure.shader(bug, "fixed"), measure.shader(bug, "bug")
    original_fixed, original_bug = fixed_path.read_text(), bug_path.read_text()
    base = verdict(check_file, bug)
    text = original_fixed
    kept_claim = claim(text, candidates(text))
    dropped = []
    try:
        # Work from the last line upward so that line indices of earlier candidates stay valid.
        for index, annotated, plain, name in reversed(candidates(text)):
            if name == kept_claim:
                continue
            trial_text, (old, new) = drop(text, index, annotated, plain, name)
            trial_bug = replace_in_bug(bug, old, new)
            if trial_text.count(new) != text.count(new) + 1:
                continue
            try:
                bug_text = measure.apply_edits(trial_bug, trial_text)
            except SystemExit:
                continue
            fixed_path.write_text(trial_text)
            bug_path.write_text(bug_text)
            try:
                same = verdict(check_file, trial_bug) == base
            except SystemExit:
                same = False
            if same:
                text, bug = trial_text, trial_bug
                dropped.append(f"{old} -> {new}")
    finally:
        if dry_run:
            fixed_path.write_text(original_fixed)
            bug_path.write_text(original_bug)
        else:
            fixed_path.write_text(text)
            bug_path.write_text(measure.apply_edits(bug, text))
    return bug, dropped, kept_claim


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("check_file")
    parser.add_argument("--dry-run", action="store_true", help="report what would be dropped; change nothing")
    parser.add_argument("--bug", help="only this bug")
    args = parser.parse_args()
    check_file = str(pathlib.Path(args.check_file).resolve())
    data = json.loads((HERE / "bugs.json").read_text())
    total = 0
    for i, bug in enumerate(data["bugs"]):
        if args.bug and bug["name"] != args.bug:
            continue
        new_bug, dropped, kept = minimize(check_file, bug, args.dry_run)
        data["bugs"][i] = new_bug
        total += len(dropped)
        print(f"{bug['name']}: {len(dropped)} dropped" + (f" (claim kept: {kept})" if kept else ""))
        for d in dropped:
            print("    " + d)
    if not args.dry_run:
        (HERE / "bugs.json").write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n")
    print(f"{total} annotations dropped")
    return 0


if __name__ == "__main__":
    sys.exit(main())
