#!/usr/bin/env python3
"""The acceleration structure at scale: our BVH against Embree on the same rays,
and whole renders of the same meshes, from a thousand to ten million triangles.

    python3 bench/scale/run.py            # full: 1e3 … 1e7 triangles, both meshes
    SAFEGI_BENCH_QUICK=1 python3 bench/scale/run.py   # 1e3 … 1e5
    SAFEGI_PBRT=/path/to/pbrt python3 bench/scale/run.py   # adds pbrt-v3's renders

Part 1 (safegi-bench-scale, one process per mesh and size): BVH build time on
all cores, bytes per triangle, and rays per CPU-second on one thread for
camera, extension and shadow rays, with Embree tracing the same rays in the
same process when the program was built with it (Debian: libembree-dev, then
configure with -DSAFEGI_BENCH_EMBREE=ON).
Part 2: safegi-render on a pbrt-v3 scene of the height field under a quad
light (path tracing, depth 5), its rays per render CPU-second and peak memory;
with SAFEGI_PBRT, pbrt-v3 on the same file, back to back.
"""
from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lib"))
import harness as h  # noqa: E402
import plot  # noqa: E402

SIZES = [1_000, 10_000, 100_000] if h.quick() else [1_000, 10_000, 100_000, 1_000_000, 10_000_000]
MESHES = ["heightfield", "torus"]
RAY_SETS = ("camera", "extension", "shadow")
RESOLUTION = 256
THREADS = os.cpu_count() or 1

SCENE = """LookAt 2.2 -2.6 2.4  0 0 0  0 0 1
Camera "perspective" "float fov" [33.4]
Sampler "halton" "integer pixelsamples" [{spp}]
Integrator "path" "integer maxdepth" [5]
Film "image" "integer xresolution" [{resolution}] "integer yresolution" [{resolution}] "string filename" "{image}"
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [8 8 8]
  Shape "trianglemesh" "integer indices" [0 2 1 0 3 2]
    "point P" [-0.5 -0.5 1.5  0.5 -0.5 1.5  0.5 0.5 1.5  -0.5 0.5 1.5]
AttributeEnd
Material "matte" "rgb Kd" [0.6 0.6 0.6]
Shape "plymesh" "string filename" "{ply}"
WorldEnd
"""


def run_measured(command: list[str], cwd: Path) -> tuple[str, float, float, int]:
    """stdout, wall seconds, CPU seconds and peak RSS (KiB) of one child process."""
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        start = time.monotonic()
        process = subprocess.Popen(command, cwd=cwd, stdout=out, stderr=err, text=True)
        _, status, usage = os.wait4(process.pid, 0)  # reaped here, so its own usage is read
        wall = time.monotonic() - start
        out.seek(0)
        err.seek(0)
        if os.waitstatus_to_exitcode(status) != 0:
            raise SystemExit(f"bench: {' '.join(command)} failed:\n{err.read()[-2000:]}")
        return out.read(), wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss


def trace_sets(program: Path) -> list[dict]:
    results = []
    for mesh in MESHES:
        for size in SIZES:
            out = subprocess.run([str(program), "--mesh", mesh, "--triangles", str(size), "--resolution",
                                  str(RESOLUTION), "--threads", str(THREADS)], capture_output=True, text=True,
                                 check=True).stdout
            results.append(json.loads(out))
    return results


def renders(program: Path, tmp: Path) -> list[dict]:
    results = []
    pbrt = os.environ.get("SAFEGI_PBRT")
    for size in SIZES:
        spp = 4 if size >= 4_000_000 else (8 if h.quick() else 32)
        ply = tmp / f"heightfield-{size}.ply"
        subprocess.run([str(program), "--mesh", "heightfield", "--triangles", str(size), "--ply", str(ply)], check=True)
        scene = tmp / f"heightfield-{size}.pbrt"
        scene.write_text(SCENE.format(spp=spp, resolution=RESOLUTION, image=f"pbrt-{size}.exr", ply=ply.name))
        out, wall, _, _ = run_measured([str(h.binary("safegi-render")), str(scene), "--length-unit", "m",
                                        "--threads", str(THREADS), "-q", "--stats", "-o", str(tmp / f"ours-{size}")],
                                       tmp)
        stats = json.loads(out)
        row = {"triangles": size, "spp": spp, "ours_wall": wall, "ours_rays_per_cpu_second": stats["rays_per_cpu_second"],
               "ours_peak_mib": stats["peak_memory_kib"] / 1024}
        if pbrt:
            out, wall, cpu, peak = run_measured([pbrt, "--nthreads", str(THREADS), scene.name], tmp)
            traced = sum(int(n) for n in re.findall(r"(?:Regular|Shadow) ray intersection tests\s+(\d+)", out))
            compared = subprocess.run([str(h.binary("safegi-image-compare")), str(tmp / f"ours-{size}.exr"),
                                       str(tmp / f"pbrt-{size}.exr")], capture_output=True, text=True, check=True)
            row.update({"pbrt_wall": wall, "pbrt_rays_per_cpu_second": traced / cpu if traced else None,
                        "pbrt_peak_mib": peak / 1024,
                        "mean_ratio": json.loads(compared.stdout)["mean_ratio"][0]})
        results.append(row)
    return results


def million(x: float) -> str:
    return f"{x / 1e6:.2f} M"


def main() -> None:
    load = h.machine_line()
    program = h.binary("safegi-bench-scale")
    traced = trace_sets(program)
    with_embree = "embree_build_seconds" in traced[0]
    with tempfile.TemporaryDirectory() as directory:
        rendered = renders(program, Path(directory))

    header = ["mesh", "triangles", "build s (ours / Embree)", "bytes per triangle (ours / Embree)"]
    for ray_set in RAY_SETS:
        header.append(f"{ray_set}: rays per CPU-s (ours / Embree, ratio)")
    rows = []
    for r in traced:
        row = [r["mesh"], f"{r['triangles']:,}",
               f"{r['ours_build_seconds']:.3f}" + (f" / {r['embree_build_seconds']:.3f}" if with_embree else ""),
               f"{r['ours_bytes_per_triangle']:.0f}" + (f" / {r['embree_bytes_per_triangle']:.0f}" if with_embree else "")]
        for ray_set in RAY_SETS:
            s = r[ray_set]
            cell = million(s["ours_rays_per_cpu_second"])
            if with_embree:
                cell += f" / {million(s['embree_rays_per_cpu_second'])}, " \
                        f"{s['ours_rays_per_cpu_second'] / s['embree_rays_per_cpu_second']:.2f}"
                if s["disagreements"]:
                    cell += f" ({s['disagreements']} of {s['rays']} rays disagree)"
            row.append(cell)
        rows.append(row)

    image = h.ROOT / ("out/bench/img" if h.quick() else "docs/img") / "scale-rays.png"
    series = {}
    for mesh in MESHES:
        mine = [r for r in traced if r["mesh"] == mesh]
        series[f"ours, {mesh}"] = [(r["triangles"], r["extension"]["ours_rays_per_cpu_second"]) for r in mine]
        if with_embree:
            series[f"Embree, {mesh}"] = [(r["triangles"], r["extension"]["embree_rays_per_cpu_second"]) for r in mine]
    plotted = plot.loglog(image, "Extension rays per CPU-second by mesh size", series, xlabel="triangles",
                          ylabel="rays per CPU-second")

    text = f"""## The renderer at scale: BVH against Embree, 1e3 … 1e7 triangles

Measured by `bench/scale/run.py` ({'quick mode' if h.quick() else 'full mode'}; {load}).
`safegi-bench-scale` generates each mesh in memory (a height field; a closed, rippled torus), builds our
BVH as the renderer does (`PrimitiveSet`, {THREADS} threads) and {'Embree 3 (`rtcCommitScene`, same threads)' if with_embree else 'no Embree (not built with it)'}
over the same triangles, then traces on one thread, through both, the same {RESOLUTION}² camera rays, one
cosine-distributed bounce from each camera hit (extension) and one ray from each hit to a point on a quad
light (shadow; any hit). Rays per CPU-second is that thread's CPU time. Bytes per triangle: what each
structure holds for tracing (ours: triangle blocks with their shape and face indices, nodes; Embree: its memory monitor's peak).
"Disagree" counts rays where the two report a hit against a miss or distances apart by more than 1e-4
(relative): grazing hits on shared edges.

"""
    if plotted:
        text += "![extension rays per CPU-second against triangles](img/scale-rays.png)\n\n"
    text += h.table(header, rows)
    if with_embree:
        largest = {mesh: max(r["triangles"] for r in traced if r["mesh"] == mesh) for mesh in MESHES}
        million_rows = [r for r in traced if 500_000 <= r["triangles"] <= 2_000_000] or traced
        ratios = [r[s]["ours_rays_per_cpu_second"] / r[s]["embree_rays_per_cpu_second"]
                  for r in million_rows for s in RAY_SETS]
        builds = [r["ours_build_seconds"] / r["embree_build_seconds"] for r in traced
                  if r["triangles"] == largest[r["mesh"]]]
        memory = [r["ours_bytes_per_triangle"] / r["embree_bytes_per_triangle"] for r in traced]
        text += (f"\n* Around {million_rows[0]['triangles']:,} triangles ours traces {min(ratios):.2f}–{max(ratios):.2f}× "
                 f"Embree's rays per CPU-second (all three sets, both meshes; ours: eight-wide nodes, each one AVX2 "
                 f"test of a ray against its eight boxes where the CPU has AVX2 and two SSE tests elsewhere, a leaf's "
                 f"blocks of four triangles filtered two at a time with AVX2 (one at a time with SSE), each triangle "
                 f"kept re-tested in double; Embree 3: its AVX2 kernels, eight-wide nodes).\n"
                 f"* Build at {max(largest.values()) / 1e6:.0f} M triangles: {min(builds):.2f}–{max(builds):.2f}× Embree's time on the same "
                 f"threads; memory per triangle {min(memory):.2f}–{max(memory):.2f}× Embree's.\n")
    render_header = ["triangles", "spp", "ours: rays per render CPU-s", "ours: peak MiB", "ours: wall s"]
    pbrt = any("pbrt_wall" in r for r in rendered)
    if pbrt:
        render_header += ["pbrt-v3: rays per CPU-s", "pbrt-v3: peak MiB", "pbrt-v3: wall s", "ours / pbrt-v3: rays per CPU-s",
                          "peak memory", "image mean"]
    render_rows = []
    for r in rendered:
        row = [f"{r['triangles']:,}", str(r["spp"]), million(r["ours_rays_per_cpu_second"]),
               f"{r['ours_peak_mib']:.0f}", f"{r['ours_wall']:.2f}"]
        if pbrt:
            rays = r.get("pbrt_rays_per_cpu_second")
            row += [million(rays) if rays else "—", f"{r['pbrt_peak_mib']:.0f}", f"{r['pbrt_wall']:.2f}",
                    f"{r['ours_rays_per_cpu_second'] / rays:.2f}×" if rays else "—",
                    f"{r['ours_peak_mib'] / r['pbrt_peak_mib']:.2f}×", f"{r['mean_ratio']:.4f}"]
        render_rows.append(row)
    text += (f"\nWhole renders: `safegi-render` on a pbrt-v3 file of the height field under a quad light, "
             f"{RESOLUTION}², path tracing to depth 5, {THREADS} threads (render CPU includes the BVH build, which "
             f"dominates the 4 spp render of the largest mesh; no image is read, so OpenImageIO is not loaded)"
             + (", and pbrt-v3 (`SAFEGI_PBRT`) on the same file, back to back. pbrt-v3's rays are its"
                " 'Regular' and 'Shadow ray intersection tests' over its whole process's CPU time (parsing and"
                " BVH included), ours over the render's (BVH included, import not); 'image mean' is ours over"
                " pbrt-v3's mean pixel value" if pbrt else
                "; pbrt-v3's columns appear when `SAFEGI_PBRT` names its binary") + ":\n\n")
    text += h.table(render_header, render_rows)
    h.write_section("scale", text)


if __name__ == "__main__":
    main()
