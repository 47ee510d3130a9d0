#!/usr/bin/env bash
# A scene over MPI ranks gives the bits of one process (issue 20): the final checkpoint,
# energy.csv and the driver CSVs of -np 1, 2 and 3 equal a plain run's byte for byte, on a
# pour with walls (cubes, octahedra, spheres) and a turning drum (spheres, dodecahedra); a
# -np 2 checkpoint resumed with -np 3 ends on the same bits; a fast sphere running through a
# row across the cuts keeps the body count and the momentum; at -np 3 each rank
# holds fewer than all bodies and a third of the work (POLYDEM_MPI_COUNTS); a bad scene under
# -np 2 gives one message and exit 1, no hang; a blow-up at -np 2 stops as the plain run.
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
source "$here/mpi_lib.bash"

for scene in pour drum; do
  "$polydem" run "$here/mpi_$scene.yaml" --out "$tmp/$scene" --threads 1 > /dev/null 2>&1 || fail "plain $scene run"
  for np in 1 2 3; do
    threads=$((np == 1 ? 2 : 1))
    mpi "$np" run "$here/mpi_$scene.yaml" --out "$tmp/$scene$np" --threads "$threads" > /dev/null 2>&1 ||
      fail "$scene at -np $np"
    same_outputs "$tmp/$scene" "$tmp/$scene$np" "$here/mpi_$scene.yaml"
  done
  echo "ok: $scene: -np 1, 2, 3 give the plain run's bits"
done

# A skin per body (simulation: skin_max) in one process, the ranks on the scene's skin: the same bits.
sed "s#  skin: \"0.5 mm\"#  skin: \"0.5 mm\"\n  skin_max: \"2 mm\"#; s#\.\./\.\./shapes/#$here/../../shapes/#" "$here/mpi_pour.yaml" > "$tmp/skins.yaml"
grep -q skin_max "$tmp/skins.yaml" || fail "no skin_max in the pour's copy"
"$polydem" run "$tmp/skins.yaml" --out "$tmp/skins" --threads 1 > /dev/null 2>&1 || fail "plain pour with skin_max"
same_outputs "$tmp/pour" "$tmp/skins" "$tmp/skins.yaml"
mpi 2 run "$tmp/skins.yaml" --out "$tmp/skins2" --threads 1 > /dev/null 2>&1 || fail "pour with skin_max at -np 2"
same_outputs "$tmp/pour" "$tmp/skins2" "$tmp/skins.yaml"
echo "ok: pour: skin_max gives the plain run's bits, alone and at -np 2"

# Each of 3 ranks moves its share of the pour and holds fewer than all 100 bodies; the ghosts
# come point to point from the boxes near its own; the cut by measured work keeps each rank's
# share of the weight near a third, cut again only at some rebuilds; a rebuild sends the movers
# and the ghosts point to point, no rank gathers the state of all 100 bodies (224 bytes each)
# nor keeps it after its first cut (POLYDEM_MPI_COUNTS: three lines per rank).
POLYDEM_MPI_COUNTS=1 mpi 3 run "$here/mpi_pour.yaml" --out "$tmp/counted" --threads 1 > /dev/null 2> "$tmp/counts" ||
  fail "counted pour at -np 3"
same_outputs "$tmp/pour" "$tmp/counted" "$here/mpi_pour.yaml"
/usr/bin/python3 - "$tmp/counts" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
rows = sorted((int(m[1]), int(m[2]), int(m[3]), int(m[4]), float(m[5])) for m in re.finditer(
    r"rank (\d) of 3: holds (\d+) of 100 bodies \((\d+) owned, (\d+) ghosts\); per step: ([\d.]+) point-to-point", text))
work = sorted((int(m[1]), int(m[2]), float(m[3]), int(m[4]), int(m[5]), int(m[6])) for m in re.finditer(
    r"rank (\d) of 3: last lists: (\d+) pairs, \d+ candidate feature pairs; ([\d.]+)% of the weight; (\d+) cuts in "
    r"(\d+) rebuilds; the scene's arrays hold (\d+) bytes a body", text))
rebuild = sorted((int(m[1]), float(m[2]), float(m[3])) for m in re.finditer(
    r"rank (\d) of 3: per rebuild: [\d.]+ point-to-point messages, ([\d.e+]+) bytes; [\d.]+ collectives, "
    r"[\d.e+]+ bytes of its own in them, ([\d.e+]+) bytes received", text))
assert [r[0] for r in rows] == [0, 1, 2] and [w[0] for w in work] == [0, 1, 2], (rows, work)
assert [r[0] for r in rebuild] == [0, 1, 2], rebuild
for rank, sent, received in rebuild:
    assert 0 < sent and received < 224 * 100 / 3, f"rank {rank}: {sent} bytes sent, {received} received a rebuild"
assert sum(r[2] for r in rows) == 100, f"owned bodies add up to {sum(r[2] for r in rows)}, expected 100"
for rank, held, owned, ghosts, messages in rows:
    assert held == owned + ghosts and held < 100 and ghosts > 0, f"rank {rank} holds {held} bodies"
    assert messages < 2.5, f"rank {rank}: {messages} messages a step"  # 1-2 neighbours, and the rebuilds
assert abs(sum(w[2] for w in work) - 100.0) < 0.2, work
for rank, pairs, share, cuts, rebuilds, scene_bytes in work:
    assert pairs > 0 and abs(share - 100.0 / 3) < 100.0 / 3 * 0.1, f"rank {rank}: {share}% of the weight"
    assert 2 <= cuts < rebuilds, f"rank {rank}: {cuts} cuts in {rebuilds} rebuilds"
    # no probe or drag gathers the state: after the first cut the scene's arrays keep the
    # constants alone (52 bytes a body: shape, scale, mass, inertia, group, id), not its 224 of state
    assert scene_bytes <= 52, f"rank {rank}: the scene's arrays hold {scene_bytes} bytes a body"
print("; ".join(f"rank {r[0]}: {r[2]} owned + {r[3]} ghosts, {r[4]:g} messages a step, {w[2]}% of the weight"
                for r, w in zip(rows, work)))
PY
echo "ok: -np 3: each rank holds fewer than all bodies and a third of the work, within 10%"

# A -np 2 checkpoint at 20 ms resumed with -np 3 ends where the plain run ends.
first=$(ls "$tmp/pour2"/checkpoint_*.bin | grep -v '_p[0-9]*\.bin$' | sort | head -1)
[ "$first" != "$(last_checkpoint "$tmp/pour2")" ] || fail "no checkpoint half way"
cp -r "$tmp/pour2" "$tmp/resumed"
last=$(last_checkpoint "$tmp/resumed")
rm -f "$last" "${last%.bin}"_p*.bin  # the resumed run writes its own manifest and pieces
mpi 3 run "$here/mpi_pour.yaml" --out "$tmp/resumed" --resume "$tmp/resumed/$(basename "$first")" --threads 1 \
  > /dev/null 2>&1 || fail "resume with -np 3"
same_outputs "$tmp/pour" "$tmp/resumed" "$here/mpi_pour.yaml"
echo "ok: a -np 2 checkpoint resumed with -np 3 gives the plain run's bits"

# The projectile: 13 bodies at the end, momentum 20 m/s x m along x (equal masses).
"$polydem" run "$here/mpi_projectile.yaml" --out "$tmp/shot" --threads 1 > /dev/null 2>&1 || fail "plain projectile"
mpi 3 run "$here/mpi_projectile.yaml" --out "$tmp/shot3" --threads 1 > /dev/null 2>&1 || fail "projectile at -np 3"
same_outputs "$tmp/shot" "$tmp/shot3" "$here/mpi_projectile.yaml"
/usr/bin/python3 - "$tmp/shot3" <<'PY'
import glob, sys
import vtk
from vtk.util.numpy_support import vtk_to_numpy
r = vtk.vtkXMLPUnstructuredGridReader()  # the ranks' pieces as one data set
r.SetFileName(sorted(glob.glob(sys.argv[1] + "/bodies_*.pvtu"))[-1])
r.Update()
d = r.GetOutput()
ids = vtk_to_numpy(d.GetCellData().GetArray("id"))
v = vtk_to_numpy(d.GetCellData().GetArray("velocity"))
assert len(set(ids.tolist())) == 13, f"{len(set(ids.tolist()))} bodies, expected 13"
px = v[:, 0].sum() if len(v) == 13 else sum(v[ids == b][0, 0] for b in set(ids.tolist()))
assert abs(px - 20.0) < 1e-9 * 20.0, f"momentum per unit mass {px} m/s, expected 20"
last = v[ids == 12][0, 0]  # the far end of the row: the push went through every cut
assert last > 5.0, f"the last sphere of the row moves at {last} m/s"
print(f"13 bodies, sum vx = {px:.15g} m/s, the row's far end at {last:.3g} m/s")
PY
echo "ok: the projectile crossed the cuts with 13 bodies and its momentum"

# A blow-up (dt 52 x critical): each rank checks its own bodies, the first over all ranks
# stops every rank at the plain run's step with its one message, exit 2, and rank 0 writes
# the same last good state (the gathers for it go to rank 0 only).
sed -e 's|dt: auto|dt: "2 ms"|' -e 's|duration: "40 ms"|duration: "5 s"|' -e "s|../../shapes|$here/../../shapes|" \
  "$here/drop.yaml" > "$tmp/blowup.yaml"
expect_exit 2 "became non-finite" "$polydem" run "$tmp/blowup.yaml" --out "$tmp/blowup" --threads 1
plain_error=$(grep "became non-finite" "$tmp/err" | sed "s|$tmp/blowup/||")
expect_exit 2 "became non-finite" mpirun --oversubscribe -q --mca mpi_yield_when_idle 1 -np 2 "$polydem" run \
  "$tmp/blowup.yaml" --out "$tmp/blowup2" --threads 1
[ "$(grep -c "became non-finite" "$tmp/err")" -eq 1 ] || fail "-np 2 blow-up: not one message"
[ "$(grep "became non-finite" "$tmp/err" | sed "s|$tmp/blowup2/||")" = "$plain_error" ] || fail "-np 2 blow-up: another message"
cmp "$tmp/blowup/bodies_last_good.vtu" "$tmp/blowup2/bodies_last_good.vtu" || fail "-np 2 blow-up: another last good state"
echo "ok: a blow-up at -np 2 stops as the plain run: $plain_error"

# Too deep a contact (200 m/s into a soft floor, no CSV rows: checked at the finiteness checks
# only): each rank checks the pairs it answers for, and the first in one process's order is
# warned of once, by rank 0, with the plain run's line (bodies 2 and 3 lie past the cut).
cat > "$tmp/deep.yaml" <<YAML
simulation: {duration: "0.12 ms", dt: auto}
shapes: [$here/../../shapes/platonic.shp]
bodies:
  - {shape: sphere, position: [-0.03, 0, 0.0052], velocity: [0, 0, -1]}
  - {shape: sphere, position: [-0.01, 0, 0.0052], velocity: [0, 0, -1]}
  - {shape: sphere, position: [0.01, 0, 0.02], velocity: [0, 0, -200]}
  - {shape: sphere, position: [0.03, 0, 0.02], velocity: [0, 0, -200]}
drivers:
  - wall: {name: floor, point: [0, 0, 0], normal: [0, 0, 1]}
forces:
  - contact_polyhedron:
      config: {kn: 1.0e5, kt: 1.0e5, mu: 0.5, en: 0.5}
YAML
"$polydem" run "$tmp/deep.yaml" --out "$tmp/deep1" --threads 1 2> "$tmp/deep1.err" > /dev/null || fail "deep: plain run"
plain_warning=$(grep "an overlap of" "$tmp/deep1.err")
[ -n "$plain_warning" ] || fail "deep: the plain run did not warn"
for n in 2 3; do
  mpirun --oversubscribe -q --mca mpi_yield_when_idle 1 -np $n "$polydem" run "$tmp/deep.yaml" --out "$tmp/deep$n" \
    --threads 1 2> "$tmp/deep$n.err" > /dev/null || fail "deep: -np $n run"
  [ "$(grep "an overlap of" "$tmp/deep$n.err")" = "$plain_warning" ] || { cat "$tmp/deep$n.err"; fail "deep: -np $n warned otherwise"; }
done
echo "ok: a too-deep contact past the cut is warned of once at -np 2 and 3, as by the plain run"

printf 'simulation:\n  duration: "1 s"\n  dtt: 3\n' > "$tmp/broken.yaml"
expect_exit 1 "broken.yaml" mpirun --oversubscribe -q -np 2 "$polydem" run "$tmp/broken.yaml" --out "$tmp/bad"
[ "$(cat "$tmp/out" "$tmp/err" | grep -c .)" -eq 1 ] || { cat "$tmp/out" "$tmp/err"; fail "not one message"; }
echo "ok: a bad scene under -np 2: one message, exit 1"
