"""freestand: seismic screening of free-standing rigid-block stacks.

The package is layered:

- :mod:`freestand.core` -- the pure numerical core (SI floats, numpy arrays,
  frozen dataclasses; no printing, no files, no plotting);
- :mod:`freestand.io` -- model files, spectra and records, validated at the
  boundary;
- :mod:`freestand.plot`, :mod:`freestand.report` -- figures and reports that
  only consume results;
- :mod:`freestand.cli` -- the thin ``freestand`` command.
"""

from freestand.errors import FreestandError

__version__ = "0.1.0"

__all__ = ["FreestandError", "__version__"]
