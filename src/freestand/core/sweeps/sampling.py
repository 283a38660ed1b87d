"""Uncertainty sweeps: Monte Carlo over uncertain model inputs.

Engineers rarely know the friction coefficient, the exact centre of gravity
or the excitation level. A sweep draws the uncertain inputs from
distributions, solves the initial motion of every sample with the batch
solver (:mod:`freestand.core.contact.batch`, paper section 3) and reports, for every
case (configuration x excitation x sense), the probability of each initial
motion of each block with a binomial confidence interval.

The same samples (common random numbers) are used for every case, so that
cases can be compared sample by sample. Each varied input has its own random
stream (``numpy.random.SeedSequence(seed).spawn``), so adding a variation
does not change the samples of the others.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np

from freestand.core.contact.batch import (
    AMBIGUOUS,
    FREE_FLIGHT,
    INCONSISTENT,
    INVALID,
    MOTIONS,
    STATUS_NAMES,
    BatchResult,
    Parameter,
    case_inputs,
    solve_batch,
)
from freestand.core.contact.screening import GRAVITY
from freestand.core.model import Excitation, Stack

# --- distributions ------------------------------------------------------------------------------


@dataclass(frozen=True)
class Fixed:
    """Every sample takes ``value`` (a zero-spread distribution)."""

    value: float

    def sample(self, rng: np.random.Generator, count: int) -> np.ndarray:
        """``count`` samples."""
        return np.full(count, float(self.value))

    def describe(self) -> str:
        """Text such as ``"fixed(0.25)"``."""
        return f"fixed({self.value:g})"


@dataclass(frozen=True)
class Uniform:
    """Uniform between ``low`` and ``high`` (``low <= high``)."""

    low: float
    high: float

    def __post_init__(self):
        if not self.low <= self.high:
            raise ValueError(f"uniform needs low <= high, not {self.low} > {self.high}")

    def sample(self, rng: np.random.Generator, count: int) -> np.ndarray:
        """``count`` samples."""
        return rng.uniform(self.low, self.high, count)

    def describe(self) -> str:
        """Text such as ``"uniform(0.15, 0.35)"``."""
        return f"uniform({self.low:g}, {self.high:g})"


@dataclass(frozen=True)
class Normal:
    """Normal (Gaussian) with mean and standard deviation (``std >= 0``)."""

    mean: float
    std: float

    def __post_init__(self):
        if not self.std >= 0:
            raise ValueError(f"normal needs std >= 0, not {self.std}")

    def sample(self, rng: np.random.Generator, count: int) -> np.ndarray:
        """``count`` samples."""
        return rng.normal(self.mean, self.std, count)

    def describe(self) -> str:
        """Text such as ``"normal(0.36, 0.05)"``."""
        return f"normal({self.mean:g}, {self.std:g})"


@dataclass(frozen=True)
class TruncatedNormal:
    """Normal(mean, std) restricted to ``[low, high]`` (by inverse transform)."""

    mean: float
    std: float
    low: float
    high: float

    def __post_init__(self):
        if not self.std >= 0 or not self.low <= self.high:
            raise ValueError(
                f"truncnormal needs std >= 0 and low <= high (std {self.std}, "
                f"low {self.low}, high {self.high})"
            )
        if not self.low <= self.mean <= self.high and self.std == 0:
            raise ValueError(f"truncnormal with std 0 needs low <= mean <= high ({self.mean})")

    def sample(self, rng: np.random.Generator, count: int) -> np.ndarray:
        """``count`` samples."""
        if self.std == 0:
            return np.full(count, float(self.mean))
        from scipy.stats import truncnorm

        a = (self.low - self.mean) / self.std
        b = (self.high - self.mean) / self.std
        return truncnorm.ppf(rng.uniform(0.0, 1.0, count), a, b, loc=self.mean, scale=self.std)

    def describe(self) -> str:
        """Text such as ``"truncnormal(0.25, 0.05, 0.1, 0.4)"``."""
        return f"truncnormal({self.mean:g}, {self.std:g}, {self.low:g}, {self.high:g})"


@dataclass(frozen=True)
class Triangular:
    """Triangular between ``low`` and ``high`` with its peak at ``mode``."""

    low: float
    mode: float
    high: float

    def __post_init__(self):
        if not self.low <= self.mode <= self.high:
            raise ValueError(
                f"triangular needs low <= mode <= high ({self.low}, {self.mode}, {self.high})"
            )

    def sample(self, rng: np.random.Generator, count: int) -> np.ndarray:
        """``count`` samples."""
        if self.low == self.high:
            return np.full(count, float(self.low))
        return rng.triangular(self.low, self.mode, self.high, count)

    def describe(self) -> str:
        """Text such as ``"triangular(0.15, 0.25, 0.35)"``."""
        return f"triangular({self.low:g}, {self.mode:g}, {self.high:g})"


@dataclass(frozen=True)
class LogNormal:
    """Log-normal with ``median`` and the standard deviation of its logarithm."""

    median: float
    log_std: float

    def __post_init__(self):
        if not self.median > 0 or not self.log_std >= 0:
            raise ValueError(
                f"lognormal needs median > 0 and log_std >= 0 ({self.median}, {self.log_std})"
            )

    def sample(self, rng: np.random.Generator, count: int) -> np.ndarray:
        """``count`` samples."""
        return self.median * np.exp(rng.normal(0.0, self.log_std, count))

    def describe(self) -> str:
        """Text such as ``"lognormal(16600, 0.1)"``."""
        return f"lognormal({self.median:g}, {self.log_std:g})"


Distribution = Fixed | Uniform | Normal | TruncatedNormal | Triangular | LogNormal


@dataclass(frozen=True)
class Variation:
    """An uncertain input and its distribution.

    Parameters
    ----------
    parameter : Parameter
        What is varied (and how its value acts on the model's: set, add,
        scale).
    distribution : Distribution
        Values in SI units (a factor for ``scale``).
    """

    parameter: Parameter
    distribution: Distribution

    def describe(self) -> str:
        """Text such as ``"cart.centre.x = normal(0.36, 0.05)"``."""
        operator = {"set": "=", "add": "+=", "scale": "*="}[self.parameter.operation]
        return f"{self.parameter.name} {operator} {self.distribution.describe()}"


def draw_samples(
    variations: Sequence[Variation], count: int, seed: int = 0
) -> tuple[np.ndarray, ...]:
    """Draw ``count`` samples of every variation, one random stream each.

    Parameters
    ----------
    variations : sequence of Variation
    count : int
        Number of samples N.
    seed : int, optional
        Seed of the ``numpy.random.SeedSequence``.

    Returns
    -------
    tuple of numpy.ndarray
        Shape (N,) per variation, in order.
    """
    streams = np.random.SeedSequence(seed).spawn(len(variations))
    return tuple(
        variation.distribution.sample(np.random.default_rng(stream), count)
        for variation, stream in zip(variations, streams, strict=True)
    )


# --- intervals ----------------------------------------------------------------------------------


def _z(confidence: float) -> float:
    from scipy.stats import norm

    return float(norm.ppf(0.5 + confidence / 2.0))


def wilson_interval(successes, trials, confidence: float = 0.95) -> tuple[np.ndarray, np.ndarray]:
    """Wilson score interval of a binomial proportion.

    ``(p + z^2/2n +- z sqrt(p(1-p)/n + z^2/4n^2)) / (1 + z^2/n)`` with
    ``p = k/n`` (Wilson 1927; Brown, Cai & DasGupta 2001, Statist. Sci. 16,
    eq. 4). It is 1 at the top when every trial succeeds.

    Parameters
    ----------
    successes, trials : int or numpy.ndarray
        k and n (n > 0).
    confidence : float, optional
        Two-sided confidence level [-].

    Returns
    -------
    tuple of numpy.ndarray
        Lower and upper bounds [-].
    """
    k = np.asarray(successes, dtype=float)
    n = np.asarray(trials, dtype=float)
    z = _z(confidence)
    p = k / n
    denominator = 1.0 + z * z / n
    centre = (p + z * z / (2.0 * n)) / denominator
    half = z / denominator * np.sqrt(np.maximum(p * (1.0 - p) / n + z * z / (4.0 * n * n), 0.0))
    low = np.where(k <= 0, 0.0, np.clip(centre - half, 0.0, 1.0))
    high = np.where(k >= n, 1.0, np.clip(centre + half, 0.0, 1.0))
    return low, high


def clopper_pearson_interval(
    successes, trials, confidence: float = 0.95
) -> tuple[np.ndarray, np.ndarray]:
    """Clopper-Pearson ("exact") interval of a binomial proportion.

    Bounds from the beta distribution: ``B(alpha/2; k, n-k+1)`` and
    ``B(1-alpha/2; k+1, n-k)`` (Clopper & Pearson 1934, Biometrika 26).

    Parameters
    ----------
    successes, trials : int or numpy.ndarray
        k and n (n > 0).
    confidence : float, optional
        Two-sided confidence level [-].

    Returns
    -------
    tuple of numpy.ndarray
        Lower and upper bounds [-].
    """
    from scipy.stats import beta

    k = np.asarray(successes, dtype=float)
    n = np.asarray(trials, dtype=float)
    alpha = 1.0 - confidence
    with np.errstate(invalid="ignore"):
        low = np.where(k <= 0, 0.0, beta.ppf(alpha / 2.0, k, n - k + 1.0))
        high = np.where(k >= n, 1.0, beta.ppf(1.0 - alpha / 2.0, k + 1.0, n - k))
    return np.nan_to_num(low), np.nan_to_num(high, nan=1.0)


INTERVALS: dict[str, Callable] = {
    "wilson": wilson_interval,
    "clopper-pearson": clopper_pearson_interval,
}

# --- sweeps -------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Probability:
    """How often an outcome occurred, with its confidence interval.

    Attributes
    ----------
    outcome : str
        What occurred (a motion such as ``"slide"``, a joint state such as
        ``"bridge slides, cart rests"``, or a status).
    block : str or None
        The block, for a block's motion.
    count : int
        Samples with this outcome.
    total : int
        Samples considered (the valid ones).
    probability : float
        ``count / total`` [-].
    low, high : float
        Confidence interval [-].
    """

    outcome: str
    block: str | None
    count: int
    total: int
    probability: float
    low: float
    high: float


@dataclass(frozen=True)
class SweepCase:
    """The outcome of a sweep for one configuration, excitation and sense.

    Attributes
    ----------
    configuration, excitation : str
        Names.
    sense : int
        +1 or -1: sense of the horizontal inertial force.
    samples : int
        Samples drawn N.
    invalid : int
        Samples whose inputs make no model (e.g. a negative mass); left out
        of every probability.
    motions : tuple of Probability
        Probability of each initial motion of each block (outcome
        ``"no consistent state"`` where none exists).
    states : tuple of Probability
        Probability of each joint state (all blocks), most likely first.
    statuses : tuple of Probability
        Probability of each solver status (unique, ambiguous, inconsistent,
        free-flight); ambiguous cases count with their chosen state above.
    result : BatchResult
        Every sample's solution.
    """

    configuration: str
    excitation: str
    sense: int
    samples: int
    invalid: int
    motions: tuple[Probability, ...]
    states: tuple[Probability, ...]
    statuses: tuple[Probability, ...]
    result: BatchResult = field(repr=False)

    def probability(self, block: str, motion: str) -> Probability:
        """The probability that ``block`` starts with ``motion`` (e.g. ``"slide"``)."""
        for item in self.motions:
            if item.block == block and item.outcome == motion:
                return item
        raise KeyError((block, motion))


@dataclass(frozen=True)
class Sweep:
    """A Monte Carlo sweep over every requested case.

    Attributes
    ----------
    variations : tuple of Variation
    samples : tuple of numpy.ndarray
        The drawn values, one array per variation (same for every case).
    seed : int
    confidence : float
    interval : str
        ``"wilson"`` or ``"clopper-pearson"``.
    cases : tuple of SweepCase
    """

    variations: tuple[Variation, ...]
    samples: tuple[np.ndarray, ...] = field(repr=False)
    seed: int
    confidence: float
    interval: str
    cases: tuple[SweepCase, ...]


def _probabilities(items, total, interval, confidence) -> tuple[Probability, ...]:
    if not items:
        return ()
    counts = np.array([count for _, _, count in items])
    if total > 0:
        low, high = interval(counts, total, confidence)
    else:
        low = high = np.full(len(items), np.nan)
    return tuple(
        Probability(
            outcome=outcome,
            block=block,
            count=int(count),
            total=int(total),
            probability=float(count / total) if total else float("nan"),
            low=float(lo),
            high=float(hi),
        )
        for (outcome, block, count), lo, hi in zip(items, low, high, strict=True)
    )


def summarise(
    result: BatchResult,
    configuration: str,
    excitation: str,
    sense: int,
    confidence: float = 0.95,
    interval: str = "wilson",
) -> SweepCase:
    """Probabilities of the motions, joint states and statuses of a batch.

    Parameters
    ----------
    result : BatchResult
        One solution per sample.
    configuration, excitation : str
        Names for the report.
    sense : int
        +1 or -1.
    confidence : float, optional
        Two-sided confidence level [-].
    interval : str, optional
        ``"wilson"`` or ``"clopper-pearson"``.

    Returns
    -------
    SweepCase
    """
    method = INTERVALS[interval]
    valid = result.status != INVALID
    total = int(np.count_nonzero(valid))
    motions = []
    for b, name in enumerate(result.names):
        codes = result.motion[valid, b]
        for code, motion in enumerate(MOTIONS):
            count = int(np.count_nonzero(codes == code))
            if count:
                motions.append((motion.value, name, count))
        count = int(np.count_nonzero(codes < 0))
        if count:
            motions.append(("no consistent state", name, count))
    state_codes = result.state_codes()[valid]
    unique_codes, counts = np.unique(state_codes, return_counts=True)
    order = np.argsort(-counts, kind="stable")
    states = [(result.state_label(int(unique_codes[i])), None, int(counts[i])) for i in order]
    statuses = []
    for code in (0, AMBIGUOUS, INCONSISTENT, FREE_FLIGHT):
        count = int(np.count_nonzero(result.status[valid] == code))
        if count:
            statuses.append((STATUS_NAMES[code], None, count))
    return SweepCase(
        configuration=configuration,
        excitation=excitation,
        sense=sense,
        samples=result.count,
        invalid=result.count - total,
        motions=_probabilities(motions, total, method, confidence),
        states=_probabilities(states, total, method, confidence),
        statuses=_probabilities(statuses, total, method, confidence),
        result=result,
    )


def monte_carlo(
    stacks: Sequence[Stack],
    excitations: Sequence[Excitation],
    variations: Sequence[Variation],
    count: int,
    seed: int = 0,
    gravity: float = GRAVITY,
    senses: Sequence[int] = (1, -1),
    confidence: float = 0.95,
    interval: str = "wilson",
    progress: Callable[[int], None] | None = None,
) -> Sweep:
    """Monte Carlo sweep of the initial motion over uncertain inputs.

    Parameters
    ----------
    stacks : sequence of Stack
        Configurations.
    excitations : sequence of Excitation
        Excitation levels (their a_hor, a_ver are the nominal values that
        ``horizontal``/``vertical`` variations act on).
    variations : sequence of Variation
        Uncertain inputs. Kinetic friction is kept at or below static
        friction (:func:`freestand.core.contact.batch.case_inputs`).
    count : int
        Samples per case N.
    seed : int, optional
        Random seed; the same seed gives the same samples.
    gravity : float, optional
        g [m/s^2].
    senses : sequence of int, optional
        Senses of the horizontal inertial force.
    confidence : float, optional
        Two-sided confidence level of the intervals [-].
    interval : str, optional
        ``"wilson"`` (default) or ``"clopper-pearson"``.
    progress : callable, optional
        Called with the number of samples just solved.

    Returns
    -------
    Sweep
    """
    if count < 1:
        raise ValueError(f"count must be >= 1, not {count}")
    if interval not in INTERVALS:
        raise ValueError(f"interval must be one of {sorted(INTERVALS)}, not {interval!r}")
    samples = draw_samples(variations, count, seed)
    cases = []
    for stack in stacks:
        for excitation in excitations:
            for sense in senses:
                inputs = case_inputs(
                    stack,
                    excitation.horizontal,
                    excitation.vertical,
                    sense,
                    [(v.parameter, s) for v, s in zip(variations, samples, strict=True)],
                    count,
                )
                result = solve_batch(inputs, gravity, progress=progress)
                cases.append(
                    summarise(result, stack.name, excitation.name, sense, confidence, interval)
                )
    return Sweep(
        variations=tuple(variations),
        samples=samples,
        seed=seed,
        confidence=confidence,
        interval=interval,
        cases=tuple(cases),
    )
