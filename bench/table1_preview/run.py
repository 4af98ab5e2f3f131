#!/usr/bin/env python3
"""Table 1 of the SafeGI paper, redone for the GL preview's host code.

`safegi-preview` (runtime_gl and the typed library checked) against
`safegi-preview-unchecked` (plain floats), built from one source, compared by
  * image identity (exact floats, PFM),
  * instructions executed in the program's own code inside Preview::render
    (callgrind; the GL driver, LLVM's JIT and libc are left out: they run the
    same for both and would hide the host's difference),
  * whole-process wall time (interleaved runs, median (min–max)) and its ratio.
A section of its own (after bench/table1's) so that either can be re-run alone.
"""
from __future__ import annotations

import filecmp
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lib"))
import harness as h  # noqa: E402

# The GL preview host: the preview's own code (its executable, with runtime_gl and
# the renderer's scene code linked in statically) inside Preview::render, i.e.
# without the GL driver (Mesa, LLVM), libc and start-up (shader compilation).
PREVIEW_FUNCTION = "safegi::preview::Preview::render*"
# (row label, scene file relative to the repository)
PREVIEW_CASES = [
    ("point light, cube shadow map", "preview/scenes/cornell-point-light.json"),
    ("Phong, point + area light", "examples/scenes/phong.json"),
    ("motion blur", "examples/scenes/motion-blur.json"),
]


def preview_command(program: str, scene: str, size: str, light_samples: int, passes: int, output: Path,
                    frames: int = 1) -> list[str]:
    return [str(h.binary(program)), str(h.ROOT / scene), "--resolution", size, "--light-samples", str(light_samples),
            "--time-samples", str(passes), "--frames", str(frames), "--platform", "osmesa", "--pfm",
            "-o", f"{output}.exr"]


def compare_preview(label: str, scene: str, tmp: Path) -> list[str]:
    quick = h.quick()
    # llvmpipe single-threaded under callgrind: its threads would only add driver code.
    size, samples, passes = ("32x24", 1, 2) if quick else ("64x48", 2, 4)
    counts, outputs = {}, {}
    for name, program in (("typed", "safegi-preview"), ("unchecked", "safegi-preview-unchecked")):
        outputs[name] = tmp / f"preview-{name}"
        command = preview_command(program, scene, size, samples, passes, outputs[name])
        counts[name] = h.instructions_in_object(command, PREVIEW_FUNCTION, h.binary(program), {"LP_NUM_THREADS": "0"})
    identical = filecmp.cmp(f"{outputs['typed']}.pfm", f"{outputs['unchecked']}.pfm", shallow=False)
    size, repeats, frames = ("64x48", 2, 2) if quick else ("256x192", 5, 10)
    timed = {name: preview_command(program, scene, size, 4, 4, tmp / f"pt-{name}", frames)
             for name, program in (("typed", "safegi-preview"), ("unchecked", "safegi-preview-unchecked"))}
    times = h.interleaved(timed, repeats)
    return [label, "yes" if identical else "**NO**", f"{counts['typed']:,}", f"{counts['unchecked']:,}",
            h.ratio(counts["typed"], counts["unchecked"]), times["typed"].cell(), times["unchecked"].cell(),
            h.ratio(times["typed"].median, times["unchecked"].median)]


def preview_table(tmp: Path) -> str:
    try:
        h.binary("safegi-preview")
        h.binary("safegi-preview-unchecked")
    except SystemExit:
        return "Not measured: this build has no `safegi-preview` (configure with `-DSAFEGI_BUILD_GL=ON`).\n"
    cases = PREVIEW_CASES[:1] if h.quick() else PREVIEW_CASES
    rows = [compare_preview(label, scene, tmp) for label, scene in cases]
    quick = h.quick()
    return f"""`safegi-preview` (typed host: runtime_gl and the typed library checked) against
`safegi-preview-unchecked` (plain floats), one source, OSMesa/llvmpipe. Images: exact float comparison of PFM
output. Instructions: callgrind, only those executed in the program's own code (the executable: preview,
runtime_gl, scene code; not Mesa, LLVM or libc) inside `Preview::render`, llvmpipe single-threaded,
{'32×24, 2 passes × 1' if quick else '64×48, 4 passes × 2'} area samples. Wall time: whole process
({'64×48, 2 frames, 2' if quick else '256×192, 10 frames, 5'} interleaved runs), 4 passes × 4 area samples,
seconds, median (min–max).

""" + h.table(["scene", "identical image", "host instructions typed", "host instructions unchecked", "ratio",
               "wall typed (s)", "wall unchecked (s)", "ratio"], rows)


def main() -> None:
    machine = h.machine_line()
    with tempfile.TemporaryDirectory() as tmp_name:
        table = preview_table(Path(tmp_name))
    mode = "quick mode" if h.quick() else "full mode"
    text = f"""### Table 1, the GL preview host

Measured by `bench/table1_preview/run.py` ({mode}; {machine}).
""" + table
    h.write_section("table1_preview", text)


if __name__ == "__main__":
    main()
