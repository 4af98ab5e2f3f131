#!/usr/bin/env bash
# Our path tracer against pbrt-v3 at equal samples, by hand (never in ctest).
#
#   bench/renderer/compare_pbrt.sh PBRT_BINARY REFERENCE_EXR [BUILD_DIR] [SPP...]
#
# PBRT_BINARY: a pbrt-v3 executable (Release build; see docs/cpu-renderer.md for
# how it was built). REFERENCE_EXR: the converged Cornell box, e.g.
# ../shared/reference/cornell-box-pbrt-v3-path-512-4096spp.exr. SPP defaults to
# 16 64 256.
#
# 1. Writes the Cornell box as a pbrt-v3 scene from our own scene file
#    (examples/scenes/cornell-box/), so both renderers see the same triangles:
#    512x512, path tracing, max depth 65 (pbrt: Russian roulette after depth 3,
#    as ours), Halton sampler, box filter of radius 0.5 pixel.
# 2. Renders it with pbrt and with safegi-render at each sample count (both on
#    all threads) and prints the relative RMSE of each against the reference.
# 3. Times both on one thread at 16 spp, one after the other (same machine
#    load): rays and CPU time per sample for each (pbrt's ray counts come from
#    its statistics, its CPU time from its rusage; ours from --stats). On a
#    loaded machine compare CPU times, not wall times.
#
# Nothing of pbrt (code, scenes, images) is kept in the repository; set
# KEEP_DIR=DIR to keep the images and logs there.
set -euo pipefail
pbrt=${1:?usage: compare_pbrt.sh PBRT_BINARY REFERENCE_EXR [BUILD_DIR] [SPP...]}
reference=${2:?usage: compare_pbrt.sh PBRT_BINARY REFERENCE_EXR [BUILD_DIR] [SPP...]}
build=${3:-build}
shift $(( $# < 3 ? $# : 3 ))
spps=("$@")
[[ ${#spps[@]} -gt 0 ]] || spps=(16 64 256)
root=$(cd "$(dirname "$0")/../.." && pwd)
scene=$root/examples/scenes/cornell-box/cornell-box.json
out=${KEEP_DIR:-$(mktemp -d)}
[[ -n ${KEEP_DIR:-} ]] || trap 'rm -rf "$out"' EXIT
mkdir -p "$out"

# The pbrt-v3 scene, from our JSON and OBJ files (metres; quads and OBJ faces as
# triangles with our winding, so the one-sided light emits downwards in both).
write_pbrt_scene() {  # SPP OUTPUT_EXR > scene.pbrt
  python3 "$root/bench/renderer/json_to_pbrt.py" "$scene" "$1" "$2"
}

compare() {  # IMAGE -> "relative_rmse global_relative_rmse"
  "$build/bin/safegi-image-compare" "$1" "$reference" |
    python3 -c 'import json,sys; s=json.load(sys.stdin); print("%.4f %.4f" % (s["relative_rmse"], s["global_relative_rmse"]))'
}

echo "| spp | pbrt-v3 relative RMSE | safegi-render relative RMSE | pbrt-v3 global | safegi-render global |"
echo "|---|---|---|---|---|"
for spp in "${spps[@]}"; do
  write_pbrt_scene "$spp" "$out/pbrt$spp.exr" > "$out/cornell$spp.pbrt"
  "$pbrt" --quiet "$out/cornell$spp.pbrt" > "$out/pbrt$spp.log" 2>&1
  "$build/bin/safegi-render" "$scene" --resolution 512x512 --spp "$spp" -q -o "$out/ours$spp"
  read -r pbrt_rel pbrt_global < <(compare "$out/pbrt$spp.exr")
  read -r ours_rel ours_global < <(compare "$out/ours$spp.exr")
  echo "| $spp | $pbrt_rel | $ours_rel | $pbrt_global | $ours_global |"
done

# Speed on one thread, back to back. pbrt's statistics (printed without
# --quiet) count camera rays and the intersection tests of regular (camera +
# extension) and shadow rays; its CPU time is its rusage as our child.
echo
echo "| renderer | threads | wall | CPU time | rays (camera / extension / shadow) | rays per CPU-second | CPU time per sample | rays per wall second |"
echo "|---|---|---|---|---|---|---|---|"
write_pbrt_scene 16 "$out/pbrt-speed.exr" > "$out/speed.pbrt"
ours=$("$build/bin/safegi-render" "$scene" --resolution 512x512 --spp 16 --threads 1 -q --stats -o "$out/ours-speed")
python3 - "$pbrt" "$out/speed.pbrt" "$ours" <<'PY'
import json, re, resource, subprocess, sys, time
pbrt, pbrt_scene, ours = sys.argv[1], sys.argv[2], json.loads(sys.argv[3])
start = time.monotonic()
log = subprocess.run([pbrt, "--nthreads", "1", pbrt_scene], capture_output=True, text=True, check=True).stdout
wall = time.monotonic() - start
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = usage.ru_utime + usage.ru_stime
def count(name):
    m = re.search(r"^\s*" + re.escape(name) + r"\s+(\d+)", log, re.M)
    if not m: raise SystemExit(f"pbrt printed no '{name}' statistic")
    return int(m.group(1))
camera, regular, shadow = count("Camera rays traced"), count("Regular ray intersection tests"), count("Shadow ray intersection tests")
rays = regular + shadow
print(f"| pbrt-v3 | 1 | {wall:.2f} s | {cpu:.2f} s | {rays/1e6:.2f} M ({camera/1e6:.2f} / {(regular-camera)/1e6:.2f} / "
      f"{shadow/1e6:.2f}) | {rays/cpu/1e6:.2f} M | {cpu/camera*1e6:.2f} µs | {rays/wall/1e6:.2f} M |")
print(f"| safegi-render | 1 | {ours['seconds']:.2f} s | {ours['render_cpu_seconds']:.2f} s | {ours['rays']/1e6:.2f} M "
      f"({ours['camera_rays']/1e6:.2f} / {ours['extension_rays']/1e6:.2f} / {ours['shadow_rays']/1e6:.2f}) | "
      f"{ours['rays_per_cpu_second']/1e6:.2f} M | {ours['render_cpu_seconds']/ours['samples']*1e6:.2f} µs | "
      f"{ours['rays_per_second']/1e6:.2f} M |")
PY
