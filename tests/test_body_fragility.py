"""Fragility campaigns of 3-D bodies: the command, the store, incidence angles, refusals."""

from __future__ import annotations

import json
import math
from types import SimpleNamespace

import numpy as np
import pytest

import freestand as fs
from freestand.core.body import Body, BodyConfiguration, Box, Cylinder
from freestand.core.model import Friction
from freestand.core.motion.ground_motion import GroundMotion
from freestand.core.sweeps.fragility.campaign import Campaign, columns
from freestand.core.sweeps.fragility.intensity import IntensityMeasure
from freestand.core.sweeps.fragility.outcomes import body_values
from freestand.errors import FreestandError
from freestand.io.records import write_at2
from freestand.io.store import CampaignStore
from freestand.io.suites import suite_text
from tests.conftest import ROOT, run_freestand
from tests.test_cli_fragility import MODEL as PLANAR

BODIES = ROOT / "examples" / "bodies.toml"

#: A cabinet-like box: 0.8 m along x, 0.5 m along y, G at 1.1 m; tan(alpha) 0.364 (x), 0.227 (y).
BOX = BodyConfiguration("box", (Body("box", Box((0.8, 0.5, 2.2)), 450.0, Friction(0.8, 0.75)),))
#: A slender cylinder: R 0.5 m, G at 1.2 m (alpha = atan(0.5/1.2) in every direction).
CYLINDER = BodyConfiguration(
    "cylinder", (Body("cylinder", Cylinder(0.5, 2.4), 900.0, Friction(0.8, 0.75)),)
)


def noise_records(count, *, low=0.8, high=2.5, seed=3, dt=0.01, duration=5.0, y=False):
    """Short records: four sines of random frequency and phase under a rise-and-decay envelope."""
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, duration, dt)
    envelope = np.minimum(1.0, t / 0.5) * np.exp(-np.maximum(0.0, t - 2.0))

    def component():
        frequency, phase = rng.uniform(low, high, 4), rng.uniform(0.0, 2 * np.pi, 4)
        return envelope * np.sin(2 * np.pi * frequency[:, None] * t + phase[:, None]).sum(0)

    return [
        GroundMotion(dt, component(), name=f"n{k}", horizontal_y=component() if y else None)
        for k in range(count)
    ]


@pytest.fixture()
def files(tmp_path):
    """bodies.toml and a suite of two three-component records and one with x alone."""
    (tmp_path / "bodies.toml").write_text(BODIES.read_text())
    motions = noise_records(3, duration=3.0, y=True, seed=5)
    entries = []
    for k, motion in enumerate(motions):
        write_at2(tmp_path / f"r{k}_x.AT2", motion, component="horizontal")
        entry = {"name": f"r{k}", "x": f"r{k}_x.AT2"}
        if k < 2:
            along_y = GroundMotion(motion.dt, motion.horizontal_y)
            write_at2(tmp_path / f"r{k}_y.AT2", along_y, component="horizontal")
            vertical = GroundMotion(motion.dt, 0.5 * motion.horizontal_y[::-1])
            write_at2(tmp_path / f"r{k}_up.AT2", vertical, component="horizontal")
            entry.update(y=f"r{k}_y.AT2", vertical=f"r{k}_up.AT2")
        entries.append(entry)
    (tmp_path / "suite.toml").write_text(suite_text("three", entries))
    return tmp_path


CABINET_ARGS = (
    "fragility", "bodies.toml", "-c", "cabinet", "--suite", "suite.toml", "--levels", "3:9:3",
    "--outcome", "rotation:cabinet>0.5alpha", "--outcome", "twist:cabinet>2",
    "--outcome", "slide:cabinet>5mm", "--outcome", "uplift:cabinet", "--bootstrap", "20",
    "--free-time", "2",
)  # fmt: skip


def test_the_command_runs_a_3d_campaign_and_resumes_its_store(files):
    # a stopped run: the first two chunks of one simulation each are stored
    stopped = files / "stopped"
    model = fs.load_model(files / "bodies.toml")

    def stop(done: int, total: int) -> None:
        if len(CampaignStore(stopped).chunks()) >= 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        fs.fragility(
            model, files / "suite.toml", None, "3:9:3", list(CABINET_ARGS[9:17:2]),
            configuration="cabinet", workers=1, store=stopped, chunk=1, progress=stop,
            free_time=2.0,
        )  # fmt: skip
    assert len(CampaignStore(stopped).chunks()) == 2
    resumed = run_freestand(*CABINET_ARGS, "--workers", "1", "--chunk", "1", "--store", "stopped",
                            "--json", cwd=files)  # fmt: skip
    assert resumed.returncode == 0, resumed.stderr
    document = json.loads(resumed.stdout)
    assert document["shape"] == "box" and document["angles"] == "uniform"
    assert document["im"] == {"kind": "pga-rotd50", "unit": "m/s^2", "components": "x, y"}
    assert document["simulations"] == 9 and document["failed"] == 0
    names = [item["name"] for item in document["outcomes"]]
    assert names == ["cabinet rotates > 0.5 alpha", "cabinet twists > 2 deg",
                     "cabinet slides > 0.005 m", "cabinet uplifts"]  # fmt: skip
    # the same campaign in one uninterrupted run (two workers, its own store): the same rows
    whole = fs.fragility(
        model, files / "suite.toml", None, "3:9:3", list(CABINET_ARGS[9:17:2]),
        configuration="cabinet", workers=2, store=files / "whole", chunk=1, bootstrap=20,
        free_time=2.0,
    )  # fmt: skip
    assert whole.to_dict()["outcomes"] == document["outcomes"]
    rows, again = CampaignStore(stopped).read(), CampaignStore(files / "whole").read()
    assert list(rows) == list(again)
    for name in rows:
        assert np.array_equal(rows[name], again[name]), name
    # the angle and the body's peaks are stored with every simulation
    assert np.all((rows["angle"] >= 0.0) & (rows["angle"] < 360.0))
    assert np.unique(rows["angle"]).size == 9
    for quantity in ("max_rotation", "max_slide", "max_twist", "alpha", "tilt_ratio"):
        assert np.all(np.isfinite(rows[f"cabinet.{quantity}"])), quantity
    # the figure, and a new outcome judged from the stored peaks
    other = run_freestand("fragility", "--from-store", "stopped", "--outcome",
                          "twist:cabinet>10deg", "--plot", "f.png", "--json", "--bootstrap", "0",
                          cwd=files)  # fmt: skip
    assert other.returncode == 0, other.stderr
    assert json.loads(other.stdout)["outcomes"][0]["name"] == "cabinet twists > 10 deg"
    assert (files / "f.png").stat().st_size > 1000


def test_a_fixed_angle_and_a_sweep(tmp_path):
    records = noise_records(2, duration=3.0)
    fixed = fs.fragility(BOX, records, "pga", "4,8", ["uplift:box"], angle=90.0, workers=1,
                         bootstrap=0, store=tmp_path / "fixed")  # fmt: skip
    rows = CampaignStore(tmp_path / "fixed").read()
    assert fixed.to_dict()["angles"] == [90.0] and np.all(rows["angle"] == 90.0)
    # a record along x turned to +y rocks the box about its long edge: alpha = atan(b_y / h)
    rocked = rows["box.uplift"] == 1.0
    assert rocked.any()
    assert rows["box.alpha"][rocked] == pytest.approx(math.atan(0.25 / 1.1), rel=1e-6)
    swept = fs.fragility(BOX, records, "pga", "4,8", ["uplift:box"], angles=4, workers=1,
                         bootstrap=0, store=tmp_path / "swept")  # fmt: skip
    rows = CampaignStore(tmp_path / "swept").read()
    assert swept.core.simulations == 2 * 2 * 4
    for record in (0, 1):
        for level in (0, 1):
            mine = (rows["record"] == record) & (rows["level"] == level)
            assert rows["angle"][mine].tolist() == [0.0, 90.0, 180.0, 270.0]


def test_uncertain_friction_and_mass_of_a_body(tmp_path):
    records = noise_records(1, duration=3.0)
    vary = ["box.friction.static=uniform(0.1,0.5)", "box.mass*=uniform(0.5,2)"]
    result = fs.fragility(BOX, records, "pga", "4,8", ["slide:box>0.01m"], vary=vary, samples=3,
                          angle=0.0, free_time=1.0, workers=1, bootstrap=0,
                          store=tmp_path / "s")  # fmt: skip
    rows = CampaignStore(tmp_path / "s").read()
    assert result.to_dict()["variations"] == [
        "box.friction.static = uniform(0.1, 0.5)", "box.mass *= uniform(0.5, 2)"
    ]  # fmt: skip
    static = rows["input:box.friction.static"]
    assert static.size == 6 and np.all((static > 0.1) & (static < 0.5))
    assert np.unique(static).size == 6 and set(rows["status"]) == {"completed"}
    # a rigid body's slide does not depend on its mass: the least friction slides farthest
    at_top = rows["level"] == 1
    assert np.argmax(rows["box.max_slide"][at_top]) == np.argmin(static[at_top])


def test_a_dask_scheduler_gives_the_rows_of_one_process(tmp_path):
    distributed = pytest.importorskip("distributed", reason="dask.distributed not installed")
    records = noise_records(2, duration=3.0, y=True)
    options = dict(levels="4,8", outcomes=["uplift:cylinder", "twist:cylinder>1"], bootstrap=0,
                   free_time=1.0)  # fmt: skip
    local = fs.fragility(CYLINDER, records, workers=1, store=tmp_path / "local", **options)
    with (
        distributed.LocalCluster(n_workers=1, processes=False, dashboard_address=None) as cluster,
        distributed.Client(cluster) as client,
    ):
        clustered = fs.fragility(CYLINDER, records, scheduler=client, chunk=3,
                                 store=tmp_path / "dask", **options)  # fmt: skip
    assert clustered.to_dict()["outcomes"] == local.to_dict()["outcomes"]
    rows, again = CampaignStore(tmp_path / "local").read(), CampaignStore(tmp_path / "dask").read()
    for name in rows:
        assert np.array_equal(rows[name], again[name]), name


def test_drawn_angles_are_uniform_reproducible_and_shared_by_both_polarities():
    records = noise_records(3, duration=1.0)
    campaign = Campaign(BOX, tuple(records), IntensityMeasure("pga"), [1.0, 2.0, 3.0],
                        polarities=(1, -1), seed=4)  # fmt: skip
    angles = np.array([campaign.angle(i) for i in range(campaign.size)])
    assert np.all((angles >= 0.0) & (angles < 360.0))
    assert np.array_equal(angles[0::2], angles[1::2])  # both polarities at one angle
    assert np.unique(angles[0::2]).size == campaign.size // 2
    again = Campaign(BOX, tuple(records), IntensityMeasure("pga"), [1.0, 2.0, 3.0],
                     polarities=(1, -1), seed=4)  # fmt: skip
    assert np.array_equal(angles, [again.angle(i) for i in range(again.size)])
    other = Campaign(BOX, tuple(records), IntensityMeasure("pga"), [1.0, 2.0, 3.0],
                     polarities=(1, -1), seed=5)  # fmt: skip
    assert not np.array_equal(angles, [other.angle(i) for i in range(other.size)])
    assert "angle" in columns(campaign) and "box.tilt_ratio" in columns(campaign)


@pytest.mark.parametrize(
    ("twist", "reach"),
    [(0.0, 0.4), (math.pi / 2, 0.25), (math.pi / 4, (0.4 + 0.25) / math.sqrt(2))],
)
def test_alpha_is_taken_where_the_twisted_box_tilts(twist, reach):
    # the box twisted about the vertical, then tilted by 0.1 rad towards +x: its pivot
    # reach along x is b_x, b_y or the diagonal's, and alpha = atan(reach / h)
    swing, turn = np.array([math.cos(0.05), 0.0, math.sin(0.05), 0.0]), 0.5 * twist
    w, y = swing[0], swing[2]
    quaternion = [w * math.cos(turn), y * math.sin(turn), y * math.cos(turn), w * math.sin(turn)]
    state = np.zeros((1, 13))
    state[0, 3:7] = quaternion
    history = SimpleNamespace(
        tilt=np.array([0.1]), state=state, twist=np.array([twist]), overturned=False,
        max_rotation=0.1, max_slide=0.0, max_twist=twist, uplift=True, free_flight=False,
    )  # fmt: skip
    values = body_values(history, BOX)
    assert values["box.alpha"] == pytest.approx(math.atan(reach / 1.1), rel=1e-12)
    assert values["box.tilt_ratio"] == pytest.approx(0.1 / math.atan(reach / 1.1), rel=1e-12)


def _median(configuration, angle, levels):
    """Median [m/s^2] and its 95 % interval of a tilt beyond 0.3 alpha, at a fixed angle."""
    name = configuration.name
    result = fs.fragility(configuration, noise_records(8), "pga", levels,
                          [f"rotation:{name}>0.3alpha"], angle=angle, workers=1, bootstrap=200,
                          free_time=2.0)  # fmt: skip
    fit = result.outcomes[0].fragility
    assert fit.fitted, fit.reason
    return fit.median, fit.median_interval


def test_a_cylinders_fragility_does_not_depend_on_the_angle_a_boxs_does():
    # a cylinder is the same in every direction: the medians lie in each other's intervals
    first, first_interval = _median(CYLINDER, 0.0, "2:10:5")
    turned, turned_interval = _median(CYLINDER, 60.0, "2:10:5")
    assert first_interval[0] <= turned <= first_interval[1]
    assert turned_interval[0] <= first <= turned_interval[1]
    # a box shaken across its narrow side (along y, angle 90) tilts sooner than along x:
    # the intervals of the two medians do not overlap
    along_x, x_interval = _median(BOX, 0.0, "1.5:7.5:7")
    along_y, y_interval = _median(BOX, 90.0, "1.5:7.5:7")
    assert y_interval[1] < x_interval[0] and along_y < along_x


def test_bad_input_names_the_option(files):
    planar = fs.Block.rectangle("cabinet", 0.6, 2.0, 1200.0, fs.Friction(0.8, 0.7))
    stack = fs.Stack("cabinet", (planar,))
    records = noise_records(1, duration=1.0)
    cases = [
        (stack, {"outcomes": ["twist:cabinet>5"]}, "--outcome", "outcome of 3-D bodies"),
        (BOX, {"outcomes": ["twist:box"]}, "--outcome", "give a threshold, e.g. twist:box>5deg"),
        (BOX, {"im": "pga-alpha"}, "--im", "depends on the direction"),
        (BOX, {"vary": ["box.centre.x+=normal(0,0.01)"]}, "--vary", "cannot be varied yet"),
        (BOX, {"vary": ["cart.mass*=uniform(0.9,1.1)"]}, "--vary", "no block 'cart'"),
        (BOX, {"angle": 10.0, "angles": 4}, "--angles", "not both"),
        (BOX, {"angles": 0}, "--angles", "give 1 to 360"),
        (stack, {"angles": 4}, "--angles", "is planar"),
    ]
    for model, options, option, words in cases:
        with pytest.raises(FreestandError) as error:
            fs.fragility(model, records, levels="1,2", workers=1, **options)
        assert error.value.source == option and words in str(error.value), options
    # the command: --angle on a planar model, without a traceback
    (files / "block.toml").write_text(PLANAR)
    result = run_freestand("fragility", "block.toml", "--suite", "suite.toml", "--levels", "1,2",
                           "--angle", "30", cwd=files)  # fmt: skip
    assert result.returncode == 2 and "--angle" in result.stderr
    assert "is planar" in result.stderr and "Traceback" not in result.stderr
