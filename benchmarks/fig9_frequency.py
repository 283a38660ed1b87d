"""Paper section 6, Fig. 9: the crane bridge's lowest vertical frequency against the cart position.

Prints Dunkerley's estimate (paper eqs. 1-4), the exact continuous-beam value and a
finite-element check at a few positions, the same with the cart's rotary inertia, the
jump check against a stand-in vertical spectrum, and the time the sweep takes.

    python benchmarks/fig9_frequency.py [output-stem]

With an output stem, also writes the figure as <stem>.png and <stem>.svg.
"""

from __future__ import annotations

import sys
import time

import numpy as np

from freestand.core.motion.spectra import Spectrum
from freestand.core.structure.beam import (
    SimplySupportedBeam,
    dunkerley_frequency,
    exact_frequency,
    finite_element_frequency,
    frequency_sweep,
    jump_check,
)

SPAN = 9.8
PARKING = (1.33, SPAN - 1.33)
CRANE = SimplySupportedBeam(SPAN, 2.1e11, 0.014, 16600.0, 25600.0)
# The cart's inertia about its centre in the x-z plane (Theta_S2y) and the height of its
# centre (z = 4.03 m) above the bridge's centre (z = 0.98 m), crane-model.md.
CRANE_ROTARY = SimplySupportedBeam(SPAN, 2.1e11, 0.014, 16600.0, 25600.0, 124100.0, 3.05)
STAND_IN = Spectrum(
    np.array([0.1, 1.0, 8.0, 12.0, 33.0, 100.0]),
    np.array([0.2, 3.0, 9.81, 9.81, 2.35, 2.35]),
    damping=0.05,
    direction="vertical",
    label="stand-in vertical spectrum: plateau 1.0 g at 8-12 Hz, ZPA 2.35 m/s^2",
)


def table(beam: SimplySupportedBeam, title: str) -> None:
    positions = np.array([0.0, 0.5, 1.0, 1.33, 2.0, 3.0, 4.0, 4.9])
    dunkerley = dunkerley_frequency(beam, positions)
    exact = exact_frequency(beam, positions)
    fe = finite_element_frequency(beam, positions, elements=32)
    print(title)
    print("   d [m]  Dunkerley [Hz]  exact [Hz]  FE-32 [Hz]  Dunkerley below exact")
    for d, fd, fx, ff in zip(positions, dunkerley, exact, fe, strict=True):
        print(f"  {d:6.2f}  {fd:14.4f}  {fx:10.4f}  {ff:10.4f}  {100 * (1 - fd / fx):8.2f} %")


def main() -> None:
    table(CRANE, "Crane bridge, cart as a point mass (paper section 6)")
    print()
    table(
        CRANE_ROTARY, "Same, cart with rotary inertia 124100 kg m^2, centre 3.05 m above the axis"
    )
    print()
    start = time.perf_counter()
    sweep = frequency_sweep(CRANE, points=197, parking=PARKING)
    elapsed = time.perf_counter() - start
    print(f"sweep of {sweep.position.size} positions: {elapsed:.3f} s")
    for method in ("dunkerley", "exact"):
        low, high = sweep.frequency_range(PARKING, method=method)
        print(f"  {method:9s} over the parking range: {low:.2f} - {high:.2f} Hz")
    print()
    for basis in ("dunkerley", "exact", "band"):
        check = jump_check(sweep, STAND_IN, 9.81, parking=PARKING, basis=basis)
        runs = ", ".join(f"{a:.2f}-{b:.2f} m" for a, b in check.risk_intervals) or "none"
        print(
            f"jump check ({basis:9s}): {check.status}; at risk {runs}; "
            f"min margin g - S_a = {check.minimum_margin:.3f} m/s^2 "
            f"at {check.minimum_margin_position:.2f} m"
        )
    rotary = frequency_sweep(CRANE_ROTARY, points=197, parking=PARKING)
    check = jump_check(rotary, STAND_IN, 9.81, parking=PARKING)
    runs = ", ".join(f"{a:.2f}-{b:.2f} m" for a, b in check.risk_intervals) or "none"
    print(f"jump check with rotary inertia (band): {check.status}; at risk {runs}")
    if len(sys.argv) > 1:
        from freestand.plot.frequency import plot_frequency_sweep, save_frequency_figure

        check = jump_check(sweep, STAND_IN, 9.81, parking=PARKING)
        figure = plot_frequency_sweep(sweep, jump=check, vertical_spectrum=STAND_IN)
        for path in save_frequency_figure(figure, sys.argv[1]):
            print(f"wrote {path}")


if __name__ == "__main__":
    main()
