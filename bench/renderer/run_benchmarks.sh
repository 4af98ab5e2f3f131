#!/usr/bin/env bash
# Renderer throughput and accuracy benchmarks (by hand, never in ctest).
#
#   bench/renderer/run_benchmarks.sh [BUILD_DIR] [PBRT_REFERENCE_EXR]
#
# 1. Speed: the Cornell box, 512x512, 16 spp path tracing (the pbrt-v3 setting),
#    typed and unchecked programs, 1 and 2 threads: rays/s (camera + extension
#    + shadow), samples/s, wall time, peak memory.
# 2. Unused features cost nothing: the same scene with a shutter interval but
#    nothing moving, and with a zero-radius lens.
# 3. Accuracy: relative RMSE against a converged reference (optional argument,
#    e.g. the pbrt-v3 4096 spp EXR) at 16, 64 and 256 spp.
set -euo pipefail
build=${1:-build}
reference=${2:-}
root=$(cd "$(dirname "$0")/../.." && pwd)
scene=$root/examples/scenes/cornell-box/cornell-box.json
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

row() {  # program threads label extra-args...
  local program=$1 threads=$2 label=$3
  shift 3
  local json
  json=$("$build/bin/$program" "$scene" --resolution 512x512 --spp "${SPP:-16}" --threads "$threads" -q --stats \
         -o "$out/img" "$@")
  python3 - "$program" "$threads" "$label" "$json" <<'PY'
import json, sys
program, threads, label, stats = sys.argv[1], int(sys.argv[2]), sys.argv[3], json.loads(sys.argv[4])
rays = stats["rays"]
print(f"| {program:24} | {label:18} | {threads} | {stats['seconds']:7.2f} s | {stats['render_cpu_seconds']:7.2f} s | "
      f"{rays/1e6:6.2f} M ({stats['camera_rays']/1e6:.2f} / {stats['extension_rays']/1e6:.2f} / "
      f"{stats['shadow_rays']/1e6:.2f}) | {stats['rays_per_second']/1e6:6.2f} M | "
      f"{stats['rays_per_cpu_second']/1e6:6.2f} M | {stats['samples_per_second']/1e6:5.2f} M | "
      f"{stats['peak_memory_kib']/1024:6.1f} MiB |")
PY
}

# rays per CPU-second (CPU time of the render, all threads) is the per-core
# throughput, also on a shared machine where wall-clock time is not.
echo "| program | variant | threads | wall | CPU time | rays (camera / extension / shadow) | rays/s (wall) | rays per CPU-second | samples/s (wall) | peak memory |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for program in safegi-render safegi-render-unchecked; do
  for threads in 1 2; do row "$program" "$threads" "cornell box"; done
done

# Unused features: a scene copy that switches them on without using them.
sed 's/"fov": "19.5 deg"/"fov": "19.5 deg", "shutter": {"open": "0 s", "close": "10 ms"}/' "$scene" > "$out/shutter.json"
sed 's/"fov": "19.5 deg"/"fov": "19.5 deg", "lens_radius": "0 m"/' "$scene" > "$out/lens.json"
cp "$root"/examples/scenes/cornell-box/*.obj "$out/"
for variant in shutter lens; do
  scene=$out/$variant.json row safegi-render 1 "$variant, unused"
done

if [[ -n "$reference" ]]; then
  echo
  echo "| spp | relative RMSE | global relative RMSE | mean ratio (r, g, b) |"
  echo "|---|---|---|---|"
  for spp in 16 64 256; do
    "$build/bin/safegi-render" "$scene" --resolution 512x512 --spp "$spp" -q -o "$out/acc$spp"
    python3 - "$spp" "$("$build/bin/safegi-image-compare" "$out/acc$spp.exr" "$reference")" <<'PY'
import json, sys
s = json.loads(sys.argv[2])
print(f"| {sys.argv[1]} | {s['relative_rmse']:.4f} | {s['global_relative_rmse']:.4f} | {s['mean_ratio']} |")
PY
  done
fi
