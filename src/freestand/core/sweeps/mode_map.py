"""Mode maps: the initial motion over a grid of two parameters.

A mode map solves the initial motion (paper section 3) of a stack at every
node of a grid of two inputs (excitation components, a friction
coefficient, a mass, a centre coordinate...) and names each node by the
joint motion of its blocks ("bridge slides, cart rocks"). Regions of equal
names show where the boundaries between rest, slide, rock and slide-rock
lie.

When both axes are excitation components the map uses
:func:`freestand.core.contact.batch.solve_excitation_plane` (each contact mode's
solution is linear in ``s a_hor`` and ``g - a_ver``, so the boundaries are
straight lines through ``(0, g)`` in the ``(a_hor, a_ver)`` plane); otherwise
:func:`freestand.core.contact.batch.solve_batch`.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace

import numpy as np

from freestand.core.contact.batch import (
    AMBIGUOUS,
    EXCITATION_FIELDS,
    BatchResult,
    Parameter,
    case_inputs,
    solve_batch,
    solve_excitation_plane,
)
from freestand.core.contact.screening import GRAVITY
from freestand.core.model import Excitation, Stack


@dataclass(frozen=True)
class Axis:
    """One axis of a map: a parameter from ``start`` to ``stop``.

    Parameters
    ----------
    parameter : Parameter
    start, stop : float
        Range in SI units (a factor for ``scale``, an offset for ``add``).
    """

    parameter: Parameter
    start: float
    stop: float

    def values(self, count: int) -> np.ndarray:
        """``count`` equally spaced values from start to stop."""
        return np.linspace(self.start, self.stop, count)

    @property
    def title(self) -> str:
        """Axis title with unit, e.g. ``"horizontal [m/s^2]"``."""
        return f"{self.parameter.label} [{self.parameter.unit}]"

    def model_value(self, stack: Stack, excitation: Excitation) -> float:
        """Where the model itself lies on this axis for ``excitation``.

        The nominal value for ``set``, 0 for ``add``, 1 for ``scale``.
        """
        if self.parameter.operation == "add":
            return 0.0
        if self.parameter.operation == "scale":
            return 1.0
        return self.parameter.nominal(stack, excitation.horizontal, excitation.vertical)


@dataclass(frozen=True)
class ModeMap:
    """Initial motion over a grid.

    Attributes
    ----------
    configuration, excitation : str
        Names (the excitation gives the values of the components that are
        not on an axis).
    sense : int
        +1 or -1: sense of the horizontal inertial force.
    x, y : Axis
    x_values, y_values : numpy.ndarray
        Grid values, shapes (nx,) and (ny,).
    codes : numpy.ndarray
        Shape (ny, nx): joint-state code of every node
        (:meth:`freestand.core.contact.batch.BatchResult.state_codes`).
    labels : dict
        Code -> region name ("bridge slides, cart rests").
    ambiguous : numpy.ndarray
        Shape (ny, nx) bool: several states admissible (the rule's choice
        is the one coloured).
    result : BatchResult
        The solution at every node, row-major (y outer, x inner).
    """

    configuration: str
    excitation: str
    sense: int
    x: Axis
    y: Axis
    x_values: np.ndarray
    y_values: np.ndarray
    codes: np.ndarray
    labels: dict[int, str]
    ambiguous: np.ndarray
    result: BatchResult = field(repr=False)

    def fractions(self) -> dict[str, float]:
        """Share of the grid's nodes in each region [-], largest first."""
        codes, counts = np.unique(self.codes, return_counts=True)
        order = np.argsort(-counts, kind="stable")
        return {self.labels[int(codes[i])]: counts[i] / self.codes.size for i in order}

    def node(self, x: float, y: float) -> tuple[int, int]:
        """(row, column) of the grid node nearest to (x, y)."""
        return (
            int(np.argmin(np.abs(self.y_values - y))),
            int(np.argmin(np.abs(self.x_values - x))),
        )

    def label_at(self, x: float, y: float) -> str:
        """Region name at the node nearest to (x, y)."""
        row, column = self.node(x, y)
        return self.labels[int(self.codes[row, column])]


def mode_map(
    stack: Stack,
    x: Axis,
    y: Axis,
    excitation: Excitation,
    sense: int = 1,
    count: int | tuple[int, int] = 400,
    gravity: float = GRAVITY,
    progress: Callable[[int], None] | None = None,
) -> ModeMap:
    """Initial motion of ``stack`` over a grid of two parameters.

    Parameters
    ----------
    stack : Stack
    x, y : Axis
        The two parameters and their ranges (different parameters).
    excitation : Excitation
        Nominal excitation (a_hor, a_ver [m/s^2]) for the components not on
        an axis.
    sense : int, optional
        +1 or -1: sense of the horizontal inertial force.
    count : int or (int, int), optional
        Nodes per axis (nx, ny).
    gravity : float, optional
        g [m/s^2].
    progress : callable, optional
        Called with the number of nodes just solved.

    Returns
    -------
    ModeMap
    """
    if x.parameter.name == y.parameter.name:
        raise ValueError(f"both axes vary {x.parameter.name!r}; choose two different parameters")
    nx, ny = (count, count) if isinstance(count, int) else count
    x_values = x.values(nx)
    y_values = y.values(ny)
    grid_x, grid_y = np.meshgrid(x_values, y_values)
    values = [(x.parameter, grid_x.ravel()), (y.parameter, grid_y.ravel())]
    if x.parameter.field in EXCITATION_FIELDS and y.parameter.field in EXCITATION_FIELDS:
        excitation_values = {
            "horizontal": np.full(grid_x.size, excitation.horizontal),
            "vertical": np.full(grid_x.size, excitation.vertical),
        }
        for parameter, value in values:
            excitation_values[parameter.field] = parameter.applied(
                excitation_values[parameter.field], value
            )
        result = solve_excitation_plane(
            stack,
            sense * excitation_values["horizontal"],
            excitation_values["vertical"],
            gravity,
            progress=progress,
        )
    else:
        inputs = case_inputs(
            stack, excitation.horizontal, excitation.vertical, sense, values, grid_x.size
        )
        result = solve_batch(inputs, gravity, progress=progress)
    codes = result.state_codes()
    labels = {int(code): result.state_label(int(code)) for code in np.unique(codes)}
    return ModeMap(
        configuration=stack.name,
        excitation=excitation.name,
        sense=sense,
        x=x,
        y=y,
        x_values=x_values,
        y_values=y_values,
        codes=codes.reshape(ny, nx),
        labels=labels,
        ambiguous=(result.status == AMBIGUOUS).reshape(ny, nx),
        result=result,
    )


def _on_axis(maps: ModeMap, field_name: str) -> bool:
    return any(
        axis.parameter.field == field_name and axis.parameter.operation == "set"
        for axis in (maps.x, maps.y)
    )


def model_points(
    maps: ModeMap,
    stack: Stack,
    excitations: Sequence[Excitation],
    nominal: Excitation | None = None,
) -> list[tuple[str, float, float]]:
    """Where the model's own excitations lie on a map: (name, x, y) each.

    Parameters
    ----------
    maps : ModeMap
    stack : Stack
    excitations : sequence of Excitation
        The model's excitations; one analysed in both vertical senses gives
        two points, ``"<name> (a_v down)"`` and ``"<name> (a_v up)"``.
    nominal : Excitation, optional
        The excitation the map takes the components not on an axis from.
        When given, only the excitations that the map really evaluates are
        returned: those whose components off the axes equal the nominal ones
        and whose point lies within the axes' ranges. A point of another
        excitation would be labelled with a state it does not have.

    Returns
    -------
    list of (str, float, float)
    """
    points = []
    for excitation in excitations:
        verticals = excitation.verticals()
        for vertical in verticals:
            case = replace(excitation, vertical=vertical, vertical_senses="given")
            name = excitation.name
            if len(verticals) > 1:
                name += f" (a_v {'up' if vertical < 0 else 'down'})"
            x = maps.x.model_value(stack, case)
            y = maps.y.model_value(stack, case)
            if nominal is not None:
                off_axis = [f for f in EXCITATION_FIELDS if not _on_axis(maps, f)]
                if any(
                    not np.isclose(getattr(case, f), getattr(nominal, f), rtol=1e-12, atol=1e-12)
                    for f in off_axis
                ):
                    continue
                inside = all(
                    min(axis.start, axis.stop) <= value <= max(axis.start, axis.stop)
                    for axis, value in ((maps.x, x), (maps.y, y))
                )
                if not inside:
                    continue
            points.append((name, x, y))
    return points


def point_label(
    maps: ModeMap,
    stack: Stack,
    x: float,
    y: float,
    excitation: Excitation,
    gravity: float = GRAVITY,
) -> str:
    """The region name of the exact point (x, y), solved there, not read off the grid.

    The grid's nearest node can lie across a boundary from the point; this
    solves the one case the point stands for, with the map's sense and the
    components not on an axis from ``excitation`` (the map's nominal one).
    """
    single = mode_map(
        stack,
        Axis(maps.x.parameter, x, x),
        Axis(maps.y.parameter, y, y),
        excitation,
        maps.sense,
        (1, 1),
        gravity,
    )
    return single.labels[int(single.codes[0, 0])]
