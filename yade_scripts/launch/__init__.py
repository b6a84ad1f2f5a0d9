"""The launchers: a pool of runs on this machine
(:mod:`~yade_scripts.launch.pool`), every line of a run folder's table
(:mod:`~yade_scripts.launch.batch`), a SLURM job array and one of its tasks
(:mod:`~yade_scripts.launch.slurm`, :mod:`~yade_scripts.launch.task`) and
the memory a set of runs needs (:mod:`~yade_scripts.launch.resources`).

Above the scene (they read its parameters and start it in YADE), below the
campaign (tests/test_yade_layers.py).
"""
