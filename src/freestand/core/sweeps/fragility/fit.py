"""Lognormal fragility functions fitted by maximum likelihood.

A fragility function gives the probability that an outcome (a damage state)
occurs at an intensity measure level x:

    P(x) = Phi(ln(x / theta) / beta)

with median theta [IM unit] and logarithmic standard deviation beta [-]
(Baker 2015, eq. 1). It is a probit model, ``P = Phi(a + b ln x)`` with
``b = 1 / beta`` and ``a = -ln(theta) / beta``, fitted here by maximising the
binomial likelihood of the counts z_j of n_j trials at each level x_j
(Baker 2015, eqs. 10-11; multiple-stripe analysis):

    ln L = sum_j [z_j ln P(x_j) + (n_j - z_j) ln(1 - P(x_j))]

A cloud analysis (every simulation at its own intensity) is the same
likelihood with n_j = 1 per simulation.

The maximum is found by Fisher scoring (iteratively reweighted least squares
of the probit model), vectorised over bootstrap replicates. Confidence
intervals of theta and beta are percentile intervals of a bootstrap that
resamples the trials within each stripe (binomial counts with the observed
fractions; for a cloud, the simulations). The HCLPF capacity (high
confidence of a low probability of failure) is the lower ``confidence``
bootstrap percentile of the 5 % quantile ``theta exp(-1.645 beta)``: the
intensity at which, with 95 % confidence, the probability of the outcome is
at most 5 % (the definition of EPRI NP-6041 and ASCE 43, estimated from the
sample instead of from assumed beta_r and beta_u).

Outcomes that occur in no trial or in every trial, or whose stripes separate
perfectly (all trials below some level fail to occur, all above occur), have
no maximum-likelihood estimate (beta -> 0 or the median unbounded): they are
reported as such, with the reason, and not fitted.

References
----------
.. [1] J. W. Baker, "Efficient analytical fragility function fitting using
   dynamic structural analysis", Earthquake Spectra 31(1), 579-599, 2015.
.. [2] R. P. Kennedy, M. K. Ravindra, "Seismic fragilities for nuclear power
   plant risk studies", Nucl. Eng. Des. 79, 47-68, 1984 (HCLPF).
.. [3] B. Efron, R. J. Tibshirani, An Introduction to the Bootstrap, 1993
   (percentile intervals).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.special import log_ndtr, ndtr, ndtri

from freestand.core.sweeps.sampling import wilson_interval

#: beta is kept in [BETA_MIN, BETA_MAX] by the optimiser [-]: a replicate
#: whose stripes separate perfectly converges to BETA_MIN (a step function).
BETA_MIN = 1e-3
BETA_MAX = 20.0

#: z of the 5 % quantile of the standard normal distribution [-].
Z05 = float(ndtri(0.05))


@dataclass(frozen=True)
class Fragility:
    """A fitted (or unfittable) fragility function of one outcome.

    Attributes
    ----------
    levels : numpy.ndarray
        Intensity levels x_j [IM unit] (stripes; for a cloud, the distinct
        intensities of the simulations, sorted).
    counts, totals : numpy.ndarray
        Trials z_j in which the outcome occurred, and trials n_j, per level.
    fraction : numpy.ndarray
        z_j / n_j [-] (NaN where n_j = 0).
    fraction_low, fraction_high : numpy.ndarray
        Wilson interval of the fraction at ``confidence`` [-].
    fitted : bool
        Whether theta and beta were estimated.
    reason : str
        Why not, in words (empty when fitted).
    median, beta : float
        theta [IM unit] and beta [-]; NaN when not fitted.
    median_interval, beta_interval : tuple of float
        Bootstrap percentile intervals at ``confidence``; NaN when not fitted.
    quantile05 : float
        ``theta exp(-1.645 beta)`` [IM unit]: the intensity of 5 % probability.
    hclpf : float
        Lower ``confidence`` bootstrap bound of ``quantile05`` [IM unit].
    log_likelihood : float
        ln L at the estimate.
    bootstrap : int
        Bootstrap replicates used.
    confidence : float
        Confidence level of the intervals [-].
    method : str
        ``"stripes"`` or ``"cloud"``.
    replicates : numpy.ndarray
        Shape (R, 2): (theta, beta) of every bootstrap replicate.
    """

    levels: np.ndarray
    counts: np.ndarray
    totals: np.ndarray
    fraction: np.ndarray
    fraction_low: np.ndarray
    fraction_high: np.ndarray
    fitted: bool
    reason: str
    median: float
    beta: float
    median_interval: tuple[float, float]
    beta_interval: tuple[float, float]
    quantile05: float
    hclpf: float
    log_likelihood: float
    bootstrap: int
    confidence: float
    method: str
    replicates: np.ndarray

    def probability(self, level) -> np.ndarray:
        """P(x) = Phi(ln(x / theta) / beta) [-] at ``level`` (NaN when not fitted)."""
        x = np.asarray(level, dtype=float)
        if not self.fitted:
            return np.full(x.shape, np.nan)
        with np.errstate(divide="ignore"):
            return ndtr(np.log(x / self.median) / self.beta)

    def band(self, level, confidence: float | None = None) -> tuple[np.ndarray, np.ndarray]:
        """Pointwise bootstrap band of P(x) at ``level`` (percentiles of the replicates)."""
        x = np.atleast_1d(np.asarray(level, dtype=float))
        if not self.fitted or self.replicates.size == 0:
            nan = np.full(x.shape, np.nan)
            return nan, nan
        level_of = self.confidence if confidence is None else confidence
        theta = self.replicates[:, 0:1]
        beta = self.replicates[:, 1:2]
        with np.errstate(divide="ignore"):
            curves = ndtr(np.log(x[None, :] / theta) / beta)
        tail = 50.0 * (1.0 - level_of)
        return np.percentile(curves, tail, axis=0), np.percentile(curves, 100.0 - tail, axis=0)


def _start(x: np.ndarray, z: np.ndarray, n: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Probit regression on the smoothed fractions (weighted least squares): (a, b) per row."""
    p = (z + 0.5) / (n + 1.0)
    y = ndtri(p)
    w = n + 1e-12
    sw = w.sum(axis=-1)
    mx = (w * x).sum(axis=-1) / sw
    my = (w * y).sum(axis=-1) / sw
    sxx = (w * (x - mx[..., None]) ** 2).sum(axis=-1)
    sxy = (w * (x - mx[..., None]) * (y - my[..., None])).sum(axis=-1)
    b = np.where(sxx > 0, sxy / np.where(sxx > 0, sxx, 1.0), 1.0)
    b = np.clip(b, 1.0 / BETA_MAX, 1.0 / BETA_MIN)
    a = my - b * mx
    return a, b


def _log_likelihood(a, b, x, z, n) -> np.ndarray:
    eta = a[..., None] + b[..., None] * x
    return (z * log_ndtr(eta) + (n - z) * log_ndtr(-eta)).sum(axis=-1)


def probit_mle(
    x: np.ndarray, z: np.ndarray, n: np.ndarray, iterations: int = 100
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Maximum-likelihood probit fit ``P = Phi(a + b x)``, vectorised over rows.

    Parameters
    ----------
    x : numpy.ndarray
        Shape (J,) or (R, J): ln of the intensity levels.
    z, n : numpy.ndarray
        Shape (R, J) or (J,): occurrences and trials per level (n may be 0).
    iterations : int, optional
        Largest number of Fisher-scoring steps.

    Returns
    -------
    tuple of numpy.ndarray
        a, b (shape (R,) or scalar arrays) and ln L. b is kept in
        [1 / BETA_MAX, 1 / BETA_MIN].

    Notes
    -----
    Fisher scoring: with eta = a + b x, the score of eta_j is
    ``z_j lambda(eta_j) - (n_j - z_j) lambda(-eta_j)`` and its expected
    information ``n_j lambda(eta_j) lambda(-eta_j)``, lambda = phi / Phi the
    inverse Mills ratio. Each step solves the 2 x 2 normal equations; a step
    that lowers ln L is halved (up to 30 times).
    """
    x = np.asarray(x, dtype=float)
    z = np.asarray(z, dtype=float)
    n = np.asarray(n, dtype=float)
    single = z.ndim == 1
    z2 = np.atleast_2d(z)
    n2 = np.atleast_2d(n)
    x2 = np.broadcast_to(np.atleast_2d(x), z2.shape)
    a, b = _start(x2, z2, n2)
    ll = _log_likelihood(a, b, x2, z2, n2)
    b_low, b_high = 1.0 / BETA_MAX, 1.0 / BETA_MIN
    log_2pi = 0.5 * math.log(2.0 * math.pi)
    for _ in range(iterations):
        eta = a[:, None] + b[:, None] * x2
        log_pdf = -0.5 * eta * eta - log_2pi
        lam_plus = np.exp(log_pdf - log_ndtr(eta))
        lam_minus = np.exp(log_pdf - log_ndtr(-eta))
        score = z2 * lam_plus - (n2 - z2) * lam_minus
        weight = n2 * lam_plus * lam_minus
        g0 = score.sum(axis=1)
        g1 = (score * x2).sum(axis=1)
        i00 = weight.sum(axis=1)
        i01 = (weight * x2).sum(axis=1)
        i11 = (weight * x2 * x2).sum(axis=1)
        det = i00 * i11 - i01 * i01
        ok = det > 1e-300 * (np.abs(i00 * i11) + 1e-300)
        safe = np.where(ok, det, 1.0)
        da = np.where(ok, (i11 * g0 - i01 * g1) / safe, 0.0)
        db = np.where(ok, (i00 * g1 - i01 * g0) / safe, 0.0)
        step = np.ones_like(a)
        new_a, new_b = a + da, np.clip(b + db, b_low, b_high)
        new_ll = _log_likelihood(new_a, new_b, x2, z2, n2)
        for _halving in range(30):
            worse = ~(new_ll >= ll - 1e-12 * np.abs(ll))
            if not worse.any():
                break
            step = np.where(worse, 0.5 * step, step)
            new_a = a + step * da
            new_b = np.clip(b + step * db, b_low, b_high)
            new_ll = np.where(worse, _log_likelihood(new_a, new_b, x2, z2, n2), new_ll)
        better = new_ll >= ll - 1e-12 * np.abs(ll)
        change = np.abs(new_a - a) + np.abs(new_b - b)
        a = np.where(better, new_a, a)
        b = np.where(better, new_b, b)
        ll = np.where(better, new_ll, ll)
        if np.all(change <= 1e-10 * (1.0 + np.abs(a) + np.abs(b))):
            break
    if single:
        return a[0], b[0], ll[0]
    return a, b, ll


def _to_median_beta(a, b, x_scale: float):
    beta = 1.0 / b
    median = np.exp(-a / b + x_scale)
    return median, beta


def _percentile_interval(values: np.ndarray, confidence: float) -> tuple[float, float]:
    tail = 50.0 * (1.0 - confidence)
    values = values[np.isfinite(values)]
    if values.size == 0:
        return math.nan, math.nan
    low, high = np.percentile(values, [tail, 100.0 - tail])
    return float(low), float(high)


def _not_fitted(levels, counts, totals, low, high, reason, confidence, method, bootstrap):
    fraction = np.where(totals > 0, counts / np.where(totals > 0, totals, 1), np.nan)
    nan = (math.nan, math.nan)
    return Fragility(
        levels, counts, totals, fraction, low, high, False, reason, math.nan, math.nan,
        nan, nan, math.nan, math.nan, math.nan, bootstrap, confidence, method, np.empty((0, 2)),
    )  # fmt: skip


def _u(unit: str) -> str:
    return f" {unit}" if unit else ""


def _degenerate(levels, counts, totals, unit: str) -> str:
    """The reason a stripe data set has no MLE, or ''."""
    used = totals > 0
    z, n, x = counts[used], totals[used], levels[used]
    if n.sum() == 0:
        return "no valid simulation"
    if z.sum() == 0:
        return f"never occurred ({int(n.sum())} simulations, up to {x.max():.4g}{_u(unit)})"
    if np.all(z == n):
        return f"occurred in every simulation ({int(n.sum())}, from {x.min():.4g}{_u(unit)})"
    order = np.argsort(x, kind="stable")
    z, n, x = z[order], n[order], x[order]
    # a finite MLE needs overlap: an occurrence at some level below a level with
    # a non-occurrence; otherwise the data are (quasi-)separated and beta -> 0
    first_hit = x[np.flatnonzero(z > 0)[0]]
    last_miss = x[np.flatnonzero(z < n)[-1]]
    if not first_hit < last_miss and last_miss == x[-1]:
        top = int(z[-1]), int(n[-1])
        return (
            f"it occurs only at the highest level, {last_miss:.4g}{_u(unit)} ({top[0]} of "
            f"{top[1]}): the median lies above it and beta cannot be estimated; add higher levels"
        )
    if not first_hit < last_miss:
        return (
            f"the stripes separate (it occurs at no level below {first_hit:.4g}{_u(unit)} "
            f"and in every simulation above {last_miss:.4g}{_u(unit)}): the median lies "
            "there and beta cannot be estimated; add levels or records in between"
        )
    return ""


def fit_fragility(
    levels,
    counts,
    totals,
    *,
    bootstrap: int = 1000,
    confidence: float = 0.95,
    seed: int = 0,
    unit: str = "",
    method: str = "stripes",
) -> Fragility:
    """Fit a lognormal fragility function to stripe counts by maximum likelihood.

    Parameters
    ----------
    levels : array_like
        Intensity levels x_j > 0 [IM unit].
    counts, totals : array_like
        z_j occurrences in n_j trials at each level.
    bootstrap : int, optional
        Bootstrap replicates for the intervals and the HCLPF (0 for none).
    confidence : float, optional
        Two-sided confidence level of the intervals [-]; the HCLPF is the
        one-sided lower bound at this level.
    seed : int, optional
        Seed of the bootstrap (``numpy.random.SeedSequence``).
    unit : str, optional
        IM unit, for the reasons given in words.
    method : str, optional
        ``"stripes"`` (bootstrap: binomial resampling within each stripe) or
        ``"cloud"`` (one trial per level; bootstrap: the trials resampled).

    Returns
    -------
    Fragility
    """
    x_levels = np.asarray(levels, dtype=float)
    z = np.asarray(counts, dtype=float)
    n = np.asarray(totals, dtype=float)
    if not (x_levels.shape == z.shape == n.shape) or x_levels.ndim != 1:
        raise ValueError("levels, counts and totals must be 1-D arrays of the same length")
    if np.any(~(x_levels > 0)) or np.any(z < 0) or np.any(z > n):
        raise ValueError("levels must be positive and 0 <= counts <= totals")
    with np.errstate(invalid="ignore", divide="ignore"):
        low, high = wilson_interval(z, np.where(n > 0, n, 1), confidence)
    low = np.where(n > 0, low, np.nan)
    high = np.where(n > 0, high, np.nan)
    counts_i = z.astype(np.int64)
    totals_i = n.astype(np.int64)
    reason = _degenerate(x_levels, z, n, unit)
    if reason:
        return _not_fitted(
            x_levels, counts_i, totals_i, low, high, reason, confidence, method, bootstrap
        )
    # centre ln x for a well-conditioned fit
    logs = np.log(x_levels)
    used = n > 0
    centre = float(np.average(logs[used], weights=n[used]))
    xc = logs - centre
    a, b, ll = probit_mle(xc, z, n)
    median, beta = _to_median_beta(float(a), float(b), centre)
    if b >= 1.0 / BETA_MIN * (1.0 - 1e-9):
        return _not_fitted(
            x_levels, counts_i, totals_i, low, high,
            "beta tends to zero (the data are a step in the intensity); add levels near "
            f"{median:.4g}{_u(unit)}", confidence, method, bootstrap,
        )  # fmt: skip
    if b <= 1.0 / BETA_MAX * (1.0 + 1e-9):
        return _not_fitted(
            x_levels, counts_i, totals_i, low, high,
            "the fraction does not increase with the intensity over these levels (beta "
            f"beyond {BETA_MAX:g}); a lognormal fragility does not describe it",
            confidence, method, bootstrap,
        )  # fmt: skip
    replicates = np.empty((0, 2))
    median_interval = beta_interval = (math.nan, math.nan)
    hclpf = math.nan
    if bootstrap > 0:
        rng = np.random.default_rng(np.random.SeedSequence(seed))
        if method == "cloud":
            weights = rng.multinomial(int(n.sum()), n / n.sum(), size=bootstrap).astype(float)
            fractions = np.where(n > 0, z / np.where(n > 0, n, 1.0), 0.0)
            z_star = rng.binomial(weights.astype(np.int64), fractions[None, :]).astype(float)
            n_star = weights
        else:
            fractions = np.where(n > 0, z / np.where(n > 0, n, 1.0), 0.0)
            z_star = rng.binomial(totals_i[None, :], fractions[None, :], size=(bootstrap, n.size))
            z_star = z_star.astype(float)
            n_star = np.broadcast_to(n, z_star.shape)
        a_star, b_star, _ = probit_mle(xc, z_star, n_star)
        theta_star, beta_star = _to_median_beta(a_star, b_star, centre)
        replicates = np.column_stack([theta_star, beta_star])
        median_interval = _percentile_interval(theta_star, confidence)
        beta_interval = _percentile_interval(beta_star, confidence)
        q05 = theta_star * np.exp(Z05 * beta_star)
        q05 = q05[np.isfinite(q05)]
        hclpf = float(np.percentile(q05, 100.0 * (1.0 - confidence))) if q05.size else math.nan
    fraction = np.where(n > 0, z / np.where(n > 0, n, 1.0), np.nan)
    return Fragility(
        levels=x_levels,
        counts=counts_i,
        totals=totals_i,
        fraction=fraction,
        fraction_low=low,
        fraction_high=high,
        fitted=True,
        reason="",
        median=float(median),
        beta=float(beta),
        median_interval=median_interval,
        beta_interval=beta_interval,
        quantile05=float(median * math.exp(Z05 * beta)),
        hclpf=hclpf,
        log_likelihood=float(ll),
        bootstrap=int(bootstrap),
        confidence=float(confidence),
        method=method,
        replicates=replicates,
    )


def fit_cloud(
    intensities, occurred, *, bootstrap: int = 1000, confidence: float = 0.95, seed: int = 0,
    unit: str = "",
) -> Fragility:  # fmt: skip
    """Fit a lognormal fragility to a cloud: one simulation per (positive) intensity.

    Parameters
    ----------
    intensities : array_like
        IM of every simulation x_i > 0 [IM unit].
    occurred : array_like of bool
        Whether the outcome occurred in simulation i.
    bootstrap, confidence, seed, unit
        As for :func:`fit_fragility`.

    Returns
    -------
    Fragility
        With one "level" per distinct intensity (occurrences and trials
        pooled there); the bootstrap resamples the simulations.
    """
    x = np.asarray(intensities, dtype=float)
    y = np.asarray(occurred, dtype=bool)
    levels, inverse = np.unique(x, return_inverse=True)
    counts = np.bincount(inverse, weights=y.astype(float), minlength=levels.size)
    totals = np.bincount(inverse, minlength=levels.size).astype(float)
    return fit_fragility(
        levels, counts, totals, bootstrap=bootstrap, confidence=confidence, seed=seed,
        unit=unit, method="cloud",
    )  # fmt: skip
