#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz) and runs each for SECONDS (default 60) on its
# corpus, with its dictionary. Any crash, sanitizer report, leak, timeout (> 10 s for one
# input) or out-of-memory (> 2 GB) fails the run; the input is kept in
# build-asan/fuzz-artifacts/. The corpora grow in build-asan/fuzz-corpus/ from run to run.
#
# Usage: scripts/fuzz.sh [SECONDS] [FUZZER...]     (default: all fuzzers)
#   FUZZ_PARALLEL=N  run N fuzzers at a time (default 1)
#   JOBS=N           build parallelism
# A summary (executions, coverage, corpus size per fuzzer) goes to build-asan/fuzz-report.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
bash scripts/install-deps.sh
bash scripts/install-sanitizer-deps.sh
source scripts/sanitize-env.sh
configure_sanitized_build
cmake --build "$SUBDIV_ASAN_DIR" -j"$SUBDIV_JOBS" --target fuzzers subdiv_cli subdiv_sqrt2 subdiv_circle_preserving

bin=$SUBDIV_ASAN_DIR/tests/fuzz
corpora=$SUBDIV_ASAN_DIR/fuzz-corpus
artifacts=$SUBDIV_ASAN_DIR/fuzz-artifacts
logs=$SUBDIV_ASAN_DIR/fuzz-logs
mkdir -p "$corpora" "$artifacts" "$logs"

# name | dictionary | largest input | seed files
fuzzers=(
  "fuzz_read_obj|obj|4096|examples/meshes/*.obj examples/curves/*.obj"
  "fuzz_read_off|off|4096|@off tests/fuzz/seeds/off/*"
  "fuzz_read_ply|ply|4096|@ply tests/fuzz/seeds/ply/*"
  "fuzz_read_stl|stl|4096|@stl tests/fuzz/seeds/stl/*"
  "fuzz_read_vtp|vtp|16384|@vtp tests/fuzz/seeds/vtp/*"
  "fuzz_read_vtk|vtk|4096|tests/fuzz/seeds/vtk/*"
  "fuzz_read_om|om|4096|tests/fuzz/seeds/om/*"
  "fuzz_scheme|json|16384|schemes/*.json"
  "fuzz_features|features|2048|tests/fuzz/seeds/features/*"
  "fuzz_scheme_sequence|sequence|256|tests/fuzz/seeds/sequence/*"
  "fuzz_params|sequence|256|tests/fuzz/seeds/params/*"
  "fuzz_refine|json|16384|tests/fuzz/seeds/refine/*"
  "fuzz_write_read|write|2048|tests/fuzz/seeds/write/*"
  "fuzz_plugin_file|elf|262144|@so"
  "fuzz_points_file|points|4096|tests/fuzz/seeds/points/*"
)

# Seeds in formats the examples do not come in: the example meshes written by `subdiv`.
converted=$SUBDIV_ASAN_DIR/fuzz-seeds
if [ ! -d "$converted" ]; then
  mkdir -p "$converted.tmp"
  for mesh in examples/meshes/cube.obj examples/meshes/octahedron.obj examples/meshes/plane-with-hole.obj \
              examples/meshes/cube-creased.obj; do
    stem=$(basename "$mesh" .obj)
    for ext in off ply stl vtp; do
      "$SUBDIV_ASAN_DIR/tools/subdiv/subdiv" refine "$mesh" -l 0 -q -o "$converted.tmp/$stem.$ext" || true
    done
  done
  mv "$converted.tmp" "$converted"
fi

wanted=("$@")
selected() {
  [ ${#wanted[@]} -eq 0 ] && return 0
  local w
  for w in "${wanted[@]}"; do [ "$w" = "$1" ] && return 0; done
  return 1
}

run_one() {
  local name=$1 dict=$2 max_len=$3 seeds=$4
  local corpus=$corpora/$name
  mkdir -p "$corpus"
  local s
  for s in $seeds; do
    case $s in
      @so) cp -n "$SUBDIV_ASAN_DIR"/plugins/*.so "$corpus"/ 2>/dev/null || true ;;  # the built plugins
      @*) cp -n "$converted"/*."${s#@}" "$corpus"/ 2>/dev/null || true ;;
      */scheme.schema.json) ;;  # the JSON Schema, not a scheme
      *) if [ -f "$s" ]; then cp -n "$s" "$corpus"/; fi ;;
    esac
  done
  # The exit status goes to a file: bash forgets finished background jobs once `jobs` has
  # reported them, so `wait PID` cannot be trusted for it.
  local status=0 lsan=$LSAN_OPTIONS
  case $name in  # VTK's leaks on its own error paths: see the suppression file
    fuzz_read_vtp | fuzz_read_vtk) lsan="suppressions=$PWD/tests/sanitizers/lsan-vtk-readers.supp:print_suppressions=0" ;;
  esac
  LSAN_OPTIONS=$lsan "$bin/$name" "$corpus" -dict="tests/fuzz/dict/$dict.dict" -max_len="$max_len" -max_total_time="$seconds" \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -close_fd_mask=1 \
    -artifact_prefix="$artifacts/$name-" >"$logs/$name.log" 2>&1 || status=$?
  echo "$status" >"$logs/$name.status"
}

pids=()
names=()
parallel=${FUZZ_PARALLEL:-1}
for entry in "${fuzzers[@]}"; do
  IFS='|' read -r name dict max_len seeds <<<"$entry"
  selected "$name" || continue
  echo "fuzzing $name for ${seconds}s"
  rm -f "$logs/$name.status"
  run_one "$name" "$dict" "$max_len" "$seeds" &
  pids+=($!)
  names+=("$name")
  while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do sleep 1; done
done

failed=0
report=$SUBDIV_ASAN_DIR/fuzz-report.txt
printf '%-22s %8s %12s %10s %8s %8s %s\n' fuzzer seconds executions exec/s cov ft corpus >"$report"
for i in "${!pids[@]}"; do
  name=${names[$i]}
  wait "${pids[$i]}" 2>/dev/null || true
  status=ok
  [ "$(cat "$logs/$name.status" 2>/dev/null || echo missing)" = 0 ] || status=FAILED
  log=$logs/$name.log
  # (|| true: a fuzzer that crashed at once prints no statistics)
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | awk '{print $2}' | tail -1 || true)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | awk '{print $2}' | tail -1 || true)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | awk '{print $2}' || true)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | awk '{print $2}' || true)
  files=$(find "$corpora/$name" -type f | wc -l)
  printf '%-22s %8s %12s %10s %8s %8s %s %s\n' "$name" "$seconds" "${execs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" \
    "$files" "$status" >>"$report"
  if [ "$status" != ok ]; then
    failed=1
    echo "== $name failed; the end of $log:"
    tail -40 "$log"
  fi
done
cat "$report"
[ "$failed" -eq 0 ] || { echo "fuzzing found problems; inputs in $artifacts"; exit 1; }
