"""Public screening from rest: :func:`screen` (paper Tables 2-5) and its result."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from freestand.api.base import Result, frame, subject
from freestand.core.contact.screening import ForceEnvelope, InitialMotion, force_envelope
from freestand.core.contact.screening import screen as _screen_stack
from freestand.core.model import VERTICAL_SENSES, Excitation, Stack
from freestand.errors import FreestandError

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
    """

    model: str
    gravity: float
    configurations: tuple[Stack, ...]
    cases: tuple[InitialMotion, ...]
    envelope: tuple[ForceEnvelope, ...]

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

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        from freestand.io.results import envelope_document, screening_document

        document = screening_document(self.model, self.cases, self.gravity)
        document["force_envelope"] = [envelope_document(item) for item in self.envelope]
        return document

    def to_frame(self):
        """One row per case and block (blocks bottom to top).

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


def screen(
    model,
    excitations: Excitation | Iterable[Excitation] | None = None,
    gravity: float | None = None,
    *,
    configurations: str | Iterable[str] | None = None,
    vertical_senses: str | None = None,
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

    Parameters
    ----------
    model : ModelFile, Stack or sequence of Stack
        A loaded model file (``fs.load_model``), or stacks (bottom block first).
    excitations : Excitation or sequence of Excitation, optional
        Support acceleration levels: horizontal magnitude a_h [m/s^2] (both
        senses analysed) and signed vertical a_v [m/s^2], positive downward.
        Default: the model's; required for a stack.
    gravity : float, optional
        g [m/s^2] (default: the model's, 9.81 for a stack).
    configurations : str or sequence of str, optional
        Only these configurations of the model (default: all).
    vertical_senses : {"both", "given"}, optional
        ``"both"`` analyses every excitation with a_v downward and upward
        (named ``"<name> (a_v down)"`` and ``"<name> (a_v up)"``); default:
        each excitation's own ``vertical_senses``.

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
    stacks = what.select(configurations)
    cases = tuple(
        case
        for stack in stacks
        for case in _screen_configuration(stack, what.excitations, what.gravity, vertical_senses)
    )
    return ScreeningResult(
        what.name, what.gravity, tuple(stacks), cases, tuple(force_envelope(cases))
    )


def _screen_configuration(stack, excitations, gravity, vertical_senses) -> list[InitialMotion]:
    """The cases of one configuration (the place to dispatch another kind of configuration)."""
    return _screen_stack(stack, tuple(excitations), gravity, vertical_senses)
