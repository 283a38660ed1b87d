"""Ground-motion records: support accelerations sampled at a uniform time step.

A :class:`GroundMotion` holds the horizontal support acceleration along x and,
optionally, a second horizontal component along y and the vertical one,
sampled at t_i = i dt. Between samples the
acceleration is taken to vary linearly (the piecewise-linear representation
on which the exact response-spectrum recursion and the sliding solver rest).
Before t = 0 and after the last sample the support is at rest: the record is
followed by zero samples, so its last value ramps to zero over one step.

Sign conventions (the same as :class:`freestand.core.model.Excitation`):

- ``horizontal``: support acceleration along +x [m/s^2];
- ``horizontal_y``: support acceleration along +y [m/s^2], or None for a
  record with one horizontal component (every planar analysis uses x only).
  x, y and z (up) form a right-handed frame: seen from above, y is x turned
  90 degrees counter-clockwise;
- ``vertical``: *downward* support acceleration [m/s^2], so that a block of
  mass m on the support has the apparent weight m (g - a_v) (paper section 2).
  Instruments record vertical motion positive upward; the record readers in
  :mod:`freestand.io.records` change the sign when they load such a component.

The module also builds the analytic pulses (rectangular, half-sine, one-sine,
one-cosine) as sampled records, and a deterministic synthetic record for tests
and demonstrations.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

#: Component names of a record, in the order x, y, vertical (the attribute names).
COMPONENTS = ("horizontal", "horizontal_y", "vertical")


def _frozen_array(values, name: str) -> np.ndarray:
    array = np.array(values, dtype=float, copy=True)
    if array.ndim != 1:
        raise ValueError(f"{name} must be a 1-D array")
    array.flags.writeable = False
    return array


@dataclass(frozen=True)
class GroundMotion:
    """A support-acceleration record at a uniform time step.

    Parameters
    ----------
    dt : float
        Time step [s], positive.
    horizontal : numpy.ndarray
        Horizontal support acceleration a_x(t_i) [m/s^2] along +x at
        t_i = i dt, at least two samples, all finite.
    vertical : numpy.ndarray or None, optional
        Downward support acceleration a_v(t_i) [m/s^2] (positive down: the
        weight becomes m (g - a_v)), same length as ``horizontal``; ``None``
        when the record has no vertical component.
    name : str, optional
        Record name used in labels.
    metadata : dict, optional
        Free-form provenance (source file, header lines, scale factor...).
    horizontal_y : numpy.ndarray or None, optional
        Second horizontal support acceleration a_y(t_i) [m/s^2] along +y
        (keyword only), same length as ``horizontal``; ``None`` (default) for
        a record with one horizontal component. Seen from above, +y is +x
        turned 90 degrees counter-clockwise (x, y and z up right-handed).
        Planar analyses use ``horizontal`` only.

    Notes
    -----
    Everything that makes a new record from this one (:meth:`scaled`,
    :meth:`with_trailing_zeros`, :meth:`rotated`,
    :func:`combine_components`, the floor motion) treats the three
    components alike; :meth:`rotated` turns the horizontal pair.

    Examples
    --------
    >>> import numpy as np
    >>> import freestand as fs
    >>> motion = fs.GroundMotion(0.01, np.array([0.0, 1.0, -2.0, 0.5]), name="four samples")
    >>> motion.peak_horizontal, motion.duration, motion.components  # [m/s^2], [s]
    (2.0, 0.03, ('horizontal',))
    >>> motion.scaled_to_peak(4.0).horizontal.tolist()
    [0.0, 2.0, -4.0, 1.0]
    """

    dt: float
    horizontal: np.ndarray
    vertical: np.ndarray | None = None
    name: str = ""
    metadata: dict = field(default_factory=dict, compare=False)
    horizontal_y: np.ndarray | None = field(default=None, kw_only=True)

    def __post_init__(self) -> None:
        dt = float(self.dt)
        if not (dt > 0 and math.isfinite(dt)):
            raise ValueError(f"dt must be positive and finite, got {self.dt!r}")
        horizontal = _frozen_array(self.horizontal, "horizontal")
        if horizontal.size < 2:
            raise ValueError("a record needs at least two samples")
        if not np.all(np.isfinite(horizontal)):
            raise ValueError("the horizontal acceleration contains non-finite values")
        object.__setattr__(self, "dt", dt)
        object.__setattr__(self, "horizontal", horizontal)
        if self.vertical is not None:
            vertical = _frozen_array(self.vertical, "vertical")
            if vertical.shape != horizontal.shape:
                raise ValueError(
                    f"vertical has {vertical.size} samples, horizontal {horizontal.size}; "
                    "they must have the same length (see combine_components)"
                )
            if not np.all(np.isfinite(vertical)):
                raise ValueError("the vertical acceleration contains non-finite values")
            object.__setattr__(self, "vertical", vertical)
        if self.horizontal_y is not None:
            horizontal_y = _frozen_array(self.horizontal_y, "horizontal_y")
            if horizontal_y.shape != horizontal.shape:
                raise ValueError(
                    f"horizontal_y has {horizontal_y.size} samples, horizontal "
                    f"{horizontal.size}; they must have the same length (see combine_components)"
                )
            if not np.all(np.isfinite(horizontal_y)):
                raise ValueError("the horizontal_y acceleration contains non-finite values")
            object.__setattr__(self, "horizontal_y", horizontal_y)

    # ------------------------------------------------------------------ basics
    @property
    def n_samples(self) -> int:
        """Number of samples [-]."""
        return int(self.horizontal.size)

    @property
    def time(self) -> np.ndarray:
        """Sample times t_i = i dt [s]."""
        return np.arange(self.n_samples) * self.dt

    @property
    def duration(self) -> float:
        """Time of the last sample, (n - 1) dt [s]."""
        return (self.n_samples - 1) * self.dt

    @property
    def components(self) -> tuple[str, ...]:
        """Names of the components the record has, among :data:`COMPONENTS`."""
        return tuple(name for name in COMPONENTS if getattr(self, name) is not None)

    def component(self, name: str) -> np.ndarray:
        """The ``"horizontal"``, ``"horizontal_y"`` or ``"vertical"`` acceleration [m/s^2]."""
        if name not in COMPONENTS:
            raise ValueError(f"component must be one of {', '.join(COMPONENTS)}, got {name!r}")
        values = getattr(self, name)
        if values is None:
            raise ValueError(f"record {self.name!r} has no {name} component")
        return values

    # ------------------------------------------------------------- peak values
    @property
    def peak_horizontal(self) -> float:
        """Peak horizontal ground acceleration max abs(a_h) [m/s^2]."""
        return float(np.max(np.abs(self.horizontal)))

    @property
    def peak_horizontal_y(self) -> float | None:
        """Peak acceleration along y, max abs(a_y) [m/s^2], None without a y component."""
        return None if self.horizontal_y is None else float(np.max(np.abs(self.horizontal_y)))

    @property
    def peak_vertical(self) -> float | None:
        """Peak vertical ground acceleration max abs(a_v) [m/s^2], None without one."""
        return None if self.vertical is None else float(np.max(np.abs(self.vertical)))

    @property
    def peak_downward(self) -> float | None:
        """Largest downward support acceleration max(a_v, 0) [m/s^2], None without one."""
        return None if self.vertical is None else float(max(np.max(self.vertical), 0.0))

    def velocity(self, component: str = "horizontal") -> np.ndarray:
        """Support velocity at the samples [m/s], from rest, exact for linear segments.

        v_{i+1} = v_i + (a_i + a_{i+1}) dt / 2. No baseline correction.
        """
        a = self.component(component)
        v = np.zeros_like(a)
        v[1:] = np.cumsum(0.5 * (a[:-1] + a[1:]) * self.dt)
        return v

    def displacement(self, component: str = "horizontal") -> np.ndarray:
        """Support displacement at the samples [m], from rest, exact for linear segments.

        d_{i+1} = d_i + v_i dt + (2 a_i + a_{i+1}) dt^2 / 6. No baseline correction.
        """
        a = self.component(component)
        v = self.velocity(component)
        d = np.zeros_like(a)
        d[1:] = np.cumsum(v[:-1] * self.dt + (2.0 * a[:-1] + a[1:]) * self.dt**2 / 6.0)
        return d

    @property
    def peak_horizontal_velocity(self) -> float:
        """Peak horizontal ground velocity [m/s] (no baseline correction)."""
        return float(np.max(np.abs(self.velocity("horizontal"))))

    @property
    def peak_horizontal_displacement(self) -> float:
        """Peak horizontal ground displacement [m] (no baseline correction)."""
        return float(np.max(np.abs(self.displacement("horizontal"))))

    # ----------------------------------------------------------- interpolation
    def _at(self, values: np.ndarray, t) -> np.ndarray | float:
        times = np.arange(values.size + 1) * self.dt
        padded = np.append(values, 0.0)
        t_arr = np.asarray(t, dtype=float)
        out = np.interp(t_arr, times, padded, left=0.0, right=0.0)
        return float(out) if np.ndim(t) == 0 else out

    def horizontal_at(self, t) -> np.ndarray | float:
        """Horizontal acceleration [m/s^2] at times ``t`` [s] (linear interpolation).

        Zero before t = 0; after the last sample it ramps to zero over one step.
        """
        return self._at(self.horizontal, t)

    def horizontal_y_at(self, t) -> np.ndarray | float:
        """Acceleration along y [m/s^2] at times ``t`` [s] (linear interpolation).

        Zero without a y component, before t = 0 and (after a one-step ramp)
        after the record.
        """
        return self._at_or_zero(self.horizontal_y, t)

    def vertical_at(self, t) -> np.ndarray | float:
        """Downward acceleration [m/s^2] at times ``t`` [s] (linear interpolation).

        Zero without a vertical component, before t = 0 and (after a one-step
        ramp) after the record.
        """
        return self._at_or_zero(self.vertical, t)

    def _at_or_zero(self, values: np.ndarray | None, t) -> np.ndarray | float:
        if values is None:
            t_arr = np.zeros_like(np.asarray(t, dtype=float))
            return float(t_arr) if np.ndim(t) == 0 else t_arr
        return self._at(values, t)

    # ------------------------------------------------------------ new records
    def _replace(self, **changes) -> GroundMotion:
        values = {
            "dt": self.dt,
            "horizontal": self.horizontal,
            "vertical": self.vertical,
            "horizontal_y": self.horizontal_y,
            "name": self.name,
            "metadata": dict(self.metadata),
        }
        values.update(changes)
        return GroundMotion(**values)

    def _each_component(self, function) -> dict:
        """``{name: function(values)}`` for every component (None stays None)."""
        return {
            name: None if getattr(self, name) is None else function(getattr(self, name))
            for name in COMPONENTS
        }

    def scaled(self, factor: float) -> GroundMotion:
        """Every component multiplied by ``factor`` [-]; metadata records the factor."""
        if not math.isfinite(factor):
            raise ValueError(f"scale factor must be finite, got {factor!r}")
        metadata = dict(self.metadata)
        metadata["scale_factor"] = metadata.get("scale_factor", 1.0) * factor
        return self._replace(**self._each_component(lambda a: a * factor), metadata=metadata)

    def scaled_to_peak(self, target: float, component: str = "horizontal") -> GroundMotion:
        """Scale every component so that the peak of ``component`` is ``target`` [m/s^2].

        Parameters
        ----------
        target : float
            Peak ground acceleration wanted [m/s^2], non-negative.
        component : str, optional
            ``"horizontal"`` (default), ``"horizontal_y"`` or ``"vertical"``: the
            component whose peak is matched; the others are scaled by the same
            factor.
        """
        if not (target >= 0 and math.isfinite(target)):
            raise ValueError(f"target peak must be non-negative and finite, got {target!r}")
        peak = float(np.max(np.abs(self.component(component))))
        if peak == 0.0:
            raise ValueError(f"record {self.name!r} is all zero in {component}; cannot scale it")
        return self.scaled(target / peak)

    def scaled_to_spectral(
        self,
        target: float,
        frequency: float,
        damping: float = 0.05,
        component: str = "horizontal",
    ) -> GroundMotion:
        """Scale every component so that the pseudo-acceleration at one frequency is ``target``.

        Parameters
        ----------
        target : float
            Spectral pseudo-acceleration wanted [m/s^2], non-negative.
        frequency : float
            Oscillator natural frequency [Hz].
        damping : float, optional
            Damping ratio [-] (default 0.05).
        component : str, optional
            Component whose spectrum is matched (default ``"horizontal"``).

        Notes
        -----
        The response of a linear oscillator is linear in the record, so one
        factor target / PSA(f) matches it exactly (PSA by
        :func:`freestand.core.motion.response_spectrum.spectral_response`).
        """
        from freestand.core.motion.response_spectrum import spectral_response

        if not (target >= 0 and math.isfinite(target)):
            raise ValueError(f"target spectral value must be non-negative, got {target!r}")
        psa = float(
            spectral_response(
                self, None, [frequency], damping, component=component
            ).pseudo_acceleration[0]
        )
        if psa == 0.0:
            raise ValueError(f"record {self.name!r} has zero response at {frequency} Hz")
        return self.scaled(target / psa)

    def with_vertical(self, vertical: np.ndarray | None) -> GroundMotion:
        """The same record with the downward acceleration ``vertical`` [m/s^2] (or none)."""
        return self._replace(vertical=vertical)

    def with_horizontal_y(self, horizontal_y: np.ndarray | None) -> GroundMotion:
        """The same record with the acceleration along y ``horizontal_y`` [m/s^2] (or none)."""
        return self._replace(horizontal_y=horizontal_y)

    def with_trailing_zeros(self, total_duration: float) -> GroundMotion:
        """The record followed by zero samples up to ``total_duration`` [s] (if longer)."""
        n_total = int(round(total_duration / self.dt)) + 1
        extra = max(0, n_total - self.n_samples)
        if extra == 0:
            return self
        return self._replace(**self._each_component(lambda a: np.concatenate([a, np.zeros(extra)])))

    def rotated(self, angle: float) -> GroundMotion:
        """The record in horizontal axes turned by ``angle`` [rad] about the vertical.

        Parameters
        ----------
        angle : float
            Angle theta [rad] from the record's x axis to the new x' axis,
            counter-clockwise seen from above (towards +y).

        Returns
        -------
        GroundMotion
            The same ground motion along the turned axes:

                a_x'(t) =  a_x(t) cos theta + a_y(t) sin theta,
                a_y'(t) = -a_x(t) sin theta + a_y(t) cos theta,

            the vertical unchanged. a_x' is the rotated time series of Boore
            (2010, BSSA 100(4), 1830-1835, eq. 1). A record with one horizontal
            component is taken as moving along x only (a_y = 0): its rotation
            has both components. ``metadata["rotation"]`` accumulates the
            angle [rad]; ``rotated(a).rotated(b)`` equals ``rotated(a + b)``.
        """
        if not math.isfinite(angle):
            raise ValueError(f"angle must be finite, got {angle!r}")
        cos, sin = math.cos(angle), math.sin(angle)
        x = self.horizontal
        y = np.zeros_like(x) if self.horizontal_y is None else self.horizontal_y
        metadata = dict(self.metadata)
        metadata["rotation"] = metadata.get("rotation", 0.0) + float(angle)
        return self._replace(
            horizontal=cos * x + sin * y, horizontal_y=-sin * x + cos * y, metadata=metadata
        )


def resample(acceleration: np.ndarray, dt: float, new_dt: float) -> np.ndarray:
    """Linear interpolation of a record onto the step ``new_dt`` [s], same end time.

    Exact for the piecewise-linear record when ``dt`` is a whole multiple of
    ``new_dt``. Samples run from 0 to the last multiple of ``new_dt`` not after
    the record's end.
    """
    acceleration = np.asarray(acceleration, dtype=float)
    end = (acceleration.size - 1) * dt
    n_new = int(math.floor(end / new_dt + 1e-9)) + 1
    return np.interp(np.arange(n_new) * new_dt, np.arange(acceleration.size) * dt, acceleration)


def combine_components(
    horizontal: np.ndarray,
    horizontal_dt: float,
    vertical: np.ndarray | None = None,
    vertical_dt: float | None = None,
    *,
    horizontal_y: np.ndarray | None = None,
    horizontal_y_dt: float | None = None,
    name: str = "",
    metadata: dict | None = None,
) -> GroundMotion:
    """One record from components sampled separately (x, and y and/or vertical).

    Parameters
    ----------
    horizontal : numpy.ndarray
        Acceleration along x [m/s^2] at steps of ``horizontal_dt`` [s].
    horizontal_dt : float
        Its time step [s].
    vertical : numpy.ndarray, optional
        Downward acceleration [m/s^2] at steps of ``vertical_dt`` [s].
    vertical_dt : float, optional
        Its time step [s] (required with ``vertical``).
    horizontal_y : numpy.ndarray, optional
        Acceleration along y [m/s^2] at steps of ``horizontal_y_dt`` [s].
    horizontal_y_dt : float, optional
        Its time step [s] (required with ``horizontal_y``).
    name : str, optional
        Name of the combined record.
    metadata : dict, optional
        Provenance; the rule applied is added under ``"combination"``.

    Returns
    -------
    GroundMotion
        Rule: the common step is the smallest; a component with a coarser
        step is linearly interpolated onto it (exact when its step is a whole
        multiple of the finer one); the shorter components are followed by
        zeros (support at rest) up to the length of the longest one.
    """
    given = [("horizontal", horizontal, horizontal_dt)]
    for label, values, step in (
        ("horizontal_y", horizontal_y, horizontal_y_dt),
        ("vertical", vertical, vertical_dt),
    ):
        if values is not None:
            if step is None:
                raise ValueError(f"the {label} component needs its time step")
            given.append((label, values, step))
    common_dt = min(step for _, _, step in given)
    rule = []
    arrays = {}
    for label, values, step in given:
        array = np.asarray(values, dtype=float)
        if not math.isclose(step, common_dt, rel_tol=1e-9):
            array = resample(array, step, common_dt)
            rule.append(f"{label} resampled from dt={step:g} s to {common_dt:g} s")
        arrays[label] = array
    n = max(array.size for array in arrays.values())
    for label, array in arrays.items():
        if array.size < n:
            rule.append(f"{label} padded with {n - array.size} zeros")
            arrays[label] = np.concatenate([array, np.zeros(n - array.size)])
    metadata = dict(metadata or {})
    metadata["combination"] = "; ".join(rule) if rule else "same step and length"
    return GroundMotion(
        common_dt,
        arrays["horizontal"],
        arrays.get("vertical"),
        name=name,
        metadata=metadata,
        horizontal_y=arrays.get("horizontal_y"),
    )


# ---------------------------------------------------------------- pulses


def _pulse_times(dt: float, pulse_duration: float, total_duration: float | None):
    if not (dt > 0 and math.isfinite(dt)):
        raise ValueError(f"dt must be positive, got {dt!r}")
    if not (pulse_duration > 0 and math.isfinite(pulse_duration)):
        raise ValueError(f"pulse duration must be positive, got {pulse_duration!r}")
    total = pulse_duration if total_duration is None else float(total_duration)
    if total < pulse_duration * (1 - 1e-12):
        raise ValueError(f"total duration {total} s is shorter than the pulse ({pulse_duration} s)")
    n = int(round(total / dt)) + 1
    n = max(n, 2)
    t = np.arange(n) * dt
    inside = t <= pulse_duration * (1 + 1e-12) + 1e-12 * dt
    return t, inside


def _pulse_period(frequency, duration, cycles: float, kind: str) -> tuple[float, float]:
    """(frequency [Hz], pulse duration [s]) from either one; ``cycles`` of the sine."""
    if (frequency is None) == (duration is None):
        raise ValueError(f"{kind}: give exactly one of frequency [Hz] or duration [s]")
    if frequency is not None:
        if not (frequency > 0 and math.isfinite(frequency)):
            raise ValueError(f"{kind}: frequency must be positive, got {frequency!r}")
        return float(frequency), cycles / float(frequency)
    if not (duration > 0 and math.isfinite(duration)):
        raise ValueError(f"{kind}: duration must be positive, got {duration!r}")
    return cycles / float(duration), float(duration)


def rectangular_pulse(
    amplitude: float,
    duration: float,
    dt: float,
    total_duration: float | None = None,
    *,
    name: str | None = None,
) -> GroundMotion:
    """A rectangular acceleration pulse as a sampled record.

    Parameters
    ----------
    amplitude : float
        Pulse acceleration a_p [m/s^2] (sign gives the direction).
    duration : float
        Pulse duration t_1 [s].
    dt : float
        Time step [s].
    total_duration : float, optional
        Record length [s], the pulse followed by zeros (default: the pulse).
    name : str, optional
        Record name.

    Returns
    -------
    GroundMotion
        a(t_i) = a_p for t_i <= t_1, 0 after (Housner 1963). With linear
        interpolation the end of the pulse is a ramp over one step, so the
        sampled pulse carries the impulse a_p (t_1' + dt / 2) with t_1' the
        last sample time not after t_1: choose a small ``dt`` against t_1.
    """
    t, inside = _pulse_times(dt, duration, total_duration)
    a = np.where(inside, float(amplitude), 0.0)
    return GroundMotion(
        dt,
        a,
        name=name or f"rectangular pulse {amplitude:g} m/s^2, {duration:g} s",
        metadata={"pulse": "rectangular", "amplitude": amplitude, "pulse_duration": duration},
    )


def half_sine_pulse(
    amplitude: float,
    *,
    frequency: float | None = None,
    duration: float | None = None,
    dt: float,
    total_duration: float | None = None,
    name: str | None = None,
) -> GroundMotion:
    """A half-sine pulse a_p sin(2 pi f t), 0 <= t <= 1 / (2 f), as a sampled record.

    Parameters
    ----------
    amplitude : float
        Peak acceleration a_p [m/s^2].
    frequency : float, optional
        Frequency f of the sine [Hz]; or give ``duration`` = 1 / (2 f) [s].
    duration : float, optional
        Pulse duration [s].
    dt : float
        Time step [s].
    total_duration : float, optional
        Record length [s] with trailing zeros (default: the pulse).
    name : str, optional
        Record name.

    Notes
    -----
    Housner (1963); Makris and Roussos (2000), Geotechnique 50(3).
    """
    f, tp = _pulse_period(frequency, duration, 0.5, "half-sine pulse")
    t, inside = _pulse_times(dt, tp, total_duration)
    a = np.where(inside, amplitude * np.sin(2.0 * np.pi * f * t), 0.0)
    return GroundMotion(
        dt,
        a,
        name=name or f"half-sine pulse {amplitude:g} m/s^2, {f:g} Hz",
        metadata={"pulse": "half-sine", "amplitude": amplitude, "frequency": f},
    )


def one_sine_pulse(
    amplitude: float,
    *,
    frequency: float | None = None,
    duration: float | None = None,
    dt: float,
    total_duration: float | None = None,
    name: str | None = None,
) -> GroundMotion:
    """A one-sine (type A) pulse a_p sin(2 pi f t), 0 <= t <= 1 / f, as a sampled record.

    Parameters
    ----------
    amplitude : float
        Peak acceleration a_p [m/s^2].
    frequency : float, optional
        Pulse frequency f [Hz]; or give ``duration`` = 1 / f [s].
    duration : float, optional
        Pulse duration [s].
    dt : float
        Time step [s].
    total_duration : float, optional
        Record length [s] with trailing zeros (default: the pulse).
    name : str, optional
        Record name.

    Notes
    -----
    Zhang and Makris (2001), J. Eng. Mech. 127(5), type-A pulse.
    """
    f, tp = _pulse_period(frequency, duration, 1.0, "one-sine pulse")
    t, inside = _pulse_times(dt, tp, total_duration)
    a = np.where(inside, amplitude * np.sin(2.0 * np.pi * f * t), 0.0)
    return GroundMotion(
        dt,
        a,
        name=name or f"one-sine pulse {amplitude:g} m/s^2, {f:g} Hz",
        metadata={"pulse": "one-sine", "amplitude": amplitude, "frequency": f},
    )


def one_cosine_pulse(
    amplitude: float,
    *,
    frequency: float | None = None,
    duration: float | None = None,
    dt: float,
    total_duration: float | None = None,
    name: str | None = None,
) -> GroundMotion:
    """A one-cosine (type B) pulse a_p cos(2 pi f t), 0 <= t <= 1 / f, as a sampled record.

    Parameters
    ----------
    amplitude : float
        Peak acceleration a_p [m/s^2].
    frequency : float, optional
        Pulse frequency f [Hz]; or give ``duration`` = 1 / f [s].
    duration : float, optional
        Pulse duration [s].
    dt : float
        Time step [s].
    total_duration : float, optional
        Record length [s] with trailing zeros (default: the pulse).
    name : str, optional
        Record name.

    Notes
    -----
    Zhang and Makris (2001), J. Eng. Mech. 127(5), type-B pulse. The record
    starts at a_p (a step at t = 0) and ends at a_p, after which it ramps to
    zero over one step.
    """
    f, tp = _pulse_period(frequency, duration, 1.0, "one-cosine pulse")
    t, inside = _pulse_times(dt, tp, total_duration)
    a = np.where(inside, amplitude * np.cos(2.0 * np.pi * f * t), 0.0)
    return GroundMotion(
        dt,
        a,
        name=name or f"one-cosine pulse {amplitude:g} m/s^2, {f:g} Hz",
        metadata={"pulse": "one-cosine", "amplitude": amplitude, "frequency": f},
    )


# ------------------------------------------------------- synthetic record


def synthetic_acceleration(
    *,
    duration: float,
    dt: float,
    peak: float,
    seed: int,
    ground_frequency: float,
    ground_damping: float = 0.6,
    rise_time: float = 1.5,
    strong_end: float = 6.0,
    decay_rate: float = 0.5,
    highpass_frequency: float = 0.2,
) -> np.ndarray:
    """A deterministic synthetic accelerogram [m/s^2] (filtered noise with an envelope).

    Parameters
    ----------
    duration : float
        Record length [s].
    dt : float
        Time step [s].
    peak : float
        Peak acceleration of the result [m/s^2].
    seed : int
        Seed of :func:`numpy.random.default_rng`; the same seed gives the same record.
    ground_frequency : float
        Kanai-Tajimi ground frequency f_g [Hz].
    ground_damping : float, optional
        Kanai-Tajimi ground damping zeta_g [-] (default 0.6).
    rise_time, strong_end : float, optional
        Envelope: (t / rise_time)^2 up to ``rise_time`` [s], 1 until
        ``strong_end`` [s] (defaults 1.5 s, 6 s) ...
    decay_rate : float, optional
        ... then exp(-decay_rate (t - strong_end)) [1/s] (default 0.5).
    highpass_frequency : float, optional
        Corner of the zero-phase 4th-order Butterworth high-pass [Hz] that
        removes the drift of velocity and displacement (default 0.2 Hz).

    Returns
    -------
    numpy.ndarray
        Accelerations at t_i = i dt, peak |a| = ``peak``.

    Notes
    -----
    Procedure: (1) standard normal white noise from ``default_rng(seed)``;
    (2) Kanai-Tajimi filter: the absolute acceleration of an oscillator
    (f_g, zeta_g) on that noise (Kanai 1957; Tajimi 1960), computed with the
    exact recursion of :func:`freestand.core.motion.response_spectrum.oscillator_response`;
    (3) multiplication by the envelope of Jennings, Housner and Tsai (1968);
    (4) zero-phase Butterworth high-pass; (5) baseline correction: subtract
    envelope (c0 + c1 t / T) with c0, c1 such that the final ground velocity and
    displacement are zero; (6) scaling to ``peak``.
    It imitates the character of a strong-motion record; it is not a recorded
    earthquake.
    """
    from scipy.signal import butter, sosfiltfilt

    from freestand.core.motion.response_spectrum import oscillator_response

    n = int(round(duration / dt)) + 1
    t = np.arange(n) * dt
    noise = np.random.default_rng(seed).standard_normal(n)
    filtered = oscillator_response(noise, ground_frequency, ground_damping, dt)
    a = filtered.absolute_acceleration
    envelope = np.where(
        t < rise_time,
        (t / rise_time) ** 2,
        np.where(t <= strong_end, 1.0, np.exp(-decay_rate * (t - strong_end))),
    )
    a = a * envelope
    sos = butter(4, highpass_frequency, btype="highpass", fs=1.0 / dt, output="sos")
    a = sosfiltfilt(sos, a)
    # (5) baseline: subtract envelope * (c0 + c1 t) so that the support ends at
    # rest where it started (final velocity and displacement zero)
    a = baseline_correct(a, dt, envelope)
    return a * (peak / np.max(np.abs(a)))


def baseline_correct(acceleration: np.ndarray, dt: float, weight: np.ndarray) -> np.ndarray:
    """Remove the drift of velocity and displacement: the support ends at rest where it started.

    Parameters
    ----------
    acceleration : numpy.ndarray
        Accelerations a(t_i) [m/s^2] at t_i = i dt, piecewise linear.
    dt : float
        Time step [s].
    weight : numpy.ndarray
        Non-negative shape w(t_i) [-] of the correction, e.g. the time envelope
        of the record, so that the correction follows the record's intensity
        and leaves its quiet start and end quiet.

    Returns
    -------
    numpy.ndarray
        a(t) - w(t) (c0 + c1 t / t_end) [m/s^2], with c0, c1 [m/s^2] solving the
        2 x 2 linear system that makes the final velocity v(t_end) and
        displacement d(t_end) zero (integrals from rest of the piecewise-linear
        record, exact). A low-order, envelope-weighted variant of the
        polynomial baseline correction of Boore (2001), "Effect of baseline
        corrections on displacements and response spectra for several
        recordings of the 1999 Chi-Chi, Taiwan, earthquake", BSSA 91(5).
    """
    a = np.asarray(acceleration, dtype=float)
    w = np.asarray(weight, dtype=float)
    t = np.arange(a.size) * dt
    basis = [w, w * t / t[-1]]
    ends = np.array([_final_velocity_displacement(b, dt) for b in basis]).T
    c = np.linalg.solve(ends, _final_velocity_displacement(a, dt))
    return a - c[0] * basis[0] - c[1] * basis[1]


def _final_velocity_displacement(a: np.ndarray, dt: float) -> np.ndarray:
    """Final velocity and displacement from rest of a piecewise-linear record."""
    v = np.concatenate([[0.0], np.cumsum(0.5 * (a[:-1] + a[1:]) * dt)])
    d_end = np.sum(v[:-1] * dt + (2.0 * a[:-1] + a[1:]) * dt**2 / 6.0)
    return np.array([v[-1], d_end])


def synthetic_ground_motion(
    *,
    duration: float = 15.0,
    dt: float = 0.005,
    horizontal_peak: float = 0.25 * 9.81,
    vertical_peak: float | None = 0.25 * 9.81 * 2.0 / 3.0,
    seed: int = 20240601,
    horizontal_frequency: float = 2.5,
    vertical_frequency: float = 6.0,
) -> GroundMotion:
    """The synthetic example record shipped with freestand (see :func:`synthetic_acceleration`).

    Parameters
    ----------
    duration : float, optional
        Record length [s] (default 15 s).
    dt : float, optional
        Time step [s] (default 0.005 s).
    horizontal_peak : float, optional
        Horizontal peak acceleration [m/s^2] (default 0.25 g with g = 9.81).
    vertical_peak : float or None, optional
        Vertical peak acceleration [m/s^2] (default 2/3 of the horizontal);
        None for no vertical component.
    seed : int, optional
        Seed of the horizontal noise; the vertical uses ``seed + 1``.
    horizontal_frequency, vertical_frequency : float, optional
        Kanai-Tajimi ground frequencies [Hz] (defaults 2.5 Hz and 6 Hz).
    """
    horizontal = synthetic_acceleration(
        duration=duration,
        dt=dt,
        peak=horizontal_peak,
        seed=seed,
        ground_frequency=horizontal_frequency,
    )
    vertical = None
    if vertical_peak is not None:
        vertical = synthetic_acceleration(
            duration=duration,
            dt=dt,
            peak=vertical_peak,
            seed=seed + 1,
            ground_frequency=vertical_frequency,
        )
    return GroundMotion(
        dt,
        horizontal,
        vertical,
        name=f"synthetic (seed {seed})",
        metadata={"synthetic": True, "seed": seed},
    )
