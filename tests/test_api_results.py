"""Every public analysis: its ``to_dict()`` is the command's ``--json`` (the real command run on
the same inputs), its ``to_frame()`` has the documented columns, its ``plot()`` the documented
content."""

from __future__ import annotations

import json

import numpy as np
import pytest
from matplotlib.figure import Figure

import freestand as fs
from freestand.api.fragility import FIT_COLUMNS, STRIPE_COLUMNS
from freestand.api.frequency import FREQUENCY_COLUMNS
from freestand.api.maps import SAMPLE_COLUMNS
from freestand.api.overturning import PULSE_COLUMNS, RECTANGULAR_COLUMNS
from freestand.api.screening import SCREENING_COLUMNS
from tests.conftest import CRANE, ROOT, run_freestand

RECORD = ROOT / "examples" / "records" / "synthetic_H.AT2"


def command_json(*args: str, cwd=None):
    """The document the real command prints with --json."""
    result = run_freestand(*args, "--json", cwd=cwd)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def same_document(result) -> dict:
    """``to_dict()`` as the JSON the command prints, read back (the normalisation)."""
    text = result.to_json()
    assert text == json.dumps(result.to_dict(), indent=2)
    return json.loads(text)


@pytest.fixture(scope="module")
def crane():
    return fs.load_model(CRANE)


def test_screen(crane):
    result = fs.screen(crane, configurations=["y-z"], vertical_senses="both")
    assert same_document(result) == command_json(
        "screen", str(CRANE), "-c", "y-z", "--vertical-senses", "both"
    )
    table = result.to_frame()
    assert tuple(table.columns) == SCREENING_COLUMNS
    assert len(table) == sum(len(case.blocks) for case in result)
    assert table.attrs["model"] == crane.name
    assert [case.excitation for case in result][:2] == ["rigid (a_v down)"] * 2


def test_simulate(crane):
    motion = fs.load_record(RECORD).scaled_to_peak(8.0)
    result = fs.simulate(crane, motion, 2.0, configuration="x-z cart right")
    document = command_json(
        "simulate", str(CRANE), "-c", "x-z cart right", "--record", str(RECORD), "--peak", "8",
        "--duration", "2",
    )  # fmt: skip
    assert same_document(result) == document
    history = result.to_frame()
    assert history.columns[:3].tolist() == [
        "time [s]", "support_horizontal [m/s^2]", "support_vertical [m/s^2]"
    ]  # fmt: skip
    assert {"cart.rotation [rad]", "bridge.slide [m]", "cart.normal_left [N]"} <= set(history)
    assert len(history) == result.core.time.size
    peaks = result.to_frame("peaks")
    assert peaks["block"].tolist() == ["bridge", "cart"]
    np.testing.assert_array_equal(peaks["max_rotation [rad]"], result.max_rotation)
    figure = result.plot()
    panels = [ax for ax in figure.axes if ax.get_lines()]
    assert len(panels) == 5  # support, slide, rotation, one panel per interface
    assert panels[-1].get_xlabel() == "time t [s]"


def test_overturning(crane):
    result = fs.overturning(crane, configuration="x-z cart right", block="cart",
                            frequencies=[0.5, 2.0])  # fmt: skip
    document = command_json(
        "overturn", str(CRANE), "-c", "x-z cart right", "-b", "cart", "--frequencies", "0.5,2"
    )
    assert same_document(result) == document
    table = result.to_frame()
    assert tuple(table.columns) == PULSE_COLUMNS
    assert table["frequency [Hz]"].tolist() == [0.5, 2.0]
    assert tuple(result.to_frame("rectangular").columns) == RECTANGULAR_COLUMNS
    figure = Figure()
    ax = figure.add_subplot()
    assert result.plot(ax) is figure
    assert ax.get_xlabel() == "pulse frequency f [Hz]"
    labels = [line.get_label() for line in ax.get_lines()]
    assert sum(label.startswith(("Housner", "Makris", "exact")) for label in labels) == 3
    spectrum = result.plot(figure="spectrum")
    assert crane.spectrum("horizontal").label in [
        line.get_label() for line in spectrum.axes[0].get_lines()
    ]


def test_frequency(crane):
    result = fs.frequency(crane, positions=[1.33, 4.9])
    assert same_document(result) == command_json("frequency", str(CRANE), "--positions", "1.33,4.9")
    table = result.to_frame()
    assert tuple(table.columns) == FREQUENCY_COLUMNS
    assert table["verdict"].tolist() == [str(v) for v in result.check.verdict]
    figure = result.plot()
    ax = figure.axes[0]
    assert ax.get_xlabel() == "cart position d from the left support [m]"
    assert {"exact (continuous beam)"} <= {line.get_label() for line in ax.get_lines()}


def test_mode_map(crane):
    result = fs.mode_map(crane, "horizontal=0:12", "friction.static=0.1:0.5", nodes=20,
                         configurations=["y-z", "x-z cart right"], sense="+")  # fmt: skip
    document = command_json(
        "map", str(CRANE), "-c", "y-z", "-c", "x-z cart right", "--x", "horizontal=0:12",
        "--y", "friction.static=0.1:0.5", "--nodes", "20", "--sense", "+",
    )  # fmt: skip
    assert same_document(result) == document
    table = result.to_frame()
    assert tuple(table.columns) == result.columns()
    assert table.columns[2:4].tolist() == ["horizontal [m/s^2]", "friction.static [-]"]
    assert len(table) == 2 * 20 * 20
    shares = table[table["configuration"] == "y-z"]["region"].value_counts(normalize=True)
    assert shares.to_dict() == pytest.approx(result.maps[0].fractions())
    figure = result.plot()
    assert len([ax for ax in figure.axes if ax.get_images()]) == 2


def test_sample(crane):
    result = fs.sample(crane, ["friction.static=uniform(0.25,0.45)"], n=2000, seed=3,
                       configurations="y-z", excitations="rigid")  # fmt: skip
    document = command_json(
        "sample", str(CRANE), "-c", "y-z", "-e", "rigid", "--n", "2000", "--seed", "3",
        "--vary", "friction.static=uniform(0.25,0.45)",
    )  # fmt: skip
    assert same_document(result) == document
    table = result.to_frame()
    assert tuple(table.columns) == SAMPLE_COLUMNS
    slides = table[(table["block"] == "bridge") & (table["motion"] == "slide")]
    assert slides["probability [-]"].between(0.4, 0.7).all()
    samples = result.samples_frame()
    assert len(samples) == 2000 * len(result.cases)
    assert {"friction.static", "bridge.motion", "status"} <= set(samples)


@pytest.fixture(scope="module")
def block_suite(tmp_path_factory):
    """A slender block and a suite of two half-sine pulses."""
    from freestand.core.motion.ground_motion import half_sine_pulse
    from freestand.io.records import write_at2
    from freestand.io.suites import suite_text

    folder = tmp_path_factory.mktemp("fragility")
    (folder / "block.toml").write_text(
        'name = "Block"\n[[excitation]]\nname = "none"\nhorizontal = 0.0\n'
        '[[configuration]]\nname = "block"\n[[configuration.block]]\nname = "block"\n'
        "mass = 500\ninertia = 266.6666666666667\ncentre = [0.0, 1.2]\n"
        "base = { left = -0.4, right = 0.4, level = 0.0 }\n"
        'friction = { static = 2.0, kinetic = 2.0 }\nsliding = "none"\n'
    )
    records = []
    for number, f in enumerate((1.5, 3.5)):
        motion = half_sine_pulse(1.0, frequency=f, dt=1.0 / (200.0 * f))
        write_at2(folder / f"p{number}.AT2", motion, component="horizontal", title="pulse",
                  description=f"half-sine {f} Hz")  # fmt: skip
        records.append({"horizontal": f"p{number}.AT2", "name": f"p{number}"})
    (folder / "suite.toml").write_text(suite_text("pulses", records))
    return folder


def test_fragility(block_suite):
    model = fs.load_model(block_suite / "block.toml")
    store = block_suite / "store"
    result = fs.fragility(model, block_suite / "suite.toml", "pga", "3:12:4", ["overturn:block", "uplift:block"],
                          bootstrap=20, workers=1, store=store)  # fmt: skip
    document = command_json(
        "fragility", str(block_suite / "block.toml"), "--suite", str(block_suite / "suite.toml"),
        "--levels", "3:12:4", "--outcome", "overturn:block", "--outcome", "uplift:block",
        "--bootstrap", "20", "--store", str(store),
    )  # fmt: skip
    assert same_document(result) == document
    again = fs.fragility_from_store(store, bootstrap=20)
    assert again.to_dict()["outcomes"] == document["outcomes"]
    stripes = result.to_frame()
    assert tuple(stripes.columns) == tuple(c.format(unit="m/s^2") for c in STRIPE_COLUMNS)
    assert len(stripes) == 2 * 4
    assert stripes["total"].tolist() == [2] * 8
    fits = result.to_frame("fits")
    assert tuple(fits.columns) == tuple(c.format(unit="m/s^2") for c in FIT_COLUMNS)
    assert fits["outcome"].tolist() == ["block overturns", "block uplifts"]


def test_report(tmp_path, crane):
    result = fs.write_report(crane, tmp_path / "api.html", date="2024-01-01")
    document = command_json("report", str(CRANE), "-o", str(tmp_path / "cli.html"),
                            "--date", "2024-01-01")  # fmt: skip
    produced = same_document(result)
    assert produced.pop("files") == [str(tmp_path / "api.html")]
    assert document.pop("files") == [str(tmp_path / "cli.html")]
    assert produced == document
    assert (tmp_path / "api.html").read_bytes() == (tmp_path / "cli.html").read_bytes()
    assert tuple(result.to_frame().columns) == SCREENING_COLUMNS
