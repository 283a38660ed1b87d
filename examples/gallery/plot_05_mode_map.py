"""
Mode maps and Monte Carlo: where the crane slides, rocks or rests
=================================================================

The screening answers for the excitation levels of the model file. A *mode
map* answers for every excitation at once: the initial motion of each block
over a grid of two parameters (the horizontal and vertical support
accelerations, a friction coefficient, a mass...). A *Monte Carlo sweep*
answers for inputs that are not known exactly: the probability of each
motion when, say, the rail friction lies anywhere between 0.25 and 0.45.
Both solve the screening's contact problem (paper section 3) with a compiled
batch solver, hundreds of thousands of cases a second.
"""

# %%
# The map of the excitation plane
# -------------------------------
# The y-z plane of the crane over the horizontal support acceleration (0 to
# 12 m/s^2) and the vertical one (-3 to 10 m/s^2, positive downward), for
# both senses of the horizontal inertial force. The model's two levels
# (rigid and elastic) are marked where they lie.
import freestand as fs

model = fs.load_model("../crane.toml")
excitation_map = fs.mode_map(
    model, "horizontal=0:12", "vertical=-3:10", configurations="y-z", nodes=300
)
for item in excitation_map.to_dict()["maps"]:
    shares = {region: round(share, 3) for region, share in item["regions"].items()}
    print(f"{item['configuration']}, sense {item['sense']}: {shares}")
fig_excitation = excitation_map.plot()

# %%
# The bridge slides where a_h > mu_0 (g - a_v): a straight boundary through
# a_v = g. Above g downward, the blocks are weightless (free flight).
#
# The map of a friction coefficient
# ---------------------------------
# The x-z plane with the cart at its right end stop, over the horizontal
# acceleration and the static friction of the cart's brakes (the vertical
# acceleration is the elastic level's, 2.35 m/s^2): where does the cart
# slide, where does it rock about its wheels?
friction_map = fs.mode_map(
    model,
    "horizontal=0:12",
    "cart.friction.static=0.1:0.6",
    configurations="x-z cart right",
    excitation="elastic",
    nodes=300,
)
table = friction_map.to_frame()
print(table.groupby(["sense", "region"]).size().rename("nodes").to_string())
fig_friction = friction_map.plot()

# %%
# Monte Carlo: an uncertain rail friction
# ---------------------------------------
# The rail friction of the bridge is not known better than "between 0.25
# and 0.45". At the rigid level (a_h = 2.70, a_v = 2.35 m/s^2) the bridge
# slides where mu_0 < a_h / (g - a_v) = 2.70 / 7.46 = 0.362. 20,000 samples:
sweep = fs.sample(
    model,
    "friction.static=uniform(0.25,0.45)",
    n=20_000,
    seed=1,
    configurations="y-z",
    excitations="rigid",
)
probabilities = sweep.to_frame()
print(
    probabilities[["sense", "block", "motion", "probability [-]", "low [-]", "high [-]"]]
    .round(3)
    .to_string(index=False)
)

# %%
# Every sample is a row of ``samples_frame()``: the inputs drawn and each
# block's motion. The histogram of the friction drawn, by the bridge's
# motion, shows the threshold 0.362:
import numpy as np
from matplotlib.figure import Figure

samples = sweep.samples_frame()
print(samples.columns.tolist())
positive = samples[samples["sense"] == "+"]
friction = [c for c in samples.columns if c.startswith("friction.static")][0]
fig_samples = Figure(figsize=(7.0, 3.6), layout="constrained")
ax = fig_samples.add_subplot()
bins = np.linspace(0.25, 0.45, 41)
for motion, colour in (("slide", "C3"), ("rest", "C0")):
    chosen = positive[positive["bridge.motion"] == motion][friction]
    ax.hist(chosen, bins=bins, color=colour, alpha=0.7, label=f"bridge {motion}s ({len(chosen)})")
ax.axvline(2.70 / (9.81 - 2.35), color="k", linestyle="--", label="a_h / (g - a_v) = 0.362")
ax.set_xlabel(f"static friction coefficient of the rails, {friction} [-]")
ax.set_ylabel("samples [-]")
ax.set_title("y-z, rigid level, sense +: 20,000 samples of the rail friction", fontsize=10)
ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.2), ncols=3, frameon=False)

# %%
# Several uncertain inputs
# ------------------------
# The cart at its right end stop rocks about its right wheels, with the
# inertial force towards the stop (sense +), once a_h exceeds
# (g - a_v) b / h = 7.46 x 1.33 / 2.83 = 3.5 m/s^2. Near that threshold
# the answer hangs on what is not known exactly: the cart's centre of
# gravity (a normal error of 5 cm), its mass (within 10 %) and its brakes'
# friction. At a_h = 3.5 m/s^2, the probability of each motion with its
# 95 % Wilson interval:
near = fs.Excitation("near the threshold", horizontal=3.5, vertical=2.35)
uncertain = fs.sample(
    model,
    [
        "cart.centre.x+=normal(0,0.05)",
        "cart.mass*=uniform(0.9,1.1)",
        "cart.friction.static=uniform(0.2,0.3)",
    ],
    n=20_000,
    seed=2,
    configurations="x-z cart right",
    excitations=near,
    sense="+",
)
frame = uncertain.to_frame()
print(
    frame[frame["block"] == "cart"][["motion", "probability [-]", "low [-]", "high [-]"]]
    .round(3)
    .to_string(index=False)
)
