#!/usr/bin/env python3
"""Table 1 of the SafeGI paper, redone: what does checking cost?

For each bundled scene and feature, the typed (`safegi-render`) and unchecked
(`safegi-render-unchecked`) programs, built from one source, are compared by
  * image identity (exact floats, PFM),
  * instruction count (callgrind, one thread) and its ratio,
  * wall time (interleaved runs, median (min–max)) and its ratio;
and the compile-time cost of the checks: the renderer's translation units
compiled typed vs unchecked, and one TU that only includes the typed headers.
"""
from __future__ import annotations

import filecmp
import json
import shlex
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lib"))
import harness as h  # noqa: E402

SCENES = h.ROOT / "examples" / "scenes"
# Instructions are counted inside the renderer's entry point only: start-up
# (OpenImageIO's initialisation alone is ~0.9 G instructions) and image writing
# are the same code in both programs and would hide the difference.
RENDER_FUNCTION = "safegi::render::render(*"

# (row label, feature, scene file, integrator)
CASES = [
    ("Cornell box", "path", "cornell-box/cornell-box.json", "path"),
    ("Cornell box", "direct", "cornell-box/cornell-box.json", "direct"),
    ("motion blur", "motion", "motion-blur.json", "path"),
    ("depth of field", "dof", "depth-of-field.json", "path"),
    ("Phong", "direct", "phong.json", "direct"),
    ("many lights", "direct", "many-lights.json", "direct"),
    # A PLY mesh under the BVH: traversal and triangle tests dominate.
    ("PLY torus", "mesh", "ply-mesh.json", "path"),
]


def render_command(program: str, scene: str, integrator: str, size: int, spp: int, threads: int,
                   output: Path) -> list[str]:
    return [str(h.binary(program)), str(SCENES / scene), "--integrator", integrator,
            "--resolution", f"{size}x{size}", "--spp", str(spp), "--threads", str(threads),
            "--quiet", "--pfm", "-o", str(output)]


def compare_scene(label, feature, scene, integrator, tmp: Path) -> list[str]:
    quick = h.quick()
    typed = tmp / "typed"
    unchecked = tmp / "unchecked"
    # Identity and instructions at a size callgrind runs in seconds.
    size, spp = (32, 2) if quick else (64, 4)
    commands = {name: render_command(program, scene, integrator, size, spp, 1, out)
                for name, program, out in (("typed", "safegi-render", typed),
                                           ("unchecked", "safegi-render-unchecked", unchecked))}
    counts = {name: h.instructions(cmd, inside=RENDER_FUNCTION) for name, cmd in commands.items()}
    identical = filecmp.cmp(f"{typed}.pfm", f"{unchecked}.pfm", shallow=False)
    # Wall time at a size where start-up is small next to rendering.
    size, spp, repeats = (64, 4, 2) if quick else (256, 16, 5)
    timed = {name: render_command(program, scene, integrator, size, spp, 2, tmp / f"t-{name}")
             for name, program in (("typed", "safegi-render"), ("unchecked", "safegi-render-unchecked"))}
    times = h.interleaved(timed, repeats)
    return [label, feature, "yes" if identical else "**NO**",
            f"{counts['typed']:,}", f"{counts['unchecked']:,}", h.ratio(counts["typed"], counts["unchecked"]),
            times["typed"].cell(), times["unchecked"].cell(),
            h.ratio(times["typed"].median, times["unchecked"].median)]


def renderer_compile_commands() -> dict[str, list[list[str]]]:
    entries = json.loads((h.build_dir() / "compile_commands.json").read_text())
    variants: dict[str, list[list[str]]] = {"typed": [], "unchecked": []}
    for entry in entries:
        command = entry.get("command") or " ".join(entry["arguments"])
        if "/cpu_renderer/src/" not in entry["file"]:
            continue
        if "safegi_cpu_renderer.dir" in command:
            variants["typed"].append((entry["directory"], shlex.split(command)))
        elif "safegi_cpu_renderer_unchecked.dir" in command:
            variants["unchecked"].append((entry["directory"], shlex.split(command)))
    return variants


def compile_seconds(commands, tmp: Path) -> float:
    total = 0.0
    for directory, argv in commands:
        argv = list(argv)
        argv[argv.index("-o") + 1] = str(tmp / "unit.o")
        if "-MF" in argv:
            argv[argv.index("-MF") + 1] = str(tmp / "unit.d")
        start = time.perf_counter()
        subprocess.run(argv, cwd=directory, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        total += time.perf_counter() - start
    return total


def compile_cost(tmp: Path) -> str:
    variants = renderer_compile_commands()
    repeats = 1 if h.quick() else 3
    samples = {"typed": [], "unchecked": []}
    for _ in range(repeats):
        for name in samples:
            samples[name].append(compile_seconds(variants[name], tmp))
    typed, unchecked = h.Timing(samples["typed"]), h.Timing(samples["unchecked"])
    # One TU including only the typed headers vs only GLM, same flags.
    include_dirs = [f"-I{h.ROOT / 'typed' / 'include'}"]
    flags = ["g++", "-std=c++20", "-O2", "-fsyntax-only", *include_dirs, "-x", "c++", "-"]
    def header_cost(source: str) -> h.Timing:
        times = []
        for _ in range(3 if h.quick() else 7):
            start = time.perf_counter()
            subprocess.run(flags, input=source.encode(), check=True)
            times.append(time.perf_counter() - start)
        return h.Timing(times)
    typed_tu = header_cost("#include <safegi/typed.hpp>\n")
    glm_tu = header_cost("#include <glm/glm.hpp>\n#include <glm/gtc/matrix_transform.hpp>\n")
    rows = [
        [f"renderer sources ({len(variants['typed'])} TUs), -O3", typed.cell(), unchecked.cell(),
         h.ratio(typed.median, unchecked.median)],
        ["one TU: `#include <safegi/typed.hpp>` vs GLM only, -fsyntax-only", typed_tu.cell(), glm_tu.cell(),
         h.ratio(typed_tu.median, glm_tu.median)],
    ]
    return h.table(["what is compiled", "typed (s)", "unchecked / GLM (s)", "ratio"], rows)


def main() -> None:
    with tempfile.TemporaryDirectory() as tmp_name:
        tmp = Path(tmp_name)
        rows = [compare_scene(*case, tmp) for case in CASES]
        compile_table = compile_cost(tmp)
    mode = "quick mode" if h.quick() else "full mode"
    text = f"""## Table 1, redone: the cost of checking (CPU renderer)

Measured by `bench/table1/run.py` ({mode}; {h.machine_line()}).
Images: exact float comparison of PFM output. Instructions: callgrind inside `safegi::render::render`, 1 thread,
{'32×32, 2 spp' if h.quick() else '64×64, 4 spp'}. Wall time: 2 threads,
{'64×64, 4 spp, 2' if h.quick() else '256×256, 16 spp, 5'} interleaved runs each, seconds, median (min–max).
The target is an instruction-count ratio within 0.1 % of 1 and bit-identical images.

""" + h.table(["scene", "feature", "identical image", "instructions typed", "instructions unchecked",
               "ratio", "wall typed (s)", "wall unchecked (s)", "ratio"], rows) + """
### Compile-time cost of the checks

""" + compile_table
    h.write_section("table1", text)


if __name__ == "__main__":
    main()
