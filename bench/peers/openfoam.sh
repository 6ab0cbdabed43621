#!/usr/bin/env bash
# bench/peers/openfoam.sh: dgwarp against OpenFOAM's own mesh motion (moveMesh,
# displacementLaplacian), on the same mesh and the same boundary motion (#15 item 4;
# docs/RESULTS.md, "dgwarp against OpenFOAM's moveMesh", says what it measures).
#
# Usage: bench/peers/openfoam.sh [options] [CASE ...]
#   CASE            sphere0 (squeezed-sphere --size 0, motion squeeze), sphere2 (--size 2),
#                   wing1 (wing-body --size 1, motion fold-20); default: all three
#   --mesh NAME MESH MOTION
#                   another case: a 3D mesh file (.su2, .msh, .vtu) and a motion file
#   --work DIR      where meshes, cases and logs go (default build/peer-openfoam); the case
#                   meshes are made once (`dgwarp case`) and reused from DIR/meshes
#   --dgwarp PATH   the dgwarp binary (default build/dgwarp)
#   --methods LIST  dgwarp runs, comma-separated (default: all of dg-harmonic, dg-idw,
#                   dg-idw-auto, dg-idw-continuous, dg-idw-untangle, dgm, idw, rbf; rbf and idw
#                   are skipped where `dgwarp bench` skips them)
#   --checkmesh LIST
#                   the dgwarp runs whose result checkMesh checks, comma-separated (default: all;
#                   none: only the original and OpenFOAM's results; each takes a minute on the
#                   size-2 sphere)
#   --skip-openfoam run everything but OpenFOAM (the test suite does, on a tiny mesh)
#
# It installs nothing. Without OpenFOAM (moveMesh and checkMesh, on the PATH or after sourcing
# $FOAM_BASHRC, /usr/share/openfoam/etc/bashrc or /usr/lib/openfoam/openfoam*/etc/bashrc) it says
# so and exits 0 (unless --skip-openfoam). Peak memory needs GNU time (/usr/bin/time, Debian
# package `time`): without it the script says so and leaves that column empty.
#
# For each case:
#  1. the mesh (an SU2 file) becomes an OpenFOAM case, BASE = WORK/NAME/base: `dgwarp convert
#     MESH BASE/ --foam-format binary`; OpenFOAM's checkMesh checks it (the polyMesh dgwarp wrote).
#  2. `dgwarp motion-field` writes BASE/0/pointDisplacement: every patch a fixedValue holding,
#     per point, exactly the displacement dgwarp applies to that boundary node (and a CSV of it).
#  3. OpenFOAM: moveMesh with dynamicMotionSolverFvMesh, displacementLaplacian, diffusivity
#     inverseDistance to the moving patches, GAMG (smoother GaussSeidel), in two set-ups:
#       usual:     laplacian `Gauss linear corrected`, tolerance 1e-5, relTol 0, GAMG's default
#                  iterations (maxIter 1000, nCellsInCoarsestLevel 10): OpenFOAM's wingMotion tutorial
#       converged: `Gauss linear uncorrected`, tolerance 0, relTol 0, minIter 20, maxIter 20: exactly
#                  20 V-cycles per component (a tolerance of 0 is never met, so maxIter stops it)
#     then checkMesh on the moved mesh (time 1) and dgwarp's quality of it.
#  4. dgwarp: `dgwarp deform RUN -m MOTION -o RUN --foam-time 1 --threads 1` per method, each in
#     its own process, reading the same polyMesh (RUN/constant/polyMesh links to BASE's) and
#     writing the moved points as moveMesh does (RUN/1/polyMesh/points); checkMesh on the result.
# Each run: wall time, CPU time (user + system) and peak memory of the process (/usr/bin/time -v), solve time (OpenFOAM:
# from its "Time = 1" line to its last linear-solve line, timestamped as they are printed, so
# the diffusivity, the assembly and the GAMG solves, not reading or writing; dgwarp: prepare +
# step from its --json report), Knupp quality min / mean / inverted (dgwarp's metric, as
# `dgwarp bench`: the OpenFOAM result through `dgwarp quality --reference BASE`), the largest
# boundary error (|moved - original - prescribed| over the boundary nodes: 0 when the run moved
# the boundary exactly as told) and checkMesh's verdict. At the end: a markdown table per case,
# the load of the machine (uptime) before and after, and the time ratios.
#
# Exit: 0 when done (or when OpenFOAM is missing), 1 on a usage error, 2 when a step that must
# work fails (the mesh, the conversion, the motion field).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
tools="/usr/bin/python3 $here/openfoam_tools.py"
work="$root/build/peer-openfoam"
dgwarp="$root/build/dgwarp"
methods="dg-harmonic,dg-idw,dg-idw-auto,dg-idw-continuous,dg-idw-untangle,dgm,idw,rbf"
skip_openfoam=0
checkmesh_runs=all
cases=()
declare -A custom_mesh custom_motion

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//' >&2; exit "${1:-1}"; }

while [ $# -gt 0 ]; do
  case "$1" in
    --work) work=$2; shift 2 ;;
    --dgwarp) dgwarp=$2; shift 2 ;;
    --methods) methods=$2; shift 2 ;;
    --skip-openfoam) skip_openfoam=1; shift ;;
    --checkmesh) checkmesh_runs=$2; shift 2 ;;
    --mesh) [ $# -ge 4 ] || usage
            cases+=("$2"); custom_mesh[$2]=$(realpath "$3"); custom_motion[$2]=$(realpath "$4"); shift 4 ;;
    sphere0|sphere2|wing1) cases+=("$1"); shift ;;
    -h|--help) usage 0 ;;
    *) echo "openfoam.sh: unknown argument '$1'" >&2; usage ;;
  esac
done
[ ${#cases[@]} -gt 0 ] || cases=(sphere0 sphere2 wing1)
[ -x "$dgwarp" ] || { echo "openfoam.sh: no dgwarp at $dgwarp (build it: cmake --build build --target dgwarp)" >&2; exit 2; }
dgwarp=$(realpath "$dgwarp")

# OpenFOAM: on the PATH, or after sourcing its bashrc (which may print errors and return non-zero).
have_openfoam() { command -v moveMesh >/dev/null 2>&1 && command -v checkMesh >/dev/null 2>&1; }
if [ $skip_openfoam = 0 ] && ! have_openfoam; then
  for rc in "${FOAM_BASHRC:-}" /usr/share/openfoam/etc/bashrc /usr/lib/openfoam/openfoam*/etc/bashrc; do
    if [ -n "$rc" ] && [ -f "$rc" ]; then
      set +eu; source "$rc" >/dev/null 2>&1; set -eu
      have_openfoam && break
    fi
  done
fi
if [ $skip_openfoam = 0 ] && ! have_openfoam; then
  echo "openfoam.sh: OpenFOAM is not installed (no moveMesh and checkMesh, also after sourcing its bashrc):"
  echo "nothing to compare with. Debian: apt-get install openfoam; or run with --skip-openfoam for dgwarp alone."
  exit 0
fi
if [ $skip_openfoam = 0 ] && [ -z "${WM_PROJECT_DIR:-}" ]; then
  # Debian's moveMesh finds its etc/controlDict only through the environment the bashrc sets.
  for rc in "${FOAM_BASHRC:-}" /usr/share/openfoam/etc/bashrc /usr/lib/openfoam/openfoam*/etc/bashrc; do
    if [ -n "$rc" ] && [ -f "$rc" ]; then set +eu; source "$rc" >/dev/null 2>&1; set -eu; break; fi
  done
fi
timer=()
if [ -x /usr/bin/time ] && /usr/bin/time -v true >/dev/null 2>&1; then
  timer=(/usr/bin/time -v -o)
else
  echo "openfoam.sh: no GNU time (/usr/bin/time, Debian package 'time'): peak memory is not measured"
fi

mkdir -p "$work/meshes"
work=$(realpath "$work")
results="$work/results.jsonl"
: > "$results"
load_before=$(uptime)
started=$(date -u '+%Y-%m-%d %H:%M UTC')

# timed TIMEFILE COMMAND...: runs COMMAND with its wall time and peak memory in TIMEFILE
# (GNU time's -v report, when there is GNU time, and a line "Wall seconds: S.NNNNNNNNN"); returns its exit code.
timed() {
  local tf=$1; shift
  local t0 t1 rc=0
  t0=$(date +%s%N)
  if [ ${#timer[@]} -gt 0 ]; then "${timer[@]}" "$tf" "$@" || rc=$?; else "$@" || rc=$?; fi
  t1=$(date +%s%N)
  [ ${#timer[@]} -gt 0 ] || : > "$tf"
  # The wall time to the nanosecond clock's resolution (GNU time's is 10 ms: a tiny case read 0.00).
  printf 'Wall seconds: %d.%09d\n' $(((t1 - t0) / 1000000000)) $(((t1 - t0) % 1000000000)) >> "$tf"
  return $rc
}

# The case mesh and motion: made once with `dgwarp case`, or given with --mesh.
case_inputs() {
  local name=$1 kind size motion
  if [ -n "${custom_mesh[$name]:-}" ]; then mesh=${custom_mesh[$name]}; motion_file=${custom_motion[$name]}; return; fi
  case $name in
    sphere0) kind=squeezed-sphere; size=0; motion=squeeze ;;
    sphere2) kind=squeezed-sphere; size=2; motion=squeeze ;;
    wing1) kind=wing-body; size=1; motion=fold-20 ;;
  esac
  mesh="$work/meshes/$name.su2"
  motion_file="$work/meshes/$name-motions/$motion.json"
  if [ ! -f "$mesh" ] || [ ! -f "$motion_file" ]; then
    echo "== $name: dgwarp case $kind --size $size (once; kept in $work/meshes)"
    "$dgwarp" case $kind --size $size -o "$mesh" --motions "$work/meshes/$name-motions" -q ||
      { echo "openfoam.sh: dgwarp case $kind failed" >&2; exit 2; }
  fi
}

write_system() {  # write_system CASE SETUP(usual|converged|check) MOVING_PATCHES
  local dir=$1 setup=$2 patches=$3 lap snap solver
  mkdir -p "$dir/system" "$dir/constant"
  cat > "$dir/system/controlDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application     moveMesh;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         1;
deltaT          1;
writeControl    timeStep;
writeInterval   1;
writeFormat     binary;
writePrecision  17;
writeCompression off;
timeFormat      general;
timePrecision   6;
runTimeModifiable false;
EOF
  if [ "$setup" = converged ]; then
    lap="Gauss linear uncorrected"; snap=uncorrected
    solver="solver GAMG; smoother GaussSeidel; tolerance 0; relTol 0; minIter 20; maxIter 20;"
  else
    lap="Gauss linear corrected"; snap=corrected
    solver="solver GAMG; smoother GaussSeidel; tolerance 1e-5; relTol 0;"
  fi
  cat > "$dir/system/fvSchemes" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object fvSchemes; }
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; }
laplacianSchemes { default $lap; }
interpolationSchemes { default linear; }
snGradSchemes { default $snap; }
EOF
  cat > "$dir/system/fvSolution" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }
solvers { "cellDisplacement.*" { $solver } }
EOF
  cat > "$dir/constant/dynamicMeshDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object dynamicMeshDict; }
dynamicFvMesh    dynamicMotionSolverFvMesh;
motionSolverLibs ("libfvMotionSolvers.so");
motionSolver     displacementLaplacian;
displacementLaplacianCoeffs { diffusivity inverseDistance ($patches); }
EOF
}

# A run folder: its own system/ and time folders, BASE's polyMesh (linked, not copied).
make_run() {  # make_run DIR SETUP PATCHES
  rm -rf "$1"
  write_system "$1" "$2" "$3"
  ln -s "$base/constant/polyMesh" "$1/constant/polyMesh"
}

# The quality of the points RUN/1/polyMesh/points, judged against BASE (dgwarp quality --reference).
moved_quality() {  # moved_quality RUN OUT.json
  local view=$1/quality-view/constant/polyMesh f
  rm -rf "$1/quality-view"; mkdir -p "$view"
  for f in faces owner neighbour boundary; do ln -s "$base/constant/polyMesh/$f" "$view/$f"; done
  ln -s "$1/1/polyMesh/points" "$view/points"
  "$dgwarp" quality "$1/quality-view" --reference "$base" --json > "$2"
}

checkmesh_time1() {  # checkmesh_time1 RUN: checkMesh of the moved mesh, log in RUN/checkMesh.log
  [ $skip_openfoam = 0 ] || return 0
  (cd "$1" && checkMesh -time 1 > checkMesh.log 2>&1) || true
}

for name in "${cases[@]}"; do
  case_inputs "$name"
  dir="$work/$name"; base="$dir/base"
  mkdir -p "$dir"
  echo "== $name: $mesh, motion $motion_file"
  case_load_before=$(uptime); case_started=$(date -u '+%H:%M')
  rm -rf "$base"
  "$dgwarp" convert "$mesh" "$base/" --foam-format binary -q || { echo "openfoam.sh: convert failed" >&2; exit 2; }
  write_system "$base" usual ""
  rm -f "$base/constant/dynamicMeshDict"
  field_out=$("$dgwarp" motion-field "$base" -m "$motion_file" -o "$base") ||
    { echo "openfoam.sh: motion-field failed" >&2; exit 2; }
  "$dgwarp" motion-field "$base" -m "$motion_file" -o "$dir/boundary.csv" -q
  patches=$(echo "$field_out" | sed -n 's/^moving markers: //p')
  nb=$(echo "$field_out" | sed -n 's/.*displacement of \([0-9]*\) boundary nodes.*/\1/p')
  "$dgwarp" quality "$base" --json > "$dir/original-quality.json"
  nv=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['mesh']['nodes'])" "$dir/original-quality.json")
  echo "   $nv nodes, $nb boundary nodes, moving patches: $patches"
  original=(case="$name" label=original quality_json="$dir/original-quality.json")
  if [ $skip_openfoam = 0 ]; then
    (cd "$base" && checkMesh > checkMesh.log 2>&1) || true
    echo "   checkMesh of the polyMesh dgwarp wrote from $(basename "$mesh"): $(grep -E 'Mesh OK|Failed' "$base/checkMesh.log" || echo 'no verdict')"
    original+=(checkmesh_log="$base/checkMesh.log")
  fi
  $tools record "$results" "${original[@]}"

  if [ $skip_openfoam = 0 ]; then
    for setup in usual converged; do
      run="$dir/openfoam-$setup"
      make_run "$run" $setup "$patches"
      mkdir -p "$run/0"; cp "$base/0/pointDisplacement" "$run/0/"
      echo "   OpenFOAM moveMesh, $setup"
      # moveMesh's lines timestamped as they come (the solve time), its exit code kept.
      rc=0
      (cd "$run" && timed time.txt moveMesh 2>&1 | $tools stamp > moveMesh.log) || rc=$?
      $tools foam-solve "$run/moveMesh.log" > "$run/solve.json"
      if [ $rc = 0 ] && [ -f "$run/1/polyMesh/points" ]; then
        moved_quality "$run" "$run/quality.json"
        err=$($tools boundary-error "$base/constant/polyMesh/points" "$run/1/polyMesh/points" "$dir/boundary.csv")
        checkmesh_time1 "$run"
        $tools record "$results" case="$name" label="openfoam-$setup" tool=OpenFOAM setup="$setup" \
          time_file="$run/time.txt" foam_log="$run/solve.json" quality_json="$run/quality.json" \
          boundary_error="$err" checkmesh_log="$run/checkMesh.log"
      else
        $tools record "$results" case="$name" label="openfoam-$setup" tool=OpenFOAM setup="$setup" \
          time_file="$run/time.txt" status="moveMesh failed (exit $rc; $run/moveMesh.log)"
      fi
    done
  fi

  IFS=, read -r -a runs <<< "$methods"
  for m in "${runs[@]}"; do
    case $m in
      dg-harmonic|dg-idw|dgm|idw|rbf) opts=(--method "$m") ;;
      dg-idw-auto) opts=(--method dg-idw --length-scale auto) ;;
      dg-idw-continuous) opts=(--method dg-idw --dg-idw-weights continuous) ;;
      dg-idw-untangle) opts=(--method dg-idw --untangle) ;;
      *) echo "openfoam.sh: unknown method '$m'" >&2; exit 1 ;;
    esac
    # Where `dgwarp bench` skips a method, so does this.
    if [ "$m" = rbf ] && [ "$nb" -gt 20000 ]; then
      $tools record "$results" case="$name" label="$m" tool=dgwarp setup="$m" status="skipped: dense ${nb}² system (as dgwarp bench)"
      continue
    fi
    if [ "$m" = idw ] && [ $((nv * nb)) -gt 100000000000 ]; then
      $tools record "$results" case="$name" label="$m" tool=dgwarp setup="$m" status="skipped: N_v × N_b too large (as dgwarp bench)"
      continue
    fi
    run="$dir/dgwarp-$m"
    make_run "$run" check ""
    rm -f "$run/constant/dynamicMeshDict"
    echo "   dgwarp $m"
    rc=0
    timed "$run/time.txt" "$dgwarp" deform "$run" -m "$motion_file" -o "$run" --foam-time 1 \
      --threads 1 --allow-invalid --json "${opts[@]}" > "$run/deform.json" 2> "$run/deform.err" || rc=$?
    rec=(case="$name" label="$m" tool=dgwarp setup="$m" time_file="$run/time.txt" deform_json="$run/deform.json" deform_err="$run/deform.err")
    if [ -f "$run/1/polyMesh/points" ]; then
      rec+=(boundary_error="$($tools boundary-error "$base/constant/polyMesh/points" "$run/1/polyMesh/points" "$dir/boundary.csv")")
      if [ $skip_openfoam = 0 ] && { [ "$checkmesh_runs" = all ] || [[ ",$checkmesh_runs," == *",$m,"* ]]; }; then
        checkmesh_time1 "$run"
        rec+=(checkmesh_log="$run/checkMesh.log")
      fi
    fi
    [ $rc = 0 ] || rec+=(status="exit $rc")
    $tools record "$results" "${rec[@]}"
  done
  case_load_after=$(uptime)
  $tools record "$results" case="$name" label=load \
    status="$case_started-$(date -u '+%H:%M') UTC, load before ${case_load_before#*load average: }, after ${case_load_after#*load average: }"
done

load_after=$(uptime)
echo
echo "## dgwarp against OpenFOAM's moveMesh (bench/peers/openfoam.sh)"
echo
echo "- date: $started; dgwarp $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?'); OpenFOAM ${WM_PROJECT_VERSION:-not run}"
echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores; every run one process, one thread"
echo "- load before: ${load_before#*load average: }; after: ${load_after#*load average: } (uptime: 1, 5, 15 min)"
$tools table "$results"
