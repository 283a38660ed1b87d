"""The real ``freestand simulate`` command (issue 7, in progress)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import CRANE, run_freestand

RECORD = Path(__file__).resolve().parents[1] / "examples" / "records" / "synthetic_H.AT2"


def test_simulate_crane_under_the_synthetic_record():
    result = run_freestand(
        "simulate", str(CRANE), "-c", "x-z cart right", "--record", str(RECORD),
        "--peak", "8", "--duration", "2", "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert document["status"] == "completed"
    assert document["peak_horizontal"] == 8.0
    names = [block["name"] for block in document["blocks"]]
    assert names == ["bridge", "cart"]
    assert not any(block["overturned"] for block in document["blocks"])


def test_bad_record_gives_a_message(tmp_path):
    empty = tmp_path / "empty.AT2"
    empty.write_text("")
    result = run_freestand("simulate", str(CRANE), "-c", "y-z", "--record", str(empty))
    assert result.returncode == 2
    assert "empty.AT2" in result.stderr and "Traceback" not in result.stderr


def test_scale_and_peak_exclude_each_other():
    result = run_freestand(
        "simulate", str(CRANE), "-c", "y-z", "--record", str(RECORD), "--scale", "2", "--peak", "3"
    )
    assert result.returncode == 2 and "not several" in result.stderr


def test_spectral_scaling_matches_the_target(tmp_path):
    """--spectral A@F,zeta: the scaled record's PSA at F is A (linear oscillator, exact)."""
    from freestand.core.motion.response_spectrum import spectral_response
    from freestand.io.records import load_record

    result = run_freestand(
        "simulate", str(CRANE), "-c", "y-z", "--record", str(RECORD),
        "--spectral", "1.05g@2.5Hz,2%", "--duration", "0.5", "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    motion = load_record(RECORD).scaled(document["scale_factor"])
    response = spectral_response(motion, frequencies=[2.5], damping=0.02)
    # the factor is target / PSA: the scaled PSA matches to round-off
    assert response.pseudo_acceleration[0] == pytest.approx(1.05 * 9.81, rel=1e-9)
    assert document["peak_horizontal"] == pytest.approx(motion.peak_horizontal, rel=1e-12)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("3", "not ACCELERATION@FREQUENCY"),
        ("3@0", "not a positive frequency"),
        ("-3@2", "negative"),
        ("3@2,150%", "damping"),
        ("3 kg@2", "not acceleration"),
    ],
)
def test_bad_spectral_target(text, message):
    from freestand.errors import FreestandError
    from freestand.io.records import parse_spectral_target

    with pytest.raises(FreestandError, match=message):
        parse_spectral_target(text)


def test_plot_and_animate_write_files_and_list_them(tmp_path):
    figures = tmp_path / "figures"
    gif = tmp_path / "anim" / "crane.gif"
    result = run_freestand(
        "simulate", str(CRANE), "-c", "x-z cart right", "--record", str(RECORD),
        "--peak", "8", "--duration", "1", "--plot", str(figures), "--animate", str(gif),
        "--exaggerate", "1000", "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    expected = [figures / "time-history.png", figures / "time-history.svg", gif]
    assert document["figures"] == [str(path) for path in expected]
    assert all(path.stat().st_size > 1000 for path in expected)
    from PIL import Image

    image = Image.open(gif)
    assert image.format == "GIF" and image.n_frames > 1


def test_plot_paths_are_printed(tmp_path):
    result = run_freestand(
        "simulate", str(CRANE), "-c", "y-z", "--record", str(RECORD), "--peak", "3",
        "--duration", "0.3", "--plot", str(tmp_path),
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert f"wrote {tmp_path / 'time-history.png'}" in result.stdout.replace("\n", "")


def test_animation_must_be_a_gif(tmp_path):
    result = run_freestand(
        "simulate", str(CRANE), "-c", "y-z", "--record", str(RECORD),
        "--animate", str(tmp_path / "motion.mp4"),
    )  # fmt: skip
    assert result.returncode == 2
    assert "--animate" in result.stderr and "motion.mp4" in result.stderr
    assert "motion.gif" in result.stderr  # the fix
    assert "Traceback" not in result.stderr
    assert not (tmp_path / "motion.mp4").exists()


def test_bad_exaggeration_and_plot_folder_give_messages(tmp_path):
    result = run_freestand(
        "simulate", str(CRANE), "-c", "y-z", "--record", str(RECORD), "--exaggerate", "-2"
    )
    assert result.returncode == 2 and "--exaggerate" in result.stderr
    assert "Traceback" not in result.stderr
    occupied = tmp_path / "file.txt"
    occupied.write_text("")
    result = run_freestand(
        "simulate", str(CRANE), "-c", "y-z", "--record", str(RECORD), "--plot", str(occupied)
    )
    assert result.returncode == 2 and "--plot" in result.stderr and "folder" in result.stderr
    assert "Traceback" not in result.stderr
