#!/usr/bin/env python3
"""Measures the corpus of real bugs: physics and geometry mistakes that shipped
in public renderers and were fixed there (docs/typechecker.md, "Real bugs").

    testsuite/real_bugs/measure.py build/bin/safegi_check_file                 # summary and table
    testsuite/real_bugs/measure.py build/bin/safegi_check_file --json          # the same as JSON
    testsuite/real_bugs/measure.py build/bin/safegi_check_file --write docs/typechecker.md
    testsuite/real_bugs/measure.py build/bin/safegi_check_file --check docs/typechecker.md   # ctest: the page is current
    testsuite/real_bugs/measure.py build/bin/safegi_check_file --bug NAME      # ctest: one bug's recorded outcome

Each bug of bugs.json is a folder with the fixed program (fixed.sgl.<stage>)
and the same program with only the original mistake put back (bug.sgl.<stage>,
written from the fixed one by make_bugs.py with the bug's "edits"). A bug is
caught when the checker rejects bug.* and accepts fixed.*; a fixed program the
checker rejects although it is correct is recorded with the reason
("fixed_rejected_reason") and the rewrite that would satisfy the checker.
Nothing is timed: the counts are exact.
"""
import argparse
import json
import pathlib
import re
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(ROOT / "scripts"))
sys.path.insert(0, str(ROOT / "testsuite" / "bugs"))
import generated_section  # noqa: E402


def _catalogue_measure():
    """testsuite/bugs/measure.py, under a name of its own (this module is `measure` too)."""
    import importlib.util
    spec = importlib.util.spec_from_file_location("catalogue_measure", ROOT / "testsuite" / "bugs" / "measure.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


first_error = _catalogue_measure().first_error  # one reading of the checker's output for both corpora

BEGIN, END = "<!-- real-bugs-measure:begin -->", "<!-- real-bugs-measure:end -->"

# An annotation on a line: `<…>` after a type word (declarations, parameters,
# casts such as float<pdf_solid_angle>(…)), or a conversion `e in target`.
TYPE_WORDS = (r"(?:float|double|u?int|[dbiu]?vec[234]|d?mat[234](?:x[234])?|spectrum|point|vector|direction|normal|hpoint"
              r"|map|rigidmap|projmap|[iu]?sampler\w*|[iu]?texture\w*|[iu]?image\w*)")
ANNOTATED_TYPE = re.compile(r"\b" + TYPE_WORDS + r"\s*<")
CONVERSION = re.compile(r"[\w)\]]\s+in\s+(?:\w+|\([^()]*\))\s*(?=[;,)\]*/+\-]|$)")
DECLARATION = re.compile(r"^\s*(?:space|dimension|unit)\s+\w+")


def load() -> list:
    return json.loads((HERE / "bugs.json").read_text())["bugs"]


def shader(bug: dict, which: str) -> pathlib.Path:
    return HERE / bug["name"] / f"{which}.sgl.{bug['stage']}"


def apply_edits(bug: dict, text: str) -> str:
    """The bug program: the fixed one with each edit (from, to) applied once."""
    for old, new in bug["edits"]:
        if text.count(old) != 1:
            sys.exit(f"{bug['name']}: edit source occurs {text.count(old)} times in the fixed program: {old!r}")
        text = text.replace(old, new)
    return text


def diagnostics(check_file: str, path: pathlib.Path) -> str:
    """What the checker prints for `path`, run by its bare name (so no folder name reaches a message)."""
    run = subprocess.run([check_file, path.name], cwd=path.parent, capture_output=True, text=True)
    if run.returncode not in (0, 1):
        sys.exit(f"{path}: safegi_check_file failed ({run.returncode}): {run.stderr}")
    return run.stdout + run.stderr


def error_code(message: str) -> str:
    found = re.search(r"\[(E-[A-Z-]+)\]", message)
    return found.group(1) if found else ""


def code_lines(path: pathlib.Path):
    """Non-blank lines without comments, preprocessor directives and annotation declarations."""
    in_block = False
    for raw in path.read_text().splitlines():
        line = raw
        if in_block:
            if "*/" not in line:
                continue
            line, in_block = line.split("*/", 1)[1], False
        while "/*" in line:
            head, rest = line.split("/*", 1)
            if "*/" in rest:
                line = head + rest.split("*/", 1)[1]
            else:
                line, in_block = head, True
        line = line.split("//", 1)[0].rstrip()
        if not line.strip() or line.lstrip().startswith("#") or DECLARATION.match(line):
            continue
        yield line


def annotated(line: str) -> bool:
    return bool(ANNOTATED_TYPE.search(line) or CONVERSION.search(line))


def rewritten(bug: dict, fixed: str, buggy: str):
    """Both programs with the bug's "rewrite" applied: each (from, to) replaces text
    that occurs once in a program (it must occur in the fixed one; the bug program
    may spell that place differently, then its own entry rewrites it)."""
    for old, new in bug["rewrite"]:
        counts = (fixed.count(old), buggy.count(old))
        if max(counts) > 1 or counts == (0, 0):
            sys.exit(f"{bug['name']}: rewrite source occurs {counts} times in the fixed and bug programs: {old!r}")
        fixed, buggy = fixed.replace(old, new), buggy.replace(old, new)
    return fixed, buggy


def diagnostics_of_text(check_file: str, like: pathlib.Path, text: str) -> str:
    """The checker's output for `text`, a program of the same stage as `like` (written to a
    scratch folder: the programs include nothing but the prelude)."""
    with tempfile.TemporaryDirectory(prefix="real_bugs.") as folder:
        scratch = pathlib.Path(folder) / like.name
        scratch.write_text(text)
        return diagnostics(check_file, scratch)


def judge(check_file: str, bug: dict) -> dict:
    fixed_path, bug_path = shader(bug, "fixed"), shader(bug, "bug")
    if bug_path.read_text() != apply_edits(bug, fixed_path.read_text()):
        sys.exit(f"{bug_path}: not the fixed program with the bug's edits; run make_bugs.py")
    fixed_out, bug_out = diagnostics(check_file, fixed_path), diagnostics(check_file, bug_path)
    after = None
    if bug.get("rewrite"):
        fixed_text, bug_text = rewritten(bug, fixed_path.read_text(), bug_path.read_text())
        f_out = diagnostics_of_text(check_file, fixed_path, fixed_text)
        b_out = diagnostics_of_text(check_file, bug_path, bug_text)
        f_ok = ": error:" not in f_out
        b_caught = f_ok and ": error:" in b_out
        after = {"fixed": "accepted" if f_ok else "rejected", "bug": "caught" if b_caught else "missed",
                 "cause_named": b_caught and bug["cause"].lower() in first_error(b_out).lower(),
                 "first_error_code": error_code(first_error(b_out if f_ok else f_out))}
    fixed_ok = ": error:" not in fixed_out
    bug_rejected = ": error:" in bug_out
    caught = fixed_ok and bug_rejected
    message = first_error(bug_out)
    lines = list(code_lines(fixed_path))
    return {
        "name": bug["name"],
        "bug_class": bug["bug_class"],
        "project": bug["project"],
        "url": bug["url"],
        "type_visible": bug["type_visible"],
        "fixed": "accepted" if fixed_ok else "rejected",
        "bug": "caught" if caught else "missed",
        "bug_rejected": bug_rejected,
        "cause_named": caught and bug["cause"].lower() in message.lower(),
        "first_error": message.splitlines()[0].split(": error: ", 1)[-1] if message else "",
        "first_error_code": error_code(message),
        "fixed_first_error": first_error(fixed_out).splitlines()[0].split(": error: ", 1)[-1] if not fixed_ok else "",
        "lines": len(lines),
        "annotated_lines": sum(annotated(line) for line in lines),
        "forced_rewrites": len(bug["forced_rewrites"]),
        "after_rewrite": after,
        "expect": bug["expect"],
    }


def summary(results: list) -> dict:
    visible = [r for r in results if r["type_visible"]]
    caught = [r for r in results if r["bug"] == "caught"]
    return {
        "bugs": len(results),
        "type_visible": len(visible),
        "caught_type_visible": sum(r["bug"] == "caught" for r in visible),
        "caught_not_type_visible": sum(r["bug"] == "caught" for r in results if not r["type_visible"]),
        "fixed_accepted": sum(r["fixed"] == "accepted" for r in results),
        "caught": len(caught),
        "cause_named": sum(r["cause_named"] for r in caught),
        "lines": sum(r["lines"] for r in results),
        "annotated_lines": sum(r["annotated_lines"] for r in results),
        "forced_rewrites": sum(r["forced_rewrites"] for r in results),
        "projects": len({r["project"].split(" ")[0] for r in results}),
        "rewritten": sum(r["after_rewrite"] is not None for r in results),
        "caught_after_rewrite": sum(r["after_rewrite"] is not None and r["after_rewrite"]["bug"] == "caught"
                                    for r in results),
        "named_after_rewrite": sum(r["after_rewrite"] is not None and r["after_rewrite"]["cause_named"]
                                   for r in results),
    }


def pct(a: int, b: int) -> str:
    return f"{100.0 * a / b:.1f} %" if b else "—"


def note(bug: dict, result: dict) -> str:
    if result["fixed"] == "rejected":
        text = "fixed rejected: " + bug["fixed_rejected_reason"].split(":")[0] + "; needs " + bug["rewrite_needed"].rstrip(";")
        after = result["after_rewrite"]
        if after is None:
            return text + ("; " + bug["missed_reason"] if bug.get("missed_reason") else "")
        if after["fixed"] == "rejected":
            return text + f"; rewritten, the fixed program is still rejected ({after['first_error_code']})"
        if after["bug"] == "missed":
            return text + "; rewritten, the bug checks clean" + (": " + bug["missed_reason"] if bug.get("missed_reason") else "")
        return text + f"; rewritten, the bug is caught ({after['first_error_code']}, cause " + \
            ("named)" if after["cause_named"] else "not named)")
    if result["type_visible"] and result["bug"] == "missed":
        return "bug checks clean: " + bug.get("missed_reason", "")
    if not result["type_visible"]:
        return "right types, wrong value"
    return result["first_error_code"]


def table(bugs: list, results: list) -> str:
    s = summary(results)
    lines = [
        f"Bugs caught: **{s['caught_type_visible']} of {s['type_visible']}** type-visible bugs "
        f"({pct(s['caught_type_visible'], s['type_visible'])}); {s['caught_not_type_visible']} of the "
        f"{s['bugs'] - s['type_visible']} others (right types, wrong value). A bug is caught when its program is "
        "rejected and the fixed program accepted.",
        f"Fixed programs accepted: **{s['fixed_accepted']} of {s['bugs']}** ({pct(s['fixed_accepted'], s['bugs'])}).",
        f"First error names the cause: **{s['cause_named']} of {s['caught']}** caught bugs "
        f"({pct(s['cause_named'], s['caught'])}).",
        f"Annotated lines: **{s['annotated_lines']} of {s['lines']}** lines of the fixed programs "
        f"({pct(s['annotated_lines'], s['lines'])}; non-blank lines without comments, directives and "
        "space declarations; a line is annotated when it has a `<…>` on a type or an `in` conversion). "
        "The corpus is annotated as a user relying on inference would annotate it: the interface (uniforms, "
        "inputs, outputs, block members), constants, function signatures where generic helpers need them, and "
        "the result a computation claims to produce (the radiance written out); the other locals are inferred "
        "from their initialisers (docs/language.md, \"Gradual typing\"). minimize_annotations.py drops each "
        "local annotation that changes no verdict.",
        f"Rewrites of idiomatic GLSL forced by the checker: **{s['forced_rewrites']}**.",
        f"With the rewrites the rejected fixed programs would need (`rewrite` in bugs.json, {s['rewritten']} bugs), "
        f"{s['caught_after_rewrite']} more bugs would be caught, {s['named_after_rewrite']} of them with the cause named.",
        f"{s['bugs']} bugs from {s['projects']} projects; the note of a missed bug says why.",
        "",
        "| bug | class | type-visible | fixed | bug | cause named | note |",
        "|---|---|---|---|---|---|---|",
    ]
    by_name = {b["name"]: b for b in bugs}
    for r in results:
        named = "yes" if r["cause_named"] else ("no" if r["bug"] == "caught" else "—")
        lines.append(f"| [{r['name']}]({r['url']}) | {r['bug_class']} | {'yes' if r['type_visible'] else 'no'} | "
                     f"{r['fixed']} | {r['bug']} | {named} | {note(by_name[r['name']], r).replace('|', '/')} |")
    return "\n".join(lines) + "\n"


def check_one(check_file: str, bugs: list, name: str) -> int:
    bug = next((b for b in bugs if b["name"] == name), None)
    if bug is None:
        sys.exit(f"no bug named {name} in bugs.json")
    r = judge(check_file, bug)
    got = {"fixed": r["fixed"], "bug": r["bug"]}
    if got == bug["expect"]:
        return 0
    sys.stdout.write(f"{name}: expected fixed {bug['expect']['fixed']}, bug {bug['expect']['bug']}; "
                     f"now fixed {got['fixed']}, bug {got['bug']}\n")
    if r["fixed_first_error"]:
        sys.stdout.write(f"  fixed program: {r['fixed_first_error']}\n")
    if r["first_error"]:
        sys.stdout.write(f"  bug program: {r['first_error']}\n")
    sys.stdout.write("If the change is intended, update \"expect\" in testsuite/real_bugs/bugs.json "
                     "(and fixed_rejected_reason), then measure.py --write docs/typechecker.md.\n")
    return 1


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("check_file", help="path to safegi_check_file")
    parser.add_argument("--json", action="store_true", help="print the summary and per-bug results as JSON")
    parser.add_argument("--write", help="replace the section between the markers in this file")
    parser.add_argument("--check", help="fail unless the section between the markers in this file is current")
    parser.add_argument("--bug", help="check one bug's outcome against its \"expect\" in bugs.json")
    args = parser.parse_args()
    check_file = str(pathlib.Path(args.check_file).resolve())
    bugs = load()
    if args.bug:
        return check_one(check_file, bugs, args.bug)
    results = [judge(check_file, b) for b in bugs]
    if args.json:
        sys.stdout.write(json.dumps({"summary": summary(results), "bugs": results}, indent=1) + "\n")
        return 0
    text = table(bugs, results)
    if not args.write and not args.check:
        sys.stdout.write(text)
        return 0
    doc = pathlib.Path(args.write or args.check)
    return generated_section.update(doc, BEGIN, END, text, bool(args.check),
                                    f"testsuite/real_bugs/measure.py <safegi_check_file> --write {doc}")


if __name__ == "__main__":
    sys.exit(main())
