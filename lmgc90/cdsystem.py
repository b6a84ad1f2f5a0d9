"""One LMGC90 Contact Dynamics system, stepped from Python through ``chipy``.

:class:`CDSystem` reads the DATBOX of a run folder (:mod:`lmgc90.cdmodel`),
steps it with LMGC90's rigid-body scheme (Moreau-Jean, theta method), solves
each step's contact problem by NLGS (``Stored_Delassus_Loops``, LMGC90's
``nlgs_3D`` driven check by check so the iterations are counted), and gives
the state as arrays (body positions, frames, velocities, reactions, the
interactions). After the solve the bodies' reactions are assembled
again from the final local reactions (``nlgs_3D_ComputeRnod`` after
``nlgs_3D_ExPost``, which sweeps the contacts once more after its own
assembly): the contact forces the bodies move by are those stored and
dumped. The walls are driven through their velocity DOFs (held, or
moved at a set speed) or pushed by an external force (a freed normal DOF).

LMGC90 keeps its state in one Fortran module per process: one CDSystem per
process. Its checkpoints are LMGC90's own restart files (``DOF.LAST``,
``Vloc_Rloc.LAST``: the warm start of the contact forces) plus every body's
displacement, velocity and inertia frame at full precision (npz), so a
resumed run continues from the same state.
"""
from __future__ import annotations

import os
import shutil

import numpy as np


class CDSystem:
    """LMGC90's CD system of a run folder.

    Parameters
    ----------
    chipy : module
        ``pylmgc90.chipy`` (:func:`lmgc90.build.import_pylmgc90`).
    folder : str
        The run folder holding ``DATBOX/``; LMGC90 writes ``OUTBOX/`` there.
    dt : float
        s, the time step.
    theta : float
        The theta method's parameter (0.5: LMGC90's usual choice).
    cundall_iterations : int
        Iterations of the PRPRx common-plane (Cundall) detection.
    restart : str, optional
        A checkpoint folder (:meth:`save`) to start from.

    Attributes
    ----------
    n_bodies : int
        RBDY3 bodies (grains, then the six walls).
    masses : ndarray, shape (n_bodies,)
        kg, as LMGC90 computed them.
    iterations : int
        NLGS iterations of the last step.
    converged : bool
        Whether the last step's NLGS met its tolerance.
    """

    def __init__(self, chipy, folder, dt, theta=0.5, cundall_iterations=50, restart=None):
        self.chipy = chipy
        self.folder = os.path.abspath(folder)
        os.chdir(self.folder)
        c = chipy
        c.Initialize()
        c.checkDirectories()
        c.utilities_DisableLogMes()
        c.SetDimension(3)
        c.PRPRx_UseCpCundallDetection(int(cundall_iterations))
        c.TimeEvolution_SetTimeStep(float(dt))
        c.Integrator_InitTheta(float(theta))
        datbox = os.path.join(self.folder, "DATBOX")
        if restart is not None:
            shutil.copy(os.path.join(restart, "DOF.LAST"), os.path.join(datbox, "DOF.INI"))
            shutil.copy(os.path.join(restart, "Vloc_Rloc.LAST"), os.path.join(datbox, "Vloc_Rloc.INI"))
        c.ReadDatbox(deformable=False)
        c.ComputeMass()
        self.dt = float(dt)
        self.n_bodies = int(c.RBDY3_GetNbRBDY3())
        if restart is not None:
            state = np.load(os.path.join(restart, "bodies.npz"))
            for i in range(self.n_bodies):
                c.RBDY3_PutBodyVector("Xbeg_", i + 1, state["Xbeg"][i])
                c.RBDY3_PutBodyVector("Vbeg_", i + 1, state["Vbeg"][i])
                c.RBDY3_PutBodyMatrix("IFbeg", i + 1, state["IFbeg"][i])
            c.TimeEvolution_SetInitialStep(int(state["step"]))
            c.TimeEvolution_SetInitialTime(float(state["time"]))
            c.RBDY3_CompCoor()
        self.masses = np.array([c.RBDY3_GetMass(i + 1) for i in range(self.n_bodies)])
        self.driven = {}           # (0-based body, dof) -> velocity set every step
        self.iterations = 0        # NLGS iterations of the last step
        self.converged = True

    # ------------------------------------------------------------ state
    @property
    def step_number(self):
        """LMGC90's step counter (int)."""
        return int(self.chipy.TimeEvolution_GetStep())

    @property
    def time(self):
        """LMGC90's time, s (float)."""
        return float(self.chipy.TimeEvolution_GetTime())

    def vectors(self, name, bodies):
        """One of RBDY3's vectors of some bodies.

        Parameters
        ----------
        name : str
            RBDY3's name of the vector: 'Coor_' (m), 'V____' (m/s, rad/s),
            'Reac_' (N, N m: the contact reaction force and moment), 'Xbeg_', 'Vbeg_' ...
        bodies : iterable of int
            0-based body rows.

        Returns
        -------
        ndarray, shape (len(bodies), 6)
        """
        return np.array([self.chipy.RBDY3_GetBodyVector(name, int(i) + 1) for i in bodies], float)

    def frames(self, bodies, name="IF___"):
        """The bodies' inertia frames.

        Parameters
        ----------
        bodies : iterable of int
            0-based body rows.
        name : str
            'IF___' (now), 'IFbeg' (the step's start), 'IFref'.

        Returns
        -------
        ndarray, shape (len(bodies), 3, 3)
            Columns the body axes in the global frame.
        """
        return np.array([self.chipy.RBDY3_GetBodyMatrix(name, int(i) + 1) for i in bodies], float)

    def interactions(self, keys=False):
        """This step's interactions (contact points).

        Parameters
        ----------
        keys : bool
            Also return each point's identity across steps
            (:mod:`lmgc90.cdaverage`).

        Returns
        -------
        candidate, antagonist : ndarray, shape (P,)
            int, 0-based body rows.
        coor : ndarray, shape (P, 3)
            m, the points.
        frames : ndarray, shape (P, 3, 3)
            Columns t, n, s (n from the antagonist to the candidate).
        reactions : ndarray, shape (P, 3)
            N, (r_t, r_n, r_s) on the candidate (LMGC90's impulses / dt).
        gaps : ndarray, shape (P,)
            m, negative for an interpenetration.
        law : ndarray, shape (P,)
            int, the contact law's number.
        keys : ndarray, shape (P, 7)
            int, only with ``keys=True``: interaction type, candidate and
            antagonist bodies, contactors and sub-contactors.
        """
        inters = self.chipy.getInteractions(this=True, human=False)
        out = (np.asarray(inters["icdbdy"], np.int64) - 1, np.asarray(inters["ianbdy"], np.int64) - 1,
                np.asarray(inters["coor"], float).reshape(-1, 3), np.asarray(inters["uc"], float).reshape(-1, 3, 3),
                np.asarray(inters["rl"], float).reshape(-1, 3), np.asarray(inters["gapTT"], float).reshape(-1),
                np.asarray(inters["behav"], np.int64).reshape(-1))
        if keys:
            out += (np.stack([np.asarray(inters[n], np.int64).reshape(-1) for n in
                              ("inter", "icdbdy", "ianbdy", "icdtac", "iantac", "icdsci", "iansci")],
                             axis=1).reshape(-1, 7),)
        return out

    def n_interactions(self):
        """The number of this step's interactions (contact points within the alert distance).

        Returns
        -------
        int
            PRPRx, PRPLx, SPSPx and SPPLx together.
        """
        c = self.chipy
        return int(sum(c.inter_handler_3D_tgetNb(k) for k in (c.PRPRx_ID, c.PRPLx_ID, c.SPSPx_ID, c.SPPLx_ID)))

    # ------------------------------------------------------------ driving
    def free_dof(self, body, dof):
        """Let the 0-based ``body``'s velocity DOF ``dof`` (1..6) move freely.

        Returns
        -------
        None
        """
        self.chipy.RBDY3_SetInvisibleVlocyDrivenDof(int(body) + 1, int(dof))
        self.driven.pop((int(body), int(dof)), None)

    def drive_dof(self, body, dof, velocity):
        """Drive DOF ``dof`` (1..6) of the 0-based ``body`` at ``velocity``
        (m/s) from the next step on (LMGC90 evaluates a driven DOF from its
        DRV_DOF.DAT definition at each step's start, so :meth:`step` sets
        the value again every step, after ``IncrementStep``).

        Returns
        -------
        None
        """
        self.chipy.RBDY3_SetVisibleVlocyDrivenDof(int(body) + 1, int(dof))
        self.driven[(int(body), int(dof))] = float(velocity)

    def step(self, forces, nlgs):
        """One CD step.

        Parameters
        ----------
        forces : dict
            0-based body -> (6,) external force and moment (N, N m) this step.
        nlgs : dict
            ``norm`` ('QM/16', 'Quad ' or 'Maxm '), ``tol``, ``relax``,
            ``check_every`` (iterations between convergence checks) and
            ``max_checks``.

        Returns
        -------
        None
            Sets :attr:`iterations` and :attr:`converged` (False when the
            iterations ran out before the tolerance was met).
        """
        c = self.chipy
        c.IncrementStep()
        for (body, dof), v in self.driven.items():
            c.RBDY3_SetVlocyDrivenDof(body + 1, dof, v)
        c.ComputeFext()
        for body, f in forces.items():
            c.RBDY3_PutBodyVector("Fext_", int(body) + 1, np.asarray(f, float))
        c.ComputeBulk()
        c.ComputeFreeVelocity()
        c.SelectProxTactors()
        c.RecupRloc()
        c.nlgs_3D_SetCheckType(nlgs["norm"], float(nlgs["tol"]), float(nlgs["relax"]))
        c.nlgs_3D_ExPrep("Stored_Delassus_Loops")
        it, conv = 0, 0
        for _ in range(int(nlgs["max_checks"])):
            c.nlgs_3D_ExIter(int(nlgs["check_every"]))
            it += int(nlgs["check_every"])
            conv = c.nlgs_3D_AfterIterCheck()
            if conv == 0 or conv == -1:
                break
        c.nlgs_3D_ExPost()
        # ExPost sweeps the contacts once more after assembling the bodies'
        # reactions (as ExSolver does); assembling them again from the final
        # local reactions makes the forces stored, dumped and applied the same
        c.nlgs_3D_ComputeRnod()
        c.StockRloc()
        c.ComputeDof()
        c.UpdateStep()
        self.iterations = it
        self.converged = conv == 0

    # ------------------------------------------------------------ checkpoints
    def save(self, folder):
        """Write the state after the last step to ``folder`` (made; must not
        exist): LMGC90's ``DOF.LAST`` and ``Vloc_Rloc.LAST`` and
        ``bodies.npz`` (Xbeg, Vbeg (B, 6), IFbeg (B, 3, 3), step, time).

        Returns
        -------
        None
        """
        c = self.chipy
        os.makedirs(folder)
        c.WriteLastDof()
        c.WriteLastVlocRloc()
        for name in ("DOF.LAST", "Vloc_Rloc.LAST"):
            shutil.copy(os.path.join(self.folder, "OUTBOX", name), os.path.join(folder, name))
        every = range(self.n_bodies)
        np.savez(os.path.join(folder, "bodies.npz"), Xbeg=self.vectors("Xbeg_", every),
                 Vbeg=self.vectors("Vbeg_", every), IFbeg=self.frames(every, "IFbeg"),
                 step=self.step_number, time=self.time)
