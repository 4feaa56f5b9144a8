# common.sh: what the table scripts share; source it. Moves to the repository, makes a scratch
# folder $tmp that goes on exit, and lists the surfaces the tables run on.
cd "$(dirname "${BASH_SOURCE[0]}")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The shared meshes the tables use (those present in $1), then with "and-generated" as $2 the
# surfaces in Data/; with "all" as $3 every shared mesh.
surfaces() {
  local name names="bunny-lowres spot fandisk rocker-arm cheburashka teapot"
  [ "${3:-}" = all ] && names="$names armadillo bumpy-cube decimated-knight lion screwdriver 3holes fertility truck"
  for name in $names; do
    [ -f "$1/$name.obj" ] && echo "$1/$name.obj"
  done
  if [ "${2:-}" = and-generated ]; then
    for name in sphere torus knot roundedcube cylinder components dumbbell plate frame bracket shaft; do
      echo "Data/$name.obj"
    done
  fi
  return 0
}
