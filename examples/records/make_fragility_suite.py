"""Write a suite of synthetic records for a fragility example.

    python examples/records/make_fragility_suite.py FOLDER [COUNT] [DURATION]

Writes COUNT (default 8) pairs of synthetic records (horizontal and vertical,
AT2 files) of DURATION seconds (default 10) and ``suite.toml`` listing them
into FOLDER. The records come from
:func:`freestand.core.motion.ground_motion.synthetic_ground_motion` with seeds 1, 2,
...: band-limited noise with an envelope, not recordings of earthquakes. The
same call always writes the same files.
"""

import sys
from pathlib import Path

from freestand.core.motion.ground_motion import synthetic_ground_motion
from freestand.io.records import write_at2
from freestand.io.suites import suite_text

TITLE = "PEER NGA STRONG MOTION DATABASE RECORD - SYNTHETIC, NOT A RECORDED EARTHQUAKE"


def main(folder: Path, count: int = 8, duration: float = 10.0) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    records = []
    for seed in range(1, count + 1):
        motion = synthetic_ground_motion(seed=seed, duration=duration)
        for component, suffix in (("horizontal", "H"), ("vertical", "UP")):
            description = f"SYNTHETIC freestand record, seed {seed}"
            write_at2(folder / f"syn{seed:02d}_{suffix}.AT2", motion, component=component,
                      title=TITLE, description=description)  # fmt: skip
        records.append({"name": f"syn{seed:02d}", "horizontal": f"syn{seed:02d}_H.AT2",
                        "vertical": f"syn{seed:02d}_UP.AT2"})  # fmt: skip
    text = suite_text(f"{count} synthetic records, {duration:g} s", records)
    (folder / "suite.toml").write_text(text, encoding="utf-8")
    print(f"wrote {folder / 'suite.toml'} and {2 * count} records")


if __name__ == "__main__":
    arguments = sys.argv[1:]
    if not arguments:
        sys.exit(__doc__)
    main(Path(arguments[0]), *(int(arguments[1]),) if len(arguments) > 1 else (),
         *(float(arguments[2]),) if len(arguments) > 2 else ())  # fmt: skip
