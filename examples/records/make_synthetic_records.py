"""Regenerate the synthetic example records in this folder.

    python examples/records/make_synthetic_records.py

The records are synthetic: band-limited noise with an envelope, made by
:func:`freestand.core.motion.ground_motion.synthetic_ground_motion` with its default
arguments (seed 20240601, 15 s at 0.005 s, horizontal peak 0.25 g with a
Kanai-Tajimi filter at 2.5 Hz, vertical peak 2/3 of it at 6 Hz). They are not
recordings of an earthquake. The same call always gives the same files.
"""

from pathlib import Path

from freestand.core.motion.ground_motion import synthetic_ground_motion
from freestand.io.records import write_at2

HERE = Path(__file__).resolve().parent
TITLE = "PEER NGA STRONG MOTION DATABASE RECORD - SYNTHETIC, NOT A RECORDED EARTHQUAKE"


def main() -> None:
    motion = synthetic_ground_motion()
    seed = motion.metadata["seed"]
    write_at2(
        HERE / "synthetic_H.AT2",
        motion,
        component="horizontal",
        title=TITLE,
        description=(
            f"SYNTHETIC freestand example, seed {seed}, Kanai-Tajimi 2.5 Hz, "
            "PGA 0.25 g, component H"
        ),
    )
    write_at2(
        HERE / "synthetic_UP.AT2",
        motion,
        component="vertical",
        title=TITLE,
        description=(
            f"SYNTHETIC freestand example, seed {seed + 1}, Kanai-Tajimi 6 Hz, "
            "PGA 0.167 g, component UP"
        ),
    )


if __name__ == "__main__":
    main()
