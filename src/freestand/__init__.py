"""freestand: seismic screening of free-standing rigid-block stacks.

``import freestand as fs`` gives the public entry points (README, "Python
API"); they are loaded on first use, so the command line starts fast:

- models and records: :func:`load_model` (and :func:`example_path`), :func:`load_record`,
  :func:`load_suite`, :func:`load_station`, :class:`GroundMotion`, :class:`SupportMotion`,
  :class:`SupportMotion3` (and :func:`support_motion3`),
  :class:`Block`, :class:`Stack`, :class:`Friction`, :class:`Sliding`,
  :class:`Excitation`;
- analyses, one per command, each returning a result with ``to_dict()``
  (the command's ``--json``), ``to_frame()`` (a pandas table) and, where the
  command draws one, ``plot()``: :func:`screen` (paper Tables 2-5),
  :func:`simulate` (time history), :func:`overturning` (Figs. 6-8),
  :func:`frequency` (Fig. 9), :func:`mode_map`, :func:`sample` (Monte
  Carlo), :func:`fragility` (and :func:`fragility_from_store`),
  :func:`write_report`, :func:`response_spectrum`, :func:`generate_suite`,
  :func:`floor_motion`; also :class:`RockingBlock`,
  :func:`overturning_limits`, and :func:`intensity_measure` with
  :class:`IntensityMeasure` (PGA, PGV, Sa, and of two horizontal components
  their geometric mean, RotD50 and RotD100);
- :class:`FreestandError`, the one error class.

The package is layered:

- :mod:`freestand.core` -- the pure numerical core (SI floats, numpy arrays,
  frozen dataclasses; no printing, no files, no plotting);
- :mod:`freestand.io` -- model files, spectra and records, validated at the
  boundary;
- :mod:`freestand.plot`, :mod:`freestand.report` -- figures and reports that
  only consume results;
- :mod:`freestand.cli` -- the thin ``freestand`` command.
"""

from __future__ import annotations

from importlib import import_module

from freestand.errors import FreestandError

__version__ = "0.1.0"

#: Public name -> module that defines it.
_PUBLIC = {
    "load_model": "freestand.io.model_file",
    "example_path": "freestand.io.examples",
    "load_record": "freestand.io.records",
    "load_suite": "freestand.io.suites",
    "GroundMotion": "freestand.core.motion.ground_motion",
    "SupportMotion": "freestand.core.dynamics.timehistory",
    "TimeHistoryResult": "freestand.core.dynamics.timehistory",
    "Block": "freestand.core.model",
    "Stack": "freestand.core.model",
    "Friction": "freestand.core.model",
    "Sliding": "freestand.core.model",
    "Excitation": "freestand.core.model",
    "screen": "freestand.api",
    "simulate": "freestand.api",
    "support_motion": "freestand.api",
    "support_motion3": "freestand.api",
    "SupportMotion3": "freestand.core.dynamics.body_history",
    "overturning": "freestand.api",
    "frequency": "freestand.api",
    "mode_map": "freestand.api",
    "sample": "freestand.api",
    "fragility": "freestand.api",
    "fragility_from_store": "freestand.api",
    "write_report": "freestand.api",
    "response_spectrum": "freestand.api",
    "generate_suite": "freestand.api",
    "floor_motion": "freestand.api",
    "intensity_measure": "freestand.api",
    "IntensityMeasure": "freestand.core.sweeps.fragility.intensity",
    "ScreeningResult": "freestand.api",
    "SimulationResult": "freestand.api",
    "BodyOverturningResult": "freestand.api",
    "BodySimulationResult": "freestand.api",
    "OverturningResult": "freestand.api",
    "FrequencyResult": "freestand.api",
    "ModeMapResult": "freestand.api",
    "SampleResult": "freestand.api",
    "FragilityResult": "freestand.api",
    "ReportResult": "freestand.api",
    "RecordSpectra": "freestand.api",
    "GeneratedSuite": "freestand.api",
    "FloorMotion": "freestand.api",
    "load_station": "freestand.io.pairing",
    "RockingBlock": "freestand.core.rocking.properties",
    "overturning_limits": "freestand.core.rocking.overturning",
}

__all__ = ["FreestandError", "__version__", *_PUBLIC]


def __getattr__(name: str):
    module = _PUBLIC.get(name)
    if module is None:
        raise AttributeError(f"module 'freestand' has no attribute {name!r}")
    value = getattr(import_module(module), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(__all__)
