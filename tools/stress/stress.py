"""Stress tests of polydem: where the integration breaks, and what long runs do.

usage: stress.py POLYDEM OUT_DIR [dt[:SHAPE,..]|impact|sheet|rest|extreme ...]   (default: all five)
Writes the scenes it runs under OUT_DIR and one row per run to tools/stress/results.csv
(family, case, parameter, value, outcome, figures). Runs use --threads 1, one at a time.
"""
import csv
import glob
import math
import os
import re
import subprocess
import sys
import time

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
PLATONIC = os.path.join(ROOT, "shapes", "platonic.shp")
EXTREME = os.path.join(HERE, "shapes", "extreme.shp")
G = 9.807
LAW = {"kn": 1.0e5, "kt": 1.0e5, "mu": 0.5, "en": 0.5}


def box_walls(half, floor=0.0):
    walls = [{"wall": {"name": "floor", "point": [0, 0, floor], "normal": [0, 0, 1]}}]
    for name, p, n in (("left", [-half, 0, 0], [1, 0, 0]), ("right", [half, 0, 0], [-1, 0, 0]),
                       ("front", [0, -half, 0], [0, 1, 0]), ("back", [0, half, 0], [0, -1, 0])):
        walls.append({"wall": {"name": name, "point": p, "normal": n}})
    return walls


def scene(bodies, drivers, duration, dt="auto", law=None, csv_every=1e-3, vtk_every=None):
    s = {"simulation": {"duration": duration, "dt": dt, "seed": 3},
         "shapes": [PLATONIC, EXTREME], "bodies": bodies, "drivers": drivers,
         "forces": [{"gravity_force": {"gravity": [0, 0, -G]}},
                    {"contact_polyhedron": {"config": dict(law or LAW)}}],
         "output": {"csv_every": csv_every, "contacts": False}}
    if vtk_every:
        s["output"]["vtk_every"] = vtk_every
    return s


class Runner:
    def __init__(self, polydem, out):
        self.polydem, self.out = polydem, out
        os.makedirs(out, exist_ok=True)

    def write(self, name, s):
        path = os.path.join(self.out, name + ".yaml")
        with open(path, "w") as f:
            yaml.safe_dump(s, f, sort_keys=False)
        return path

    def check(self, name, s):
        """(critical step s, smallest contact-point mass kg) printed by polydem check."""
        return self.check_modes(name, s)[:2]

    def check_modes(self, name, s):
        """(critical step s, normal contact-point mass kg, mode setting it, normal mode alone s)."""
        p = subprocess.run([self.polydem, "check", self.write(name, s)], capture_output=True, text=True)
        m = re.search(r"critical time step: (\S+) s \(smallest contact-point mass (\S+) kg\)\n"
                      r"  set by the (\w+) mode \(normal mode alone: (\S+) s", p.stdout)
        if not m:
            sys.exit(f"polydem check {name}: {p.stderr.strip()}")
        return float(m.group(1)), float(m.group(2)), m.group(3), float(m.group(4))

    def run(self, name, s):
        """Runs a scene with one thread: exit code, wall s, energy rows, stderr, output folder."""
        path, out = self.write(name, s), os.path.join(self.out, name)
        start = time.time()
        p = subprocess.run([self.polydem, "run", path, "--out", out, "--threads", "1"], capture_output=True, text=True)
        wall = time.time() - start
        rows = []
        energy = os.path.join(out, "energy.csv")
        if os.path.exists(energy):
            with open(energy) as f:
                rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
        return p.returncode, wall, rows, p.stderr, out


def crash_note(code):
    """The run ended in a crash after its last output (a segfault writing the final checkpoint)."""
    return f"; exit {code} after the last output" if code not in (0, 1, 2) else ""


def balance(rows):
    """Energy created (> 0) or lost unaccounted, J: stored + dissipated - initial - work in."""
    first, last = rows[0], rows[-1]
    stored = lambda r: r["kinetic"] + r["rotational"] + r["elastic"]
    return stored(last) + last["dissipated"] - stored(first) - last["gravity_work"] - last["driver_work"]


def created(rows):
    """Largest mechanical energy above what was ever put in, J: kinetic + rotational + elastic
    - initial - work of gravity and drivers. Independent of the dissipation ledger."""
    first = rows[0]
    e0 = first["kinetic"] + first["rotational"] + first["elastic"]
    return max(r["kinetic"] + r["rotational"] + r["elastic"] - e0 - r["gravity_work"] - r["driver_work"] for r in rows)


def energy_scale(rows):
    first = rows[0]
    return max(first["kinetic"] + first["rotational"] + first["elastic"] + max(r["gravity_work"] for r in rows), 1e-300)


def bounds(out):
    """Bounding box of the bodies in the last VTK file (python3-vtk9)."""
    import vtk
    files = sorted(glob.glob(os.path.join(out, "bodies_*.vtu")))
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(files[-1])
    reader.Update()
    return reader.GetOutput().GetBounds()


def shape_mass(name, density=2700.0):
    lib = EXTREME if name in ("needle", "plate") else PLATONIC
    import json
    info = json.loads(subprocess.run([RUNNER.polydem, "shape", "info", lib, "--json"], capture_output=True, text=True).stdout)
    shapes = info["shapes"] if isinstance(info, dict) else info
    for s in shapes:
        if s["name"] == name:
            return density * s["volume"]
    raise KeyError(name)


def dt_sweep(rows_out, shapes=("sphere", "cube", "plate", "needle")):
    """Eight bodies of one shape thrown into a 7 cm box at 0.6 m/s, 0.15 s, dt = f x critical.
    Unstable: a non-finite state, or more mechanical energy than was put in (by 1%)."""
    fractions = [0.1, 0.3, 0.5, 0.7, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4, 1.6, 1.8, 2.0, 2.5, 3.0]
    for shape in shapes:
        bodies = [{"generate": "lattice", "shapes": shape, "count": 8,
                   "region": {"box": {"min": [-0.03, -0.03, 0.015], "max": [0.03, 0.03, 0.12]}},
                   "orientation": "random", "velocity": [0.3, -0.2, -0.5]}]
        base = scene(bodies, box_walls(0.035), 0.15)
        critical, m_point, mode, critical_normal = RUNNER.check_modes(f"dt_{shape}_check", base)
        m_body = shape_mass(shape)
        # The printed normal step is for the lightest contact point (rotation included) of a
        # pair; the translational one uses the body mass: same formula, sqrt of the mass ratio.
        critical_translational = critical_normal * math.sqrt(m_body / m_point)
        for f in fractions:
            s = dict(base)
            s["simulation"] = dict(base["simulation"], dt=f * critical)
            code, wall, rows, err, _ = RUNNER.run(f"dt_{shape}_{f:g}", s)
            gain = created(rows) / energy_scale(rows) if rows else float("nan")
            ledger = balance(rows) / energy_scale(rows) if rows else float("nan")
            outcome = "non-finite (exit 2)" if code == 2 else ("energy gain" if gain > 0.01 else "ok")
            rows_out.append(["dt sweep", shape, "dt/critical", f"{f:g}", outcome,
                             f"dt {f * critical:.3g} s; critical {critical:.3g} s ({mode} mode; normal {critical_normal:.3g} s, m* {m_point:.3g} kg), "
                             f"translational {critical_translational:.3g} s; energy created {gain:+.2e} of input; "
                             f"ledger (stored + dissipated - input) {ledger:+.2e}; wall {wall:.1f} s{crash_note(code)}"])
            print(rows_out[-1], flush=True)
            if code == 2 or (outcome != "ok" and f >= 1.0):
                break


def impacts(rows_out):
    """A sphere and a cube (corner first) at increasing speed on the floor, dt auto."""
    for shape, q in (("sphere", None), ("cube", {"axis": [1, 1, 0], "angle": 0.9553166})):
        for v in (1, 3, 10, 30, 50, 100, 300, 1000):
            body = {"shape": shape, "position": [0, 0, 0.02], "velocity": [0, 0, -v]}
            if q:
                body["orientation"] = q
            duration = 0.02 / v + 0.01
            s = scene([body], box_walls(0.2)[:1], duration, csv_every=2e-6, vtk_every=duration)
            code, wall, rows, err, out = RUNNER.run(f"impact_{shape}_{v}", s)
            if not rows or not glob.glob(os.path.join(out, "bodies_000001.vtu")):
                rows_out.append(["impact", shape, "speed m/s", v, f"exit {code}", err.strip().splitlines()[-1][:200]])
                continue
            zmin, zmax = bounds(out)[4:6]
            ke0 = rows[0]["kinetic"]
            e = math.sqrt(max(rows[-1]["kinetic"] + rows[-1]["rotational"], 0) / ke0)
            warned = "warning" in err.lower()
            # Deepest overlap from the largest elastic energy 1/2 kn x^2 (one contact), sampled every 2 us.
            depth = math.sqrt(2.0 * max(r["elastic"] for r in rows) / LAW["kn"])
            outcome = "tunnelled" if zmax < 0 else ("stuck in wall" if zmin < -0.001 else "rebounds")
            if outcome == "rebounds" and depth > 0.005:
                outcome = "rebounds, overlap > 5 mm"
            crash = crash_note(code)
            rows_out.append(["impact", shape, "speed m/s", v, outcome,
                             f"max overlap {depth * 1e3:.3g} mm; final z {zmin:.4g}..{zmax:.4g} m; energy restitution {e:.3f}; "
                             f"warning: {'yes' if warned else 'no'}; wall {wall:.1f} s{crash}"])
            print(rows_out[-1], flush=True)


def write_sheet(path, half=0.1):
    """A flat square sheet of two triangles in the plane z = 0 (ASCII STL), half side `half` m."""
    a, b, c, d = (-half, -half, 0), (half, -half, 0), (half, half, 0), (-half, half, 0)
    with open(path, "w") as f:
        f.write("solid sheet\n")
        for tri in ((a, b, c), (a, c, d)):
            f.write("facet normal 0 0 1\nouter loop\n")
            f.write("".join(f"vertex {x:g} {y:g} {z:g}\n" for x, y, z in tri))
            f.write("endloop\nendfacet\n")
        f.write("endsolid sheet\n")


def sheet_impacts(rows_out):
    """A sphere and a cube (corner first) shot at a thin STL sheet (two triangles, zero thickness)
    at increasing speed, dt auto: does the body pass through, and was it warned?"""
    sheet = os.path.join(RUNNER.out, "sheet.stl")
    write_sheet(sheet)
    for shape, q in (("sphere", None), ("cube", {"axis": [1, 1, 0], "angle": 0.9553166})):
        for v in (1, 10, 20, 30, 40, 50, 60, 80, 100, 300, 1000, 3000):
            body = {"shape": shape, "position": [0, 0, 0.02], "velocity": [0, 0, -v]}
            if q:
                body["orientation"] = q
            duration = 0.04 / v + 0.005
            s = scene([body], [{"stl": {"name": "sheet", "file": sheet}}], duration, csv_every=duration / 2000,
                      vtk_every=duration)
            code, wall, rows, err, out = RUNNER.run(f"sheet_{shape}_{v}", s)
            if not rows or not glob.glob(os.path.join(out, "bodies_000001.vtu")):
                rows_out.append(["stl sheet", shape, "speed m/s", v, f"exit {code}", err.strip().splitlines()[-1][:200]])
                continue
            zmin, zmax = bounds(out)[4:6]
            depth = math.sqrt(2.0 * max(r["elastic"] for r in rows) / LAW["kn"])  # m, one contact
            outcome = "tunnelled" if (zmin + zmax) / 2 < 0 else "rebounds"
            warned = re.search(r"above (\S+) m/s", err)
            rows_out.append(["stl sheet", shape, "speed m/s", v, outcome,
                             f"max overlap {depth * 1e3:.3g} mm; final centre z {(zmin + zmax) / 2:.4g} m; "
                             f"start-up warning: {'yes (above ' + warned.group(1) + ' m/s)' if warned else 'no'}; "
                             f"run-time warning: {'yes' if 'an overlap of' in err else 'no'}; wall {wall:.1f} s{crash_note(code)}"])
            print(rows_out[-1], flush=True)


SETTLED = 1.0  # s: the heaps have landed and stopped sliding by then


def rest_outcome(code, ke):
    """Against the level of the first tenth of the run: at rest when the last kinetic energy is
    below 1e-18 J (speeds ~1e-8 m/s for 27 g), rings down below 1e-3 of that level, rings on
    within it; otherwise it grows."""
    if code == 2:
        return "non-finite (exit 2)"
    early = max(ke[:len(ke) // 10 + 1])
    if ke[-1] < 1e-18:
        return "at rest"
    if ke[-1] < 1e-3 * early:
        return "rings down"
    return "rings on, bounded" if ke[-1] <= early else "energy grows"


def rest(rows_out, steps=1_000_000):
    """A tower of 6 offset cubes and heaps of 27 cubes, settled then run to `steps` steps."""
    tower = [{"shape": "cube", "position": [0.001 if k % 2 else -0.001, 0.0005 * (k % 3), 0.005 + 0.01 * k],
              "orientation": {"axis": [0, 0, 1], "angle": 0.17 if k % 2 else -0.17}} for k in range(6)]
    heap = [{"generate": "lattice", "shapes": "cube", "count": 27,
             "region": {"box": {"min": [-0.025, -0.025, 0.012], "max": [0.025, 0.025, 0.07]}},
             "orientation": "random"}]
    damped = dict(LAW, damp_tangential=0.3)  # the heap's torsion and rocking ring on without it
    floor = box_walls(0.1)[:1]
    for name, bodies, law, seed in (("tower", tower, LAW, 3), ("heap", heap, LAW, 3),
                                    ("heap, damp_tangential 0.3", heap, damped, 3),
                                    ("heap, damp_tangential 0.3, seed 4", heap, damped, 4)):
        base = scene(bodies, floor, 1.0, law=law, csv_every=0.01)
        base["simulation"]["seed"] = seed
        file = "rest_" + name.replace(", ", "_").replace(" ", "_")
        critical, _ = RUNNER.check(file + "_check", base)
        dt = 0.1 * critical
        base["simulation"]["duration"] = steps * dt
        code, wall, rows, err, _ = RUNNER.run(file, base)
        settle = [r for r in rows if r["time"] >= SETTLED]
        ke = [r["kinetic"] + r["rotational"] for r in settle]
        creep = settle[-1]["gravity_work"] - settle[0]["gravity_work"]  # J: m g times the mean descent
        drift = balance(rows) - balance(rows[:rows.index(settle[0]) + 1])  # J, energy created after settling
        rows_out.append(["rest", name, "steps", steps, rest_outcome(code, ke),
                         f"simulated {steps * dt:.3g} s at dt {dt:.3g} s; after {SETTLED:g} s: kinetic max {max(ke):.2e} J, last {ke[-1]:.2e} J; "
                         f"gravity work change {creep:+.2e} J (creep); energy balance change {drift:+.2e} J of "
                         f"{energy_scale(rows):.3e} J; wall {wall:.0f} s{crash_note(code)}"])
        print(rows_out[-1], flush=True)


def extreme(rows_out):
    """Needles 1:20, plates 20:1 and a 1:10 sphere size mix poured into a box, dt auto."""
    mixes = {
        "needles 1:20": [{"generate": "lattice", "shapes": "needle", "count": 60, "orientation": "random",
                          "region": {"box": {"min": [-0.04, -0.04, 0.01], "max": [0.04, 0.04, 0.2]}}}],
        "plates 20:1": [{"generate": "lattice", "shapes": "plate", "count": 24, "orientation": "random",
                         "region": {"box": {"min": [-0.04, -0.04, 0.015], "max": [0.04, 0.04, 0.2]}}}],
        "spheres 1:10": [{"generate": "random", "shapes": "sphere", "count": 100, "scale": {"min": 0.1, "max": 0.1},
                          "region": {"box": {"min": [-0.035, -0.035, 0.025], "max": [0.035, 0.035, 0.04]}}},
                         {"generate": "random", "shapes": "sphere", "count": 10,
                          "region": {"box": {"min": [-0.035, -0.035, 0.005], "max": [0.035, 0.035, 0.02]}}}],
    }
    for name, bodies in mixes.items():
        # The 1:10 mix runs at the small spheres' step (0.03 x that of the big ones): 0.06 s.
        duration = 0.06 if "1:10" in name else 0.3
        s = scene(bodies, box_walls(0.045), duration, vtk_every=duration)
        critical, m_point = RUNNER.check("extreme_check", s)
        code, wall, rows, err, out = RUNNER.run("extreme_" + name.split()[0], s)
        figures = f"critical {critical:.3g} s (m* {m_point:.3g} kg), dt auto; wall {wall:.0f} s"
        if rows:
            b = bounds(out)
            escaped = b[0] < -0.047 or b[1] > 0.047 or b[2] < -0.047 or b[3] > 0.047 or b[4] < -0.002
            figures += (f"; energy created {created(rows) / energy_scale(rows):+.2e} of input"
                        f"; ledger {balance(rows) / energy_scale(rows):+.2e} of input; final kinetic "
                        f"{rows[-1]['kinetic'] + rows[-1]['rotational']:.2e} J; bodies inside the box: {'no' if escaped else 'yes'}")
        outcome = "non-finite (exit 2)" if code == 2 else "completed"
        rows_out.append(["extreme", name, "bodies", sum(g["count"] for g in bodies), outcome, figures + crash_note(code)])
        print(rows_out[-1], flush=True)


RUNNER = None


def main():
    global RUNNER
    RUNNER = Runner(os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]))
    # FAMILY or FAMILY:CASE,CASE (dt:sphere reruns the spheres of the dt sweep only)
    families = [a.split(":") + [""] if ":" not in a else a.split(":") for a in sys.argv[3:]] or \
        [[f, ""] for f in ("dt", "impact", "sheet", "rest", "extreme")]
    results = os.path.join(HERE, "results.csv")
    old = []
    if os.path.exists(results):  # keep the rows of the families (and cases) not rerun
        with open(results) as f:
            old = [r for r in csv.reader(f)][1:]
    names = {"dt": "dt sweep", "impact": "impact", "rest": "rest", "extreme": "extreme", "sheet": "stl sheet"}
    rerun = lambda r: any(names[f] == r[0] and (not cases or r[1] in cases.split(",")) for f, cases in families)
    rows = [r for r in old if r and not rerun(r)]
    runners = {"dt": dt_sweep, "impact": impacts, "rest": rest, "extreme": extreme, "sheet": sheet_impacts}
    for family, cases in families:
        if family not in runners:
            sys.exit(f"unknown family '{family}': expected one of {', '.join(runners)}")
        if cases and family == "dt":
            dt_sweep(rows, cases.split(","))
        else:
            runners[family](rows)
        with open(results, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["family", "case", "parameter", "value", "outcome", "figures"])
            w.writerows(rows)


if __name__ == "__main__":
    main()
