#!/usr/bin/env bash
# `mpirun -np P dgwarp deform CASE ...` on a decomposed OpenFOAM case of P
# processors (docs/MPI.md): each process reads only its own processor folder
# and writes only its own, and the files are one process's, byte for byte
# (into the case itself and into another folder); one report with
# "processes": P. A motion that inverts cells, or a damaged processor folder
# (read by one process only), fails on every process with nothing written.
# MARKER moves by MOVE (a JSON vector), then by SINK (which inverts cells).
#   cli_mpirun_openfoam_parts.sh MPIRUN DGWARP SOURCE_DIR CASE WORK_DIR P METHOD MARKER MOVE SINK
set -euo pipefail
mpirun=$1 dgwarp=$2 source=$3 case=$4 work=$5 np=$6 method=$7 marker=$8 move=$9 sink=${10}
command -v strace > /dev/null || { echo "strace is needed to see which files each process opens (scripts/install-deps.sh)"; exit 1; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"
cp -r "$case" one && cp -r "$case" many && cp -r "$case" input
motion=move.json
echo "{\"markers\": {\"$marker\": {\"translate\": $move}}, \"default\": \"fixed\", \"shared_nodes\": \"moving_wins\"}" > move.json
echo "{\"markers\": {\"$marker\": {\"translate\": $sink}}, \"default\": \"fixed\", \"shared_nodes\": \"moving_wins\"}" > sink.json
run() { "$mpirun" --oversubscribe --bind-to none -np "$np" "$dgwarp" "$@"; }

"$dgwarp" deform one -m "$motion" --method "$method" -o one -q
# Every process's file opens, creations and renames.
strace -f -qq -e trace=openat,open,creat,rename,renameat,renameat2 -o trace \
  "$mpirun" --oversubscribe --bind-to none -np "$np" "$dgwarp" deform many -m "$motion" --method "$method" \
  -o many --json > report.json
diff -r one many || { echo "DIFFERENT: the processors' points differ from one process's"; exit 1; }
run deform input -m "$motion" --method "$method" -o out -q
for p in one/processor*; do
  cmp "$p/0/polyMesh/points" "out/$(basename "$p")/0/polyMesh/points" || { echo "DIFFERENT: out/$p"; exit 1; }
done

# A series (plunging, three frames): every time folder the same as one process's.
echo "{\"markers\": {\"$marker\": {\"periodic\": {\"plunge\": {\"amplitude\": $move, \"frequency\": 1, \"phase_deg\": 90}}}}, \"default\": \"fixed\", \"time\": {\"time_step\": 0.25, \"steps\": 3}}" > series.json
"$dgwarp" deform input -m series.json --method "$method" -o series_one -q
run deform input -m series.json --method "$method" -o series_many -q
diff -r series_one series_many || { echo "DIFFERENT: a series on $np processes"; exit 1; }
[ "$(ls series_many/processor0 | tr '\n' ' ')" = "0 0.25 0.5 constant " ] || { echo "time folders:"; ls series_many/processor0; exit 1; }

[ "$(grep -c '"schema_version"' report.json)" = 1 ] || { echo "expected one report"; cat report.json; exit 1; }
/usr/bin/python3 "$source/tests/tools/check_json_schema.py" "$source/docs/schema" deform report.json
/usr/bin/python3 - "$np" <<'PY'
import json, re, sys
np = int(sys.argv[1])
r = json.load(open("report.json"))
assert r["processes"] == np, r["processes"]
assert len(r["plan"]["process_seconds"]) == np and all(len(f["process_seconds"]) == np for f in r["frames"])
# Which processor folders each process touched (read, created or renamed in).
touched = {}
for line in open("trace"):
    for n in re.findall(r'["/]many/processor(\d+)/', line):
        touched.setdefault(line.split()[0], set()).add(int(n))
folders = sorted(tuple(sorted(s)) for s in touched.values())
assert folders == [(n,) for n in range(np)], f"processor folders touched by each process: {folders}"
print(f"{np} processes, each touched only its own processor folder")
PY

# A motion that inverts cells: every process fails (exit 3), nothing is written.
status=0
run deform input -m sink.json --method "$method" -o sunk -q 2> sink.err || status=$?
[ "$status" = 3 ] || { echo "expected exit 3 for inverted cells, got $status"; cat sink.err; exit 1; }
grep -q "inverted cell" sink.err || { echo "no inverted cells named:"; cat sink.err; exit 1; }
[ -z "$(find sunk -name points 2> /dev/null)" ] || { echo "points written for an invalid frame"; exit 1; }

# A damaged points file that only the last process reads: every process stops
# (exit 2), the error names the process and the file, and no process wrote its points.
last=$((np - 1))
cp -r "$case" damaged
head -c 300 "damaged/processor$last/constant/polyMesh/points" > cut && mv cut "damaged/processor$last/constant/polyMesh/points"
status=0
run deform damaged -m "$motion" --method "$method" -o damaged_out -q 2> damaged.err || status=$?
[ "$status" = 2 ] || { echo "expected exit 2 for a damaged processor, got $status"; cat damaged.err; exit 1; }
grep -q "process $last: .*processor$last/constant/polyMesh/points" damaged.err || { echo "error not naming it:"; cat damaged.err; exit 1; }
[ -z "$(find damaged_out -name points 2> /dev/null)" ] || { echo "points written after an error"; exit 1; }
[ "$(grep -c 'dgwarp: ' damaged.err)" = 1 ] || { echo "expected one error message (rank 0's)"; cat damaged.err; exit 1; }
echo "same files: $np processes, each reading and writing its own processor folder ($method)"
