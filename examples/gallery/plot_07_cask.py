"""
A storage cask in 3-D against two planar problems
=================================================

A vertical spent-fuel storage cask of the HI-STORM 100 class (``examples/cask.toml``:
a solid cylinder of radius 1.683 m and height 6.083 m, 163 t, its centre of gravity
3.0 m up) stands free on a concrete pad. Today's method analyses it as a planar block
under each horizontal component of a record with the vertical and keeps the worse of
the two; the 3-D body feels both components at once and can roll on its rim.

The fragility campaign of 1,200 simulations and the same simulations as planar
problems are run by ``examples/cask_comparison.py`` (about a minute on two cores);
this example reads its results, ``examples/cask-comparison.json``, and simulates one
record both ways (``docs/cask.md`` has the whole example).
"""

# %%
# The fragility curves, 3-D against planar
# ----------------------------------------
# PGA RotD50 from 0.1 to 1.5 g, 20 three-component RG 1.60 records, the static
# friction uniform on 0.2-0.8, 4 samples per record and level. The planar
# simulations have the same scale factor and friction as the 3-D ones; an outcome
# counts when it occurs under x or under y.
import json

import numpy as np
from scipy.stats import norm

document = json.loads(open("../cask-comparison.json", encoding="utf-8").read())
levels = np.array(document["levels"])
for method, fits in document["fragility"].items():
    for key, fit in fits.items():
        median = f"{fit['median']:.2f} m/s^2" if fit["fitted"] else "not fitted"
        print(f"{method:26s} {key:9s} {median}")

# %%
# Stripe fractions (points) and fitted lognormal curves (lines) of the 3-D body and
# of the worse planar problem; the dashed curve is the 3-D fit of the simulations
# whose friction holds the cask against lifting (mu_0 > R/h = 0.561): only those
# tilt and overturn.
from matplotlib.figure import Figure

titles = {"slide": "slide > 0.1 m", "tilt": "tilt > 0.5 alpha", "overturn": "overturn"}
x = np.linspace(0.2, 16.0, 200)
fig = Figure(figsize=(11, 3.6))
axes = fig.subplots(1, 3, sharey=True)
lifting = document["friction_above_tan_alpha"]["fragility"]["3-D"]
for ax, key in zip(axes, titles, strict=True):
    for method, colour in (("3-D", "C3"), ("planar, worse of x and y", "C0")):
        fit = document["fragility"][method][key]
        fraction = np.array(fit["counts"]) / np.maximum(fit["totals"], 1)
        ax.plot(levels, fraction, "o", color=colour, ms=4)
        if fit["fitted"]:
            ax.plot(x, norm.cdf(np.log(x / fit["median"]) / fit["beta"]), color=colour,
                    label=f"{method}: {fit['median']:.1f} m/s^2")  # fmt: skip
        else:
            ax.plot([], [], "o", color=colour, label=f"{method}: not fitted")
    fit = lifting[key]
    if fit["fitted"]:
        ax.plot(x, norm.cdf(np.log(x / fit["median"]) / fit["beta"]), "--", color="C3",
                label=f"3-D, mu_0 > R/h: {fit['median']:.1f} m/s^2")  # fmt: skip
    ax.set_title(titles[key])
    ax.set_xlabel("PGA RotD50 [m/s^2]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
axes[0].set_ylabel("probability [-]")
fig.tight_layout()

# %%
# One record, both ways
# ---------------------
# A record generated as the suite's (RG 1.60, three components, 20 s), scaled to a
# PGA RotD50 of 0.8 g, on the cask of the model file (mu_0 = 0.6, just above R/h):
# the 3-D cask, and the planar block under x and under y, each with the vertical.
import freestand as fs

model = fs.load_model("../cask.toml")
suite = fs.generate_suite(
    "rg1.60:pga=0.3g,damping=5%", count=1, duration=20.0, seed=20, horizontal_y=True,
    vertical="rg1.60:pga=0.2g,damping=5%,direction=vertical",
)  # fmt: skip
record = suite.motions[0]
record = record.scaled(0.8 * 9.81 / fs.intensity_measure(record, "pga-rotd50"))
cask = fs.simulate(model, record, configuration="cask", until_rest=True)
print(cask.to_dict()["message"], cask.to_dict()["blocks"][0])
planar = {}
for name, component in (("x", record.horizontal), ("y", record.horizontal_y)):
    motion = fs.GroundMotion(dt=record.dt, horizontal=component, vertical=record.vertical)
    planar[name] = fs.simulate(model, motion, configuration="cask-planar", until_rest=True)
    print(name, planar[name].to_dict()["message"], planar[name].to_dict()["blocks"][0])

# %%
# The 3-D cask lifts, rolls on its rim and slides in every direction (its tilt
# vector, right, winds round: a planar block's would stay on one line), and is still
# moving 10 s after the record; as planar blocks it barely rocks.
history = cask.to_frame("history")
fig_record = Figure(figsize=(11, 3.8))
left, right = fig_record.subplots(1, 2, gridspec_kw={"width_ratios": [2.2, 1]})
left.plot(history["time [s]"], history["cask.tilt [rad]"], color="C3", label="3-D: tilt")
for name, colour in (("x", "C0"), ("y", "C2")):
    rows = planar[name].to_frame("history")
    left.plot(rows["time [s]"], rows["cask.rotation [rad]"].abs(), color=colour,
              label=f"planar under {name}: |rotation|")  # fmt: skip
left.axhline(np.arctan(1.683 / 3.0), color="k", ls=":", label="alpha = atan(R/h)")
left.set_xlabel("time [s]")
left.set_ylabel("tilt, rotation [rad]")
left.set_title("An RG 1.60 record at PGA RotD50 0.8 g, mu_0 = 0.6: 3-D against planar",
               fontsize=10)  # fmt: skip
left.legend(fontsize=8)
left.grid(alpha=0.3)
right.plot(history["cask.tilt_x [rad]"], history["cask.tilt_y [rad]"], color="C3", lw=0.8)
right.set_aspect("equal")
right.set_xlabel("tilt x [rad]")
right.set_ylabel("tilt y [rad]")
right.set_title("3-D tilt vector, seen from above", fontsize=10)
right.grid(alpha=0.3)
fig_record.tight_layout()
