"""Spectrum-compatible acceleration records: matching, baseline correction, acceptance.

A suite of records compatible with a design spectrum (US NRC SRP 3.7.1) is made
in three steps for each record:

1. a **seed** from the stochastic model of Rezaeian and Der Kiureghian (2010)
   (:mod:`freestand.core.motion.synthesis`): a nonstationary motion with a realistic
   envelope and a frequency content that changes in time;
2. **spectral matching** by the continuous-wavelet-transform method of Montejo
   and Suarez (2013): the record is the sum of its wavelet details at the
   scales of the matching frequencies, each detail is multiplied by the ratio
   of the target to the record's spectrum at its frequency, and the sum is
   iterated to convergence. Because each detail keeps its place in time, the
   record keeps the seed's nonstationary character. With a scale factor that
   is constant in time, the operation is a zero-phase filter whose gain is the
   ratios weighted by the wavelets' spectra; here, a simplification, the gain
   is the ratio interpolated (log-log) between the 241 closely spaced check
   frequencies, applied by FFT (zero-padded, no wrap-around). Each iteration
   also trims the peak ground acceleration towards the target's zero-period
   value with short wavelets at the peaks, as the time-domain corrections of
   Al Atik and Abrahamson (2010);
3. **baseline correction**: an envelope-weighted linear correction makes the
   final velocity and displacement zero
   (:func:`freestand.core.motion.ground_motion.baseline_correct`).

The spectrum of every iterate is computed by the exact piecewise-linear
recursion of :mod:`freestand.core.motion.response_spectrum`, with its coefficients
built once (:class:`~freestand.core.motion.response_spectrum.SpectrumPlan`).

Acceptance (SRP 3.7.1 option 1 approach 2, as in the issue): the spectrum at
the target's damping, at 100 log-spaced frequencies per decade from 0.2 to
50 Hz, within 0.9 and 1.3 times the target at every frequency; the suite mean
not below the target; the peak acceleration within 5 % of the target's
zero-period value; the 5-75 % Arias-intensity duration reported; the
correlation coefficient of any two records below 0.3, and of any two
components of one record (x, y, vertical: their statistical independence)
below 0.3.

References
----------
Montejo, L. A. and Suarez, L. E. (2013). An improved CWT-based algorithm for
the generation of spectrum-compatible records. International Journal of
Advanced Structural Engineering 5:26.

Al Atik, L. and Abrahamson, N. (2010). An improved method for nonstationary
spectral matching. Earthquake Spectra 26(3), 601-617.

US NRC (2014). Standard Review Plan 3.7.1, Seismic design parameters, Rev. 4.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from freestand.core.motion.ground_motion import baseline_correct
from freestand.core.motion.response_spectrum import SpectrumPlan
from freestand.core.motion.spectra import Spectrum
from freestand.core.motion.synthesis import SeedParameters, draw_seed_parameters, seed_acceleration


@dataclass(frozen=True)
class AcceptanceCriteria:
    """Acceptance criteria of a spectrum-compatible record and suite.

    Parameters
    ----------
    lowest_frequency, highest_frequency : float
        Frequency range checked [Hz] (default 0.2 to 50 Hz).
    per_decade : int
        Log-spaced check frequencies per decade [-] (default 100).
    lower_ratio, upper_ratio : float
        Bounds of record spectrum / target at every frequency [-] (0.9, 1.3).
    peak_tolerance : float
        Largest relative deviation of the peak acceleration from the
        target's zero-period value [-] (0.05).
    max_correlation : float
        Largest allowed |correlation coefficient| of two records [-] (0.3).
    """

    lowest_frequency: float = 0.2
    highest_frequency: float = 50.0
    per_decade: int = 100
    lower_ratio: float = 0.9
    upper_ratio: float = 1.3
    peak_tolerance: float = 0.05
    max_correlation: float = 0.3

    def frequencies(self) -> np.ndarray:
        """The check frequencies [Hz], both ends included."""
        decades = math.log10(self.highest_frequency / self.lowest_frequency)
        count = int(round(self.per_decade * decades)) + 1
        return np.geomspace(self.lowest_frequency, self.highest_frequency, count)


def zero_period_acceleration(target: Spectrum) -> float:
    """The target's zero-period (rigid) acceleration [m/s^2].

    ``metadata["zero_period_acceleration"]`` when the spectrum states it (the
    design spectra of :mod:`freestand.core.motion.design_spectra` do), otherwise its
    value at its highest tabulated frequency.
    """
    value = target.metadata.get("zero_period_acceleration")
    if value is not None:
        return float(value)
    return float(target.acceleration[-1])


def arias_intensity(acceleration: np.ndarray, dt: float, gravity: float = 9.81) -> np.ndarray:
    """Cumulative Arias intensity I_a(t_i) = pi / (2 g) int_0^t a^2 dt [m/s] (Arias 1970).

    Exact for the piecewise-linear record: the integral of a^2 over a step is
    dt (a_i^2 + a_i a_{i+1} + a_{i+1}^2) / 3.
    """
    a = np.asarray(acceleration, dtype=float)
    steps = dt * (a[:-1] ** 2 + a[:-1] * a[1:] + a[1:] ** 2) / 3.0
    return math.pi / (2.0 * gravity) * np.concatenate([[0.0], np.cumsum(steps)])


def significant_duration(
    acceleration: np.ndarray, dt: float, start: float = 0.05, end: float = 0.75
) -> float:
    """Time between ``start`` and ``end`` fractions of the Arias intensity [s] (D5-75).

    Trifunac and Brady (1975) significant duration with the 5-75 % bounds;
    the crossing times are interpolated linearly between samples.
    """
    cumulative = arias_intensity(acceleration, dt)
    total = cumulative[-1]
    if total <= 0:
        return 0.0
    t = np.arange(cumulative.size) * dt
    fraction = cumulative / total
    return float(np.interp(end, fraction, t) - np.interp(start, fraction, t))


@dataclass(frozen=True)
class RecordCheck:
    """Acceptance checks of one matched record component.

    Attributes
    ----------
    min_ratio, max_ratio : float
        Smallest and largest record spectrum / target on the check frequencies [-].
    min_ratio_frequency, max_ratio_frequency : float
        Where they occur [Hz].
    peak_acceleration : float
        Peak ground acceleration max |a| [m/s^2].
    zero_period_acceleration : float
        The target's zero-period value [m/s^2].
    duration_5_75 : float
        5-75 % Arias-intensity duration [s].
    final_velocity, final_displacement : float
        Velocity [m/s] and displacement [m] at the last sample.
    passed : bool
        Spectrum within bounds and PGA within tolerance.
    reasons : tuple of str
        Why it failed (empty when it passed).
    iterations : int
        Matching iterations used [-].
    attempts : int
        Seeds tried [-] (1 when the first seed matched).
    """

    min_ratio: float
    max_ratio: float
    min_ratio_frequency: float
    max_ratio_frequency: float
    peak_acceleration: float
    zero_period_acceleration: float
    duration_5_75: float
    final_velocity: float
    final_displacement: float
    passed: bool
    reasons: tuple[str, ...] = ()
    iterations: int = 0
    attempts: int = 1

    @property
    def peak_ratio(self) -> float:
        """PGA / zero-period value [-]."""
        return self.peak_acceleration / self.zero_period_acceleration


def _record_check(
    acceleration: np.ndarray,
    dt: float,
    psa: np.ndarray,
    psa_record: np.ndarray,
    target_values: np.ndarray,
    frequencies: np.ndarray,
    zpa: float,
    criteria: AcceptanceCriteria,
    *,
    iterations: int = 0,
    attempts: int = 1,
) -> RecordCheck:
    # lower bound: the spectrum over the record alone; upper: with the free vibration
    ratio_low = psa_record / target_values
    ratio = psa / target_values
    i_min = int(np.argmin(ratio_low))
    i_max = int(np.argmax(ratio))
    pga = float(np.max(np.abs(acceleration)))
    reasons = []
    if ratio_low[i_min] < criteria.lower_ratio:
        reasons.append(
            f"spectrum {ratio_low[i_min]:.3f} x target at {frequencies[i_min]:.3g} Hz "
            f"(below {criteria.lower_ratio:g})"
        )
    if ratio[i_max] > criteria.upper_ratio:
        reasons.append(
            f"spectrum {ratio[i_max]:.3f} x target at {frequencies[i_max]:.3g} Hz "
            f"(above {criteria.upper_ratio:g})"
        )
    if abs(pga / zpa - 1.0) > criteria.peak_tolerance:
        reasons.append(
            f"peak acceleration {pga:.4g} m/s^2 is {pga / zpa:.3f} x the zero-period value "
            f"{zpa:.4g} m/s^2 (tolerance {100 * criteria.peak_tolerance:g} %)"
        )
    v = np.concatenate([[0.0], np.cumsum(0.5 * (acceleration[:-1] + acceleration[1:]) * dt)])
    d_end = float(np.sum(v[:-1] * dt + (2.0 * acceleration[:-1] + acceleration[1:]) * dt**2 / 6))
    return RecordCheck(
        min_ratio=float(ratio_low[i_min]),
        max_ratio=float(ratio[i_max]),
        min_ratio_frequency=float(frequencies[i_min]),
        max_ratio_frequency=float(frequencies[i_max]),
        peak_acceleration=pga,
        zero_period_acceleration=zpa,
        duration_5_75=significant_duration(acceleration, dt),
        final_velocity=float(v[-1]),
        final_displacement=d_end,
        passed=not reasons,
        reasons=tuple(reasons),
        iterations=iterations,
        attempts=attempts,
    )


@dataclass(frozen=True)
class MatchSettings:
    """Settings of the iterative matching.

    Parameters
    ----------
    aim : float
        The record is matched to ``aim`` times the target [-] (default 1.08,
        near the geometric centre of the 0.9-1.3 band, so that the suite mean
        stays above the target).
    band : tuple of float
        Iterations stop once spectrum / target lies within this band at every
        check frequency [-] and the PGA within ``peak_band`` (default 0.93-1.25).
    peak_band : float
        Relative PGA tolerance for stopping [-] (default 0.025).
    max_iterations : int
        Iterations per seed [-] (default 40).
    max_attempts : int
        Seeds tried for one record before it is reported as failed [-] (default 6).
    relaxation : float
        Exponent beta of the gain ratio^beta per iteration [-] (default 1).
    correlation_margin : float
        A record whose correlation coefficient with an earlier one exceeds
        this fraction of the allowed maximum is regenerated (up to twice) [-]
        (default 0.8), so that the suite keeps a margin below the limit.
    """

    aim: float = 1.10
    band: tuple[float, float] = (0.96, 1.26)
    peak_band: float = 0.025
    max_iterations: int = 40
    max_attempts: int = 6
    relaxation: float = 1.0
    correlation_margin: float = 0.8


@dataclass(frozen=True)
class MatchedRecord:
    """One spectrum-compatible acceleration history.

    Attributes
    ----------
    acceleration : numpy.ndarray
        a(t_i) [m/s^2], baseline corrected.
    dt : float
        Time step [s].
    check : RecordCheck
        Its acceptance checks.
    spectrum : numpy.ndarray
        Its pseudo-acceleration [m/s^2] at the check frequencies (with the free
        vibration after the record).
    seed_parameters : SeedParameters
        The stochastic-model parameters of the seed that was matched.
    """

    acceleration: np.ndarray
    dt: float
    check: RecordCheck
    spectrum: np.ndarray
    seed_parameters: SeedParameters
    spectrum_in_record: np.ndarray | None = None

    @property
    def lower_spectrum(self) -> np.ndarray:
        """Pseudo-acceleration [m/s^2] over the record alone (a lower bound of ``spectrum``)."""
        return self.spectrum if self.spectrum_in_record is None else self.spectrum_in_record


def end_tapers(n: int, dt: float, start: float = 0.5, end: float = 1.0) -> np.ndarray:
    """A window [-] rising as a half cosine over ``start`` [s] and falling over ``end`` [s].

    The tapers are at most 5 % (start) and 10 % (end) of the record; the
    window is 0 at the first and last samples, so the support starts and ends
    at rest without a jump in acceleration.
    """
    t = np.arange(n) * dt
    total = t[-1]
    rise = min(start, 0.05 * total)
    fall = min(end, 0.10 * total)
    w = np.ones(n)
    head = t < rise
    w[head] = 0.5 - 0.5 * np.cos(np.pi * t[head] / rise)
    tail = t > total - fall
    w[tail] = 0.5 - 0.5 * np.cos(np.pi * (total - t[tail]) / fall)
    return w


def _gain(freq_grid, match_freq, ratio, low_cut, nyquist):
    """Zero-phase gain on the FFT grid: the ratio interpolated on log axes.

    Below the lowest matching frequency the ratio is held, then tapered to 1 at
    half that frequency; above the highest it is held up to the Nyquist
    frequency.
    """
    log_f = np.log(np.maximum(freq_grid, 1e-12))
    g = np.exp(np.interp(log_f, np.log(match_freq), np.log(ratio)))
    f0 = match_freq[0]
    below = freq_grid < f0
    # cosine taper from the held ratio at f0 to 1 at f0 / 2
    x = np.clip((freq_grid - low_cut) / (f0 - low_cut), 0.0, 1.0)
    taper = 0.5 - 0.5 * np.cos(np.pi * x)
    g = np.where(below, 1.0 + (g - 1.0) * taper, g)
    return g


def _trim_peak(a: np.ndarray, dt: float, zpa: float, centre_frequency: float) -> np.ndarray:
    """Bring max |a| to ``zpa`` with short cosine-Gaussian wavelets at the peaks.

    Every sample above zpa in magnitude is pulled down by a wavelet
    psi(t) = exp(-(t / s)^2) cos(2 pi f_w t) (psi(0) = 1, s = 1 / (2 f_w));
    when the peak is below zpa, the largest sample is pushed up. The wavelets
    are short (a few hundredths of a second) and carry almost no net area, so
    they change the spectrum mainly at high frequencies, where the next
    spectral correction restores it (compare the time-domain adjustment
    wavelets of Al Atik and Abrahamson 2010).
    """
    a = a.copy()
    s = 1.0 / (2.0 * centre_frequency)
    half = int(math.ceil(3.0 * s / dt))
    tau = np.arange(-half, half + 1) * dt
    psi = np.exp(-((tau / s) ** 2)) * np.cos(2.0 * np.pi * centre_frequency * tau)
    for _ in range(20):
        k = int(np.argmax(np.abs(a)))
        excess = abs(a[k]) - zpa
        if abs(excess) <= 0.002 * zpa:
            break
        if excess < 0:
            # push the largest peak up to zpa
            delta = -excess * np.sign(a[k])
        else:
            delta = -excess * np.sign(a[k])
        lo = max(0, k - half)
        hi = min(a.size, k + half + 1)
        a[lo:hi] += delta * psi[lo - (k - half) : hi - (k - half)]
    return a


def match_record(
    seed: np.ndarray,
    dt: float,
    target: Spectrum,
    *,
    weight: np.ndarray,
    criteria: AcceptanceCriteria | None = None,
    settings: MatchSettings | None = None,
    plan: SpectrumPlan | None = None,
    lower: np.ndarray | None = None,
    rescale: bool = True,
) -> tuple[np.ndarray, np.ndarray, RecordCheck]:
    """Match one seed record to a target spectrum (Montejo and Suarez 2013).

    Parameters
    ----------
    seed : numpy.ndarray
        Seed accelerations (any scale) at t_i = i dt.
    dt : float
        Time step [s].
    target : Spectrum
        Target pseudo-acceleration spectrum [m/s^2] at its damping.
    weight : numpy.ndarray
        Time envelope of the seed [-], the shape of the baseline correction.
    criteria, settings : optional
        Acceptance criteria and matching settings (defaults).
    plan : SpectrumPlan, optional
        Precomputed recursion coefficients at the check frequencies, step and
        target damping.
    lower : numpy.ndarray, optional
        Lower end of the stopping band at each check frequency [-] (default
        ``settings.band[0]`` everywhere); the suite refinement raises it where
        the suite mean falls short of the target.
    rescale : bool, optional
        Scale the seed to the target's level first (default True; False when
        refining a record that is already matched).

    Returns
    -------
    acceleration, spectrum, spectrum_in_record, check
        The matched, baseline-corrected record [m/s^2], its pseudo-acceleration
        at the check frequencies [m/s^2] with and without the free vibration
        after the record, and its acceptance checks (on the returned record
        itself: the lower bounds on the second spectrum, the upper on the first,
        so that they hold whichever convention a spectrum program follows).
    """
    criteria = criteria or AcceptanceCriteria()
    settings = settings or MatchSettings()
    frequencies = criteria.frequencies()
    if plan is None:
        plan = SpectrumPlan.build(frequencies, dt, target.damping)
    target_values = np.asarray(target.acceleration_at(frequencies), dtype=float)
    zpa = zero_period_acceleration(target)
    n = seed.size
    n_fft = 1 << int(math.ceil(math.log2(2 * n)))
    freq_grid = np.fft.rfftfreq(n_fft, dt)
    nyquist = 0.5 / dt
    aim = settings.aim * target_values
    # the record starts and ends at rest: cosine tapers at both ends, applied to
    # every iterate and to the shape of the baseline correction
    window = end_tapers(n, dt)
    weight = np.asarray(weight, dtype=float) * window
    # initial scale: the seed's spectrum to the target on average (log)
    a = np.asarray(seed, dtype=float) * window
    if rescale:
        a = baseline_correct(a, dt, weight)
        psa = plan.pseudo_acceleration(a)
        a = a * float(np.exp(np.mean(np.log(aim / np.maximum(psa, 1e-300)))))
    best = None
    centre = min(0.25 / dt, 25.0)
    lo_band = np.full(frequencies.size, settings.band[0]) if lower is None else lower
    hi_band = settings.band[1]
    for iteration in range(1, settings.max_iterations + 1):
        a = baseline_correct(a, dt, weight)
        psa, psa_record = plan.pseudo_acceleration_bounds(a)
        ratio = psa / target_values
        pga = float(np.max(np.abs(a)))
        # distance from acceptance, in log terms: the worst excursion
        excess = max(
            float(np.max(np.log(lo_band / (psa_record / target_values)))),
            math.log(ratio.max() / hi_band),
            abs(pga / zpa - 1.0) - settings.peak_band,
            0.0,
        )
        if best is None or excess < best[0]:
            best = (excess, a, psa, psa_record, iteration)
        if excess == 0.0:
            break
        gain = (aim / np.maximum(psa, 1e-300)) ** settings.relaxation
        spectrum_fft = np.fft.rfft(a, n_fft)
        spectrum_fft *= _gain(freq_grid, frequencies, gain, 0.5 * frequencies[0], nyquist)
        a = np.fft.irfft(spectrum_fft, n_fft)[:n] * window
        a = _trim_peak(a, dt, zpa, centre)
    _, a, psa, psa_record, iteration = best
    check = _record_check(a, dt, psa, psa_record, target_values, frequencies, zpa, criteria,
                          iterations=iteration)  # fmt: skip
    return a, psa, psa_record, check


def correlation_matrix(records: list[np.ndarray]) -> np.ndarray:
    """Pearson correlation coefficients of every pair of records [-] (zero-mean not assumed)."""
    n = min(r.size for r in records)
    stacked = np.array([r[:n] for r in records])
    return np.corrcoef(stacked)


@dataclass(frozen=True)
class SuiteComponent:
    """The matched records of one direction of a suite.

    Attributes
    ----------
    direction : str
        The component: ``"horizontal"`` (x), ``"horizontal_y"`` or ``"vertical"``.
    target : Spectrum
        The target spectrum.
    records : tuple of MatchedRecord
    frequencies : numpy.ndarray
        Check frequencies [Hz].
    target_values : numpy.ndarray
        Target at the check frequencies [m/s^2].
    """

    direction: str
    target: Spectrum
    records: tuple[MatchedRecord, ...]
    frequencies: np.ndarray
    target_values: np.ndarray

    @property
    def mean_spectrum(self) -> np.ndarray:
        """Arithmetic mean of the records' spectra [m/s^2]."""
        return np.mean([r.spectrum for r in self.records], axis=0)

    @property
    def mean_ratio_min(self) -> float:
        """Smallest suite-mean / target ratio [-] (spectra over the records alone)."""
        mean = np.mean([r.lower_spectrum for r in self.records], axis=0)
        return float(np.min(mean / self.target_values))


@dataclass(frozen=True)
class SuiteResult:
    """A generated suite and its acceptance checks.

    Attributes
    ----------
    horizontal : SuiteComponent
        The x components.
    vertical : SuiteComponent or None
    dt : float
        Time step [s].
    seed : int
        The seed the suite was generated from.
    max_correlation : float
        Largest |correlation coefficient| of any two time histories of the
        suite (every component of every record) [-].
    max_correlation_pair : tuple of str
        The pair where it occurs, as ``("3H", "7H")`` (``"3X"``, ``"3Y"``,
        ``"3V"`` in a suite with two horizontal components).
    criteria : AcceptanceCriteria
    status : str
        ``"accepted"`` or ``"failed"``.
    failures : tuple of str
        Every failed check, naming the record and why.
    horizontal_y : SuiteComponent or None
        The y components (None for a suite with one horizontal component).
    """

    horizontal: SuiteComponent
    vertical: SuiteComponent | None
    dt: float
    seed: int
    max_correlation: float
    max_correlation_pair: tuple[str, str]
    criteria: AcceptanceCriteria
    status: str
    failures: tuple[str, ...] = field(default=())
    horizontal_y: SuiteComponent | None = None

    @property
    def count(self) -> int:
        """Number of records [-]."""
        return len(self.horizontal.records)

    @property
    def components(self) -> tuple[SuiteComponent, ...]:
        """The suite's components in the order x, y, vertical (those it has)."""
        return tuple(
            c for c in (self.horizontal, self.horizontal_y, self.vertical) if c is not None
        )

    def component_correlations(self) -> list[dict]:
        """Independence of each record's components (US NRC SRP 3.7.1).

        Returns
        -------
        list of dict
            Per record: ``pairs``, the |correlation coefficient| [-] of every
            pair of its components (keys such as ``"horizontal-vertical"``),
            and ``max``, the largest (None for a record of one component).
            The suite passes when every one is below
            ``criteria.max_correlation``; ``max_correlation`` (any two time
            histories of the suite) bounds them all.
        """
        out = []
        for index in range(self.count):
            histories = [(c.direction, c.records[index].acceleration) for c in self.components]
            pairs = {}
            for i, (first, a) in enumerate(histories):
                for second, b in histories[i + 1 :]:
                    pairs[f"{first}-{second}"] = float(abs(correlation_matrix([a, b])[0, 1]))
            out.append({"pairs": pairs, "max": max(pairs.values()) if pairs else None})
        return out


#: Seed-stream index of each component: record k, component c draws from
#: SeedSequence([seed, k, c, attempt]); y comes third so that a suite without
#: it draws exactly as before.
COMPONENT_STREAMS = {"horizontal": 0, "vertical": 1, "horizontal_y": 2}


def _rng(seed: int, record: int, component: int, attempt: int) -> np.random.Generator:
    """Independent stream for one (record, component, attempt), from the suite seed."""
    return np.random.default_rng(np.random.SeedSequence([seed, record, component, attempt]))


def _one_record(
    index, component, direction, n, dt, target, criteria, settings, plan, seed, start_attempt=0,
    lower=None,
):  # fmt: skip
    best = best_key = None
    attempts = 0
    target_values = None
    if lower is not None:
        target_values = np.asarray(target.acceleration_at(criteria.frequencies()), dtype=float)
    for attempt in range(start_attempt, start_attempt + settings.max_attempts):
        attempts += 1
        rng = _rng(seed, index, component, attempt)
        kind = "vertical" if direction == "vertical" else "horizontal"
        parameters = draw_seed_parameters(rng, (n - 1) * dt, direction=kind)
        raw = seed_acceleration(parameters, n, dt, rng)
        weight = parameters.envelope(np.arange(n) * dt)
        a, psa, psa_record, check = match_record(
            raw, dt, target, weight=weight, criteria=criteria, settings=settings, plan=plan,
            lower=lower,
        )  # fmt: skip
        record = MatchedRecord(a, dt, check, psa, parameters, psa_record)
        shortfall = 0.0
        if lower is not None:
            shortfall = float(np.max(np.maximum(0.0, lower - psa_record / target_values)))
        key = (_badness(check, criteria), shortfall)
        if best_key is None or key < best_key:
            best, best_key = record, key
        if check.passed and shortfall == 0.0:
            break
    check = best.check
    from dataclasses import replace

    return replace(best, check=replace(check, attempts=attempts)), start_attempt + attempts


def _refine_mean(
    records, target, criteria, settings, plan, n, dt, *, component, direction, seed, margin=0.005
):
    """Raise the records where the suite mean falls below the target.

    Where the mean of the records' spectra is below (1 + margin) times the
    target, every record that is below (1 + margin) there is matched again,
    from where it stands, with its stopping band's lower end raised to
    1 + margin at those frequencies: then the mean cannot be below the target
    there. Records that already pass are untouched elsewhere. Up to three
    rounds; if the mean still falls short, records are regenerated from new
    seeds with the raised band (the last resort for suites of one or two short
    records, whose spectra are jagged at low frequencies).
    """
    from dataclasses import replace

    frequencies = criteria.frequencies()
    target_values = np.asarray(target.acceleration_at(frequencies), dtype=float)
    records = list(records)
    for round_ in range(4):
        mean_ratio = np.mean([r.lower_spectrum for r in records], axis=0) / target_values
        deficient = mean_ratio < 1.0 + margin
        if not np.any(deficient):
            break
        if round_ == 3:
            # last resort: new seeds, worst record first, until the mean holds
            lower = np.where(deficient, 1.0 + margin, settings.band[0])
            shortfall = [np.min(r.lower_spectrum[deficient] / target_values[deficient])
                         for r in records]  # fmt: skip
            for worst in np.argsort(shortfall, kind="stable"):
                worst = int(worst)
                record, _ = _one_record(
                    worst, component, direction, n, dt, target, criteria, settings, plan, seed,
                    start_attempt=1000, lower=lower,
                )  # fmt: skip
                candidate = records[:worst] + [record] + records[worst + 1 :]
                old_mean = np.mean([r.lower_spectrum for r in records], axis=0) / target_values
                new_mean = np.mean([r.lower_spectrum for r in candidate], axis=0) / target_values
                if record.check.passed and new_mean.min() > old_mean.min():
                    records = candidate
                if new_mean.min() >= 1.0 and record.check.passed:
                    break
            break
        for k, record in enumerate(records):
            ratio = record.lower_spectrum / target_values
            if not np.any(deficient & (ratio < 1.0 + margin)):
                continue
            lower = np.where(deficient, 1.0 + margin, settings.band[0])
            weight = record.seed_parameters.envelope(np.arange(n) * dt)
            a, psa, psa_record, check = match_record(
                record.acceleration, dt, target, weight=weight, criteria=criteria,
                settings=settings, plan=plan, lower=lower, rescale=False,
            )  # fmt: skip
            if check.passed or not record.check.passed:
                check = replace(
                    check,
                    iterations=record.check.iterations + check.iterations,
                    attempts=record.check.attempts,
                )
                records[k] = replace(
                    record, acceleration=a, spectrum=psa, spectrum_in_record=psa_record,
                    check=check,
                )  # fmt: skip
    return records


def _badness(check: RecordCheck, criteria: AcceptanceCriteria) -> float:
    return max(
        0.0,
        math.log(criteria.lower_ratio / check.min_ratio),
        math.log(check.max_ratio / criteria.upper_ratio),
        abs(check.peak_ratio - 1.0) - criteria.peak_tolerance,
    )


def generate_suite(
    target: Spectrum,
    *,
    count: int,
    duration: float,
    dt: float = 0.005,
    seed: int = 0,
    vertical_target: Spectrum | None = None,
    horizontal_y_target: Spectrum | None = None,
    criteria: AcceptanceCriteria | None = None,
    settings: MatchSettings | None = None,
    progress=None,
) -> SuiteResult:
    """Generate ``count`` statistically independent records compatible with ``target``.

    Parameters
    ----------
    target : Spectrum
        Horizontal target pseudo-acceleration spectrum [m/s^2] at its damping
        (the x components).
    count : int
        Number of records [-], at least 1.
    duration : float
        Record length [s].
    dt : float, optional
        Time step [s] (default 0.005 s, 200 samples per second).
    seed : int, optional
        Suite seed; record k, component c, attempt j draw from
        ``SeedSequence([seed, k, c, j])`` with c = 0 for x, 1 for the
        vertical and 2 for y (:data:`COMPONENT_STREAMS`), so the suite is
        reproducible, its components independent, and a suite without y the
        same as before y existed.
    vertical_target : Spectrum, optional
        Target for vertical components (matched the same way, independent seeds).
    horizontal_y_target : Spectrum, optional
        Target for a second horizontal component along y (e.g. ``target``
        itself), matched the same way from independent seeds: a suite of
        three-component records (US NRC SRP 3.7.1).
    criteria, settings : optional
        Acceptance criteria and matching settings.
    progress : callable, optional
        Called with no argument after each matched component.

    Returns
    -------
    SuiteResult
        Records, per-record and suite checks, and the list of failures. A
        record that misses its checks is regenerated from new seeds (up to
        ``settings.max_attempts``); a record too correlated with an earlier
        one (any component of any record, so also the components of one
        record with each other) is regenerated as well; what still fails is
        listed in ``failures``, never dropped: a record's spectrum, peak or
        duration, a suite mean below its target, two records correlated,
        or a record whose components are not independent (US NRC SRP
        3.7.1: the correlation coefficient of every pair of its components
        below ``criteria.max_correlation``, :meth:`SuiteResult.component_correlations`).
    """
    criteria = criteria or AcceptanceCriteria()
    settings = settings or MatchSettings()
    if count < 1:
        raise ValueError(f"count must be at least 1, got {count}")
    if not (duration > 0 and dt > 0):
        raise ValueError("duration and dt must be positive")
    n = int(round(duration / dt)) + 1
    if 0.5 / dt < criteria.highest_frequency:
        raise ValueError(
            f"dt = {dt} s cannot represent {criteria.highest_frequency} Hz; "
            f"use dt <= {0.5 / criteria.highest_frequency} s"
        )
    frequencies = criteria.frequencies()
    components = [("horizontal", target)]
    if horizontal_y_target is not None:
        components.append(("horizontal_y", horizontal_y_target))
    if vertical_target is not None:
        components.append(("vertical", vertical_target))
    plans = {}
    for _, spectrum in components:
        if spectrum.damping not in plans:
            plans[spectrum.damping] = SpectrumPlan.build(frequencies, dt, spectrum.damping)
    results: dict[str, list[MatchedRecord]] = {d: [] for d, _ in components}
    accepted_histories: list[np.ndarray] = []
    failures: list[str] = []
    for index in range(count):
        for direction, spectrum in components:
            start = 0
            record = None
            best_key = None
            for _ in range(3):  # regenerate if too correlated with earlier records
                candidate, start = _one_record(
                    index, COMPONENT_STREAMS[direction], direction, n, dt, spectrum, criteria,
                    settings, plans[spectrum.damping], seed, start,
                )  # fmt: skip
                worst = 0.0
                if accepted_histories:
                    r = correlation_matrix([candidate.acceleration, *accepted_histories])[0, 1:]
                    worst = float(np.max(np.abs(r)))
                key = (not candidate.check.passed, worst)
                if best_key is None or key < best_key:
                    record, best_key = candidate, key
                if worst < settings.correlation_margin * criteria.max_correlation:
                    break
            results[direction].append(record)
            accepted_histories.append(record.acceleration)
            if progress is not None:
                progress()
    for direction, spectrum in components:
        results[direction] = _refine_mean(
            results[direction], spectrum, criteria, settings, plans[spectrum.damping], n, dt,
            component=COMPONENT_STREAMS[direction], direction=direction, seed=seed,
        )  # fmt: skip
    letters = (
        {"horizontal": "X", "horizontal_y": "Y", "vertical": "V"}
        if horizontal_y_target is not None
        else {"horizontal": "H", "vertical": "V"}
    )
    labels = []
    histories = []
    for index in range(count):
        for direction, _ in components:
            labels.append(f"{index + 1}{letters[direction]}")
            histories.append(results[direction][index].acceleration)
    max_corr, pair = 0.0, ("", "")
    across = (0.0, ("", ""))
    if len(histories) > 1:
        matrix = np.abs(correlation_matrix(histories))
        np.fill_diagonal(matrix, 0.0)
        max_corr, pair = _largest_pair(matrix, labels)
        # pairs of different records (those of one record: the independence check below)
        owners = np.repeat(np.arange(count), len(components))
        across = _largest_pair(np.where(owners[:, None] == owners, 0.0, matrix), labels)
    suite_components = {}
    for direction, spectrum in components:
        records = tuple(results[direction])
        for k, record in enumerate(records):
            if not record.check.passed:
                failures.append(
                    f"record {k + 1} {direction}: " + "; ".join(record.check.reasons)
                    + f" (after {record.check.attempts} seed(s))"
                )  # fmt: skip
        suite_components[direction] = SuiteComponent(
            direction,
            spectrum,
            records,
            frequencies,
            np.asarray(spectrum.acceleration_at(frequencies), dtype=float),
        )
        mean_min = suite_components[direction].mean_ratio_min
        if mean_min < 1.0:
            failures.append(
                f"suite mean {direction} spectrum is {mean_min:.3f} x target at its lowest "
                "(must not be below the target)"
            )
    if across[0] >= criteria.max_correlation:
        failures.append(
            f"records {across[1][0]} and {across[1][1]} have a correlation coefficient "
            f"{across[0]:.3f} (must be below {criteria.max_correlation:g})"
        )
    result = SuiteResult(
        horizontal=suite_components["horizontal"],
        vertical=suite_components.get("vertical"),
        dt=dt,
        seed=seed,
        max_correlation=max_corr,
        max_correlation_pair=pair,
        criteria=criteria,
        status="accepted",
        horizontal_y=suite_components.get("horizontal_y"),
    )
    failures += _independence_failures(result)
    return replace(result, status="failed" if failures else "accepted", failures=tuple(failures))


def _largest_pair(matrix: np.ndarray, labels: list[str]) -> tuple[float, tuple[str, str]]:
    """The largest entry of a symmetric |correlation| matrix and its two labels."""
    i, j = np.unravel_index(int(np.argmax(matrix)), matrix.shape)
    return float(matrix[i, j]), (labels[min(i, j)], labels[max(i, j)])


def _independence_failures(result: SuiteResult) -> list[str]:
    """The records whose components are not statistically independent (SRP 3.7.1).

    US NRC SRP 3.7.1 (Rev. 4) asks for the components of a record to be
    statistically independent: the absolute correlation coefficient of every
    pair below ``criteria.max_correlation`` (0.3).
    """
    limit = result.criteria.max_correlation
    failures = []
    for index, record in enumerate(result.component_correlations()):
        if record["max"] is not None and record["max"] >= limit:
            worst = max(record["pairs"], key=record["pairs"].get)
            first, second = worst.split("-")
            failures.append(
                f"record {index + 1}: components {first} and {second} are not independent "
                f"(SRP 3.7.1): correlation coefficient {record['max']:.3f} (must be below "
                f"{limit:g})"
            )
    return failures
