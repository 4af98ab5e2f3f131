#!/usr/bin/env python3
"""Compile-time cost of the typed library's checks, as a ratio against the unchecked
build of the same program in the same run.

Programs: docs/typed/quick-start.md's file (a small renderer-style host program) and
testsuite/zero_overhead/kernels.cpp (seven hot kernels), each compiled with -O2 -c
checked and with -DSAFEGI_UNCHECKED=1, interleaved. Time is the compiler's CPU time
(user + system), which a loaded machine disturbs less than wall time.

SAFEGI_TYPED_BASELINE=<commit> adds the same measurement against the headers of that
commit (extracted with git archive), for a before/after comparison; programs that do
not compile against the old headers are left out of its rows.
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
    return {"quick-start host program": quick_start, "zero_overhead kernels": h.ROOT / "testsuite/zero_overhead/kernels.cpp"}


def measure(include: Path, sources: dict[str, Path], tmp: Path, repeats: int) -> list[tuple[str, h.Timing, h.Timing]]:
    cxx = os.environ.get("CXX", "g++")
    rows = []
    for name, source in sources.items():
        base = [cxx, "-std=c++20", "-O2", "-DNDEBUG", f"-I{include}", "-c", str(source), "-o", str(tmp / "out.o")]
        commands = {"checked": base, "unchecked": base[:1] + ["-DSAFEGI_UNCHECKED=1"] + base[1:]}
        if subprocess.run(base, capture_output=True).returncode != 0:
            continue  # e.g. the quick-start program against headers older than it
        samples: dict[str, list[float]] = {mode: [] for mode in commands}
        for _ in range(repeats):
            for mode, command in commands.items():
                samples[mode].append(cpu_seconds(command))
        rows.append((name, h.Timing(samples["checked"]), h.Timing(samples["unchecked"])))
    return rows


def main() -> None:
    repeats = 2 if h.quick() else 9
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
        table_rows = []
        for label, include in trees:
            for name, checked, unchecked in measure(include, sources, tmp, repeats):
                table_rows.append([name, label, checked.cell(), unchecked.cell(),
                                   h.ratio(checked.median, unchecked.median)])
    text = f"""## Compile-time cost of the typed library's checks

Measured by `bench/typed_compile/run.py` ({'quick' if h.quick() else 'full'} mode; {h.machine_line()}).
Each program compiled with `g++ -std=c++20 -O2 -DNDEBUG -c`, checked and with
`-DSAFEGI_UNCHECKED=1`, {repeats} interleaved runs each; compiler CPU seconds (user + system),
median (min–max); ratio = checked / unchecked. `SAFEGI_TYPED_BASELINE=<commit>` adds rows
for the headers of an older commit.

""" + h.table(["program", "headers", "checked (s)", "unchecked (s)", "ratio"], table_rows)
    h.write_section("typed_compile", text)


if __name__ == "__main__":
    main()
