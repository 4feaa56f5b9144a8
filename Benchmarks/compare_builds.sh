#!/usr/bin/env bash
# Which outputs does a change touch, and how? Runs two builds side by side (two at a time) on
# every surface at 1,000, 3,000 and 6,500 quads, compares their VTPs byte for byte, and for those
# that differ prints both validity figures (Benchmarks/validity.py: valid, quads, χ and boundary
# loops against the input's, Hausdorff %, irregular vertices, edge RSD %, faces against the input).
#   bash Benchmarks/compare_builds.sh OLD_PREFIX NEW_PREFIX OUTDIR [SURFACE.obj ...]
# The prefixes are installed builds (cmake --install build --prefix OLD_PREFIX); the surfaces
# default to the shared meshes and Data/; add generated families, e.g.
#   $(ls GEN/*.obj) after /usr/bin/python3 Benchmarks/generated_shapes.py GEN.
# QUADS="1000 3000" changes the counts. Seconds are of the new build while the old one runs too.
set -euo pipefail
old=$1 new=$2 out=$3
shift 3
cd "$(dirname "$0")/.."
mkdir -p "$out"
shared=${SHARED:-../shared/data}
if [ $# -eq 0 ]; then
  set -- $(ls "$shared"/*.obj 2>/dev/null) Data/*.obj
fi
run() { # run PREFIX IN OUT [ARGS]: that build's quadcover on IN, nothing printed
  local prefix=$1 in=$2 result=$3
  shift 3
  LD_LIBRARY_PATH="$prefix/lib" timeout 600 "$prefix/bin/quadcover" "$in" -o "$result" "$@" \
    >/dev/null 2>&1 || true
}
figures() { # figures OUT REF: one line of validity figures
  /usr/bin/python3 Benchmarks/validity.py "$1" "$2" 2>/dev/null | /usr/bin/python3 -c '
import json, sys
r = json.load(sys.stdin)
print("valid" if r["valid"] else "INVALID", r["faces"], r["chi"], r["loops"], r["hausdorff_pct"],
      r["irregular"], r["rsd_edge"], r["against_normal"])' || echo "no output"
}
for mesh in "$@"; do
  name=$(basename "$mesh" .obj)
  ref="$out/$name.ref.vtp"
  [ -f "$ref" ] || run "$new" "$mesh" "$ref" --stage repair
  for quads in ${QUADS:-1000 3000 6500}; do
    a="$out/$name.$quads.old.vtp" b="$out/$name.$quads.new.vtp"
    run "$old" "$mesh" "$a" --target-quad-count "$quads" &
    start=$(date +%s.%N)
    run "$new" "$mesh" "$b" --target-quad-count "$quads"
    seconds=$(echo "$(date +%s.%N) - $start" | bc)
    wait
    if cmp -s "$a" "$b"; then
      echo "$name $quads same"
    else
      echo "$name $quads DIFF old: $(figures "$a" "$ref") | new: $(figures "$b" "$ref") | new ${seconds} s"
    fi
  done
done
