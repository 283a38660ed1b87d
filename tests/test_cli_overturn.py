"""The real ``freestand overturn`` command on the crane cart (paper section 5, Figs. 6-8)."""

from __future__ import annotations

import json

import pytest

from tests.conftest import CRANE, run_freestand


@pytest.fixture(scope="module")
def cart_document():
    result = run_freestand(
        "overturn", str(CRANE), "-c", "x-z cart right", "-b", "cart",
        "--amplitudes", "10.31", "--frequencies", "0.5,1", "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def test_cart_rocking_properties(cart_document):
    # shared/spec/crane-model.md: R = 3.127 m, alpha = 0.4393 rad, p = 1.449 rad/s.
    assert cart_document["pivot"] == "right"  # it rocks about its outer wheel in screening
    assert cart_document["R"] == pytest.approx(3.127, abs=1e-3)
    assert cart_document["alpha"] == pytest.approx(0.4393, abs=1e-4)
    assert cart_document["p"] == pytest.approx(
        1.449, abs=2e-3
    )  # I_B from coordinates: 374 412 vs 374 250


def test_paper_fig6_and_fig7_numbers(cart_document):
    (rectangular,) = cart_document["rectangular"]
    assert rectangular["housner"] == pytest.approx(0.37, abs=0.01)  # paper Fig. 6: 0.37 s
    assert rectangular["exact"] > rectangular["housner"]  # alpha = 0.44 rad is not slender
    half = {row["frequency"]: row for row in cart_document["half_sine"]}
    # Paper Fig. 7: 10.31 m/s^2 overturns the cart only below 0.5 Hz by Housner's criterion.
    assert half[0.5]["housner"] == pytest.approx(10.31, rel=0.01)
    # The corrected and exact limits are lower (Makris and Roussos 2000).
    assert half[0.5]["linear"] < half[0.5]["housner"] and half[0.5]["exact"] < half[0.5]["housner"]
    assert cart_document["overturns_below_frequency"]["housner"] == pytest.approx(0.5, abs=0.01)
    assert cart_document["overturns_below_frequency"]["exact"] > 0.55


def test_spectrum_check_against_the_stand_in(cart_document):
    checks = cart_document["spectrum_check"]
    assert set(checks) == {"housner", "makris-roussos", "exact"}
    for check in checks.values():
        assert check["verdict"] in ("no overturning", "overturning possible")
        assert check["min_ratio"] > 0 and check["frequency"] > 0


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("-c", "x-z cart right", "-b", "bridge"), "carries 'cart'"),
        (("-c", "x-z cart right", "-b", "tower"), "no block named 'tower'"),
        (("-c", "x-z cart right", "-b", "cart", "--pivot", "middle"), "not a pivot"),
        (
            ("-c", "x-z cart right", "-b", "cart", "--restitution", "1.5"),
            "not an angular-velocity ratio",
        ),
        (
            ("-c", "x-z cart right", "-b", "cart", "--spectrum", "rg1.60:pga=0.2g,damping=4%"),
            "tabulates damping",
        ),
    ],
)
def test_bad_input(args, message):
    result = run_freestand("overturn", str(CRANE), *args)
    assert result.returncode == 2
    assert message in result.stderr and "Traceback" not in result.stderr


def test_restitution_override():
    result = run_freestand(
        "overturn", str(CRANE), "-c", "x-z cart right", "-b", "cart", "--restitution", "0.9",
        "--amplitudes", "10.31", "--frequencies", "1", "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["restitution"] == pytest.approx(0.9)


def test_record_spectrum_and_bare_numbers_in_options():
    """--spectrum takes a record's response spectrum; bare option numbers are SI."""
    from tests.conftest import ROOT

    record = ROOT / "examples" / "records" / "synthetic_H.AT2"
    checks = {}
    for option in (f"record:{record},peak=2.943", f"record:{record},peak=0.3g"):
        result = run_freestand(
            "overturn", str(CRANE), "-c", "x-z cart right", "-b", "cart",
            "--frequencies", "0.5", "--spectrum", option, "--json",
        )  # fmt: skip
        assert result.returncode == 0, result.stderr
        checks[option] = json.loads(result.stdout)["spectrum_check"]
    first, second = checks.values()
    assert first["exact"]["min_ratio"] == pytest.approx(second["exact"]["min_ratio"], rel=1e-9)
    assert first["exact"]["min_ratio"] > 1  # 0.3 g record: the cart does not overturn
    result = run_freestand(
        "overturn", str(CRANE), "-c", "x-z cart right", "-b", "cart", "--frequencies", "0.5",
        "--spectrum", "en1998:ag=2.5,ground=B,type=1", "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
