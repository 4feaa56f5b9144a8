#!/usr/bin/env bash
# Is every output a valid quad mesh of its input? All quads, manifold, oriented, no face against
# the input's normal, per component the input's χ and boundary loops (after the counted repairs).
#   bash Benchmarks/validity_table.sh [SHARED_DIR] [QUADS] [QUADCOVER OPTIONS...]
# (after bash Scripts/build.sh), e.g. ... ../shared/data 6500 --smoothing-weight 1 --no-optimize-branch-points
# GENERATED=DIR adds the surfaces Benchmarks/generated_shapes.py DIR wrote.
set -euo pipefail
shared=${1:-../shared/data}
quads=${2:-6500}
shift $(( $# < 2 ? $# : 2 ))
source "$(dirname "$0")/common.sh"
qc=${QUADCOVER:-build/bin/quadcover} # another build: QUADCOVER=/path/bin/quadcover
echo "| surface | triangles | quads | valid | components (input) | χ (input) | boundary loops (input) | against normal | Hausdorff % | irregular | edge RSD % | seconds |"
echo "|---|---:|---:|---|---|---|---|---:|---:|---:|---:|---:|"
generated=${GENERATED:+$(ls "$GENERATED"/*.obj)}
for mesh in $(surfaces "$shared" and-generated all) $generated; do
  name=$(basename "$mesh" .obj)
  "$qc" "$mesh" -o "$tmp/ref.vtp" --stage repair 2>/dev/null || { echo "| $name | refused: $("$qc" "$mesh" -o "$tmp/ref.vtp" --stage repair 2>&1 | head -1) |"; continue; }
  start=$(date +%s.%N)
  if ! err=$(timeout 600 "$qc" "$mesh" -o "$tmp/out.vtp" --target-quad-count "$quads" "$@" 2>&1); then
    echo "| $name | failed: ${err%%$'\n'*} |"; continue
  fi
  seconds=$(echo "$(date +%s.%N) - $start" | bc)
  /usr/bin/python3 Benchmarks/validity.py "$tmp/out.vtp" "$tmp/ref.vtp" | /usr/bin/python3 -c '
import json, sys
r = json.loads(sys.stdin.read()); name, tris, secs = sys.argv[1:4]
print("| %s | %s | %d | %s | %d (%d) | %d (%d) | %d (%d) | %d | %.2f | %d | %.1f | %.1f |" % (
    name, tris, r["faces"], "yes" if r["valid"] else "**no**", *r["components"], *r["chi"],
    *r["loops"], r["against_normal"], r["hausdorff_pct"], r["irregular"], r["rsd_edge"], float(secs)))
' "$name" "$(/usr/bin/python3 -c 'import vtk,sys; r=vtk.vtkXMLPolyDataReader(); r.SetFileName(sys.argv[1]); r.Update(); print(r.GetOutput().GetNumberOfPolys())' "$tmp/ref.vtp")" "$seconds"
done
