"""The built-in example model files, packaged with freestand (``freestand example NAME``)."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from freestand.errors import FreestandError

#: Example name -> packaged model file.
EXAMPLES = {"crane": "crane.toml", "bodies": "bodies.toml", "cask": "cask.toml"}


def example_path(name: str) -> Path:
    """Path of the built-in example model file ``name``.

    ``"crane"`` is the reference paper's crane (``docs/getting-started.md``),
    ``"bodies"`` a cask and a cabinet in 3-D (``docs/three-d.md``), ``"cask"``
    the storage cask of the worked fragility example (``docs/cask.md``).
    ``freestand example NAME`` prints the same file.

    Parameters
    ----------
    name : str
        One of ``EXAMPLES``: ``"crane"``, ``"bodies"``, ``"cask"``.

    Returns
    -------
    pathlib.Path
        The packaged model file (its records and spectra lie beside it).

    Raises
    ------
    FreestandError
        For a name that is not a built-in example; the message lists them.

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model(fs.example_path("cask"))
    >>> [configuration.name for configuration in model.body_configurations]
    ['cask']
    """
    if name not in EXAMPLES:
        raise FreestandError(
            f"{name!r} is not a built-in example; choose one of {', '.join(EXAMPLES)}",
            source="freestand example",
        )
    return Path(str(resources.files("freestand.examples").joinpath(EXAMPLES[name])))
