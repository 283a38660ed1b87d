"""The fragility figure: its content, not only a file."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from freestand.core.sweeps.fragility.analysis import analyse  # noqa: E402
from freestand.core.sweeps.fragility.outcomes import Outcome  # noqa: E402
from freestand.plot.fragility import plot_fragility, save_fragility_figure  # noqa: E402


def _rows():
    levels = np.repeat(np.arange(5), 10)
    overturned = np.zeros(50)
    overturned[[12, 13, 21, 22, 23, 24, 25, 31, 32, 33, 34, 35, 36, 37, 38]] = 1
    overturned[40:] = 1
    return {
        "status": np.array(["completed"] * 50, dtype=object),
        "level": levels,
        "im": np.repeat([1.0, 2.0, 3.0, 4.0, 5.0], 10),
        "block.overturned": overturned,
        "block.uplift": np.ones(50),
    }


def test_curves_bands_and_fractions(tmp_path):
    result = analyse(
        _rows(),
        [Outcome("overturn", "block"), Outcome("uplift", "block")],
        [1.0, 2.0, 3.0, 4.0, 5.0],
        unit="m/s^2",
        bootstrap=100,
    )
    fig = plot_fragility(result, "PGA [m/s^2]", title="test")
    ax = fig.axes[0]
    labels = [line.get_label() for line in ax.get_lines()]
    fitted = result.outcomes[0].fragility
    assert f"block overturns: median {fitted.median:.3g}, beta {fitted.beta:.2f}" in labels
    assert "block uplifts: not fitted" in labels  # uplift in every simulation
    curve = next(
        line for line in ax.get_lines() if line.get_label().startswith("block overturns: median")
    )
    x, y = curve.get_data()
    np.testing.assert_allclose(y, fitted.probability(x))
    # the confidence band and the stripe fractions with their Wilson intervals
    assert any(c.get_label() == "block overturns: 95 % band" for c in ax.collections)
    handles, legend = ax.get_legend_handles_labels()
    assert "block overturns: fractions" in legend
    markers = [c for c in ax.containers if c.get_label() == "block overturns: fractions"][0]
    np.testing.assert_allclose(markers.lines[0].get_ydata(), [0.0, 0.2, 0.5, 0.8, 1.0])
    assert ax.get_xlabel() == "PGA [m/s^2]" and ax.get_ylabel() == "probability [-]"
    written = save_fragility_figure(fig, tmp_path / "fragility.svg")
    assert written.stat().st_size > 1000 and "block overturns" in written.read_text()
