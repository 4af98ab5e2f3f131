#!/usr/bin/env python3
"""Type-check time per line beside parse time (issue 4's benchmark).

Runs build/bin/safegi_checker_bench (bench/checker/checker_bench.cpp) on a
generated annotated shader of ~50k lines (prelude dimensions, spaces, maps,
generic functions instantiated at each call) and reports lines/s of
preprocess+parse alone, of preprocess+parse+check, and of the check alone,
with the ratio of the two whole-pipeline rates.
"""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lib"))
import harness as h  # noqa: E402

LABELS = {
    "BM_Parse": "preprocess + parse",
    "BM_ParseAndCheck": "preprocess + parse + type check",
    "BM_CheckOnly": "type check alone (tree already parsed)",
}


def main() -> None:
    lines = 10000 if h.quick() else 50000
    repetitions = 1 if h.quick() else 5
    command = [str(h.binary("safegi_checker_bench")), "--lines", str(lines), "--benchmark_format=json",
               f"--benchmark_repetitions={repetitions}", "--benchmark_report_aggregates_only=true"]
    report = json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)
    medians = {}
    for b in report["benchmarks"]:
        name = b["run_name"]
        if b.get("aggregate_name", "median") != "median" and repetitions > 1:
            continue
        medians[name] = b
    rows = []
    for name, label in LABELS.items():
        b = medians[name]
        # CPU time, like Google Benchmark's rates: wall time on a shared machine mostly measures the others.
        ms = b["cpu_time"] if b["time_unit"] == "ms" else b["cpu_time"] / 1e6
        rows.append([label, f"{int(b['lines']):,}", f"{ms:.1f}", f"{b['lines_per_s']:,.0f}"])
    parse = medians["BM_Parse"]["lines_per_s"]
    both = medians["BM_ParseAndCheck"]["lines_per_s"]
    text = "## Type checker: check time per line beside parsing\n\n"
    text += ("Generated annotated fragment shader (`build/bin/safegi_checker_bench --print` writes it): "
             "per block a dimension-generic and a space-generic function, and a shading function with "
             "`map<object, world>`, points, normals, directions, spectra, inferred locals and a "
             "`sampler2D<float<length>>` lookup; the prelude is included (its lines are not counted). "
             f"Median of {repetitions} repetition(s), CPU time, in one process "
             f"(`build/bin/safegi_checker_bench --lines {lines}`). {h.machine_line()}.\n\n")
    text += h.table(["pipeline", "lines", "CPU ms", "lines/s"], rows)
    text += (f"\nParse + check runs at **{both / parse:.2f}×** the rate of parsing alone "
             f"(checking costs {parse / both - 1:.2f}× the parse time).\n")
    h.write_section("checker", text)


if __name__ == "__main__":
    main()
