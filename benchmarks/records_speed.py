"""Timing and accuracy figures for records: response spectrum and sliding block.

    python benchmarks/records_speed.py

Prints the time of a 5 % response spectrum of a 20 s record at 200 samples/s
on 100 frequencies (0.1-100 Hz, compiled code cached after the first call), and
of a sliding-block history; then the agreement of the spectrum with a direct
high-resolution integration at a few frequencies; then the time of RotD50 of
Sa of a pair of 20 s components at one frequency (the two responses computed
once and combined over 180 angles) against the anchor, one component's Sa at
that frequency, and against rotating the pair and computing each angle's
spectrum on its own.
"""

from __future__ import annotations

import math
import time

import numpy as np
from scipy.integrate import solve_ivp

from freestand.core.dynamics.sliding import slide_block
from freestand.core.motion.ground_motion import synthetic_ground_motion
from freestand.core.motion.response_spectrum import response_spectrum, spectral_response
from freestand.core.motion.rotd import rotation_angles, spectral_peaks_over_angles


def best_of(function, repeats=5):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def direct_peak(acceleration, dt, frequency, zeta):
    omega = 2 * math.pi * frequency
    times = np.arange(acceleration.size + 1) * dt
    values = np.append(acceleration, 0.0)
    t_end = times[-1] + 1 / frequency

    def rhs(t, y):
        a_g = np.interp(t, times, values, right=0.0)
        return [y[1], -a_g - 2 * zeta * omega * y[1] - omega**2 * y[0]]

    sol = solve_ivp(
        rhs,
        (0, t_end),
        [0, 0],
        method="DOP853",
        rtol=1e-11,
        atol=1e-14,
        max_step=dt / 2,
        dense_output=True,
    )
    grid = np.arange(0, t_end, min(dt, 1 / frequency) / 200)
    return np.max(np.abs(sol.sol(grid)[0]))


def main() -> None:
    motion = synthetic_ground_motion(duration=20.0, dt=0.005)
    frequencies = np.geomspace(0.1, 100.0, 100)
    response_spectrum(motion, frequencies=frequencies)  # compile / load cache
    elapsed = best_of(lambda: response_spectrum(motion, frequencies=frequencies))
    print(f"response spectrum, 20 s at 200 samples/s, 100 frequencies: {1e3 * elapsed:.1f} ms")
    slide_block(motion, 0.2, 0.15)
    elapsed = best_of(lambda: slide_block(motion, 0.2, 0.15))
    result = slide_block(motion, 0.2, 0.15)
    print(
        f"sliding block, same record, mu0 = 0.2, mu = 0.15: {1e3 * elapsed:.1f} ms "
        f"(max slide {1e3 * result.max_slide:.1f} mm, "
        f"residual {1e3 * result.residual_slide:.1f} mm)"
    )
    short = synthetic_ground_motion(duration=4.0, dt=0.01, vertical_peak=None)
    check = [0.5, 2.0, 10.0, 30.0, 60.0, 100.0]
    ours = spectral_response(short, None, check, 0.05).displacement
    print("frequency [Hz]  T/dt   relative difference to solve_ivp (rtol 1e-11)")
    for f, value in zip(check, ours, strict=True):
        reference = direct_peak(short.horizontal, short.dt, f, 0.05)
        print(f"{f:14.1f}  {1 / (f * short.dt):5.1f}   {value / reference - 1:+.2e}")
    rotd_speed()


def rotd_speed() -> None:
    """RotD50 of Sa(f) of a two-component 20 s record: combined responses vs brute force."""
    x = synthetic_ground_motion(duration=20.0, dt=0.005, seed=1, vertical_peak=None).horizontal
    y = synthetic_ground_motion(duration=20.0, dt=0.005, seed=2, vertical_peak=None).horizontal
    dt = 0.005
    angles = rotation_angles()
    for frequency in (1.0, 10.0, 40.0):
        spectral_peaks_over_angles(x, y, dt, frequency)  # compile / load cache
        anchor = best_of(lambda f=frequency: spectral_response(x, dt, [f], 0.05))
        combined = best_of(lambda f=frequency: spectral_peaks_over_angles(x, y, dt, f))
        brute = best_of(
            lambda f=frequency: [
                spectral_response(math.cos(a) * x + math.sin(a) * y, dt, [f], 0.05) for a in angles
            ],
            repeats=1,
        )
        print(
            f"RotD50 of Sa({frequency:g} Hz), 20 s pair at 200 samples/s, 180 angles: "
            f"{1e3 * combined:.2f} ms = {combined / anchor:.1f} x one component's Sa "
            f"({1e3 * anchor:.2f} ms); rotating and computing each angle: "
            f"{1e3 * brute:.0f} ms ({brute / combined:.0f} x slower)"
        )


if __name__ == "__main__":
    main()
