"""Spectrum-compatible record generation: acceptance, reproducibility, baseline, seeds."""

from __future__ import annotations

import numpy as np
import pytest

from freestand.core.motion.design_spectra import en1998_spectrum, rg160_spectrum
from freestand.core.motion.ground_motion import GroundMotion, baseline_correct
from freestand.core.motion.response_spectrum import response_spectrum
from freestand.core.motion.spectrum_matching import (
    AcceptanceCriteria,
    MatchSettings,
    arias_intensity,
    correlation_matrix,
    generate_suite,
    significant_duration,
    zero_period_acceleration,
)
from freestand.core.motion.synthesis import draw_seed_parameters, seed_acceleration

G = 9.81

TARGETS = {
    "rg1.60 5%": lambda: rg160_spectrum(0.3 * G, 0.05),
    "rg1.60 2%": lambda: rg160_spectrum(0.3 * G, 0.02),
    "en1998 B 5%": lambda: en1998_spectrum(0.25 * G, "B", 1, 0.05),
    "en1998 C 2%": lambda: en1998_spectrum(0.25 * G, "C", 1, 0.02),
}


@pytest.fixture(scope="module", params=sorted(TARGETS))
def suite(request):
    target = TARGETS[request.param]()
    # short records and few of them keep the test fast; the checks are the full ones
    return target, generate_suite(target, count=3, duration=8.0, dt=0.005, seed=13)


def test_matching_meets_acceptance(suite):
    target, result = suite
    assert result.status == "accepted", result.failures
    criteria = AcceptanceCriteria()
    frequencies = criteria.frequencies()
    # 100 per decade from 0.2 to 50 Hz, both ends included
    assert frequencies[0] == pytest.approx(0.2) and frequencies[-1] == pytest.approx(50.0)
    assert frequencies.size == 241
    goal = target.acceleration_at(frequencies)
    spectra = []
    for record in result.horizontal.records:
        # recomputed here with the general spectrum function, not the matcher's own plan
        psa = response_spectrum(
            record.acceleration, record.dt, frequencies, target.damping
        ).acceleration
        spectra.append(psa)
        ratio = psa / goal
        assert ratio.min() >= 0.9 and ratio.max() <= 1.3
        pga = np.max(np.abs(record.acceleration))
        assert pga == pytest.approx(zero_period_acceleration(target), rel=0.05)
        assert record.check.duration_5_75 > 0.5
    assert np.all(np.mean(spectra, axis=0) >= goal)
    corr = np.abs(correlation_matrix([r.acceleration for r in result.horizontal.records]))
    np.fill_diagonal(corr, 0.0)
    assert corr.max() < 0.3


def test_baseline_corrected_motion_ends_at_rest(suite):
    _, result = suite
    for record in result.horizontal.records:
        motion = GroundMotion(record.dt, record.acceleration)
        velocity = motion.velocity()
        displacement = motion.displacement()
        # end values against the peaks: round-off only
        assert abs(velocity[-1]) < 1e-9 * np.max(np.abs(velocity))
        assert abs(displacement[-1]) < 1e-9 * np.max(np.abs(displacement))
        # the support starts and ends at rest: no jump in acceleration at either end
        assert record.acceleration[0] == 0.0 and record.acceleration[-1] == 0.0


def test_same_seed_same_suite_other_seed_other_suite():
    target = rg160_spectrum(0.2 * G, 0.05)
    a = generate_suite(target, count=2, duration=6.0, seed=5)
    b = generate_suite(target, count=2, duration=6.0, seed=5)
    c = generate_suite(target, count=2, duration=6.0, seed=6)
    for x, y in zip(a.horizontal.records, b.horizontal.records, strict=True):
        assert x.acceleration.tobytes() == y.acceleration.tobytes()
    assert not np.allclose(
        a.horizontal.records[0].acceleration, c.horizontal.records[0].acceleration
    )


def test_vertical_components_are_matched_to_their_target():
    horizontal = rg160_spectrum(0.3 * G, 0.05)
    vertical = rg160_spectrum(0.3 * G, 0.05, "vertical")
    result = generate_suite(horizontal, count=2, duration=8.0, seed=3, vertical_target=vertical)
    assert result.status == "accepted", result.failures
    assert result.vertical is not None and len(result.vertical.records) == 2
    assert result.vertical.mean_ratio_min >= 1.0


def test_baseline_correct_zeroes_final_velocity_and_displacement():
    rng = np.random.default_rng(0)
    dt = 0.01
    t = np.arange(1001) * dt
    weight = np.sin(np.pi * t / t[-1]) ** 2
    a = rng.standard_normal(t.size) * weight + 0.05
    corrected = baseline_correct(a, dt, weight)
    motion = GroundMotion(dt, corrected)
    assert abs(motion.velocity()[-1]) < 1e-12
    assert abs(motion.displacement()[-1]) < 1e-12


def test_seed_model_is_nonstationary_and_reproducible():
    n, dt = 4001, 0.005
    rng = np.random.default_rng(np.random.SeedSequence([1, 0, 0, 0]))
    parameters = draw_seed_parameters(rng, 20.0)
    x = seed_acceleration(parameters, n, dt, rng)
    rng = np.random.default_rng(np.random.SeedSequence([1, 0, 0, 0]))
    draw_seed_parameters(rng, 20.0)
    assert np.array_equal(x, seed_acceleration(parameters, n, dt, rng))
    # the envelope: quiet start, strong middle, decaying end
    t = np.arange(n) * dt
    peak_time = (parameters.alpha2 - 1) / parameters.alpha3
    strong = np.abs(t - peak_time) < 2.0
    assert np.std(x[strong]) > 3 * np.std(x[:40])
    # the frequency content softens with time (f' < 0): zero crossings per second fall
    first, last = x[(t > 1) & (t < 8)], x[(t > 12) & (t < 19)]
    crossings = [np.count_nonzero(np.diff(np.sign(part)) != 0) for part in (first, last)]
    assert parameters.frequency_slope <= 0
    assert crossings[1] <= crossings[0] * 1.1


def test_arias_intensity_and_duration_of_a_constant_record():
    dt = 0.01
    a = np.ones(1001)  # 10 s of 1 m/s^2: I_a = pi / (2 g) * 10
    cumulative = arias_intensity(a, dt, gravity=G)
    assert cumulative[-1] == pytest.approx(np.pi / (2 * G) * 10.0)
    assert significant_duration(a, dt) == pytest.approx(0.70 * 10.0, rel=1e-9)


def test_generate_rejects_a_step_too_coarse_for_50_hz():
    with pytest.raises(ValueError, match="dt"):
        generate_suite(rg160_spectrum(3.0), count=1, duration=4.0, dt=0.02)


THREE_COMPONENT_TARGETS = {
    "rg1.60": lambda: (rg160_spectrum(0.3 * G, 0.05), rg160_spectrum(0.3 * G, 0.05, "vertical")),
    "en1998": lambda: (
        en1998_spectrum(0.25 * G, "B", 1, 0.05),
        en1998_spectrum(0.25 * G, "B", 1, 0.05, "vertical"),
    ),
}


@pytest.mark.parametrize("name", sorted(THREE_COMPONENT_TARGETS))
def test_three_component_suites_meet_every_check(name):
    horizontal, vertical = THREE_COMPONENT_TARGETS[name]()
    # two records of 8 s keep the test to about a second; the checks are the full ones
    result = generate_suite(
        horizontal, count=2, duration=8.0, seed=11, vertical_target=vertical,
        horizontal_y_target=horizontal,
    )  # fmt: skip
    assert result.status == "accepted", result.failures
    assert [c.direction for c in result.components] == ["horizontal", "horizontal_y", "vertical"]
    frequencies = AcceptanceCriteria().frequencies()
    for component in result.components:
        goal = component.target.acceleration_at(frequencies)
        spectra = []
        for record in component.records:
            # every check recomputed with the general spectrum function
            psa = response_spectrum(
                record.acceleration, record.dt, frequencies, component.target.damping
            ).acceleration
            spectra.append(psa)
            assert (psa / goal).min() >= 0.9 and (psa / goal).max() <= 1.3, component.direction
            pga = np.max(np.abs(record.acceleration))
            assert pga == pytest.approx(zero_period_acceleration(component.target), rel=0.05)
            assert record.check.duration_5_75 > 0.5
        assert np.all(np.mean(spectra, axis=0) >= goal), component.direction
    # independence (SRP 3.7.1): every pair of components of a record below 0.3
    independence = result.component_correlations()
    for index, record in enumerate(independence):
        histories = [c.records[index].acceleration for c in result.components]
        corr = np.abs(np.corrcoef(histories))
        assert set(record["pairs"]) == {
            "horizontal-horizontal_y", "horizontal-vertical", "horizontal_y-vertical"
        }  # fmt: skip
        assert record["pairs"]["horizontal-horizontal_y"] == pytest.approx(corr[0, 1])
        assert record["max"] == pytest.approx(np.max(corr[np.triu_indices(3, 1)]))
        assert record["max"] < 0.3
    assert max(r["max"] for r in independence) <= result.max_correlation < 0.3
    assert all(label[-1] in "XYV" for label in result.max_correlation_pair)


def test_the_second_horizontal_component_has_its_own_seeds():
    horizontal = rg160_spectrum(0.3 * G, 0.05)
    result = generate_suite(
        horizontal, count=1, duration=6.0, seed=2, horizontal_y_target=horizontal
    )
    x = result.horizontal.records[0]
    y = result.horizontal_y.records[0]
    assert x.seed_parameters != y.seed_parameters
    assert abs(np.corrcoef(x.acceleration, y.acceleration)[0, 1]) < 0.3
    assert result.vertical is None and result.count == 1
    assert result.component_correlations()[0]["pairs"].keys() == {"horizontal-horizontal_y"}


def test_components_that_are_not_independent_fail_the_srp_check():
    horizontal = rg160_spectrum(0.3 * G, 0.05)
    # a limit no independent pair of 6 s records meets: the check must fail, naming the
    # record, the pair and SRP 3.7.1, and the suite must say "failed"
    criteria = AcceptanceCriteria(max_correlation=0.002)
    settings = MatchSettings(max_attempts=1)
    result = generate_suite(
        horizontal, count=1, duration=6.0, seed=2, horizontal_y_target=horizontal,
        criteria=criteria, settings=settings,
    )  # fmt: skip
    largest = result.component_correlations()[0]["max"]
    assert largest >= 0.002
    assert result.status == "failed"
    message = [f for f in result.failures if "SRP 3.7.1" in f]
    assert message == [
        "record 1: components horizontal and horizontal_y are not independent (SRP 3.7.1): "
        f"correlation coefficient {largest:.3f} (must be below 0.002)"
    ]
    # one record: no pair of different records, so no message about two records
    assert not any(f.startswith("records ") for f in result.failures)
