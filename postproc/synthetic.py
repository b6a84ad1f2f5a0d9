"""Synthetic contact sets drawn from the seed's harmonic forms (eqs. 6, 7 and 9).

Used by the tests (known truth) and by the benchmarks. A contact set with
anisotropies (a, a_l, a_n, a_t) about an axis is drawn as follows, with
theta the angle between the branch direction n and the axis:

* n with density P(n) = (1/4pi)[1 + a(3cos^2 theta - 1)] (rejection sampling);
* branch length l = <l>(theta) * U, U uniform on [1-s_l, 1+s_l] (mean 1);
* radial force f_n' = <f_n'>(theta) * E, E exponential with mean 1 (the
  usual shape of contact force distributions);
* orthoradial force f_t' = f0 a_t sin 2theta + f0 s_t Z (Z standard normal)
  along t', the unit vector towards the axis in the meridian plane (n taken
  in the hemisphere n.axis >= 0), plus an azimuthal component f0 s_t Z'
  with zero mean.

So <l>, <f_n'> and <f_t'> follow eqs. 6, 7 and 9 exactly. Each contact joins two
fresh bodies (ids 2k, 2k+1) placed at random in a box; the order of id1 and
id2 is then swapped at random (n and f change sign together), which leaves
every physical quantity unchanged.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .axes import rotation_z_to
from .schema import KIND_SPHERE, DumpWriter


@dataclass
class SyntheticContacts:
    """Contacts with known anisotropies. Shapes: (N, 3) vectors, (N,) ids."""

    branch: np.ndarray       # l = x2 - x1, m
    force: np.ndarray        # on id2 by id1, N
    id1: np.ndarray
    id2: np.ndarray
    x1: np.ndarray
    x2: np.ndarray
    point: np.ndarray        # contact point, midway along the branch
    volume: float            # m^3, the box the bodies were placed in
    truth: dict              # a, a_l, a_n, a_t, l0, f0, axis


def sample_directions(n, a, rng):
    """(n, 3) unit vectors with density (1/4pi)[1 + a(3 cos^2 theta - 1)]
    about +z. Requires -1/2 <= a <= 1 (a non-negative density)."""
    if not -0.5 <= a <= 1.0:
        raise ValueError(f"a = {a} gives a negative density; need -1/2 <= a <= 1")
    peak = max(1 + 2 * a, 1 - a)
    out = np.empty((0,))
    need = n
    chunks = []
    while need > 0:
        m = int(need * peak * 1.2) + 16
        u = rng.uniform(-1, 1, m)
        keep = rng.uniform(0, peak, m) < 1 + a * (3 * u * u - 1)
        u = u[keep][:need]
        chunks.append(u)
        need -= len(u)
    u = np.concatenate(chunks) if chunks else out
    phi = rng.uniform(0, 2 * np.pi, n)
    s = np.sqrt(1 - u * u)
    return np.column_stack([s * np.cos(phi), s * np.sin(phi), u])


def harmonic_contacts(n, a=0.0, a_l=0.0, a_n=0.0, a_t=0.0, *, axis=2,
                      l0=0.03, f0=10.0, spread_l=0.3, spread_t=0.3,
                      box=1.0, seed=0):
    """Draw ``n`` contacts from the harmonic forms with the given anisotropies.

    Parameters
    ----------
    n : int, number of contacts.
    a, a_l, a_n, a_t : anisotropies (dimensionless). Need -1/2 <= a, a_l,
        a_n <= 1 so that densities, lengths and mean forces stay >= 0.
    axis : compression axis (0/1/2, 'x'/'y'/'z' or a 3-vector).
    l0 : m, mean branch length; f0 : N, mean radial force.
    spread_l : half-width of the relative length noise (< 1).
    spread_t : standard deviation of the tangential noise, in units of f0.
    box : m, side of the cubic box the bodies are placed in (volume box^3).
    seed : int or numpy Generator.

    Returns
    -------
    SyntheticContacts
    """
    for name, val in (("a_l", a_l), ("a_n", a_n)):
        if not -0.5 <= val <= 1.0:
            raise ValueError(f"{name} = {val} gives negative means; need -1/2 <= {name} <= 1")
    if not 0 <= spread_l < 1:
        raise ValueError("spread_l must be in [0, 1)")
    rng = seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)
    nz = sample_directions(n, a, rng)
    nz *= np.where(nz[:, 2] < 0, -1.0, 1.0)[:, None]       # hemisphere c >= 0
    c = nz[:, 2]
    sin = np.sqrt(np.maximum(1 - c * c, 0.0))
    p2 = 3 * c * c - 1
    length = l0 * (1 + a_l * p2) * rng.uniform(1 - spread_l, 1 + spread_l, n)
    fn = f0 * (1 + a_n * p2) * rng.exponential(1.0, n)
    ft = f0 * a_t * 2 * sin * c + f0 * spread_t * rng.standard_normal(n)
    fphi = f0 * spread_t * rng.standard_normal(n)
    ez = np.array([0.0, 0.0, 1.0])
    # t' = (e - c n)/sin theta points towards the axis; e_phi = e x n / sin
    with np.errstate(invalid="ignore", divide="ignore"):
        t = (ez[None, :] - c[:, None] * nz) / sin[:, None]
        ephi = np.cross(ez[None, :], nz) / sin[:, None]
    pole = sin < 1e-12
    t[pole] = [1.0, 0.0, 0.0]
    ephi[pole] = [0.0, 1.0, 0.0]
    f = fn[:, None] * nz + ft[:, None] * t + fphi[:, None] * ephi
    R = rotation_z_to(axis)
    nvec = nz @ R.T
    f = f @ R.T
    flip = np.where(rng.random(n) < 0.5, -1.0, 1.0)[:, None]
    branch = length[:, None] * nvec * flip
    f = f * flip
    x1 = rng.uniform(0, box, (n, 3))
    x2 = x1 + branch
    ids = np.arange(2 * n, dtype=np.int64)
    return SyntheticContacts(
        branch=branch, force=f, id1=ids[0::2], id2=ids[1::2], x1=x1, x2=x2,
        point=x1 + 0.5 * branch, volume=float(box) ** 3,
        truth={"a": a, "a_l": a_l, "a_n": a_n, "a_t": a_t, "l0": l0,
               "f0": f0, "axis": axis},
    )


def write_synthetic_dump(path, n_contacts=20000, n_snapshots=6, final=(0.3, 0.1, 0.5, 0.2),
                         axis=2, seed=0):
    """Write a dump (schema v1) whose snapshots are harmonic contact sets with
    anisotropies ramping linearly from 0 to ``final`` = (a, a_l, a_n, a_t),
    while the box shortens along ``axis`` by up to 10 %. A stand-in for a
    simulation, with known truth, to exercise the whole analysis chain.

    Every contact joins two fresh spheres; there are no wall contacts, and the
    wall forces are left at zero. Returns the list of truths per snapshot.
    """

    rng = np.random.default_rng(seed)
    k_ax = int(np.argmax(np.abs(np.asarray(rotation_z_to(axis))[:, 2])))
    truths = []
    with DumpWriter(path, "spheres", {"generator": "postproc.synthetic.write_synthetic_dump",
                                      "n_contacts": n_contacts, "final": list(final),
                                      "axis": k_ax, "seed": seed}) as w:
        for k in range(n_snapshots):
            frac = k / max(n_snapshots - 1, 1)
            aniso = [frac * x for x in final]
            s = harmonic_contacts(n_contacts, *aniso, axis=axis, seed=rng)
            truths.append(dict(zip(("a", "a_l", "a_n", "a_t"), aniso)))
            ids = np.concatenate([s.id1, s.id2]) + 6
            nb = len(ids)
            lengths = np.ones(3)
            lengths[k_ax] -= 0.1 * frac
            unit = s.branch / np.linalg.norm(s.branch, axis=1)[:, None]
            fn = np.einsum("ij,ij->i", s.force, unit)[:, None] * unit
            w.write_snapshot(
                step=1000 * k, time=0.01 * k, stage="shear",
                box_lo=np.zeros(3), box_hi=lengths, wall_ids=np.arange(6),
                wall_forces=np.zeros((6, 3)),
                bodies={"id": ids, "kind": np.full(nb, KIND_SPHERE),
                        "position": np.concatenate([s.x1, s.x2]),
                        "orientation": np.tile([1.0, 0, 0, 0], (nb, 1)),
                        "volume": np.full(nb, np.pi / 6 * 0.03 ** 3),
                        "mass": np.full(nb, 2700 * np.pi / 6 * 0.03 ** 3),
                        "shape_index": np.full(nb, -1), "size": np.full(nb, 0.03)},
                contacts={"id1": s.id1 + 6, "id2": s.id2 + 6, "point": s.point,
                          "normal": unit, "force_normal": fn,
                          "force_tangential": s.force - fn, "overlap": np.zeros(len(unit))})
    return truths
