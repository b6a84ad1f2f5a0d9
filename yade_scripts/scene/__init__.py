"""The triaxial scene and its parts: ``triaxial.py`` (the script YADE runs,
copied into every run folder), its parameters
(:mod:`~yade_scripts.scene.parameters`), its grains and bodies
(:mod:`~yade_scripts.scene.grains`, :mod:`~yade_scripts.scene.sample`), the
controller its ``PyRunner`` calls every step
(:mod:`~yade_scripts.scene.controller`), the wall servo and the loading program
(:mod:`~yade_scripts.scene.servo`, :mod:`~yade_scripts.scene.loading`), the
time step (:mod:`~yade_scripts.scene.timestep`), the contact laws
(:mod:`~yade_scripts.scene.tangential`,
:mod:`~yade_scripts.scene.kernel_contacts`) and the dump's gathering
(:mod:`~yade_scripts.scene.yadedump`).

Above :mod:`yade_scripts.runs` and the plugin's loader
(:mod:`yade_scripts.yadeplugin`), below the launchers
(tests/test_yade_layers.py).
"""
