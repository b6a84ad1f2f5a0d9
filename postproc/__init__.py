"""postproc: stress, fabric and force anisotropies of granular contact dumps.

Kept free of heavy imports so that ``postproc.schema`` (numpy + h5py only)
can be imported by YADE's system Python.
"""
__version__ = "0.1.0"
