#!/usr/bin/env bash
# Fuzzes dgwarp's readers with libFuzzer (clang, ASan + UBSan).
#
#   scripts/fuzz.sh [SECONDS] [TARGETS...]
#
# SECONDS per target (default 60); TARGETS among su2 gmsh vtu openfoam cgns motion plan (default:
# all). FUZZ_JOBS=2 runs two targets at a time (each fuzzer uses one core).
# Builds in build-fuzz/ (DGWARP_FUZZ=ON, clang++). Each target starts from its
# seed corpus fuzz/corpus/<target>/ and the inputs found in earlier runs
# (build-fuzz/corpus/<target>/, not committed). A crash, leak, timeout or
# out-of-memory input is saved in build-fuzz/crashes/<target>/; the script
# prints where and exits with status 1. Add each such input to
# tests/data/fuzz_regressions/<target>/ once fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(su2 gmsh vtu openfoam cgns motion plan)
jobs=${FUZZ_JOBS:-1}
build=build-fuzz

case "$seconds" in
  ''|*[!0-9]*) echo "usage: scripts/fuzz.sh [SECONDS] [su2|gmsh|vtu|openfoam|cgns|motion|plan ...]" >&2; exit 2 ;;
esac
for t in "${targets[@]}"; do
  case "$t" in
    su2|gmsh|vtu|openfoam|cgns|motion|plan) ;;
    *) echo "fuzz.sh: unknown target '$t' (su2, gmsh, vtu, openfoam, cgns, motion, plan)" >&2; exit 2 ;;
  esac
done

scripts/install-deps.sh fuzz
mkdir -p "$build"
if [ ! -f "$build/CMakeCache.txt" ]; then
  # Optimised, with debug info and assertions (no NDEBUG): a failed assert is a finding too.
  cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g" \
    -DDGWARP_FUZZ=ON -DDGWARP_BUILD_TESTS=OFF -DDGWARP_BUILD_BENCH=OFF >"$build/configure.log" 2>&1 \
    || { cat "$build/configure.log"; exit 1; }
fi
echo "fuzz.sh: building ${targets[*]/#/fuzz_} (log: $build/build.log)"
cmake --build "$build" -j "${FUZZ_BUILD_JOBS:-2}" --target "${targets[@]/#/fuzz_}" >"$build/build.log" 2>&1 \
  || { grep -E -B2 -A8 'error' "$build/build.log" | head -60; echo "fuzz.sh: build failed: see $build/build.log"; exit 1; }

# Longest input per target: a few times the largest seed, small enough that
# every execution is quick.
max_len() {
  case "$1" in
    su2|gmsh) echo 16384 ;;
    vtu) echo 32768 ;;
    openfoam) echo 32768 ;;
    cgns) echo 65536 ;;  # HDF5 files are large: the seeds are 12-33 KB
    motion) echo 4096 ;;
    plan) echo 16384 ;;
  esac
}
dict() {
  case "$1" in
    su2) echo fuzz/dict/su2.dict ;;
    gmsh) echo fuzz/dict/gmsh.dict ;;
    vtu) echo fuzz/dict/vtu.dict ;;
    openfoam) echo fuzz/dict/openfoam.dict ;;
    cgns) echo fuzz/dict/cgns.dict ;;
    motion) echo fuzz/dict/json.dict ;;
    plan) echo fuzz/dict/plan.dict ;;
  esac
}

run_one() {
  local t=$1
  local work="$build/corpus/$t" crashes="$build/crashes/$t" log="$build/fuzz-$t.log"
  mkdir -p "$work" "$crashes"
  # The CGNS target writes each input to a file and writes two files from it
  # (each synced to disk): in memory (/dev/shm) when there is one, it runs
  # several times faster.
  local tmp=${TMPDIR:-/tmp}
  [ "$t" = cgns ] && [ -d /dev/shm ] && [ -w /dev/shm ] && tmp=/dev/shm
  # One thread: deform_dg_idw (plan target) would otherwise start a thread per core.
  # tests/lsan.supp: the third-party leaks the test suite suppresses too
  # (libcgns cannot free the half-read tree of a damaged file).
  TMPDIR=$tmp LSAN_OPTIONS="suppressions=$root/tests/lsan.supp:print_suppressions=0" OMP_NUM_THREADS=1 nice "$build/fuzz/fuzz_$t" "$work" "fuzz/corpus/$t" \
    -max_total_time="$seconds" -max_len="$(max_len "$t")" -rss_limit_mb=2048 -malloc_limit_mb=512 \
    -timeout=10 -dict="$(dict "$t")" -artifact_prefix="$crashes/" -print_final_stats=1 \
    >"$log" 2>&1
}

summary() {
  local t=$1 status=$2 log="$build/fuzz-$t.log"
  local execs done_line
  execs=$(grep -E '^stat::number_of_executed_units:' "$log" | awk '{print $2}' | tail -1)
  # libFuzzer's last status line: "#N DONE cov: C ft: F corp: units/size ..."
  done_line=$(grep -E '^#[0-9]+[[:space:]]+DONE' "$log" | tail -1 | sed -E 's/.*(cov: [0-9]+).*(corp: [0-9]+\/[0-9]+[a-zA-Z]*).*/\1, \2/')
  if [ "$status" -eq 0 ]; then
    echo "fuzz.sh: $t: ok, ${seconds} s, ${execs:-?} executions, ${done_line:-no summary}"
    return 0
  fi
  echo "fuzz.sh: $t: FAILED (status $status) after ${execs:-?} executions; log: $log"
  grep -E '^==[0-9]+==ERROR|SUMMARY:|runtime error|terminate called|what\(\)|Test unit written to' "$log" | head -10 | sed 's/^/  /'
  return 1
}

failed=0
declare -A pids=()
running=()
finish() {  # waits for the oldest running target
  local t=${running[0]} status=0
  wait "${pids[$t]}" || status=$?
  running=("${running[@]:1}")
  summary "$t" "$status" || failed=1
}
for t in "${targets[@]}"; do
  [ ${#running[@]} -ge "$jobs" ] && finish
  echo "fuzz.sh: $t: fuzzing for $seconds s (log: $build/fuzz-$t.log)"
  run_one "$t" &
  pids[$t]=$!
  running+=("$t")
done
while [ ${#running[@]} -gt 0 ]; do finish; done

if [ "$failed" -ne 0 ]; then
  echo "fuzz.sh: crash inputs are in $root/$build/crashes/<target>/; reproduce with"
  echo "  $build/fuzz/fuzz_<target> <input>"
  echo "and, once fixed, copy each input to tests/data/fuzz_regressions/<target>/."
  exit 1
fi
