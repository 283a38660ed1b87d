"""Intensity of two horizontal components: geometric mean, RotD50, RotD100 (Boore 2010)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.model import Block, Friction, Sliding, Stack
from freestand.core.motion.ground_motion import GroundMotion, synthetic_acceleration
from freestand.core.motion.response_spectrum import spectral_response
from freestand.core.motion.rotd import rotation_angles
from freestand.core.sweeps.fragility.intensity import (
    KINDS,
    TWO_COMPONENT_KINDS,
    IntensityMeasure,
    intensity,
)
from freestand.errors import FreestandError
from freestand.io.fragility_options import parse_intensity

BLOCK = Block("block", 500.0, 266.6666666666667, (0.0, 1.2), -0.4, 0.4, 0.0,
              Friction(2.0, 2.0), Sliding.NONE)  # fmt: skip
STACK = Stack("block", (BLOCK,))


def _pair(seed: int = 5, duration: float = 6.0, dt: float = 0.01) -> GroundMotion:
    """Two correlated synthetic components (a record whose axes are not principal)."""
    common = dict(duration=duration, dt=dt, ground_damping=0.6)
    x = synthetic_acceleration(peak=3.0, seed=seed, ground_frequency=2.0, **common)
    other = synthetic_acceleration(peak=2.0, seed=seed + 1, ground_frequency=4.0, **common)
    return GroundMotion(dt, x, name="pair", horizontal_y=0.5 * x + other)


PAIR = _pair()


def _brute_force_peaks(motion: GroundMotion, base: str, frequency=None, damping=0.05):
    """The peak of each rotated series, rotated sample by sample at 1-degree steps.

    Boore (2010) takes the non-redundant angles 0-179 deg at 1-degree steps;
    each rotated series is built on its own and passed to the one-component
    measures (PGA of the samples, PGV integrated from rest, the exact spectrum).
    """
    peaks = []
    for degrees in range(180):
        theta = np.deg2rad(degrees)
        rotated = GroundMotion(
            motion.dt, np.cos(theta) * motion.horizontal + np.sin(theta) * motion.horizontal_y
        )
        if base == "pga":
            peaks.append(np.max(np.abs(rotated.horizontal)))
        elif base == "pgv":
            peaks.append(np.max(np.abs(rotated.velocity())))
        else:
            response = spectral_response(rotated, None, [frequency], damping)
            peaks.append(response.pseudo_acceleration[0])
    return np.array(peaks)


@pytest.mark.parametrize(
    ("base", "frequency", "damping"),
    [("pga", None, 0.05), ("pgv", None, 0.05), ("sa", 0.4, 0.05), ("sa", 2.5, 0.02),
     ("sa", 40.0, 0.05)],
)  # fmt: skip
def test_rotd_against_a_brute_force_rotation(base, frequency, damping):
    peaks = _brute_force_peaks(PAIR, base, frequency, damping)
    for combination, expected in (("rotd50", np.median(peaks)), ("rotd100", np.max(peaks))):
        measure = IntensityMeasure(f"{base}-{combination}", frequency=frequency, damping=damping)
        # the responses of x and y combined per angle equal the response of the rotated
        # series (linearity): round-off only; 1e-6 relative as the issue asks
        assert intensity(PAIR, measure, STACK) == pytest.approx(expected, rel=1e-6)


def test_rotd_bounds_and_the_geometric_mean():
    for base, frequency in (("pga", None), ("pgv", None), ("sa", 2.5)):
        values = {
            combination: intensity(PAIR, IntensityMeasure(f"{base}-{combination}", frequency),
                                   STACK)
            for combination in ("gm", "rotd50", "rotd100")
        }  # fmt: skip
        one = IntensityMeasure(base, frequency)
        x = intensity(PAIR, one, STACK)
        y = intensity(GroundMotion(PAIR.dt, PAIR.horizontal_y), one, STACK)
        assert values["gm"] == pytest.approx(np.sqrt(x * y), rel=1e-12)
        # RotD100 is at least either component's value (angles 0 and 90 deg are among
        # the angles); RotD50 at most RotD100
        assert values["rotd100"] >= max(x, y) * (1 - 1e-12)
        assert values["rotd50"] <= values["rotd100"]


def test_one_component_along_x_gives_the_planar_measures():
    x = PAIR.horizontal
    along_x = GroundMotion(PAIR.dt, x, horizontal_y=np.zeros_like(x))
    for base, frequency in (("pga", None), ("pgv", None), ("sa", 2.5), ("sa", 40.0)):
        planar = intensity(along_x, IntensityMeasure(base, frequency), STACK)
        rotd100 = intensity(along_x, IntensityMeasure(f"{base}-rotd100", frequency), STACK)
        assert rotd100 == pytest.approx(planar, rel=1e-12)


@settings(max_examples=15, deadline=None)
@given(degrees=st.integers(min_value=-360, max_value=360))
def test_rotating_a_record_keeps_its_rotd_values(degrees):
    # a rotation by whole degrees maps Boore's 1-degree angles onto themselves (up to
    # the sign of the series): the same peaks, so the same RotD50 and RotD100
    turned = PAIR.rotated(np.deg2rad(degrees))
    for kind, frequency in (("pga-rotd50", None), ("pga-rotd100", None),
                            ("sa-rotd50", 2.5), ("sa-rotd100", 2.5)):  # fmt: skip
        measure = IntensityMeasure(kind, frequency)
        assert intensity(turned, measure, STACK) == pytest.approx(
            intensity(PAIR, measure, STACK), rel=1e-9
        )


def test_rotating_by_any_angle_keeps_rotd100_within_the_angle_grid():
    # between the 1-degree angles the peak direction can fall half a degree from the
    # nearest one: RotD100 moves by at most 1 - cos(0.5 deg) = 3.8e-5
    for angle in (0.1234, 1.0, 2.5):
        turned = PAIR.rotated(angle)
        for kind, frequency in (("pga-rotd100", None), ("sa-rotd100", 2.5)):
            measure = IntensityMeasure(kind, frequency)
            assert intensity(turned, measure, STACK) == pytest.approx(
                intensity(PAIR, measure, STACK), rel=1 - np.cos(np.deg2rad(0.5))
            )


@pytest.mark.parametrize("kind", sorted(TWO_COMPONENT_KINDS))
def test_two_component_measures_scale_with_the_record(kind):
    measure = IntensityMeasure(kind, frequency=2.5 if kind.startswith("sa") else None)
    value = intensity(PAIR, measure, STACK)
    assert intensity(PAIR.scaled(7.0 / value), measure, STACK) == pytest.approx(7.0, rel=1e-12)
    assert KINDS[kind] == ("m/s" if kind.startswith("pgv") else "m/s^2")


def test_a_two_component_measure_of_a_one_component_record_is_an_error():
    planar = GroundMotion(PAIR.dt, PAIR.horizontal, name="rec01_H.AT2")
    with pytest.raises(ValueError, match=r"'rec01_H.AT2' has one horizontal component.*x and y"):
        intensity(planar, IntensityMeasure("pga-rotd50"), STACK)


def test_im_names_and_descriptions():
    assert parse_intensity("pga-gm", STACK) == IntensityMeasure("pga-gm")
    assert parse_intensity("PGV-RotD100", STACK) == IntensityMeasure("pgv-rotd100")
    measure = parse_intensity("sa-rotd50:2.5Hz,2%", STACK)
    assert measure == IntensityMeasure("sa-rotd50", frequency=2.5, damping=0.02)
    assert measure.describe() == "Sa(2.5 Hz, 2 %) RotD50"
    assert measure.to_dict() == {
        "kind": "sa-rotd50", "unit": "m/s^2", "frequency": 2.5, "damping": 0.02
    }  # fmt: skip
    assert IntensityMeasure("pga-gm").describe() == "PGA geometric mean"
    assert measure.two_components and not IntensityMeasure("sa", 2.5).two_components
    with pytest.raises(FreestandError, match="needs a frequency; e.g. sa-rotd100:2.5Hz"):
        parse_intensity("sa-rotd100", STACK)
    with pytest.raises(FreestandError, match="pga-rotd50"):
        parse_intensity("pga-rotd", STACK)
    with pytest.raises(FreestandError, match="takes no argument"):
        parse_intensity("pga-rotd50:3", STACK)


def test_rotation_angles_are_boores():
    angles = rotation_angles()
    assert angles.size == 180 and angles[0] == 0.0
    assert np.rad2deg(angles[-1]) == pytest.approx(179.0)
    assert rotation_angles(0.5).size == 360
    with pytest.raises(ValueError, match="does not divide"):
        rotation_angles(7.0)


@pytest.mark.parametrize(
    ("name", "base", "frequency", "damping"),
    [("pga", "pga", None, 0.05), ("pgv", "pgv", None, 0.05),
     ("sa-{}:2.5Hz,2%", "sa", 2.5, 0.02)],
)  # fmt: skip
def test_public_intensity_measure_against_a_brute_force_rotation(name, base, frequency, damping):
    import freestand as fs

    peaks = _brute_force_peaks(PAIR, base, frequency, damping)
    pattern = name if "{}" in name else name + "-{}"
    for combination, expected in (("rotd50", np.median(peaks)), ("rotd100", np.max(peaks))):
        assert fs.intensity_measure(PAIR, pattern.format(combination)) == pytest.approx(
            expected, rel=1e-6
        )
    # the geometric mean: the two components' own one-component measures (angles 0 and 90)
    assert fs.intensity_measure(PAIR, pattern.format("gm")) == pytest.approx(
        np.sqrt(peaks[0] * peaks[90]), rel=1e-6
    )
    # the one-component measure is that of x (angle 0)
    one = "sa:2.5Hz,2%" if base == "sa" else base
    assert fs.intensity_measure(PAIR, one) == pytest.approx(peaks[0], rel=1e-6)


def test_public_intensity_measure_says_what_is_wrong():
    import freestand as fs

    planar = GroundMotion(PAIR.dt, PAIR.horizontal, name="rec01_H.AT2")
    with pytest.raises(FreestandError, match=r"^im: .*'rec01_H.AT2' has one horizontal"):
        fs.intensity_measure(planar, "pga-rotd50")
    with pytest.raises(FreestandError, match=r"^im: 'pga-rotd' is not an intensity measure"):
        fs.intensity_measure(PAIR, "pga-rotd")
    with pytest.raises(FreestandError, match=r"^im: .*give the configuration"):
        fs.intensity_measure(PAIR, "pga-alpha")
    # with the block's configuration: PGA / (g tan alpha), alpha = atan(0.4 m / 1.2 m)
    alpha = fs.intensity_measure(PAIR, "pga-alpha", stack=STACK)
    assert alpha == pytest.approx(PAIR.peak_horizontal / (9.81 * 0.4 / 1.2), rel=1e-9)
    measure = fs.IntensityMeasure("pga-rotd100")
    assert fs.intensity_measure(PAIR, measure) == intensity(PAIR, measure, STACK)
