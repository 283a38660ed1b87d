"""fs.example_path: the built-in example model files, as `freestand example NAME` prints them."""

import pytest

import freestand as fs
from tests.conftest import run_freestand


@pytest.mark.parametrize("name", ["crane", "bodies", "cask"])
def test_every_example_loads_and_is_what_the_command_prints(name):
    path = fs.example_path(name)
    model = fs.load_model(path)
    assert model.configurations or model.body_configurations
    printed = run_freestand("example", name)
    assert printed.returncode == 0
    assert printed.stdout == path.read_text()


def test_an_unknown_example_names_the_choices():
    with pytest.raises(fs.FreestandError, match="crane, bodies, cask"):
        fs.example_path("cabinet")
    printed = run_freestand("example", "cabinet")
    assert printed.returncode != 0
    assert "crane, bodies, cask" in printed.stderr + printed.stdout
    assert "Traceback" not in printed.stderr
