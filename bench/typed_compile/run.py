#!/usr/bin/env python3
"""Compile-time cost of the typed library's checks, as a ratio against the unchecked
build of the same program in the same run.

Programs: docs/typed/quick-start.md's file (a small renderer-style host program),
testsuite/zero_overhead/kernels.cpp (seven hot kernels) and bench/typed_compile/smallpt.cpp
(smallpt ported to the library), each compiled with -O2 -c checked and with
-DSAFEGI_UNCHECKED=1, interleaved. Time is the compiler's CPU time (user + system),
which a loaded machine disturbs less than wall time.

The include cost: a file that only includes <safegi/typed.hpp>, -fsyntax-only, under
g++ and clang++ (whichever are installed), beside a file that includes only the GLM and
standard headers the library itself includes (the floor no library over GLM can go
below); the library's own cost is the difference.

SAFEGI_TYPED_BASELINE=<commit> adds the same measurement against the headers of that
commit (extracted with git archive), for a before/after comparison, interleaved with this
commit's runs; programs that do not compile against the old headers are left out of its
rows. SAFEGI_TYPED_REPEATS=<n> sets the runs of each compile (default 9, 2 quick): on a
loaded machine more runs steady the medians.
"""
from __future__ import annotations

import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lib"))
import harness as h  # noqa: E402


def cpu_seconds(command: list[str]) -> float:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def programs(tmp: Path) -> dict[str, Path]:
    page = (h.ROOT / "docs/typed/quick-start.md").read_text()
    quick_start = tmp / "lighting.cpp"
    quick_start.write_text(re.findall(r"```cpp\n(.*?)```", page, flags=re.S)[0])
    return {"quick-start host program": quick_start, "zero_overhead kernels": h.ROOT / "testsuite/zero_overhead/kernels.cpp",
            "smallpt port": h.ROOT / "bench/typed_compile/smallpt.cpp"}


# The GLM and standard headers typed.hpp includes (representation.hpp, space.hpp,
# map.hpp, spectrum.hpp, quantity.hpp): what a file pays for GLM alone.
FLOOR_HEADERS = ["glm/gtc/matrix_transform.hpp", "glm/mat3x3.hpp", "glm/mat4x4.hpp", "glm/matrix.hpp",
                 "glm/common.hpp", "glm/geometric.hpp", "glm/exponential.hpp", "cmath", "limits", "compare",
                 "concepts", "cstdio", "cstdlib"]


def include_cost(trees: list[tuple[str, Path]], tmp: Path, repeats: int) -> list[list[str]]:
    only_typed = tmp / "only_typed.cpp"
    only_typed.write_text("#include <safegi/typed.hpp>\n")
    floor = tmp / "floor.cpp"
    floor.write_text("".join(f"#include <{header}>\n" for header in FLOOR_HEADERS))
    rows = []
    for cxx in ("g++", "clang++"):
        if subprocess.run(["which", cxx], capture_output=True).returncode != 0:
            continue
        commands = {"floor": [cxx, "-std=c++20", "-O2", "-fsyntax-only", str(floor)]}
        for label, include in trees:
            commands[label] = [cxx, "-std=c++20", "-O2", "-fsyntax-only", f"-I{include}", str(only_typed)]
        samples: dict[str, list[float]] = {name: [] for name in commands}
        for _ in range(repeats):
            for name, command in commands.items():
                samples[name].append(cpu_seconds(command))
        floor_median = statistics.median(samples["floor"])
        for label, _ in trees:
            timing = h.Timing(samples[label])
            rows.append([cxx, label, timing.cell(), h.Timing(samples["floor"]).cell(),
                         f"{timing.median - floor_median:.3f}"])
    return rows


def measure(trees: list[tuple[str, Path]], sources: dict[str, Path], tmp: Path,
            repeats: int) -> list[tuple[str, str, h.Timing, h.Timing]]:
    """Each program checked and unchecked against every tree's headers, all interleaved
    (one run of each per round), so a change in the machine's load falls on every row alike."""
    cxx = os.environ.get("CXX", "g++")
    rows = []
    for name, source in sources.items():
        commands: dict[tuple[str, str], list[str]] = {}
        for label, include in trees:
            base = [cxx, "-std=c++20", "-O2", "-DNDEBUG", f"-I{include}", "-c", str(source), "-o", str(tmp / "out.o")]
            if subprocess.run(base, capture_output=True).returncode != 0:
                continue  # e.g. the quick-start program against headers older than it
            commands[(label, "checked")] = base
            commands[(label, "unchecked")] = base[:1] + ["-DSAFEGI_UNCHECKED=1"] + base[1:]
        samples: dict[tuple[str, str], list[float]] = {key: [] for key in commands}
        for _ in range(repeats):
            for key, command in commands.items():
                samples[key].append(cpu_seconds(command))
        for label, _ in trees:
            if (label, "checked") in samples:
                rows.append((name, label, h.Timing(samples[(label, "checked")]), h.Timing(samples[(label, "unchecked")])))
    return rows


def main() -> None:
    repeats = int(os.environ.get("SAFEGI_TYPED_REPEATS", "0")) or (2 if h.quick() else 9)
    baseline = os.environ.get("SAFEGI_TYPED_BASELINE", "")
    with tempfile.TemporaryDirectory() as tmp_name:
        tmp = Path(tmp_name)
        sources = programs(tmp)
        trees = [("this commit", h.ROOT / "typed/include")]
        if baseline:
            old = tmp / "baseline"
            old.mkdir()
            archive = subprocess.run(["git", "-C", str(h.ROOT), "archive", baseline, "typed/include"], check=True,
                                     capture_output=True).stdout
            subprocess.run(["tar", "-x", "-C", str(old)], input=archive, check=True)
            trees.append((f"headers at {baseline}", old / "typed/include"))
        include_rows = include_cost(trees, tmp, repeats)
        table_rows = []
        for name, label, checked, unchecked in measure(trees, sources, tmp, repeats):
            table_rows.append([name, label, checked.cell(), unchecked.cell(),
                               h.ratio(checked.median, unchecked.median)])
    text = f"""## Compile-time cost of the typed library's checks

Measured by `bench/typed_compile/run.py` ({'quick' if h.quick() else 'full'} mode; {h.machine_line()}).
Each program compiled with `g++ -std=c++20 -O2 -DNDEBUG -c`, checked and with
`-DSAFEGI_UNCHECKED=1`, {repeats} interleaved runs each; compiler CPU seconds (user + system),
median (min–max); ratio = checked / unchecked. `SAFEGI_TYPED_BASELINE=<commit>` adds rows
for the headers of an older commit, measured interleaved with this commit's
(`SAFEGI_TYPED_REPEATS=<n>` sets the runs).

""" + h.table(["program", "headers", "checked (s)", "unchecked (s)", "ratio"], table_rows) + f"""

The include cost: a file holding only `#include <safegi/typed.hpp>`, `-std=c++20 -O2
-fsyntax-only`, beside a file holding only the GLM and standard headers the library
includes (the floor); the library's own cost is the difference of the medians.

""" + h.table(["compiler", "headers", "typed.hpp alone (s)", "GLM floor (s)", "library's own (s)"], include_rows)
    h.write_section("typed_compile", text)


if __name__ == "__main__":
    main()
