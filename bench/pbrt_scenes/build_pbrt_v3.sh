#!/usr/bin/env bash
# Build pbrt-v3 (mmp/pbrt-v3, benchmarked at 13d871f) without CMake and without
# its git submodules, as described in docs/cpu-renderer.md ("Against pbrt-v3").
#
#   bench/pbrt_scenes/build_pbrt_v3.sh PBRT_V3_SOURCE_DIR OUTPUT_DIR
#
# PBRT_V3_SOURCE_DIR is an extracted pbrt-v3 tree (e.g. `git archive | tar -x`);
# the program is written to OUTPUT_DIR/pbrt. pbrt is a benchmark tool only, not
# a dependency of SafeGI: nothing of pbrt is committed, and its -dev packages
# are installed here on the measuring machine only (not by install-deps.sh).
# Debian 12 replaces the submodules: OpenEXR 3.1, glog 0.6 and zlib come from
# packages; Ptex (not packaged) is left out. The given tree is never modified:
# it is copied to OUTPUT_DIR/src-copy, and the copy is edited.
set -euo pipefail

die() { echo "build_pbrt_v3.sh: error: $*" >&2; exit 1; }
[ $# -eq 2 ] || die "usage: $0 PBRT_V3_SOURCE_DIR OUTPUT_DIR"
SRC_IN=$(cd "$1" 2>/dev/null && pwd) || die "no such directory: $1"
[ -f "$SRC_IN/src/main/pbrt.cpp" ] && [ -f "$SRC_IN/src/core/api.cpp" ] \
  || die "$SRC_IN does not look like a pbrt-v3 source tree"
mkdir -p "$2"; OUT=$(cd "$2" && pwd)

# 1. System libraries standing in for src/ext/{openexr,glog,zlib}.
PKGS=(libopenexr-dev libgoogle-glog-dev zlib1g-dev)
MISSING=()
for p in "${PKGS[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || MISSING+=("$p"); done
if [ ${#MISSING[@]} -gt 0 ]; then
  [ "$(id -u)" -eq 0 ] || die "missing packages ${MISSING[*]}; run as root or install them"
  echo "installing ${MISSING[*]}"
  DEBIAN_FRONTEND=noninteractive apt-get update -q
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${MISSING[@]}"
fi

# 2. Scratch copy of the source, edited for the Ptex removal.
WORK="$OUT/src-copy"
rm -rf "$WORK"; mkdir -p "$WORK"
cp -a "$SRC_IN/src" "$WORK/src"
API="$WORK/src/core/api.cpp"
grep -q '#include "textures/ptex.h"' "$API" || die "api.cpp: ptex include not found"
python3 - "$API" <<'EOF'
import re, sys
p = sys.argv[1]; s = open(p).read()
s = s.replace('#include "textures/ptex.h"\n', '')
# The "ptex" branches of MakeFloatTexture/MakeSpectrumTexture become an error.
s, n = re.subn(r'tex = CreatePtex(Float|Spectrum)Texture\(tex2world, tp\);',
               r'Error("\"ptex\" textures are not supported: this pbrt was built without Ptex");', s)
if n != 2: sys.exit("api.cpp: expected 2 ptex branches, found %d" % n)
open(p, 'w').write(s)
EOF
rm -f "$WORK"/src/textures/ptex.{cpp,h}

# 3. Flags: the definitions pbrt-v3's CMakeLists.txt sets for GCC on Linux
# (alloca.h/memory.h, C++11 feature probes, itimer, mmap, posix_memalign,
# thread_local, noinline). gnu++14 instead of its gnu++11: glog 0.6 needs it.
DEFS="-DNDEBUG -DPBRT_HAVE_ALLOCA_H -DPBRT_HAVE_MEMORY_H -DPBRT_HAVE_HEX_FP_CONSTANTS \
 -DPBRT_HAVE_BINARY_CONSTANTS -DPBRT_HAVE_CONSTEXPR -DPBRT_CONSTEXPR=constexpr \
 -DPBRT_HAVE_ALIGNAS -DPBRT_HAVE_ALIGNOF -DPBRT_HAVE_ITIMER -DPBRT_HAVE_NONPOD_IN_UNIONS \
 -DPBRT_HAVE_MMAP -D'PBRT_NOINLINE=__attribute__((noinline))' \
 -DPBRT_HAVE_POSIX_MEMALIGN -DPBRT_THREAD_LOCAL=thread_local"
INCS="-Isrc -Isrc/core -Isrc/ext -I/usr/include/OpenEXR -I/usr/include/Imath"
[ -f /usr/include/OpenEXR/ImfRgbaFile.h ] || die "OpenEXR headers not in /usr/include/OpenEXR"

# 4. Sources (same set as the CMake build's pbrt_exe, less Ptex).
cd "$WORK"
SRCS=()
for d in core accelerators cameras filters integrators lights materials media \
         samplers shapes textures; do SRCS+=(src/$d/*.cpp); done
SRCS+=(src/ext/lodepng.cpp src/ext/rply.cpp src/ext/targa.cpp src/ext/ArHosekSkyModel.c \
       src/main/pbrt.cpp)

# 5. A generated Makefile compiles each translation unit in parallel, then links.
OBJS=$(printf 'obj/%s.o ' "${SRCS[@]}")
cat > Makefile <<EOF
CXXFLAGS = -O3 -std=gnu++14 -Wno-conversion-null $DEFS $INCS
CFLAGS = -O3 $DEFS $INCS
$OUT/pbrt: $OBJS
	g++ -O3 -o \$@ \$^ -lglog -lOpenEXR -lImath -lIex -lz -lpthread
obj/%.cpp.o: %.cpp
	@mkdir -p \$(@D); echo "CXX \$<"; g++ \$(CXXFLAGS) -c \$< -o \$@
obj/%.c.o: %.c
	@mkdir -p \$(@D); echo "CC  \$<"; gcc \$(CFLAGS) -c \$< -o \$@
EOF
JOBS=$(nproc)
echo "compiling ${#SRCS[@]} files with $JOBS jobs in $WORK"
START=$(date +%s)
nice make -j"$JOBS" --no-print-directory || die "build failed (see the compiler output above)"
echo "built $OUT/pbrt in $(( $(date +%s) - START )) s"
