"""Public mode maps (:func:`mode_map`) and Monte Carlo sweeps (:func:`sample`) from rest.

Both solve the screening's contact problem for many inputs at once with the
compiled batch solver (the same answers as :func:`freestand.screen`), over a
grid of two parameters or over random samples of uncertain inputs. The
parameters are named as in the command line: ``horizontal``, ``vertical``,
``friction.static``, ``cart.mass``, ``cart.centre.x``... (``docs/maps.md``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, replace

import numpy as np

from freestand.api.base import Result, frame, subject
from freestand.core.contact.batch import MOTIONS, STATUS_NAMES
from freestand.core.model import Excitation, Stack
from freestand.core.sweeps.mode_map import Axis, ModeMap, model_points, point_label
from freestand.core.sweeps.mode_map import mode_map as _map_stack
from freestand.core.sweeps.sampling import INTERVALS, Sweep, Variation, monte_carlo
from freestand.errors import FreestandError

SENSES = {"+": (1,), "-": (-1,), "both": (1, -1)}

#: Most grid nodes of one map run (nodes per axis squared, times senses and
#: configurations): about 1.5 GB of results and a minute of work.
MAX_MAP_NODES = 10_000_000
#: Most samples per case of :func:`sample`, and most solutions (samples x cases) of one run:
#: beyond, a run lasts many minutes and its samples file many gigabytes.
MAX_SAMPLES = 10_000_000
MAX_SOLVES = 20_000_000


def _sense_word(sense: int) -> str:
    return "+" if sense > 0 else "-"


def parse_sense(value: str) -> tuple[int, ...]:
    """``"+"``, ``"-"`` or ``"both"`` -> the senses (+1, -1) of the horizontal inertial force."""
    if value not in SENSES:
        raise FreestandError(f"{value!r} is not a sense; use +, - or both", source="option --sense")
    return SENSES[value]


def _block_columns(result, names: Sequence[str]) -> dict[str, np.ndarray]:
    """Per block: its motion, pivot and slide direction at every node or sample."""
    motion_names = np.array([m.value for m in MOTIONS] + [""], dtype=object)
    pivots = np.array(["left", "", "right"], dtype=object)
    columns = {}
    for b, name in enumerate(names):
        columns[f"{name}.motion"] = motion_names[result.motion[:, b]]
        columns[f"{name}.pivot"] = pivots[np.clip(result.pivot[:, b], -1, 1) + 1]
        columns[f"{name}.slide_direction"] = np.asarray(result.slide_direction[:, b])
    return columns


# --- mode maps ------------------------------------------------------------------------------


@dataclass(frozen=True)
class ModeMapResult(Result):
    """Regions of initial motion over a grid of two parameters, one map per configuration and sense.

    Attributes
    ----------
    model : str
        Model name.
    configurations : tuple of Stack
        The configurations mapped.
    excitation : Excitation
        The excitation that gives the inputs not on an axis.
    x, y : Axis
        The two parameters and their ranges.
    nodes : int
        Grid nodes per axis.
    maps : tuple of ModeMap
        Per configuration and sense: the joint state of every node, its
        region name, the ambiguous nodes and the solutions.
    points : tuple of tuple
        Per map, the model's excitations that lie on it: (name, x, y, region
        solved at the point).
    points_not_shown : tuple of str
        Excitations whose inputs off the axes differ from ``excitation``'s,
        or that lie outside the map.

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model("examples/crane.toml")
    >>> result = fs.mode_map(model, nodes=50, configurations="y-z", sense="+")
    >>> result.to_frame().shape  # 50 x 50 nodes
    (2500, 14)
    >>> sorted(result.to_dict()["maps"][0]["regions"])
    ['bridge rests, cart rests', 'bridge slides, cart rests', 'free flight (a_ver >= g)']
    >>> fig = result.plot()
    """

    model: str
    configurations: tuple[Stack, ...]
    excitation: Excitation
    x: Axis
    y: Axis
    nodes: int
    maps: tuple[ModeMap, ...]
    points: tuple[tuple[tuple[str, float, float, str], ...], ...]
    points_not_shown: tuple[str, ...]

    def invalid_share(self, index: int) -> float:
        """Share [-] of the nodes of map ``index`` that make no model."""
        return float(self.maps[index].fractions().get("invalid input", 0.0))

    def to_dict(self) -> dict:
        """The ``freestand map --json`` document.

        Keys: ``model``, ``configurations``, ``configuration`` (the first),
        ``excitation``, ``x`` and ``y`` (``parameter``, ``start``, ``stop``,
        SI), ``nodes``, ``maps`` (per configuration and sense: ``regions``,
        each region's share [-], ``ambiguous_nodes``, ``points``),
        ``points_not_shown`` and ``files`` (written by the command).

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        return {
            "model": self.model,
            "configurations": [stack.name for stack in self.configurations],
            "configuration": self.configurations[0].name,
            "excitation": self.excitation.name,
            "x": {"parameter": self.x.parameter.label, "start": self.x.start, "stop": self.x.stop},
            "y": {"parameter": self.y.parameter.label, "start": self.y.start, "stop": self.y.stop},
            "nodes": self.nodes,
            "maps": [
                {
                    "configuration": m.configuration,
                    "sense": _sense_word(m.sense),
                    "regions": {label: float(f) for label, f in m.fractions().items()},
                    "ambiguous_nodes": int(m.ambiguous.sum()),
                    "points": [
                        {"excitation": name, "x": px, "y": py, "region": label}
                        for name, px, py, label in pts
                    ],
                }
                for m, pts in zip(self.maps, self.points, strict=True)
            ],
            "points_not_shown": list(self.points_not_shown),
            "files": [],
        }

    def columns(self) -> tuple[str, ...]:
        """The columns of :meth:`to_frame`, in order."""
        names = self.maps[0].result.names
        blocks = [f"{n}.{c}" for n in names for c in ("motion", "pivot", "slide_direction")]
        return (
            "configuration", "sense", self.x.title, self.y.title, "status", "region",
            "ambiguous", "admissible_states", *blocks,
        )  # fmt: skip

    def to_frame(self):
        """One row per grid node of every map (y outer, x inner).

        Columns: ``configuration``, ``sense``, the x and y parameters with
        their units (e.g. ``horizontal [m/s^2]``, ``vertical [m/s^2]``),
        ``status`` (``unique``, ``ambiguous``, ``inconsistent``,
        ``free-flight``, ``invalid input``), ``region`` (the joint state's
        name), ``ambiguous``, ``admissible_states``, and per block B
        ``B.motion``, ``B.pivot``, ``B.slide_direction``. ``attrs``:
        ``model``, ``excitation``, ``nodes``.

        Returns
        -------
        pandas.DataFrame
            The table described above: units in the column names, metadata in
            ``attrs``.
        """
        import pandas as pd

        parts = []
        for m in self.maps:
            result = m.result
            grid_x, grid_y = np.meshgrid(m.x_values, m.y_values)
            codes = m.codes.ravel()
            region = np.array([m.labels[int(c)] for c in np.unique(codes)], dtype=object)
            columns = {
                "configuration": np.full(result.count, m.configuration, dtype=object),
                "sense": np.full(result.count, _sense_word(m.sense), dtype=object),
                self.x.title: grid_x.ravel(),
                self.y.title: grid_y.ravel(),
                "status": np.array(STATUS_NAMES, dtype=object)[result.status],
                "region": region[np.searchsorted(np.unique(codes), codes)],
                "ambiguous": m.ambiguous.ravel(),
                "admissible_states": np.asarray(result.admissible_count, dtype=int),
                **_block_columns(result, result.names),
            }
            parts.append(pd.DataFrame(columns))
        table = pd.concat(parts, ignore_index=True)[list(self.columns())]
        table.attrs.update(
            {"model": self.model, "excitation": self.excitation.name, "nodes": self.nodes}
        )
        return table

    def plot(self, ax=None):
        """The map figure ``freestand map --plot`` writes: one panel per configuration and sense.

        Regions coloured with a legend below, ambiguous nodes hatched, the
        model's excitations marked with the region solved at each. It has one
        panel per map, so ``ax`` must be None.

        Returns
        -------
        matplotlib.figure.Figure
        """
        if ax is not None:
            raise ValueError("the map figure has one panel per map; call plot() without ax")
        from freestand.plot.maps import mode_map_figure

        return mode_map_figure(self.maps, self.points, title=f"{self.model}: initial motion")


def _axis(value, option: str, gravity: float) -> Axis:
    if isinstance(value, Axis):
        return value
    from freestand.io.parameters import parse_axis

    return parse_axis(value, option, gravity)


def _nominal(what, excitation) -> Excitation:
    if isinstance(excitation, Excitation):
        return excitation
    if not what.excitations:
        raise FreestandError(
            "no excitation for the inputs off the axes; give excitation=fs.Excitation(...)",
            source="option --excitation",
        )
    if excitation is None:
        return what.excitations[0]
    for candidate in what.excitations:
        if candidate.name == excitation:
            return candidate
    known = ", ".join(repr(e.name) for e in what.excitations)
    raise FreestandError(
        f"no excitation named {excitation!r}; choose one of {known}",
        source="option --excitation",
    )


def mode_map(
    model,
    x: str | Axis = "horizontal=0:12",
    y: str | Axis = "vertical=-3:10",
    *,
    configurations: str | Iterable[str] | None = None,
    excitation: str | Excitation | None = None,
    sense: str = "both",
    nodes: int = 400,
    excitations: Iterable[Excitation] | None = None,
    gravity: float | None = None,
    progress: Callable[[int], None] | None = None,
) -> ModeMapResult:
    """Regions of initial motion of every block over a grid of two parameters.

    At every node of an ``nodes`` x ``nodes`` grid the screening's contact
    problem from rest is solved (the same linear complementarity problem as
    :func:`freestand.screen`, paper section 3, by the compiled batch solver);
    nodes with the same joint state of all blocks form a region.

    Parameters
    ----------
    model : ModelFile or Stack
        A loaded model file or a stack (with ``excitations``).
    x, y : str or Axis
        The axes, ``"NAME=START:STOP"`` in SI or with units
        (``"horizontal=0:12"``, ``"friction.static=0.1:0.5"``,
        ``"cart.centre.x+=-0.5:0.5"``); see ``docs/maps.md``.
    configurations : str or sequence of str, optional
        Configurations to map (default: the first).
    excitation : str or Excitation, optional
        The excitation giving the inputs not on an axis (default: the first).
    sense : {"both", "+", "-"}
        Sense(s) of the horizontal inertial force: one map each.
    nodes : int
        Nodes per axis, 2 to 5000.
    excitations : sequence of Excitation, optional
        In place of the model's (marked on the map where they lie on it).
    gravity : float, optional
        g [m/s^2] (default: the model's, 9.81 for a stack).
    progress : callable, optional
        Called with the number of nodes just solved.

    Returns
    -------
    ModeMapResult
        ``to_dict()`` (the ``freestand map --json`` document), ``to_frame()``
        (one row per node) and ``plot()`` (the map figure).

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model("examples/crane.toml")
    >>> result = fs.mode_map(model, "horizontal=0:12", "vertical=-3:10", nodes=50,
    ...                      configurations="y-z", sense="+")
    >>> max(result.maps[0].fractions(), key=result.maps[0].fractions().get)
    'bridge slides, cart rests'
    """
    from freestand.io.parameters import check_parameters

    what = subject(model, excitations, gravity)
    stacks = what.select(
        configurations if configurations is not None else [what.configuration(None).name]
    )
    nominal = _nominal(what, excitation)
    if not 2 <= nodes <= 5000:
        raise FreestandError(
            f"{nodes} nodes per axis is out of range; give 2 to 5000, e.g. --nodes 400",
            source="--nodes",
        )
    x_axis = _axis(x, "--x", what.gravity)
    y_axis = _axis(y, "--y", what.gravity)
    if x_axis.parameter.name == y_axis.parameter.name:
        raise FreestandError(
            f"both axes vary {x_axis.parameter.label!r}; choose two different parameters, "
            "e.g. --x horizontal=0:12 --y vertical=-3:10",
            source="--x/--y",
        )
    check_parameters([(x_axis.parameter, str(x)), (y_axis.parameter, str(y))], stacks, "--x/--y")
    senses = parse_sense(sense)
    total = nodes * nodes * len(senses) * len(stacks)
    if total > MAX_MAP_NODES:
        largest = int((MAX_MAP_NODES / (len(senses) * len(stacks))) ** 0.5)
        raise FreestandError(
            f"{nodes} x {nodes} nodes x {len(senses) * len(stacks)} map(s) is {total:,} nodes, "
            f"beyond the {MAX_MAP_NODES:,} of one run (each takes about 150 bytes and a few "
            f"microseconds); give --nodes {largest} or fewer, or --sense + / -",
            source="--nodes",
        )
    maps = tuple(
        _map_stack(stack, x_axis, y_axis, nominal, s, nodes, what.gravity, progress)
        for stack in stacks
        for s in senses
    )
    by_name = {stack.name: stack for stack in stacks}
    points = tuple(
        tuple(
            (name, px, py, point_label(m, by_name[m.configuration], px, py, nominal, what.gravity))
            for name, px, py in model_points(m, by_name[m.configuration], what.excitations, nominal)
        )
        for m in maps
    )
    shown = {name.split(" (a_v")[0] for pts in points for name, *_ in pts}
    left_out = tuple(sorted({e.name for e in what.excitations} - shown))
    return ModeMapResult(
        what.name, tuple(stacks), nominal, x_axis, y_axis, nodes, maps, points, left_out
    )


# --- Monte Carlo ----------------------------------------------------------------------------

#: Columns of :meth:`SampleResult.to_frame`.
SAMPLE_COLUMNS = (
    "configuration",
    "excitation",
    "sense",
    "block",
    "motion",
    "count",
    "total",
    "probability [-]",
    "low [-]",
    "high [-]",
)


@dataclass(frozen=True)
class SampleResult(Result):
    """The probability of each initial motion over samples of uncertain inputs.

    Attributes
    ----------
    model : str
        Model name.
    sweep : Sweep
        Per configuration, excitation and sense: the probabilities of every
        block's motion, of every joint state and of every solver status, with
        their confidence intervals, and every sample's solution.

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model("examples/crane.toml")
    >>> result = fs.sample(model, "friction.static=uniform(0.25,0.45)", n=1000,
    ...                    configurations="y-z", excitations="rigid", sense="+")
    >>> result.to_frame()[["block", "motion", "probability [-]"]].values.tolist()
    [['bridge', 'rest', 0.441], ['bridge', 'slide', 0.559], ['cart', 'rest', 1.0]]
    >>> result.samples_frame().shape  # one row per sample
    (1000, 10)
    """

    model: str
    sweep: Sweep

    @property
    def cases(self):
        """The cases of the sweep (configuration, excitation, sense)."""
        return self.sweep.cases

    def to_dict(self) -> dict:
        """The ``freestand sample --json`` document.

        Keys: ``model``, ``seed``, ``confidence``, ``interval``,
        ``variations`` and ``cases`` (per configuration, excitation and sense:
        ``samples``, ``invalid``, and ``motions``, ``states``, ``statuses``,
        each an ``outcome`` with ``block``, ``count``, ``total``,
        ``probability`` [-] and ``interval`` [-]).

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """

        def probability(item):
            return {
                "outcome": item.outcome,
                "block": item.block,
                "count": item.count,
                "total": item.total,
                "probability": item.probability,
                "interval": [item.low, item.high],
            }

        sweep = self.sweep
        return {
            "model": self.model,
            "seed": sweep.seed,
            "confidence": sweep.confidence,
            "interval": sweep.interval,
            "variations": [v.describe() for v in sweep.variations],
            "cases": [
                {
                    "configuration": case.configuration,
                    "excitation": case.excitation,
                    "sense": _sense_word(case.sense),
                    "samples": case.samples,
                    "invalid": case.invalid,
                    "motions": [probability(item) for item in case.motions],
                    "states": [probability(item) for item in case.states],
                    "statuses": [probability(item) for item in case.statuses],
                }
                for case in sweep.cases
            ],
        }

    def to_frame(self):
        """One row per configuration, excitation, sense, block and motion.

        Columns: ``configuration``, ``excitation``, ``sense``, ``block``,
        ``motion``, ``count``, ``total`` (valid samples), ``probability [-]``,
        ``low [-]``, ``high [-]`` (the confidence interval). ``attrs``:
        ``model``, ``seed``, ``confidence``, ``interval``, ``variations``.

        Returns
        -------
        pandas.DataFrame
            The table described above: units in the column names, metadata in
            ``attrs``.
        """
        rows = [
            {
                "configuration": case.configuration,
                "excitation": case.excitation,
                "sense": _sense_word(case.sense),
                "block": item.block,
                "motion": item.outcome,
                "count": item.count,
                "total": item.total,
                "probability [-]": item.probability,
                "low [-]": item.low,
                "high [-]": item.high,
            }
            for case in self.sweep.cases
            for item in case.motions
        ]
        sweep = self.sweep
        return frame(
            rows,
            SAMPLE_COLUMNS,
            {
                "model": self.model,
                "seed": sweep.seed,
                "confidence": sweep.confidence,
                "interval": sweep.interval,
                "variations": [v.describe() for v in sweep.variations],
            },
        )

    def sample_columns(self) -> dict[str, np.ndarray]:
        """Every sample of every case: the inputs drawn and each block's motion.

        Keys: ``configuration``, ``excitation``, ``sense``, ``sample``, each
        varied parameter's label, ``status``, and per block B ``B.motion``,
        ``B.slide_direction`` (the columns ``freestand sample --samples``
        writes).
        """
        sweep = self.sweep
        columns: dict[str, list] = {}
        n = len(sweep.samples[0]) if sweep.samples else sweep.cases[0].samples
        motion_names = np.array([m.value for m in MOTIONS] + [""], dtype=object)
        for case in sweep.cases:
            result = case.result
            columns.setdefault("configuration", []).append(
                np.full(n, case.configuration, dtype=object)
            )
            columns.setdefault("excitation", []).append(np.full(n, case.excitation, dtype=object))
            columns.setdefault("sense", []).append(
                np.full(n, _sense_word(case.sense), dtype=object)
            )
            columns.setdefault("sample", []).append(np.arange(n))
            for variation, values in zip(sweep.variations, sweep.samples, strict=True):
                columns.setdefault(variation.parameter.label, []).append(values)
            columns.setdefault("status", []).append(
                np.array(STATUS_NAMES, dtype=object)[result.status]
            )
            for b, name in enumerate(result.names):
                columns.setdefault(f"{name}.motion", []).append(motion_names[result.motion[:, b]])
                columns.setdefault(f"{name}.slide_direction", []).append(
                    result.slide_direction[:, b]
                )
        return {key: np.concatenate(parts) for key, parts in columns.items()}

    def samples_frame(self):
        """:meth:`sample_columns` as a DataFrame: one row per sample and case.

        Returns
        -------
        pandas.DataFrame
            One row per sample, units in the column names.
        """
        import pandas as pd

        table = pd.DataFrame(self.sample_columns())
        table.attrs.update({"model": self.model, "seed": self.sweep.seed})
        return table


def _excitations(what, excitations) -> list[Excitation]:
    """The excitations asked (names or objects), each vertical sense its own excitation."""
    if excitations is None:
        chosen = list(what.excitations)
    else:
        if isinstance(excitations, str | Excitation):
            excitations = [excitations]
        known = {e.name: e for e in what.excitations}
        chosen = []
        for item in excitations:
            if isinstance(item, Excitation):
                chosen.append(item)
            elif item in known:
                chosen.append(known[item])
            else:
                raise FreestandError(
                    f"no excitation named {item!r}; choose one of "
                    + ", ".join(repr(e) for e in known),
                    source="option --excitation",
                )
    if not chosen:
        raise FreestandError(
            "no excitation to sample; give excitations=[fs.Excitation(...)]",
            source="option --excitation",
        )
    return [
        replace(
            e,
            name=e.name if len(e.verticals()) == 1 else f"{e.name} (a_v {word})",
            vertical=vertical,
            vertical_senses="given",
        )
        for e in chosen
        for vertical, word in zip(e.verticals(), ("down", "up"), strict=False)
    ]


def _variations(vary, gravity: float, stacks) -> list[Variation]:
    from freestand.io.parameters import check_parameters, parse_variation

    if isinstance(vary, str | Variation):
        vary = [vary]
    items = list(vary or [])
    variations = [
        item if isinstance(item, Variation) else parse_variation(item, "--vary", gravity)
        for item in items
    ]
    check_parameters(
        [(v.parameter, str(text)) for v, text in zip(variations, items, strict=True)],
        stacks,
        "--vary",
    )
    return variations


def sample(
    model,
    vary: str | Variation | Iterable[str | Variation] = (),
    n: int = 100_000,
    seed: int = 0,
    *,
    configurations: str | Iterable[str] | None = None,
    excitations: str | Excitation | Iterable[str | Excitation] | None = None,
    sense: str = "both",
    confidence: float = 0.95,
    interval: str = "wilson",
    gravity: float | None = None,
    progress: Callable[[int], None] | None = None,
) -> SampleResult:
    """Monte Carlo over uncertain inputs: the probability of each initial motion.

    ``n`` samples of the inputs are drawn (``numpy.random.default_rng(seed)``)
    and the screening's contact problem from rest is solved for each
    (compiled batch solver, the same answers as :func:`freestand.screen`);
    the share of each block's motion is given with its Wilson (1927) or
    Clopper-Pearson (1934) confidence interval.

    Parameters
    ----------
    model : ModelFile or Stack
        A loaded model file or a stack (with ``excitations`` as objects).
    vary : str or Variation, or a sequence of them
        Uncertain inputs ``NAME=DISTRIBUTION``, e.g.
        ``"friction.static=uniform(0.25,0.45)"``, ``"cart.centre.x+=normal(0,0.05)"``,
        ``"cart.mass*=uniform(0.9,1.1)"`` (see ``docs/maps.md``).
    n : int
        Samples per case, 1 to 10,000,000.
    seed : int
        Random seed (>= 0).
    configurations : str or sequence of str, optional
        Only these configurations (default: all).
    excitations : str or Excitation, or a sequence of them, optional
        Only these excitations (names of the model's, or objects); default
        all. An excitation analysed with both vertical senses is two cases.
    sense : {"both", "+", "-"}
        Sense(s) of the horizontal inertial force.
    confidence : float
        Confidence level of the intervals, in (0, 1).
    interval : {"wilson", "clopper-pearson"}
        Kind of interval.
    gravity : float, optional
        g [m/s^2] (default: the model's, 9.81 for a stack).
    progress : callable, optional
        Called with the number of samples just solved.

    Returns
    -------
    SampleResult
        ``to_dict()`` (the ``freestand sample --json`` document),
        ``to_frame()`` (one row per motion) and ``samples_frame()`` (one row
        per sample).

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model("examples/crane.toml")
    >>> result = fs.sample(model, "friction.static=uniform(0.25,0.45)", n=10_000,
    ...                    configurations="y-z", excitations="rigid", sense="+")
    >>> case = result.cases[0]
    >>> round(case.probability("bridge", "slide").probability, 2)
    0.56
    """
    what = subject(model, gravity=gravity)
    stacks = what.select(configurations)
    chosen = _excitations(what, excitations)
    if not 0 <= seed < 2**63:
        raise FreestandError(
            f"{seed} is not a seed; give a whole number >= 0, e.g. --seed 1",
            source="option --seed",
        )
    if not 1 <= n <= MAX_SAMPLES:
        raise FreestandError(
            f"{n} samples per case is out of range; give 1 to {MAX_SAMPLES:,}, e.g. --n 10000",
            source="option --n",
        )
    if not 0 < confidence < 1:
        raise FreestandError(
            f"{confidence} is not a confidence level; give a number between 0 and 1, e.g. 0.95",
            source="option --confidence",
        )
    if interval not in INTERVALS:
        raise FreestandError(
            f"{interval!r} is not an interval; use {' or '.join(INTERVALS)}",
            source="option --interval",
        )
    variations = _variations(vary, what.gravity, stacks)
    senses = parse_sense(sense)
    total = n * len(stacks) * len(chosen) * len(senses)
    if total > MAX_SOLVES:
        raise FreestandError(
            f"{n:,} samples x {total // n} cases is {total:,} solutions, beyond the "
            f"{MAX_SOLVES:,} of one run; give a smaller --n, or fewer cases with -c, -e or "
            "--sense",
            source="option --n",
        )
    sweep = monte_carlo(
        stacks, chosen, variations, n, seed, what.gravity, senses, confidence, interval, progress
    )
    return SampleResult(what.name, sweep)
