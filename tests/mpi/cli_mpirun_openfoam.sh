#!/usr/bin/env bash
# `mpirun -np 2 dgwarp deform CASE -m MOTION -o CASE` on a decomposed OpenFOAM
# case with 2 processors (docs/MPI.md): each process deforms its processor's
# points, and every processor's points file is written as by one process.
#   cli_mpirun_openfoam.sh MPIRUN DGWARP CASE MOTION WORK_DIR
set -euo pipefail
mpirun=$1 dgwarp=$2 case=$3 motion=$4 work=$5
rm -rf "$work" && mkdir -p "$work"
cp -r "$case" "$work/one" && cp -r "$case" "$work/many"
"$dgwarp" deform "$work/one" -m "$motion" -o "$work/one" -q
"$mpirun" --oversubscribe --bind-to none -np 2 "$dgwarp" deform "$work/many" -m "$motion" -o "$work/many" --json \
  > "$work/report.json"
grep -q '"processes": 2' "$work/report.json" || { echo "no processes = 2 in the report"; exit 1; }
ls "$work"/many/processor*/0/polyMesh/points > /dev/null
diff -r "$work/one" "$work/many" || { echo "DIFFERENT: the processors' points differ from one process's"; exit 1; }
echo "same files: every processor's points as one process writes them"
