"""Shared measurement helpers for bench/*/run.py.

Every comparison is measured in the same run: whole-process timings are
interleaved (A B A B ...) so that drift in machine load hits both sides alike,
and reported as median with min and max. Instruction counts come from
valgrind's callgrind, which counts the same total whatever else the machine is
doing, so they back every overhead claim that wall time on a shared 2-core
machine cannot.
"""
from __future__ import annotations

import os
import re
import shutil
import statistics
import subprocess
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def build_dir() -> Path:
    return Path(os.environ.get("SAFEGI_BUILD", ROOT / "build")).resolve()


def quick() -> bool:
    return os.environ.get("SAFEGI_BENCH_QUICK", "") not in ("", "0")


def binary(name: str) -> Path:
    path = build_dir() / "bin" / name
    if not path.exists():
        raise SystemExit(f"bench: {path} is missing; build first (scripts/build.sh)")
    return path


@dataclass
class Timing:
    samples: list[float]

    @property
    def median(self) -> float:
        return statistics.median(self.samples)

    def cell(self) -> str:
        return f"{self.median:.3f} ({min(self.samples):.3f}–{max(self.samples):.3f})"


def wall_time(command: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def wall_time_in(command: list[str], cwd: Path) -> float:
    """Wall time of `command` run in `cwd`, whatever its exit status."""
    start = time.perf_counter()
    subprocess.run(command, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def run_with_input(command: list[str], source: str) -> tuple[subprocess.CompletedProcess, float]:
    """Runs `command` with `source` on stdin: its result (any exit status) and wall time."""
    start = time.perf_counter()
    result = subprocess.run(command, input=source, capture_output=True, text=True)
    return result, time.perf_counter() - start


def interleaved(commands: dict[str, list[str]], repeats: int) -> dict[str, Timing]:
    """Runs every command `repeats` times, alternating between them."""
    results: dict[str, list[float]] = {name: [] for name in commands}
    for _ in range(repeats):
        for name, command in commands.items():
            results[name].append(wall_time(command))
    return {name: Timing(samples) for name, samples in results.items()}


def instructions(command: list[str], inside: str | None = None) -> int:
    """Instructions executed by `command`, by callgrind: all of them, or only
    those executed while a function matching `inside` (callgrind's
    --toggle-collect pattern) is on the stack, which leaves out process
    start-up and file I/O that would otherwise swamp a small workload."""
    if shutil.which("valgrind") is None:
        raise SystemExit("bench: valgrind is needed for instruction counts (scripts/install-deps.sh)")
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "callgrind.out"
        toggle = [f"--toggle-collect={inside}"] if inside else []
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", *toggle, *command],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for line in out.read_text().splitlines():
            match = re.match(r"^(?:summary|totals):\s+(\d+)", line)
            if match:
                return int(match.group(1))
    raise RuntimeError(f"no instruction total in callgrind output of {command}")


def instructions_in_object(command: list[str], inside: str, obj: Path, env: dict | None = None) -> int:
    """Instructions executed in the code of one object file (e.g. the program's
    own executable, leaving out the GL driver and libc) while a function matching
    `inside` is on the stack: the self cost of every function of that object."""
    if shutil.which("valgrind") is None:
        raise SystemExit("bench: valgrind is needed for instruction counts (scripts/install-deps.sh)")
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "callgrind.out"
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", f"--toggle-collect={inside}",
                        *command], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       env={**os.environ, **(env or {})})
        return _self_cost_by_object(out).get(str(obj), 0)


def _self_cost_by_object(callgrind_out: Path) -> dict[str, int]:
    """Self cost per object (ob=) of a callgrind output file: cost lines, except
    the one after each calls= line (that is the callee's inclusive cost)."""
    objects: dict[str, str] = {}
    costs: dict[str, int] = {}
    current, after_call = "", False
    for line in callgrind_out.read_text(errors="replace").splitlines():
        match = re.match(r"^(c?ob)=\((\d+)\)(?: (.*))?$", line)
        if match:
            kind, ident, name = match.groups()
            if name is not None:
                objects[ident] = name
            if kind == "ob":
                current = objects[ident]
            continue
        if line.startswith("calls="):
            after_call = True
        elif line[:1].isdigit() or line[:1] in "+-*":
            if after_call:
                after_call = False
                continue
            fields = line.split()
            if len(fields) >= 2:
                costs[current] = costs.get(current, 0) + int(fields[1])
    return costs


def ratio(a: float, b: float) -> str:
    return f"{a / b:.4f}" if b else "n/a"


def table(header: list[str], rows: list[list[str]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def machine_line() -> str:
    load = os.getloadavg()[0]
    cpu = "unknown CPU"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    commit = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip() or "unknown"
    return f"commit {commit}; {os.cpu_count()} cores, {cpu}; load average at start {load:.2f}"


def write_section(name: str, text: str) -> None:
    out = Path(os.environ.get("SAFEGI_BENCH_OUT", ROOT / "out" / "bench"))
    out.mkdir(parents=True, exist_ok=True)
    (out / f"{name}.md").write_text(text)
    print(text)
