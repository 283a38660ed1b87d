"""Figures of record spectra against a target."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np

from freestand.core.motion.design_spectra import rg160_spectrum
from freestand.plot.records import plot_floor_motion, plot_record_spectra


def test_spectra_figure_draws_records_target_band_and_ratios():
    f = np.geomspace(0.2, 50, 50)
    target = rg160_spectrum(3.0, 0.05)
    goal = target.acceleration_at(f)
    curves = [("a", goal * 1.1), ("b", goal * 0.95)]
    figure = plot_record_spectra(f, curves, target=target, damping=0.05, title="t")
    upper, lower = figure.axes
    assert upper.get_xscale() == "log"
    assert "5 % damping" in upper.get_ylabel() and "m/s" in upper.get_ylabel()
    lines = {line.get_label(): line for line in upper.get_lines()}
    assert np.allclose(lines["a"].get_ydata(), goal * 1.1)
    assert np.allclose(lines[target.label].get_ydata(), goal)
    assert np.allclose(lines["0.9 and 1.3 x target"].get_ydata(), 0.9 * goal)
    ratios = [line.get_ydata() for line in lower.get_lines()]
    assert any(np.allclose(r, 1.1) for r in ratios)
    assert any(np.allclose(r, 0.95) for r in ratios)
    assert lower.get_ylabel() == "record / its target [-]"


def test_suite_figure_draws_the_mean():
    f = np.geomspace(0.2, 50, 20)
    curves = [(f"r{k}", np.full(f.size, float(k))) for k in range(12)]
    figure = plot_record_spectra(f, curves)
    (axes,) = figure.axes
    mean = [line for line in axes.get_lines() if line.get_label() == "mean of 12"]
    assert len(mean) == 1 and np.allclose(mean[0].get_ydata(), 5.5)


def test_floor_figure():
    t = np.linspace(0, 1, 11)
    figure = plot_floor_motion(t, np.sin(t), 2 * np.sin(t), title="floor")
    (axes,) = figure.axes
    assert axes.get_xlabel() == "time [s]"
    assert {line.get_label() for line in axes.get_lines()} == {
        "ground",
        "floor (oscillator absolute acceleration)",
    }
