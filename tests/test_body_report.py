"""The screening report of a model with 3-D configurations (#18): tables by direction, figure."""

from __future__ import annotations

import datetime
import json
import math

import pytest

import freestand as fs
from freestand.io.model_file import load_model_text
from freestand.report.content import collect_report
from freestand.report.html import render_html
from tests.conftest import ROOT, run_freestand
from tests.report_html import parse_report, shown_number
from tests.test_body_model_file import PLANAR  # a planar frame (it does not lift)

BODIES = ROOT / "examples" / "bodies.toml"


@pytest.fixture(scope="module")
def bodies_report():
    model = fs.load_model(BODIES)
    content = collect_report(model, date=datetime.date(2024, 5, 31))
    return model, content, parse_report(render_html(content))


def test_every_direction_carries_the_solver_numbers(bodies_report):
    model, content, report = bodies_report
    result = fs.screen(model)
    assert content.body_cases == result.body_cases
    for case in result.body_cases:
        where = {"configuration": case.configuration, "excitation": case.excitation}
        cells = report.find("uplift_threshold", **where)
        assert len(cells) == 24 + 1  # the sweep and the excitation's own direction
        for cell, state in zip(cells, [*case.directions, case.at_excitation], strict=True):
            assert cell.value == pytest.approx(state.uplift_threshold, rel=1e-12)
            assert shown_number(cell.text) == pytest.approx(state.uplift_threshold, abs=5.1e-4)
        motions = [q.attr_text for q in report.find("motion", **where)]
        assert motions[0].split(" ")[0] == case.directions[0].motion.value
        normals = report.find("normal_force", **where)
        finite = [s.normal_force for s in case.directions if math.isfinite(s.normal_force)]
        assert [q.value for q in normals if math.isfinite(q.value)][: len(finite)] == finite


def test_inputs_summary_figure_and_method(bodies_report):
    _, content, report = bodies_report
    assert report.one("mass", configuration="cask", block="cask").value == 180000.0
    assert report.one("inertia_yy", configuration="cabinet", block="cabinet").value == 205.0
    assert report.one("excitation_direction", excitation="SL-2").value == pytest.approx(
        36.8699, abs=1e-4
    )
    summary = " ".join(content.summary)
    assert "3-D configuration cabinet. Under SL-1" in summary
    assert "rests in 14 of 24 directions, rocks in 10 of 24 directions" in summary
    assert "not assessed for overturning" in summary
    assert "No block" not in summary  # no planar configuration
    figures = [f for f in report.figures if f.attrs.get("data-figure") == "uplift-polar"]
    assert [f.attrs["data-configuration"] for f in figures] == ["cask", "cabinet"]
    for figure in figures:
        assert figure.svg_elements.get("path", 0) >= 50 and "a*(" in figure.caption
    assert "bodies-not-assessed" in report.ids
    assert "3-D bodies" in report.text and "Housner 1963, generalised" in report.text


def test_a_model_with_both_kinds_reports_both():
    text = BODIES.read_text() + PLANAR
    model = load_model_text(text, source="both.toml")
    content = collect_report(model, date=datetime.date(2024, 5, 31))
    report = parse_report(render_html(content))
    assert {q.context.get("configuration") for q in report.find("base_normal_left")} == {"plane"}
    assert len(report.find("uplift_threshold")) == 2 * 2 * 25
    assert any(s.startswith("Configuration plane.") for s in content.summary)
    assert "No block of the planar configurations lifts" in " ".join(content.summary)


def test_report_command_on_a_3d_model(tmp_path):
    target = tmp_path / "bodies.html"
    result = run_freestand("report", str(BODIES), "-o", str(target), "--date", "2024-05-31")
    assert result.returncode == 0, result.stderr
    html = target.read_text()
    assert html.count('data-figure="uplift-polar"') == 2
    assert "Traceback" not in result.stderr


def test_report_with_a_record_gives_the_time_history_of_each_3d_body(tmp_path):
    """freestand report --record: section 4 has the peaks (the API's numbers) and the figures."""
    records = ROOT / "examples" / "records"
    target = tmp_path / "bodies.html"
    result = run_freestand(
        "report", str(BODIES), "-o", str(target), "--date", "2024-05-31", "--json",
        "--record", str(records / "synthetic_H.AT2"), "--record-y", str(records / "synthetic_H.AT2"),
        "--peak", "5", "--angle", "30",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    report = parse_report(target.read_text())
    record = fs.load_record(records / "synthetic_H.AT2", horizontal_y=records / "synthetic_H.AT2")
    model = fs.load_model(BODIES)
    for name in ("cask", "cabinet"):
        history = fs.simulate(model, record.scaled_to_peak(5.0), configuration=name, angle=30.0,
                              until_rest=True)  # fmt: skip
        where = {"configuration": name, "block": name}
        assert report.one("max_rotation", **where).value == history.max_rotation[0]
        assert report.one("max_slide_mm", **where).value == 1000.0 * history.max_slide[0]
        assert report.one("end_time", **where).value == history.core.time[-1]
    kinds = [
        (f.attrs.get("data-figure"), f.attrs.get("data-configuration")) for f in report.figures
    ]
    for name in ("cask", "cabinet"):
        assert ("body-history", name) in kinds and ("body-plan", name) in kinds
    summary = " ".join(json.loads(result.stdout)["summary"])
    assert "Under the record synthetic_H.AT2 (turned 30 deg) the cabinet (cabinet) lifts" in summary
    assert "not assessed for overturning" not in summary
    assert "body-histories" in report.ids and "bodies-not-assessed" not in report.ids


@pytest.mark.parametrize(
    ("model_file", "args", "option"),
    [
        (BODIES, ("--record-y", "y.AT2"), "--record-y"),
        (ROOT / "examples" / "crane.toml", ("--record", "x.AT2"), "--record"),
    ],
)
def test_report_record_options_need_a_record_and_a_3d_configuration(model_file, args, option,
                                                                      tmp_path):  # fmt: skip
    records = ROOT / "examples" / "records"
    (tmp_path / "x.AT2").write_text((records / "synthetic_H.AT2").read_text())
    result = run_freestand("report", str(model_file), "-o", "out.html", *args, cwd=tmp_path)
    assert result.returncode == 2 and option in result.stderr
    assert "Traceback" not in result.stderr and not (tmp_path / "out.html").exists()
