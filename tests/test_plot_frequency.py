"""The Fig. 9 analogue: frequency against cart position."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.figure import Figure

from freestand.core.motion.spectra import Spectrum
from freestand.core.structure.beam import SimplySupportedBeam, frequency_sweep, jump_check
from freestand.plot.frequency import plot_frequency_sweep, save_frequency_figure

PARKING = (1.33, 8.47)


@pytest.fixture(scope="module")
def crane_sweep():
    beam = SimplySupportedBeam(9.8, 2.1e11, 0.014, 16600.0, 25600.0)
    return frequency_sweep(beam, points=49, parking=PARKING)


@pytest.fixture(scope="module")
def spectrum():
    return Spectrum(
        np.array([0.1, 1.0, 8.0, 12.0, 33.0, 100.0]),
        np.array([0.2, 3.0, 9.81, 9.81, 2.35, 2.35]),
        direction="vertical",
    )


def _corners(patch) -> np.ndarray:
    """Corner coordinates of a span patch (a Rectangle or a Polygon, by matplotlib version)."""
    return patch.get_patch_transform().transform(patch.get_path().vertices)


def _labelled(axes):
    handles, labels = axes.get_legend_handles_labels()
    return dict(zip(labels, handles, strict=True))


def test_both_curves_and_the_parking_range(crane_sweep):
    figure = plot_frequency_sweep(crane_sweep, parking=PARKING)
    assert isinstance(figure, Figure)
    (axes,) = figure.axes
    items = _labelled(axes)
    exact = items["exact (continuous beam)"]
    dunkerley = items["Dunkerley (paper eqs. 1-4)"]
    assert np.allclose(exact.get_xdata(), crane_sweep.position)
    assert np.allclose(exact.get_ydata(), crane_sweep.exact)
    assert np.allclose(dunkerley.get_ydata(), crane_sweep.dunkerley)
    shaded = items["parking range"]
    x = _corners(shaded)[:, 0]
    assert x.min() == pytest.approx(PARKING[0]) and x.max() == pytest.approx(PARKING[1])
    assert "position" in axes.get_xlabel() and "[m]" in axes.get_xlabel()
    assert "[Hz]" in axes.get_ylabel()
    assert axes.get_xlim() == pytest.approx((0.0, 9.8))
    assert "cart may jump (S_a >= g)" not in items


def test_positions_at_risk_are_marked(crane_sweep, spectrum):
    check = jump_check(crane_sweep, spectrum, 9.81, parking=PARKING)
    figure = plot_frequency_sweep(crane_sweep, jump=check, vertical_spectrum=spectrum)
    items = _labelled(figure.axes[0])
    markers = items["cart may jump (S_a >= g)"]
    drawn = np.isfinite(markers.get_ydata())
    assert np.allclose(markers.get_xdata()[drawn], check.positions_at_risk)
    assert drawn.any() and not drawn.all()
    assert "parking range" in items  # taken from the check
    band = _corners(items["spectrum reaches g"])[:, 1]
    # The stand-in spectrum reaches g from 8 to 12 Hz (tolerance: the 4000-point grid).
    assert band.min() == pytest.approx(8.0, rel=2e-3) and band.max() == pytest.approx(
        12.0, rel=2e-3
    )


def test_save_writes_png_and_svg(crane_sweep, tmp_path):
    figure = plot_frequency_sweep(crane_sweep)
    written = save_frequency_figure(figure, tmp_path / "out" / "fig9.pdf")
    assert [p.suffix for p in written] == [".png", ".svg"]
    assert written[0].read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert b"<svg" in written[1].read_bytes()[:2000]


def test_mismatched_check_is_refused(crane_sweep, spectrum):
    other = frequency_sweep(crane_sweep.beam, points=7)
    check = jump_check(other, spectrum, 9.81)
    with pytest.raises(ValueError, match="positions"):
        plot_frequency_sweep(crane_sweep, jump=check)
