"""Public vertical frequency of the bridge and jump check (paper section 6): :func:`frequency`."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from freestand.api.base import Result, Subject, frame, resolve_spectrum
from freestand.core.contact.screening import GRAVITY
from freestand.core.motion.spectra import Spectrum
from freestand.core.structure.beam import (
    FrequencySweep,
    JumpCheck,
    SimplySupportedBeam,
    frequency_sweep,
    jump_check,
)
from freestand.errors import FreestandError

#: Columns of :meth:`FrequencyResult.to_frame`.
FREQUENCY_COLUMNS = (
    "position [m]",
    "dunkerley [Hz]",
    "exact [Hz]",
    "parked",
    "spectral_acceleration [m/s^2]",
    "ratio_to_g [-]",
    "verdict",
)


@dataclass(frozen=True)
class FrequencyResult(Result):
    """Lowest vertical frequency of the bridge against the cart's position, and the jump check.

    Attributes
    ----------
    model : str
        Model name.
    parking : tuple of float
        The cart's parking range [m] from the left support.
    sweep : FrequencySweep
        Dunkerley's and the exact frequency [Hz] at the positions asked.
    full_sweep : FrequencySweep
        The same over the whole span (the figure's curves).
    check : JumpCheck or None
        The jump check at the positions asked (None without a vertical spectrum).
    full_check : JumpCheck or None
        The jump check over the whole span.
    spectrum : Spectrum or None
        The vertical spectrum of the check.
    gravity : float
        g [m/s^2].
    note : str or None
        Positions asked outside the parking range, in words.

    Examples
    --------
    >>> import freestand as fs
    >>> result = fs.frequency(fs.load_model("examples/crane.toml"), positions=[0.0, 4.9])
    >>> result.to_frame()[["position [m]", "verdict"]].values.tolist()
    [[0.0, 'not parked'], [4.9, 'jump possible']]
    >>> fig = result.plot()  # paper Fig. 9
    """

    model: str
    parking: tuple[float, float]
    sweep: FrequencySweep
    full_sweep: FrequencySweep
    check: JumpCheck | None
    full_check: JumpCheck | None
    spectrum: Spectrum | None
    gravity: float
    note: str | None

    def parked(self) -> np.ndarray:
        """Whether each position of :attr:`sweep` lies in the parking range."""
        tolerance = 1e-9 * self.sweep.beam.span
        low, high = self.parking
        return (self.sweep.position >= low - tolerance) & (self.sweep.position <= high + tolerance)

    def to_dict(self) -> dict:
        """The ``freestand frequency --json`` document.

        Keys: ``model``, ``parking`` [m], ``positions`` (per position
        ``position`` [m], ``dunkerley`` and ``exact`` [Hz], and with a spectrum
        ``spectral_acceleration`` [m/s^2], ``ratio_to_g`` [-], ``verdict``),
        ``note`` (positions outside the parking range), ``jump_check``
        (``spectrum``, ``basis``, ``status``, ``positions_at_risk`` [m],
        ``risk_intervals`` [m], ``minimum_margin`` [m/s^2],
        ``minimum_margin_position`` [m], ``notes``) and ``figures``.

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        sweep, check = self.sweep, self.check
        rows = []
        for k, position in enumerate(sweep.position):
            row = {
                "position": float(position),
                "dunkerley": float(sweep.dunkerley[k]),
                "exact": float(sweep.exact[k]),
            }
            if check is not None:
                row.update(
                    spectral_acceleration=float(check.spectral_acceleration[k]),
                    ratio_to_g=float(check.ratio[k]),
                    verdict=str(check.verdict[k]),
                )
            rows.append(row)
        document = {"model": self.model, "parking": list(self.parking), "positions": rows}
        if self.note:
            document["note"] = self.note
        if check is not None:
            document["jump_check"] = {
                "spectrum": check.spectrum_label,
                "basis": check.basis,
                "status": check.status,
                "positions_at_risk": [float(p) for p in check.positions_at_risk],
                "risk_intervals": [list(run) for run in check.risk_intervals],
                "minimum_margin": check.minimum_margin,
                "minimum_margin_position": check.minimum_margin_position,
                "notes": list(check.notes),
            }
        document["figures"] = []
        return document

    def to_frame(self):
        """One row per cart position.

        Columns: ``position [m]`` (from the left support), ``dunkerley [Hz]``
        (paper eqs. 1-4, a lower bound), ``exact [Hz]`` (Euler-Bernoulli beam
        with the point mass), ``parked`` (inside the parking range),
        ``spectral_acceleration [m/s^2]`` (vertical, at that frequency),
        ``ratio_to_g [-]`` and ``verdict`` (the last three NaN / empty
        without a vertical spectrum). ``attrs``: ``model``, ``parking [m]``,
        ``spectrum``, ``status`` (of the jump check).

        Returns
        -------
        pandas.DataFrame
            The table described above: units in the column names, metadata in
            ``attrs``.
        """
        sweep, check = self.sweep, self.check
        count = sweep.position.size
        columns = dict(
            zip(
                FREQUENCY_COLUMNS,
                (
                    sweep.position,
                    sweep.dunkerley,
                    sweep.exact,
                    self.parked(),
                    check.spectral_acceleration if check is not None else np.full(count, np.nan),
                    check.ratio if check is not None else np.full(count, np.nan),
                    check.verdict if check is not None else np.full(count, ""),
                ),
                strict=True,
            )
        )
        rows = [{key: values[k] for key, values in columns.items()} for k in range(count)]
        return frame(
            rows,
            FREQUENCY_COLUMNS,
            {
                "model": self.model,
                "parking [m]": self.parking,
                "spectrum": check.spectrum_label if check is not None else None,
                "status": check.status if check is not None else None,
            },
        )

    def plot(self, ax=None):
        """The paper's Fig. 9 analogue ``freestand frequency --plot`` writes.

        The lowest vertical frequency against the cart's position over the
        whole span (exact and Dunkerley), the parking range shaded, the band of
        frequencies where the vertical spectrum reaches g and the positions
        where the cart may jump marked.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Draw into these axes (default: a new figure).

        Returns
        -------
        matplotlib.figure.Figure
        """
        from freestand.plot.frequency import plot_frequency_sweep

        return plot_frequency_sweep(
            self.full_sweep, parking=self.parking, jump=self.full_check,
            vertical_spectrum=self.spectrum, ax=ax,
        )  # fmt: skip


def frequency(
    model,
    positions: Sequence[float] | None = None,
    *,
    spectrum: Spectrum | str | None = None,
    parking: tuple[float, float] | None = None,
    gravity: float | None = None,
) -> FrequencyResult:
    """Lowest vertical frequency of the bridge against the cart's position; may the cart jump?

    The bridge is a simply supported Euler-Bernoulli beam carrying the cart as
    a point mass (paper section 6). The lowest frequency is given by
    Dunkerley's method as the paper builds it, 1/f^2 = 1/f_beam^2 +
    1/f_cart^2 (paper eqs. 1-4, a lower bound), and exactly (the beam's
    modal receptance at the cart, summed to convergence). The vertical
    spectral acceleration at that frequency is compared with g: where it
    reaches g the cart may lose contact with its rails (paper section 6.1).

    Parameters
    ----------
    model : ModelFile or SimplySupportedBeam
        A loaded model file with a ``[beam]`` table (its parking range,
        vertical spectrum and g), or a beam with ``parking`` given here.
    positions : sequence of float, optional
        Cart positions [m] from the left support (default: 99 over the span,
        with the parking range's ends and middle).
    spectrum : Spectrum or str, optional
        The vertical spectrum (default: the model's), or a ``--spectrum``
        text such as ``"rg1.60:pga=0.3g,direction=vertical"``.
    parking : tuple of float, optional
        The cart's parking range [m] (default: the model's; the whole span
        for a bare beam).
    gravity : float, optional
        g [m/s^2] (default: the model's, 9.81 otherwise).

    Returns
    -------
    FrequencyResult
        ``to_dict()`` (the ``freestand frequency --json`` document),
        ``to_frame()`` (one row per position) and ``plot()`` (Fig. 9).

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model("examples/crane.toml")
    >>> result = fs.frequency(model, positions=[0.0, 4.9])
    >>> result.to_frame()["dunkerley [Hz]"].round(1).tolist()
    [21.5, 10.6]
    """
    what, beam, parking = _beam(model, parking, gravity)
    values = None if positions is None else [float(p) for p in positions]
    if values is not None:
        for value in values:
            if not 0 <= value <= beam.span:
                raise FreestandError(
                    f"position {value:g} m is outside the span 0 .. {beam.span:g} m; give "
                    "positions measured from the left support",
                    source="--positions",
                )
    full_sweep = frequency_sweep(beam, parking=parking)
    sweep = full_sweep if values is None else frequency_sweep(beam, np.array(values))
    vertical = resolve_spectrum(spectrum, what, "vertical")
    tolerance = 1e-9 * beam.span
    parked = [parking[0] - tolerance <= p <= parking[1] + tolerance for p in sweep.position]
    note = None
    if not all(parked):
        outside = ", ".join(
            f"{p:g}" for p, inside in zip(sweep.position, parked, strict=True) if not inside
        )
        note = (
            f"position(s) {outside} m lie outside the parking range {parking[0]:g}-"
            f"{parking[1]:g} m: the cart does not park there"
            + ("; their jump verdict is given as if it did" if vertical else "")
        )
    check = full_check = None
    if vertical:
        # the jump check counts parked positions only; for positions asked outside the
        # parking range alone, it is made as if the cart parked there (and says so)
        check = jump_check(sweep, vertical, what.gravity, parking=parking if any(parked) else None)
        full_check = (
            check
            if sweep is full_sweep
            else jump_check(full_sweep, vertical, what.gravity, parking=parking)
        )
    return FrequencyResult(
        what.name, parking, sweep, full_sweep, check, full_check, vertical, what.gravity, note
    )


def _beam(model, parking, gravity) -> tuple[Subject, SimplySupportedBeam, tuple[float, float]]:
    """The subject, the beam and the parking range of a model file or a bare beam."""
    from freestand.io.model_file import ModelFile

    if isinstance(model, SimplySupportedBeam):
        g = GRAVITY if gravity is None else float(gravity)
        what = Subject("beam", g, (), ())
        return what, model, tuple(parking) if parking is not None else (0.0, model.span)
    if not isinstance(model, ModelFile):
        raise TypeError(
            "expected a model file with a [beam] table (fs.load_model) or a "
            f"SimplySupportedBeam, not {type(model).__name__}"
        )
    if model.beam is None:
        raise FreestandError(
            "has no [beam] section; add span, youngs_modulus, second_moment, mass, load_mass "
            "and parking (see the README)",
            source=model.source,
        )
    what = Subject(
        model.name,
        model.gravity if gravity is None else float(gravity),
        tuple(model.configurations),
        tuple(model.excitations),
        model,
    )
    return what, model.beam.beam, tuple(parking) if parking is not None else model.beam.parking
