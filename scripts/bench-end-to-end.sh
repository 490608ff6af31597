#!/bin/sh
# End to end: `subdiv refine` of an NU x NV quad torus (tools/bench/torus_obj.py) to level L
# into .vtp, against the refinement alone, in one run (docs/benchmarks.md, "End to end").
#
#   scripts/bench-end-to-end.sh [BUILD_DIR] [-- extra refine options per run, see RUNS]
#
# Environment: NU, NV (1000 x 1000: 1M faces), LEVELS (2), WORK (a scratch folder, which
# must hold the torus and ~2 GB of output), BEFORE (optional: another `subdiv` binary, e.g.
# an older build, timed first with the same input), RUNS (the option sets to time, one per
# line; default: the defaults (LZ4, base64), then no compression, raw appended data with LZ4
# and without compression, and every array; RUNS="" runs the defaults alone), EXT (vtp: the output's extension; pvtp for
# `--pieces` runs, whose piece files count in the file size). For every run it prints wall, user and system
# time and peak memory (GNU time), the load average before and after, and, from
# `subdiv refine --timings` in the same process (BEFORE too, if it has the option), the time reading the mesh, refining (topology and every level's values:
# the refinement alone) and writing, and end to end / refinement.
set -eu
BUILD=${1:-build}
SUBDIV=$BUILD/tools/subdiv/subdiv
NU=${NU:-1000}
NV=${NV:-1000}
LEVELS=${LEVELS:-2}
WORK=${WORK:-/tmp/subdiv-bench-e2e}
EXT=${EXT:-vtp}
RUNS=${RUNS-"
--compression none
--vtp-encoding raw
--vtp-encoding raw --compression none
--arrays all"}
here=$(cd "$(dirname "$0")/.." && pwd)
[ -x "$SUBDIV" ] || { echo "bench-end-to-end: no $SUBDIV; build the subdiv_cli target first" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "bench-end-to-end: needs GNU time (/usr/bin/time; apt-get install time)" >&2; exit 1; }
mkdir -p "$WORK"
mesh=$WORK/torus_${NU}x${NV}.obj
[ -f "$mesh" ] || python3 "$here/tools/bench/torus_obj.py" "$NU" "$NV" "$mesh"

# One run: $1 label, $2 binary, rest: refine options.
run() {
  label=$1 bin=$2
  shift 2
  out=$WORK/out.$EXT
  rm -rf "$WORK"/out*
  load_before=$(cut -d' ' -f1-3 /proc/loadavg)
  /usr/bin/time -f "%e %U %S %M" -o "$WORK/time.txt" "$bin" refine "$mesh" -l "$LEVELS" -o "$out" "$@" \
    2> "$WORK/stderr.txt" > /dev/null || { cat "$WORK/stderr.txt" >&2; exit 1; }
  load_after=$(cut -d' ' -f1-3 /proc/loadavg)
  size=$(du -cb "$WORK"/out* | tail -n 1 | cut -f1)  # with a .pvtp's piece files
  read -r wall user sys peak_kb < "$WORK/time.txt"
  # --timings lines: "subdiv:   1.234 s  peak   0.22 GB  <step>"; older binaries print none.
  awk -v label="$label" -v wall="$wall" -v user="$user" -v sys="$sys" -v peak="$peak_kb" -v size="$size" \
      -v lb="$load_before" -v la="$load_after" '
    /^subdiv: .* s  peak/ {
      t = $2; step = $0; sub(/.*GB  /, "", step)
      if (step ~ /^reading/) read += t
      else if (step ~ /^(refining topology|level [0-9]+\/)/) refine += t
      else if (step ~ /^writing/) write += t
      timed = 1
    }
    END {
      printf "%-28s wall %6.2f s  user %6.2f s  sys %5.2f s  peak %5.2f GB  file %7.1f MB  load %s -> %s\n",
             label, wall, user, sys, peak / 1048576, size / 1e6, lb, la
      if (timed)
        printf "%-28s read %6.2f s  refine %6.2f s  write %6.2f s  end to end / refine %5.2f\n", "", read, refine,
               write, wall / refine
    }' "$WORK/stderr.txt"
  rm -rf "$WORK"/out*
}

echo "subdiv refine $(basename "$mesh") ($NU x $NV quads) -l $LEVELS -o .$EXT, $(nproc) cores"
if [ -n "${BEFORE:-}" ]; then
  libs="$(dirname "$BEFORE")${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"  # its own libraries next to it, if copied there
  timings=
  LD_LIBRARY_PATH="$libs" "$BEFORE" refine --help 2>/dev/null | grep -q -- --timings && timings=--timings
  # shellcheck disable=SC2086  # no word, or one
  LD_LIBRARY_PATH="$libs" run "before: $BEFORE" "$BEFORE" $timings
fi
printf '%s\n' "$RUNS" | while IFS= read -r options; do
  # shellcheck disable=SC2086  # the options are words
  run "${options:-(defaults)}" "$SUBDIV" --timings $options
done
