#!/usr/bin/env bash
# What a spatial sort of the bodies would buy (issue 19), counted: the settled bed written as a
# body table in global id order and in cell order (bed_table.py), each run under callgrind's
# cache simulation (as count_peers.sh: L1 48 KB, LL 32 MB) for STEPS and 2 STEPS steps from
# its table, the difference taken. The two runs do the same arithmetic in another order (same
# instructions, other bits); both start their contacts new, so neither is count_peers.sh's
# resumed bed. Prints per particle-step Ir, L1 read and write misses, LL misses, mispredicted
# branches, the cycle estimate Ir + 10 L1 misses + 100 LL misses, then the split by part.
# Needs run_peers.sh's settled state (build/bench/peers/polydem/settled.bin). Each table runs in
# its rows' order (--body-order input: builds that have simulation.body_order).
# usage: tools/bench/peers/count_order.sh [STEPS] [POLYDEM]   (defaults 300 and build/polydem)
set -euo pipefail
cd "$(dirname "$0")/../../.."
steps=${1:-300}
bin=$(realpath "${2:-build/polydem}")
here=tools/bench/peers
settled=build/bench/peers/polydem/settled.bin
[ -f "$settled" ] || { echo "count_order: run tools/bench/peers/run_peers.sh once for $settled" >&2; exit 1; }
work=$PWD/build/bench/peers/order  # the callgrind files stay for callgrind_annotate
mkdir -p "$work"
python3 "$here/bed_table.py" "$settled" "$work"
cache=(--cache-sim=yes --branch-sim=yes --D1=49152,12,64 --I1=32768,8,64 --LL=33554432,16,64)
for order in id cell; do
  # spheres.yaml with the generated bodies replaced by the table
  sed -e "s#  - generate: random#  - file: bodies_$order.csv#" -e '/shapes: sphere/d;/count: 3375/d;/region: {box/d' \
      -e "s#\.\./\.\./\.\./shapes#$PWD/shapes#" "$here/spheres.yaml" > "$work/$order.yaml"
  for n in "$steps" $((2 * steps)); do
    rm -rf "$work/run"
    valgrind --tool=callgrind "${cache[@]}" --callgrind-out-file="$work/$order.$n" "$bin" run "$work/$order.yaml" \
        --out "$work/run" --threads 1 --fixed-threads --body-order input --until "$(python3 -c "print($n * 1e-5)")" > "$work/$order.$n.log" 2>&1
    callgrind_annotate --show=Ir,D1mr,D1mw,Bcm --threshold=100 "$work/$order.$n" > "$work/$order.$n.txt" 2> /dev/null
  done
done
python3 - "$work" "$steps" 3375 <<'PY'
import re, sys
work, steps, bodies = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
events = ["Ir", "D1mr", "D1mw", "DLmr", "DLmw", "Bcm"]
parts = [("pair loop", r"sphere_pair_loop"), ("closing pass", r"kick_after"),
         ("wall pairs", r"ContactEngine::forces|all_pair_forces<false"), ("opening pass", r"start_step")]

def summary(path):
    for line in open(path):
        if line.startswith("events:"):
            names = line.split()[1:]
        if line.startswith("summary:"):
            return dict(zip(names, map(int, line.split()[1:])))

def by_part(path):  # self Ir, D1mr, D1mw, Bcm summed by part
    out = {label: [0] * 4 for label, _ in parts + [("other", "")]}
    for line in open(path):
        m = re.match(r"\s*((?:(?:[\d,]+ \(\s*[\d.]+%\)|\.)\s+){4})(\S.*)$", line)
        if not m or "PROGRAM TOTALS" in line:
            continue
        nums = [0 if x == "." else int(x.replace(",", "")) for x in re.findall(r"[\d,]+(?= \()|(?<!\S)\.(?!\S)", m.group(1))]
        label = next((lab for lab, pat in parts if re.search(pat, m.group(2))), "other")
        out[label] = [a + b for a, b in zip(out[label], nums)]
    return out

per = steps * bodies
print(f"{steps} steps, {bodies} spheres, per particle-step")
print(f"{'order':6}" + "".join(f"{e:>9}" for e in events) + "   cycles")
for order in ("id", "cell"):
    a, b = summary(f"{work}/{order}.{steps}"), summary(f"{work}/{order}.{2 * steps}")
    d = {k: b[k] - a[k] for k in a}
    cycles = d["Ir"] + 10 * (d["I1mr"] + d["D1mr"] + d["D1mw"]) + 100 * (d["ILmr"] + d["DLmr"] + d["DLmw"])
    print(f"{order:6}" + "".join(f"{d[e] / per:9.2f}" for e in events) + f"   {cycles / per:.1f}")
for order in ("id", "cell"):
    a, b = by_part(f"{work}/{order}.{steps}.txt"), by_part(f"{work}/{order}.{2 * steps}.txt")
    print(f"\n{order} order by part (self costs): Ir, D1mr, D1mw, Bcm")
    for label in a:
        print("  " + " ".join(f"{(y - x) / per:8.2f}" for x, y in zip(a[label], b[label])) + f"  {label}")
PY
