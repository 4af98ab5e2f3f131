#!/usr/bin/env python3
"""Per-process latency of safeglslc beside glslangValidator, in paired runs.

For each annotated example shader: `safeglslc <shader> -o … --symbols …`
(check, erase, symbol table) against `glslangValidator -S <stage> <the emitted
GLSL>` (parse and check only), and the SPIR-V pair `safeglslc -G` against
`glslangValidator -G --aml --amb`. Each pair runs back to back, in alternating
order, N times; the ratio is taken per pair and its median reported, so load
that drifts during the run hits both sides alike. Beside wall time: CPU time
(user + system of the child) and callgrind's instruction count of one whole
process each (the dynamic loader included, the kernel's exec and page faults
not), which no other load changes.

  bench/compiler/run.py                       (SAFEGI_BUILD: build folder; SAFEGI_BENCH_QUICK=1: 5 pairs)
  SAFEGI_BENCH_BASELINE=<old safeglslc> …     adds a paired row old vs new safeglslc
"""
from __future__ import annotations

import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lib"))
import harness as h  # noqa: E402


def run_once(command: list[str]) -> tuple[float, float]:
    """Wall and CPU (user + system) seconds of one process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def paired(a: list[str], b: list[str], pairs: int) -> dict:
    walls_a, walls_b, cpus_a, cpus_b, ratios = [], [], [], [], []
    for i in range(pairs):
        if i % 2 == 0:
            wa, ca = run_once(a)
            wb, cb = run_once(b)
        else:
            wb, cb = run_once(b)
            wa, ca = run_once(a)
        walls_a.append(wa)
        walls_b.append(wb)
        cpus_a.append(ca)
        cpus_b.append(cb)
        ratios.append(wa / wb)
    quartiles = statistics.quantiles(ratios, n=4) if len(ratios) >= 4 else [min(ratios), 0, max(ratios)]
    return {
        "wall_a": statistics.median(walls_a), "wall_b": statistics.median(walls_b),
        "cpu_a": sum(cpus_a) / pairs, "cpu_b": sum(cpus_b) / pairs,
        "ratio": statistics.median(ratios), "q1": quartiles[0], "q3": quartiles[2],
    }


def ms(seconds: float) -> str:
    return f"{seconds * 1e3:.2f}"


def main() -> None:
    pairs = 5 if h.quick() else 40
    safeglslc = str(h.binary("safeglslc"))
    validator = subprocess.run(["sh", "-c", "command -v glslangValidator"], capture_output=True, text=True).stdout.strip()
    if not validator:
        raise SystemExit("bench: glslangValidator is missing (scripts/install-deps.sh installs glslang-tools)")
    shaders = sorted((h.ROOT / "examples" / "shaders").glob("*.sgl.*"))
    include = ["-I", str(h.ROOT / "examples" / "shaders")]
    rows, instruction_rows, ratios = [], [], []
    with tempfile.TemporaryDirectory() as tmp_dir:
        tmp = Path(tmp_dir)
        for shader in shaders:
            name = shader.name
            stage = name.rsplit(".", 1)[1]
            emitted = tmp / name.replace(".sgl", "")
            subprocess.run([safeglslc, str(shader), *include, "-o", str(emitted)], check=True)
            ours = [safeglslc, str(shader), *include, "-o", str(tmp / "out.glsl"), "--symbols", str(tmp / "out.json")]
            theirs = [validator, "-S", stage, str(emitted)]
            ours_spv = [safeglslc, "-G", str(shader), *include, "-o", str(tmp / "out.spv")]
            theirs_spv = [validator, "-S", stage, "-G", "--aml", "--amb", str(emitted), "-o", str(tmp / "theirs.spv")]
            for label, a, b in (("GLSL + symbols / parse", ours, theirs), ("SPIR-V, -G", ours_spv, theirs_spv)):
                r = paired(a, b, pairs)
                if label.startswith("GLSL"):
                    ratios.append(r["ratio"])
                rows.append([name, label, ms(r["wall_a"]), ms(r["wall_b"]),
                             f"**{r['ratio']:.3f}** ({r['q1']:.3f}–{r['q3']:.3f})",
                             ms(r["cpu_a"]), ms(r["cpu_b"]), f"{r['cpu_a'] / r['cpu_b']:.3f}"])
            if not h.quick():
                ia, ib = h.instructions(ours), h.instructions(theirs)
                # callgrind does not follow safeglslc's exec of safeglslc-spirv: count that one directly
                # (the exec's own cost is in the wall and CPU columns).
                spirv_direct = [str(h.binary("safeglslc-spirv")), *ours_spv[1:]]
                sa, sb = h.instructions(spirv_direct), h.instructions(theirs_spv)
                instruction_rows.append([name, f"{ia:,}", f"{ib:,}", f"{ia / ib:.3f}", f"{sa:,}", f"{sb:,}",
                                         f"{sa / sb:.3f}"])
        baseline = os.environ.get("SAFEGI_BENCH_BASELINE")
        baseline_text = ""
        if baseline:
            shader = h.ROOT / "examples" / "shaders" / "area_light.sgl.frag"
            old = [baseline, str(shader), *include, "-o", str(tmp / "old.glsl"), "--symbols", str(tmp / "old.json")]
            new = [safeglslc, str(shader), *include, "-o", str(tmp / "new.glsl"), "--symbols", str(tmp / "new.json")]
            r = paired(new, old, pairs)
            baseline_text = (f"\nThis safeglslc against `{baseline}` on area_light.sgl.frag, paired the same way: "
                             f"{ms(r['wall_a'])} vs {ms(r['wall_b'])} ms wall, median ratio {r['ratio']:.3f} "
                             f"({r['q1']:.3f}–{r['q3']:.3f}); CPU {ms(r['cpu_a'])} vs {ms(r['cpu_b'])} ms.\n")

    text = "## safeglslc per process against glslangValidator\n\n"
    text += ("`bench/compiler/run.py`: each annotated example shader, safeglslc (check, erase, write GLSL and the "
             "symbol table) against glslangValidator parsing the GLSL safeglslc emitted, and the SPIR-V pair "
             f"(`safeglslc -G` against `glslangValidator -G --aml --amb`). {pairs} pairs per row, run back to back "
             "in alternating order; the ratio is safeglslc / glslangValidator per pair, median (quartiles). "
             f"Wall time is median per process, CPU time (user + system) mean per process. {h.machine_line()}.\n\n")
    text += h.table(["shader", "job", "safeglslc ms", "glslangValidator ms", "wall ratio", "safeglslc CPU ms",
                     "glslangValidator CPU ms", "CPU ratio"], rows)
    if instruction_rows:
        text += ("\nInstructions of one whole process (valgrind --tool=callgrind; the dynamic loader counted, the "
                 "kernel not):\n\n")
        text += h.table(["shader", "safeglslc", "glslangValidator", "ratio", "safeglslc-spirv -G",
                         "glslangValidator -G", "ratio"], instruction_rows)
    text += (f"\nGLSL job, median wall ratio over the shaders: **{statistics.median(ratios):.3f}** "
             f"(largest {max(ratios):.3f}); target ≤ 0.15.\n")
    text += baseline_text
    h.write_section("compiler", text)


if __name__ == "__main__":
    main()
