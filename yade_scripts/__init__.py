"""yade_scripts: generated YADE triaxial scenes for S1 (polyhedra) and S2
(spheres). The helper modules here import only the standard library and
numpy (plus h5py for I/O), because YADE runs them on Debian's system Python.
"""
