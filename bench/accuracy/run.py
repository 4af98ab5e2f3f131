#!/usr/bin/env python3
"""The speed/accuracy trade: error against time for the renderer's settings.

For each scene, every setting is rendered at increasing samples per pixel and
compared with a converged reference (the average of two independent renders
at REF_SPP/2 samples each, cached under build/bench-cache/accuracy/ keyed by
scene, size, commit and renderer binary). The error is the relative RMSE of
bench/renderer/image_compare.cpp with the reference's own noise removed
(measured from the difference of its two halves). Time is the render's CPU
seconds from `--stats` (process CPU minus the start-up CPU measured in the same
run), one thread, plus its wall seconds.

Also: the GL preview's error against the CPU renderer's `direct` reference at
increasing area-light samples, and the `--time-budget` mode's error on the
Cornell box at 1, 10 and 60 seconds.
"""
from __future__ import annotations

import json
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lib"))
import harness as h  # noqa: E402
import images  # noqa: E402
import plot  # noqa: E402

SCENES = h.ROOT / "examples" / "scenes"
CORNELL = "cornell-box/cornell-box.json"
# (label, scene file, full-mode size): about 4000 pixels, the scene's aspect.
CASES = [("Cornell box", CORNELL, (64, 64)), ("Phong", "phong.json", (100, 40)),
         ("many lights", "many-lights.json", (80, 60))]


def quick_size(size: tuple[int, int]) -> tuple[int, int]:
    return (max(4, size[0] // 4), max(4, size[1] // 4))


REF_SPP = 256 if h.quick() else 16384
SPPS = [1, 4, 16] if h.quick() else [1, 4, 16, 64, 256, 1024]
PREVIEW_SAMPLES = [1, 4] if h.quick() else [1, 4, 16, 64, 256]
PREVIEW_PASSES = 16
BUDGETS = [0.5] if h.quick() else [1.0, 10.0, 60.0]


@dataclass
class Point:
    spp: int
    cpu: float
    wall: float
    error: float


def run_json(command: list[str]) -> dict:
    result = subprocess.run(command, check=True, capture_output=True, text=True)
    return json.loads(result.stdout.strip().splitlines()[-1])


def renderer_help() -> str:
    return subprocess.run([str(h.binary("safegi-render")), "--help"], capture_output=True, text=True).stdout


def render(scene: str, size, spp: int, extra: list[str], output: Path, threads: int = 1, seed: int = 1) -> dict:
    return run_json([str(h.binary("safegi-render")), str(SCENES / scene), *extra, "--resolution", f"{size[0]}x{size[1]}",
                     "--spp", str(spp), "--threads", str(threads), "--seed", str(seed), "-q", "--pfm", "--stats",
                     "-o", str(output)])


def startup_cpu(tmp: Path) -> float:
    """Process CPU seconds of a 1×1, 1-spp render: loading, OpenImageIO, exit."""
    return statistics.median(render(CORNELL, (1, 1), 1, [], tmp / "startup")["cpu_seconds"] for _ in range(3))


def cache_key(scene: str) -> str:
    """The last commit that changed the renderer or the scene ('-dirty' when either
    has uncommitted changes): a converged reference depends on nothing else."""
    paths = ["cpu_renderer", str(Path("examples/scenes") / scene)]
    git = ["git", "-C", str(h.ROOT)]
    commit = subprocess.run([*git, "log", "-1", "--format=%h", "--", *paths], capture_output=True,
                            text=True).stdout.strip() or "unknown"
    dirty = subprocess.run([*git, "status", "--porcelain", "--", *paths], capture_output=True, text=True).stdout
    return commit + ("-dirty" if dirty.strip() else "")


@dataclass
class Reference:
    image: images.Image
    noise_mse: float  # the reference's own relative MSE, removed from every error

    @property
    def noise(self) -> float:
        return math.sqrt(self.noise_mse)


def reference(scene: str, size, integrator: str) -> Reference:
    directory = h.build_dir() / "bench-cache" / "accuracy"
    directory.mkdir(parents=True, exist_ok=True)
    stem = f"{Path(scene).stem}-{integrator}-{size[0]}x{size[1]}-{REF_SPP}spp-{cache_key(scene)}"
    halves = [directory / f"{stem}-{half}" for half in ("a", "b")]
    for seed, half in enumerate(halves, start=1001):
        if not half.with_suffix(".pfm").exists():
            render(scene, size, REF_SPP // 2, ["--integrator", integrator], half, threads=os.cpu_count() or 1,
                   seed=seed)
    a, b = (images.read_pfm(half.with_suffix(".pfm")) for half in halves)
    image = images.average([a, b])
    return Reference(image, images.half_difference_mse(a, b, image))


def render_cpu(stats: dict, startup: float) -> float:
    """CPU seconds of the render alone: `render_cpu_seconds` where --stats has it,
    else the process's CPU minus the start-up measured in this run."""
    if "render_cpu_seconds" in stats:
        return max(stats["render_cpu_seconds"], 1e-3)
    return max(stats["cpu_seconds"] - startup, 1e-3)


def sweep(scene: str, size, extra: list[str], ref: Reference, startup: float, tmp: Path) -> list[Point]:
    points = []
    for spp in SPPS:
        stats = render(scene, size, spp, extra, tmp / "sweep")
        image = images.read_pfm(tmp / "sweep.pfm")
        points.append(Point(spp, render_cpu(stats, startup), stats["seconds"],
                            images.corrected_rmse(image, ref.image, ref.noise_mse)))
    return points


def comparison_groups(help_text: str) -> tuple[dict[str, dict[str, list[str]]], list[str]]:
    """Settings compared with each other, by group; and the knobs this build lacks.
    Every group's default setting is the plain path tracer, rendered once."""
    path = ["--integrator", "path"]
    groups = {"direct vs path": {"path": path, "direct": ["--integrator", "direct"]}}
    missing = []
    if "--mis" in help_text:
        groups["MIS"] = {"MIS on (default)": path, "MIS off": [*path, "--mis", "off"]}
    else:
        missing.append("`--mis on|off`")
    if "--light-samples" in help_text:
        groups["light samples"] = {"1 light sample (default)": path,
                                   **{f"{n} light samples": [*path, "--light-samples", str(n)] for n in (4, 16)}}
    else:
        missing.append("`--light-samples N`")
    if "--rr-depth" in help_text:
        groups["Russian roulette"] = {"RR off": [*path, "--rr", "off"],
                                      "RR from bounce 1": [*path, "--rr-depth", "1"],
                                      "RR from bounce 3 (default)": path,
                                      "RR from bounce 8": [*path, "--rr-depth", "8"]}
    else:
        missing.append("`--rr on|off`, `--rr-depth N`")
    return groups, missing


def log_interpolate(points: list[tuple[float, float]], x: float) -> float | None:
    """y at x on the polyline through points, linear in log x and log y."""
    points = sorted(points)
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        if x0 <= x <= x1 and x0 > 0 and y0 > 0 and y1 > 0:
            if x1 == x0:
                return y0
            s = (math.log(x) - math.log(x0)) / (math.log(x1) - math.log(x0))
            return math.exp(math.log(y0) + s * (math.log(y1) - math.log(y0)))
    return None


def time_to_error(points: list[Point], error: float) -> float | None:
    """The first time the curve reaches `error` (errors fall, apart from noise)."""
    ordered = sorted(points, key=lambda p: p.cpu)
    for p0, p1 in zip(ordered, ordered[1:]):
        if p0.error >= error >= p1.error and p0.error > 0 and p1.error > 0 and p0.error != p1.error:
            s = (math.log(p0.error) - math.log(error)) / (math.log(p0.error) - math.log(p1.error))
            return math.exp(math.log(p0.cpu) + s * (math.log(p1.cpu) - math.log(p0.cpu)))
    return ordered[0].cpu if ordered and ordered[0].error <= error else None


def winners(curves: dict[str, list[Point]]) -> str:
    """Equal time: the least error at the longest time every setting reached.
    Equal error: the least time to the smallest error every setting reached."""
    if len(curves) < 2:
        return "—"
    common_time = min(max(p.cpu for p in points) for points in curves.values())
    at_time = {name: log_interpolate([(p.cpu, p.error) for p in points], common_time)
               for name, points in curves.items()}
    at_time = {k: v for k, v in at_time.items() if v is not None}
    common_error = max(min(p.error for p in points) for points in curves.values())
    to_error = {name: time_to_error(points, common_error) for name, points in curves.items()}
    to_error = {k: v for k, v in to_error.items() if v is not None}
    parts = []
    if len(at_time) >= 2:
        best = min(at_time, key=at_time.get)
        rest = ", ".join(f"{k} {v:.4f}" for k, v in at_time.items() if k != best)
        parts.append(f"equal time ({common_time:.3g} CPU s): {verdict(best, at_time)} (error {at_time[best]:.4f}; {rest})")
    if len(to_error) >= 2:
        best = min(to_error, key=to_error.get)
        rest = ", ".join(f"{k} {v:.3g} s" for k, v in to_error.items() if k != best)
        parts.append(f"equal error ({common_error:.4f}): {verdict(best, to_error)} ({to_error[best]:.3g} CPU s; {rest})")
    return "; ".join(parts) or "—"


# CPU times on the shared machine vary by several per cent from run to run, and
# the error of one render by as much; a lead smaller than this is not a result.
TIE = 1.10


def verdict(best: str, values: dict[str, float]) -> str:
    runner_up = min(v for k, v in values.items() if k != best)
    if runner_up < TIE * values[best]:
        close = [k for k, v in values.items() if v < TIE * values[best]]
        return "tie (within 10 %): " + ", ".join(f"**{k}**" for k in close)
    return f"**{best}**"


def image_dir() -> Path:
    return h.ROOT / ("out/bench/img" if h.quick() else "docs/img")


def image_link(path: Path) -> str:
    """The image's link from the report: docs/benchmarks.md, or out/bench/benchmarks.md in quick mode."""
    return f"img/{path.name}"


def scene_section(label: str, scene: str, size, groups, startup: float, tmp: Path) -> str:
    size = quick_size(size) if h.quick() else size
    ref = reference(scene, size, "path")
    runs: dict[tuple[str, ...], list[Point]] = {}
    curves: dict[str, dict[str, list[Point]]] = {}
    for group, settings in groups.items():
        curves[group] = {}
        for name, extra in settings.items():
            key = tuple(extra)
            if key not in runs:
                runs[key] = sweep(scene, size, extra, ref, startup, tmp)
            curves[group][name] = runs[key]
    slug = Path(scene).stem
    # One curve per distinct render: every group's default is the same plain path tracer.
    series: dict[str, list[tuple[float, float]]] = {}
    plotted_runs: set[int] = set()
    for settings in curves.values():
        for name, points in settings.items():
            if id(points) not in plotted_runs:
                plotted_runs.add(id(points))
                series["path (defaults)" if name == "path" else name] = [(p.cpu, p.error) for p in points]
    plotted = plot.loglog(image_dir() / f"accuracy-{slug}.png", f"{label}, {size[0]}x{size[1]}", series)
    rows = []
    for group, settings in curves.items():
        for name, points in settings.items():
            rows.append([group, name] + [f"{p.error:.4f} ({p.cpu:.3g} s)" for p in points])
    text = f"### {label} ({size[0]}×{size[1]}; reference {REF_SPP} spp path, its own noise {ref.noise:.4f})\n\n"
    if plotted:
        text += f"![error against CPU time, {label}]({image_link(image_dir() / f'accuracy-{slug}.png')})\n\n"
    text += "Relative RMSE (CPU seconds of the render) at " + ", ".join(str(s) for s in SPPS) + " spp:\n\n"
    text += h.table(["group", "setting", *[f"{s} spp" for s in SPPS]], rows)
    text += "\nWinners:\n\n" + "".join(f"* {group}: {winners(settings)}\n" for group, settings in curves.items())
    walls = [p.wall for settings in curves.values() for points in settings.values() for p in points]
    cpus = [p.cpu for settings in curves.values() for points in settings.values() for p in points]
    text += (f"\nWall seconds of the same renders: {sum(walls):.1f} in all against {sum(cpus):.1f} CPU seconds "
             f"(the machine is shared; one thread each).\n")
    return text


def preview_frame_cpu(stderr: str) -> float | None:
    """CPU seconds per frame from `safegi-preview --stats` (llvmpipe's threads included)."""
    match = re.search(r"process CPU time per frame: median ([0-9.]+) ms", stderr)
    return float(match.group(1)) / 1000 if match else None


def preview_section(tmp: Path, measured: str) -> str:
    try:
        preview = h.binary("safegi-preview")
    except SystemExit:
        return "## GL preview against the CPU renderer\n\nNot measured: this build has no `safegi-preview` (configure with `-DSAFEGI_BUILD_GL=ON`).\n"
    size = quick_size((64, 64)) if h.quick() else (64, 64)
    ref = reference(CORNELL, size, "direct")
    rows, points = [], []
    # More passes at the end: they separate the anti-aliasing part of the bias from the shadow maps'.
    runs = [(PREVIEW_PASSES, n) for n in PREVIEW_SAMPLES] + ([] if h.quick() else [(64, 16), (256, 4)])
    for passes, samples in runs:
        out = tmp / "preview"
        command = [str(preview), str(SCENES / CORNELL), "--resolution", f"{size[0]}x{size[1]}",
                   "--light-samples", str(samples), "--time-samples", str(passes), "--pfm", "--stats",
                   "-o", str(out) + ".exr"]
        start = time.perf_counter()
        before = os.times()
        result = subprocess.run(command, check=True, capture_output=True, text=True)
        after = os.times()
        wall = time.perf_counter() - start
        cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
        frame_cpu = preview_frame_cpu(result.stderr)
        image = images.read_pfm(out.with_suffix(".pfm"))
        error = images.corrected_rmse(image, ref.image, ref.noise_mse)
        ratio = images.mean_ratio(image, ref.image)
        if passes == PREVIEW_PASSES:
            points.append((cpu, error))
        rows.append([str(passes), str(samples), str(samples * passes), f"{error:.4f}", f"{ratio:.4f}", f"{cpu:.2f}",
                     f"{wall:.2f}", f"{frame_cpu:.3f}" if frame_cpu is not None else "—"])
    plot.loglog(image_dir() / "accuracy-preview.png", f"GL preview vs CPU direct, Cornell box {size[0]}x{size[1]}",
                {"preview": points}, xlabel="process CPU seconds")
    floor = min(e for _, e in points)
    text = f"""## GL preview against the CPU renderer (Cornell box, {size[0]}×{size[1]})

{measured}
`safegi-preview --time-samples {PREVIEW_PASSES} --light-samples N` (OSMesa/llvmpipe) against the CPU
renderer's converged `direct` image ({REF_SPP} spp, its own noise {ref.noise:.4f}): the preview computes
direct lighting only. Time is the whole process's CPU time (GL start-up and shader compilation
included, llvmpipe's threads included).

![preview error against CPU time]({image_link(image_dir() / 'accuracy-preview.png')})

"""
    text += h.table(["passes", "area samples per pass", "samples per pixel", "relative RMSE", "mean ratio preview/CPU",
                     "process CPU s", "wall s", "frame CPU s (--stats)"], rows)
    text += (f"\nWith {PREVIEW_PASSES} passes the error stops falling at about {floor:.3f}: that is the preview's "
             f"bias, not noise — shadow maps' resolution and bias, and edge anti-aliasing from only {PREVIEW_PASSES} "
             f"sub-pixel positions (docs/preview.md); the rows with more passes show how much of it is the "
             f"anti-aliasing. The mean ratio says the overall brightness agrees.\n")
    return text


def budget_section(tmp: Path, measured: str) -> str:
    """Error reached by --time-budget on the Cornell box at its own size.
    Two independent runs per budget: for an unbiased estimator the error of
    run A against the converged image is estimated from A − B."""
    size = (128, 128) if h.quick() else (512, 512)
    threads = os.cpu_count() or 1
    rows = []
    for budget in BUDGETS:
        runs = []
        for seed in (11, 12):
            out = tmp / f"budget{seed}"
            stats = run_json([str(h.binary("safegi-render")), str(SCENES / CORNELL), "--resolution",
                              f"{size[0]}x{size[1]}", "--time-budget", str(budget), "--threads", str(threads),
                              "--seed", str(seed), "-q", "--pfm", "--stats", "-o", str(out)])
            runs.append((stats, images.read_pfm(out.with_suffix(".pfm"))))
        (sa, a), (sb, b) = runs
        mean = images.average([a, b])
        difference = images.half_difference_mse(a, b, mean) * 4  # E[(a-b)^2 / ...] = err_a^2 + err_b^2
        spp_a, spp_b = sa["spp"], sb["spp"]
        error_a = math.sqrt(difference * (1 / spp_a) / (1 / spp_a + 1 / spp_b))
        render_cpu_a = sa.get("render_cpu_seconds")
        rows.append([f"{budget:g}", str(sa.get("threads", threads)), f"{spp_a}, {spp_b}", f"{sa['seconds']:.2f}",
                     f"{render_cpu_a:.2f}" if render_cpu_a is not None else "—", f"{sa['cpu_seconds']:.2f}",
                     f"{error_a:.4f}"])
    return f"""## `--time-budget` on the Cornell box ({size[0]}×{size[1]}, path)

{measured}
`safegi-render cornell-box.json --time-budget T --threads {threads}`, run twice with different seeds; the
error of the first run is estimated from the difference of the two (an unbiased estimator's error against
the converged image; the bias check is the 64×64 sweep above). With two threads on a machine shared with
other builds, the budget buys fewer samples than on an idle machine: the CPU seconds say how much of it the
render got.

""" + h.table(["budget (s)", "threads", "spp reached (run A, B)", "render wall s (A)", "render CPU s (A)",
               "process CPU s (A)", "relative RMSE (A)"], rows)


def main() -> None:
    # Optional arguments pick parts (scene file stems, "preview", "budget"); each part
    # writes its own section (accuracy, accuracy_preview, accuracy_budget), so one part
    # can be re-run alone and spliced into the report (bench/run-all.sh --only).
    only = set(sys.argv[1:])
    wanted = lambda name: not only or name in only  # noqa: E731
    groups, missing = comparison_groups(renderer_help())
    mode = "quick mode" if h.quick() else "full mode"
    with tempfile.TemporaryDirectory() as tmp_name:
        tmp = Path(tmp_name)
        startup = startup_cpu(tmp)
        load = h.machine_line()
        scenes = [scene_section(label, scene, size, groups, startup, tmp) for label, scene, size in CASES
                  if wanted(Path(scene).stem)]
        measured = f"Measured by `bench/accuracy/run.py` ({mode}; {load})."
        if wanted("preview"):
            h.write_section("accuracy_preview", preview_section(tmp, measured))
        if wanted("budget"):
            h.write_section("accuracy_budget", budget_section(tmp, measured))
    if not scenes:
        return
    note = ""
    if missing:
        note = ("\nNot compared in this build: " + ", ".join(missing) +
                " (renderer options not in this `safegi-render`).\n")
    text = f"""## The speed/accuracy trade

{measured} Relative RMSE = sqrt(mean of (v − r)² / (r² + 0.01)) against a
converged reference (cached in `build/bench-cache/accuracy/`), with the reference's own noise removed. Time:
CPU seconds of the render from `--stats` (`render_cpu_seconds`; the process's start-up, {startup:.2f} CPU s in
this run, is left out), one thread; the machine is shared with other builds, so CPU time is the figure to
compare, wall time is listed beside it. Direct lighting is compared with the *path-traced* reference: its
error levels off at its bias (the missing indirect light). Equal-time winner: the least error at the longest
time all settings of a group reached; equal-error winner: the least time to the smallest error all settings
reached (log–log interpolation); a lead under 10 % is called a tie (CPU time on a shared machine and
the error of one render both vary by a few per cent). The GL preview and `--time-budget` follow in their
own sections.
{note}
""" + "\n".join(scenes)
    h.write_section("accuracy", text)


if __name__ == "__main__":
    main()
