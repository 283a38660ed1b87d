"""The store of a campaign: one Parquet row per simulation, written chunk by chunk.

Layout of a store folder::

    campaign.json        what the campaign is (model, records, levels, inputs,
                         outcomes, seeds, versions) and its fingerprint
    part-000000.parquet  the rows of chunk 0 (tasks 0 .. chunk_size - 1)
    part-000001.parquet  ...

Every part is written to a temporary file and renamed into place (atomic on
one file system), so a part is either complete or absent: an interrupted
campaign loses at most the chunks in progress, and a new run with the same
definition computes only the chunks that are missing. A store whose
fingerprint differs from the campaign being run is refused, never mixed.

Parquet is read and written with pyarrow.
"""

from __future__ import annotations

import json
import os
import re
import tempfile
from pathlib import Path

import numpy as np

from freestand.errors import FreestandError

DEFINITION = "campaign.json"
_PART = re.compile(r"^part-(\d{6})\.parquet$")


def _pyarrow():
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:  # pragma: no cover - pyarrow is a dependency
        raise FreestandError(
            "the campaign store needs pyarrow, which is not installed; pip install pyarrow",
            source="--store",
        ) from None
    return pa, pq


def _write_atomic(path: Path, write) -> None:
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(handle)
    try:
        write(temporary)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


class CampaignStore:
    """A store folder (see the module notes).

    Parameters
    ----------
    path : str or Path
        The folder.
    """

    def __init__(self, path: str | Path):
        self.path = Path(path)

    # -- definition ------------------------------------------------------------------------
    def definition(self) -> dict:
        """The ``campaign.json`` document; FreestandError if there is none."""
        file = self.path / DEFINITION
        if not file.is_file():
            raise FreestandError(
                f"{str(self.path)!r} is not a campaign store (no {DEFINITION}); give the folder "
                "that a run with --store wrote",
                source="--store",
            )
        try:
            return json.loads(file.read_text(encoding="utf-8"))
        except (OSError, ValueError) as error:
            raise FreestandError(f"cannot read {file} ({error})", source="--store") from None

    def open(self, definition: dict) -> None:
        """Create the store for ``definition``, or check that it holds the same campaign.

        Raises
        ------
        FreestandError
            If the folder holds another campaign (another fingerprint) or is a
            non-empty folder that is not a store, or cannot be written.
        """
        file = self.path / DEFINITION
        if file.is_file():
            existing = self.definition()
            if existing.get("fingerprint") != definition.get("fingerprint"):
                raise FreestandError(
                    f"{str(self.path)!r} holds another campaign (different model, records, "
                    "levels, inputs, outcomes or seed); give a new folder, or the same "
                    "options to resume it",
                    source="--store",
                )
            return
        if self.path.exists() and (not self.path.is_dir() or any(self.path.iterdir())):
            raise FreestandError(
                f"{str(self.path)!r} exists and is not a campaign store; give a new or empty "
                "folder",
                source="--store",
            )
        try:
            self.path.mkdir(parents=True, exist_ok=True)
            text = json.dumps(definition, indent=2)
            _write_atomic(file, lambda name: Path(name).write_text(text, encoding="utf-8"))
        except OSError as error:
            raise FreestandError(
                f"cannot write the store {str(self.path)!r} ({error.strerror})", source="--store"
            ) from None

    # -- parts ------------------------------------------------------------------------------
    def chunks(self) -> set[int]:
        """The chunks already written."""
        if not self.path.is_dir():
            return set()
        found = set()
        for entry in self.path.iterdir():
            match = _PART.match(entry.name)
            if match:
                found.add(int(match.group(1)))
        return found

    def write(self, chunk: int, rows: dict[str, np.ndarray]) -> Path:
        """Write the rows of one chunk as ``part-NNNNNN.parquet`` (atomically)."""
        pa, pq = _pyarrow()
        table = pa.table({name: pa.array(list(values) if values.dtype == object else values)
                          for name, values in rows.items()})  # fmt: skip
        target = self.path / f"part-{chunk:06d}.parquet"
        _write_atomic(target, lambda name: pq.write_table(table, name))
        return target

    def read(self) -> dict[str, np.ndarray]:
        """Every row of the store, in task order (columns as numpy arrays)."""
        pa, pq = _pyarrow()
        parts = sorted(self.chunks())
        if not parts:
            return {}
        tables = [pq.read_table(self.path / f"part-{chunk:06d}.parquet") for chunk in parts]
        table = pa.concat_tables(tables)
        rows = {}
        for name in table.column_names:
            column = table.column(name).to_numpy(zero_copy_only=False)
            rows[name] = column
        order = np.argsort(rows["task"], kind="stable")
        return {name: values[order] for name, values in rows.items()}
