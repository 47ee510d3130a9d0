# Sourced by the pour scripts: pour_yaml WORK writes WORK/pour.yaml (the box-fill sample, shapes found
# from here, dt fixed at the value its states were made with); pour_state BIN WORK prints a state at
# 0.1 s, made once into WORK (11,767 steps, ~10 s) when the scripts are given none.
pour_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
pour_dt=8.498501385433668e-06  # s: the sample's auto dt when the states were made (session 27)
pour_yaml() {
  sed "s#\.\./\.\./shapes/#$pour_dir/../../../shapes/#; s#dt: auto#dt: $pour_dt#" \
    "$pour_dir/../../../samples/box-fill/scene.yaml" > "$1/pour.yaml"
}
pour_state() {
  local state="$2/state/checkpoint_011767.bin"
  if [ ! -f "$state" ]; then
    pour_yaml "$2"
    rm -rf "$2/state"; "$1" run "$2/pour.yaml" --out "$2/state" --until 0.1 >&2
  fi
  [ -f "$state" ] || { echo "pour_state: no $state" >&2; return 1; }
  echo "$state"
}
