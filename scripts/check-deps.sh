#!/usr/bin/env bash
# The dependency guard: fails, naming the file and its package, when the build
# uses a file that scripts/install-deps.sh did not bring.
#
#   scripts/check-deps.sh [build-dir]      (default build/; configures it first)
#
# Configure records every file the build takes from outside the tree
# (cmake/SafeGIDependencyFiles.cmake: the files of every imported target of
# every find_package, find_library/find_path/find_program results, package
# config directories). Each must exist and belong (dpkg -S) to a package that
# install-deps.sh names, that one of those depends on (Depends/Pre-Depends,
# recursively: install-deps installs without recommends), or that every
# Debian system has (Essential or Priority: required). A package that is only
# installed on this machine by chance, as openimageio-tools was on CI's,
# fails the check even though the build would pass here.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}

# CMake's default generator, as scripts/test.sh's Release pass uses in the same folder;
# a folder already configured keeps its generator.
cmake -S "$root" -B "$build" >/dev/null
files="$build/dependency-files.tsv"
[[ -s "$files" ]] || { echo "check-deps: $files is missing or empty (configure did not record the dependencies)" >&2; exit 1; }

python3 - "$files" $("$root/scripts/install-deps.sh" --list) <<'PY'
import os, re, subprocess, sys

files_tsv, roots = sys.argv[1], sys.argv[2:]

# Installed packages: name -> (depends, provides, essential, priority).
query = subprocess.run(
    ["dpkg-query", "-W", "-f", "${Package}\t${db:Status-Abbrev}\t${Pre-Depends}\t${Depends}\t${Provides}\t${Essential}\t${Priority}\n"],
    capture_output=True, text=True, check=True).stdout
installed, providers = {}, {}
for line in query.splitlines():
    name, status, pre, dep, provides, essential, priority = (line.split("\t") + [""] * 7)[:7]
    if not status.startswith("ii"):
        continue
    installed[name] = [pre, dep]
    if essential == "yes" or priority == "required":
        roots.append(name)
    for p in filter(None, (x.strip() for x in provides.split(","))):
        providers.setdefault(re.split(r"[\s(:]", p)[0], []).append(name)

def package_names(field):
    """Every installed package that can satisfy an alternative of each relation."""
    for relation in filter(None, (r.strip() for r in field.split(","))):
        for alternative in relation.split("|"):
            name = re.split(r"[\s(:]", alternative.strip())[0]
            yield from ([name] if name in installed else []) + providers.get(name, [])

missing_roots = [r for r in set(roots) if r not in installed]
closure, todo = set(), [r for r in roots if r in installed]
while todo:
    name = todo.pop()
    if name in closure:
        continue
    closure.add(name)
    for field in installed[name]:
        todo.extend(p for p in package_names(field) if p not in closure)

# Found by a CMake find module whether asked for or not, linked by nothing here,
# and absent on a fresh machine without harm. Anything else must come from
# install-deps.sh.
optional = {
    "OpenGL::GLU": "FindOpenGL looks for GLU whatever the components; SafeGI never links it",
    "OPENGL_glu_LIBRARY": "FindOpenGL looks for GLU whatever the components; SafeGI never links it",
}

entries, notes = [], []
for line in open(files_tsv):
    origin, path, use = (line.rstrip("\n").split("\t") + ["", ""])[:3]
    if not path:
        continue
    name = origin.split()[-2] if origin.startswith("imported target") else origin.split()[-1]
    if name in optional:
        notes.append(f"{path} ({origin}) not checked: {optional[name]}")
        continue
    if use == "unlinked" and not os.path.exists(path):
        # An imported target nothing links, whose package config tolerates the
        # missing file (Imath's Python binding): harmless.
        notes.append(f"{path} ({origin}) does not exist; nothing links the target and configure accepts it")
        continue
    entries.append((origin, path))

def candidates(path):
    """The path as dpkg may list it: as given, resolved, and across the merged-/usr links."""
    seen = []
    for p in (path, os.path.realpath(path)):
        for q in (p, re.sub(r"^/usr/(lib|lib64|bin|sbin)/", r"/\1/", p), re.sub(r"^/(lib|lib64|bin|sbin)/", r"/usr/\1/", p)):
            if q not in seen:
                seen.append(q)
    return seen

all_paths = sorted({c for _, p in entries for c in candidates(p)})
owners = {}
search = subprocess.run(["dpkg-query", "-S", *all_paths], capture_output=True, text=True)
for line in search.stdout.splitlines():
    # "pkg1, pkg2:arch: /path" (diversions start with "diversion by")
    if line.startswith("diversion "):
        continue
    packages, _, path = line.rpartition(": ")
    owners.setdefault(path, set()).update(re.sub(r":.*$", "", p.strip()) for p in packages.split(","))

problems = []
for origin, path in entries:
    if not os.path.exists(path):
        problems.append(f"{path} ({origin}) does not exist")
        continue
    found = set().union(*(owners.get(c, set()) for c in candidates(path)))
    if not found:
        problems.append(f"{path} ({origin}) belongs to no Debian package")
    elif not found & closure:
        names = ", ".join(sorted(found))
        problems.append(f"{path} ({origin}) belongs to {names}, which scripts/install-deps.sh neither "
                        f"installs nor pulls in: add {sorted(found)[0]} to its list")

for r in sorted(missing_roots):
    problems.append(f"{r} is listed in scripts/install-deps.sh but not installed (run it first)")
if problems:
    print(f"check-deps: {len(problems)} of {len(entries)} dependency files are not provided by scripts/install-deps.sh:",
          file=sys.stderr)
    for p in problems:
        print(f"check-deps: error: {p}", file=sys.stderr)
    sys.exit(1)
for n in notes:
    print(f"check-deps: note: {n}")
print(f"check-deps: {len(entries)} dependency files, each from a package install-deps.sh brings "
      f"({len(closure)} packages with their dependencies)")
PY
