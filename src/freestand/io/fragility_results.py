"""The definition of a fragility campaign (for its store) and its JSON document."""

from __future__ import annotations

import hashlib
import json
import math
import platform

import numpy as np

from freestand.core.sweeps.fragility.analysis import FragilityResult
from freestand.core.sweeps.fragility.campaign import Campaign
from freestand.core.sweeps.fragility.intensity import IntensityMeasure

#: How the HCLPF is defined (in the JSON document and the docs).
HCLPF_DEFINITION = (
    "lower one-sided bootstrap bound, at the confidence level, of the 5 % quantile "
    "median * exp(-1.645 beta): the intensity at which, with that confidence, the "
    "probability of the outcome is at most 5 %"
)


def _versions() -> dict:
    from importlib.metadata import PackageNotFoundError, version

    out = {"python": platform.python_version()}
    for name in ("freestand", "numpy", "scipy", "numba", "pyarrow"):
        try:
            out[name] = version(name)
        except PackageNotFoundError:
            out[name] = None
    return out


def _record_hash(motion) -> str:
    digest = hashlib.sha256()
    digest.update(np.float64(motion.dt).tobytes())
    digest.update(np.ascontiguousarray(motion.horizontal, dtype=float).tobytes())
    if motion.vertical is not None:
        digest.update(np.ascontiguousarray(motion.vertical, dtype=float).tobytes())
    if getattr(motion, "horizontal_y", None) is not None:  # planar records hash as before
        digest.update(b"horizontal_y")
        digest.update(np.ascontiguousarray(motion.horizontal_y, dtype=float).tobytes())
    return digest.hexdigest()


def campaign_definition(
    campaign: Campaign,
    *,
    model_name: str,
    model_source: str,
    model_sha256: str,
    suite_name: str,
    suite_source: str,
    chunk_size: int,
) -> dict:
    """Everything that defines the simulations, with a fingerprint over it.

    Two runs with the same fingerprint compute the same rows; the store
    refuses to mix runs with different fingerprints. A 3-D campaign adds
    ``shape`` (``box`` or ``cylinder``) and ``angles`` (the fixed incidence
    angles [deg], or ``"uniform"`` for one drawn per simulation).
    """
    stack = campaign.stack
    im = campaign.measure.to_dict()
    if campaign.three_d:
        im["components"] = "x, y" if campaign.measure.two_components else "x"
    defining = {
        "model_sha256": model_sha256,
        "configuration": stack.name,
        "records": [_record_hash(m) for m in campaign.motions],
        "im": im,
        "levels": [float(x) for x in campaign.levels],
        "cloud": campaign.cloud,
        "variations": [v.describe() for v in campaign.variations],
        "samples": campaign.samples,
        "polarities": list(campaign.polarities),
        "seed": campaign.seed,
        "outcomes": [o.key for o in campaign.outcomes],
        "free_time": campaign.free_time,
        "method": campaign.method,
        "gravity": campaign.gravity,
        "chunk_size": chunk_size,
        "freestand": _versions()["freestand"],
    }
    if campaign.three_d:
        defining["shape"] = type(stack.body.shape).__name__.lower()
        defining["angles"] = list(campaign.angles) or "uniform"
    fingerprint = hashlib.sha256(json.dumps(defining, sort_keys=True).encode()).hexdigest()
    return {
        "format": "freestand fragility store 1",
        "fingerprint": fingerprint,
        "model": model_name,
        "model_file": model_source,
        "suite": {
            "name": suite_name,
            "file": suite_source,
            "records": [m.name for m in campaign.motions],
            "record_intensity": [float(x) for x in campaign.record_intensity],
        },
        "blocks": list(campaign.block_names),
        "simulations": campaign.size,
        "versions": _versions(),
        **defining,
    }


def _number(value) -> float | None:
    value = float(value)
    return value if math.isfinite(value) else None


def _pair(values) -> list:
    return [_number(v) for v in values]


def fragility_document(definition: dict, result: FragilityResult, bootstrap: int,
                       confidence: float) -> dict:  # fmt: skip
    """The ``--json`` document: campaign, counts and fits of every outcome (SI units)."""
    outcomes = []
    for item in result.outcomes:
        f = item.fragility
        data = item.outcome.to_dict()
        data.update(
            levels=[float(x) for x in f.levels],
            counts=[int(x) for x in f.counts],
            totals=[int(x) for x in f.totals],
            fractions=[_number(x) for x in f.fraction],
            fraction_intervals=[[_number(lo), _number(hi)]
                                for lo, hi in zip(f.fraction_low, f.fraction_high, strict=True)],
            fitted=f.fitted,
            reason=f.reason or None,
            median=_number(f.median) if f.fitted else None,
            beta=_number(f.beta) if f.fitted else None,
            median_interval=_pair(f.median_interval) if f.fitted else None,
            beta_interval=_pair(f.beta_interval) if f.fitted else None,
            quantile05=_number(f.quantile05) if f.fitted else None,
            hclpf=_number(f.hclpf) if f.fitted else None,
        )  # fmt: skip
        outcomes.append(data)
    three_d = {key: definition[key] for key in ("shape", "angles") if key in definition}
    return {
        "model": definition["model"],
        "configuration": definition["configuration"],
        **three_d,
        "suite": definition["suite"],
        "im": definition["im"],
        "levels": definition["levels"],
        "cloud": definition["cloud"],
        "samples": definition["samples"],
        "polarities": definition["polarities"],
        "variations": definition["variations"],
        "seed": definition["seed"],
        "free_time": definition["free_time"],
        "simulations": result.simulations,
        "failed": result.failed,
        "statuses": result.statuses,
        "fit": {
            "method": "cloud" if result.cloud else "multiple stripes",
            "likelihood": "binomial (Baker 2015)",
            "bootstrap": bootstrap,
            "confidence": confidence,
            "hclpf": HCLPF_DEFINITION,
        },
        "outcomes": outcomes,
        "versions": definition["versions"],
        "fingerprint": definition["fingerprint"],
    }


def im_label(im: dict) -> str:
    """Axis label of an IM document with its unit, e.g. ``"PGA [m/s^2]"``."""
    measure = IntensityMeasure(
        im["kind"],
        frequency=im.get("frequency"),
        damping=im.get("damping", 0.05),
        block=im.get("block"),
    )
    on_x = " of x" if im.get("components") == "x" else ""
    return f"{measure.describe()}{on_x} [{im['unit']}]"
