#!/usr/bin/env bash
# The peer bed counted rather than timed: LIGGGHTS and polydem under callgrind with its cache
# simulation (L1 48 KB, LL 32 MB: this machine's L1d and L3), 1 process / 1 thread, each run for
# STEPS and for 2 STEPS steps from its settled state; the difference is STEPS steps without
# set-up, reading or writing. Prints per particle-step and per contact-step: instructions (Ir),
# L1 read and write misses (D1mr, D1mw), last-level read and write misses (DLmr, DLmw),
# mispredicted conditional and indirect branches (Bcm, Bim: callgrind's simple predictor); then
# each program's split by function (inclusive, the same difference). Needs the settled states
# of run_peers.sh (build/bench/peers/bed.restart and polydem/settled.bin).
# usage: tools/bench/peers/count_peers.sh [STEPS] [POLYDEM]   (defaults 300 and build/polydem)
set -euo pipefail
cd "$(dirname "$0")/../../.."
steps=${1:-300}
bin=$(realpath "${2:-build/polydem}")
here=tools/bench/peers
peers=build/bench/peers
[ -f "$peers/bed.restart" ] && [ -f "$peers/polydem/settled.bin" ] ||
  { echo "count_peers: run tools/bench/peers/run_peers.sh once for the settled states" >&2; exit 1; }
work=$PWD/$peers/count  # the callgrind files stay for callgrind_annotate
mkdir -p "$work"
cp "$here"/*.liggghts "$peers/bed.restart" "$work"/
cache=(--cache-sim=yes --branch-sim=yes --D1=49152,12,64 --I1=32768,8,64 --LL=33554432,16,64)
t_settled=$(tail -1 "$peers/polydem/energy.csv" | cut -d, -f1)
bodies=3375

liggghts_run() {  # steps out
  (cd "$work" && valgrind --tool=callgrind "${cache[@]}" --callgrind-out-file="$2" \
      liggghts -in run.liggghts -var steps "$1" -echo none -log none > "$2.log" 2>&1)
}
polydem_run() {  # steps out
  rm -rf "$work/run"
  valgrind --tool=callgrind "${cache[@]}" --callgrind-out-file="$2" "$bin" run \
      "$here/spheres.yaml" --out "$work/run" --threads 1 --fixed-threads \
      --resume "$peers/polydem/settled.bin" --force \
      --until "$(python3 -c "print($t_settled + $1 * 1e-5)")" > "$2.log" 2>&1
}
for n in "$steps" $((2 * steps)); do
  [ -z "${ANALYSE_ONLY:-}" ] || break  # ANALYSE_ONLY=1: the callgrind files of the last run
  liggghts_run "$n" "$work/lig.$n"
  polydem_run "$n" "$work/pd.$n"
done
# contacts in the bed: LIGGGHTS' and polydem's settled beds hold about the same number
contacts=$(tail -1 "$peers/polydem/energy.csv" | cut -d, -f8)
for prog in lig pd; do
  for n in "$steps" $((2 * steps)); do
    callgrind_annotate --show=Ir,D1mr,D1mw,Bcm --threshold=100 "$work/$prog.$n" > "$work/$prog.$n.txt" 2> /dev/null
  done
done
python3 - "$work" "$steps" "$bodies" "$contacts" <<'EOF'
import re, sys
work, steps, bodies, contacts = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
events = ["Ir", "D1mr", "D1mw", "DLmr", "DLmw", "Bcm", "Bim"]
# Each program's functions (self cost) by part of the step: the first pattern that matches.
parts = {
    "lig": [("walls (the law's calls from them under pair)", r"FixWallGran|Walls::Granular"),
            ("pair (kernel, law, its helper 0x41dd40)", r"PairStyles::Granular|ContactModels::|PairGran|0x000000000041dd40"),
            ("integrate (nve/sphere, gravity)", r"FixNVESphere|FixGravity"),
            ("force clear (memset)", r"memset|force_clear"),
            ("neighbor (check, bins, lists)", r"Neighbor|NPair|NBin"),
            ("comm", r"Comm")],
    "pd": [("pair loop (sphere kernel, law)", r"sphere_pair_loop"),
           ("closing pass (force sums, kick)", r"kick_after"),
           ("wall pairs (with the drivers' reaction sums)", r"ContactEngine::forces|ContactEngine6forces|all_pair_forces<false|reduce_drivers"),
           ("opening pass (kick, drift, prediction, gravity; the closing pass joined to it)", r"start_step"),
           ("rebuild check", r"RebuildTrigger"),
           ("rebuilds", r"candidate|CellList|CandidateBlock|SphereGrid|list_build|collect_near|mark_beyond|rebuild")],
}

def summary(path):
    for line in open(path):
        if line.startswith("events:"):
            names = line.split()[1:]
        if line.startswith("summary:"):
            vals = dict(zip(names, map(int, line.split()[1:])))
    return [vals[e] for e in events]

def by_function(path):  # self Ir, D1mr, D1mw, Bcm by function; "." is 0
    out = {}
    for line in open(path):
        m = re.match(r"\s*((?:(?:[\d,]+ \(\s*[\d.]+%\)|\.)\s+){4})(\S.*)$", line)
        if not m or "PROGRAM TOTALS" in line:
            continue
        nums = [0 if x == "." else int(x.replace(",", "")) for x in re.findall(r"[\d,]+(?= \()|(?<!\S)\.(?!\S)", m.group(1))]
        out[m.group(2)] = [a + b for a, b in zip(out.get(m.group(2), [0] * 4), nums)]
    return out

print(f"{steps} steps, {bodies} spheres, {contacts} contacts in polydem's settled bed")
print(f"{'':10}" + "".join(f"{e:>10}" for e in events) + "   (per particle-step, then per contact-step)")
for prog, name in (("lig", "LIGGGHTS"), ("pd", "polydem")):
    a = summary(f"{work}/{prog}.{steps}")
    b = summary(f"{work}/{prog}.{2 * steps}")
    d = [y - x for x, y in zip(a, b)]
    print(f"{name:10}" + "".join(f"{v / steps / bodies:10.2f}" for v in d) + f"   total Ir {d[0]:.4e}")
    print(f"{'':10}" + "".join(f"{v / steps / contacts:10.2f}" for v in d))
for prog, name in (("lig", "LIGGGHTS"), ("pd", "polydem")):
    fa = by_function(f"{work}/{prog}.{steps}.txt")
    fb = by_function(f"{work}/{prog}.{2 * steps}.txt")
    sums = {label: [0] * 4 for label, _ in parts[prog] + [("other", "")]}
    for k, v in fb.items():
        d = [y - x for x, y in zip(fa.get(k, [0] * 4), v)]
        label = next((lab for lab, pat in parts[prog] if re.search(pat, k)), "other")
        sums[label] = [x + y for x, y in zip(sums[label], d)]
    print(f"\n{name} by part, per particle-step (self costs of {steps} steps):")
    print(f"  {'Ir':>8} {'D1mr':>7} {'D1mw':>7} {'Bcm':>7}  part")
    for label, v in sums.items():
        print("  " + " ".join(f"{x / steps / bodies:{w}.{p}f}" for x, w, p in zip(v, (8, 7, 7, 7), (1, 2, 2, 2))) + f"  {label}")
EOF
