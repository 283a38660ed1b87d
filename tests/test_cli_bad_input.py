"""Bad input to the real ``freestand`` command: a message, never a traceback, no file left.

Every case runs the installed console script in a fresh folder and checks the
exit status (2 for bad input, 1 for a failed computation), that stderr names
the option or file and the offending value (and, for model files, the fix),
that no "Traceback" appears anywhere, and that no file is left behind.
"""

from __future__ import annotations

import os
import re
import stat
import sys
from pathlib import Path

import pytest

from tests.conftest import CRANE, run_freestand

ROOT = Path(__file__).resolve().parents[1]
RECORD = ROOT / "examples" / "records" / "synthetic_H.AT2"
CRANE_TEXT = CRANE.read_text()

#: Edits of the crane's model file: name -> (old text, new text).
BAD_MODELS = {
    "nan_friction.toml": (
        'friction = { static = 0.25, kinetic = 0.20 }\nsliding = "free"',
        'friction = { static = nan, kinetic = 0.20 }\nsliding = "free"',
    ),
    "inf_kinetic.toml": (
        'friction = { static = 0.25, kinetic = 0.20 }\nsliding = "free"',
        'friction = { static = 0.25, kinetic = inf }\nsliding = "free"',
    ),
    "raised_bottom.toml": ('level = 0.0, names = ["G", "H"]', 'level = 0.5, names = ["G", "H"]'),
    "huge_mass.toml": ("mass = 16600                    # kg\n", "mass = 1e300\n"),
    "tiny_mass.toml": ("mass = 16600                    # kg\n", "mass = 1e-300\n"),
    "huge_inertia.toml": ("inertia = 49400", "inertia = 1e300"),
    "huge_centre.toml": ("centre = [0.0, 0.98]", "centre = [0.0, 1e200]"),
    "huge_horizontal.toml": ('horizontal = "2.70 m/s^2"', "horizontal = 1e300"),
    "huge_vertical.toml": ('vertical = "2.35 m/s^2"', "vertical = -1e300"),
    "bad_senses.toml": (
        'vertical = "2.35 m/s^2"',
        'vertical = "2.35 m/s^2"\nvertical_senses = "sideways"',
    ),
    "not_toml.toml": ('name = "Bridge crane"', 'name = "Bridge crane'),
}


@pytest.fixture(scope="module")
def inputs(tmp_path_factory) -> Path:
    """Bad model files and records, in a folder of their own."""
    folder = tmp_path_factory.mktemp("inputs")
    for name, (old, new) in BAD_MODELS.items():
        assert old in CRANE_TEXT, name
        (folder / name).write_text(CRANE_TEXT.replace(old, new, 1))
    outside = CRANE_TEXT.replace("centre = [0.57, 4.03]", "centre = [2.5, 4.03]", 1)
    (folder / "centre_outside.toml").write_text(outside)
    at2 = RECORD.read_text()
    (folder / "huge.AT2").write_text(at2.replace("E-03", "E+150", 50))
    (folder / "nan.AT2").write_text(at2.replace("2.1318711E-03", "nan", 1))
    (folder / "zeros.txt").write_text("0\n" * 50)
    (folder / "a_file").write_text("not a folder")
    (folder / "a_folder.csv").mkdir()
    (folder / "a_folder.gif").mkdir()
    (folder / "a_folder.html").mkdir()
    (folder / "a_folder.png").mkdir()
    return folder


def _case(*args, code=2, words=(), id=None):
    return pytest.param(args, code, words, id=id)


SIMULATE = ("simulate", "{crane}", "-c", "y-z", "--record", "{record}")

CASES = [
    # 1. usage mistakes: typer's short usage message, exit 2
    _case(code=2, words=("Usage: freestand",), id="no-arguments"),
    _case("bogus", words=("No such command", "bogus"), id="unknown-command"),
    _case("screen", words=("Missing argument",), id="missing-model"),
    _case("screen", "{crane}", "--bogus", words=("No such option", "--bogus"), id="unknown-opt"),
    _case("screen", "{crane}", "--json", "true", words=("true",), id="flag-with-value"),
    _case("map", "{crane}", "--n", "abc", words=("--n", "abc"), id="map-n-not-a-number"),
    _case(
        "overturn",
        "{crane}",
        "--restitution",
        "abc",
        words=("--restitution", "abc"),
        id="restitution-not-a-number",
    ),
    _case(*SIMULATE, "--dt", "abc", words=("--dt", "abc"), id="dt-not-a-number"),
    # 2. errors inside freestand: messages
    _case(
        "overturn",
        "{inputs}/centre_outside.toml",
        "-c",
        "x-z cart right",
        "-b",
        "cart",
        words=("--block", "cart", "x = 2.5", "cannot stand"),
        id="overturn-centre-outside-base",
    ),
    _case(
        "overturn",
        "{crane}",
        "-c",
        "x-z cart right",
        "-b",
        "cart",
        "--frequencies",
        "nan",
        words=("--frequencies", "nan", "not finite"),
        id="frequencies-nan",
    ),
    _case(
        "frequency",
        "{crane}",
        "--positions",
        "-1",
        words=("--positions", "-1 m", "outside the span"),
        id="position-outside-span",
    ),
    _case(*SIMULATE, "--scale", "nan", words=("--scale", "nan", "finite"), id="scale-nan"),
    _case(*SIMULATE, "--scale", "inf", words=("--scale", "inf", "finite"), id="scale-inf"),
    _case(*SIMULATE, "--duration", "0", words=("--duration", "0", "positive"), id="duration-0"),
    _case(*SIMULATE, "--duration", "-1", words=("--duration", "-1", "positive"), id="duration-1"),
    _case(
        *SIMULATE,
        "--step",
        "1e-7",
        words=("--step", "1e-07", "integration steps", "larger --step"),
        id="step-too-small",
    ),
    _case(
        *SIMULATE,
        "--plot",
        "{inputs}/a_file",
        words=("--plot", "a_file", "is a file"),
        id="plot-onto-a-file",
    ),
    _case(
        *SIMULATE,
        "--plot",
        "{inputs}/a_file/figures",
        words=("--plot", "a_file", "not a folder"),
        id="plot-under-a-file",
    ),
    _case(
        *SIMULATE,
        "--animate",
        "out.mp4",
        words=("--animate", "out.mp4", ".gif"),
        id="animate-not-gif",
    ),
    _case(
        *SIMULATE,
        "--plot",
        "figures",
        "--animate",
        "{inputs}/a_folder.gif",
        words=("--animate", "a_folder.gif", "is a folder"),
        id="animate-onto-a-folder",
    ),
    _case(
        "map",
        "{crane}",
        "--n",
        "20",
        "--plot",
        "out.txt",
        words=("--plot", "out.txt"),
        id="map-plot-bad-extension",
    ),
    _case(
        "map",
        "{crane}",
        "--n",
        "20",
        "--csv",
        "{inputs}/a_folder.csv",
        words=("--csv", "a_folder.csv", "is a folder"),
        id="map-csv-onto-a-folder",
    ),
    _case(
        "map",
        "{crane}",
        "--n",
        "20",
        "--csv",
        "/proc/freestand/map.csv",
        words=("--csv", "/proc", "cannot write"),
        id="map-csv-unwritable",
    ),
    _case(
        "sample",
        "{crane}",
        "--n",
        "100",
        "--samples",
        "{inputs}/a_file/s.csv",
        words=("--samples", "a_file", "not a folder"),
        id="samples-under-a-file",
    ),
    _case(
        "sample",
        "{crane}",
        "--n",
        "100",
        "--samples",
        "s.txt",
        words=("--samples", "s.txt", ".csv or .parquet"),
        id="samples-bad-extension",
    ),
    _case(
        "report",
        "{crane}",
        "-o",
        "report.txt",
        words=("--output", "report.txt", ".html"),
        id="report-bad-extension",
    ),
    _case(
        "report",
        "{crane}",
        "-o",
        "{inputs}/a_folder.html",
        words=("--output", "a_folder.html", "is a folder"),
        id="report-onto-a-folder",
    ),
    _case(
        "sample",
        "{crane}",
        "--n",
        "100000000000",
        words=("--n", "100000000000", "out of range"),
        id="sample-n-huge",
    ),
    _case(
        "map", "{crane}", "--n", "100000", words=("--nodes", "100000", "2 to 5000"), id="map-n-huge"
    ),
    # 4. inputs that were accepted silently
    _case(
        "screen",
        "{inputs}/nan_friction.toml",
        words=("nan_friction.toml", "friction", "static = nan", "between 0 and 100"),
        id="nan-friction",
    ),
    _case(
        "screen",
        "{inputs}/inf_kinetic.toml",
        words=("inf_kinetic.toml", "kinetic = inf"),
        id="inf-friction",
    ),
    _case(
        "screen",
        "{inputs}/raised_bottom.toml",
        words=("raised_bottom.toml", "bridge", "level = 0.5", "subtract"),
        id="bottom-level-not-0",
    ),
    _case(
        "screen",
        "{inputs}/huge_mass.toml",
        words=("huge_mass.toml", "mass", "1e+300", "plausible"),
        id="mass-1e300",
    ),
    _case(
        "screen",
        "{inputs}/tiny_mass.toml",
        words=("tiny_mass.toml", "mass", "1e-300", "smallest plausible"),
        id="mass-1e-300",
    ),
    _case(
        "screen",
        "{inputs}/huge_inertia.toml",
        words=("huge_inertia.toml", "inertia", "1e+300"),
        id="inertia-1e300",
    ),
    _case(
        "screen",
        "{inputs}/huge_centre.toml",
        words=("huge_centre.toml", "centre", "1e+200"),
        id="centre-1e200",
    ),
    _case(
        "screen",
        "{inputs}/huge_horizontal.toml",
        words=("huge_horizontal.toml", "horizontal", "1e+300"),
        id="excitation-1e300",
    ),
    _case(
        "screen",
        "{inputs}/huge_vertical.toml",
        words=("huge_vertical.toml", "vertical", "-1e+300"),
        id="vertical-1e300",
    ),
    _case(
        "screen",
        "{inputs}/bad_senses.toml",
        words=("bad_senses.toml", "vertical_senses", "sideways", "'both'"),
        id="vertical-senses-word",
    ),
    _case("screen", "{inputs}/not_toml.toml", words=("not_toml.toml", "TOML"), id="not-toml"),
    _case(
        "simulate",
        "{crane}",
        "-c",
        "y-z",
        "--record",
        "{inputs}/huge.AT2",
        words=("huge.AT2", "e+150 g", "plausible", "unit"),
        id="record-1e150",
    ),
    _case(
        "simulate",
        "{crane}",
        "-c",
        "y-z",
        "--record",
        "{inputs}/nan.AT2",
        words=("nan.AT2",),
        id="record-nan",
    ),
    _case(
        *SIMULATE,
        "--scale",
        "1e300",
        words=("scaled horizontal", "plausible"),
        id="record-scaled-to-1e300",
    ),
    _case(
        "overturn",
        "{crane}",
        "-c",
        "x-z cart right",
        "-b",
        "cart",
        "--spectrum",
        "vertical (stand-in)",
        words=("--spectrum", "vertical (stand-in)", "vertical spectrum", "horizontal one"),
        id="vertical-spectrum-to-overturning",
    ),
    _case(
        "frequency",
        "{crane}",
        "--spectrum",
        "horizontal (stand-in)",
        words=("--spectrum", "horizontal (stand-in)", "vertical one"),
        id="horizontal-spectrum-to-jump-check",
    ),
    # 7. quantities with units: a wrong unit is a message
    _case(*SIMULATE, "--peak", "0.3 kg", words=("--peak", "0.3 kg", "acceleration"), id="peak-kg"),
    _case(
        "overturn",
        "{crane}",
        "-c",
        "x-z cart right",
        "-b",
        "cart",
        "--amplitudes",
        "2 m",
        words=("--amplitudes", "2 m", "acceleration"),
        id="amplitudes-in-m",
    ),
    # 3. unwritable outputs (/proc takes no new file, even for root): refused before computing
    _case(
        "records", "spectrum", "{record}", "--plot", "/proc/spectra.png",
        words=("--plot", "cannot write", "/proc"), id="records-spectrum-plot-unwritable",
    ),
    _case(
        "records", "spectrum", "{record}", "--csv", "/proc/spectra.csv",
        words=("--csv", "cannot write", "/proc"), id="records-spectrum-csv-unwritable",
    ),
    _case(
        "records", "floor", "{record}", "--frequency", "2.5Hz", "--output", "/proc/floor.csv",
        words=("--output", "cannot write", "/proc"), id="records-floor-output-unwritable",
    ),
    _case(
        "records", "generate", "--target", "rg1.60:pga=0.3g", "--count", "1", "--duration", "2",
        "--output", "/proc/suite", words=("--output", "cannot write", "/proc"),
        id="records-generate-output-unwritable",
    ),
    _case(
        "records", "generate", "--target", "rg1.60:pga=0.3g", "--count", "1", "--duration", "2",
        "--output", "suite", "--plot", "/proc/suite.png", words=("--plot", "cannot write"),
        id="records-generate-plot-unwritable",
    ),
    _case(
        "fragility", "{crane}", "--suite", "suite.toml", "--levels", "1:2:2",
        "--plot", "/proc/fragility.png", words=("--plot", "cannot write"),
        id="fragility-plot-unwritable",
    ),
    _case(
        "fragility", "{crane}", "--suite", "suite.toml", "--levels", "1:2:2",
        "--plot", "{inputs}/a_folder.png", words=("--plot", "is a folder"),
        id="fragility-plot-is-a-folder",
    ),
    _case(
        "fragility", "{crane}", "--suite", "suite.toml", "--levels", "1:2:2", "--seed", "-1",
        words=("--seed", "-1"), id="fragility-negative-seed",
    ),
    _case(
        "fragility", "--from-store", "{inputs}", words=("--from-store", "not a campaign store"),
        id="fragility-from-store-not-a-store",
    ),
    _case(
        "records", "generate", "--target", "rg1.60:pga=0.3g", "--output", "{inputs}/a_file/suite",
        words=("--output", "a_file", "is a file"), id="records-generate-output-under-a-file",
    ),
    _case(*SIMULATE, "--method", "rk4", words=("--method", "'rk4'", "not a solver"),
          id="simulate-unknown-method"),
    _case(
        "records", "floor", "{inputs}", "--frequency", "2.5Hz",
        words=("is a directory", "not a record"), id="records-floor-folder-as-record",
    ),
    _case(
        "fragility", "{crane}", "--suite", "suite.toml", "--levels", "1:2:2", "--samples", "2",
        words=("--samples", "without --vary", "identical"), id="fragility-samples-without-vary",
    ),
    # 4. a typo that would run for hours
    _case(
        "records", "generate", "--target", "rg1.60:pga=0.3g", "--count", "1", "--duration", "2",
        "--output", "suite", "--dt", "1e-9", words=("--dt", "1e-09", "samples"),
        id="records-generate-dt-tiny",
    ),
    _case(
        "fragility", "{crane}", "--suite", "suite.toml", "--levels", "1:2:2",
        "--samples", "100000000", words=("--samples", "100000000", "1 to"),
        id="fragility-samples-huge",
    ),
    # 5. messages print as written: rich would turn ":B:" of "A:B:N" into an emoji
    _case(
        "fragility", "{crane}", "--suite", "suite.toml", "--levels", "1:2",
        words=("--levels", "'1:2'", "A:B:N"), id="fragility-levels-two-fields",
    ),
]  # fmt: skip


def _expand(args: tuple[str, ...], inputs: Path) -> list[str]:
    values = {"crane": str(CRANE), "record": str(RECORD), "inputs": str(inputs)}
    return [arg.format(**values) for arg in args]


def _files(folder: Path) -> set[str]:
    return {str(path.relative_to(folder)) for path in folder.rglob("*")}


@pytest.mark.parametrize(("args", "code", "words"), CASES)
def test_bad_input_gives_one_message_and_no_file(args, code, words, inputs, tmp_path):
    work = tmp_path / "work"
    work.mkdir()
    before = _files(inputs)
    result = run_freestand(*_expand(args, inputs), cwd=work)
    output = result.stdout + result.stderr
    assert "Traceback" not in output, output
    assert result.returncode == code, output
    flat = re.sub(r"\s+", " ", result.stderr)
    for word in words:
        assert word in flat, (word, result.stderr)
    if "error:" in result.stderr:
        assert result.stderr.count("error:") == 1, result.stderr
    assert _files(work) == set(), "files left behind"
    assert _files(inputs) == before, "files left behind"


def test_centre_outside_the_base_is_a_warning_on_every_command(inputs):
    model = str(inputs / "centre_outside.toml")
    for args in (("screen", model), ("screen", model, "--json"), ("map", model, "--n", "5")):
        result = run_freestand(*args)
        assert "Traceback" not in result.stdout + result.stderr
        assert result.returncode == 0, result.stderr
        flat = re.sub(r"\s+", " ", result.stderr)
        assert "warning:" in flat and "'cart'" in flat and "cannot stand" in flat


def test_version_and_help_exit_cleanly():
    from freestand import __version__

    result = run_freestand("--version")
    assert result.returncode == 0 and result.stdout.strip() == f"freestand {__version__}"
    result = run_freestand("screen", "--help")
    assert result.returncode == 0 and "Usage: freestand screen" in result.stdout


@pytest.mark.skipif(
    sys.platform == "win32" or os.geteuid() == 0, reason="root writes into read-only folders"
)
def test_read_only_folder_is_refused_before_computing(tmp_path):
    folder = tmp_path / "locked"
    folder.mkdir()
    folder.chmod(stat.S_IRUSR | stat.S_IXUSR)
    try:
        result = run_freestand("map", str(CRANE), "--n", "20", "--csv", str(folder / "m.csv"))
        assert result.returncode == 2
        assert "--csv" in result.stderr and "cannot write" in result.stderr
    finally:
        folder.chmod(stat.S_IRWXU)


def test_scheduler_that_is_not_dask_is_refused_in_one_line(tmp_path):
    """A server at the --scheduler address that answers something else than Dask (here a
    few bytes of HTTP): a message naming the option, exit 2, no traceback and no hang."""
    import socket
    import threading

    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen()
    server.settimeout(30)
    port = server.getsockname()[1]

    def answer():
        try:
            for _ in range(5):
                connection, _ = server.accept()
                with connection:
                    connection.sendall(b"HTTP/1.1 400 Bad Request\r\n\r\n" + b"\xff" * 64)
        except OSError:
            pass

    (tmp_path / "suite.toml").write_text(
        f'name = "one"\n[[record]]\nname = "r"\nhorizontal = "{RECORD.as_posix()}"\n'
    )
    thread = threading.Thread(target=answer, daemon=True)
    thread.start()
    try:
        result = run_freestand(
            "fragility", str(CRANE), "--suite", str(tmp_path / "suite.toml"), "--levels",
            "1:2:2", "--scheduler", f"tcp://127.0.0.1:{port}", cwd=tmp_path,
        )  # fmt: skip
    finally:
        server.close()
    output = result.stdout + result.stderr
    assert "Traceback" not in output and "internal error" not in output, output
    assert result.returncode == 2, output
    assert "--scheduler" in result.stderr
