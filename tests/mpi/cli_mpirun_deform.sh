#!/usr/bin/env bash
# `mpirun -np P dgwarp deform MESH -m MOTION -o OUT --json` (docs/MPI.md):
# one output file, written by rank 0, the same bytes as one process's; one
# report, with "processes": P, valid against docs/schema/deform.schema.json.
#   cli_mpirun_deform.sh MPIRUN DGWARP SOURCE_DIR WORK_DIR P MESH MOTION METHOD
set -euo pipefail
mpirun=$1 dgwarp=$2 source=$3 work=$4 np=$5 mesh=$6 motion=$7 method=$8
rm -rf "$work" && mkdir -p "$work" && cd "$work"

"$dgwarp" deform "$mesh" -m "$motion" --method "$method" -o one.su2 -q
"$mpirun" --oversubscribe --bind-to none -np "$np" "$dgwarp" deform "$mesh" -m "$motion" --method "$method" \
  -o many.su2 --json > report.json
cmp one.su2 many.su2 || { echo "DIFFERENT: $np processes wrote another mesh than one process"; exit 1; }
# One report (not P), from rank 0, with the number of processes.
[ "$(grep -c '"schema_version"' report.json)" = 1 ] || { echo "expected one report"; cat report.json; exit 1; }
/usr/bin/python3 - "$np" <<'PY'
import json, sys
r = json.load(open("report.json"))
np = int(sys.argv[1])
assert r["processes"] == np, r["processes"]
if np > 1:
    assert len(r["plan"]["process_seconds"]) == np
    assert all(len(f["process_seconds"]) == np for f in r["frames"])
PY
/usr/bin/python3 "$source/tests/tools/check_json_schema.py" "$source/docs/schema" deform report.json
# Nothing but the output and the report was left behind (no temporary file of a rank).
[ "$(ls | sort | tr '\n' ' ')" = "many.su2 one.su2 report.json " ] || { echo "unexpected files:"; ls; exit 1; }
# Bad input: every rank exits with rank 0's code (2), not rank 0 alone.
if [ "$np" -gt 1 ]; then
  "$mpirun" --oversubscribe --bind-to none -np "$np" bash -c \
    '"$0" deform "$1" -m no-such-motion.json -o bad.su2 -q 2> /dev/null; echo "exit $?"' "$dgwarp" "$mesh" \
    > codes.txt || true
  [ "$(grep -c '^exit 2$' codes.txt)" = "$np" ] || { echo "expected every rank to exit 2:"; cat codes.txt; exit 1; }
  rm codes.txt
fi
echo "same bytes: $np processes, $method, one report with processes = $np"
