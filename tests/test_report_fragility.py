"""The fragility appendix of the report, for a model file with a [fragility] table."""

from __future__ import annotations

import pytest

from freestand.core.motion.ground_motion import half_sine_pulse
from freestand.errors import FreestandError
from freestand.io.model_file import load_model
from freestand.io.records import write_at2
from freestand.io.suites import suite_text

MODEL = """
name = "Block"
[[excitation]]
name = "rigid"
horizontal = 2.0
[[configuration]]
name = "block"
[[configuration.block]]
name = "block"
mass = 500
inertia = 266.6666666666667
centre = [0.0, 1.2]
base = { left = -0.4, right = 0.4, level = 0.0 }
friction = { static = 2.0, kinetic = 2.0 }
sliding = "none"

[fragility]
suite = "records/suite.toml"
levels = "3:12:4"
outcomes = ["overturn:block", "uplift:block"]
seed = 3
bootstrap = 50
"""


def _model(tmp_path, text=MODEL):
    folder = tmp_path / "records"
    folder.mkdir()
    records = []
    for number, f in enumerate((1.5, 2.5, 3.5)):
        motion = half_sine_pulse(1.0, frequency=f, dt=1.0 / (200.0 * f))
        write_at2(folder / f"p{number}.AT2", motion, component="horizontal", title="pulse",
                  description=f"half-sine {f} Hz")  # fmt: skip
        records.append({"horizontal": f"p{number}.AT2"})
    (folder / "suite.toml").write_text(suite_text("three pulses", records))
    (tmp_path / "block.toml").write_text(text)
    return load_model(tmp_path / "block.toml")


def test_report_has_the_fragility_appendix(tmp_path):
    from freestand.report.content import collect_report
    from freestand.report.html import render_html

    model = _model(tmp_path)
    assert model.fragility["levels"] == "3:12:4"
    content = collect_report(model)
    assert content.fragility is not None
    document = content.fragility.document
    assert document["simulations"] == 12 and document["seed"] == 3
    page = render_html(content)
    assert '<section id="fragility">' in page and 'href="#fragility"' in page
    assert 'data-outcome="block overturns"' in page and 'data-outcome="block uplifts"' in page
    assert "three pulses" in page and "records/suite.toml" in page  # what to reproduce it with
    assert "fingerprint" in page and "HCLPF" in page and "<svg" in page


def test_bad_fragility_table_names_the_key(tmp_path):
    from freestand.report.fragility import assess_fragility

    model = _model(tmp_path, MODEL.replace('levels = "3:12:4"', 'levels = "3:12:4"\nspeed = 1'))
    with pytest.raises(FreestandError, match="speed"):
        assess_fragility(model)


BODY_MODEL = """
name = "Cylinder"
[[excitation]]
name = "rigid"
horizontal = 2.0
y = 1.0
[[configuration]]
name = "drum"
[[configuration.block]]
name = "drum"
shape = "cylinder"
radius = 0.4
height = 2.0
mass = 500
friction = { static = 0.8, kinetic = 0.7 }

[fragility]
suite = "records/suite.toml"
levels = "2:8:3"
outcomes = ["overturn:drum", "rotation:drum>0.5alpha", "twist:drum>5"]
free_time = 2.0
bootstrap = 20
"""


def _body_model(tmp_path, extra=""):
    folder = tmp_path / "records"
    folder.mkdir()
    records = []
    for number, f in enumerate((1.5, 2.5)):
        motion = half_sine_pulse(1.0, frequency=f, dt=1.0 / (200.0 * f))
        for axis, factor in (("X", 1.0), ("Y", 0.6)):
            write_at2(folder / f"p{number}_{axis}.AT2", motion.scaled(factor),
                      component="horizontal", title="pulse", description=f"{f} Hz {axis}")  # fmt: skip
        records.append({"x": f"p{number}_X.AT2", "y": f"p{number}_Y.AT2"})
    (folder / "suite.toml").write_text(suite_text("two pulse pairs", records))
    (tmp_path / "drum.toml").write_text(BODY_MODEL + extra)
    return load_model(tmp_path / "drum.toml")


def test_a_3d_configuration_gets_its_fragility_appendix(tmp_path):
    """A cylinder's [fragility] table: the default IM of 3-D bodies (PGA RotD50), angles drawn,
    3-D outcomes, and the 3-D sentence in the appendix."""
    from freestand.report.content import collect_report
    from freestand.report.html import render_html

    content = collect_report(_body_model(tmp_path))
    document = content.fragility.document
    assert document["im"]["kind"] == "pga-rotd50" and document["shape"] == "cylinder"
    assert document["angles"] == "uniform" and document["simulations"] == 6
    assert document["failed"] == 0
    page = render_html(content)
    assert '<section id="fragility">' in page and "RotD50" in page
    assert "A 3-D cylinder" in page and "drawn uniformly" in page
    assert "until the body is at rest" in page and 'data-outcome="drum overturns"' in page
    assert "twist" in page


def test_a_3d_fragility_table_takes_angle_and_angles(tmp_path):
    from freestand.report.fragility import assess_fragility

    section = assess_fragility(_body_model(tmp_path, "angle = 30\n"), workers=1)
    assert section.document["angles"] == [30.0] and section.document["simulations"] == 6
    (tmp_path / "records").rename(tmp_path / "old")
    swept = assess_fragility(_body_model(tmp_path, 'angles = 2\nim = "pga"\n'), workers=1)
    assert swept.document["angles"] == [0.0, 180.0] and swept.document["simulations"] == 12
    assert swept.document["im"]["kind"] == "pga" and swept.document["im"]["components"] == "x"


@pytest.mark.parametrize(
    ("extra", "match"),
    [
        ('angle = "north"\n', "angle"),
        ("angles = 2.5\n", "angles"),
        ("angle = 10\nangles = 4\n", "angles"),
    ],
)
def test_bad_3d_fragility_keys_are_named(tmp_path, extra, match):
    from freestand.report.fragility import assess_fragility

    with pytest.raises(FreestandError, match=match):
        assess_fragility(_body_model(tmp_path, extra), workers=1)
