"""Running the chunks of a fragility campaign: in this process, on local cores, or on Dask.

The tasks of a :class:`~freestand.core.sweeps.fragility.campaign.Campaign` are cut
into fixed chunks (chunk c holds tasks ``c * size`` to ``(c + 1) * size - 1``).
A chunk is the unit of work and of storage: each finished chunk is handed to
the store (one Parquet part) as soon as it arrives, in whatever order the
workers finish. Since every task is a pure function of the campaign and its
index, the rows do not depend on the number of workers or on the scheduler.

* ``workers = 1``: the chunks run in this process, in order.
* ``workers > 1``: a local process pool (``concurrent.futures``), the campaign
  sent once to each worker.
* ``scheduler = "tcp://HOST:8786"`` (or a ``distributed.Client``): a Dask
  distributed cluster (``pip install freestand[cluster]``), the campaign
  scattered once to every worker.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor, as_completed

import numpy as np

from freestand.core.sweeps.fragility.campaign import Campaign, run_tasks
from freestand.errors import FreestandError
from freestand.io.store import CampaignStore


class CampaignInterrupted(RuntimeError):
    """The run stopped before every chunk was done (the finished ones are stored)."""


def default_chunk_size(campaign: Campaign) -> int:
    """Simulations per chunk: 200 for one planar block (about 0.2 s of work), else 8 (a stack
    or a 3-D body); at most size / 16."""
    preferred = 200 if not campaign.three_d and len(campaign.stack.blocks) == 1 else 8
    return max(1, min(preferred, math.ceil(campaign.size / 16)))


def default_workers() -> int:
    """All the cores this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not on Linux
        return max(1, os.cpu_count() or 1)


_CAMPAIGN: Campaign | None = None


def _initialise(campaign: Campaign) -> None:
    global _CAMPAIGN
    _CAMPAIGN = campaign


def _run_chunk(start: int, stop: int) -> dict[str, np.ndarray]:
    assert _CAMPAIGN is not None
    return run_tasks(_CAMPAIGN, start, stop)


def _merge(parts: dict[int, dict[str, np.ndarray]]) -> dict[str, np.ndarray]:
    if not parts:
        return {}
    ordered = [parts[c] for c in sorted(parts)]
    return {name: np.concatenate([p[name] for p in ordered]) for name in ordered[0]}


def _dask_client(scheduler):
    try:
        from distributed import Client
    except ImportError:
        raise FreestandError(
            "running on a cluster needs dask.distributed; install it with "
            "pip install 'freestand[cluster]'",
            source="--scheduler",
        ) from None
    if isinstance(scheduler, Client):
        return scheduler, False
    try:
        return Client(scheduler, timeout="20s"), True
    except (OSError, TimeoutError, ValueError) as error:
        raise FreestandError(
            f"cannot reach the Dask scheduler {scheduler!r} ({error}); start one with "
            "`dask scheduler` and workers with `dask worker ADDRESS`",
            source="--scheduler",
        ) from None
    except Exception as error:  # a server that is not Dask
        # whatever answers at the address is not a Dask scheduler: its bytes read as a
        # Dask message give absurd frame lengths (MemoryError) or undecodable data
        raise FreestandError(
            f"{scheduler!r} answers, but not as a Dask scheduler ({type(error).__name__}); "
            "give the address that `dask scheduler` prints, e.g. tcp://HOST:8786",
            source="--scheduler",
        ) from None


def run_campaign(
    campaign: Campaign,
    *,
    chunk_size: int | None = None,
    workers: int | None = None,
    scheduler=None,
    store: CampaignStore | None = None,
    progress: Callable[[int], None] | None = None,
    stop_after: int | None = None,
) -> dict[str, np.ndarray]:
    """Run every simulation of ``campaign`` not yet in ``store``.

    Parameters
    ----------
    campaign : Campaign
    chunk_size : int, optional
        Simulations per chunk (default :func:`default_chunk_size`); must stay
        the same over the runs of one store.
    workers : int, optional
        Local worker processes (default: every core); 1 runs in this process.
    scheduler : str or distributed.Client, optional
        A Dask scheduler address (``tcp://HOST:8786``) or client; replaces
        the local pool.
    store : CampaignStore, optional
        Where each finished chunk is written, and where finished chunks are
        skipped; opened beforehand (:meth:`CampaignStore.open`).
    progress : callable, optional
        Called with the number of simulations just finished (also for those
        found in the store, once at the start).
    stop_after : int, optional
        Stop with :class:`CampaignInterrupted` after this many chunks have been
        written in this run (to test resuming).

    Returns
    -------
    dict of str to numpy.ndarray
        Every row of the campaign in task order (read back from the store
        when there is one).
    """
    size = chunk_size or default_chunk_size(campaign)
    count = math.ceil(campaign.size / size)
    done = store.chunks() if store is not None else set()
    pending = [c for c in range(count) if c not in done]
    if progress is not None and done:
        progress(sum(min(size, campaign.size - c * size) for c in done if c < count))
    parts: dict[int, dict[str, np.ndarray]] = {}
    written = 0

    def finish(chunk: int, rows: dict[str, np.ndarray]) -> None:
        nonlocal written
        if store is not None:
            store.write(chunk, rows)
        else:
            parts[chunk] = rows
        written += 1
        if progress is not None:
            progress(int(rows["task"].size))
        if stop_after is not None and written >= stop_after and len(pending) > written:
            raise CampaignInterrupted(f"stopped after {written} chunk(s)")

    def bounds(chunk: int) -> tuple[int, int]:
        return chunk * size, min((chunk + 1) * size, campaign.size)

    if scheduler is not None:
        client, owned = _dask_client(scheduler)
        try:
            from distributed import as_completed as dask_completed

            shared = client.scatter(campaign, broadcast=True)
            futures = {client.submit(run_tasks, shared, *bounds(c), pure=False): c for c in pending}
            try:
                for future in dask_completed(list(futures)):
                    finish(futures[future], future.result())
            finally:
                client.cancel(list(futures))
        finally:
            if owned:
                client.close()
    elif (workers or default_workers()) <= 1 or len(pending) <= 1:
        for chunk in pending:
            finish(chunk, run_tasks(campaign, *bounds(chunk)))
    else:
        n = min(workers or default_workers(), len(pending))
        with ProcessPoolExecutor(n, initializer=_initialise, initargs=(campaign,)) as pool:
            futures = {pool.submit(_run_chunk, *bounds(c)): c for c in pending}
            try:
                for future in as_completed(futures):
                    finish(futures[future], future.result())
            except BaseException:
                for future in futures:
                    future.cancel()
                raise
    if store is not None:
        return store.read()
    return _merge(parts)


def run_fragility(
    campaign: Campaign,
    *,
    model_name: str,
    model_source: str,
    model_sha256: str,
    suite_name: str,
    suite_source: str,
    chunk_size: int | None = None,
    workers: int | None = None,
    scheduler=None,
    store=None,
    progress: Callable[[int], None] | None = None,
    bootstrap: int = 1000,
    confidence: float = 0.95,
    seed: int = 0,
):
    """Run a campaign (or what its store lacks) and fit every outcome.

    Parameters
    ----------
    campaign : Campaign
    model_name, model_source, model_sha256, suite_name, suite_source : str
        What the definition (and the store's fingerprint) records of the inputs.
    chunk_size, workers, scheduler, progress
        As for :func:`run_campaign`.
    store : str or pathlib.Path, optional
        A store folder: opened (created, or checked to hold this campaign)
        and resumed.
    bootstrap, confidence, seed
        As for :func:`freestand.core.sweeps.fragility.analysis.analyse`.

    Returns
    -------
    tuple
        (definition dict, FragilityResult).
    """
    from freestand.core.sweeps.fragility.analysis import analyse
    from freestand.io.fragility_results import campaign_definition

    size = chunk_size or default_chunk_size(campaign)
    definition = campaign_definition(
        campaign, model_name=model_name, model_source=model_source, model_sha256=model_sha256,
        suite_name=suite_name, suite_source=suite_source, chunk_size=size,
    )  # fmt: skip
    target = None
    if store is not None:
        target = CampaignStore(store)
        target.open(definition)
    rows = run_campaign(
        campaign, chunk_size=size, workers=workers, scheduler=scheduler, store=target,
        progress=progress,
    )  # fmt: skip
    result = analyse(
        rows, campaign.outcomes, campaign.levels, unit=campaign.measure.unit,
        bootstrap=bootstrap, confidence=confidence, seed=seed,
    )  # fmt: skip
    return definition, result
