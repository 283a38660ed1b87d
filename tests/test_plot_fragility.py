"""The fragility figure: its content, not only a file."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from freestand.core.sweeps.fragility.analysis import analyse  # noqa: E402
from freestand.core.sweeps.fragility.outcomes import Outcome  # noqa: E402
from freestand.plot.fragility import plot_fragility, save_fragility_figure  # noqa: E402


def _rows():
    levels = np.repeat(np.arange(5), 10)
    overturned = np.zeros(50)
    overturned[[12, 13, 21, 22, 23, 24, 25, 31, 32, 33, 34, 35, 36, 37, 38]] = 1
    overturned[40:] = 1
    status = np.array(["completed"] * 50, dtype=object)
    status[49] = "failed"
    return {
        "status": status,
        "level": levels,
        "im": np.repeat([1.0, 2.0, 3.0, 4.0, 5.0], 10),
        "block.overturned": overturned,
        "block.uplift": np.ones(50),
        "block.flight": np.zeros(50),
        "other.overturned": np.zeros(50),
    }


def _result():
    outcomes = [Outcome("overturn", "block"), Outcome("uplift", "block"),
                Outcome("flight", "block"), Outcome("overturn", "other")]  # fmt: skip
    return analyse(_rows(), outcomes, [1.0, 2.0, 3.0, 4.0, 5.0], unit="m/s^2", bootstrap=100)


def _labels(ax) -> list[str]:
    return [a.get_label() for a in (*ax.get_lines(), *ax.collections, *ax.containers)]


def _note(fig) -> str:
    (text,) = [t for t in fig.findobj(matplotlib.text.Text) if t.get_gid() == "note"]
    return text.get_text().replace("\n", " ")


def test_a_panel_per_outcome_that_occurred_and_a_note_for_the_others(tmp_path):
    result = _result()
    fig = plot_fragility(result, "PGA [m/s^2]", title="test")
    panels = [ax for ax in fig.axes if ax.axison]
    assert len(panels) == 2  # overturns and uplifts occurred; free flight and "other" never
    overturn, uplift = panels
    fitted = result.outcomes[0].fragility
    assert overturn.get_title(loc="left").startswith(
        f"block overturns\nmedian {fitted.median:.3g} m/s^2, beta {fitted.beta:.2f}"
    )
    curve = next(line for line in overturn.get_lines() if "median" in line.get_label())
    x, y = curve.get_data()
    np.testing.assert_allclose(y, fitted.probability(x))
    assert any(c.get_label() == "block overturns: 95 % band" for c in overturn.collections)
    markers = [c for c in overturn.containers if c.get_label() == "block overturns: fractions"][0]
    np.testing.assert_allclose(markers.lines[0].get_ydata(), [0.0, 0.2, 0.5, 0.8, 1.0])
    # uplift in every simulation: drawn, with the reason it has no curve in its title
    assert "block uplifts\nnot fitted" in uplift.get_title(loc="left")
    assert not any("median" in label for label in _labels(uplift))
    # never-occurring outcomes: no artist anywhere, named in the note
    for ax in fig.axes:
        assert not any(label.startswith(("block in free flight", "other")) for label in _labels(ax))
    note = _note(fig)
    assert "Never occurred in the 49 simulations counted" in note
    assert "block in free flight, other overturns" in note
    assert "1 failed simulation(s)" in note
    assert overturn.get_xlabel() == "PGA [m/s^2]" and overturn.get_ylabel() == "probability [-]"
    # one legend (three keys) for all panels, outside them
    (legend,) = [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]
    assert [t.get_text() for t in legend.get_texts()] == [
        "fraction of simulations (95 % Wilson interval)", "lognormal fit",
        "bootstrap band of the fit",
    ]  # fmt: skip
    assert not any(ax.get_legend() for ax in panels)
    written = save_fragility_figure(fig, tmp_path / "fragility.svg")
    assert written.stat().st_size > 1000 and "block overturns" in written.read_text()


def test_into_given_axes_with_the_legend_outside():
    result = _result()
    fig = Figure(layout="constrained")
    ax = fig.add_subplot()
    assert plot_fragility(result, "PGA [m/s^2]", ax=ax) is fig
    assert len(fig.axes) == 1
    legend = ax.get_legend()
    texts = [t.get_text() for t in legend.get_texts()]
    assert len(texts) == 2 and texts[0].startswith("block overturns: median")
    assert legend.get_bbox_to_anchor().x0 > ax.get_window_extent().x1  # right of the axes
    assert "block in free flight" in _note(fig) and "Markers: fraction" in _note(fig)


def test_a_cloud_and_a_campaign_in_which_nothing_occurred():
    rows = _rows()
    cloud = analyse(rows, [Outcome("overturn", "block"), Outcome("overturn", "other")], [],
                    unit="m/s^2", bootstrap=50)  # fmt: skip
    fig = plot_fragility(cloud, "PGA [m/s^2]")
    (legend,) = [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]
    assert legend.get_texts()[0].get_text() == "simulations (1: occurred, 0: not)"
    assert (
        [ax for ax in fig.axes if ax.axison][0].get_title(loc="left").startswith("block overturns")
    )
    assert "other overturns" in _note(fig)
    nothing = analyse(rows, [Outcome("overturn", "other")], [1.0, 2.0, 3.0, 4.0, 5.0], bootstrap=0)
    fig = plot_fragility(nothing, "PGA [m/s^2]")
    (panel,) = [ax for ax in fig.axes if ax.axison]
    assert [t.get_text() for t in panel.texts] == ["no outcome occurred"]
    assert not panel.lines and not panel.containers
    assert "other overturns" in _note(fig)
