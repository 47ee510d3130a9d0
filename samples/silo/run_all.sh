#!/usr/bin/env bash
# Runs the silo for several orifice sizes and fits Beverloo's law to the discharge rates:
#   samples/silo/run_all.sh [POLYDEM] [D_mm ...]     (default: build/polydem, 45 50 55 60)
# Each size D gets meshes/plate_D<D>.stl, scene_D<D>.yaml (scene.yaml with that plate and
# output folder out/D<D>) and a run with --threads 1; then beverloo_fit.py reads the folders.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
polydem=$(realpath "${1:-$here/../../build/polydem}")
shift || true
sizes=("${@:-45 50 55 60}")
sizes=(${sizes[*]})
/usr/bin/python3 "$here/make_meshes.py" "${sizes[@]}"
folders=()
for d in "${sizes[@]}"; do
  scene="$here/scene_D$d.yaml"
  [ "$d" = 50 ] && scene="$here/scene.yaml"
  if [ "$d" != 50 ]; then
    { echo "# Written by run_all.sh: scene.yaml with plate_D$d.stl and out/D$d."
      sed -e "s/plate_D50\.stl/plate_D$d.stl/" -e "s/dir: out\/D50/dir: out\/D$d/" "$here/scene.yaml"; } > "$scene"
  fi
  "$polydem" run "$scene" --threads 1
  folders+=("$here/out/D$d")
done
/usr/bin/python3 "$here/beverloo_fit.py" --polydem "$polydem" "${folders[@]}"
