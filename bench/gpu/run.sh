#!/bin/bash
# Rays per second of safegi-render-gpu (the annotated-GLSL path tracer on a
# Vulkan device) against safegi-render (the CPU path tracer) on the same
# machine, scenes and settings, in one call: builds both programs if needed,
# renders each scene with each, prints one JSON line per render and the
# GPU / CPU ratio of rays per second (docs/gpu-renderer.md, docs/benchmarks.md).
#
#   bench/gpu/run.sh                      # lavapipe (llvmpipe) here
#   SAFEGI_VK_DEVICE=nvidia bench/gpu/run.sh   # an NVIDIA GPU (needs its Vulkan ICD)
#
# Environment: BUILD (build folder, default build-bench-gpu), SIZE (default
# 256x256), SPP (default 16), THREADS (CPU threads, default all cores),
# SCENES (default: the Cornell box and phong.json).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD:-$root/build-bench-gpu}
size=${SIZE:-256x256}
spp=${SPP:-16}
threads=${THREADS:-$(nproc)}
device=${SAFEGI_VK_DEVICE:-}
scenes=${SCENES:-"$root/examples/scenes/cornell-box/cornell-box.json $root/examples/scenes/phong.json"}

if [ ! -x "$build/bin/safegi-render" ] || [ ! -x "$build/bin/safegi-render-gpu" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSAFEGI_BUILD_BENCH=OFF -DSAFEGI_BUILD_GL=OFF \
        -DSAFEGI_BUILD_TESTS=OFF >/dev/null
  ninja -C "$build" -j"$(nproc)" safegi-render safegi-render-gpu
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "# $(date -u +%FT%TZ) $(uname -n), $(nproc) cores, ${size}, ${spp} spp, CPU threads ${threads}, GPU device '${device:-first}'"
for scene in $scenes; do
  name=$(basename "$scene" .json)
  cpu=$("$build/bin/safegi-render" "$scene" --resolution "$size" --spp "$spp" --threads "$threads" -q --stats -o "$out/cpu")
  gpu=$("$build/bin/safegi-render-gpu" "$scene" --resolution "$size" --spp "$spp" -q --stats -o "$out/gpu" \
        ${device:+--device "$device"})
  echo "cpu $name $cpu"
  echo "gpu $name $gpu"
  python3 - "$name" "$cpu" "$gpu" <<'PY'
import json, sys
name, cpu, gpu = sys.argv[1], json.loads(sys.argv[2]), json.loads(sys.argv[3])
print(f"{name}: CPU {cpu['rays_per_second'] / 1e6:.2f} M rays/s ({cpu['threads']} threads), "
      f"GPU {gpu['rays_per_second'] / 1e6:.2f} M rays/s on {gpu['device']}: "
      f"GPU/CPU = {gpu['rays_per_second'] / cpu['rays_per_second']:.2f}")
PY
done
