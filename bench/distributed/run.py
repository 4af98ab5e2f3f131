#!/usr/bin/env python3
"""Strong scaling of distributed safegi-render: 1, 2 and 4 MPI ranks.

The Cornell box at a fixed size and sample count, rendered by one process
(1 and 2 threads, the baselines) and by `mpirun -np N safegi-render
--threads 1` for N = 1, 2, 4, interleaved (A B C … A B C …), each a few
times. Reported per configuration (medians, with min–max for wall times):
the job's wall time (mpirun and process start-up included), the render's
wall time (`seconds` of --stats: rank 0, from the render's start until the
image is gathered), the render CPU time summed over ranks
(`render_cpu_seconds`) and that of the busiest rank
(`busiest_rank_render_cpu_seconds`), the whole job's CPU time (`cpu_seconds`:
every rank's process), the speed-up of the render's wall time over one rank
and its efficiency (speed-up / ranks), and the CPU speed-up: one rank's render
CPU time over the busiest rank's, the speed-up that one idle core per rank
would give (work split and duplicated work counted, waiting not), which a
loaded machine does not change. Every image is checked bit-identical (PFM)
to the single process's.

The machine has 2 cores: 4 ranks oversubscribe it, and on a machine shared
with other builds the wall times mostly measure the others (the load average
is printed); CPU times stay meaningful.
"""
from __future__ import annotations

import filecmp
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lib"))
import harness as h  # noqa: E402

SCENE = h.ROOT / "examples" / "scenes" / "cornell-box" / "cornell-box.json"
# Open MPI on this machine only: shared memory and loopback, more ranks than
# cores, as root (docs/cpu-renderer.md, "Distributed rendering").
LOCAL_OPEN_MPI = {
    "OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
    "OMPI_MCA_rmaps_base_oversubscribe": "1", "OMPI_MCA_btl": "self,vader",
    "OMPI_MCA_btl_vader_single_copy_mechanism": "none", "OMPI_MCA_pml": "ob1",
    "OMPI_MCA_oob_tcp_if_include": "lo", "OMPI_MCA_plm_rsh_agent": "",
}


def main() -> None:
    mpirun = shutil.which("mpirun")
    if mpirun is None:
        raise SystemExit("bench: mpirun is missing (scripts/install-deps.sh installs openmpi-bin)")
    size, spp, repeats = (64, 4, 1) if h.quick() else (256, 16, 3)
    render = str(h.binary("safegi-render"))
    common = [str(SCENE), "--resolution", f"{size}x{size}", "--spp", str(spp), "--integrator", "path",
              "--quiet", "--stats", "--pfm"]
    configurations = {
        "1 process, 1 thread": lambda out: [render, *common, "--threads", "1", "-o", out],
        "1 process, 2 threads": lambda out: [render, *common, "--threads", "2", "-o", out],
    }
    for ranks in (1, 2, 4):
        configurations[f"mpirun -np {ranks}, 1 thread each"] = (
            lambda out, ranks=ranks: [mpirun, "-np", str(ranks), "--bind-to", "none", render, *common,
                                      "--threads", "1", "-o", out])
    environment = {**os.environ, **{k: os.environ.get(k, v) for k, v in LOCAL_OPEN_MPI.items()}}

    load_start = os.getloadavg()[0]
    machine = h.machine_line()
    results: dict[str, list[dict]] = {name: [] for name in configurations}
    job_walls: dict[str, list[float]] = {name: [] for name in configurations}
    identical = {name: True for name in configurations}
    with tempfile.TemporaryDirectory() as tmp:
        reference = None
        for _ in range(repeats):
            for index, (name, command) in enumerate(configurations.items()):
                out = str(Path(tmp) / f"c{index}")
                start = time.perf_counter()
                run = subprocess.run(command(out), check=True, capture_output=True, text=True, env=environment)
                job_walls[name].append(time.perf_counter() - start)
                results[name].append(json.loads(run.stdout.strip().splitlines()[-1]))
                if reference is None:
                    reference = Path(tmp) / "reference.pfm"
                    shutil.copy(f"{out}.pfm", reference)
                identical[name] &= filecmp.cmp(f"{out}.pfm", reference, shallow=False)
    load_end = os.getloadavg()[0]

    def median(name: str, field: str) -> float:
        return statistics.median(r[field] for r in results[name])

    one_rank = median("mpirun -np 1, 1 thread each", "seconds")
    one_rank_cpu = median("mpirun -np 1, 1 thread each", "render_cpu_seconds")
    rows = []
    for name in configurations:
        stats = results[name][0]
        render_wall = [r["seconds"] for r in results[name]]
        workers = stats["ranks"] if name.startswith("mpirun") else stats["threads"]
        speedup = one_rank / statistics.median(render_wall)
        rows.append([
            name, f"{stats['ranks']} × {stats['threads'] // stats['ranks']}",
            h.Timing(job_walls[name]).cell(), h.Timing(render_wall).cell(),
            f"{median(name, 'render_cpu_seconds'):.3f}", f"{median(name, 'busiest_rank_render_cpu_seconds'):.3f}",
            f"{median(name, 'cpu_seconds'):.3f}", f"{speedup:.2f}", f"{speedup / workers:.2f}",
            f"{one_rank_cpu / median(name, 'busiest_rank_render_cpu_seconds'):.2f}" if name.startswith("mpirun")
            else "—",
            f"{median(name, 'rays_per_cpu_second') / 1e6:.2f} M", "yes" if identical[name] else "**NO**"])
    text = "## Distributed rendering: strong scaling over MPI ranks (Cornell box)\n\n"
    text += (f"Cornell box {size}×{size}, {spp} spp, path tracing (`bench/distributed/run.py`): one process "
             "(`safegi-render … --threads T`) and `mpirun -np N --bind-to none safegi-render … --threads 1` "
             f"with Debian's Open MPI on this machine (shared memory, loopback), {repeats} interleaved run(s) "
             "each, medians (min–max). *job wall*: the whole command, mpirun and start-up included; "
             "*render wall*: `seconds` of `--stats` (rank 0, render start until the image is gathered); "
             "*render CPU*: `render_cpu_seconds`, summed over ranks; *busiest rank*: the largest rank's "
             "render CPU time; *job CPU*: `cpu_seconds`, every process; "
             "*speed-up*: render wall of `mpirun -np 1` over this one; *efficiency*: speed-up per rank "
             "(per thread for one process); *CPU speed-up*: render CPU of `mpirun -np 1` over the busiest "
             "rank's, what one idle core per rank would give (load-independent). "
             f"{machine}; load average at the end {load_end:.2f}. "
             "**This machine has 2 cores**: 4 ranks oversubscribe it, so at best they match 2"
             + (" — and with the load above, wall times mostly measure the other processes; CPU times "
                "stay meaningful." if max(load_start, load_end) > 2.5 else ".") + "\n\n")
    text += h.table(["configuration", "ranks × threads", "job wall s", "render wall s", "render CPU s",
                     "busiest rank CPU s", "job CPU s", "speed-up", "efficiency", "CPU speed-up",
                     "rays per CPU-second", "image bit-identical"], rows)
    h.write_section("distributed", text)


if __name__ == "__main__":
    main()
