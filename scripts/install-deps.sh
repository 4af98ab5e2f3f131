#!/usr/bin/env bash
# Installs SafeGI's build and test dependencies from Debian 12 packages.
# Idempotent and non-interactive; does nothing (and needs no network) when
# everything is already installed. Must run as root (or with sudo available).
#   scripts/install-deps.sh           install what is missing
#   scripts/install-deps.sh --list    print the package names, one a line (scripts/check-deps.sh)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git python3
  clang libclang-rt-14-dev           # libFuzzer target of the compiler
  glslang-dev glslang-tools          # validates emitted GLSL, safeglslc -V/-G; glslangValidator for tests and benchmarks
  spirv-tools                        # spirv-val: the tests validate every SPIR-V module safeglslc writes
  libosmesa6-dev libegl-dev libegl1-mesa-dev libgl-dev libgl1-mesa-dri
  python3-glad                       # generates the GL loader at build time
  libvulkan-dev                      # runtime_vk: the Vulkan loader and headers
  vulkan-validationlayers            # runtime_vk's tests run with VK_LAYER_KHRONOS_validation on
  mesa-vulkan-drivers                # lavapipe: the software Vulkan device the tests run on (no GPU on CI)
  libglm-dev
  libopenimageio-dev openimageio-tools # the tools: OpenImageIO's CMake config imports /usr/bin/iconvert etc.
  libopenexr-dev libpng-dev          # the renderer writes EXR and PNG without OpenImageIO's start-up cost
  nlohmann-json3-dev libcli11-dev libtinyobjloader-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  valgrind                           # instruction counts for the benchmarks
  gnuplot-nox                        # the benchmarks' log-log plots (docs/img/)
  libopenmpi-dev openmpi-bin         # distributed safegi-render (mpirun); optional at configure time
)

if [[ "${1:-}" == "--list" ]]; then
  printf '%s\n' "${packages[@]}"
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
