#!/usr/bin/env bash
# The integer-grid map on the generated surfaces and the shared meshes at about 3,000 quads
# (or QUADS): branch points, seams, energies, flipped triangles and seconds, as the Markdown
# table kept in Documentation/Algorithms.md.
#   bash Benchmarks/param_table.sh [SHARED_DIR] [QUADS]      (after bash Scripts/build.sh)
set -euo pipefail
shared=${1:-../shared/data}
quads=${2:-3000}
source "$(dirname "$0")/common.sh"
echo "| surface | triangles | branch points (on grid) | seam edges | energy continuous → rounded → final | flipped continuous → rounded → final | param s |"
echo "|---|---:|---|---:|---|---|---:|"
for mesh in $(surfaces "$shared" and-generated); do
  build/bin/quadcover "$mesh" -o "$tmp/out.vtp" --stage param --target-quad-count "$quads" \
    --stats "$tmp/s.json"
  /usr/bin/python3 - "$mesh" "$tmp/s.json" <<'PY'
import json, os, sys
s = json.load(open(sys.argv[2]))
p = s["param"]
print("| %s | %d | %d (%d) | %d | %.4f → %.4f → %.4f | %d → %d → %d | %.2f |" % (
    os.path.basename(sys.argv[1]).replace(".obj", ""), s["surface"]["triangles"],
    *p["branch_points_on_grid"], p["seam_edge_count"], *p["parameterization_energy"],
    *p["flipped_triangles"], s["seconds"]["param"]))
PY
done
