#!/usr/bin/env bash
# Branch points before and after branch-point optimization, and the singularities left, on the
# generated surfaces and the shared meshes, as the Markdown table kept in Documentation/Algorithms.md
# (with the merges on and the alignment everywhere, the former defaults; extra options follow).
#   bash Benchmarks/singularity_table.sh [SHARED_DIR]      (after bash Scripts/build.sh)
set -euo pipefail
shared=${1:-../shared/data}
shift $(( $# < 1 ? $# : 1 ))
source "$(dirname "$0")/common.sh"
echo "| surface | triangles | chi | held frames | smoothing energy | branch points before → after | singularities (by index) | index sum |"
echo "|---|---:|---:|---:|---|---|---|---:|"
for mesh in $(surfaces "$shared" and-generated); do
  build/bin/quadcover "$mesh" -o "$tmp/out.vtp" --stage matching --stats "$tmp/s.json" \
    --optimize-branch-points --coherence-radius 0 "$@"
  /usr/bin/python3 - "$mesh" "$tmp/s.json" <<'PY'
import json, os, sys
s = json.load(open(sys.argv[2]))
sm, m = s["smooth"], s["matching"]
by = ", ".join("%g: %d" % (index, count) for index, count in m["singularity_histogram"])
chi = round(m["singularity_index_sum"])
print("| %s | %d | %d | %d | %.3g → %.3g | %d → %d | %d (%s) | %.6g |" % (
    os.path.basename(sys.argv[1]).replace(".obj", ""), s["surface"]["triangles"], chi,
    sm["constrained_frame_count"], *sm["smoothing_energy"], *m["branch_point_count"],
    m["singularity_count"], by or "none", m["singularity_index_sum"]))
PY
done
