#!/usr/bin/env bash
# The quad meshes of the shared meshes (and the generated surfaces) at about QUADS quads (default
# 6,500, the paper's Table 1 density): the figures kept in Documentation/Algorithms.md.
#   bash Benchmarks/quad_table.sh [SHARED_DIR] [QUADS] [QUADCOVER OPTIONS...]
# (after bash Scripts/build.sh), e.g. ... ../shared/data 6500 --relaxation-iterations 10
set -euo pipefail
shared=${1:-../shared/data}
quads=${2:-6500}
shift $(( $# < 2 ? $# : 2 ))
source "$(dirname "$0")/common.sh"
echo "| surface | vertices | quads | quad share | irregular inner (+ boundary) | edge-length RSD | angle RSD | scaled Jacobian min / mean | Hausdorff % | χ (input) | dropped cells | seconds (all stages) |"
echo "|---|---:|---:|---:|---|---:|---:|---|---:|---|---:|---:|"
for mesh in $(surfaces "$shared" and-generated); do
  build/bin/quadcover "$mesh" -o "$tmp/out.vtp" --target-quad-count "$quads" --stats "$tmp/s.json" \
    "$@" 2>/dev/null
  /usr/bin/python3 - "$mesh" "$tmp/s.json" <<'PY'
import json, os, sys
s = json.load(open(sys.argv[2]))
q = s["quads"]
chi = round(s["matching"]["singularity_index_sum"])
print("| %s | %d | %d | %.0f%% | %d (+ %d) | %.1f%% | %.1f%% | %.2f / %.3f | %.2f | %d (%d) | %d | %.2f |" % (
    os.path.basename(sys.argv[1]).replace(".obj", ""), q["vertices"], q["faces"],
    100 * q["quad_share"], q["irregular_vertices"][0], q["irregular_vertices"][1],
    100 * q["edge_length_rsd"], 100 * q["angle_rsd"], q["scaled_jacobian_statistics"][0],
    q["scaled_jacobian_statistics"][1], q["hausdorff_distance"][0], q["euler_characteristic"],
    chi, sum(q["dropped_cells"]),
    sum(v for k, v in s["seconds"].items() if k not in ("read", "repair", "write"))))
PY
done
