#!/usr/bin/env python3
"""What a safeglslc check costs beside a glslangValidator -V run of the same shader,
one process each, as users run them (docs/benchmarks.md, "Check cost per shader").

    bench/frontend/check_cost.py build-dev/bin/safeglslc SHADER [-D NAME=VALUE ...] [-I DIR ...]

Counts instructions with callgrind (valgrind must be installed), which a loaded
machine does not move, and also reports CPU seconds over repeated runs. The
check is `safeglslc SHADER` (no -o, --symbols or SPIR-V: nothing rendered);
glslangValidator writes SPIR-V for Vulkan 1.2, as a build would ask of it.
"""
from __future__ import annotations

import argparse
import os
import re
import resource
import subprocess
import sys
import tempfile


def instructions(command: list[str]) -> int:
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "callgrind.out")
        run = subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", *command],
                             capture_output=True, text=True)
        found = re.search(r"I\s+refs:\s+([\d,]+)", run.stderr)
        if not found:
            sys.exit(f"callgrind gave no count for {command[0]}:\n{run.stderr[-2000:]}")
        return int(found.group(1).replace(",", ""))


def cpu_seconds(command: list[str], runs: int) -> float:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    for _ in range(runs):
        subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime) / runs


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("safeglslc")
    parser.add_argument("shader")
    parser.add_argument("-D", action="append", default=[], help="a macro, NAME or NAME=VALUE")
    parser.add_argument("-I", action="append", default=[], help="an include directory")
    parser.add_argument("--runs", type=int, default=20, help="runs for the CPU-time figure")
    args = parser.parse_args()
    flags = [f"-D{d}" for d in args.D] + [f"-I{i}" for i in args.I]
    with tempfile.TemporaryDirectory() as folder:
        ours = [args.safeglslc, "-w", *flags, args.shader]
        theirs = ["glslangValidator", "-V", "--target-env", "vulkan1.2", *flags, "-o",
                  os.path.join(folder, "out.spv"), args.shader]
        if subprocess.run(theirs, capture_output=True).returncode != 0:
            sys.exit("glslangValidator rejects the shader with these flags")
        if subprocess.run(ours, capture_output=True).returncode != 0:
            sys.exit("safeglslc rejects the shader with these flags")
        i_ours, i_theirs = instructions(ours), instructions(theirs)
        c_ours, c_theirs = cpu_seconds(ours, args.runs), cpu_seconds(theirs, args.runs)
    print(f"instructions: safeglslc {i_ours / 1e6:.1f} M, glslangValidator -V {i_theirs / 1e6:.1f} M, "
          f"ratio {i_ours / i_theirs:.3f}")
    print(f"CPU per run ({args.runs} runs): safeglslc {c_ours * 1e3:.1f} ms, glslangValidator -V {c_theirs * 1e3:.1f} ms, "
          f"ratio {c_ours / c_theirs:.3f} (load {os.getloadavg()[0]:.1f})")


if __name__ == "__main__":
    main()
