"""LMGC90 (Contact Dynamics) beside YADE: the vendored source (``vendor/``) and its build (``build``)."""
