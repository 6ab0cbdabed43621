#!/usr/bin/env bash
# bench/su2_rotations.sh: dgwarp's default (dg-harmonic) and the paper's DG-IDW on SU2's own
# 2D airfoil meshes (RANS boundary layers, hybrid and inviscid), the airfoil turned about its
# quarter chord, and moved and turned at once; prints one Markdown row per mesh, motion and
# method: inverted cells, min / mean Knupp quality, min / mean ratio to the original cell.
# The table in docs/RESULTS.md ("SU2's airfoil meshes, turned") is its output.
#
# Usage: bench/su2_rotations.sh [--dgwarp PATH] [--meshes DIR]
#   --dgwarp  the dgwarp binary (default build/dgwarp)
#   --meshes  SU2's test meshes (default ../shared/meshes/su2)
set -euo pipefail
dgwarp=build/dgwarp
meshes=../shared/meshes/su2
while [ $# -gt 0 ]; do
  case "$1" in
    --dgwarp) dgwarp=$2; shift 2 ;;
    --meshes) meshes=$2; shift 2 ;;
    *) echo "su2_rotations.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# mesh file (without .su2), moving marker
cases=(
  "rans_naca0012_n0012_225-65 airfoil"
  "unsteady_pitching_naca64a010_rans_mesh_NACA64A010_turb airfoil"
  "deformation_rae2822_mesh_RAE2822_turb_ffd AIRFOIL"
  "aeroelastic_mesh_NACA64A010_hybrid_inv airfoil"
)
motions=(
  "turn 5°|\"rotate\": {\"angle_deg\": 5, \"axis\": [0, 0, 1], \"center\": [0.25, 0, 0]}"
  "turn 20°|\"rotate\": {\"angle_deg\": 20, \"axis\": [0, 0, 1], \"center\": [0.25, 0, 0]}"
  "turn 90°|\"rotate\": {\"angle_deg\": 90, \"axis\": [0, 0, 1], \"center\": [0.25, 0, 0]}"
  "up 0.3, back 0.3, turn -25°|\"translate\": [0.3, 0.3, 0], \"rotate\": {\"angle_deg\": -25, \"axis\": [0, 0, 1], \"center\": [0.25, 0, 0]}"
)
echo "| mesh | nodes | motion | method | inverted | min | mean | ratio min | ratio mean |"
echo "|---|---|---|---|---|---|---|---|---|"
for c in "${cases[@]}"; do
  read -r mesh marker <<<"$c"
  file="$meshes/$mesh.su2"
  [ -f "$file" ] || { echo "su2_rotations.sh: no $file" >&2; exit 2; }
  for m in "${motions[@]}"; do
    label=${m%%|*}
    echo "{\"markers\": {\"$marker\": {${m#*|}}}}" >"$work/motion.json"
    for method in dg-harmonic dg-idw; do
      "$dgwarp" deform "$file" -m "$work/motion.json" -o "$work/out.su2" --method "$method" \
        --allow-invalid --no-untangle --json 2>/dev/null >"$work/report.json" || true
      /usr/bin/python3 - "$work/report.json" "$mesh" "$label" "$method" <<'PY'
import json, sys
report, mesh, label, method = sys.argv[1:]
d = json.load(open(report))
if d.get("error"):
    print(f"| {mesh} | | {label} | {method} | error: {d['error']} | | | | |")
    sys.exit(0)
f = d["frames"][0]
q, r = f["quality"], f["ratio"]
print(f"| {mesh} | {d['mesh']['nodes']:,} | {label} | {method} | {q['inverted']} | {q['min']:.3g} | {q['mean']:.4f} | {r['min']:.3f} | {r['mean']:.4f} |")
PY
    done
  done
done
