"""Generate the demo record suite on demand (not shipped: 60 files, about 5 MB).

    python examples/records/make_demo_suite.py [OUTPUT_FOLDER]

30 spectrum-compatible records of 20 s at 200 samples/s, horizontal and
vertical, matched to the RG 1.60 spectra anchored to 0.3 g (5 % damping),
seed 1, written as PEER .AT2 files with suite.toml and acceptance.json, and a
figure of the horizontal spectra against the target. The same command gives
the same files on every run. Default folder: build/demo-suite.
"""

from __future__ import annotations

import sys
from pathlib import Path

from freestand.cli import main

if __name__ == "__main__":
    output = Path(sys.argv[1] if len(sys.argv) > 1 else "build/demo-suite")
    sys.exit(
        main(
            [
                "records",
                "generate",
                "--target",
                "rg1.60:pga=0.3g,damping=5%",
                "--vertical",
                "rg1.60:pga=0.3g,damping=5%,direction=vertical",
                "--count",
                "30",
                "--duration",
                "20",
                "--seed",
                "1",
                "--output",
                str(output),
                "--plot",
                str(output.with_suffix(".png")),
            ]
        )  # fmt: skip
    )
