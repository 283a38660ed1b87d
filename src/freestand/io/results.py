"""Results as JSON-ready documents (``--json`` output, reports)."""

from __future__ import annotations

import math
from collections.abc import Sequence

from freestand.core.body import Body, Box
from freestand.core.contact.body_screening import (
    BodyInitialMotion,
    BodyScreeningCase,
    pivot_label,
)
from freestand.core.contact.screening import BlockState, ForceEnvelope, InitialMotion


def _sense(sense: int) -> str:
    return "+" if sense > 0 else "-"


def block_state_document(state: BlockState) -> dict:
    """One block's state: motion, accelerations [m/s^2, rad/s^2], base forces [N]."""
    return {
        "name": state.name,
        "motion": state.motion.value,
        "pivot": state.pivot,
        "slide_direction": state.slide_direction,
        "acceleration": {
            "x": state.acceleration_x,
            "z": state.acceleration_z,
            "angular": state.angular_acceleration,
        },
        "base": {
            "left": state.base_normal_left,
            "right": state.base_normal_right,
            "friction": state.base_tangential,
        },
    }


def initial_motion_document(case: InitialMotion) -> dict:
    """One screening case (configuration, excitation, sense) as a dict."""
    document = {
        "configuration": case.configuration,
        "excitation": case.excitation,
        "sense": _sense(case.sense),
        "horizontal": case.horizontal,
        "vertical": case.vertical,
        "status": case.status,
        "ambiguous": case.ambiguous,
        "paper_case": case.paper_case,
        "blocks": [block_state_document(state) for state in case.blocks],
    }
    if len(case.alternatives) > 1:
        document["alternatives"] = [
            [block_state_document(state) for state in alternative]
            for alternative in case.alternatives
        ]
    if case.diagnostics is not None:
        document["diagnostics"] = {
            "modes_tried": case.diagnostics.modes_tried,
            "singular_modes": case.diagnostics.singular_modes,
            "kinetic_only_modes": case.diagnostics.kinetic_only_modes,
            "relaxed": case.diagnostics.relaxed,
            "rule": case.diagnostics.rule,
        }
    return document


def screening_document(model_name: str, cases: Sequence[InitialMotion], gravity: float) -> dict:
    """The ``freestand screen --json`` document.

    Conventions: ``sense`` is the sense of the horizontal inertial force along
    x; ``vertical`` the signed vertical support acceleration [m/s^2], positive
    downward (weight m (g - a_v)); accelerations are relative to the support in the global frame (x
    right, z up, angular counter-clockwise); ``base`` holds the forces on the
    block from the body below: normal forces at its left and right contact [N]
    and the total tangential force [N], +x positive.
    """
    return {
        "model": model_name,
        "gravity": gravity,
        "cases": [initial_motion_document(case) for case in cases],
    }


def envelope_document(item: ForceEnvelope) -> dict:
    """One block's envelope of contact forces [N] with the cases that give them."""
    return {
        "configuration": item.configuration,
        "block": item.block,
        "left": {"normal": item.normal_left, "case": item.cases[0]},
        "right": {"normal": item.normal_right, "case": item.cases[1]},
        "tangential": {"magnitude": item.tangential, "case": item.cases[2]},
    }


def _finite(value: float) -> float | None:
    value = float(value)
    return value if math.isfinite(value) else None


def degrees(angle: float | None) -> float | None:
    """An angle [rad] in degrees over [0, 360), rounded to 1e-9 deg (None stays None)."""
    return None if angle is None else round(math.degrees(angle) % 360.0, 9) % 360.0


def body_state_document(state: BodyInitialMotion) -> dict:
    """A 3-D body's state in one direction: motion, pivot, threshold [m/s^2], forces [N]."""
    return {
        "direction": degrees(state.direction),
        "motion": state.motion.value,
        "pivot": state.pivot,
        "slide_direction": degrees(state.slide_direction),
        "uplift_threshold": _finite(state.uplift_threshold),
        "forces": {
            "normal": _finite(state.normal_force),
            "tangential": {
                "x": _finite(state.tangential_force[0]),
                "y": _finite(state.tangential_force[1]),
            },
        },
        "angular_acceleration": _finite(state.angular_acceleration),
    }


def shape_document(body: Body) -> dict:
    """The body's shape: ``{"shape": "box", "size": [...]}`` or the cylinder's dimensions [m]."""
    if isinstance(body.shape, Box):
        return {"shape": "box", "size": list(body.shape.size)}
    return {
        "shape": "cylinder",
        "radius": body.shape.radius,
        "height": body.shape.height,
        "inner_radius": body.shape.inner_radius,
    }


def body_case_document(case: BodyScreeningCase, body: Body) -> dict:
    """One 3-D configuration under one excitation: every direction swept (``body_cases``).

    Directions [deg] from +x towards +y, of the horizontal support
    acceleration; ``x``, ``y`` and ``horizontal`` (their magnitude) [m/s^2];
    ``at_excitation`` is the state in the excitation's own direction;
    ``forces`` act on the body from the support [N] (None where not computed:
    slide-rock).
    """
    lowest = case.lowest_threshold
    return {
        "configuration": case.configuration,
        "body": case.body,
        **shape_document(body),
        "excitation": case.excitation,
        "x": case.x,
        "y": case.y,
        "horizontal": case.horizontal,
        "excitation_direction": degrees(case.excitation_direction),
        "vertical": case.vertical,
        "slide_threshold": _finite(case.directions[0].slide_threshold),
        "lowest_uplift_threshold": {
            "direction": degrees(lowest.direction),
            "uplift_threshold": _finite(lowest.uplift_threshold),
            "pivot": pivot_label(body, lowest.direction),
        },
        "at_excitation": body_state_document(case.at_excitation),
        "directions": [body_state_document(state) for state in case.directions],
    }
