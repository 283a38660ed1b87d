"""The stable public entry points of freestand, for scripts and notebooks.

``import freestand as fs`` gives these names (see the README, "Python API").
They are thin: each calls the one implementation in :mod:`freestand.core` or
:mod:`freestand.io`; whatever moves inside the package, these names stay. One
module per analysis, each with its function(s) and result class(es); the
command line (:mod:`freestand.cli`) is a shell over them: a command's
``--json`` prints ``result.to_dict()``.
"""

from __future__ import annotations

from freestand.api.body_simulation import BodySimulationResult, support_motion3
from freestand.api.fragility import FragilityResult, fragility, fragility_from_store
from freestand.api.frequency import FrequencyResult, frequency
from freestand.api.intensity import intensity_measure
from freestand.api.maps import ModeMapResult, SampleResult, mode_map, sample
from freestand.api.overturning import OverturningResult, overturning
from freestand.api.records import (
    FloorMotion,
    GeneratedSuite,
    RecordSpectra,
    floor_motion,
    generate_suite,
    response_spectrum,
)
from freestand.api.report import ReportResult, write_report
from freestand.api.screening import ScreeningResult, screen
from freestand.api.simulation import SimulationResult, simulate, support_motion

__all__ = [
    "BodySimulationResult",
    "FloorMotion",
    "FragilityResult",
    "FrequencyResult",
    "GeneratedSuite",
    "ModeMapResult",
    "OverturningResult",
    "RecordSpectra",
    "ReportResult",
    "SampleResult",
    "ScreeningResult",
    "SimulationResult",
    "floor_motion",
    "fragility",
    "fragility_from_store",
    "frequency",
    "generate_suite",
    "intensity_measure",
    "mode_map",
    "overturning",
    "response_spectrum",
    "sample",
    "screen",
    "simulate",
    "support_motion",
    "support_motion3",
    "write_report",
]
