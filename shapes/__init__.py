"""shapes: a library of irregular, ballast-like convex polyhedra.

Kept free of heavy imports: ``shapes.library`` (numpy + h5py only) is read
by the YADE scene scripts on Debian's system Python.
"""
