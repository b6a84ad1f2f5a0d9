"""The studies: presets and run folders (:mod:`~yade_scripts.campaign.presets`,
:mod:`~yade_scripts.campaign.generate`), the main study
(:mod:`~yade_scripts.campaign.study`, ``make study``), its archive
(:mod:`~yade_scripts.campaign.archive`), and the sweeps around the default
(:mod:`~yade_scripts.campaign.sweeps`, ``make front``; the time step's and
the face-pair tilt's, :mod:`~yade_scripts.campaign.timestep_sweep`,
:mod:`~yade_scripts.campaign.facepair_sweep`, and the time step's draws,
:mod:`~yade_scripts.campaign.timestep_draws`).

The top layer of ``yade_scripts`` (tests/test_yade_layers.py).
"""
