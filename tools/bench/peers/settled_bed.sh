# Sourced by run_efficiency.sh and run_ceiling.sh: the settled bed of SCENE (spheres, the default:
# the peers' bed made by run_peers.sh; cubes: tools/bench/cubes.yaml's pile made by run_bench.sh)
# and the time `until` that is STEPS steps after it. Sets state, scene and until.
# usage: settled_bed POLYDEM STEPS
settled_bed() {
  local maker
  case ${SCENE:-spheres} in
    spheres) state=build/bench/peers/polydem scene=tools/bench/peers/spheres.yaml maker=run_peers.sh ;;
    cubes) state=build/bench/cubes scene=tools/bench/cubes.yaml maker=run_bench.sh ;;
    *) echo "SCENE is spheres or cubes, not '$SCENE'" >&2; exit 1 ;;
  esac
  [ -f "$state/settled.bin" ] || { echo "no $state/settled.bin: run tools/bench/$maker first" >&2; exit 1; }
  local dt
  dt=$("$1" check "$scene" | awk '/chosen time step/ {print $4}')  # s
  until=$(python3 -c "print($(tail -1 "$state/energy.csv" | cut -d, -f1) + $2 * $dt)")
}
