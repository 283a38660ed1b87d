"""The screening report's HTML carries the solver's numbers, every figure, and nothing external.

The report is read back with the standard library's HTML parser
(tests/report_html.py) and each number is compared with a direct call of the
core function that computes it: the value in ``data-value`` to round-off, the
shown text to its displayed rounding.
"""

from __future__ import annotations

import dataclasses
import datetime
import hashlib
import math
import re

import numpy as np
import pytest

import freestand
from freestand.core.contact.screening import initial_motion
from freestand.core.rocking.overturning import (
    CURVE_FREQUENCIES,
    TABLE_FREQUENCIES,
    check_spectrum,
    overturning_limits,
    rectangular_pulse_limits,
)
from freestand.core.rocking.properties import RockingBlock
from freestand.core.structure.beam import dunkerley_frequency, exact_frequency
from freestand.errors import FreestandError
from freestand.io.model_file import load_model_text
from freestand.report.content import collect_report, report_date, summary_sentences
from freestand.report.html import render_html
from tests.conftest import CRANE
from tests.report_html import parse_report, shown_number


@pytest.fixture(scope="module")
def report(crane_report):
    return parse_report(crane_report[1])


def assert_cell(cell, expected: float) -> None:
    """data-value equals the solver's number; the text shows it rounded to data-digits."""
    assert cell.value == pytest.approx(expected, rel=1e-12, abs=1e-9), cell
    if math.isfinite(expected) and cell.digits is not None:
        assert shown_number(cell.text) == pytest.approx(expected, abs=0.51 * 10**-cell.digits)


# --- header and inputs ---------------------------------------------------------------------------


def test_header_names_file_hash_version_and_date(report, crane_model):
    assert report.by_id["sha256"] == hashlib.sha256(CRANE.read_bytes()).hexdigest()
    assert report.by_id["version"] == freestand.__version__
    assert report.by_id["date"] == "2024-05-31"
    assert "crane.toml" in report.text
    assert report.one("gravity").value == crane_model.gravity


def test_inputs_echo_every_block_excitation_spectrum_and_beam(report, crane_model):
    for stack in crane_model.configurations:
        for block in stack.blocks:
            where = dict(configuration=stack.name, block=block.name, table="blocks")
            assert_cell(report.one("mass", **where), block.mass)
            assert_cell(report.one("inertia", **where), block.inertia)
            assert_cell(report.one("centre_x", **where), block.centre[0])
            assert_cell(report.one("centre_z", **where), block.centre[1])
            assert_cell(report.one("base_left", **where), block.base_left)
            assert_cell(report.one("base_right", **where), block.base_right)
            assert_cell(report.one("base_level", **where), block.base_level)
            assert_cell(report.one("friction_static", **where), block.friction.static)
            assert_cell(report.one("friction_kinetic", **where), block.friction.kinetic)
    for e in crane_model.excitations:
        assert_cell(report.one("horizontal", excitation=e.name), e.horizontal)
        assert_cell(report.one("vertical_g", excitation=e.name), e.vertical / crane_model.gravity)
    for name, spectrum in crane_model.spectra.items():
        cells = report.find("spectral_acceleration", spectrum=name)
        assert len(cells) == spectrum.frequency.size
        for cell, value in zip(cells, spectrum.acceleration, strict=True):
            assert_cell(cell, value)
    beam = crane_model.beam.beam
    assert_cell(report.one("span", table="beam"), beam.span)
    assert_cell(report.one("second_moment", table="beam"), beam.second_moment)
    assert_cell(report.one("parking_last", table="beam"), crane_model.beam.parking[1])


# --- screening (Tables 2-5) ----------------------------------------------------------------------


def test_screening_numbers_are_the_solver_numbers(report, crane_model):
    checked = 0
    for stack in crane_model.configurations:
        for e in crane_model.excitations:
            for sense in (1, -1):
                case = initial_motion(stack, e.horizontal, e.vertical, sense, crane_model.gravity)
                where = dict(configuration=stack.name, excitation=e.name, sense="+-"[sense < 0])
                for state in case.blocks:
                    row = dict(where, block=state.name)
                    motion = report.one("motion", table="motion", **row)
                    assert motion.attr_text == state.motion.value
                    for name in ("angular_acceleration", "acceleration_x", "acceleration_z"):
                        assert_cell(report.one(name, table="motion", **row), getattr(state, name))
                    for name in ("base_normal_left", "base_normal_right", "base_tangential"):
                        assert_cell(report.one(name, table="forces", **row), getattr(state, name))
                    checked += 1
    assert checked == 24  # 3 configurations x 2 excitations x 2 senses x 2 blocks


def test_paper_case_names_and_the_cart_rocking_about_its_outer_wheel(report):
    # shared/spec/crane-model.md: elastic, towards the end stop, the cart rocks (1.32 rad/s^2).
    cell = report.one(
        "angular_acceleration", configuration="x-z cart right", excitation="elastic",
        sense="+", block="cart",
    )  # fmt: skip
    assert cell.value == pytest.approx(-1.317, abs=2e-3)
    assert "3.1.1.2: cart rocks about its right edge on the steady bridge" in report.text
    assert "3.1.2.3: bridge slides, cart rests on it" in report.text
    assert "3.2: cart slides on the steady bridge" in report.text


def test_ambiguous_cases_are_flagged(crane_report):
    content, _ = crane_report
    first = content.cases[0]
    ambiguous = dataclasses.replace(
        first, status="ambiguous", alternatives=(first.blocks, first.blocks)
    )
    cases = (ambiguous, *content.cases[1:])
    flagged = dataclasses.replace(
        content,
        cases=cases,
        overturning=(),
        frequency=None,
        summary=summary_sentences(content.model, cases, (), (), None),
    )
    report = parse_report(render_html(flagged))
    rows = report.find("angular_acceleration", configuration=first.configuration,
                       excitation=first.excitation, sense="+", status="ambiguous")  # fmt: skip
    assert len(rows) == len(first.blocks)
    assert "ambiguous: 2 admissible states" in report.text
    assert "need the engineer's judgement" in report.text  # in the summary
    assert "y-z, rigid, sense +: ambiguous" in report.text  # in the list of flagged cases


# --- overturning (Figs. 6-8) ---------------------------------------------------------------------


@pytest.mark.parametrize(("configuration", "pivot"), [("x-z cart right", "right")])
def test_overturning_numbers_are_the_solver_numbers(report, crane_model, configuration, pivot):
    stack = crane_model.configuration(configuration)
    cart = stack.blocks[stack.block_index("cart")]
    rocking = RockingBlock.from_block(cart, pivot, gravity=crane_model.gravity)
    where = dict(configuration=configuration, block="cart", pivot=pivot)
    for name in ("R", "alpha", "p", "uplift_threshold", "inertia_about_pivot"):
        assert_cell(report.one(name, side="pivot", **where), getattr(rocking.about("pivot"), name))
    assert_cell(report.one("restitution", **where), rocking.restitution)

    rect = rectangular_pulse_limits(rocking, np.array([2.70, 10.31]))
    housner = report.find("housner", table="rectangular", **where)
    assert [c.value for c in housner][0] == math.inf  # 2.70 m/s^2 is below uplift: never
    assert_cell(housner[1], rect.housner[1])  # paper Fig. 6: 0.37 s
    assert housner[1].text.strip() == "0.374"
    assert_cell(report.find("exact", table="rectangular", **where)[1], rect.exact[1])

    table = overturning_limits(rocking, np.array(TABLE_FREQUENCIES))
    for name in ("housner", "makris-roussos", "exact"):
        cells = report.find(name, table="half-sine", **where)
        assert len(cells) == len(TABLE_FREQUENCIES)
        for cell, value in zip(cells, table.limits[name], strict=True):
            assert_cell(cell, value)

    curves = overturning_limits(rocking, CURVE_FREQUENCIES, operating_amplitude=10.31)
    for name, f0 in curves.operating_frequency.items():
        assert_cell(report.one("operating_frequency", limit=name, **where), f0)
    checks = check_spectrum(curves, crane_model.spectrum("horizontal"))
    for name, check in checks.items():
        assert_cell(report.one("min_ratio", limit=name, **where), check.min_ratio)
        assert report.one("verdict", limit=name, **where).attr_text == check.verdict
    assert report.one("overturning_verdict", **where).attr_text == "no overturning"


def test_both_cart_positions_are_assessed(crane_report):
    content, _ = crane_report
    assessed = {(a.configuration, a.block, a.pivot) for a in content.overturning}
    # The cart rocks about its outer wheel at either end of the bridge; the bridge never rocks.
    assert assessed == {("x-z cart right", "cart", "right"), ("x-z cart left", "cart", "left")}
    assert content.skipped == ()


# --- frequency and jump (Fig. 9) -----------------------------------------------------------------


def test_frequency_numbers_are_the_solver_numbers(report, crane_model):
    beam = crane_model.beam.beam
    cells = report.find("dunkerley", table="frequency")
    assert len(cells) >= 20
    for cell in cells:
        position = float(cell.context["position"])
        assert_cell(cell, float(dunkerley_frequency(beam, position)))
        exact = report.one("exact", table="frequency", position=cell.context["position"])
        assert_cell(exact, float(exact_frequency(beam, position)))
    # paper section 6: Dunkerley 10.6 Hz at mid-span, 16.6 Hz at 1.33 m from a support.
    assert report.one("dunkerley_min").value == pytest.approx(10.6, abs=0.05)
    assert report.one("dunkerley_max").value == pytest.approx(16.6, abs=0.05)
    assert report.one("jump_status").attr_text == "jump possible"
    assert report.by_id["risk-intervals"] == "3.00-6.80 m"


# --- summary, figures, self-containment ----------------------------------------------------------


def test_summary_tells_what_moves_and_whether_it_overturns_or_jumps(report):
    summary = report.text[report.text.index("1 Summary") : report.text.index("2 Inputs")]
    assert "the bridge slides on the support" in summary
    assert "the cart lifts and rocks about its right contact B on the bridge" in summary
    assert "It does not overturn under the spectrum 'horizontal (stand-in)'" in summary
    assert "smallest margin (limit / spectrum) is 2.57" in summary
    assert "the cart may jump" in summary and "between 3.00 and 6.80 m" in summary


def test_every_figure_is_present_and_not_empty(report):
    kinds = [f.attrs.get("data-figure") for f in report.figures]
    assert sorted(kinds) == ["fig6", "fig6", "fig7", "fig7", "fig8", "fig8", "fig9"]
    for figure in report.figures:
        assert figure.svg_elements.get("svg") == 1
        assert figure.svg_elements.get("path", 0) >= 20  # axes, ticks and curves
        assert figure.svg_elements.get("text", 0) >= 5  # labels kept as text
        assert figure.caption.startswith("Figure ")
    assert len(report.ids) == len(set(report.ids)), "ids must be unique across figures"


def test_no_external_references(crane_report, report):
    text = crane_report[1]
    for tag, attribute, value in report.references:
        assert value.startswith("#"), (tag, attribute, value)
    assert "link" not in report.tags and "script" not in report.tags
    assert "iframe" not in report.tags and "object" not in report.tags
    css = "".join(report.styles)
    assert "@import" not in css
    assert not re.search(r"url\(\s*['\"]?(?!#)", text)
    assert not re.search(r"https?://", text)


def test_report_date_from_option_and_environment(monkeypatch):
    assert report_date("2023-01-02") == datetime.date(2023, 1, 2)
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "86400")
    assert report_date() == datetime.date(1970, 1, 2)
    with pytest.raises(FreestandError, match="YYYY-MM-DD"):
        report_date("31/05/2024")


def test_model_without_spectra_or_beam_gets_no_verdicts():
    text = CRANE.read_text()
    text = text[: text.index("# --- bridge as a simply supported beam")]
    model = load_model_text(text, source="no-checks.toml")
    content = collect_report(model, date=datetime.date(2024, 1, 1))
    assert content.frequency is None
    assert all(a.verdict == "no spectrum" for a in content.overturning)
    report = parse_report(render_html(content))
    assert sorted(f.attrs["data-figure"] for f in report.figures) == [
        "fig6",
        "fig6",
        "fig7",
        "fig7",
    ]
    assert "no overturning verdict is given" in report.text
    assert "5 Vertical frequency" not in report.text


def test_overturning_conclusions_name_the_weight_and_give_the_vertical_limits(crane_report):
    content, html = crane_report
    (item,) = [a for a in content.overturning if a.configuration == "x-z cart right"]
    assert item.vertical == pytest.approx(2.35)
    # independent check: the same block with the weight m (g - a_v)
    from freestand.core.rocking.overturning import CURVE_FREQUENCIES, overturning_limits
    from freestand.core.rocking.properties import RockingBlock

    stack = next(s for s in content.model.configurations if s.name == "x-z cart right")
    lighter = RockingBlock.from_block(
        stack.blocks[1], item.pivot, gravity=9.81, vertical_acceleration=2.35
    )
    limits = overturning_limits(
        lighter, CURVE_FREQUENCIES, kind="half-sine", operating_amplitude=10.31
    )
    exact = limits.operating_frequency["exact"]
    assert item.half_sine_vertical.operating_frequency["exact"] == pytest.approx(exact)
    # lighter block: a pulse overturns it up to a higher frequency (shorter pulses)
    assert exact > item.half_sine.operating_frequency["exact"]
    summary = [s for s in content.summary if "x-z cart right the cart rocks" in s][0]
    assert "use the weight m g" in summary
    assert f"longer than {0.5 / exact:.2f} s (exact)" in summary
    assert "m (g - a_v), a_v = 2.35 m/s^2" in summary
    assert "with the weight m (g &#8722; a<sub>v</sub>)" in html
