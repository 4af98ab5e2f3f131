#!/usr/bin/env python3
"""Gator's ten benchmark shaders ported to SafeGI: annotation overhead in lines
and the size of the emitted GLSL, against Gator's own numbers and output.

Gator (cucapra/gator, "Geometry Types for Graphics Programming", OOPSLA 2020)
reports +36 % lines for its typed shaders over plain GLSL (597 → 815); its
counting rule is benchmarks/count.sh: spaces deleted, blank lines dropped.
This script applies bench/gator/ports.json to Gator's plain versions, checks
and compiles every port with safeglslc (and validates the result with
glslangValidator when present), counts lines Gator's way, and compares the
emitted GLSL's size (non-whitespace characters, helper functions) with Gator's
output: from gatorc when one is given (built from the same snapshot), else the
three compiled shaders of Gator's own test/compiler/*.expect.

    bench/gator/run.py                                   # through bench/run-all.sh, or alone
    SAFEGI_GATOR=<gator git dir> SAFEGI_GATORC=<gatorc> bench/gator/run.py

SAFEGI_GATOR defaults to /work/.mirror/cucapra+gator/repo (`fetch
github:cucapra/gator`); without it the section says how to get it. Nothing is
timed: the counts are exact.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lib"))
import harness as h  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
import ports  # noqa: E402

GATOR_LINES = (597, 815)  # Gator's paper: plain GLSL -> Gator
DEFAULT_SNAPSHOT = Path("/work/.mirror/cucapra+gator/repo")


def count_lines(text: str) -> int:
    """benchmarks/count.sh: tr -d ' ' < file | grep . | wc -l"""
    return sum(1 for line in text.replace(" ", "").split("\n") if line)


def glsl_size(text: str) -> int:
    """Non-whitespace characters: blanked annotations and layout do not count."""
    return len(re.sub(r"\s+", "", text))


def function_definitions(text: str) -> int:
    """Definitions of functions other than main: helpers a compiler added, or the shader's own."""
    return len(re.findall(r"\b[A-Za-z_]\w*\s+(?!main\b)[A-Za-z_]\w*\s*\([^;{)]*\)\s*\{", text))


def added_lines(raw: str, port: str) -> dict[str, int]:
    """What the port adds, by kind (lines counted Gator's way)."""
    kinds = {"#version": 0, "#include prelude": 0, "space declarations": 0, "other": 0}
    raw_lines = {line.replace(" ", "") for line in raw.split("\n") if line.strip()}
    for line in port.split("\n"):
        squeezed = line.replace(" ", "")
        if not squeezed or squeezed in raw_lines:
            continue
        if squeezed.startswith("#version"):
            kinds["#version"] += 1
        elif squeezed.startswith("#include"):
            kinds["#include prelude"] += 1
        elif squeezed.startswith("space"):
            kinds["space declarations"] += 1
    return kinds


def changed_lines(raw: str, port: str) -> int:
    """Port lines that are not raw lines (annotated, converted, added)."""
    raw_lines = [line.replace(" ", "") for line in raw.split("\n") if line.strip()]
    count = 0
    for line in port.split("\n"):
        squeezed = line.replace(" ", "")
        if not squeezed:
            continue
        if squeezed in raw_lines:
            raw_lines.remove(squeezed)
        else:
            count += 1
    return count


def compile_port(safeglslc: Path, port: Path, out: Path) -> tuple[bool, str]:
    run = subprocess.run([str(safeglslc), str(port), "-o", str(out)], capture_output=True, text=True)
    return run.returncode == 0, run.stdout + run.stderr


def glslang_accepts(glsl: Path, stage: str) -> bool | None:
    validator = shutil.which("glslangValidator")
    if not validator:
        return None
    return subprocess.run([validator, "-S", stage, str(glsl)], capture_output=True, text=True).returncode == 0


def gator_output(gatorc: Path, gator: Path, bench: str, lgl: str, work: Path) -> str | None:
    """Compiles one of Gator's .lgl shaders with gatorc (its includes resolved relative to it)."""
    root = work / "gator-src"
    if not root.exists():
        for path in ports.git_ls(gator, "benchmarks/benchmarks"):
            if path.endswith(".lgl"):
                (root / path).parent.mkdir(parents=True, exist_ok=True)
                (root / path).write_text(ports.git_show(gator, path))
        for b in ports.BENCHMARKS:
            for path in ports.gator_files(gator, b):
                (root / path).parent.mkdir(parents=True, exist_ok=True)
                (root / path).write_text(ports.git_show(gator, path))
    source = root / lgl
    run = subprocess.run([str(gatorc), source.name], cwd=source.parent, capture_output=True, text=True)
    return run.stdout if run.returncode == 0 and run.stdout.strip() else None


# What porting found (the recipe fixes or spells out each; the counts above include those edits).
FINDINGS = """What the checker found in Gator's plain shaders while porting them (the ports fix or spell out each):

* phong, multilight, synthetic: `dot(camPos, reflectDir)` takes a camera-space direction and a world-space
  one (E-SPACE-MISMATCH); Gator's typed versions convert `reflectDir` to camera space, and so do the ports
  (`… in camera`).
* microfacet: `normalize(geom_tangent - dot(geom_tangent, nhat))` subtracts a number from every coordinate
  where `dot(…) * nhat` was meant (E-KIND-MISMATCH, a rule added for it); Gator's version keeps the line.
  Its vertex shader transforms tangents with w = 1, as points; typed `vector<model>`, the port's
  `aTangent in view` applies the linear part only.
* fog: `BA = lightVec - worldPos` is a vector minus a point (E-POINT-ARITHMETIC); the port keeps the value
  and says what it assumes, `lightVec - vector<world>(worldPos)`. spotlight negates a point,
  `normalize(-uLight in world)`, which Gator accepts; the port writes `-vector<world>(uLight in world)`.
* bump: `normalize(-vPosition)` with a world-space `vPosition` puts the eye at the world's origin; the
  port's `-vector<world>(vPosition)` makes that assumption visible (it type-checks: the language cannot
  know where the eye is).
* shadow_map: `vShadowPos = (… * vec4(aPosition, 1.)).xyz` skips the divide by w, which is right only
  because the light's projection is orthographic (`mat4.ortho` in its main.ts): the port types it
  `map<light, light_clip>`; as a `projmap` the missing divide would be an error.

Annotations that are not lines: the normal-through-rigid-map rule needs `rigidmap` for the model and view
matrices (the benchmarks' hosts only rotate and translate; fog's model matrix scales, so its normal is a
`vector`); `float<1>(dot(n, wi))` where a cosine is used as a plain number (Phong's reflection formula).
Coordinates that are not lengths (`vShadowPos`, NDC) stay plain `vec3`: a point's coordinates are lengths.
"""


def not_measured(reason: str) -> None:
    h.write_section("gator", "## Gator's benchmarks: annotation overhead and emitted GLSL\n\n"
                    f"Not measured in this run: {reason}. Fetch the snapshot (`fetch github:cucapra/gator`, or "
                    "`git clone --bare https://github.com/cucapra/gator`) and set `SAFEGI_GATOR` to its git "
                    "directory; see `bench/gator/run.py`.\n")


def main() -> None:
    gator = Path(os.environ.get("SAFEGI_GATOR", DEFAULT_SNAPSHOT))
    if not (gator / "HEAD").exists() and not (gator / ".git").exists():
        return not_measured(f"no Gator snapshot at {gator}")
    if (gator / ".git").exists():
        gator = gator / ".git"
    safeglslc = h.binary("safeglslc")
    gatorc = os.environ.get("SAFEGI_GATORC")
    commit = subprocess.run(["git", "--git-dir", str(gator), "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    work = Path(tempfile.mkdtemp(prefix="safegi-gator-"))
    written = ports.apply(gator, work / "ports")
    rows, failures = [], []
    totals = {"raw": 0, "gator": 0, "port": 0, "changed": 0, "raw_size": 0, "our_size": 0, "gator_size": 0,
              "our_helpers": 0, "gator_helpers": 0, "gator_programs": 0, "files": 0, "accepted": 0}
    kinds_total: dict[str, int] = {}
    our_sizes: dict[str, int] = {}
    for bench in ports.BENCHMARKS:
        raw_text = {p: ports.git_show(gator, p) for p in ports.raw_files(gator, bench)}
        gator_text = {p: ports.git_show(gator, p) for p in ports.gator_files(gator, bench)}
        raw_n = sum(count_lines(t) for t in raw_text.values())
        gator_n = sum(count_lines(t) for t in gator_text.values())
        port_n = changed = raw_size = our_size = our_helpers = 0
        gator_size = gator_helpers = 0
        gator_complete = bool(gatorc)
        for path, raw in raw_text.items():
            key = ports.key_of(path)
            stage = ports.stage_of(key)
            port_path = work / "ports" / f"{key}.sgl.{stage}"
            port = port_path.read_text()
            port_n += count_lines(port)
            changed += changed_lines(raw, port)
            for k, v in added_lines(raw, port).items():
                kinds_total[k] = kinds_total.get(k, 0) + v
            glsl = port_path.with_suffix(".glsl")
            ok, log = compile_port(safeglslc, port_path, glsl)
            totals["files"] += 1
            if not ok:
                failures.append(f"{key}: {log.strip()}")
                continue
            totals["accepted"] += 1
            if glslang_accepts(glsl, stage) is False:
                failures.append(f"{key}: glslangValidator rejects the emitted GLSL")
            emitted = glsl.read_text()
            our_size += glsl_size(emitted)
            our_sizes[key] = glsl_size(emitted)
            our_helpers += function_definitions(emitted) - function_definitions(raw)
            raw_size += glsl_size(raw)
            if gatorc:
                lgl = f"benchmarks/benchmarks/{bench}/default/{Path(path).stem}.lgl"
                out = gator_output(Path(gatorc), gator, bench, lgl, work) if lgl in gator_text else None
                if out is None:
                    gator_complete = False
                else:
                    gator_size += glsl_size(out)
                    gator_helpers += function_definitions(out) - function_definitions(raw)
        for key, value in (("raw", raw_n), ("gator", gator_n), ("port", port_n), ("changed", changed),
                           ("raw_size", raw_size), ("our_size", our_size), ("our_helpers", our_helpers)):
            totals[key] += value
        gator_cells = ["—", "—"]
        if gatorc and gator_complete:
            totals["gator_size"] += gator_size
            totals["gator_helpers"] += gator_helpers
            totals["gator_programs"] += 1
            gator_cells = [f"{gator_size:,}", str(gator_helpers)]
        rows.append([bench, str(raw_n), f"{gator_n} (+{100.0 * (gator_n - raw_n) / raw_n:.0f} %)",
                     f"{port_n} (+{100.0 * (port_n - raw_n) / raw_n:.0f} %)", str(changed), f"{raw_size:,}",
                     f"{our_size:,}", str(our_helpers)] + gator_cells)

    raw_n, gator_n, port_n = totals["raw"], totals["gator"], totals["port"]
    text = "## Gator's benchmarks: annotation overhead and emitted GLSL\n\n"
    text += (f"Gator's ten benchmarks (cucapra/gator @ `{commit}`, fetched, never committed) ported to SafeGI by "
             "`bench/gator/ports.json` (edits of Gator's own plain-GLSL versions: annotated declarations, "
             "`in` conversions where Gator writes them), each checked and compiled by safeglslc"
             + (" and the result validated by glslangValidator" if shutil.which("glslangValidator") else "")
             + f". Lines are counted Gator's way (`benchmarks/count.sh`: spaces deleted, blank lines dropped); "
             f"sizes are non-whitespace characters of the GLSL; helpers are function definitions the compiler "
             f"added. `SAFEGI_GATOR={gator} bench/gator/run.py`"
             + (f" with `SAFEGI_GATORC={gatorc}`" if gatorc else "") + f"; {h.machine_line()}.\n\n")
    header = ["benchmark", "plain GLSL lines", "Gator lines", "SafeGI lines", "lines changed", "plain GLSL size",
              "SafeGI output size", "SafeGI helpers", "Gator output size", "Gator helpers"]
    rows.append(["**total**", f"**{raw_n}**", f"**{gator_n} (+{100.0 * (gator_n - raw_n) / raw_n:.1f} %)**",
                 f"**{port_n} (+{100.0 * (port_n - raw_n) / raw_n:.1f} %)**", f"**{totals['changed']}**",
                 f"**{totals['raw_size']:,}**", f"**{totals['our_size']:,}**", f"**{totals['our_helpers']}**",
                 f"**{totals['gator_size']:,}**" if totals["gator_programs"] else "—",
                 f"**{totals['gator_helpers']}**" if totals["gator_programs"] else "—"])
    text += h.table(header, rows)
    text += (f"\nGator's paper: {GATOR_LINES[0]} → {GATOR_LINES[1]} lines "
             f"(+{100.0 * (GATOR_LINES[1] - GATOR_LINES[0]) / GATOR_LINES[0]:.1f} %); counted here from the "
             f"snapshot: {raw_n} → {gator_n}. SafeGI: {raw_n} → {port_n} "
             f"(+{100.0 * (port_n - raw_n) / raw_n:.1f} %), of which the added lines are "
             + ", ".join(f"{v} {k}" for k, v in kinds_total.items() if k != "other" and v)
             + f"; {totals['changed']} lines differ from the plain shaders in all. "
             f"{totals['accepted']} of {totals['files']} ports check and compile.\n")
    if not gatorc:
        # Gator's own compiled test expectations: two are close variants of benchmark fragments.
        variants = {"auto_phong_fragment": "phong/fragment", "shadow_map_fragment": "shadow_map/fragment"}
        pairs = []
        for name, key in variants.items():
            out = ports.git_show(gator, f"test/compiler/{name}.expect")
            pairs.append(f"Gator's `test/compiler/{name}` (a variant of the {key} benchmark) is {glsl_size(out):,} "
                         f"characters with {function_definitions(out)} function definitions; our {key} is "
                         f"{our_sizes.get(key, 0):,} characters with none added "
                         f"({glsl_size(out) / max(our_sizes.get(key, 1), 1):.1f}× smaller)")
        text += ("\nWithout gatorc (`SAFEGI_GATORC`), Gator's output is known only from its compiled test "
                 "expectations: " + "; ".join(pairs) + ".\n")
    text += "\n" + FINDINGS
    if failures:
        text += "\nFailures:\n\n" + "\n".join(f"* {f}" for f in failures) + "\n"
    h.write_section("gator", text)
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
