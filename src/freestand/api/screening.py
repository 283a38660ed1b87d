"""Public screening from rest: :func:`screen` (paper Tables 2-5; 3-D bodies by direction).

Planar configurations give the cases of the paper's section 3 (both senses of
the horizontal inertial force); 3-D configurations
(:class:`~freestand.core.body.BodyConfiguration`) give, per excitation, the
initial motion and uplift threshold in every direction of a sweep
(:func:`freestand.core.contact.body_screening.screen_body_configuration`).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from freestand.api.base import Result, frame, subject
from freestand.core.body import BodyConfiguration
from freestand.core.contact.body_screening import BodyScreeningCase, screen_body_configuration
from freestand.core.contact.screening import ForceEnvelope, InitialMotion, force_envelope
from freestand.core.contact.screening import screen as _screen_stack
from freestand.core.model import VERTICAL_SENSES, Excitation, Stack
from freestand.errors import FreestandError

#: Directions of the 3-D sweep by default: every 15 deg over 0-360 deg.
DIRECTIONS = 24
#: Most directions a sweep may have (every 0.1 deg).
MAX_DIRECTIONS = 3600

#: Columns of :meth:`ScreeningResult.to_frame`.
SCREENING_COLUMNS = (
    "configuration",
    "excitation",
    "sense",
    "horizontal [m/s^2]",
    "vertical [m/s^2]",
    "status",
    "paper_case",
    "block",
    "motion",
    "pivot",
    "slide_direction",
    "acceleration_x [m/s^2]",
    "acceleration_z [m/s^2]",
    "angular_acceleration [rad/s^2]",
    "normal_left [N]",
    "normal_right [N]",
    "tangential [N]",
)

#: Columns of :meth:`ScreeningResult.to_frame` for the 3-D configurations (``"directions"``).
DIRECTION_COLUMNS = (
    "configuration",
    "body",
    "shape",
    "excitation",
    "x [m/s^2]",
    "y [m/s^2]",
    "horizontal [m/s^2]",
    "excitation_direction [deg]",
    "vertical [m/s^2]",
    "direction [deg]",
    "motion",
    "pivot",
    "slide_direction [deg]",
    "uplift_threshold [m/s^2]",
    "slide_threshold [m/s^2]",
    "normal [N]",
    "tangential_x [N]",
    "tangential_y [N]",
    "angular_acceleration [rad/s^2]",
)


@dataclass(frozen=True)
class ScreeningResult(Result):
    """Initial motion and contact forces of every configuration, excitation and sense.

    Iterating over it gives the cases (:class:`InitialMotion`), in the order
    configuration, excitation, vertical sense, horizontal sense ``+`` then ``-``.

    Attributes
    ----------
    model : str
        Model name.
    gravity : float
        g [m/s^2].
    configurations : tuple of Stack
        The configurations screened.
    cases : tuple of InitialMotion
        Every case: each block's motion, accelerations [m/s^2, rad/s^2] and
        contact forces [N], with the ambiguity report (``status``).
    envelope : tuple of ForceEnvelope
        Per block, the largest normal force at each lower contact and the
        largest tangential force [N] over the cases, with the case giving it.
    bodies : tuple of BodyConfiguration
        The 3-D configurations screened.
    body_cases : tuple of BodyScreeningCase
        Per 3-D configuration and excitation (and vertical sense): the
        initial motion, pivot, contact forces [N] and uplift threshold
        [m/s^2] in every direction of the sweep and in the excitation's own.

    Examples
    --------
    >>> import freestand as fs
    >>> result = fs.screen(fs.load_model("examples/crane.toml"))
    >>> len(result), result.flagged
    (12, ())
    >>> result.to_dict()["cases"][0]["paper_case"]
    '3.1.2.3: bridge slides, cart rests on it'
    >>> result.to_frame().shape  # 12 cases x 2 blocks, 17 columns
    (24, 17)

    A model of 3-D bodies gives its cases by direction, every 15 deg:

    >>> bodies = fs.screen(fs.load_model("examples/bodies.toml"), configurations="cabinet")
    >>> entry = bodies.to_dict()["body_cases"][0]["directions"][6]  # SL-1 at 90 deg
    >>> entry["direction"], entry["motion"], entry["pivot"], round(entry["uplift_threshold"], 3)
    (90.0, 'rock', 'edge -y', 2.032)
    >>> bodies.to_frame().shape  # 2 excitations x 24 directions, 19 columns
    (48, 19)
    """

    model: str
    gravity: float
    configurations: tuple[Stack, ...]
    cases: tuple[InitialMotion, ...]
    envelope: tuple[ForceEnvelope, ...]
    bodies: tuple[BodyConfiguration, ...] = ()
    body_cases: tuple[BodyScreeningCase, ...] = ()

    def __iter__(self):
        return iter(self.cases)

    def __len__(self) -> int:
        return len(self.cases)

    def __getitem__(self, index):
        return self.cases[index]

    @property
    def flagged(self) -> tuple[InitialMotion, ...]:
        """The cases that are ambiguous or have no consistent state."""
        return tuple(c for c in self.cases if c.status in ("ambiguous", "inconsistent"))

    def to_dict(self) -> dict:
        """The ``freestand screen --json`` document (see the README, "JSON output").

        With 3-D configurations, ``body_cases`` lists one document per
        configuration and excitation (:func:`freestand.io.results.body_case_document`):
        ``directions``, each with ``direction`` [deg], ``motion``, ``pivot``,
        ``slide_direction`` [deg], ``uplift_threshold`` [m/s^2], ``forces``
        [N] and ``angular_acceleration`` [rad/s^2]; ``at_excitation`` the same
        in the excitation's own direction. Without them the document is the
        planar one as it always was.

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        from freestand.io.results import (
            body_case_document,
            envelope_document,
            screening_document,
        )

        document = screening_document(self.model, self.cases, self.gravity)
        document["force_envelope"] = [envelope_document(item) for item in self.envelope]
        if self.bodies:
            bodies = self._body_by_configuration()
            document["body_cases"] = [
                body_case_document(case, bodies[case.configuration]) for case in self.body_cases
            ]
        return document

    def _body_by_configuration(self) -> dict:
        return {configuration.name: configuration.body for configuration in self.bodies}

    def to_frame(self, table: str | None = None):
        """The planar cases (``"cases"``) or the 3-D directions (``"directions"``) as a table.

        Parameters
        ----------
        table : {"cases", "directions"}, optional
            Default: ``"cases"`` when planar configurations were screened,
            else ``"directions"``.

        ``"directions"``: one row per 3-D configuration, excitation and swept
        direction, columns ``configuration``, ``body``, ``shape``,
        ``excitation``, ``x [m/s^2]``, ``y [m/s^2]``, ``horizontal [m/s^2]``
        (their magnitude, applied in every direction),
        ``excitation_direction [deg]``, ``vertical [m/s^2]``, ``direction
        [deg]`` (of the support acceleration, from +x towards +y),
        ``motion``, ``pivot``, ``slide_direction [deg]``,
        ``uplift_threshold [m/s^2]``, ``slide_threshold [m/s^2]``, ``normal
        [N]``, ``tangential_x [N]``, ``tangential_y [N]`` (on the body from
        the support), ``angular_acceleration [rad/s^2]``.

        ``"cases"``: one row per case and block (blocks bottom to top).

        Columns: ``configuration``, ``excitation``, ``sense`` (``+``/``-``, of
        the horizontal inertial force), ``horizontal [m/s^2]``, ``vertical
        [m/s^2]`` (signed, positive downward), ``status``, ``paper_case``,
        ``block``, ``motion``, ``pivot``, ``slide_direction`` (+1/-1/0),
        ``acceleration_x [m/s^2]``, ``acceleration_z [m/s^2]``,
        ``angular_acceleration [rad/s^2]`` (relative to the support),
        ``normal_left [N]``, ``normal_right [N]``, ``tangential [N]`` (forces on
        the block from the body below). A case with no consistent state has
        one row with no block. ``attrs``: ``model``, ``gravity [m/s^2]``.

        Returns
        -------
        pandas.DataFrame
            The table described above: units in the column names, metadata in
            ``attrs``.
        """
        if table is None:
            table = "cases" if self.cases or not self.body_cases else "directions"
        if table == "directions":
            return self._directions_frame()
        if table != "cases":
            raise FreestandError(
                f'{table!r} is not a table of the screening; use "cases" or "directions"',
                source="to_frame",
            )
        rows = []
        for case in self.cases:
            common = {
                "configuration": case.configuration,
                "excitation": case.excitation,
                "sense": "+" if case.sense > 0 else "-",
                "horizontal [m/s^2]": case.horizontal,
                "vertical [m/s^2]": case.vertical,
                "status": case.status,
                "paper_case": case.paper_case,
            }
            if not case.blocks:
                rows.append(common)
            for state in case.blocks:
                rows.append(
                    common
                    | {
                        "block": state.name,
                        "motion": state.motion.value,
                        "pivot": state.pivot,
                        "slide_direction": state.slide_direction,
                        "acceleration_x [m/s^2]": state.acceleration_x,
                        "acceleration_z [m/s^2]": state.acceleration_z,
                        "angular_acceleration [rad/s^2]": state.angular_acceleration,
                        "normal_left [N]": state.base_normal_left,
                        "normal_right [N]": state.base_normal_right,
                        "tangential [N]": state.base_tangential,
                    }
                )
        return frame(
            rows, SCREENING_COLUMNS, {"model": self.model, "gravity [m/s^2]": self.gravity}
        )

    def _directions_frame(self):
        from freestand.io.results import body_case_document

        bodies = self._body_by_configuration()
        rows = []
        for case in self.body_cases:
            document = body_case_document(case, bodies[case.configuration])
            common = {
                "configuration": case.configuration,
                "body": case.body,
                "shape": document["shape"],
                "excitation": case.excitation,
                "x [m/s^2]": case.x,
                "y [m/s^2]": case.y,
                "horizontal [m/s^2]": case.horizontal,
                "excitation_direction [deg]": document["excitation_direction"],
                "vertical [m/s^2]": case.vertical,
            }
            for state, entry in zip(case.directions, document["directions"], strict=True):
                rows.append(
                    common
                    | {
                        "direction [deg]": entry["direction"],
                        "motion": entry["motion"],
                        "pivot": entry["pivot"],
                        "slide_direction [deg]": entry["slide_direction"],
                        "uplift_threshold [m/s^2]": state.uplift_threshold,
                        "slide_threshold [m/s^2]": state.slide_threshold,
                        "normal [N]": state.normal_force,
                        "tangential_x [N]": state.tangential_force[0],
                        "tangential_y [N]": state.tangential_force[1],
                        "angular_acceleration [rad/s^2]": state.angular_acceleration,
                    }
                )
        return frame(
            rows, DIRECTION_COLUMNS, {"model": self.model, "gravity [m/s^2]": self.gravity}
        )

    def plot(self, ax=None, *, configuration: str | None = None, excitation: str | None = None):
        """The polar figure of the 3-D screening (``freestand screen --plot``).

        One polar panel per 3-D configuration and vertical acceleration: the
        uplift threshold a*(phi) [m/s^2] as a closed curve against the
        direction phi of the support acceleration, the slide threshold
        mu_0 (g - a_v) as a dashed circle, each excitation as a circle of its
        magnitude with the initial motion in every swept direction as
        coloured markers and a star in its own direction; the legend outside
        the axes (:func:`freestand.plot.body_screening.uplift_polar_figure`).
        The planar cases have no figure.

        Parameters
        ----------
        ax : matplotlib polar Axes, optional
            Draw into these axes (one panel only: select it with
            ``configuration`` and ``excitation``).
        configuration, excitation : str, optional
            Draw only this 3-D configuration / excitation (case name).

        Returns
        -------
        matplotlib.figure.Figure
        """
        from freestand.plot.body_screening import uplift_polar_figure

        cases = [
            case
            for case in self.body_cases
            if configuration in (None, case.configuration) and excitation in (None, case.excitation)
        ]
        if not cases:
            chosen = (
                f" for configuration {configuration!r} and excitation {excitation!r}"
                if configuration or excitation
                else ""
            )
            raise FreestandError(
                f"no 3-D screening to draw{chosen}; the figure shows 3-D configurations "
                "(blocks with shape) by direction",
                source="plot",
            )
        title = f"{self.model}: uplift and initial motion by direction of the support acceleration"
        return uplift_polar_figure(cases, self._body_by_configuration(), ax=ax, title=title)


def screen(
    model,
    excitations: Excitation | Iterable[Excitation] | None = None,
    gravity: float | None = None,
    *,
    configurations: str | Iterable[str] | None = None,
    vertical_senses: str | None = None,
    directions: int = DIRECTIONS,
) -> ScreeningResult:
    """Initial motion and contact forces of a stack from rest (paper Tables 2-5).

    For every configuration, excitation level and sense of the horizontal
    inertial force, the contact problem at the first instant of motion is
    solved as the linear complementarity problem it is (every contact mode
    enumerated, Coulomb friction, the weight m (g - a_v)): the type of motion
    of every block relative to the body below, its accelerations and the
    contact forces: section 3 of the reference paper ("Response of rigid
    block assemblies to earthquake excitation") for any planar stack, the
    contact problem in the complementarity form of Pfeiffer and Glocker
    (Multibody Dynamics with Unilateral Contacts, Wiley 1996).

    A 3-D configuration (a body with a shape) is screened in ``directions``
    horizontal directions evenly over 0-360 deg: in each, under the
    excitation's horizontal magnitude ``a = sqrt(x^2 + y^2)``, its initial
    motion from rest (rest, slide with its direction, rock about an edge, a
    corner or the rim, slide-rock, free flight), the contact force and the
    uplift threshold ``a* = (g - a_v) rho(phi) / h`` (Housner 1963, in 3-D:
    ``docs/three-d.md``); the state in the excitation's own direction
    atan2(y, x) is given too.

    Parameters
    ----------
    model : ModelFile, Stack, BodyConfiguration, Body or a sequence of them
        A loaded model file (``fs.load_model``), or stacks (bottom block
        first) and 3-D bodies (:mod:`freestand.core.body`).
    excitations : Excitation or sequence of Excitation, optional
        Support acceleration levels: horizontal magnitude a_h [m/s^2] (both
        senses analysed; for a 3-D body the x component, with the y
        component ``horizontal_y``) and signed vertical a_v [m/s^2],
        positive downward. Default: the model's; required for a stack.
    gravity : float, optional
        g [m/s^2] (default: the model's, 9.81 for a stack).
    configurations : str or sequence of str, optional
        Only these configurations of the model (default: all).
    vertical_senses : {"both", "given"}, optional
        ``"both"`` analyses every excitation with a_v downward and upward
        (named ``"<name> (a_v down)"`` and ``"<name> (a_v up)"``); default:
        each excitation's own ``vertical_senses``.
    directions : int, optional
        Directions of the 3-D sweep over 0-360 deg (24: every 15 deg).

    Returns
    -------
    ScreeningResult
        The cases (iterate over it), the force envelope, ``to_dict()`` (the
        ``freestand screen --json`` document) and ``to_frame()``.

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model("examples/crane.toml")
    >>> result = fs.screen(model, configurations="y-z")
    >>> [state.motion.value for state in result[0].blocks]
    ['slide', 'rest']
    >>> result.to_frame()[["excitation", "sense", "block", "motion"]].head(2)
      excitation sense   block motion
    0      rigid     +  bridge  slide
    1      rigid     +    cart   rest

    A 3-D body (a cabinet, a cask) by direction, here every 45 deg:

    >>> cabinet = fs.screen(fs.load_model("examples/bodies.toml"), configurations="cabinet",
    ...                     directions=8)
    >>> case = cabinet.body_cases[1]  # SL-2: 4.91 m/s^2 in every direction
    >>> [(s.motion.value, s.pivot) for s in case.directions[:3]]  # 0, 45, 90 deg
    [('rock', 'edge -x'), ('rock', 'edge -y'), ('rock', 'edge -y')]
    >>> figure = cabinet.plot()  # the polar figure of freestand screen --plot
    """
    if vertical_senses is not None and vertical_senses not in VERTICAL_SENSES:
        raise FreestandError(
            f"{vertical_senses!r} is not a choice; use "
            + " or ".join(repr(sense) for sense in VERTICAL_SENSES)
            + ", e.g. --vertical-senses both",
            source="--vertical-senses",
        )
    what = subject(model, excitations, gravity)
    if not what.excitations:
        raise FreestandError(
            "no excitation to screen; give excitations, e.g. "
            "fs.Excitation('rigid', horizontal=2.7, vertical=2.35)",
            source="excitations",
        )
    if (
        isinstance(directions, bool)
        or not isinstance(directions, int)
        or not (1 <= directions <= MAX_DIRECTIONS)
    ):
        raise FreestandError(
            f"{directions!r} is not a number of directions; give a whole number from 1 to "
            f"{MAX_DIRECTIONS}, e.g. --directions 24 (every 15 deg)",
            source="--directions",
        )
    stacks, bodies = what.split(configurations)
    cases = tuple(
        case
        for stack in stacks
        for case in _screen_stack(stack, tuple(what.excitations), what.gravity, vertical_senses)
    )
    body_cases = tuple(
        case
        for body in bodies
        for case in screen_body_configuration(
            body, what.excitations, what.gravity, vertical_senses, directions
        )
    )
    return ScreeningResult(
        what.name, what.gravity, tuple(stacks), cases, tuple(force_envelope(cases)),
        tuple(bodies), body_cases,
    )  # fmt: skip
