"""The intensity of a record by name, as ``freestand fragility --im`` reads it.

:func:`intensity_measure` gives the one-component measures of planar models
(``pga``, ``pgv``, ``sa:F[,DAMPING]``, ``pga-alpha[:BLOCK]``) and the
measures of two horizontal components that do not depend on the record's
orientation (Boore 2010): the geometric mean, RotD50 and RotD100 of PGA, PGV
and Sa(f, zeta). It is a shell over
:func:`freestand.core.sweeps.fragility.intensity.intensity`, the function a
fragility campaign scales its records with.
"""

from __future__ import annotations

from freestand.core.contact.screening import GRAVITY
from freestand.core.model import Stack
from freestand.core.motion.ground_motion import GroundMotion
from freestand.core.sweeps.fragility.intensity import IntensityMeasure, intensity
from freestand.errors import FreestandError


def intensity_measure(
    record: GroundMotion,
    im: str | IntensityMeasure = "pga",
    *,
    stack: Stack | None = None,
    gravity: float = GRAVITY,
) -> float:
    """The intensity measure (IM) of a record, in the IM's SI unit.

    Parameters
    ----------
    record : GroundMotion
        The record (:func:`freestand.load_record`, :func:`freestand.load_station`,
        or a suite's ``motions``); two-component IMs need its y component
        (``horizontal_y``).
    im : str or IntensityMeasure, optional
        As ``freestand fragility --im`` takes it (default ``"pga"``):

        - one component (x): ``pga`` [m/s^2], ``pgv`` [m/s],
          ``sa:F[,DAMPING]`` [m/s^2] (e.g. ``sa:2.5Hz,5%``; damping 5 %
          unless given), ``pga-alpha[:BLOCK]`` [-] (needs ``stack``);
        - two horizontal components (x and y): ``pga-gm``, ``pgv-gm``,
          ``sa-gm:F[,DAMPING]``, the geometric mean sqrt(IM_x IM_y);
          ``pga-rotd50``, ``pga-rotd100``, ``pgv-rotd50``, ``pgv-rotd100``,
          ``sa-rotd50:F[,DAMPING]``, ``sa-rotd100:F[,DAMPING]``, the median
          and the largest over the angles theta = 0, 1, ..., 179 deg of the
          peak of the rotated series a_x cos theta + a_y sin theta.
    stack : Stack, optional
        The configuration ``pga-alpha`` is of.
    gravity : float, optional
        g [m/s^2] (``pga-alpha``).

    Returns
    -------
    float
        The IM [m/s^2, m/s or -].

    Raises
    ------
    FreestandError
        An unknown IM name, or a two-component IM of a record without a y
        component (naming ``im`` and the record).

    Notes
    -----
    RotDnn (Boore 2010) is the nn-th percentile over the angles of
    ``max_t |a_theta(t)|`` (PGA), ``max_t |v_theta(t)|`` (PGV) or
    ``omega^2 max_t |u_theta(t)|`` (Sa). The oscillator is linear, so its
    response to a_theta is u_x cos theta + u_y sin theta: the two components'
    responses are computed once by the one response-spectrum recursion
    (:mod:`freestand.core.motion.response_spectrum`) and combined at every
    angle (:mod:`freestand.core.motion.rotd`).

    References
    ----------
    Boore, D. M. (2010). Orientation-independent, nongeometric-mean measures
    of seismic intensity from two horizontal components of motion. Bulletin
    of the Seismological Society of America 100(4), 1830-1835.

    Examples
    --------
    >>> import numpy as np
    >>> import freestand as fs
    >>> t = np.arange(0.0, 4.0, 0.01)
    >>> x = 3.0 * np.sin(2 * np.pi * t)           # along x, 3 m/s^2
    >>> pair = fs.GroundMotion(0.01, x, horizontal_y=4.0 * np.sin(2 * np.pi * t))
    >>> round(fs.intensity_measure(pair, "pga-rotd100"), 3)  # 5 m/s^2 along one line
    5.0
    >>> round(fs.intensity_measure(pair, "pga-gm"), 6)       # sqrt(3 x 4)
    3.464102
    >>> sa = fs.intensity_measure(pair, "sa-rotd50:2.5Hz,5%")
    """
    if isinstance(im, IntensityMeasure):
        measure = im
    else:
        from freestand.io.fragility_options import parse_intensity

        measure = parse_intensity(str(im), stack, "im")
    try:
        return intensity(record, measure, stack, gravity)
    except ValueError as error:
        raise FreestandError(f"{error}", source="im") from None
