"""From the rows of a campaign to one fragility function per outcome.

Only simulations with status ``"completed"`` or ``"capped"`` enter the
counts; failed and invalid ones are counted and reported apart.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

import numpy as np

from freestand.core.sweeps.fragility.fit import Fragility, fit_cloud, fit_fragility
from freestand.core.sweeps.fragility.outcomes import Outcome

#: Statuses whose outcomes count.
COUNTED = ("completed", "capped")


@dataclass(frozen=True)
class OutcomeFragility:
    """The fragility of one outcome.

    Attributes
    ----------
    outcome : Outcome
    fragility : Fragility
    """

    outcome: Outcome
    fragility: Fragility


@dataclass(frozen=True)
class FragilityResult:
    """Fragility functions of every outcome of a campaign.

    Attributes
    ----------
    simulations : int
        Rows (simulations run).
    statuses : dict of str to int
        Simulations per status.
    failed : int
        Simulations left out of the fits (failed or invalid).
    outcomes : tuple of OutcomeFragility
    cloud : bool
    unit : str
        IM unit.
    """

    simulations: int
    statuses: dict
    failed: int
    outcomes: tuple[OutcomeFragility, ...]
    cloud: bool
    unit: str


def outcome_column(rows: dict, outcome: Outcome) -> np.ndarray:
    """Whether ``outcome`` occurred in each row: its stored column, else judged from the values."""
    key = f"outcome:{outcome.key}"
    if key in rows:
        return np.asarray(rows[key], dtype=bool)
    return outcome.occurred(rows)


def analyse(
    rows: dict,
    outcomes,
    levels,
    *,
    unit: str = "",
    bootstrap: int = 1000,
    confidence: float = 0.95,
    seed: int = 0,
) -> FragilityResult:
    """Count and fit every outcome.

    Parameters
    ----------
    rows : dict of str to numpy.ndarray
        The columns of :func:`freestand.core.sweeps.fragility.campaign.run_tasks`
        (from one run or from a store).
    outcomes : sequence of Outcome
    levels : array_like
        IM levels of the stripes [IM unit]; empty for a cloud (each
        simulation at the IM of its record).
    unit : str, optional
        IM unit, for messages.
    bootstrap, confidence, seed
        As for :func:`freestand.core.sweeps.fragility.fit.fit_fragility`.

    Returns
    -------
    FragilityResult
    """
    levels = np.asarray(levels, dtype=float)
    status = np.asarray(rows["status"], dtype=object)
    counted = np.isin(status, COUNTED)
    statuses = dict(Counter(str(s) for s in status))
    results = []
    for number, outcome in enumerate(outcomes):
        occurred = outcome_column(rows, outcome) & counted
        # each outcome its own bootstrap stream, independent of the others
        outcome_seed = int(np.random.SeedSequence(seed, spawn_key=(number,)).generate_state(1)[0])
        if levels.size == 0:
            im = np.asarray(rows["im"], dtype=float)[counted]
            fragility = fit_cloud(
                im, occurred[counted], bootstrap=bootstrap, confidence=confidence,
                seed=outcome_seed, unit=unit,
            )  # fmt: skip
        else:
            index = np.asarray(rows["level"], dtype=np.int64)
            totals = np.bincount(index[counted], minlength=levels.size)[: levels.size]
            counts = np.bincount(index[occurred], minlength=levels.size)[: levels.size]
            fragility = fit_fragility(
                levels, counts, totals, bootstrap=bootstrap, confidence=confidence,
                seed=outcome_seed, unit=unit,
            )  # fmt: skip
        results.append(OutcomeFragility(outcome, fragility))
    return FragilityResult(
        simulations=int(status.size),
        statuses=statuses,
        failed=int(status.size - counted.sum()),
        outcomes=tuple(results),
        cloud=levels.size == 0,
        unit=unit,
    )
