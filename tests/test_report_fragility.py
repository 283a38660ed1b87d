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
