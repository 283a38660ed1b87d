"""Pairing the component files of a station into one three-component record.

Strong-motion databases deliver one file per component (PEER NGA ``.AT2``:
``RSN1063_NORTHR_RRS228.AT2``, ``..._RRS318.AT2``, ``..._RRS-UP.AT2``) or one
file with every channel of a station (CESMD COSMOS/CSMIP ``.V2``, a block per
channel, each with a header line such as ``Chan  1: 180 Deg`` or
``Chan  3: Up``). :func:`pair_components` finds which files (or channels) are
the x, y and vertical components of one station, and says how:

1. **file names** (``.AT2`` and other single-component files): the name ends
   with the component's tag after the station's name -- an azimuth in
   degrees (``RRS228``, ``_000``, ``-090``), a vertical (``-UP``, ``_DWN``,
   ``-V``, ``_HNZ``), a compass letter (``-N``, ``-E``, ``_NS``, ``_EW``),
   a channel code (``_HNE``, ``_HN1``), or freestand's own ``_H``, ``_X``,
   ``_Y``, ``_UP``; the files whose names differ only by that tag are one
   station;
2. **headers**, when the name has no tag: the second line of an ``.AT2``
   file (event, date, station, component: the last comma-separated field
   is the component, the rest names the station), or the channel line of a
   ``.V2`` file (``Chan  2:  90 Deg``) with its ``Station No.``;
3. the **channels of one .V2 file** are one station, ordered by their
   channel headers.

Orientation. x, y and z (up) form a right-handed frame: seen from above, y
is x turned 90 degrees counter-clockwise. Azimuths are clockwise from north
(PEER, CSMIP), so of two orthogonal components at azimuths A and A - 90 deg,
the one at A is x and the one at A - 90 deg is y (``090`` is x, ``000`` is y;
``180`` is x, ``090`` is y). Compass letters are azimuths (N 0, E 90, S 180,
W 270 deg). Codes without an azimuth (``H1``/``H2``, ``L``/``T``, ``HN1``/
``HN2``) give x = the first, y = the second, and the note says that their
orientation is not known. Two horizontal components that are not orthogonal,
or a station with more than two horizontal or one vertical component, are
not paired (the note says why) and the files are read one by one, as is a
file that no station claims. A vertical tagged ``DWN``/``DOWN`` is taken as
positive downward, every other as positive upward (as recorded).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

from freestand.core.motion.ground_motion import GroundMotion, combine_components
from freestand.errors import FreestandError

#: Azimuths [deg, clockwise from north] of compass tags.
_COMPASS = {"N": 0.0, "NS": 0.0, "SN": 180.0, "E": 90.0, "EW": 90.0, "WE": 270.0,
            "S": 180.0, "W": 270.0}  # fmt: skip
#: Tags of a vertical component (positive up unless ``_DOWNWARD``).
_VERTICAL = {"UP", "DWN", "DN", "DOWN", "V", "VER", "VERT", "Z"}
_DOWNWARD = {"DWN", "DN", "DOWN"}
#: Tags of horizontal components without an azimuth, and their order (x first).
_UNORIENTED = {"H": 1, "X": 1, "Y": 2, "H1": 1, "H2": 2, "L": 1, "T": 2, "LONG": 1, "TRAN": 2}

_SEPARATED_TAG = re.compile(
    r"^(?P<station>.*?[A-Za-z0-9])[-_. ](?P<tag>UP|DWN|DN|DOWN|VERT|VER|V|Z|NS|SN|EW|WE|[NSEW]"
    r"|H1|H2|LONG|TRAN|[LTHXY]|[BHSE][HLN][ENZ12]|\d{1,3})$",
    re.IGNORECASE,
)
_TRAILING_AZIMUTH = re.compile(r"^(?P<station>.*?[A-Za-z])(?P<tag>\d{3})$")
_V2_CHANNEL = re.compile(
    r"\bChan\s*\d+\s*:\s*(?:(?P<azimuth>\d{1,3})\s*Deg|(?P<word>Up|Down|Vert\w*))\b",
    re.IGNORECASE,
)
_V2_STATION = re.compile(r"\bStat(?:io)?n\s*No\.?\s*:?\s*(?P<number>[\w-]+)", re.IGNORECASE)


@dataclass(frozen=True)
class Orientation:
    """What a tag says about a component.

    Attributes
    ----------
    tag : str
        The tag as found (``"090"``, ``"UP"``, ``"Chan 2: 90 Deg"``).
    vertical : bool
        A vertical component.
    azimuth : float or None
        Azimuth of a horizontal component [deg, clockwise from north], None
        when not known.
    order : int
        Order of a horizontal component without an azimuth (1: x, 2: y).
    vertical_positive : str
        ``"up"`` or ``"down"`` for a vertical component.
    """

    tag: str
    vertical: bool = False
    azimuth: float | None = None
    order: int = 0
    vertical_positive: str = "up"


def orientation_of(tag: str) -> Orientation | None:
    """The :class:`Orientation` a component tag stands for, None if it is not one."""
    text = tag.strip()
    upper = text.upper()
    if upper in _VERTICAL:
        return Orientation(text, vertical=True,
                           vertical_positive="down" if upper in _DOWNWARD else "up")  # fmt: skip
    if upper.isdigit() and len(upper) <= 3 and int(upper) <= 360:
        return Orientation(text, azimuth=float(int(upper) % 360))
    if upper in _COMPASS:
        return Orientation(text, azimuth=_COMPASS[upper])
    if upper in _UNORIENTED:
        return Orientation(text, order=_UNORIENTED[upper])
    if len(upper) == 3 and upper[0] in "BHSE" and upper[1] in "HLN":  # SEED channel codes
        if upper[2] in "12":
            return Orientation(text, order=int(upper[2]))
        found = orientation_of(upper[2])
        return None if found is None else Orientation(text, found.vertical, found.azimuth)
    return None


@dataclass(frozen=True)
class ComponentFile:
    """One component of a station: a file, or a channel of a ``.V2`` file.

    Attributes
    ----------
    path : str
        The file.
    channel : int or None
        The ``.V2`` channel (1 for the first), None for a one-component file.
    orientation : Orientation
        What its name or header says.
    """

    path: str
    channel: int | None
    orientation: Orientation

    @property
    def label(self) -> str:
        """The file name, with the channel of a ``.V2`` file."""
        name = Path(self.path).name
        return name if self.channel is None else f"{name} channel {self.channel}"


@dataclass(frozen=True)
class StationPairing:
    """The components of one station as paired, and how.

    Attributes
    ----------
    station : str
        The station's name as found (the file name without its tag, the
        header's station, or the ``.V2`` file).
    method : str
        ``"file names"``, ``"AT2 headers"``, ``"V2 channel headers"``, or
        ``"none"`` for a file read on its own (a ``.V2`` channel other than
        the first when its file did not pair).
    components : dict
        ``{"horizontal": ComponentFile, "horizontal_y": ..., "vertical": ...}``,
        the components found.
    note : str
        One sentence saying which files were paired and how (or why not).
    reason : str
        Why a file a station claimed was read on its own ("" otherwise).
    """

    station: str
    method: str
    components: dict
    note: str
    reason: str = ""

    @property
    def paired(self) -> bool:
        """Whether several components were put together."""
        return self.method != "none"

    def to_dict(self) -> dict:
        """JSON form: station, method, the file (and channel) of each component, note."""
        return {
            "station": self.station,
            "method": self.method,
            "components": {
                role: {"file": c.path, "channel": c.channel, "tag": c.orientation.tag}
                for role, c in self.components.items()
            },
            "note": self.note,
            "reason": self.reason or None,
        }


def _name_tag(path: Path) -> tuple[str, Orientation] | None:
    stem = path.stem
    for pattern in (_SEPARATED_TAG, _TRAILING_AZIMUTH):
        match = pattern.match(stem)
        if match:
            orientation = orientation_of(match.group("tag"))
            if orientation is not None:
                return match.group("station"), orientation
    return None


def _at2_header_tag(path: Path) -> tuple[str, Orientation] | None:
    try:
        with path.open(encoding="utf-8", errors="replace") as handle:
            lines = [handle.readline() for _ in range(2)]
    except OSError:
        return None
    station, comma, tag = lines[1].strip().rpartition(",")
    orientation = orientation_of(tag) if comma else None
    if orientation is None or not station.strip():
        return None
    return station.strip(), orientation


def _v2_channels(path: Path, gravity: float) -> list[tuple[str, ComponentFile]]:
    """(station, component) of each channel of a ``.V2`` file whose header orients it."""
    from freestand.io.records import read_v2_component, v2_channel_count

    found = []
    for channel in range(1, v2_channel_count(path) + 1):
        header = read_v2_component(path, gravity=gravity, channel=channel).header
        text = "\n".join(header)
        match = _V2_CHANNEL.search(text)
        if match is None:
            return []
        if match.group("azimuth") is not None:
            orientation = orientation_of(match.group("azimuth"))
        else:
            orientation = orientation_of("DOWN" if match.group("word").upper() == "DOWN" else "UP")
        orientation = Orientation(
            " ".join(match.group(0).split()),
            orientation.vertical,
            orientation.azimuth,
            orientation.order,
            orientation.vertical_positive,
        )
        number = _V2_STATION.search(text)
        station = f"station {number.group('number')}" if number else path.name
        found.append((station, ComponentFile(str(path), channel, orientation)))
    return found


def _assign(components: list[ComponentFile]) -> tuple[dict, str] | str:
    """Roles of a station's components and the orientation note, or why they cannot pair."""
    vertical = [c for c in components if c.orientation.vertical]
    horizontal = [c for c in components if not c.orientation.vertical]
    if len(vertical) > 1 or len(horizontal) > 2 or not horizontal:
        return (
            f"{len(horizontal)} horizontal and {len(vertical)} vertical components (a record "
            "has one or two horizontal and at most one vertical)"
        )
    roles: dict = {}
    note = ""
    if len(horizontal) == 2:
        first, second = horizontal
        a, b = first.orientation.azimuth, second.orientation.azimuth
        if a is not None and b is not None:
            if math.isclose((a - b) % 360.0, 90.0, abs_tol=0.5):
                x, y = first, second
            elif math.isclose((b - a) % 360.0, 90.0, abs_tol=0.5):
                x, y = second, first
            else:
                return (
                    f"the horizontal components at azimuths {a:g} and {b:g} deg are not orthogonal"
                )
            note = (
                f"x at azimuth {x.orientation.azimuth:g} deg, y at {y.orientation.azimuth:g} deg "
                "(90 deg counter-clockwise from x seen from above)"
            )
        elif first.orientation.order and second.orientation.order:
            if first.orientation.order == second.orientation.order:
                return "both horizontal components are tagged as the same one"
            x, y = sorted(horizontal, key=lambda c: c.orientation.order)
            note = (
                f"{x.orientation.tag} taken as x and {y.orientation.tag} as y: their azimuths "
                "are not known (assumed orthogonal, y counter-clockwise from x)"
            )
        else:
            return "one horizontal component has an azimuth and the other not"
        roles["horizontal"], roles["horizontal_y"] = x, y
    else:
        roles["horizontal"] = horizontal[0]
    if vertical:
        roles["vertical"] = vertical[0]
        note = "; ".join(
            filter(None, [note, f"vertical positive {vertical[0].orientation.vertical_positive}"])
        )
    return roles, note


def pair_components(paths, *, gravity: float = 9.81) -> list[StationPairing]:
    """Group component files into stations (x, y, vertical), from their names or headers.

    Parameters
    ----------
    paths : sequence of str or Path
        Record files: one-component files (``.AT2``, CSV, single column) and
        ``.V2`` files (one or several channels).
    gravity : float, optional
        g [m/s^2] (reading ``.V2`` headers reads the channels).

    Returns
    -------
    list of StationPairing
        One per record, in the order of the first file of each: a paired
        station (``method`` says how, ``note`` which files are x, y and
        vertical and why) or a file on its own (``method`` ``"none"``; its
        ``reason`` says why when a station claimed it).
        ``.V2`` files are paired by their channel headers; other files by
        their names, else by their ``.AT2`` headers.
    """
    paths = [Path(p) for p in paths]
    groups: dict[tuple[str, str], list[ComponentFile]] = {}
    names: dict[tuple[str, str], str] = {}
    order: list[tuple[str, str] | Path] = []
    for path in paths:
        claimed = []
        if path.suffix.lower() == ".v2" and path.is_file():
            for station, component in _v2_channels(path, gravity):
                key = ("V2 channel headers", station)
                claimed.append((key, station, component))
        else:
            for method, reader in (("file names", _name_tag), ("AT2 headers", _at2_header_tag)):
                if method == "AT2 headers" and path.suffix.lower() != ".at2":
                    continue
                found = reader(path) if path.is_file() else None
                if found is not None:
                    station, orientation = found
                    folder = str(path.parent) if method == "file names" else ""
                    component = ComponentFile(str(path), None, orientation)
                    claimed = [((method, f"{folder}|{station}"), station, component)]
                    break
        if not claimed:
            order.append(path)
            continue
        for key, station, component in claimed:
            if key not in groups:
                groups[key], names[key] = [], station
                order.append(key)
            groups[key].append(component)
    pairings = []
    for item in order:
        if isinstance(item, Path):
            pairings.append(_alone(item, None, ""))
            continue
        method, station, components = item[0], names[item], groups[item]
        if len(components) == 1:
            pairings.append(_alone(Path(components[0].path), components[0].channel, ""))
            continue
        assigned = _assign(components)
        if isinstance(assigned, str):
            reason = f"{station}: {assigned}"
            pairings.extend(_alone(Path(c.path), c.channel, reason) for c in components)
            continue
        roles, orientation_note = assigned
        files = ", ".join(f"{_ROLE_WORDS[r]} = {c.label} ({c.orientation.tag})"
                          for r, c in roles.items())  # fmt: skip
        note = f"{station}: {files}; paired by {method}"
        if orientation_note:
            note += f"; {orientation_note}"
        pairings.append(StationPairing(station, method, roles, note))
    return pairings


_ROLE_WORDS = {"horizontal": "x", "horizontal_y": "y", "vertical": "vertical"}


def _alone(path: Path, channel: int | None, reason: str) -> StationPairing:
    component = ComponentFile(str(path), channel, Orientation(""))
    note = f"{component.label}: read on its own" + (f", not paired ({reason})" if reason else "")
    return StationPairing(component.label, "none", {"horizontal": component}, note, reason)


def load_pairing(
    pairing: StationPairing,
    *,
    dt: float | None = None,
    unit: str | None = None,
    gravity: float = 9.81,
    name: str | None = None,
) -> GroundMotion:
    """The record of a :class:`StationPairing` (its components combined).

    Parameters
    ----------
    pairing : StationPairing
    dt, unit : optional
        Time step [s] and unit of single-column files.
    gravity : float, optional
        g [m/s^2].
    name : str, optional
        Record name (default: the station's).

    Returns
    -------
    GroundMotion
        x, and y and the downward vertical where the station has them,
        combined by :func:`~freestand.core.motion.ground_motion.combine_components`;
        ``metadata["pairing"]`` holds the note.
    """
    from freestand.io.records import load_record, read_v2_component

    x = pairing.components["horizontal"]
    if not pairing.paired:
        if x.channel is not None and x.channel != 1:
            component = read_v2_component(x.path, gravity=gravity, channel=x.channel)
            return GroundMotion(component.dt, component.acceleration, name=name or x.label,
                                metadata={"source": x.path, "pairing": pairing.note})  # fmt: skip
        return load_record(x.path, dt=dt, unit=unit, gravity=gravity, name=name)
    arrays = {}
    for role, component in pairing.components.items():
        if component.channel is not None:
            read = read_v2_component(component.path, gravity=gravity, channel=component.channel)
            values, step = read.acceleration, read.dt
        else:
            read = load_record(component.path, dt=dt, unit=unit, gravity=gravity)
            values, step = read.horizontal, read.dt
        if role == "vertical" and component.orientation.vertical_positive == "up":
            values = -values  # freestand stores downward acceleration
        arrays[role] = (values, step)
    vertical = arrays.get("vertical", (None, None))
    horizontal_y = arrays.get("horizontal_y", (None, None))
    metadata = {
        "pairing": pairing.note,
        "source": x.path,
        "sources": {role: c.label for role, c in pairing.components.items()},
    }
    return combine_components(
        *arrays["horizontal"], *vertical, horizontal_y=horizontal_y[0],
        horizontal_y_dt=horizontal_y[1], name=name or pairing.station, metadata=metadata,
    )  # fmt: skip


def load_station(paths, *, dt=None, unit=None, gravity: float = 9.81, name=None) -> GroundMotion:
    """One three-component record from the component files of one station.

    Parameters
    ----------
    paths : sequence of str or Path, or str or Path
        The station's files (e.g. ``RSN1063_NORTHR_RRS228.AT2``,
        ``..._RRS318.AT2``, ``..._RRS-UP.AT2``), or one ``.V2`` file with
        its channels.
    dt, unit : optional
        Time step [s] and unit of single-column files.
    gravity : float, optional
        g [m/s^2].
    name : str, optional
        Record name (default: the station's).

    Returns
    -------
    GroundMotion
        The paired record; ``metadata["pairing"]`` says which file is x, y
        and vertical and how that was found (:func:`pair_components`).

    Raises
    ------
    FreestandError
        The files are not the components of one station.

    Examples
    --------
    >>> import freestand as fs
    >>> station = fs.load_station(["examples/records/synthetic_H.AT2",
    ...                            "examples/records/synthetic_UP.AT2"])
    >>> station.name, station.components
    ('synthetic', ('horizontal', 'vertical'))
    """
    paths = [paths] if isinstance(paths, str | Path) else list(paths)
    for path in paths:
        if not Path(path).is_file():
            raise FreestandError("file not found; check the path of the record", source=str(path))
    pairings = pair_components(paths, gravity=gravity)
    if len(pairings) != 1:
        raise FreestandError(
            "these files are not the components of one station: "
            + " | ".join(p.note for p in pairings)
            + "; name them like RSN1_STATION_000.AT2, RSN1_STATION_090.AT2, RSN1_STATION-UP.AT2, "
            "or give x, y and vertical explicitly",
            source=", ".join(str(p) for p in paths),
        )
    return load_pairing(pairings[0], dt=dt, unit=unit, gravity=gravity, name=name)
