"""The fragility section of the report, for a model file with a ``[fragility]`` table.

The table names the campaign (paths relative to the model file)::

    [fragility]
    suite = "records/suite.toml"     # required
    configuration = "x-z cart right" # default: the first
    im = "pga"                       # as --im; default pga, pga-rotd50 for a 3-D body
    levels = "1:8:15"                # as --levels; or cloud = true
    outcomes = ["overturn:cart", "slide:cart>0.05m"]   # default: per configuration
    vary = ["friction.static=uniform(0.15,0.35)"]      # optional
    samples = 10                     # optional
    both_polarities = true           # optional
    seed = 0                         # optional
    bootstrap = 1000                 # optional
    angle = 30                       # 3-D, optional: as --angle [deg]
    angles = 8                       # 3-D, optional: as --angles

The campaign runs on every local core, as ``freestand fragility`` would. A 3-D
configuration (a box or a cylinder) runs under the records' three components,
turned by an incidence angle drawn per simulation unless ``angle`` or ``angles``
fixes it (``docs/fragility.md``, 3-D bodies).
"""

from __future__ import annotations

import html
import math
from dataclasses import dataclass

from freestand.core.sweeps.fragility.analysis import FragilityResult
from freestand.errors import FreestandError
from freestand.io.fragility_options import FRAGILITY_KEYS

_KEYS = set(FRAGILITY_KEYS)


@dataclass(frozen=True)
class FragilitySection:
    """A fragility campaign run for the report.

    Attributes
    ----------
    document : dict
        The ``freestand fragility --json`` document.
    result : FragilityResult
    im_label : str
        Axis label with unit.
    """

    document: dict
    result: FragilityResult
    im_label: str


def assess_fragility(model, workers: int | None = None) -> FragilitySection | None:
    """Run the ``[fragility]`` campaign of ``model`` (None when it has none)."""
    table = model.fragility
    if not table:
        return None
    source = f"{model.source} [fragility] "
    unknown = sorted(set(table) - _KEYS)
    if unknown:
        raise FreestandError(
            f"unknown key(s) {', '.join(unknown)}; use {', '.join(sorted(_KEYS))}", source=source
        )
    if not isinstance(table.get("suite"), str):
        raise FreestandError('give the record suite, e.g. suite = "suite.toml"', source=source)

    def get(key: str):
        return table.get(key, FRAGILITY_KEYS[key].default)

    cloud = bool(get("cloud"))
    if cloud == ("levels" in table):
        raise FreestandError('give levels = "A:B:N" or cloud = true', source=source)
    from freestand.io.campaign_runner import run_fragility
    from freestand.io.fragility_options import build_campaign
    from freestand.io.fragility_results import fragility_document, im_label

    suite = model.base_dir / table["suite"]
    im = get("im")
    angle, angles = get("angle"), get("angles")
    campaign, records = build_campaign(
        model, get("configuration"), suite, None if im is None else str(im),
        None if cloud else str(table["levels"]), list(get("vary")) or None,
        get("samples"), list(get("outcomes")) or None,
        bool(get("both_polarities")), int(get("seed")),
        float(get("free_time")), source=source,
        angle=None if angle is None else _number(angle, "angle", source),
        angles=None if angles is None else int(_number(angles, "angles", source)),
    )  # fmt: skip
    bootstrap = int(get("bootstrap"))
    definition, result = run_fragility(
        campaign, model_name=model.name, model_source=model.source, model_sha256=model.sha256,
        suite_name=records.name, suite_source=str(table["suite"]), workers=workers,
        bootstrap=bootstrap, seed=int(get("seed")),
    )  # fmt: skip
    document = fragility_document(definition, result, bootstrap, 0.95)
    return FragilitySection(document, result, im_label(definition["im"]))


def _number(value, key: str, source: str) -> float:
    """A number of the table (an int or a float, not text nor a bool)."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        example = "angle = 30" if key == "angle" else "angles = 8"
        raise FreestandError(f"{key} = {value!r} is not a number; e.g. {example}", source=source)
    if key == "angles" and value != int(value):
        raise FreestandError(f"angles = {value!r}: give a whole number, e.g. 8", source=source)
    return value


def _n(value, digits: int = 4) -> str:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "&#8211;"
    return f"{value:.{digits}g}"


def fragility_html(doc, section: FragilitySection) -> str:
    """The report section (an appendix after the references): method, table, figure."""
    from freestand.plot.fragility import plot_fragility

    d = section.document
    e = html.escape
    unit = e(d["im"]["unit"])
    rows = []
    for item in d["outcomes"]:
        if item["fitted"]:
            cells = (
                f"<td>{_n(item['median'])}</td>"
                f"<td>{_n(item['median_interval'][0])} &#8211; "
                f"{_n(item['median_interval'][1])}</td>"
                f"<td>{_n(item['beta'], 3)}</td>"
                f"<td>{_n(item['beta_interval'][0], 3)} &#8211; "
                f"{_n(item['beta_interval'][1], 3)}</td><td>{_n(item['hclpf'])}</td><td></td>"
            )
        else:
            cells = "<td></td>" * 5 + f"<td>{e(item['reason'] or '')}</td>"
        counts = ", ".join(f"{c}/{t}" for c, t in zip(item["counts"], item["totals"], strict=True))
        rows.append(
            f'<tr data-outcome="{e(item["name"])}"><th>{e(item["name"])}</th>{cells}'
            f"<td>{counts}</td></tr>"
        )
    head = (
        f"<thead><tr><th>outcome</th><th>median [{unit}]</th><th>95 % interval</th>"
        f"<th>beta [-]</th><th>95 % interval</th><th>HCLPF [{unit}]</th><th>note</th>"
        "<th>occurred / simulations per level</th></tr></thead>"
    )
    suite = d["suite"]
    varied = "; ".join(d["variations"]) or "none"
    versions = ", ".join(f"{k} {v}" for k, v in d["versions"].items() if v)
    levels = ", ".join(f"{x:.4g}" for x in d["levels"]) or "each record unscaled (cloud)"
    three_d = "shape" in d
    if three_d:
        angles = d["angles"]
        turned = (
            "turned by an incidence angle drawn uniformly over 0&#8211;360 deg per simulation"
            if angles == "uniform"
            else "turned by the incidence angle(s) " + ", ".join(f"{a:g}" for a in angles) + " deg"
        )
        motion = (
            f"A 3-D {e(d['shape'])}: each record's x, y and vertical components, the "
            f"horizontal pair {turned}; {d['statuses'].get('capped', 0)} simulation(s) still "
            "moving at the cap, counted with the peaks reached. "
        )
        body = "the body"
    else:
        motion, body = "", "the stack"
    table = doc.table(
        f"Lognormal fragility of each outcome against {e(section.im_label)}: maximum likelihood "
        "on the binomial counts, bootstrap intervals.",
        head,
        rows,
    )
    figure = doc.figure(
        plot_fragility(section.result, section.im_label),
        "Fitted fragility curves with their 95 % bootstrap bands, and the fraction of "
        "simulations in which each outcome occurred at each level (Wilson intervals).",
    )
    return (
        '<section id="fragility"><h2>A Fragility campaign</h2>'
        f"<p>Configuration <b>{e(d['configuration'])}</b> under the {len(suite['records'])} "
        f"records of suite <code>{e(suite['name'])}</code> (<code>{e(suite['file'])}</code>), "
        f"scaled to the levels {levels} {unit} of {e(section.im_label)}; "
        f"{d['samples']} sample(s) of the uncertain inputs per record and level "
        f"({e(varied)})"
        f"{', both polarities' if len(d['polarities']) == 2 else ''}; seed {d['seed']}. "
        f"{motion}{d['simulations']} simulations, {d['failed']} failed or invalid (left out "
        f"of the fits). Each simulation runs until {body} is at rest after the record, at most "
        f"{d['free_time']:g} s after it. The HCLPF is the {e(d['fit']['hclpf'])}.</p>"
        f"{table}{figure}"
        f'<p class="note">Reproduce with <code>freestand fragility</code> and the same '
        f"options; campaign fingerprint <code>{e(d['fingerprint'][:16])}</code>; {e(versions)}."
        "</p></section>"
    )
