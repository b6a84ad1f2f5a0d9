"""One run's life, as its process and its files hold it: its lock
(:mod:`~yade_scripts.runs.runlock`), its state on disk and exit codes
(:mod:`~yade_scripts.runs.runstate`), its checkpoints
(:mod:`~yade_scripts.runs.checkpoint`), one attempt at it as the scene sees
it (:mod:`~yade_scripts.runs.attempt`), the host it ran on
(:mod:`~yade_scripts.runs.host`) and YADE started without its remote
servers (:mod:`~yade_scripts.runs.noremote`).

The bottom layer of ``yade_scripts`` (tests/test_yade_layers.py): standard
library and numpy only, nothing of the other rooms.
"""
