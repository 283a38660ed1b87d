"""The mode-map figure as a reader sees it: the labels of the model's points stay in their panel."""

import matplotlib

matplotlib.use("Agg")

from pathlib import Path  # noqa: E402

from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402

import freestand as fs  # noqa: E402

CRANE = Path(__file__).resolve().parents[1] / "examples" / "crane.toml"


def test_point_labels_stay_inside_their_panel_and_apart():
    model = fs.load_model(CRANE)
    result = fs.mode_map(model, "horizontal=0:12", "cart.friction.static=0.1:0.6",
                         configurations="x-z cart right", excitation="elastic", nodes=20)  # fmt: skip
    fig = result.plot()
    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.draw(renderer)
    panels = [ax for ax in fig.axes if ax.texts]
    assert len(panels) == 2
    for ax in panels:
        box = ax.get_window_extent(renderer)
        labels = [t for t in ax.texts if t.get_text().startswith(("rigid:", "elastic:"))]
        assert [t.get_text().split(":")[0] for t in labels] == ["rigid", "elastic"]
        extents = [t.get_window_extent(renderer) for t in labels]
        for extent in extents:
            assert box.x0 <= extent.x0 and extent.x1 <= box.x1 and box.y0 <= extent.y0
            assert extent.y1 <= box.y1
        assert not extents[0].overlaps(extents[1])
