#!/bin/bash -eu
# Builds collide's fuzz targets the OSS-Fuzz way: $CXX and $CXXFLAGS for every translation unit
# (the library, the exact oracle, the laws and the targets, so coverage reaches all of them),
# $LIB_FUZZING_ENGINE at link time, binaries, their seed archives (fuzz/seeds) and options into $OUT.
# With them the judge's targets judge_<adapter> (judge/fuzz) whose library the image has: their
# Debian libraries are not instrumented (coverage comes from the adapters and the judge), and
# their shared objects are copied to $OUT/lib, where the binaries look first ($ORIGIN/lib).
#
# Inputs (set by ClusterFuzzLite / OSS-Fuzz, or by scripts/check_build_sh.py locally):
#   CXX CXXFLAGS LIB_FUZZING_ENGINE OUT; WORK (scratch, optional); SRC (checkout parent, optional)
#   COLLIDE_JOBS (build parallelism, default: all cores)

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [[ ! -f "$ROOT/fuzz/CMakeLists.txt" ]]; then
  ROOT="${SRC:?}/collide"  # OSS-Fuzz copies this script to $SRC/build.sh
fi
BUILD="${WORK:-/tmp}/collide-fuzz-build"
JOBS="${COLLIDE_JOBS:-$(nproc)}"

# Static GMP/MPFR, named by path (CGAL's find modules would pick the shared ones; the runner image
# need not have them). The oracle needs their C libraries only, no gmpxx, so the -stdlib=libc++ of
# $CXXFLAGS links. No benchmarks; the engine only at link time. Configure stops with a clear
# message when the image lacks the CGAL, Boost or Eigen versions the code needs
# (oracles/exact/CMakeLists.txt; the Dockerfile provides them).
static_lib() {
  local path
  path="$("${CC:-cc}" -print-file-name="$1")"
  [[ "$path" == /* && -f "$path" ]] || { echo "build.sh: $1 not found (install libgmp-dev, libmpfr-dev)" >&2; exit 1; }
  printf '%s' "$path"
}
GMP_A="$(static_lib libgmp.a)"
MPFR_A="$(static_lib libmpfr.a)"
cmake -S "$ROOT" -B "$BUILD" -G Ninja \
  -DCMAKE_BUILD_TYPE= \
  -DCMAKE_CXX_COMPILER="$CXX" \
  -DCMAKE_CXX_FLAGS="$CXXFLAGS" \
  -DGMP_LIBRARY_RELEASE="$GMP_A" -DGMP_LIBRARY_DEBUG="$GMP_A" \
  -DMPFR_LIBRARIES="$MPFR_A" \
  -DCOLLIDE_BUILD_BENCH=OFF \
  -DCOLLIDE_FUZZ_ENGINE="$LIB_FUZZING_ENGINE"

TARGETS="$(sed -n 's/^COLLIDE_FUZZ_TARGETS:INTERNAL=//p' "$BUILD/CMakeCache.txt" | tr ';' ' ')"
JUDGE_TARGETS="$(sed -n 's/^COLLIDE_JUDGE_FUZZ_TARGETS:INTERNAL=//p' "$BUILD/CMakeCache.txt" | tr ';' ' ')"
if [[ -z "$TARGETS" ]]; then
  echo "build.sh: no fuzz targets configured (is collide::laws available?)" >&2
  exit 1
fi
BUILD_TARGETS=()
TARGETS="$TARGETS $JUDGE_TARGETS"
for t in $TARGETS; do BUILD_TARGETS+=("fuzz_$t"); done
cmake --build "$BUILD" -j "$JOBS" --target "${BUILD_TARGETS[@]}"

# The seeds are committed as OSS-Fuzz wants them, one archive per target; the corpus that grows
# lives in the workflows' storage repository.
mkdir -p "$OUT"
for t in $TARGETS; do
  seeds="$ROOT/fuzz/seeds/${t}_seed_corpus.zip"
  [[ -f "$seeds" ]] || { echo "build.sh: no seed archive $seeds (./harness fuzz --export-seeds writes it)" >&2; exit 1; }
  cp "$BUILD/fuzz/bin/$t" "$OUT/$t"
  cp "$seeds" "$OUT/${t}_seed_corpus.zip"
  printf '[libfuzzer]\nmax_len = 4096\n' > "$OUT/$t.options"
done
for t in $JUDGE_TARGETS; do
  ldd "$BUILD/fuzz/bin/$t" | awk '$1 ~ /^lib(box2d|chipmunk)[.]/ && $3 ~ /^\// {print $3}' | while read -r lib; do
    mkdir -p "$OUT/lib"
    cp -L "$lib" "$OUT/lib/"
  done
done
echo "build.sh: built $TARGETS into $OUT"
