"""The screening report as one self-contained HTML document.

:func:`render_html` formats a :class:`~freestand.report.content.ReportContent`:
styles inline, figures inline SVG drawn by :mod:`freestand.plot`, nothing
fetched from elsewhere, so the file can be mailed, archived and opened
offline. Built with the standard library (:func:`html.escape`), no template
engine.

Every number a reader may want to check carries its full-precision value:
``<td data-quantity="angular_acceleration" data-value="-1.3170...">-1.317</td>``,
and the rows or sections around it carry what it belongs to
(``data-configuration``, ``data-excitation``, ``data-sense``, ``data-block``,
``data-pivot``, ``data-limit``, ``data-frequency``, ``data-position``...).
"""

from __future__ import annotations

import math

import numpy as np

from freestand.core.contact.screening import InitialMotion
from freestand.core.rocking.overturning import HALF_SINE_LIMITS
from freestand.report.content import (
    FrequencyAssessment,
    ReportContent,
    RockingAssessment,
    case_label,
    limit_title,
    sense_label,
)
from freestand.report.markup import Document as _Document
from freestand.report.markup import data_attrs as _attrs
from freestand.report.markup import esc as _e
from freestand.report.markup import number_cell as _num
from freestand.report.markup import number_text as _format
from freestand.report.markup import table_head as _head
from freestand.report.tables import FORCE_HEADERS, motion_label

CSS = """
:root { --ink: #1a1a1a; --rule: #9a9a9a; --light: #f2f2f2; --flag: #fff3c4; --risk: #fde2df; }
* { box-sizing: border-box; }
html { font-family: "DejaVu Sans", "Liberation Sans", Arial, sans-serif; font-size: 10.5pt;
       color: var(--ink); background: #fff; }
body { max-width: 19cm; margin: 1.5cm auto; padding: 0 0.5cm; line-height: 1.4; }
h1 { font-size: 17pt; margin: 0 0 0.2em; }
h2 { font-size: 13.5pt; border-bottom: 1.5px solid var(--ink); padding-bottom: 2px;
     margin-top: 1.8em; break-after: avoid; }
h3 { font-size: 11.5pt; margin-top: 1.4em; break-after: avoid; }
h4 { font-size: 10.5pt; margin: 1.1em 0 0.3em; break-after: avoid; }
p { margin: 0.4em 0 0.6em; }
.subtitle { font-size: 12pt; margin: 0 0 1em; }
table { border-collapse: collapse; margin: 0.5em 0 1.1em; width: 100%; font-size: 9pt; }
caption { caption-side: top; text-align: left; font-weight: bold; padding: 0 0 4px;
          font-size: 9.5pt; }
th, td { border-top: 0.5px solid var(--rule); border-bottom: 0.5px solid var(--rule);
         padding: 2px 6px; vertical-align: top; text-align: left; }
thead th { border-bottom: 1.2px solid var(--ink); border-top: 1.2px solid var(--ink);
           background: var(--light); font-weight: 600; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
td.num { white-space: nowrap; }
td.case { min-width: 15em; font-size: 8.5pt; }
td.motion { white-space: nowrap; }
table.wide { font-size: 8pt; }
table.wide th, table.wide td { padding: 2px 3px; }
table.meta { width: auto; font-size: 9.5pt; }
table.meta th { background: none; border: none; font-weight: 600; padding-right: 1.2em; }
table.meta td { border: none; }
code, .hash { font-family: "DejaVu Sans Mono", "Liberation Mono", monospace; font-size: 8.5pt;
              word-break: break-all; }
tr.flag td { background: var(--flag); }
tr.risk td { background: var(--risk); }
.badge { display: inline-block; padding: 0 5px; border-radius: 3px; font-size: 8.5pt;
         font-weight: 600; white-space: nowrap; }
.badge.flag { background: #f5c518; color: #000; }
.badge.ok { background: #d7efd9; color: #114d1a; }
.badge.risk { background: #f6c1bb; color: #6b120a; }
.summary { border: 1.5px solid var(--ink); padding: 0.6em 1em; background: #fafafa; }
.summary li { margin: 0.35em 0; }
.note { font-size: 9pt; color: #444; }
figure { margin: 0.8em 0 1.4em; text-align: center; break-inside: avoid; }
figure svg { width: 100%; max-width: 16cm; height: auto; display: block; margin: 0 auto; }
figcaption { font-size: 9pt; text-align: left; margin-top: 4px; }
figcaption b { font-weight: 600; }
nav ol { columns: 2; font-size: 9.5pt; margin: 0.3em 0; }
nav a, a { color: inherit; }
.references li { margin: 0.3em 0; }
@page { size: A4; margin: 16mm 14mm 18mm; }
@media print {
  html { font-size: 9.5pt; }
  body { max-width: none; margin: 0; padding: 0; }
  nav { display: none; }
  tr, figure, .summary li, .keep { break-inside: avoid; page-break-inside: avoid; }
  thead { display: table-header-group; }
  caption, h2, h3, h4 { break-after: avoid; page-break-after: avoid; }
  figcaption { break-before: avoid; page-break-before: avoid; }
  section.assessment { break-before: page; }
  tr.flag td, tr.risk td, thead th, .badge { -webkit-print-color-adjust: exact;
                                             print-color-adjust: exact; }
}
"""

LIMIT_NAMES = {
    "housner": "Housner (1963), linearised",
    "makris-roussos": "Makris & Roussos (2000), linearised",
    "exact": "exact nonlinear, with impacts",
}

REFERENCES = (
    (
        "paper",
        "Response of rigid block assemblies to earthquake excitation (the reference paper of "
        "freestand): initial motion and contact forces of two stacked blocks (section 3), "
        "crane example (section 4, Tables 1-5), overturning of the cart (section 5, "
        "Figs. 6-8), vertical frequency of the bridge (section 6, Fig. 9), conclusions "
        "(section 7).",
    ),
    (
        "housner",
        "Housner, G. W. (1963). The behavior of inverted pendulum structures during "
        "earthquakes. Bulletin of the Seismological Society of America, 53(2), 403-417.",
    ),
    (
        "makris",
        "Makris, N., and Roussos, Y. S. (2000). Rocking response of rigid blocks under "
        "near-source ground motions. Geotechnique, 50(3), 243-262.",
    ),
    (
        "zhang",
        "Zhang, J., and Makris, N. (2001). Rocking response of free-standing blocks under "
        "cycloidal pulses. Journal of Engineering Mechanics, 127(5), 473-483.",
    ),
    (
        "dunkerley",
        "Dunkerley, S. (1894). On the whirling and vibration of shafts. Philosophical "
        "Transactions of the Royal Society of London A, 185, 279-360.",
    ),
    (
        "rg160",
        "U.S. Nuclear Regulatory Commission (1973, rev. 2 2014). Regulatory Guide 1.60: "
        "Design response spectra for seismic design of nuclear power plants.",
    ),
    (
        "en1998",
        "EN 1998-1:2004. Eurocode 8: Design of structures for earthquake resistance. Part 1: "
        "General rules, seismic actions and rules for buildings. Section 3.2.2.",
    ),
)


# --- sections ------------------------------------------------------------------------------------


def _header(content: ReportContent) -> str:
    model = content.model
    rows = [
        ("Model", _e(model.name)),
        ("Model file", f"<code>{_e(content.model_file)}</code>"),
        ("SHA-256 of the file", f'<span class="hash" id="sha256">{_e(content.sha256)}</span>'),
        ("freestand version", f'<span id="version">{_e(content.version)}</span>'),
        ("Date", f'<span id="date">{content.date.isoformat()}</span>'),
        (
            "Gravity g",
            f'<span data-quantity="gravity" data-value="{model.gravity!r}">'
            f"{model.gravity:g}</span> m/s<sup>2</sup>",
        ),
    ]
    meta = "".join(f"<tr><th>{k}</th><td>{v}</td></tr>" for k, v in rows)
    return (
        "<header><h1>Seismic screening of free-standing equipment</h1>"
        f'<p class="subtitle">{_e(model.name)}: initial motion, contact forces, overturning '
        "and vertical frequency, after the method of the reference paper</p>"
        f'<table class="meta">{meta}</table></header>'
    )


def _nav(content: ReportContent) -> str:
    items = [
        ("summary", "Summary of conclusions"),
        ("inputs", "Inputs"),
        ("screening", "Initial motion and contact forces"),
        ("overturning", "Overturning of rocking blocks"),
    ]
    if content.frequency is not None:
        items.append(("frequency", "Vertical frequency and jump check"))
    items += [("method", "Method, assumptions and limits"), ("references", "References")]
    if content.fragility is not None:
        items.append(("fragility", "Appendix A: fragility campaign"))
    links = "".join(f'<li><a href="#{key}">{title}</a></li>' for key, title in items)
    return f"<nav><b>Contents</b><ol>{links}</ol></nav>"


def _summary(content: ReportContent) -> str:
    items = "".join(
        f"<li>{_e(sentence).replace('m/s^2', 'm/s&#178;')}</li>" for sentence in content.summary
    )
    return (
        '<section id="summary"><h2>1 Summary of conclusions</h2>'
        f'<div class="summary"><ul>{items}</ul></div>'
        '<p class="note">Sense +/&#8722;: the sense of the horizontal inertial force along x '
        "(opposite to the support acceleration). a<sub>h</sub>, a<sub>v</sub>: horizontal and "
        "downward vertical support acceleration.</p></section>"
    )


def _inputs(doc: _Document, content: ReportContent) -> str:
    model = content.model
    g = model.gravity
    parts = ['<section id="inputs"><h2>2 Inputs</h2>']
    parts.append(
        "<p>The model file as read and checked, in SI units. Blocks are listed bottom to top; "
        "the interface below a block (friction, sliding restriction, contact names) belongs "
        "to it. x horizontal, z up, z = 0 on the support.</p>"
    )
    rows = []
    for e in model.excitations:
        rows.append(
            f"<tr{_attrs(excitation=e.name)}><td>{_e(e.name)}</td>"
            + _num(e.horizontal, 2, "horizontal")
            + _num(e.horizontal / g, 3, "horizontal_g")
            + _num(e.vertical, 2, "vertical")
            + _num(e.vertical / g, 3, "vertical_g")
            + "</tr>"
        )
    parts.append("<h3>2.1 Excitations</h3>")
    parts.append(
        doc.table(
            "Support accelerations (both horizontal senses are analysed; a<sub>v</sub> "
            "downward reduces the weight to m(g &#8722; a<sub>v</sub>)).",
            _head(
                "excitation",
                "a<sub>h</sub> [m/s<sup>2</sup>]",
                "a<sub>h</sub> [g]",
                "a<sub>v</sub> [m/s<sup>2</sup>]",
                "a<sub>v</sub> [g]",
            ),  # fmt: skip
            rows,
            table="excitations",
        )
    )
    parts.append("<h3>2.2 Configurations and blocks</h3>")
    for stack in model.configurations:
        rows = []
        for block in stack.blocks:
            left, right = block.contact_names
            rows.append(
                f"<tr{_attrs(configuration=stack.name, block=block.name)}>"
                f"<td>{_e(block.name)}</td>"
                + _num(block.mass, 0, "mass", grouped=True)
                + _num(block.inertia, 0, "inertia", grouped=True)
                + _num(block.centre[0], 3, "centre_x")
                + _num(block.centre[1], 3, "centre_z")
                + _num(
                    block.base_left,
                    3,
                    "base_left",
                    text=f"{_e(left)}: {_format(block.base_left, 3)}",
                )  # fmt: skip
                + _num(
                    block.base_right,
                    3,
                    "base_right",
                    text=f"{_e(right)}: {_format(block.base_right, 3)}",
                )  # fmt: skip
                + _num(block.base_level, 3, "base_level")
                + _num(block.friction.static, 3, "friction_static")
                + _num(block.friction.kinetic, 3, "friction_kinetic")
                + f"<td>{_e(block.sliding.value)}</td></tr>"
            )
        parts.append(
            doc.table(
                f"Configuration <i>{_e(stack.name)}</i>: blocks, bottom to top (mass m, inertia "
                "&#920;<sub>S</sub> about the centre S, contacts below the block with their "
                "names, static and kinetic friction &#956;<sub>0</sub>, &#956; below it).",
                _head(
                    "block",
                    "mass [kg]",
                    "&#920;<sub>S</sub> [kg m<sup>2</sup>]",
                    "x<sub>S</sub> [m]",
                    "z<sub>S</sub> [m]",
                    "left contact x [m]",
                    "right contact x [m]",
                    "base z [m]",
                    "&#956;<sub>0</sub> [-]",
                    "&#956; [-]",
                    "sliding",
                ),  # fmt: skip
                rows,
                cls="wide",
                table="blocks",
                configuration=stack.name,
            )
        )
    if model.configurations:
        parts.append(
            '<p class="note">sliding: <i>free</i> both ways; <i>none</i> never (wheel flanges); '
            "<i>no-right</i>/<i>no-left</i>: an end stop prevents sliding further that way "
            "relative to the body below.</p>"
        )
    if model.body_configurations:
        from freestand.report.bodies import inputs_html

        parts.append(inputs_html(doc, model))
    parts.append("<h3>2.3 Response spectra</h3>")
    if not model.spectra:
        parts.append(
            "<p>The model has no response spectra: the overturning and jump checks give no "
            "verdict.</p>"
        )
    for name, spectrum in model.spectra.items():
        frequencies = spectrum.frequency
        if frequencies.size > 12:
            frequencies = np.array([0.1, 0.25, 0.5, 1.0, 2.5, 5.0, 10.0, 20.0, 33.0])
        rows = [
            f"<tr{_attrs(spectrum=name, frequency=repr(float(f)))}>"
            + _num(f, 3, "frequency")
            + _num(spectrum.acceleration_at(f), 3, "spectral_acceleration")
            + _num(spectrum.acceleration_at(f) / g, 3, "spectral_acceleration_g")
            + "</tr>"
            for f in frequencies
        ]
        source = (
            "tabulated points"
            if frequencies is spectrum.frequency
            else f"sampled from {spectrum.frequency.size} points"
        )
        parts.append(
            doc.table(
                f"Spectrum <i>{_e(name)}</i> ({_e(spectrum.label)}): {_e(spectrum.direction)}, "
                f"{spectrum.damping * 100:g} % damping, {source}; log-log interpolation "
                "between points.",
                _head("f [Hz]", "S<sub>a</sub> [m/s<sup>2</sup>]", "S<sub>a</sub> [g]"),
                rows,
                cls="keep",
                table="spectrum",
                spectrum=name,
            )
        )
    if model.beam is not None:
        beam = model.beam.beam
        parts.append("<h3>2.4 Bridge as a beam</h3>")
        items = [
            ("span l [m]", beam.span, 3, "span"),
            ("Young's modulus E [Pa]", beam.youngs_modulus, 0, "youngs_modulus"),
            ("second moment I [m<sup>4</sup>]", beam.second_moment, 5, "second_moment"),
            ("beam mass m<sub>1</sub> [kg]", beam.mass, 0, "mass"),
            ("cart mass m<sub>2</sub> [kg]", beam.load_mass, 0, "load_mass"),
            (
                "cart rotary inertia [kg m<sup>2</sup>]",
                beam.load_rotary_inertia,
                0,
                "load_rotary_inertia",
            ),  # fmt: skip
            ("cart centre above the axis [m]", beam.load_height, 3, "load_height"),
            ("parking range, first [m]", model.beam.parking[0], 3, "parking_first"),
            ("parking range, last [m]", model.beam.parking[1], 3, "parking_last"),
        ]
        rows = [
            f"<tr><th>{label}</th>"
            + (
                _num(value, 0, quantity, text=f"{value:.4g}")
                if quantity == "youngs_modulus"
                else _num(value, digits, quantity, grouped=True)
            )
            + "</tr>"
            for label, value, digits, quantity in items
        ]
        parts.append(
            doc.table(
                "The bridge as a simply supported beam carrying the cart as a point mass "
                "(paper section 6).",
                "",
                rows,
                cls="keep",
                table="beam",
            )
        )
    parts.append("</section>")
    return "".join(parts)


def _flag_badge(case: InitialMotion) -> str:
    if case.status == "ambiguous":
        return (
            f'<span class="badge flag">ambiguous: {len(case.alternatives)} admissible states</span>'
        )
    if case.status == "inconsistent":
        return '<span class="badge flag">inconsistent: no admissible state</span>'
    if case.status == "free-flight":
        return '<span class="badge flag">free flight: a<sub>v</sub> &#8805; g</span>'
    return ""


def _case_attrs(case: InitialMotion, **more) -> str:
    return _attrs(
        configuration=case.configuration,
        excitation=case.excitation,
        sense=sense_label(case.sense),
        **more,
    )


def _screening(doc: _Document, content: ReportContent) -> str:
    model = content.model
    parts = [
        '<section id="screening"><h2>3 Initial motion and contact forces</h2>',
        "<p>The state of motion of every block just after the support acceleration sets in, "
        "and the contact forces at that instant (paper section 3). Accelerations are relative "
        "to the support, angular accelerations counter-clockwise positive; forces act on each "
        "block from the body below it, normal forces upward positive, the tangential force "
        "+x positive. Cases marked "
        '<span class="badge flag">ambiguous</span> admit several states: the table shows the '
        "one chosen by the rule 'static friction holds where it can, then fewest separations'; "
        "they need the engineer's judgement.</p>",
    ]
    for stack in model.configurations:
        cases = [c for c in content.cases if c.configuration == stack.name]
        parts.append(f"<h3>Configuration <i>{_e(stack.name)}</i></h3>")
        motion_rows, force_rows = [], []
        for case in cases:
            flag = _flag_badge(case)
            cls = ' class="flag"' if case.status in ("ambiguous", "inconsistent") else ""
            paper = case.paper_case or "(no case of the paper)"
            if not case.blocks:
                motion_rows.append(
                    f"<tr{cls}{_case_attrs(case, status=case.status)}>"
                    f"<td>{_e(case.excitation)}</td><td>{sense_label(case.sense)}</td>"
                    f'<td>&#8212;</td><td>none found</td><td colspan="3"></td>'
                    f'<td class="case">{_e(paper)} {flag}</td></tr>'
                )
            for k, state in enumerate(case.blocks):
                block = stack.blocks[stack.block_index(state.name)]
                note = (
                    f'<td class="case" rowspan="{len(case.blocks)}">{_e(paper)} {flag}</td>'
                    if k == 0
                    else ""
                )
                motion_rows.append(
                    f"<tr{cls}{_case_attrs(case, block=state.name, status=case.status)}>"
                    f"<td>{_e(case.excitation)}</td><td>{sense_label(case.sense)}</td>"
                    f"<td>{_e(state.name)}</td>"
                    f'<td class="motion" data-quantity="motion" '
                    f'data-text="{_e(state.motion.value)}">'
                    f"{_e(motion_label(state))}</td>"
                    + _num(state.angular_acceleration, 3, "angular_acceleration")
                    + _num(state.acceleration_x, 3, "acceleration_x")
                    + _num(state.acceleration_z, 3, "acceleration_z")
                    + note
                    + "</tr>"
                )
                left, right = block.contact_names
                force_rows.append(
                    f"<tr{cls}{_case_attrs(case, block=state.name, status=case.status)}>"
                    f"<td>{_e(case.excitation)}</td><td>{sense_label(case.sense)}</td>"
                    f"<td>{_e(state.name)}</td>"
                    + _num(state.base_normal_left, 0, "base_normal_left", grouped=True,
                           text=f"{_e(left)}: {_format(state.base_normal_left, 0, grouped=True)}")
                    + _num(state.base_normal_right, 0, "base_normal_right", grouped=True,
                           text=f"{_e(right)}: "
                           f"{_format(state.base_normal_right, 0, grouped=True)}")
                    + _num(state.base_tangential, 0, "base_tangential", grouped=True)
                    + "</tr>"
                )  # fmt: skip
        parts.append(
            doc.table(
                f"Initial type of motion and accelerations, configuration "
                f"<i>{_e(stack.name)}</i> (analogue of the paper's Tables 2 and 4). "
                "Accelerations are relative to the support: a block at rest on a body that "
                "moves has that body's acceleration. Blocks bottom to top.",
                _head(
                    "excitation",
                    "sense",
                    "body",
                    "type of motion",
                    "angular acc. [1/s<sup>2</sup>]",
                    "CoG acc. x [m/s<sup>2</sup>]",
                    "CoG acc. z [m/s<sup>2</sup>]",
                    "paper section 3 case",
                ),  # fmt: skip
                motion_rows,
                table="motion",
                configuration=stack.name,
            )
        )
        parts.append(
            doc.table(
                f"Contact forces on each body from the body below, configuration "
                f"<i>{_e(stack.name)}</i> (analogue of the paper's Tables 3 and 5).",
                _head(*FORCE_HEADERS[1:]),
                force_rows,
                table="forces",
                configuration=stack.name,
            )
        )
    flagged = content.flagged
    if flagged:
        items = "".join(
            f"<li{_case_attrs(c)}>{_e(c.configuration)}, {_e(case_label(c))}: {_e(c.status)} "
            f"({len(c.alternatives)} admissible state(s))</li>"
            for c in flagged
        )
        parts.append(f'<h4>Flagged cases</h4><ul id="flagged">{items}</ul>')
    if content.body_cases:
        from freestand.report.bodies import screening_html

        parts.append(screening_html(doc, model, content.body_cases))
    parts.append("</section>")
    return "".join(parts)


def _vertical_note(item: RockingAssessment) -> str:
    """The limits with the weight m (g - a_v), where the rocking cases have a downward a_v."""
    if item.half_sine_vertical is None:
        return ""
    exact = item.half_sine_vertical.operating_frequency.get("exact", float("nan"))
    exact_g = item.half_sine.operating_frequency.get("exact", float("nan"))

    def longer(f: float) -> str:
        return f"{0.5 / f:.2f} s" if math.isfinite(f) else "no duration up to 5 s"

    text = (
        f"; with the weight m (g &#8722; a<sub>v</sub>), a<sub>v</sub> = "
        f'<span data-quantity="vertical" data-value="{item.vertical!r}">{item.vertical:.2f}'
        "</span> m/s<sup>2</sup> downward as in the cases it rocks in, a half-sine pulse of "
        f"{item.operating_amplitude:.2f} m/s<sup>2</sup> overturns it if it lasts longer than "
        f'<span data-quantity="half_sine_duration_vertical">{longer(exact)}</span> '
        f"(exact; {longer(exact_g)} with m g)"
    )
    rect = item.rectangular_vertical
    if rect is not None and len(rect.amplitude):
        k = int(np.argmax(rect.amplitude))

        def seconds(value: float) -> str:
            return f"{value:.2f} s" if math.isfinite(value) else "none"

        text += (
            f", and a rectangular pulse of {rect.amplitude[k]:.2f} m/s<sup>2</sup> if it lasts "
            f'<span data-quantity="rectangular_duration_vertical">{seconds(rect.exact[k])}'
            f"</span> or longer ({seconds(item.rectangular.exact[k])} with m g)"
        )
    return text


def _assessment(doc: _Document, item: RockingAssessment, number: int) -> str:
    rocking = item.rocking
    data = dict(configuration=item.configuration, block=item.block, pivot=item.pivot)
    parts = [
        f'<section class="assessment"{_attrs(**data)}>'
        f"<h3>4.{number} The {_e(item.block)} in configuration <i>{_e(item.configuration)}</i>, "
        f"rocking about its {_e(item.pivot)} contact {_e(item.pivot_name)}</h3>",
        f"<p>It rocks in: {_e(', '.join(item.cases))}. It is treated as a rigid block rocking "
        "on the body below at rest (paper section 5), under a horizontal pulse. The tables and "
        "figures use the weight m g (the vertical support acceleration is not included)"
        + _vertical_note(item)
        + ".</p>",
    ]
    other = "left" if item.pivot == "right" else "right"
    rows = []
    for side, label in (("pivot", f"{item.pivot} (rocks first)"), ("other", other)):
        prop = rocking.about(side)
        rows.append(
            f"<tr{_attrs(side=side)}><td>{_e(label)}</td>"
            + _num(prop.R, 3, "R")
            + _num(prop.alpha, 4, "alpha")
            + _num(prop.inertia_about_pivot, 0, "inertia_about_pivot", grouped=True)
            + _num(prop.p, 3, "p")
            + _num(prop.uplift_threshold, 2, "uplift_threshold")
            + "</tr>"
        )
    parts.append(
        doc.table(
            f"Rocking properties (Housner 1963). Angular-velocity ratio at impact "
            f'<span data-quantity="restitution" data-value="{rocking.restitution!r}">'
            f"{rocking.restitution:.3f}</span> (Housner's energy ratio r = "
            f"{rocking.restitution**2:.3f}).",
            _head(
                "pivot",
                "R [m]",
                "&#945; [rad]",
                "I<sub>pivot</sub> [kg m<sup>2</sup>]",
                "p [rad/s]",
                "uplift g tan &#945; [m/s<sup>2</sup>]",
            ),  # fmt: skip
            rows,
            cls="keep",
            table="rocking",
            **data,
        )
    )

    def duration(value: float, quantity: str) -> str:
        if math.isfinite(value):
            return _num(value, 3, quantity)
        return _num(value, 3, quantity, text="no overturning")

    rect = item.rectangular
    rows = [
        f"<tr{_attrs(amplitude=repr(float(a)))}>"
        + _num(a, 2, "amplitude")
        + duration(h, "housner")
        + duration(x, "exact")
        + "</tr>"
        for a, h, x in zip(rect.amplitude, rect.housner, rect.exact, strict=True)
    ]
    parts.append(
        doc.table(
            "Rectangular pulse: shortest pulse duration that overturns the block, at the "
            "model's excitation levels (analogue of the paper's Fig. 6).",
            _head("amplitude [m/s<sup>2</sup>]", "Housner [s]", "exact [s]"),
            rows,
            cls="keep",
            table="rectangular",
            **data,
        )
    )
    from freestand.plot.overturning import (
        plot_pulse_limits,
        plot_rectangular_pulse,
        plot_spectrum_check,
    )

    parts.append(
        doc.figure(
            plot_rectangular_pulse(item.rectangular_curve),
            f"Rectangular pulse: pulses longer than the curve overturn the {_e(item.block)} "
            f"({_e(item.configuration)}); Housner's linearised and the exact nonlinear limit "
            "(analogue of the paper's Fig. 6).",
            figure="fig6",
            **data,
        )
    )
    table = item.half_sine_table
    rows = []
    for k, f in enumerate(table.frequency):
        cells = "".join(
            _num(table.limits[name][k], 2, name)
            if math.isfinite(table.limits[name][k])
            else _num(table.limits[name][k], 2, name, text="none found")
            for name in HALF_SINE_LIMITS
        )
        rows.append(
            f"<tr{_attrs(frequency=repr(float(f)))}>"
            + _num(f, 2, "frequency")
            + _num(0.5 / f, 3, "duration")
            + cells
            + "</tr>"
        )
    parts.append(
        doc.table(
            "Half-sine pulse: smallest peak acceleration that overturns the block "
            "[m/s<sup>2</sup>] (analogue of the paper's Fig. 7). Housner's criterion, which "
            "the paper applies, is "
            "unconservative (Makris and Roussos 2000).",
            _head(
                "f [Hz]",
                "duration [s]",
                "Housner [m/s<sup>2</sup>]",
                "Makris-Roussos [m/s<sup>2</sup>]",
                "exact [m/s<sup>2</sup>]",
            ),  # fmt: skip
            rows,
            cls="keep",
            table="half-sine",
            **data,
        )
    )
    op = item.operating_amplitude
    rows = []
    for name in HALF_SINE_LIMITS:
        f0 = item.half_sine.operating_frequency.get(name, float("nan"))
        rows.append(
            f"<tr{_attrs(limit=name)}><td>{_e(LIMIT_NAMES[name])}</td>"
            + (
                _num(f0, 2, "operating_frequency") + _num(0.5 / f0, 2, "operating_duration")
                if math.isfinite(f0)
                else '<td class="num" data-quantity="operating_frequency" data-value="nan">'
                "never in 0.1-20 Hz</td><td></td>"
            )
            + "</tr>"
        )
    parts.append(
        doc.table(
            f"A half-sine pulse of {op:.2f} m/s<sup>2</sup> (the largest excitation) overturns "
            "the block up to the frequency given, i.e. if it lasts longer than the duration.",
            _head("limit", "up to f [Hz]", "pulses longer than [s]"),
            rows,
            cls="keep",
            table="operating",
            **data,
        )
    )
    parts.append(
        doc.figure(
            plot_pulse_limits(item.half_sine),
            f"Half-sine pulse: smallest overturning peak acceleration of the {_e(item.block)} "
            f"({_e(item.configuration)}) against the pulse frequency; stronger pulses (above the "
            f"curves) overturn it (analogue of the paper's Fig. 7).",
            figure="fig7",
            **data,
        )
    )
    if item.spectrum is not None:
        rows = []
        for name, check in item.checks.items():
            badge = (
                '<span class="badge ok">no overturning</span>'
                if check.verdict == "no overturning"
                else f'<span class="badge risk">{_e(check.verdict)}</span>'
            )
            rows.append(
                f"<tr{_attrs(limit=name)}><td>{_e(LIMIT_NAMES.get(name, name))}</td>"
                f'<td data-quantity="verdict" data-text="{_e(check.verdict)}">{badge}</td>'
                + _num(check.min_ratio, 2, "min_ratio")
                + _num(check.frequency_at_min, 2, "frequency_at_min")
                + _num(check.limit_at_min, 2, "limit_at_min")
                + _num(check.spectrum_at_min, 2, "spectrum_at_min")
                + "</tr>"
            )
        governing = item.governing_check
        verdict = (
            f'<p><b>Verdict:</b> <span data-quantity="overturning_verdict" '
            f'data-text="{_e(item.verdict)}">{_e(item.verdict)}</span>'
            + (
                f"; smallest margin {governing.min_ratio:.2f} "
                f"({_e(limit_title(governing.limit_name))} limit, "
                f"{governing.frequency_at_min:.2f} Hz)."
                if governing is not None
                else "."
            )
            + "</p>"
        )
        parts.append(
            doc.table(
                f"Response spectrum <i>{_e(item.spectrum.label)}</i> against the overturning "
                "limits (analogue of the paper's Fig. 8): the margin is the smallest ratio "
                "limit / spectral acceleration; above 1 the spectrum does not overturn the "
                "block.",
                _head(
                    "limit",
                    "verdict",
                    "smallest margin [-]",
                    "at f [Hz]",
                    "limit there [m/s<sup>2</sup>]",
                    "S<sub>a</sub> there [m/s<sup>2</sup>]",
                ),  # fmt: skip
                rows,
                cls="keep",
                table="spectrum-check",
                **data,
            )
        )
        parts.append(verdict)
        parts.append(
            doc.figure(
                plot_spectrum_check(item.half_sine, item.spectrum, item.checks),
                f"Horizontal response spectrum <i>{_e(item.spectrum.label)}</i> against the "
                f"overturning limits of the {_e(item.block)} ({_e(item.configuration)}); "
                "squares mark the smallest margins (analogue of the paper's Fig. 8).",
                figure="fig8",
                **data,
            )
        )
    else:
        parts.append(
            "<p>The model has no horizontal spectrum, so no spectrum check (paper Fig. 8) is "
            "made; add a <code>[[spectrum]]</code> with <code>direction = "
            '"horizontal"</code>.</p>'
        )
    parts.append("</section>")
    return "".join(parts)


def _overturning(doc: _Document, content: ReportContent) -> str:
    parts = [
        '<section id="overturning"><h2>4 Overturning of rocking blocks</h2>',
        "<p>Every block that lifts (rocks, or slides and rocks) in some screened case is "
        "assessed once per configuration and pivot, as a rigid block rocking on a body at "
        "rest under horizontal pulses (paper section 5): Housner's linearised limits, the "
        "corrected linearised half-sine limit of Makris and Roussos, and the exact nonlinear "
        "limit with impacts. The half-sine limit is compared with the model's horizontal "
        "spectrum, reading the spectral acceleration at f as the peak of a pulse of "
        "frequency f, as the paper does.</p>",
    ]
    if not content.overturning and content.model.configurations:
        blocks = "block of the planar configurations" if content.body_cases else "block"
        parts.append(
            f'<p id="no-rocking">No {blocks} lifts in any screened case: no overturning '
            "assessment is needed.</p>"
        )
    if content.body_histories:
        from freestand.report.bodies import histories_html

        parts.append(histories_html(doc, content.body_histories))
    elif content.body_cases:
        parts.append(
            '<p id="bodies-not-assessed">The 3-D bodies (section 3) are not assessed for '
            "overturning: that needs their time history under a ground record "
            "(<code>freestand report --record</code>).</p>"
        )
    for number, item in enumerate(content.overturning, start=1):
        parts.append(_assessment(doc, item, number))
    for skipped in content.skipped:
        parts.append(
            f'<p class="skipped"{_attrs(configuration=skipped.configuration, block=skipped.block)}>'
            f"The {_e(skipped.block)} in <i>{_e(skipped.configuration)}</i> rocks but is not "
            f"assessed: {_e(skipped.reason)}.</p>"
        )
    parts.append("</section>")
    return "".join(parts)


def _frequency(doc: _Document, item: FrequencyAssessment) -> str:
    sweep, jump = item.sweep, item.jump
    parts = [
        '<section id="frequency"><h2>5 Vertical frequency and jump check</h2>',
        "<p>The bridge is a simply supported beam carrying the cart as a point mass (paper "
        "section 6). Its lowest vertical natural frequency is estimated by Dunkerley's formula "
        "(a lower bound, paper eqs. 1-4) and computed exactly for the continuous beam. Where "
        "the vertical spectral acceleration at that frequency reaches g the bridge's upward "
        "acceleration can exceed gravity and the cart may lose contact with its rails (jump). "
        "The spectrum is read at the largest value between the two frequency estimates.</p>",
    ]
    low, high = item.dunkerley_range
    exact_low, exact_high = item.exact_range
    rows = [
        "<tr><th>Dunkerley [Hz]</th>"
        + _num(low, 2, "dunkerley_min")
        + _num(high, 2, "dunkerley_max")
        + "</tr>",
        "<tr><th>exact [Hz]</th>"
        + _num(exact_low, 2, "exact_min")
        + _num(exact_high, 2, "exact_max")
        + "</tr>",
        "<tr><th>bare beam [Hz]</th>" + _num(sweep.bare_beam, 2, "bare_beam") + "<td></td></tr>",
    ]
    parts.append(
        doc.table(
            f"Lowest vertical frequency over the parking range {item.parking[0]:.2f}-"
            f"{item.parking[1]:.2f} m.",
            _head("estimate", "lowest [Hz]", "highest [Hz]"),
            rows,
            cls="keep",
            table="frequency-range",
        )
    )
    if jump is not None:
        runs = ", ".join(f"{a:.2f}-{b:.2f} m" for a, b in jump.risk_intervals) or "none"
        status = (
            '<span class="badge risk">jump possible</span>'
            if jump.jump_possible
            else '<span class="badge ok">no jump</span>'
        )
        parts.append(
            f'<p id="jump-verdict"><b>Jump check</b> against <i>{_e(jump.spectrum_label)}</i>: '
            f'<span data-quantity="jump_status" data-text="{_e(jump.status)}">{status}</span>; '
            f'positions at risk: <span id="risk-intervals">{_e(runs)}</span>; smallest margin '
            f"g &#8722; S<sub>a</sub> = "
            f'<span data-quantity="minimum_margin" data-value="{jump.minimum_margin!r}">'
            f"{_format(jump.minimum_margin, 2)}</span> m/s<sup>2</sup> at "
            f'<span data-quantity="minimum_margin_position" '
            f'data-value="{jump.minimum_margin_position!r}">'
            f"{jump.minimum_margin_position:.2f}</span> m.</p>"
        )
        for note in jump.notes:
            parts.append(f'<p class="note">Note: {_e(note)}</p>')
    else:
        parts.append(
            "<p>The model has no vertical spectrum, so the jump check is not made; add a "
            '<code>[[spectrum]]</code> with <code>direction = "vertical"</code>.</p>'
        )
    step = max(1, len(sweep.position) // 25)
    keep = set(range(0, len(sweep.position), step)) | {len(sweep.position) - 1}
    keep |= {int(k) for k in np.flatnonzero(sweep.within(item.parking))[[0, -1]]}
    if jump is not None:
        changes = np.flatnonzero(np.diff(jump.at_risk.astype(int)))
        keep |= {int(k) for k in changes} | {int(k) + 1 for k in changes}
    rows = []
    for k in sorted(keep):
        position = float(sweep.position[k])
        cls = ' class="risk"' if jump is not None and jump.at_risk[k] else ""
        cells = (
            _num(position, 2, "position")
            + _num(sweep.dunkerley[k], 2, "dunkerley")
            + _num(sweep.exact[k], 2, "exact")
        )
        if jump is not None:
            cells += (
                _num(jump.spectral_acceleration[k], 2, "spectral_acceleration")
                + _num(jump.ratio[k], 2, "ratio_to_g")
                + f'<td data-quantity="verdict" data-text="{_e(jump.verdict[k])}">'
                f"{_e(jump.verdict[k])}</td>"
            )
        rows.append(f"<tr{cls}{_attrs(position=repr(position))}>{cells}</tr>")
    headers = ["position d [m]", "Dunkerley [Hz]", "exact [Hz]"]
    if jump is not None:
        headers += ["S<sub>a,v</sub> [m/s<sup>2</sup>]", "S<sub>a,v</sub> / g [-]", "verdict"]
    parts.append(
        doc.table(
            "Lowest vertical frequency and jump check against the cart's position from the "
            "left support (analogue of the paper's Fig. 9); shaded rows: the cart may jump.",
            _head(*headers),
            rows,
            table="frequency",
        )
    )
    from freestand.plot.frequency import plot_frequency_sweep

    parts.append(
        doc.figure(
            plot_frequency_sweep(
                sweep, parking=item.parking, jump=jump, vertical_spectrum=item.spectrum
            ),
            "Lowest vertical natural frequency of the bridge against the cart's position "
            "(analogue of the paper's Fig. 9); grey: parking range; red band: frequencies at "
            "which the vertical spectrum reaches g; thick red line: positions where the cart "
            "may jump.",
            figure="fig9",
        )
    )
    parts.append("</section>")
    return "".join(parts)


def _method(content: ReportContent) -> str:
    number = 6 if content.frequency is not None else 5
    bodies = ""
    if content.body_cases:
        from freestand.report.bodies import HISTORY_METHOD_HTML, METHOD_HTML, NO_HISTORY_HTML

        bodies = METHOD_HTML + (HISTORY_METHOD_HTML if content.body_histories else NO_HISTORY_HTML)
    return f"""<section id="method"><h2>{number} Method, assumptions and limits</h2>
<h4>Initial motion and contact forces</h4>
<p>Each configuration is a plane stack of rigid blocks, each resting on the one below through
two point contacts (wheels or edges) with Coulomb friction, the bottom one on the support. The
support's horizontal acceleration a<sub>h</sub> (both senses) and downward vertical
acceleration a<sub>v</sub> act as inertial forces on the stack at rest, the weights being
m(g &#8722; a<sub>v</sub>). The instantaneous accelerations and contact forces follow from the
equations of motion with the contact conditions (no tension, no penetration, friction within
its cone, sliding against friction), solved as a complementarity problem over every
combination of rest, sliding, rocking and lift-off at each interface (paper section 3,
generalised to any stack). Where several combinations are admissible the case is flagged; the
state shown is the one where static friction holds where it can, then with the fewest
separations.</p>
<h4>Overturning</h4>
<p>A block that lifts is checked as a rigid block rocking about its pivot on a body at rest
(the inverted pendulum of Housner 1963, as in paper section 5): rocking properties R,
&#945;, p and the angular-velocity ratio at impact from conservation of angular momentum;
overturning under rectangular and half-sine pulses by Housner's linearised formulas, by the
corrected linearised half-sine limit of Makris and Roussos (2000, eq. 27), and by integrating
the exact nonlinear equation of rocking with impacts (Zhang and Makris 2001). A response
spectrum is compared with the half-sine limits by reading the spectral acceleration at f as
the peak of a pulse of that frequency. Housner's half-sine criterion, which the paper applies,
is unconservative: a block can overturn in free rocking after the pulse.</p>
<h4>Vertical frequency and jump</h4>
<p>The bridge is a simply supported uniform beam carrying the cart as a rigid point mass
(paper section 6). Dunkerley's formula gives a lower bound of the lowest vertical frequency;
the exact value of the continuous beam with the point mass is computed as well. The cart may
jump where the vertical spectral acceleration between the two estimates reaches g.</p>
{bodies}<h4>Assumptions and limits</h4>
<ul>
<li>The blocks are rigid; the structure's flexibility enters only through the excitation levels
(for example the elastic case's spectral acceleration at the structure's mode) and the beam
model of section 6.</li>
<li>The screening describes the <i>initial</i> motion only: what starts to move and how, not the
later history. A time-history analysis (<code>freestand simulate</code>) follows it where
needed.</li>
<li>The overturning check treats one block on a body at rest under a single pulse; real
earthquake motion is a sequence of pulses. Its tables and figures use the weight m g; where
the cases in which the block rocks have a downward vertical acceleration, the text gives the
limits with the weight m (g &#8722; a<sub>v</sub>) as well, which are lower.</li>
<li>Spectrum checks are as good as the spectra: the model's spectra are used as given
(check their source and damping in section 2).</li>
<li>As the paper says, earthquake-induced base excitations are much more complex than these
models; the screening gives a preliminary qualification of the response to be expected.</li>
</ul>
</section>"""


def _references(number: int) -> str:
    items = "".join(f'<li id="ref-{key}">{_e(text)}</li>' for key, text in REFERENCES)
    return (
        f'<section id="references"><h2>{number} References</h2>'
        f'<ol class="references">{items}</ol>'
        '<p class="note">Design spectra of RG 1.60 or EN 1998-1 are used where the model '
        "file asks for them (spectrum kinds <code>rg1.60</code>, <code>en1998</code>).</p>"
        "</section>"
    )


def render_html(content: ReportContent) -> str:
    """The whole report as one self-contained HTML document.

    Parameters
    ----------
    content : ReportContent
        From :func:`freestand.report.content.collect_report`.

    Returns
    -------
    str
        The HTML text (UTF-8, no external references).
    """
    doc = _Document()
    body = [
        _header(content),
        _nav(content),
        _summary(content),
        _inputs(doc, content),
        _screening(doc, content),
        _overturning(doc, content),
    ]
    if content.frequency is not None:
        body.append(_frequency(doc, content.frequency))
    last = 6 if content.frequency is not None else 5
    body += [_method(content), _references(last + 1)]
    if content.fragility is not None:
        from freestand.report.fragility import fragility_html

        body.append(fragility_html(doc, content.fragility))
    title = f"Seismic screening report: {content.model.name}"
    return (
        "<!DOCTYPE html>\n"
        '<html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        f'<meta name="generator" content="freestand {_e(content.version)}">'
        f"<title>{_e(title)}</title><style>{CSS}</style></head>\n"
        "<body>" + "\n".join(body) + "</body></html>\n"
    )
