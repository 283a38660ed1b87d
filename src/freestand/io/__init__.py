"""Input and output at the boundary: model files, spectra and records.

Everything read here is validated and converted to SI before it reaches the
numerical core; problems raise :class:`freestand.errors.FreestandError`.
"""
