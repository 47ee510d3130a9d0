#!/usr/bin/env bash
# Side by side with LIGGGHTS 3.8 (Debian's `liggghts`): the same bed of 3,375 settled spheres
# (box, law, step: spheres.yaml and *.liggghts), STEPS steps timed in each program, alternated
# (LIGGGHTS, polydem, LIGGGHTS, polydem ...) PAIRS times at 1 process/thread and at 2 (MPI
# ranks for LIGGGHTS, OpenMP threads for polydem). Each program's own loop time is used (no
# start-up, no settling). Appends one row per pair to tools/bench/peers/results.csv and prints
# the median ratio polydem / LIGGGHTS per process count: the figure that counts here, as
# absolute times drift by 40% on this machine.
# usage: tools/bench/peers/run_peers.sh [STEPS] [PAIRS]   (defaults 20000 and 3)
set -euo pipefail
cd "$(dirname "$0")/../../.."
steps=${1:-20000}
pairs=${2:-3}
here=tools/bench/peers
work=build/bench/peers
bin=build/polydem
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
if ! command -v liggghts > /dev/null || ! command -v mpirun > /dev/null; then
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends liggghts openmpi-bin
fi
[ -x "$bin" ] || bash tools/build.sh polydem
mkdir -p "$work"
cp "$here"/*.liggghts "$work"/
mpi=(mpirun -np 2 --bind-to none)
[ "$(id -u)" -ne 0 ] || mpi+=(--allow-run-as-root)

if [ ! -f "$work/bed.restart" ]; then
  echo "settling the LIGGGHTS bed (once)..."
  (cd "$work" && liggghts -in settle.liggghts -echo none -log none > settle.log)
fi
if [ ! -f "$work/polydem/settled.bin" ]; then
  echo "settling the polydem bed (once)..."
  "$bin" run "$here/spheres.yaml" --out "$work/polydem" --threads 2 > /dev/null 2>&1
  cp "$(ls "$work"/polydem/checkpoint_*.bin | sort | tail -1)" "$work/polydem/settled.bin"
fi
t_settled=$(tail -1 "$work/polydem/energy.csv" | cut -d, -f1)
until=$(python3 -c "print($t_settled + $steps * 1e-5)")

liggghts_seconds() {  # procs
  local cmd=(liggghts)
  [ "$1" -eq 1 ] || cmd=("${mpi[@]}" liggghts)
  (cd "$work" && "${cmd[@]}" -in run.liggghts -var steps "$steps" -echo none -log none) |
    awk '/^Loop time/ {print $4}'
}
polydem_seconds() {  # threads
  rm -rf "$work/run"
  "$bin" run "$here/spheres.yaml" --out "$work/run" --threads "$1" --fixed-threads --resume "$work/polydem/settled.bin" --force \
      --until "$until" 2>&1 | sed -n 's/.* steps in \([0-9.]*\) s.*/\1/p'
}

results=$here/results.csv
[ -f "$results" ] || echo "machine,commit,date,procs,steps,liggghts_s,polydem_s,ratio" > "$results"
machine=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//; s/,//g')
commit=$(git rev-parse --short HEAD)$(git diff --quiet HEAD -- src include || echo +)
declare -A ratios
for ((p = 0; p < pairs; ++p)); do
  for procs in 1 2; do
    l=$(liggghts_seconds "$procs")
    d=$(polydem_seconds "$procs")
    r=$(python3 -c "print(f'{$d / $l:.3f}')")
    ratios[$procs]+="$r "
    echo "\"$machine\",$commit,$(date -u +%FT%TZ),$procs,$steps,$l,$d,$r" | tee -a "$results"
  done
done
for procs in 1 2; do
  python3 -c "import statistics,sys; r=[float(x) for x in sys.argv[2:]]; print(f'{sys.argv[1]} process(es)/thread(s): polydem / LIGGGHTS median {statistics.median(r):.3f} (each pair: {\" \".join(sys.argv[2:])})')" "$procs" ${ratios[$procs]}
done
