#!/usr/bin/env python3
"""Fetches the third-party pbrt-v3 scenes of scenes.json into a cache folder
(default build/bench-cache/pbrt_scenes/), never into the repository.

    bench/pbrt_scenes/fetch.py [CACHE_DIR]

Each file is taken, in this order, from the cache (when its sha256 matches),
from a local mirror ($SAFEGI_MIRROR_DIR/<owner>+<name>/repo, a bare git
repository holding the commit), or from a blob-less clone of
https://github.com/<owner>/<name> at the pinned commit; a file whose sha256
differs from the manifest's is an error (the numbers would not be the same
scene's).
"""
from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]


def sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def git_show(git_dir: Path, commit: str, path: str) -> bytes | None:
    result = subprocess.run(["git", "--git-dir", str(git_dir), "show", f"{commit}:{path}"], capture_output=True)
    return result.stdout if result.returncode == 0 else None


def fetch_file(entry: dict, path: str, digest: str, cache: Path) -> Path:
    target = cache / entry["repo"].replace("/", "+") / path
    if target.exists() and sha256(target.read_bytes()) == digest:
        return target
    data = None
    mirror = os.environ.get("SAFEGI_MIRROR_DIR", "/work/.mirror")
    git_dir = Path(mirror) / entry["repo"].replace("/", "+") / "repo"
    if git_dir.exists():
        data = git_show(git_dir, entry["commit"], path)
    if data is None:
        clone = cache / "clones" / entry["repo"].replace("/", "+")
        if not clone.exists():
            subprocess.run(["git", "clone", "--quiet", "--bare", "--filter=blob:none",
                            f"https://github.com/{entry['repo']}", str(clone)], check=True)
        data = git_show(clone, entry["commit"], path)
    if data is None:
        raise SystemExit(f"fetch: cannot get {entry['repo']}@{entry['commit']}:{path}")
    if sha256(data) != digest:
        raise SystemExit(f"fetch: {entry['repo']}:{path} has sha256 {sha256(data)}, expected {digest}")
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_bytes(data)
    return target


def fetch_all(cache: Path) -> dict[str, Path]:
    """The main scene file of every third-party entry, by name."""
    manifest = json.loads((HERE / "scenes.json").read_text())
    scenes = {}
    for entry in manifest["scenes"]:
        if "repo" not in entry:
            continue
        for path, digest in entry["files"].items():
            fetch_file(entry, path, digest, cache)
        scenes[entry["name"]] = cache / entry["repo"].replace("/", "+") / entry["scene"]
    return scenes


if __name__ == "__main__":
    cache = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "build" / "bench-cache" / "pbrt_scenes"
    for name, path in fetch_all(cache).items():
        print(f"{name}: {path}")
