"""The report's parts for 3-D configurations: inputs, screening by direction, method.

:func:`collect_body_cases` screens every 3-D configuration of a model as
``freestand screen`` does (24 directions); the HTML functions format the
result for :mod:`freestand.report.html`: the bodies and the excitations'
components among the inputs, a table per configuration and excitation with
the initial motion, uplift threshold and contact forces in every direction
(each number with its full-precision ``data-value``), the sentence of the
summary, and the polar figure of each configuration.
"""

from __future__ import annotations

import math

from freestand.core.body import Body, Box
from freestand.core.contact.body_screening import BodyScreeningCase, screen_body_configuration
from freestand.io.results import degrees
from freestand.report.markup import Document, data_attrs, esc, number_cell, table_head
from freestand.report.tables import body_case_sentence, body_direction_rows

#: Directions of the report's sweep (every 15 deg), as ``freestand screen`` by default.
REPORT_DIRECTIONS = 24

_MS2 = "m/s<sup>2</sup>"


def collect_body_cases(model) -> tuple[BodyScreeningCase, ...]:
    """The screening of every 3-D configuration of ``model`` under its excitations."""
    return tuple(
        case
        for configuration in model.body_configurations
        for case in screen_body_configuration(
            configuration, model.excitations, model.gravity, count=REPORT_DIRECTIONS
        )
    )


def body_sentences(model, cases: tuple[BodyScreeningCase, ...], histories: tuple = ()) -> list[str]:
    """The summary's sentences: what each body does per excitation, what it did under the
    record (``histories``: one :class:`~freestand.api.body_simulation.BodySimulationResult`
    per 3-D configuration), or what is not assessed without one."""
    bodies = {c.name: c.body for c in model.body_configurations}
    sentences = [
        f"3-D configuration {case.configuration}. "
        + body_case_sentence(case, bodies[case.configuration])
        for case in cases
    ]
    lifting = sorted(
        {
            case.configuration
            for case in cases
            for state in case.directions
            if state.motion.value in ("rock", "slide-rock", "free-flight")
        }
    )
    if lifting and not histories:
        sentences.append(
            f"The 3-D bodies that lift ({', '.join(lifting)}) are not assessed for overturning "
            "here: that needs their time history under a ground record (freestand report "
            "--record, or freestand simulate)."
        )
    return sentences + [history_sentence(result) for result in histories]


def history_sentence(result) -> str:
    """What the body did under the record, in words (its status when it did not complete)."""
    core = result.core
    name = f"the {core.body} ({result.configuration})"
    record = f"Under the record {result.record}{_turned(result)}"
    if result.status == "failed":
        return (
            f"{record} the time history of {name} failed ({result.message}); up to there its "
            f"largest tilt is {core.max_rotation:.3g} rad and its largest slide "
            f"{1000.0 * core.max_slide:.1f} mm."
        )
    if core.overturned:
        verdict = f"overturns at t = {core.overturn_time:.2f} s"
    else:
        verdict = "does not overturn" + (
            ""
            if result.status == "completed"
            else f" by the end of the simulation ({result.message})"
        )
    motion = (
        f"lifts (largest tilt {core.max_rotation:.3g} rad, {math.degrees(core.max_rotation):.1f} "
        "deg)"
        if core.uplift
        else "does not lift"
    )
    return (
        f"{record} {name} {motion}, slides {1000.0 * core.max_slide:.1f} mm at most, twists "
        f"{1000.0 * core.max_twist:.1f} mrad at most and {verdict}."
    )


def _turned(result) -> str:
    return f" (turned {result.angle:g} deg)" if result.angle else ""


def _dimensions(body: Body) -> str:
    shape = body.shape
    if isinstance(shape, Box):
        return "box, l<sub>x</sub> &#215; l<sub>y</sub> &#215; l<sub>z</sub> = " + " &#215; ".join(
            f"{side:.3f}" for side in shape.size
        ) + " m"  # fmt: skip
    hollow = f", r = {shape.inner_radius:.3f} m" if shape.inner_radius else ""
    return f"cylinder, R = {shape.radius:.3f} m{hollow}, H = {shape.height:.3f} m"


def inputs_html(doc: Document, model) -> str:
    """The 3-D bodies and the excitations' horizontal components, for section 2."""
    rows = []
    for configuration in model.body_configurations:
        body = configuration.body
        inertia = body.inertia
        rows.append(
            f"<tr{data_attrs(configuration=configuration.name, block=body.name)}>"
            f"<td>{esc(body.name)}</td><td>{_dimensions(body)}</td>"
            + number_cell(body.mass, 0, "mass", grouped=True)
            + "".join(
                number_cell(c, 3, f"centre_{axis}")
                for c, axis in zip(body.centre, "xyz", strict=True)
            )
            + "".join(
                number_cell(inertia[k, k], 1, f"inertia_{axis}{axis}", grouped=True)
                for k, axis in enumerate("xyz")
            )
            + number_cell(body.friction.static, 3, "friction_static")
            + number_cell(body.friction.kinetic, 3, "friction_kinetic")
            + "</tr>"
        )
    parts = [
        doc.table(
            "3-D configurations: one rigid body each on the support (x, y horizontal, z up; the "
            "centre of gravity G from the base centre; inertia about G, diagonal of the body "
            "frame; static and kinetic friction &#956;<sub>0</sub>, &#956; on the support, "
            "circular cone).",
            table_head(
                "body",
                "shape",
                "mass [kg]",
                "x<sub>G</sub> [m]",
                "y<sub>G</sub> [m]",
                "z<sub>G</sub> [m]",
                "I<sub>xx</sub> [kg m<sup>2</sup>]",
                "I<sub>yy</sub> [kg m<sup>2</sup>]",
                "I<sub>zz</sub> [kg m<sup>2</sup>]",
                "&#956;<sub>0</sub> [-]",
                "&#956; [-]",
            ),  # fmt: skip
            rows,
            cls="wide",
            table="bodies",
        )
    ]
    rows = []
    for case in _first_per_excitation(collect_body_cases(model)):
        rows.append(
            f"<tr{data_attrs(excitation=case.excitation)}><td>{esc(case.excitation)}</td>"
            + number_cell(case.x, 2, "x")
            + number_cell(case.y, 2, "y")
            + number_cell(case.horizontal, 2, "horizontal")
            + number_cell(degrees(case.excitation_direction), 1, "excitation_direction")
            + "</tr>"
        )
    parts.append(
        doc.table(
            "Horizontal components of the excitations for the 3-D configurations: the magnitude "
            "a = &#8730;(x<sup>2</sup> + y<sup>2</sup>) is applied in every direction of the "
            "screening; the direction of (x, y) is the excitation's own.",
            table_head(
                "excitation", f"x [{_MS2}]", f"y [{_MS2}]", f"a [{_MS2}]", "direction [deg]"
            ),  # fmt: skip
            rows,
            cls="keep",
            table="excitation-components",
        )
    )
    return "".join(parts)


def _first_per_excitation(cases) -> list[BodyScreeningCase]:
    seen, first = set(), []
    for case in cases:
        name = case.excitation
        if name not in seen:
            seen.add(name)
            first.append(case)
    return first


def screening_html(doc: Document, model, cases: tuple[BodyScreeningCase, ...]) -> str:
    """Section 3's part for the 3-D configurations: a table per excitation, the figure."""
    from freestand.plot.body_screening import shape_text, uplift_polar_figure

    parts = [
        "<h3>3-D configurations: initial motion by direction</h3>",
        "<p>Each 3-D body is screened in 24 directions of the horizontal support acceleration "
        "(every 15&#176; from +x towards +y) under the excitation's horizontal magnitude, and in "
        "the excitation's own direction (last row). The uplift threshold a* = (g &#8722; "
        "a<sub>v</sub>) &#961;(&#966;)/h is where the line of action of weight and inertial "
        "force leaves the base; the body rocks about the edge, corner or rim point it crosses "
        "there when static friction holds the pivot, else it slides or slides and rocks. Forces "
        "act on the body from the support; n/a where not computed (slide-rock).</p>",
    ]
    for configuration in model.body_configurations:
        own = [case for case in cases if case.configuration == configuration.name]
        body = configuration.body
        parts.append(
            f"<h4{data_attrs(configuration=configuration.name)}>Configuration "
            f"<i>{esc(configuration.name)}</i>: the {esc(body.name)}, "
            f"{esc(shape_text(body))}</h4>"
        )
        for case in own:
            parts.append(_case_table(doc, case, body))
        parts.append(
            doc.figure(
                uplift_polar_figure(own, {configuration.name: body}),
                f"Uplift threshold and initial motion of the {esc(body.name)} "
                f"(<i>{esc(configuration.name)}</i>) by direction of the horizontal support "
                "acceleration: the closed curve is a*(&#966;) (it stays seated inside), the "
                "dashed circle the slide threshold &#956;<sub>0</sub>(g &#8722; a<sub>v</sub>), "
                "each dotted circle an excitation's magnitude with the motion in every direction "
                "as coloured markers and a star in its own direction.",
                figure="uplift-polar",
                configuration=configuration.name,
            )
        )
    return "".join(parts)


def _case_table(doc: Document, case: BodyScreeningCase, body: Body) -> str:
    rows = []
    quantities = ("uplift_threshold", "normal_force", "friction_x", "friction_y",
                  "angular_acceleration")  # fmt: skip
    for row in body_direction_rows(case):
        direction, label, *numbers = row.cells
        own = bool(row.flag)
        cells = "".join(
            number_cell(value, digits, quantity, grouped=digits == 0)
            for value, digits, quantity in zip(numbers, (3, 0, 0, 0, 3), quantities, strict=True)
        )
        where = data_attrs(
            configuration=case.configuration, excitation=case.excitation, own=str(own).lower()
        )
        shown = f"{direction:.1f}" + (" (own)" if own else "")
        rows.append(
            f"<tr{where}>"
            + number_cell(direction, 1, "direction", text=shown)
            + f'<td class="motion" data-quantity="motion" data-text="{esc(label)}">'
            + f"{esc(label)}</td>"
            + cells
            + "</tr>"
        )
    return doc.table(
        f"The {esc(body.name)} under <i>{esc(case.excitation)}</i>: a = {case.horizontal:.2f} "
        f"{_MS2} in each direction, a<sub>v</sub> = {case.vertical:.2f} {_MS2}. "
        + esc(body_case_sentence(case, body)).replace("m/s^2", _MS2),
        table_head(
            "direction [deg]",
            "type of motion",
            f"uplift threshold [{_MS2}]",
            "normal [N]",
            "friction x [N]",
            "friction y [N]",
            "angular acc. [1/s<sup>2</sup>]",
        ),  # fmt: skip
        rows,
        table="body-directions",
        configuration=case.configuration,
        excitation=case.excitation,
    )


#: The method section's paragraph for 3-D configurations.
METHOD_HTML = """<h4>3-D bodies</h4>
<p>A 3-D configuration is one rigid box or cylinder standing on the support, with Coulomb
friction on the circular cone. From rest, under a horizontal support acceleration a in the
direction &#966; and a downward vertical one a<sub>v</sub>, it stays seated while the line of
action of its weight and inertial force meets the base inside its outline (Housner 1963,
generalised): uplift begins at a* = (g &#8722; a<sub>v</sub>) &#961;(&#966;)/h, &#961; the
distance from the centre of gravity's projection to the outline against &#966;. It rests while
a &#8804; a* and a &#8804; &#956;<sub>0</sub>(g &#8722; a<sub>v</sub>); it rocks about the edge,
corner or rim point when a &gt; a* and static friction holds the pivot; it slides flat when the
base breaks away and the kinetic friction's moment keeps it flat (&#956; h &#8804; &#961;), in the
direction of the inertial force; it slides and rocks otherwise. Each excitation's horizontal
magnitude &#8730;(x<sup>2</sup> + y<sup>2</sup>) is applied in every direction of the sweep. The
screening gives the first instant only.</p>
"""

#: The method section's sentence on the 3-D time history without a record.
NO_HISTORY_HTML = """<p>Without a ground record (<code>freestand report --record</code>) the
rocking and overturning of 3-D bodies over time are not assessed in this report.</p>
"""


def histories_html(doc: Document, histories: tuple) -> str:
    """Section 4's part for the 3-D configurations under the record: a peak table, the
    figures of each (time history and plan view)."""
    from freestand.plot.body_history import plan_view_figure, time_history_figure

    first = histories[0]
    support = first.support
    parts = [
        '<h3 id="body-histories">3-D configurations under the record</h3>',
        f"<p>Each 3-D configuration is simulated under the record "
        f"<b>{esc(first.record)}</b>{esc(_turned(first))}: x, y and the downward vertical "
        f"support acceleration at a step of {support.time_step:g} s over {support.duration:g} s "
        f"(peaks |(a<sub>x</sub>, a<sub>y</sub>)| = {first.peak_horizontal:.2f} {_MS2}, "
        f"|a<sub>v</sub>| = {float(abs(support.vertical).max()):.2f} {_MS2}), and after it "
        "until the body rests (at most 10 s): exact rigid contact with Coulomb friction on the "
        "circular cone, plastic impacts (section 5).</p>",
    ]
    rows = []
    for result in histories:
        core = result.core
        overturn = core.overturn_time if core.overturned else math.nan
        rows.append(
            f"<tr{data_attrs(configuration=result.configuration, block=core.body)}>"
            f"<td>{esc(result.configuration)}</td><td>{esc(core.body)}</td>"
            f"<td>{esc(result.status)}</td>"
            + number_cell(core.max_rotation, 4, "max_rotation")
            + number_cell(1000.0 * core.max_slide, 1, "max_slide_mm")
            + number_cell(1000.0 * core.max_twist, 1, "max_twist_mrad")
            + f"<td>{'yes' if core.uplift else 'no'}</td>"
            + f"<td>{'yes' if core.free_flight else 'no'}</td>"
            + number_cell(overturn, 2, "overturn_time", text=None if core.overturned else "no")
            + number_cell(float(core.time[-1]), 2, "end_time")
            + "</tr>"
        )
    parts.append(
        doc.table(
            "Peak response of the 3-D bodies under the record: the largest tilt (angle of the "
            "body's axis from the vertical), slide of the base centre and twist about the "
            "vertical; uplift (a base point lifted), free flight (the body left the support), "
            "overturning, and the time simulated (to rest, overturning, the cap, or the failure "
            "the status says).",
            table_head(
                "configuration",
                "body",
                "status",
                "max tilt [rad]",
                "max slide [mm]",
                "max twist [mrad]",
                "uplift",
                "free flight",
                "overturned at [s]",
                "simulated to [s]",
            ),
            rows,
            cls="wide",
            table="body-histories",
        )
    )
    for result in histories:
        name = f"the {esc(result.core.body)} (<i>{esc(result.configuration)}</i>)"
        parts.append(f"<p>{esc(history_sentence(result)).replace('m/s^2', _MS2)}</p>")
        parts.append(
            doc.figure(
                time_history_figure(result),
                f"Time history of {name} under the record: support accelerations, the motion "
                "(rest, slide, rocking about an edge or a corner, rolling on the rim, free "
                "flight), the tilt with lift-offs and impacts, the slide of the base centre "
                "with slips, the twist and the contact forces.",
                figure="body-history",
                configuration=result.configuration,
            )
        )
        parts.append(
            doc.figure(
                plan_view_figure(result),
                f"{name[0].upper()}{name[1:]} seen from above: the path of the base centre and "
                "the tilt vector (the tilt along the horizontal projection of the body's axis), "
                "coloured by time.",
                figure="body-plan",
                configuration=result.configuration,
            )
        )
    return "".join(parts)


#: The method section's paragraph on the 3-D time history (with a record).
HISTORY_METHOD_HTML = """<p>Under a ground record (<code>freestand report --record</code>), each
3-D body is simulated from rest under the three components (x, y and the downward vertical),
event by event: it rests, slides and twists on its base (Coulomb friction on the circular cone,
a uniform pressure's twist torque with the ellipsoidal limit surface of Howe and Cutkosky 1996),
rocks about an edge or a corner, rocks and rolls on its rim (a cylinder), flies and overturns;
the contact is rigid and exact (no compliance), impacts are plastic at the impacting points
(Housner's law in a plane), and every event is located in time. The simulation goes on after the
record until the body rests (at most 10 s). A history whose contact the engine lost (a base
point more than 10<sup>-6</sup> of the base width below the support) stops there with the status
<i>failed</i>, and its peaks are those up to there.</p>
"""
