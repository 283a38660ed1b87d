"""Public fragility campaigns: :func:`fragility` and :func:`fragility_from_store`."""

from __future__ import annotations

import hashlib
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from freestand.api.base import Result, frame
from freestand.core.body import Body, BodyConfiguration
from freestand.core.model import Stack
from freestand.core.sweeps.fragility.analysis import FragilityResult as CoreFragilityResult
from freestand.errors import FreestandError

#: Columns of :meth:`FragilityResult.to_frame` (``table="stripes"``); ``{unit}`` is the IM's.
STRIPE_COLUMNS = (
    "outcome",
    "level [{unit}]",
    "count",
    "total",
    "fraction [-]",
    "fraction_low [-]",
    "fraction_high [-]",
    "probability [-]",
)
#: Columns of :meth:`FragilityResult.to_frame` (``table="fits"``).
FIT_COLUMNS = (
    "outcome",
    "kind",
    "block",
    "fitted",
    "reason",
    "occurrences",
    "median [{unit}]",
    "median_low [{unit}]",
    "median_high [{unit}]",
    "beta [-]",
    "beta_low [-]",
    "beta_high [-]",
    "quantile05 [{unit}]",
    "hclpf [{unit}]",
)


@dataclass(frozen=True)
class FragilityResult(Result):
    """The fragility curves of a campaign: counts per level and a lognormal fit per outcome.

    Attributes
    ----------
    definition : dict
        What defines the campaign (model, suite, IM, levels, inputs, seed,
        versions) and its fingerprint, as in the store's ``campaign.json``.
    core : freestand.core.sweeps.fragility.analysis.FragilityResult
        Per outcome, the counts, fractions with Wilson intervals and the fit
        (median theta, beta, bootstrap intervals, HCLPF).
    bootstrap : int
        Bootstrap replicates of the intervals.
    confidence : float
        Confidence level of the intervals [-].
    store : str or None
        The store folder, when there is one.

    Examples
    --------
    >>> import freestand as fs
    >>> block = fs.Block.rectangle("cabinet", 0.6, 2.0, 1200.0, fs.Friction(0.8, 0.7))
    >>> records = [fs.load_record("examples/records/synthetic_H.AT2")]
    >>> result = fs.fragility(fs.Stack("cabinet", (block,)), records, "pga", "1:8:8",
    ...                       ["uplift:cabinet", "flight:cabinet"], workers=1)
    >>> result.to_frame("fits")[["outcome", "occurrences", "fitted"]].values.tolist()
    [['cabinet uplifts', 5, False], ['cabinet in free flight', 0, False]]
    >>> fig = result.plot()  # a panel for the uplift; the free flight, never seen, in a note
    """

    definition: dict
    core: CoreFragilityResult
    bootstrap: int
    confidence: float
    store: str | None = None

    @property
    def outcomes(self):
        """Per outcome, the outcome and its fitted fragility (``OutcomeFragility``)."""
        return self.core.outcomes

    @property
    def unit(self) -> str:
        """The IM's unit (``"m/s^2"``, ``"m/s"``, ``"-"``)."""
        return self.definition["im"]["unit"]

    @property
    def im_label(self) -> str:
        """The IM with its unit, e.g. ``"PGA [m/s^2]"``."""
        from freestand.io.fragility_results import im_label

        return im_label(self.definition["im"])

    @property
    def title(self) -> str:
        """The figure title: model, configuration, simulations."""
        d = self.definition
        return f"{d['model']} / {d['configuration']}: {self.core.simulations} simulations"

    def to_dict(self) -> dict:
        """The ``freestand fragility --json`` document (see ``docs/fragility.md``, Outputs).

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        from freestand.io.fragility_results import fragility_document

        document = fragility_document(self.definition, self.core, self.bootstrap, self.confidence)
        if self.store is not None:
            document["store"] = self.store
        return document

    def to_frame(self, table: str = "stripes"):
        """The stripes or the fits as a DataFrame (IM unit in the column names).

        Parameters
        ----------
        table : {"stripes", "fits"}
            ``"stripes"`` (default): one row per outcome and level, columns
            ``outcome``, ``level [unit]``, ``count`` (simulations in which it
            occurred), ``total`` (simulations counted), ``fraction [-]``,
            ``fraction_low [-]``, ``fraction_high [-]`` (Wilson interval),
            ``probability [-]`` (the fitted curve at the level, NaN when not
            fitted); for a cloud, one row per distinct intensity.
            ``"fits"``: one row per outcome, columns ``outcome``, ``kind``,
            ``block``, ``fitted``, ``reason`` (why not), ``occurrences``,
            ``median [unit]``, ``median_low [unit]``, ``median_high [unit]``,
            ``beta [-]``, ``beta_low [-]``, ``beta_high [-]``,
            ``quantile05 [unit]``, ``hclpf [unit]``.

        ``attrs``: ``model``, ``configuration``, ``im``, ``unit``,
        ``simulations``, ``failed``, ``confidence``, ``fingerprint``.

        Returns
        -------
        pandas.DataFrame
            The table described above: units in the column names, metadata in
            ``attrs``.
        """
        unit = self.unit
        d = self.definition
        attrs = {
            "model": d["model"],
            "configuration": d["configuration"],
            "im": self.im_label,
            "unit": unit,
            "simulations": self.core.simulations,
            "failed": self.core.failed,
            "confidence": self.confidence,
            "fingerprint": d["fingerprint"],
        }
        if table == "fits":
            columns = [c.format(unit=unit) for c in FIT_COLUMNS]
            rows = []
            for item in self.core.outcomes:
                f = item.fragility
                values = (
                    item.outcome.name, item.outcome.kind, item.outcome.block, f.fitted,
                    f.reason or None, int(np.sum(f.counts)), f.median, *f.median_interval,
                    f.beta, *f.beta_interval, f.quantile05, f.hclpf,
                )  # fmt: skip
                rows.append(dict(zip(columns, values, strict=True)))
            return frame(rows, columns, attrs)
        if table != "stripes":
            raise ValueError(f"{table!r} is not a table; use 'stripes' or 'fits'")
        columns = [c.format(unit=unit) for c in STRIPE_COLUMNS]
        rows = []
        for item in self.core.outcomes:
            f = item.fragility
            probability = f.probability(f.levels) if f.fitted else np.full(f.levels.size, np.nan)
            for k in range(f.levels.size):
                values = (
                    item.outcome.name, float(f.levels[k]), int(f.counts[k]), int(f.totals[k]),
                    float(f.fraction[k]), float(f.fraction_low[k]), float(f.fraction_high[k]),
                    float(probability[k]),
                )  # fmt: skip
                rows.append(dict(zip(columns, values, strict=True)))
        return frame(rows, columns, attrs)

    def plot(self, ax=None):
        """The fragility figure ``freestand fragility --plot`` writes.

        The fitted lognormal curves with their bootstrap bands and the stripe
        fractions with their Wilson intervals, one panel per outcome that
        occurred; the outcomes that never occurred (or were not fitted) are
        named in a note under the panels. With ``ax`` (one outcome that
        occurred at most), it is drawn into those axes.

        Returns
        -------
        matplotlib.figure.Figure
        """
        from freestand.plot.fragility import plot_fragility

        return plot_fragility(self.core, self.im_label, self.title, ax=ax)


def _stack_model(stack: Stack | BodyConfiguration, gravity: float | None):
    """A model file holding one stack or 3-D configuration, for a campaign on it alone."""
    from freestand.io.model_file import ModelFile

    three_d = isinstance(stack, BodyConfiguration)
    text = repr(stack) + (repr(stack.body.inertia.tolist()) if three_d else "")
    return ModelFile(
        name=stack.name,
        gravity=9.81 if gravity is None else float(gravity),
        excitations=(),
        configurations=() if three_d else (stack,),
        source="<configuration>" if three_d else "<stack>",
        sha256=hashlib.sha256(text.encode()).hexdigest(),
        body_configurations=(stack,) if three_d else (),
    )


def _suite(suite):
    """A suite file, a loaded suite, or records made into a suite."""
    from freestand.core.motion.ground_motion import GroundMotion
    from freestand.io.suites import RecordSuite

    if isinstance(suite, str | Path | RecordSuite):
        return suite
    motions = tuple(suite)
    if not motions or not all(isinstance(m, GroundMotion) for m in motions):
        raise TypeError(
            "expected a suite file, a RecordSuite (fs.load_suite) or a list of records "
            f"(fs.load_record), not {type(suite).__name__}"
        )
    files = tuple((m.name, "") for m in motions)
    return RecordSuite("records", motions, "<records>", (1.0,) * len(motions), files)


def _check_options(levels, cloud, workers, scheduler, free_time, chunk, bootstrap, confidence,
                   seed) -> None:  # fmt: skip
    if cloud == (levels is not None):
        raise FreestandError(
            "give either --levels A:B:N (stripes) or --cloud (unscaled records)", source="--levels"
        )
    if workers is not None and workers < 1:
        raise FreestandError(f"{workers} workers: give 1 or more", source="--workers")
    if workers is not None and scheduler is not None:
        raise FreestandError("give --workers or --scheduler, not both", source="--scheduler")
    if not (free_time >= 0 and math.isfinite(free_time)):
        raise FreestandError(f"{free_time} s: give 0 or more", source="--free-time")
    if chunk is not None and chunk < 1:
        raise FreestandError(f"{chunk}: give 1 or more", source="--chunk")
    check_fit_options(bootstrap, confidence, seed)


def check_fit_options(bootstrap: int, confidence: float, seed: int) -> None:
    """FreestandError for a confidence outside (0, 1), negative replicates or seed."""
    if not 0 < confidence < 1:
        raise FreestandError(f"{confidence} is not in (0, 1); e.g. 0.95", source="--confidence")
    if bootstrap < 0:
        raise FreestandError(f"{bootstrap} replicates: give 0 or more", source="--bootstrap")
    if seed < 0:
        raise FreestandError(f"{seed} is negative; give a seed >= 0", source="--seed")


def fragility(
    model,
    suite,
    im=None,
    levels=None,
    outcomes: Sequence | None = None,
    *,
    configuration: str | None = None,
    vary: Sequence | None = None,
    samples: int | None = None,
    both_polarities: bool = False,
    cloud: bool = False,
    seed: int = 0,
    free_time: float = 10.0,
    bootstrap: int = 1000,
    confidence: float = 0.95,
    workers: int | None = None,
    scheduler=None,
    store: str | Path | None = None,
    chunk: int | None = None,
    gravity: float | None = None,
    progress: Callable[[int, int], None] | None = None,
    angle: float | None = None,
    angles: int | None = None,
) -> FragilityResult:
    """Fragility curves: the probability of each outcome against a ground-motion intensity.

    The time history (:func:`freestand.simulate`, until the stack is at rest
    after the record, at most ``free_time`` later) runs over a suite of
    records scaled to each level of an intensity measure (multiple-stripe
    analysis, Jalayer and Cornell 2009) or unscaled (``cloud``), over
    samples of uncertain inputs; a lognormal curve P(x) = Phi(ln(x / theta) /
    beta) is fitted to each outcome by maximum likelihood on the binomial
    counts (Baker 2015, eq. 11), with bootstrap intervals of theta and beta,
    Wilson intervals of the fractions and the HCLPF (Kennedy and Ravindra
    1984). Every task has its own seed: the results do not depend on the
    workers or the scheduler.

    A 3-D configuration (a box or a cylinder) runs under the records' three
    components (x, y, vertical; a record without y has y = 0), their
    horizontal pair turned by an incidence angle drawn uniformly over
    0-360 deg per simulation from ``seed`` (stored with each simulation),
    fixed (``angle``) or swept (``angles``); its outcomes are judged from
    its tilt, horizontal slide, twist, uplift and overturning
    (``docs/fragility.md``, 3-D bodies).

    Parameters
    ----------
    model : ModelFile, Stack, BodyConfiguration or Body
        A loaded model file (``configuration`` names the configuration,
        planar or 3-D), a stack or a 3-D body.
    suite : str, pathlib.Path, RecordSuite or sequence of GroundMotion
        A record suite file (TOML, see ``docs/records.md``), a loaded suite
        (``fs.load_suite``) or records (``fs.load_record``).
    im : str or IntensityMeasure, optional
        ``"pga"`` [m/s^2], ``"pgv"`` [m/s], ``"sa:F[,DAMPING]"`` [m/s^2] or
        ``"pga-alpha[:BLOCK]"`` [-] (PGA / (g tan alpha)) of the record's x
        component; for 3-D configurations also the two-component
        ``"pga-rotd50"``, ``"pga-rotd100"``, ``"pga-gm"``, the same of
        ``pgv``, ``"sa-rotd50:F[,DAMPING]"``, ... (not ``pga-alpha``).
        Default ``"pga"`` for a planar configuration, ``"pga-rotd50"`` for a
        3-D one.
    levels : str or sequence of float, optional
        The stripes: ``"A:B:N"`` (N levels from A to B, SI or with units, e.g.
        ``"0.05g:1g:20"``) or the levels [IM unit]. Leave out with ``cloud``.
    outcomes : sequence of str or Outcome, optional
        ``"overturn:BLOCK"``, ``"rotation:BLOCK>0.5alpha"``,
        ``"slide:BLOCK>0.05m"``, ``"uplift:BLOCK"``, ``"flight:BLOCK"``, and
        for a 3-D body ``"twist:BODY>5"`` [deg] (default: per configuration,
        see ``docs/fragility.md``).
    configuration : str, optional
        Configuration of the model (default: the first planar one, or the
        first 3-D one in a model without planar configurations).
    vary : sequence of str or Variation, optional
        Uncertain block inputs, as for :func:`freestand.sample` (planar
        configurations only).
    samples : int, optional
        Samples per record and level (default 1; 10 with ``vary``).
    both_polarities : bool
        Also run every record with its horizontal component negated.
    cloud : bool
        Run the records unscaled (cloud analysis) instead of stripes.
    seed : int
        Seed of the inputs and of the bootstrap (>= 0).
    free_time : float
        Cap [s] on the time simulated after a record.
    bootstrap : int
        Bootstrap replicates (0 for none).
    confidence : float
        Confidence level of the intervals [-].
    workers : int, optional
        Local worker processes (default: every core; 1 runs in this process).
    scheduler : str or distributed.Client, optional
        A Dask scheduler address (``"tcp://HOST:8786"``) or client, instead
        of local workers.
    store : str or pathlib.Path, optional
        A folder where every simulation is written (Parquet) as it finishes;
        a stopped campaign resumes from it.
    chunk : int, optional
        Simulations per chunk (the unit of work and of storage).
    gravity : float, optional
        g [m/s^2] for a bare stack (a model file's own otherwise).
    progress : callable, optional
        Called with the number of simulations just finished and the number
        in the campaign.
    angle : float, optional
        3-D configurations: a fixed incidence angle [deg] by which every
        record's horizontal pair is turned, counter-clockwise from +x
        (:func:`freestand.support_motion3`).
    angles : int, optional
        3-D configurations: every record, level and sample at N angles,
        every 360/N deg.

    Returns
    -------
    FragilityResult
        ``to_dict()`` (the ``freestand fragility --json`` document),
        ``to_frame()`` (stripes; ``"fits"`` for one row per outcome) and
        ``plot()`` (the curves).

    Examples
    --------
    >>> import freestand as fs
    >>> block = fs.Block.rectangle("cabinet", 0.6, 2.0, 1200.0, fs.Friction(0.8, 0.7))
    >>> records = [fs.load_record("examples/records/synthetic_H.AT2")]
    >>> result = fs.fragility(fs.Stack("cabinet", (block,)), records, "pga", "1:8:8",
    ...                       ["uplift:cabinet"], both_polarities=True, workers=1)
    >>> result.to_frame()[["level [m/s^2]", "count", "total"]].iloc[2:5]
       level [m/s^2]  count  total
    2            3.0      0      2
    3            4.0      2      2
    4            5.0      2      2

    A 3-D body: the cabinet of ``examples/bodies.toml`` under a record with x
    and y, scaled by its PGA RotD50 (the default IM of a 3-D configuration),
    at four incidence angles every 90 deg (it lifts from 4 m/s^2 and twists
    by about 1.2 deg there, at fine steps; by more than 10 deg at 6 m/s^2):

    >>> bodies = fs.load_model("examples/bodies.toml")
    >>> record = fs.load_record("examples/records/synthetic_H.AT2",
    ...                         horizontal_y="examples/records/synthetic_H.AT2")
    >>> cabinet = fs.fragility(bodies, [record], levels="2,4,6", configuration="cabinet",
    ...                        outcomes=["uplift:cabinet", "twist:cabinet>5"], angles=4,
    ...                        free_time=2.0, bootstrap=0, workers=1)
    >>> cabinet.to_dict()["angles"], cabinet.to_dict()["im"]["kind"]
    ([0.0, 90.0, 180.0, 270.0], 'pga-rotd50')
    >>> cabinet.to_frame()["count"].tolist()  # of 4 at 2, 4, 6 m/s^2: uplift, then twist
    [0, 4, 4, 0, 0, 4]
    """
    from freestand.io.campaign_runner import run_fragility
    from freestand.io.fragility_options import build_campaign
    from freestand.io.model_file import ModelFile

    _check_options(levels, cloud, workers, scheduler, free_time, chunk, bootstrap, confidence,
                   seed)  # fmt: skip
    if isinstance(model, Body):
        model = BodyConfiguration(model.name, (model,))
    if isinstance(model, Stack | BodyConfiguration):
        model = _stack_model(model, gravity)
    elif not isinstance(model, ModelFile):
        raise TypeError(
            "expected a model file (fs.load_model), a Stack or a BodyConfiguration, not "
            f"{type(model).__name__}"
        )
    campaign, records = build_campaign(
        model, configuration, _suite(suite), im, levels, vary, samples, outcomes, both_polarities,
        seed, free_time, angle=angle, angles=angles,
    )  # fmt: skip
    definition, result = run_fragility(
        campaign, model_name=model.name, model_source=model.source, model_sha256=model.sha256,
        suite_name=records.name,
        suite_source=str(suite) if isinstance(suite, str | Path) else records.source,
        chunk_size=chunk, workers=workers, scheduler=scheduler, store=store,
        progress=None if progress is None else lambda done: progress(done, campaign.size),
        bootstrap=bootstrap, confidence=confidence, seed=seed,
    )  # fmt: skip
    return FragilityResult(
        definition, result, bootstrap, confidence, None if store is None else str(store)
    )


def fragility_from_store(
    store: str | Path,
    outcomes: Sequence | None = None,
    *,
    bootstrap: int = 1000,
    confidence: float = 0.95,
    seed: int = 0,
) -> FragilityResult:
    """Fit again from a campaign's store alone, without simulating.

    Parameters
    ----------
    store : str or pathlib.Path
        The store folder of a campaign (``fragility(..., store=...)``).
    outcomes : sequence of str or Outcome, optional
        Outcomes to judge from the stored peaks (default: the campaign's).
    bootstrap, confidence, seed
        As for :func:`fragility`.

    Returns
    -------
    FragilityResult
        Over the simulations stored (``core.simulations`` may be fewer than
        ``definition["simulations"]`` for a stopped campaign).

    Examples
    --------
    >>> import pathlib, tempfile, freestand as fs
    >>> block = fs.Block.rectangle("cabinet", 0.6, 2.0, 1200.0, fs.Friction(0.8, 0.7))
    >>> records = [fs.load_record("examples/records/synthetic_H.AT2")]
    >>> store = pathlib.Path(tempfile.mkdtemp()) / "store"
    >>> _ = fs.fragility(fs.Stack("cabinet", (block,)), records, "pga", "1:8:8",
    ...                  ["uplift:cabinet"], workers=1, store=store)
    >>> again = fs.fragility_from_store(store, outcomes=["rotation:cabinet>0.5alpha"])
    >>> again.to_frame("fits")[["outcome", "occurrences"]].values.tolist()
    [['cabinet rotates > 0.5 alpha', 2]]
    """
    from freestand.core.sweeps.fragility.analysis import analyse
    from freestand.io.fragility_options import parse_outcome
    from freestand.io.store import CampaignStore

    check_fit_options(bootstrap, confidence, seed)
    stored = CampaignStore(store)
    try:
        definition = stored.definition()
    except FreestandError as error:
        if error.source != "--store":
            raise
        raise FreestandError(error.detail, source="--from-store") from None
    rows = stored.read()
    if not rows:
        raise FreestandError(f"{str(store)!r} holds no simulation yet", source="--from-store")
    blocks = definition["blocks"]
    chosen = [
        text
        if not isinstance(text, str)
        else parse_outcome(text, blocks, three_d="shape" in definition)
        for text in (outcomes or definition["outcomes"])
    ]
    result = analyse(
        rows, chosen, [] if definition["cloud"] else definition["levels"],
        unit=definition["im"]["unit"], bootstrap=bootstrap, confidence=confidence, seed=seed,
    )  # fmt: skip
    return FragilityResult(definition, result, bootstrap, confidence)
