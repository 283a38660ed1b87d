"""The one error class of freestand.

Every check at the boundary (model files, spectrum and record files, command
arguments) raises :class:`FreestandError`. Its message names where the problem
is (file and field), the offending value and the fix, so that the command line
can print it as it stands and exit non-zero without a traceback.
"""

from __future__ import annotations


class FreestandError(ValueError):
    """Invalid input to freestand, with a message that says how to fix it.

    Parameters
    ----------
    message : str
        What is wrong and how to fix it.
    source : str, optional
        The file (or argument) the problem was found in; prefixed to the
        message when given.
    field : str, optional
        The dotted path of the offending field (``configuration[0].block[1].mass``).

    Examples
    --------
    >>> import freestand as fs
    >>> try:
    ...     fs.Block.rectangle("cabinet", -0.6, 2.0, 1200.0, fs.Friction(0.8, 0.7))
    ... except fs.FreestandError as error:
    ...     print(error.field, "|", error.detail)
    width | ...
    >>> issubclass(fs.FreestandError, ValueError)
    True
    """

    def __init__(self, message: str, *, source: str | None = None, field: str | None = None):
        self.source = source
        self.field = field
        self.detail = message
        parts = []
        if source:
            parts.append(str(source))
        if field:
            parts.append(f"field '{field}'")
        prefix = ": ".join(parts)
        super().__init__(f"{prefix}: {message}" if prefix else message)
