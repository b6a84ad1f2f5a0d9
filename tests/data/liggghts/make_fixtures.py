"""Make the real-LIGGGHTS fixtures of tests/test_liggghts_fixtures.py.

    apt-get install -y liggghts          # Debian 12: LIGGGHTS-PUBLIC 3.8.0, binary 'liggghts'
    python3 tests/data/liggghts/make_fixtures.py

(numpy only; the script writes a LIGGGHTS input, runs ``liggghts`` on one
core and reads its log). Not run by the test suite: its outputs, written
next to this script, are committed.

A periodic packing of 120 frictional spheres (ids from 2 000 001 up in
steps of 7, above 10^6 as in runs where particles are inserted over time,
given in the data file; diameters 8-12 mm, 2500 kg/m^3, ``pair_style gran
model hertz tangential history``: Hertz normal force, history tangential
force, Young's modulus 5 MPa, Poisson 0.45, restitution 0.5, friction 0.5)
is compressed isotropically (fix deform to a cube centred on the origin),
then sheared twice at constant y (fix deform: x stretched, z shortened, 5 %
and 10 %). At three steps (compressed; sheared; sheared further), each a
``run 0`` so that the contact forces that LIGGGHTS dumps and the ones in its
virial come from the same state (a dump of compute pair/gran/local recomputes
the forces; after a step the velocities, hence the damping forces, have
moved on), it writes

* ``contacts.dump``: ``compute pair/gran/local pos id force`` (12 columns)
  with ``dump_modify ID format "%.17g ... %.17g"`` (one per column: LIGGGHTS
  3.8 refuses LAMMPS's ``format float``), so every value is the double
  LIGGGHTS had and the ids are exact;
* ``contacts-nt.dump``: ``pos id force_normal force_tangential`` (15
  columns). LIGGGHTS allows one pair/gran/local compute per pair style, so
  both files come from ``pos id force force_normal force_tangential`` (18
  columns), the 15 being columns 1-9 and 13-18, what the compute with those
  keywords alone writes;
* ``contacts-g.dump``: the 12 columns in LIGGGHTS's default ``%g`` (ids
  rounded to 6 significant digits: what a user gets without dump_modify);
* ``atoms.dump``: ``dump custom`` id x y z radius, %.17g;
* ``in.fixtures``: the LIGGGHTS input that made them (it reads a data file
  that this script writes and deletes);
* ``pressure.json``: per step, LIGGGHTS's own pair virial tensor
  (``compute pressure thermo_temp pair``: pxx pyy pzz pxy pxz pyz, Pa; the
  temperature is not used with the keyword ``pair``), the box (lo, hi,
  volume) and the number of rows of contacts.dump, the numbers printed by
  LIGGGHTS with %.20g (its immediate variables ``$(...)``).

Box bounds: LIGGGHTS writes a dump's box bounds with ``%g`` (6 significant
digits) whatever dump_modify says, so the box is deformed to bounds of 4
significant digits: the headers then hold LIGGGHTS's box exactly (to the
last bit of the double), which pressure.json confirms.

No tilted box: LIGGGHTS 3.8 makes no ghost atoms in a triclinic periodic
box (``change_box all triclinic`` at zero tilt, or a triclinic data file:
the log shows ``Nghost: 0``, the 100 contacts across the boundaries of the
compressed packing vanish from both compute pair/gran/local and the virial,
and particles are lost once the box is sheared; its comm_I.h says that the
granular communication is "not valid for triclinic").
"""
import json
import os
import re
import shutil
import subprocess
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
N, ID0, ID_STEP = 120, 2_000_001, 7
RHO, D_MIN, D_MAX = 2500.0, 0.008, 0.012
PHI0, PHI1 = 0.20, 0.66           # solid fraction of the start, of the compressed box
FILES = ("contacts.dump", "contacts-nt.dump", "contacts-g.dump", "atoms.dump")


def packing(rng):
    """Diameters and a dilute random packing (no overlaps) in a cube of side L."""
    d = rng.uniform(D_MIN, D_MAX, N)
    L = float((np.sum(np.pi / 6 * d ** 3) / PHI0) ** (1 / 3))
    pos = []
    for k in range(N):
        while True:
            x = rng.uniform(0, L, 3)
            dd = x - np.array(pos).reshape(-1, 3)
            dd -= L * np.round(dd / L)
            if np.all(np.linalg.norm(dd, axis=1) >= 0.5 * (d[k] + d[:len(pos)]) * 1.02):
                pos.append(x)
                break
    return d, np.array(pos), L


def data_file(path, d, pos, lo, hi):
    """A LIGGGHTS data file (atom_style granular: id type diameter density x y z)."""
    with open(path, "w") as fh:
        fh.write(f"fixture packing\n\n{N} atoms\n1 atom types\n\n{lo!r} {hi!r} xlo xhi\n{lo!r} {hi!r} ylo yhi\n"
                 f"{lo!r} {hi!r} zlo zhi\n\nAtoms\n\n")
        for k in range(N):
            x, y, z = map(float, pos[k])
            fh.write(f"{ID0 + ID_STEP * k} 1 {float(d[k])!r} {RHO!r} {x!r} {y!r} {z!r}\n")


def snapshot():
    """Input lines writing one snapshot (a run 0: the forces that LIGGGHTS dumps
    and the ones in its virial come from one state) and printing LIGGGHTS's
    tensor and box with %.20g (LIGGGHTS's immediate variables)."""
    c12 = " ".join(f"c_pgl[{i}]" for i in range(1, 13))
    c15 = " ".join(f"c_pgl[{i}]" for i in list(range(1, 10)) + list(range(13, 19)))
    f12 = '"' + " ".join(["%.17g"] * 12) + '"'
    f15 = '"' + " ".join(["%.17g"] * 15) + '"'
    vals = " ".join(f"$({v})" for v in ("step", "c_p[1]", "c_p[2]", "c_p[3]", "c_p[4]", "c_p[5]", "c_p[6]",
                                         "xlo", "xhi", "ylo", "yhi", "zlo", "zhi", "vol"))
    return f"""
dump d12 all local 1 contacts.dump {c12}
dump_modify d12 append yes format {f12}
dump d15 all local 1 contacts-nt.dump {c15}
dump_modify d15 append yes format {f15}
dump dg all local 1 contacts-g.dump {c12}
dump_modify dg append yes
dump da all custom 1 atoms.dump id x y z radius
dump_modify da append yes format "%d %.17g %.17g %.17g %.17g"
run 0
undump d12
undump d15
undump dg
undump da
print "SNAPSHOT {vals}"
"""


def short(x):
    """x to 4 significant digits: LIGGGHTS's %g box bounds then hold it exactly."""
    return float(f"{x:.4g}")


def main():
    rng = np.random.default_rng(2026)
    d, pos, L0 = packing(rng)
    h = short(0.5 * (np.sum(np.pi / 6 * d ** 3) / PHI1) ** (1 / 3))     # half side of the compressed cube
    # pure shear at constant y: x stretched, z shortened (x z about h^2), twice
    shear = [(short(h * (1 + e)), short(h * h / (h * (1 + e)))) for e in (0.05, 0.10)]
    tmp = tempfile.mkdtemp(prefix="liggghts-fixtures-")
    data_file(os.path.join(tmp, "packing.data"), d, pos - L0 / 2, -L0 / 2, L0 / 2)
    script = f"""
atom_style granular
atom_modify map hash
boundary p p p
newton off
communicate single vel yes
units si
read_data packing.data
neighbor 0.001 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1.0e-5
fix integ all nve/sphere
compute p all pressure thermo_temp pair
compute pgl all pair/gran/local pos id force force_normal force_tangential
thermo_style custom step atoms c_p[1] c_p[2] c_p[3] c_p[4] vol
thermo 5000
fix squeeze all deform 1 x final {-h!r} {h!r} y final {-h!r} {h!r} z final {-h!r} {h!r} remap x
run 30000
unfix squeeze
run 5000
{snapshot()}
""" + "".join(f"""
fix shear all deform 1 x final {-a!r} {a!r} z final {-c!r} {c!r} remap x
run 10000
unfix shear
{snapshot()}
""" for a, c in shear)
    with open(os.path.join(tmp, "in.fixtures"), "w") as fh:
        fh.write(script)
    res = subprocess.run(["liggghts", "-in", "in.fixtures", "-log", "log.liggghts"], cwd=tmp,
                         capture_output=True, text=True, timeout=600)
    if res.returncode != 0 or "ERROR" in res.stdout:
        raise SystemExit(f"liggghts failed (input and log in {tmp}):\n" + res.stdout[-3000:] + res.stderr[-2000:])
    version = re.search(r"LIGGGHTS \(Version ([^,)]*)", res.stdout).group(1)
    snaps = []
    for line in res.stdout.splitlines():
        if line.startswith("SNAPSHOT "):
            v = line.split()[1:]
            f = [float(x) for x in v]
            snaps.append({"step": int(v[0]), "pxx_pyy_pzz_pxy_pxz_pyz": f[1:7],
                          "lo": f[7:13:2], "hi": f[8:13:2], "volume": f[13]})
    counts = [int(n) for n in re.findall(r"\nITEM: NUMBER OF ENTRIES\n(\d+)", open(os.path.join(tmp, "contacts.dump")).read())]
    lost = re.findall(r"^ +\d+ +(\d+) ", res.stdout, re.M)
    if len(snaps) != 3 or len(counts) != 3 or any(int(n) != N for n in lost):
        raise SystemExit(f"unexpected output in {tmp}: {len(snaps)} snapshots, counts {counts}, atoms {set(lost)}")
    for s, n in zip(snaps, counts):
        s["contacts"] = n
    for f in FILES + ("in.fixtures",):
        shutil.copy(os.path.join(tmp, f), os.path.join(HERE, f))
    with open(os.path.join(HERE, "pressure.json"), "w") as fh:
        json.dump({"liggghts_version": version, "n_atoms": N, "first_id": ID0, "id_step": ID_STEP,
                   "pair": "gran model hertz tangential history; youngsModulus 5e6, poissonsRatio 0.45, "
                           "coefficientRestitution 0.5, coefficientFriction 0.5",
                   "pressure": "compute pressure thermo_temp pair", "snapshots": snaps}, fh, indent=1)
    shutil.rmtree(tmp)
    print("fixtures:", ", ".join(sorted(f for f in os.listdir(HERE) if not f.endswith(".py") and f != "__pycache__")))
    for s in snaps:
        print(s["step"], s["contacts"], s["pxx_pyy_pzz_pxy_pxz_pyz"])


if __name__ == "__main__":
    main()
