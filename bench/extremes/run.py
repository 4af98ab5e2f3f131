#!/usr/bin/env python3
"""Extremes, timed: each extreme of issue 8 is a ctest test (behaviour) and a
row here (time and outcome).

* The compiler: safeglslc on the shaders of testsuite/extremes (the largest
  exponents, exponent overflow) and on the same generators at sizes past the
  tests' (derived-dimension chains, generic call chains, operator chains,
  nested parentheses): whole-process time, median of interleaved runs, and the
  outcome (clean, or the first diagnostic).
* The typed C++ library: g++ -fsyntax-only on generated translation units (a
  chain of N derived dimensions, each a template instantiation deeper; the
  largest exponents; exponent overflow): compile time and outcome.
* The renderer: the extremes tests of cpu_renderer/tests/extremes_test.cpp, each
  with its run time and result (docs/stability.md has what each checks).
"""
from __future__ import annotations

import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lib"))
import harness as h  # noqa: E402

EXTREMES = h.ROOT / "testsuite" / "extremes"
REPEATS = 3 if h.quick() else 7


def first_diagnostic(stderr: str) -> str:
    for line in stderr.splitlines():
        match = re.search(r": ((?:fatal )?error: .*)$", line)
        if match:
            return match.group(1)
    return "clean" if not stderr.strip() else stderr.strip().splitlines()[0]


def outcome(command: list[str], cwd: Path) -> tuple[int, str]:
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    return result.returncode, first_diagnostic(result.stderr)


def timed(command: list[str], cwd: Path) -> h.Timing:
    samples = []
    for _ in range(REPEATS):
        samples.append(h.wall_time_in(command, cwd))
    return h.Timing(samples)


def generate(out: Path, sizes: list[str]) -> None:
    subprocess.run(["cmake", f"-DOUT_DIR={out}", f"-DSIZES={';'.join(sizes)}", "-P",
                    str(EXTREMES / "generate_shaders.cmake")], check=True)


COMPILER_CASES = [
    # (what, shader name, folder: "source" or "generated", generator size or None)
    ("largest exponents (length^±2147483647)", "largest_exponents", None),
    ("exponent overflow (six ways)", "exponent_overflow", None),
    ("derived-dimension chain, 2 000 names (test size)", "derived_chain_2000", "derived_chain=2000"),
    ("derived-dimension chain, 20 000 names", "derived_chain_20000", "derived_chain=20000"),
    ("generic call chain, 1 000 functions (test size)", "generic_chain_1000", "generic_chain=1000"),
    ("generic call chain, 10 000 functions", "generic_chain_10000", "generic_chain=10000"),
    ("operator chain, 2 000 operators (test size)", "operator_chain_1000", "operator_chain=1000"),
    ("operator chain, 2 200 operators (past the limit)", "operator_chain_1100", "operator_chain=1100"),
    ("operator chain, 200 000 operators", "operator_chain_100000", "operator_chain=100000"),
    ("nested parentheses, 80", "nested_parens_80", "nested_parens=80"),
    ("nested parentheses, 300 (past the limit)", "nested_parens_300", "nested_parens=300"),
    ("nested parentheses, 100 000", "nested_parens_100000", "nested_parens=100000"),
]
QUICK_SKIP = {"derived_chain_20000", "generic_chain_10000", "operator_chain_100000", "nested_parens_100000"}


def compiler_rows(tmp: Path) -> list[list[str]]:
    safeglslc = str(h.binary("safeglslc"))
    cases = [c for c in COMPILER_CASES if not (h.quick() and c[1] in QUICK_SKIP)]
    generate(tmp, [size for _, _, size in cases if size])
    rows = []
    for what, name, size in cases:
        folder = tmp if size else EXTREMES
        command = [safeglslc, "--color=never", f"{name}.sgl.frag"]
        lines = sum(1 for _ in (folder / f"{name}.sgl.frag").open())
        rc, first = outcome(command, folder)
        time = timed(command, folder)
        rows.append([what, f"{lines:,}", f"{time.median * 1000:.1f} ({min(time.samples) * 1000:.1f}–"
                     f"{max(time.samples) * 1000:.1f})", f"{rc}: {first}"])
    return rows


TYPED_CHAIN = """#include <safegi/typed.hpp>
using namespace safegi;
template <int N> struct chain {{ using type = dim::product<typename chain<N - 1>::type, dim::length>; }};
template <> struct chain<0> {{ using type = dim::length; }};
static_assert(std::is_same_v<chain<{n}>::type, dim::pow<dim::length, {n} + 1>>);
quantity<chain<{n}>::type> q;
"""

TYPED_LARGEST = """#include <climits>
#include <safegi/typed.hpp>
using namespace safegi;
using huge = dim::pow<dim::length, INT_MAX>;
static_assert(std::is_same_v<dim::product<huge, dim::inverse<huge>>, dim::dimensionless>);
auto q = from_raw<quantity<huge, double>>(2.0);
double f() { return raw(q * from_raw<quantity<dim::inverse<huge>, double>>(0.5)); }
"""


def typed_rows() -> list[list[str]]:
    flags = ["g++", "-std=c++20", "-fsyntax-only", f"-I{h.ROOT / 'typed' / 'include'}", "-x", "c++", "-"]
    cases = [("largest exponents (INT_MAX, its inverse, quantity<…, double>)", TYPED_LARGEST)]
    for n in ([100, 880] if h.quick() else [100, 400, 880, 900]):
        cases.append((f"derived-dimension chain, {n} levels of instantiation", TYPED_CHAIN.format(n=n)))
    cases.append(("exponent overflow (INT_MAX · length)", (EXTREMES.parent / "compile_fail" / "cases" /
                                                           "exponent_overflow.cpp").read_text()))
    rows = []
    for what, source in cases:
        samples, result = [], None
        for _ in range(3 if h.quick() else 5):
            result, seconds = h.run_with_input(flags, source)
            samples.append(seconds)
        time = h.Timing(samples)
        rows.append([what, time.cell(), f"{result.returncode}: {first_diagnostic(result.stderr)[:160]}"])
    return rows


def renderer_rows(tmp: Path) -> list[list[str]]:
    try:
        binary = h.binary("safegi_cpu_renderer_extremes_test")
    except SystemExit:
        return [["(not built: safegi_cpu_renderer_extremes_test)", "—", "—"]]
    report = tmp / "extremes.json"
    subprocess.run([str(binary), f"--gtest_output=json:{report}"], capture_output=True, text=True)
    rows = []
    for suite in json.loads(report.read_text())["testsuites"]:
        for test in suite["testsuite"]:
            passed = "failures" not in test
            rows.append([f"`renderer.{suite['name']}.{test['name']}`", test["time"].rstrip("s"),
                         "pass" if passed else "**FAIL**"])
    return rows


def main() -> None:
    # Optional arguments pick parts ("compiler", "typed", "renderer"; the ctest
    # bench.extremes_quick runs "compiler"); the section is complete only without them.
    only = set(sys.argv[1:])
    skipped = [["(not run)", "—", "—"]]
    machine = h.machine_line()
    with tempfile.TemporaryDirectory() as tmp_name:
        tmp = Path(tmp_name)
        compiler = compiler_rows(tmp) if not only or "compiler" in only else [["(not run)", "—", "—", "—"]]
        typed = typed_rows() if not only or "typed" in only else skipped
        renderer = renderer_rows(tmp) if not only or "renderer" in only else skipped
    mode = "quick mode" if h.quick() else "full mode"
    text = f"""## Extremes, timed (compiler, typed library, renderer)

Measured by `bench/extremes/run.py` ({mode}; {machine}). Each extreme is also a ctest test:
`ctest -L extremes` (the compiler's, `testsuite/extremes/`, exact diagnostics),
`ctest -R 'compile_fail.exponent_overflow'` (the typed library's),
`ctest -R 'renderer.Extremes'` (the renderer's, docs/stability.md). Times are whole-process wall
times on a shared machine, median (min–max) of {REPEATS} runs.

### safeglslc

The front end's limits: a literal exponent is at most 1000 (larger exponents come from powers and
products of named dimensions); exponents are 32-bit and overflow is an error; 256 levels of nesting
(statements, parentheses and operators — a parenthesis costs three, so 85 nested parentheses already
stop it); 2048 binary or postfix operators in one chain. Any tree within these limits checks on any caller
stack: the checker walks operator chains iteratively and compile() runs on a 512 MB stack (docs/stability.md,
"the operator limit was deeper than the checker's stack", fixed).

""" + h.table(["shader", "lines", "ms", "exit status: outcome"], compiler) + """
### The typed C++ library (g++ -fsyntax-only, seconds)

Exponents are `int`; a product whose exponent leaves `int` stops at a `static_assert`
("dimension exponent overflows int"); a power that overflows is g++'s own error
("overflow in constant expression"). A chain of derived dimensions defined recursively is one
template instantiation per link: g++'s default `-ftemplate-depth=900` is the limit, with its own error.

""" + h.table(["translation unit", "seconds", "exit status: first error"], typed) + """
### The renderer (gtest times, seconds)

""" + h.table(["test", "seconds", "result"], renderer)
    h.write_section("extremes", text)


if __name__ == "__main__":
    main()
