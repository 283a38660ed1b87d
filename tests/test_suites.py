"""Record suite files: reading, relative paths, scale, and clear errors."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from freestand.errors import FreestandError
from freestand.io.records import load_record
from freestand.io.suites import load_suite, suite_text

RECORDS = Path(__file__).resolve().parents[1] / "examples" / "records"


@pytest.fixture
def suite_folder(tmp_path: Path) -> Path:
    for name in ("synthetic_H.AT2", "synthetic_UP.AT2"):
        shutil.copy(RECORDS / name, tmp_path / name)
    return tmp_path


def test_suite_reads_records_relative_to_its_file_with_scale(suite_folder: Path):
    text = suite_text(
        "two records",
        [
            {"horizontal": "synthetic_H.AT2", "vertical": "synthetic_UP.AT2", "scale": 2.0},
            {"horizontal": "synthetic_H.AT2", "name": "plain"},
        ],
    )
    suite_file = suite_folder / "suite.toml"
    suite_file.write_text(text)
    suite = load_suite(suite_file)
    reference = load_record(RECORDS / "synthetic_H.AT2", vertical=RECORDS / "synthetic_UP.AT2")
    assert suite.name == "two records"
    assert len(suite) == 2
    np.testing.assert_allclose(suite.motions[0].horizontal, 2.0 * reference.horizontal)
    np.testing.assert_allclose(suite.motions[0].vertical, 2.0 * reference.vertical)
    assert suite.motions[1].vertical is None
    assert suite.motions[1].name == "plain"
    assert suite.scales == (2.0, 1.0)


@pytest.mark.parametrize(
    ("body", "expected"),
    [
        ("", "lists no record"),
        ('[[record]]\nhorizontal = "missing.AT2"\n', "does not exist"),
        ('[[record]]\nhorizontal = "synthetic_H.AT2"\nscale = -1\n', "positive"),
        ('[[record]]\nhorizontal = "synthetic_H.AT2"\nfoo = 1\n', "unknown key"),
        ("[[record]\n", "not valid TOML"),
    ],
)
def test_bad_suites_are_refused_naming_the_file(suite_folder: Path, body: str, expected: str):
    suite_file = suite_folder / "bad.toml"
    suite_file.write_text(body)
    with pytest.raises(FreestandError, match=expected) as error:
        load_suite(suite_file)
    assert "bad.toml" in str(error.value)
