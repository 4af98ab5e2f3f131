#!/usr/bin/env python3
"""Our ports of Gator's ten benchmark shaders, kept as edits of Gator's own
plain-GLSL versions (benchmarks/benchmarks/<name>/raw/*.glsl of cucapra/gator):
Gator's code is fetched, never committed, so this file holds only the line
ranges we replace and our annotated lines, and a hash of each raw file they
apply to.

    bench/gator/ports.py apply  <gator git dir> <out dir>    # writes <out>/<bench>/<file>.sgl.<stage>
    bench/gator/ports.py record <gator git dir> <ports dir>  # rewrites ports.json from edited ports

The ports are SafeGI GLSL: `#version 100` (WebGL 1, which the raw shaders
assume), the prelude, the spaces, and annotated declarations; expressions
keep their text except where a chain of matrices becomes a conversion
(`vPosition in world`, as Gator writes it) or a mistake the checker found had
to be fixed (docs/benchmarks.md, "Gator's benchmarks").
"""
import difflib
import hashlib
import json
import pathlib
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
RECIPE = HERE / "ports.json"
BENCHMARKS = ["bump", "fog", "microfacet", "multilight", "phong", "reflection", "shadow_map", "spotlight", "synthetic",
              "texture"]


def git_show(gator: pathlib.Path, path: str) -> str:
    return subprocess.run(["git", "--git-dir", str(gator), "show", f"HEAD:{path}"], check=True, capture_output=True,
                          text=True).stdout


def git_ls(gator: pathlib.Path, folder: str) -> list[str]:
    out = subprocess.run(["git", "--git-dir", str(gator), "ls-tree", "--name-only", "HEAD", folder + "/"], check=True,
                         capture_output=True, text=True).stdout
    return sorted(line for line in out.splitlines() if line)


def raw_files(gator: pathlib.Path, bench: str) -> list[str]:
    return [p for p in git_ls(gator, f"benchmarks/benchmarks/{bench}/raw") if p.endswith(".glsl")]


def gator_files(gator: pathlib.Path, bench: str) -> list[str]:
    return [p for p in git_ls(gator, f"benchmarks/benchmarks/{bench}/default") if p.endswith(".lgl")]


def stage_of(name: str) -> str:
    return "vert" if "vertex" in name.lower() else "frag"


def key_of(path: str) -> str:
    """benchmarks/benchmarks/phong/raw/vertex.glsl -> phong/vertex"""
    parts = path.split("/")
    return parts[2] + "/" + parts[-1].rsplit(".", 1)[0]


def sha(text: str) -> str:
    return hashlib.sha256(text.encode()).hexdigest()


def apply(gator: pathlib.Path, out: pathlib.Path) -> list[pathlib.Path]:
    recipe = json.loads(RECIPE.read_text())
    written = []
    for bench in BENCHMARKS:
        for path in raw_files(gator, bench):
            key = key_of(path)
            entry = recipe[key]
            raw = git_show(gator, path)
            if sha(raw) != entry["sha256"]:
                sys.exit(f"{path}: not the file the ports were made from (sha256 differs); record them again")
            lines = raw.splitlines()
            for start, end, new in reversed(entry["hunks"]):
                lines[start:end] = new
            target = out / f"{key}.sgl.{stage_of(key)}"
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text("\n".join(lines) + "\n")
            written.append(target)
    return written


def record(gator: pathlib.Path, ports: pathlib.Path) -> None:
    recipe = {}
    for bench in BENCHMARKS:
        for path in raw_files(gator, bench):
            key = key_of(path)
            raw = git_show(gator, path)
            port = (ports / f"{key}.sgl.{stage_of(key)}").read_text().splitlines()
            old = raw.splitlines()
            hunks = [[i1, i2, port[j1:j2]]
                     for tag, i1, i2, j1, j2 in difflib.SequenceMatcher(a=old, b=port, autojunk=False).get_opcodes()
                     if tag != "equal"]
            recipe[key] = {"sha256": sha(raw), "hunks": hunks}
    RECIPE.write_text(json.dumps(recipe, indent=1, ensure_ascii=False) + "\n")


def main() -> int:
    if len(sys.argv) != 4 or sys.argv[1] not in ("apply", "record"):
        print(__doc__, file=sys.stderr)
        return 2
    gator, folder = pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    if sys.argv[1] == "apply":
        for p in apply(gator, folder):
            print(p)
    else:
        record(gator, folder)
    return 0


if __name__ == "__main__":
    sys.exit(main())
