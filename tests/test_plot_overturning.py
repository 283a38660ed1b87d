"""Figures of the overturning assessment: content, not only files."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from freestand.core.motion.design_spectra import crane_stand_in_spectra  # noqa: E402
from freestand.core.rocking.overturning import (  # noqa: E402
    check_spectrum,
    overturning_limits,
    rectangular_pulse_limits,
)
from freestand.core.rocking.properties import RockingBlock  # noqa: E402
from freestand.plot.overturning import (  # noqa: E402
    plot_pulse_limits,
    plot_rectangular_pulse,
    plot_spectrum_check,
    save_figure,
)

CART = RockingBlock(25600.0, 124100.0, (-1.33, -2.83), (1.33, -2.83))


def _labels(ax):
    return [line.get_label() for line in ax.get_lines()]


def test_fig6_analogue(tmp_path):
    limits = rectangular_pulse_limits(CART, np.linspace(4.0, 30.0, 12), operating_amplitude=10.31)
    fig = plot_rectangular_pulse(limits)
    ax = fig.axes[0]
    labels = _labels(ax)
    assert any("Housner" in s for s in labels) and any("exact" in s for s in labels)
    assert any("0.37 s" in s for s in labels)  # the paper's operating point
    assert "[m/s^2]" in ax.get_xlabel() and "[s]" in ax.get_ylabel()
    written = save_figure(fig, tmp_path / "fig6")
    assert [p.suffix for p in written] == [".png", ".svg"]
    assert all(p.stat().st_size > 1000 for p in written)


def test_fig7_and_fig8_analogues():
    limits = overturning_limits(CART, np.geomspace(0.2, 10.0, 12), operating_amplitude=10.31)
    fig = plot_pulse_limits(limits)
    ax = fig.axes[0]
    labels = _labels(ax)
    for name in ("Housner", "Makris & Roussos", "exact nonlinear"):
        assert any(name in s for s in labels)
    assert any("0.50 Hz (Housner)" in s for s in labels)
    assert ax.get_xscale() == "log" and "[Hz]" in ax.get_xlabel()
    # the drawn exact curve is the computed one
    exact_line = next(line for line in ax.get_lines() if "exact nonlinear" in line.get_label())
    np.testing.assert_allclose(exact_line.get_ydata(), limits.limits["exact"])

    spectrum = crane_stand_in_spectra()[0]
    checks = check_spectrum(limits, spectrum)
    fig8 = plot_spectrum_check(limits, spectrum, checks)
    labels8 = _labels(fig8.axes[0])
    assert spectrum.label in labels8
    assert sum("smallest limit / spectrum" in s for s in labels8) == 3
    assert "[m/s^2]" in fig8.axes[0].get_ylabel()


def test_fig8_legend_below_the_axes_and_margin_markers_apart():
    limits = overturning_limits(CART, np.geomspace(0.2, 10.0, 12), operating_amplitude=10.31)
    spectrum = crane_stand_in_spectra()[0]
    checks = check_spectrum(limits, spectrum)
    fig = plot_spectrum_check(limits, spectrum, checks)
    ax = fig.axes[0]
    assert ax.get_legend() is None  # no legend over the curves
    assert len(fig.legends) == 1
    fig.draw_without_rendering()  # runs the constrained layout
    legend_box = fig.legends[0].get_window_extent()
    assert legend_box.y1 <= ax.get_window_extent().y0  # below the axes
    margins = [line for line in ax.get_lines() if "smallest limit / spectrum" in line.get_label()]
    # two limits may have their smallest margin at the same frequency: different
    # shapes and sizes keep both markers visible
    assert len({(line.get_marker(), line.get_markersize()) for line in margins}) == len(margins)
