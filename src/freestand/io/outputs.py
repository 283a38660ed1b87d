"""Output files and folders: checked before any computation, written all or nothing.

Output paths follow one rule in every command:

- ``--plot FOLDER`` is a folder; the figures are written into it under fixed
  names (``map.png``, ``fig7_half_sine_pulse.svg``...).
- every other output (``--csv``, ``--samples``, ``--animate``, ``report -o``)
  is a file with one of the suffixes the option names.
- missing folders on the way are created (like ``mkdir -p``), but only once
  everything is computed; a path under a file, onto a folder, in a folder that
  cannot be written or with another suffix is refused.

They are checked before any computation (:func:`check_folder`,
:func:`check_file`), and written through :class:`Staging`: into temporary
files first, renamed into place only when every output of the command is
complete, so a failure never leaves a partial set of files behind.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
from collections.abc import Iterator
from pathlib import Path

from freestand.errors import FreestandError


def _check_writable(folder: Path, option: str, what: Path) -> None:
    """Create and remove a scratch file in ``folder``: the only sure test of writing."""
    try:
        handle, scratch = tempfile.mkstemp(prefix=".freestand-check-", dir=folder)
    except OSError as error:
        raise FreestandError(
            f"cannot write into the folder {str(folder)!r} for {str(what)!r} "
            f"({error.strerror}); choose a folder you can write to",
            source=option,
        ) from None
    os.close(handle)
    os.unlink(scratch)


def _existing_ancestor(path: Path) -> Path:
    """The nearest folder (or file) above ``path`` that exists."""
    parent = path.parent
    while not parent.exists() and parent != parent.parent:
        parent = parent.parent
    return parent


def check_writable(path: Path, option: str) -> None:
    """Check, before computing, that ``path`` can be written: the folders above it exist or
    can be made, and the nearest existing one can be written into.

    Parameters
    ----------
    path : pathlib.Path
        The file or folder to be written.
    option : str
        The option or argument that gave it (``"--csv"``, ``"output"``), named in errors.

    Raises
    ------
    FreestandError
        A path under a file, or in a folder that cannot be written (tested with a scratch
        file, the only sure test).
    """
    existing = _existing_ancestor(path)
    if not existing.is_dir():
        raise FreestandError(
            f"{str(existing)!r} is a file, not a folder, so {str(path)!r} cannot be written "
            "under it; choose another path",
            source=option,
        )
    _check_writable(existing, option, path)


def check_folder(path: Path | None, option: str = "--plot") -> Path | None:
    """Check an output folder before computing: it is (or can be made) a writable folder."""
    if path is None:
        return None
    if path.exists():
        if not path.is_dir():
            raise FreestandError(
                f"{str(path)!r} is a file; {option} takes a folder that the figures are "
                f"written into, e.g. {option} figures",
                source=option,
            )
        _check_writable(path, option, path)
        return path
    if path.suffix:
        raise FreestandError(
            f"{str(path)!r} looks like a file name ({path.suffix}); {option} takes a folder "
            f"that the figures are written into (PNG and SVG, under fixed names), e.g. "
            f"{option} {path.with_suffix('') if path.stem else 'figures'}",
            source=option,
        )
    check_writable(path, option)
    return path


def check_file(path: Path | None, option: str, suffixes: tuple[str, ...]) -> Path | None:
    """Check an output file before computing: a known suffix, in a writable existing folder."""
    if path is None:
        return None
    if path.suffix.lower() not in suffixes:
        example = path.with_suffix(suffixes[0]) if path.stem else f"out{suffixes[0]}"
        raise FreestandError(
            f"{str(path)!r} does not end in {' or '.join(suffixes)}; name the file with one of "
            f"them, e.g. {option} {example}",
            source=option,
        )
    if path.is_dir():
        raise FreestandError(
            f"{str(path)!r} is a folder; give a file name, e.g. {option} "
            f"{path / ('out' + suffixes[0])}",
            source=option,
        )
    check_writable(path, option)
    return path


class Staging:
    """Outputs written to temporary names and renamed into place together.

    Use :meth:`file` and :meth:`folder` for the temporary path to write to;
    :meth:`commit` renames them to their targets and returns the paths really
    written. On an error (the ``staging()`` context) every temporary is removed.
    """

    def __init__(self) -> None:
        self._files: list[tuple[Path, Path]] = []
        self._folders: list[tuple[Path, Path]] = []

    def file(self, target: Path) -> Path:
        """A temporary file for ``target``, with the same suffix."""
        handle, name = tempfile.mkstemp(
            prefix=f".{target.stem}.",
            suffix=f".tmp{target.suffix}",
            dir=_existing_ancestor(target) if not target.parent.is_dir() else target.parent,
        )
        os.close(handle)
        self._files.append((Path(name), target))
        return Path(name)

    def folder(self, target: Path) -> Path:
        """A temporary folder whose files go into ``target`` (created if missing)."""
        base = target if target.is_dir() else _existing_ancestor(target)
        name = tempfile.mkdtemp(prefix=f".{target.name or 'figures'}.tmp-", dir=base)
        self._folders.append((Path(name), target))
        return Path(name)

    def forget(self, temporary: Path) -> None:
        """Drop a temporary that was only a step (already removed)."""
        self._files = [(t, target) for t, target in self._files if t != temporary]

    def commit(self) -> list[Path]:
        """Rename everything into place; the target paths, in the order written."""
        written = []
        for temporary, target in self._folders:
            target.mkdir(parents=True, exist_ok=True)
            for item in sorted(temporary.iterdir()):
                os.replace(item, target / item.name)
                written.append(target / item.name)
            shutil.rmtree(temporary, ignore_errors=True)
        for temporary, target in self._files:
            target.parent.mkdir(parents=True, exist_ok=True)
            os.chmod(temporary, 0o644)
            os.replace(temporary, target)
            written.append(target)
        self._files, self._folders = [], []
        return written

    def discard(self) -> None:
        """Remove every temporary."""
        for temporary, _ in self._folders:
            shutil.rmtree(temporary, ignore_errors=True)
        for temporary, _ in self._files:
            temporary.unlink(missing_ok=True)
        self._files, self._folders = [], []


@contextlib.contextmanager
def staging() -> Iterator[Staging]:
    """A :class:`Staging` whose temporaries are removed if the block raises."""
    stage = Staging()
    try:
        yield stage
    except BaseException:
        stage.discard()
        raise
    stage.discard()
