#!/usr/bin/env bash
# Branch points before and after branch-point optimization, and the singularities left, on the
# generated surfaces and the shared meshes, as the Markdown table kept in README.md.
#   bash Benchmarks/singularity_table.sh [SHARED_DIR]      (after bash Scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
shared=${1:-../shared/data}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| surface | triangles | chi | held frames | smoothing energy | branch points before → after | singularities (by index) | index sum |"
echo "|---|---:|---:|---:|---|---|---|---:|"
for mesh in Data/sphere.obj Data/torus.obj Data/knot.obj Data/roundedcube.obj Data/cylinder.obj \
  "$shared"/bunny-lowres.obj "$shared"/spot.obj "$shared"/fandisk.obj "$shared"/rocker-arm.obj \
  "$shared"/cheburashka.obj "$shared"/teapot.obj; do
  [ -f "$mesh" ] || continue
  build/bin/quadcover "$mesh" -o "$tmp/out.vtp" --stage matching --stats "$tmp/s.json"
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
