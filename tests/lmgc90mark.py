"""The mark of the tests that need LMGC90's build (``make lmgc90``)."""
import pytest

from lmgc90 import build as lb

try:
    lb.pylmgc90_path()
    BUILT = True
except lb.LMGC90BuildError:
    BUILT = False
needs_lmgc90 = pytest.mark.skipif(not BUILT, reason="LMGC90 is not built (make lmgc90)")
