"""yade_scripts: the triaxial scene of S1 (polyhedra) and S2 (spheres) for
YADE, and the runs of a study, in rooms that import only downward
(tests/test_yade_layers.py): :mod:`yade_scripts.runs` (one run's lock,
state, checkpoints and attempt), :mod:`yade_scripts.scene` (the scene
``triaxial.py`` and its parts), :mod:`yade_scripts.launch` (the pool, the
table's batch, SLURM arrays) and :mod:`yade_scripts.campaign` (presets, run
folders, the study, its archive, the sweeps), beside
:mod:`yade_scripts.yadeplugin` (the compiled kernel's YADE plugin). What
the scene imports runs on the Python YADE runs on (Debian's): the standard
library, numpy and h5py.
"""
