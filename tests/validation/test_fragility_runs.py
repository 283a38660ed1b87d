"""Fragility validation (c) and (d): where and how the campaign runs changes nothing.

(c) The same campaign on a Dask LocalCluster (two worker processes), on a
local pool of two processes and in this process gives the same rows (every
simulation, bit for bit) and the same fit: every task is seeded by its own
indices, not by the worker that runs it.

(d) A campaign interrupted after some chunks (by an injected stop, and by
killing the real command) and then resumed from its store gives the same
rows and the same document as a run that was never interrupted.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import time

import numpy as np
import pytest

from freestand.core.model import Block, Friction, Sliding, Stack
from freestand.core.motion.ground_motion import half_sine_pulse
from freestand.core.sweeps.fragility.analysis import analyse
from freestand.core.sweeps.fragility.campaign import Campaign, run_tasks
from freestand.core.sweeps.fragility.intensity import IntensityMeasure
from freestand.core.sweeps.fragility.outcomes import Outcome
from freestand.io.campaign_runner import CampaignInterrupted, run_campaign
from freestand.io.parameters import parse_variation
from freestand.io.store import CampaignStore
from tests.conftest import freestand_command, run_freestand

BLOCK = Block(
    "block", 500.0, 500.0 * (0.4**2 + 1.2**2) / 3.0, (0.0, 1.2), -0.4, 0.4, 0.0,
    Friction(2.0, 2.0), Sliding.NONE,
)  # fmt: skip
STACK = Stack("block", (BLOCK,))


def _campaign() -> Campaign:
    motions = tuple(
        half_sine_pulse(1.0, frequency=f, dt=1.0 / (200.0 * f), name=f"pulse {f:g} Hz")
        for f in (1.5, 2.5, 3.5)
    )
    return Campaign(
        STACK,
        motions,
        IntensityMeasure("pga"),
        np.array([3.0, 6.0, 9.0]),
        variations=(
            parse_variation("block.mass*=uniform(0.8,1.2)"),
            parse_variation("block.centre.x+=uniform(-0.02,0.02)"),
        ),  # fmt: skip
        samples=3,
        polarities=(1, -1),
        seed=5,
        outcomes=(
            Outcome("overturn", "block"),
            Outcome("rotation", "block", 0.5, "alpha"),
            Outcome("uplift", "block"),
        ),  # fmt: skip
        free_time=3.0,
    )


def _same_rows(a: dict, b: dict) -> None:
    assert list(a) == list(b)
    for name in a:
        if a[name].dtype.kind == "f":
            np.testing.assert_array_equal(a[name], b[name])  # NaN == NaN here
        else:
            assert a[name].tolist() == b[name].tolist(), name


def _fits(rows, campaign):
    result = analyse(rows, campaign.outcomes, campaign.levels, bootstrap=200, seed=1)
    return [(o.fragility.counts.tolist(), o.fragility.median, o.fragility.beta, o.fragility.hclpf)
            for o in result.outcomes]  # fmt: skip


@pytest.fixture(scope="module")
def reference():
    campaign = _campaign()
    return campaign, run_tasks(campaign, 0, campaign.size)


def test_local_pool_gives_the_rows_of_one_process(reference, tmp_path):
    campaign, rows = reference
    store = CampaignStore(tmp_path / "pool")
    store.open({"fingerprint": "test"})
    pooled = run_campaign(campaign, chunk_size=7, workers=2, store=store)
    _same_rows(rows, pooled)
    assert set(rows["status"]) <= {"completed", "capped"}


def test_dask_local_cluster_gives_the_same_store_and_fit(reference, tmp_path):
    distributed = pytest.importorskip(
        "distributed", reason="dask.distributed not installed (pip install freestand[cluster])"
    )
    campaign, rows = reference
    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        store = CampaignStore(tmp_path / "dask")
        store.open({"fingerprint": "test"})
        clustered = run_campaign(campaign, chunk_size=7, scheduler=client, store=store)
    local = CampaignStore(tmp_path / "local")
    local.open({"fingerprint": "test"})
    run_campaign(campaign, chunk_size=7, workers=1, store=local)
    assert store.chunks() == local.chunks()
    _same_rows(rows, clustered)
    _same_rows(local.read(), store.read())
    assert _fits(clustered, campaign) == _fits(rows, campaign)


def test_interrupted_campaign_resumes_to_the_same_result(reference, tmp_path):
    campaign, rows = reference
    store = CampaignStore(tmp_path / "resumed")
    store.open({"fingerprint": "test"})
    with pytest.raises(CampaignInterrupted):
        run_campaign(campaign, chunk_size=5, workers=1, store=store, stop_after=4)
    assert len(store.chunks()) == 4
    finished = []
    resumed = run_campaign(campaign, chunk_size=5, workers=1, store=store, progress=finished.append)
    # the 4 stored chunks are reported at once and not run again
    assert finished[0] == 20 and sum(finished) == campaign.size
    _same_rows(rows, resumed)
    assert _fits(resumed, campaign) == _fits(rows, campaign)


MODEL = """
name = "Block"
[[excitation]]
name = "none"
horizontal = 0.0
[[configuration]]
name = "block"
[[configuration.block]]
name = "block"
mass = 500
inertia = 266.6666666666667
centre = [0.0, 1.2]
base = { left = -0.4, right = 0.4, level = 0.0 }
friction = { static = 2.0, kinetic = 2.0 }
sliding = "none"
"""


def _files(folder):
    from freestand.io.records import write_at2
    from freestand.io.suites import suite_text

    (folder / "block.toml").write_text(MODEL)
    records = []
    for number, f in enumerate((1.5, 2.0, 2.5, 3.0, 3.5, 4.0)):
        motion = half_sine_pulse(1.0, frequency=f, dt=1.0 / (200.0 * f))
        write_at2(folder / f"p{number}.AT2", motion, component="horizontal", title="pulse",
                  description=f"half-sine {f} Hz")  # fmt: skip
        records.append({"horizontal": f"p{number}.AT2", "name": f"p{number}"})
    (folder / "suite.toml").write_text(suite_text("pulses", records))


def test_killed_command_resumes_to_the_same_document(tmp_path):
    _files(tmp_path)
    args = ["fragility", "block.toml", "--suite", "suite.toml", "--levels", "3:12:5",
            "--both-polarities", "--vary", "block.mass*=uniform(0.9,1.1)", "--samples", "2",
            "--workers", "1", "--chunk", "4", "--bootstrap", "100", "--json"]  # fmt: skip
    whole = run_freestand(*args, "--store", "whole", cwd=tmp_path)
    assert whole.returncode == 0, whole.stderr
    process = subprocess.Popen(
        [*freestand_command(), *args, "--store", "killed"], cwd=tmp_path,
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True,
    )  # fmt: skip
    store = CampaignStore(tmp_path / "killed")
    deadline = time.monotonic() + 120
    while len(store.chunks()) < 5 and process.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    os.killpg(process.pid, signal.SIGKILL)
    process.wait()
    parts = len(store.chunks())
    assert 0 < parts < 30  # stopped part-way (30 chunks in all)
    resumed = run_freestand(*args, "--store", "killed", cwd=tmp_path)
    assert resumed.returncode == 0, resumed.stderr
    first, second = json.loads(whole.stdout), json.loads(resumed.stdout)
    first.pop("store"), second.pop("store")
    assert first == second
    assert first["simulations"] == 120
    _same_rows(CampaignStore(tmp_path / "whole").read(), store.read())
