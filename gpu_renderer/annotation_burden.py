#!/usr/bin/env python3
"""The annotation burden of the GPU path tracer's shaders (docs/gpu-renderer.md).

Counts, per file and in all, the code lines (not blank, not only a comment)
and those of them that carry SafeGI annotations: an annotated type
(`float<length>`, `point<world>`, `mat3<shading, world, rigid>`, ...), an
annotation declaration (`space`, `dimension`, `unit`), a `template<...>`
header, or a unit written as a factor (`* radian`, `steradian`). Also
counts casts, the one-argument constructor calls of annotated types
(`direction<world>(n)`), split into those of literals, constants and plain
GLSL values entering the checked world and those of annotated values (kind
changes), the ones a reader must look at; -v lists them.

Usage: annotation_burden.py [-v] SHADER_DIR   (prints a table; exit status 0)
"""
import pathlib
import re
import sys

TYPE_WORDS = (r"float|double|u?int|[biud]?vec[234]|mat[234]|spectrum|point|vector|direction|normal|hpoint|"
              r"map|rigidmap|projmap")
ANNOTATED_TYPE = re.compile(r"\b(?:%s)<" % TYPE_WORDS)
DECLARATION = re.compile(r"^\s*(?:space|dimension|unit)\s+\w+")
TEMPLATE = re.compile(r"\btemplate\s*<")
UNIT_FACTOR = re.compile(r"\b(?:radian|steradian|meter|metre|square_meter|degree)\b")
CONSTRUCTOR = re.compile(r"\b(?:%s)<[^;{}()]*?>\(" % TYPE_WORDS)
ENTERING = re.compile(r"^\s*(?:-?[0-9.][0-9.e+-]*|(?:vec[234]|float|u?int)\(.*|[A-Z_]+)\s*$")


def casts_in(line):
    """The one-argument constructors of annotated types in `line`: (text, entering)."""
    found = []
    for match in CONSTRUCTOR.finditer(line):
        depth, i, top_comma = 1, match.end(), False
        while i < len(line) and depth:
            depth += {"(": 1, ")": -1}.get(line[i], 0)
            top_comma |= depth == 1 and line[i] == ","
            i += 1
        argument = line[match.end():i - 1]
        if not top_comma:
            found.append((line[match.start():i], bool(ENTERING.match(argument))))
    return found


def code_lines(text):
    in_block = False
    for raw in text.splitlines():
        line = raw
        if in_block:
            if "*/" not in line:
                continue
            line = line.split("*/", 1)[1]
            in_block = False
        line = re.sub(r"/\*.*?\*/", "", line)
        if "/*" in line:
            line, in_block = line.split("/*", 1)[0], True
        line = line.split("//", 1)[0]
        if line.strip():
            yield line


def main():
    arguments = [a for a in sys.argv[1:] if a != "-v"]
    verbose = "-v" in sys.argv[1:]
    folder = pathlib.Path(arguments[0] if arguments else pathlib.Path(__file__).parent / "shaders")
    files = sorted(p for p in folder.iterdir() if p.suffix in (".sgl", ".comp"))
    totals = [0, 0, 0, 0]
    print(f"{'file':24} {'lines':>6} {'annotated':>9} {'share':>6} {'casts':>6} {'entering':>8}")
    for path in files:
        lines = list(code_lines(path.read_text()))
        annotated = sum(1 for l in lines if ANNOTATED_TYPE.search(l) or DECLARATION.search(l) or TEMPLATE.search(l)
                        or UNIT_FACTOR.search(l))
        found = [c for l in lines for c in casts_in(l)]
        casts = len(found)
        entering = sum(1 for _, e in found if e)
        if verbose:
            for text, e in found:
                print(f"    {'entering' if e else 'CAST    '} {text}")
        for i, n in enumerate((len(lines), annotated, casts, entering)):
            totals[i] += n
        print(f"{path.name:24} {len(lines):6} {annotated:9} {annotated / max(len(lines), 1):6.0%} {casts:6} {entering:8}")
    print(f"{'total':24} {totals[0]:6} {totals[1]:9} {totals[1] / max(totals[0], 1):6.0%} {totals[2]:6} {totals[3]:8}")
    print(f"casts of annotated values (kind changes): {totals[2] - totals[3]}")


if __name__ == "__main__":
    main()
