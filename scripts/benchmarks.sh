#!/bin/sh
# Every figure of docs/benchmarks.md in one run, then its tables and chart
# (scripts/bench_report.py).
#
#   scripts/benchmarks.sh [BUILD_DIR] [OUT_DIR]
#
# Needs the Release build of subdiv-bench, subdiv-bench-meshlibs, subdiv-bench-stages,
# subdiv-bench-io and subdiv (`cmake --build build --target subdiv-bench subdiv-bench-meshlibs
# subdiv-bench-stages subdiv-bench-io subdiv_cli`). Writes each
# program's output into OUT_DIR (default /tmp/subdivkit-bench-<UTC date-time>), then fills the
# tables of docs/benchmarks.md and draws docs/images/benchmarks.svg from them (PAGE=no leaves
# the page alone and prints the tables). On a quiet 2-core machine it runs about 32 minutes
# (QUICK=1 took 2.5 minutes at load 9).
#
# Environment: ROUNDS (3: worker processes per side, alternating, best of each side),
# FACES (1000000), QUICK=1 (a smoke run: 20k faces, one round, sizes up to 160k faces, a
# 150 x 150 torus end to end),
# SKIP (space-separated parts to leave out: refine update threads stages streaming sizes
# meshlibs e2e io big).
set -eu
BUILD=${1:-build}
OUT=${2:-${TMPDIR:-/tmp}/subdivkit-bench-$(date -u +%Y%m%d-%H%M)}
here=$(cd "$(dirname "$0")/.." && pwd)
BENCH=$BUILD/tools/bench
ROUNDS=${ROUNDS:-3}
FACES=${FACES:-1000000}
SIZES="10000 40000 160000 640000 2500000 4000000"
if [ "${QUICK:-0}" = 1 ]; then
  ROUNDS=1 FACES=20000 SIZES="10000 40000 160000"
  NU=${NU:-150} NV=${NV:-150}
  export NU NV
fi
SKIP=" ${SKIP:-} "
[ -x "$BENCH/subdiv-bench" ] || { echo "benchmarks: no $BENCH/subdiv-bench; build it first (see the top of $0)" >&2; exit 1; }
mkdir -p "$OUT"
wants() { case "$SKIP" in *" $1 "*) return 1 ;; *) return 0 ;; esac; }
step() { echo "[$(date -u +%H:%M:%S), load $(cut -d' ' -f1-3 /proc/loadavg)] $*" >&2; }

if wants refine; then
  step "OpenSubdiv refine, levels 1-3"
  "$BENCH/subdiv-bench" --faces "$FACES" --levels 1-3 --rounds "$ROUNDS" > "$OUT/refine.txt"
fi
if wants update; then
  step "repeated evaluation"
  "$BENCH/subdiv-bench" --faces "$FACES" --mode update --levels 1-2 --repeat 10 --rounds "$ROUNDS" > "$OUT/update.txt"
fi
if wants threads; then
  for t in 1 2; do
    step "threads: $t"
    "$BENCH/subdiv-bench" --faces "$FACES" --side subdivkit --levels 1-2 --repeat 3 --rounds "$ROUNDS" --threads "$t" \
      --check off > "$OUT/threads$t.txt"
  done
  # Two threads while another process keeps one core busy: what the scheduler then gives.
  step "threads: 2, the other core busy"
  sh -c 'while :; do :; done' &
  busy=$!
  "$BENCH/subdiv-bench" --faces "$FACES" --side subdivkit --levels 1-2 --repeat 3 --rounds "$ROUNDS" --threads 2 \
    --check off > "$OUT/threads2-busy.txt" || true
  kill "$busy"
fi
if wants stages && [ -x "$BENCH/subdiv-bench-stages" ]; then
  # Where the time goes, stage by stage, on one and two threads (issue 32, item 1).
  for scheme in catmull-clark loop; do
    for level in 1 2; do
      step "stages: $scheme level $level"
      "$BENCH/subdiv-bench-stages" --scheme "$scheme" --faces "$FACES" --level "$level" --rounds "$((ROUNDS + 2))" \
        > "$OUT/stages-$scheme-$level.txt" || true
    done
  done
fi
if wants streaming; then
  # The same refinement without streaming stores for the last level (util/streaming_stores.h),
  # to compare with refine.txt: the ratios to OpenSubdiv of both runs.
  step "OpenSubdiv refine, levels 1-2, no streaming stores"
  SUBDIV_STREAMING_STORES=0 "$BENCH/subdiv-bench" --faces "$FACES" --levels 1-2 --rounds "$ROUNDS" > "$OUT/refine-nostream.txt"
fi
if wants sizes; then
  for f in $SIZES; do
    step "level 1 of $f faces"
    "$BENCH/subdiv-bench" --faces "$f" --levels 1 --rounds "$ROUNDS" > "$OUT/sizes-$f.txt"
  done
fi
if wants meshlibs && [ -x "$BENCH/subdiv-bench-meshlibs" ]; then
  step "OpenMesh and CGAL"
  for last in full faces; do
    "$BENCH/subdiv-bench-meshlibs" --faces "$FACES" --schemes sqrt3,doo-sabin,modified-butterfly,loop,catmull-clark \
      --levels 1,2 --repeat 3 --last-level "$last" > "$OUT/meshlibs-$last.txt" || true
  done
fi
if wants e2e && [ -x "$BUILD/tools/subdiv/subdiv" ]; then
  step "end to end"
  RUNS="
--compression none" "$here/scripts/bench-end-to-end.sh" "$BUILD" > "$OUT/e2e.txt" || true
fi
if wants io && [ -x "$BENCH/subdiv-bench-io" ]; then
  # Writers against VTK's (16M faces, clean page cache, then with the first file's pages
  # dirty), readers against VTK's and OpenMesh's (4M faces: VTK's OBJ reader is slow).
  step "writing .vtp"
  "$BENCH/subdiv-bench-io" --faces "$((FACES * 16))" --rounds "$ROUNDS" --reads false > "$OUT/io-write.txt" || true
  step "reading .vtp, .obj, .ply"
  "$BENCH/subdiv-bench-io" --faces "$((FACES * 4))" --rounds "$ROUNDS" --writes false > "$OUT/io-read.txt" || true
fi
if wants big && [ -x "$BUILD/tools/subdiv/subdiv" ]; then
  # Level 3 of the torus (64M faces at the default size), whole and in pieces within 4 GB.
  step "a big level, whole"
  LEVELS=3 RUNS="" "$here/scripts/bench-end-to-end.sh" "$BUILD" > "$OUT/big-whole.txt" || true
  step "a big level, in pieces"
  LEVELS=3 EXT=pvtp RUNS="--pieces 8 --max-memory 4G" "$here/scripts/bench-end-to-end.sh" "$BUILD" \
    > "$OUT/big-pieces.txt" || true
fi
step "done: $OUT"
if [ "${PAGE:-yes}" = no ]; then
  python3 "$here/scripts/bench_report.py" "$OUT" --chart "$OUT/benchmarks.svg"
else
  python3 "$here/scripts/bench_report.py" "$OUT" --page "$here/docs/benchmarks.md" --chart "$here/docs/images/benchmarks.svg"
fi
