#!/usr/bin/env bash
# Quads at about QUADS quads (default 6,500) on the shared meshes for pairs of smoothing weight
# (vtkFrameSmoother, --smoothing-weight) and branch-point weight (vtkMatchingBuilder,
# --branch-point-weight):
# irregular inner vertices, edge-length RSD / angle RSD, and (!) where the map kept a flipped
# triangle or a fan wound the wrong way. The table that chose λ and the weight for the former
# defaults (merges on, no cone pairs, alignment everywhere: the options it passes), kept in
# Documentation/Algorithms.md.
#   bash Benchmarks/tuning_table.sh [SHARED_DIR] [QUADS]      (after bash Scripts/build.sh)
set -euo pipefail
shared=${1:-../shared/data}
quads=${2:-6500}
pairs=("0.5 6" "0.9 4" "0.95 3" "0.95 4" "0.95 6" "0.98 4")
source "$(dirname "$0")/common.sh"
header="| surface |"
rule="|---|"
for p in "${pairs[@]}"; do
  set -- $p
  header+=" λ $1, weight $2 |"
  rule+="---|"
done
echo "$header"
echo "$rule"
for mesh in $(surfaces "$shared"); do
  mesh=$(basename "$mesh" .obj)
  row="| $mesh |"
  for p in "${pairs[@]}"; do
    set -- $p
    build/bin/quadcover "$shared/$mesh.obj" -o "$tmp/q.vtp" --target-quad-count "$quads" \
      --optimize-branch-points --cone-pair-gain 0 --coherence-radius 0 \
      --smoothing-weight "$1" --branch-point-weight "$2" --no-compute-hausdorff-distance --stats "$tmp/s.json" 2>/dev/null
    row+=" $(/usr/bin/python3 - "$tmp/s.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
q, p = s["quads"], s["param"]
bad = "" if p["flipped_triangles"][2] == 0 and p["winding_errors"] == 0 else " (!)"
print("%d, %.1f / %.1f%%%s" % (q["irregular_vertices"][0], 100 * q["edge_length_rsd"],
                              100 * q["angle_rsd"], bad))
PY
) |"
  done
  echo "$row"
done
