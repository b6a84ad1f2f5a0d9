"""The CD scene's bodies, laws and visibility tables, written as LMGC90's DATBOX.

One function, :func:`write_datbox`, takes the grains (posed polyhedra or
spheres), the box and the contact parameters and writes ``DATBOX/`` with
LMGC90's ``pre`` API: the grains as POLYR (polyhedra) or SPHER (spheres)
RBDY3 bodies, then six PLANx walls, the two IQS_CLB laws (grain-grain
friction ``mu``, grain-wall ``mu_wall``) and the visibility tables with
their alert distance. The body order in LMGC90 (1-based) is the grains'
order, then the walls in the dump's order x-, x+, y-, y+, z-, z+.

Why PLANx walls (and not thin POLYR boxes): a PLANx is LMGC90's rigid plane,
its contacts with a polyhedron (PRPLx) or a sphere (SPPLx) are found along
the plane's normal exactly, one point per vertex within the alert distance,
with no polyhedron-polyhedron detection to tune; a thin POLYR box would go
through the PRPRx detection (common-plane iterations, face-to-face
clipping) the grains use, cost more per step and add its own tolerances.
Each PLANx's local z axis points into the box (LMGC90 detects a PLANx
contact only on that side).

Every wall has all six velocity DOFs driven (zero), so LMGC90 holds it;
the scene frees a wall's normal DOF (``RBDY3_SetInvisibleVlocyDrivenDof``)
to push it with a force (stress control) or sets that DOF's velocity
(``RBDY3_SetVlocyDrivenDof``: the top wall in shear).
"""
from __future__ import annotations

import os
import shutil
from dataclasses import dataclass

import numpy as np

GRAIN_COLOR = "BLEUx"
WALL_COLOR = "WALLx"
#: each wall's axis and the side it bounds, in the dump's order x-, x+, y-, y+, z-, z+
WALL_AXES = ((0, -1), (0, 1), (1, -1), (1, 1), (2, -1), (2, 1))


@dataclass
class Walls:
    """The six PLANx walls as written (dump order x-, x+, y-, y+, z-, z+).

    Attributes
    ----------
    half_size : float
        m, half the side of each square wall (PLANx axe1 = axe2).
    half_thickness : float
        m, PLANx axe3; the wall's centre is this far outside its inner face.
    mass : float
        kg, each wall's mass (from the wall material's density).
    """

    half_size: float
    half_thickness: float
    mass: float


def wall_centres(lo, hi, half_thickness):
    """The centres of the six walls whose inner faces are the box's faces.

    Parameters
    ----------
    lo, hi : array_like, shape (3,)
        m, the box (inner faces).
    half_thickness : float
        m.

    Returns
    -------
    ndarray, shape (6, 3)
        m, dump order x-, x+, y-, y+, z-, z+; each centre is on the box's
        axis through the middle of its face.

    Examples
    --------
    >>> from lmgc90.cdmodel import wall_centres
    >>> print(wall_centres([0, 0, 0], [1, 1, 2], 0.1)[5])
    [0.5 0.5 2.1]
    """
    lo = np.asarray(lo, float)
    hi = np.asarray(hi, float)
    mid = 0.5 * (lo + hi)
    out = np.tile(mid, (6, 1))
    for k, (axis, side) in enumerate(WALL_AXES):
        out[k, axis] = (hi[axis] + half_thickness) if side > 0 else (lo[axis] - half_thickness)
    return out


def _wall_rotation(axis, side):
    """(axis of rotation, angle) turning a PLANx's local z into the inward normal."""
    if axis == 2:
        return ([1.0, 0.0, 0.0], 0.0 if side < 0 else np.pi)
    if axis == 1:     # about x: z -> (0, -sin a, cos a); inward +y needs a = -pi/2
        return ([1.0, 0.0, 0.0], -0.5 * np.pi if side < 0 else 0.5 * np.pi)
    # about y: z -> (sin a, 0, cos a); inward +x needs a = +pi/2
    return ([0.0, 1.0, 0.0], 0.5 * np.pi if side < 0 else -0.5 * np.pi)


def write_datbox(folder, grains, lo, hi, *, kind, density, mu, mu_wall, alert, wall_mass,
                 wall_half_size, wall_half_thickness, pre):
    """Write ``folder/DATBOX`` for the CD scene.

    Parameters
    ----------
    folder : str
        The run folder (LMGC90's working directory); an old DATBOX is replaced.
    grains : list of dict
        One per grain, in order: ``vertices`` (V, 3) m posed in the global
        frame and ``triangles`` (T, 3) int (0-based, outward) for polyhedra;
        ``centre`` (3,) m and ``radius`` m for spheres.
    lo, hi : array_like, shape (3,)
        m, the box (the walls' inner faces).
    kind : {"polyhedra", "spheres"}
    density : float
        kg/m^3, the grains'.
    mu, mu_wall : float
        Coulomb friction grain-grain and grain-wall (IQS_CLB).
    alert : float
        m, the visibility tables' alert distance: a pair is an interaction
        once its gap is below it.
    wall_mass : float
        kg, each wall's mass.
    wall_half_size, wall_half_thickness : float
        m, PLANx axe1 = axe2 and axe3.
    pre : module
        ``pylmgc90.pre``.

    Returns
    -------
    Walls
    """
    datbox = os.path.join(folder, "DATBOX")
    if os.path.isdir(datbox):
        shutil.rmtree(datbox)
    os.makedirs(datbox)
    bodies, mats, mods = pre.avatars(), pre.materials(), pre.models()
    svs, tacts = pre.see_tables(), pre.tact_behavs()
    wall_volume = 8.0 * wall_half_size ** 2 * wall_half_thickness
    gmat = pre.material(name="GRAIN", materialType="RIGID", density=float(density))
    wmat = pre.material(name="WALLm", materialType="RIGID", density=float(wall_mass / wall_volume))
    mats.addMaterial(gmat)
    mats.addMaterial(wmat)
    mod = pre.model(name="rigid", physics="MECAx", element="Rxx3D", dimension=3)
    mods.addModel(mod)
    for g in grains:
        if kind == "polyhedra":
            v = np.array(g["vertices"], float)
            faces = np.asarray(g["triangles"], np.int64) + 1
            body = pre.rigidPolyhedron(model=mod, material=gmat, color=GRAIN_COLOR, generation_type="full",
                                       vertices=v, faces=faces)
        else:
            body = pre.rigidSphere(r=float(g["radius"]), center=np.asarray(g["centre"], float), model=mod,
                                   material=gmat, color=GRAIN_COLOR)
        bodies += body
    centres = wall_centres(lo, hi, wall_half_thickness)
    for k, (axis, side) in enumerate(WALL_AXES):
        w = pre.rigidPlan(axe1=wall_half_size, axe2=wall_half_size, axe3=wall_half_thickness,
                          center=centres[k], model=mod, material=wmat, color=WALL_COLOR)
        about, angle = _wall_rotation(axis, side)
        if angle:
            w.rotate(description="axis", alpha=angle, axis=about, center=w.nodes[1].coor)
        w.imposeDrivenDof(component=[1, 2, 3, 4, 5, 6], dofty="vlocy")
        bodies += w
    law_gg = pre.tact_behav(name="iqsg0", law="IQS_CLB", fric=float(mu))
    law_gw = pre.tact_behav(name="iqsw0", law="IQS_CLB", fric=float(mu_wall))
    tacts += law_gg
    tacts += law_gw
    tac = "POLYR" if kind == "polyhedra" else "SPHER"
    svs += pre.see_table(CorpsCandidat="RBDY3", candidat=tac, colorCandidat=GRAIN_COLOR,
                         CorpsAntagoniste="RBDY3", antagoniste=tac, colorAntagoniste=GRAIN_COLOR,
                         behav=law_gg, alert=float(alert))
    svs += pre.see_table(CorpsCandidat="RBDY3", candidat=tac, colorCandidat=GRAIN_COLOR,
                         CorpsAntagoniste="RBDY3", antagoniste="PLANx", colorAntagoniste=WALL_COLOR,
                         behav=law_gw, alert=float(alert))
    pre.writeDatbox(3, mats, mods, bodies, tacts, svs, datbox_path=datbox, gravy=[0.0, 0.0, 0.0])
    return Walls(float(wall_half_size), float(wall_half_thickness), float(wall_mass))
