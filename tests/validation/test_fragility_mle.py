"""Fragility validation (b): the maximum-likelihood fit recovers a known lognormal.

Counts are drawn from a known fragility (median 2.0, beta 0.4) at stripes of
20 trials (Baker 2015, Earthquake Spectra 31(1), the binomial likelihood of
eq. 11). Over many repetitions the estimates centre on the truth and the
bootstrap percentile intervals cover it about as often as their nominal
95 %.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import minimize
from scipy.stats import norm

from freestand.core.sweeps.fragility.fit import Z05, fit_cloud, fit_fragility

THETA, BETA = 2.0, 0.4
LEVELS = np.linspace(0.5, 5.0, 10)
TRIALS = np.full(LEVELS.size, 20)


def _counts(rng):
    return rng.binomial(TRIALS, norm.cdf(np.log(LEVELS / THETA) / BETA))


def test_estimate_is_the_maximum_of_the_binomial_likelihood():
    counts = _counts(np.random.default_rng(1))
    fit = fit_fragility(LEVELS, counts, TRIALS, bootstrap=0)

    def negative(q):
        p = np.clip(norm.cdf(np.log(LEVELS / np.exp(q[0])) / np.exp(q[1])), 1e-300, 1 - 1e-16)
        return -(counts * np.log(p) + (TRIALS - counts) * np.log(1 - p)).sum()

    best = minimize(negative, [0.0, np.log(0.5)], method="Nelder-Mead",
                    options={"xatol": 1e-10, "fatol": 1e-12, "maxiter": 4000})  # fmt: skip
    # Fisher scoring and a general optimiser reach the same maximum
    assert fit.median == pytest.approx(np.exp(best.x[0]), rel=1e-6)
    assert fit.beta == pytest.approx(np.exp(best.x[1]), rel=1e-6)
    assert fit.log_likelihood == pytest.approx(-best.fun, abs=1e-8)
    assert fit.quantile05 == pytest.approx(fit.median * np.exp(Z05 * fit.beta))


def test_estimates_centre_on_the_truth_and_intervals_cover_it():
    rng = np.random.default_rng(2015)
    repetitions = 200
    medians, betas = [], []
    cover_median = cover_beta = cover_q05 = 0
    q05_true = THETA * np.exp(Z05 * BETA)
    for repetition in range(repetitions):
        fit = fit_fragility(LEVELS, _counts(rng), TRIALS, bootstrap=400, seed=repetition)
        assert fit.fitted
        medians.append(np.log(fit.median))
        betas.append(fit.beta)
        cover_median += fit.median_interval[0] <= THETA <= fit.median_interval[1]
        cover_beta += fit.beta_interval[0] <= BETA <= fit.beta_interval[1]
        cover_q05 += fit.hclpf <= q05_true
    medians, betas = np.array(medians), np.array(betas)
    # unbiased median within 3 standard errors of the mean; beta's MLE is
    # biased low by a few percent at 200 trials (Baker 2015, Fig. 4): 10 %
    assert abs(medians.mean() - np.log(THETA)) < 3 * medians.std() / np.sqrt(repetitions)
    assert abs(betas.mean() / BETA - 1) < 0.10
    # coverage of the nominal 95 % intervals: binomial standard error 1.5 %
    # at 200 repetitions; percentile-bootstrap intervals run a little short
    # for small samples, so accept 88 % to 99 %
    assert 0.88 <= cover_median / repetitions <= 0.99
    assert 0.85 <= cover_beta / repetitions <= 0.99
    # HCLPF: a one-sided 95 % lower bound of the 5 % quantile
    assert 0.88 <= cover_q05 / repetitions <= 1.0


def test_cloud_fit_recovers_the_fragility():
    rng = np.random.default_rng(7)
    im = np.exp(rng.normal(np.log(THETA), 0.7, 2000))
    occurred = rng.random(im.size) < norm.cdf(np.log(im / THETA) / BETA)
    fit = fit_cloud(im, occurred, bootstrap=300, seed=1)
    assert fit.method == "cloud"
    assert fit.median_interval[0] < THETA < fit.median_interval[1]
    assert fit.beta_interval[0] < BETA < fit.beta_interval[1]


def test_degenerate_outcomes_are_reported_not_fitted():
    never = fit_fragility(LEVELS, np.zeros(10), TRIALS, unit="m/s^2")
    always = fit_fragility(LEVELS, TRIALS, TRIALS)
    step = fit_fragility(LEVELS, np.where(LEVELS > 2.4, TRIALS, 0), TRIALS)
    assert not never.fitted and "never occurred" in never.reason and "m/s^2" in never.reason
    assert not always.fitted and "every simulation" in always.reason
    assert not step.fitted and "stripes separate" in step.reason
    assert np.isnan(never.median) and np.isnan(step.beta)
    # seen only in part of the highest stripe: the median lies above every level
    top = fit_fragility(LEVELS, np.where(LEVELS == LEVELS.max(), 3, 0), TRIALS, unit="m/s^2")
    assert not top.fitted and "only at the highest level" in top.reason
    assert "add higher levels" in top.reason and "above" in top.reason
    # the stripe fractions and their Wilson intervals are still given
    assert always.fraction.tolist() == [1.0] * 10 and (always.fraction_low > 0.8).all()
