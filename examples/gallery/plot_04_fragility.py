"""
A fragility campaign: the crane's cart at its end stop
======================================================

How likely is the crane's cart, parked at the right end of the bridge
against its end stop, to lift off its wheels, slide or overturn, as the
shaking grows? A fragility campaign runs the time history over a suite of
records scaled to a series of peak ground accelerations (multiple-stripe
analysis), over samples of an uncertain input (the friction of the cart's
brakes), and fits a lognormal curve P(x) = Phi(ln(x / theta) / beta) to
each outcome by maximum likelihood on the counts (Baker 2015).

Kept small so that it runs in seconds: 8 records of 10 s, 12 levels, both
polarities of every record and 3 friction samples each, 576 simulations.
A campaign for a decision wants 30 records or more.
"""

# %%
# The records
# -----------
# Spectrum-compatible records generated for the site's design spectra (see
# the record suite example): horizontal RG 1.60 at 0.3 g, vertical at 0.2 g.
import freestand as fs

suite = fs.generate_suite(
    "rg1.60:pga=0.3g,damping=5%",
    count=8,
    duration=10.0,
    seed=7,
    vertical="rg1.60:pga=0.2g,damping=5%,direction=vertical",
)
print(suite.status, "|", len(suite.motions), "records")

# %%
# The campaign
# ------------
# The x-z configuration with the cart at its right end stop; the cart's
# static friction coefficient (its brakes) is uncertain, uniform between
# 0.2 and 0.3. The outcomes are the default ones of the configuration: each
# block overturning or lifting off, the cart in free flight (off its rails)
# and sliding more than 1 cm. ``store=`` keeps every simulation (Parquet),
# so that a stopped campaign resumes and other outcomes can be fitted later.
import tempfile
from pathlib import Path

model = fs.load_model("../crane.toml")
store = Path(tempfile.mkdtemp()) / "crane-store"
campaign = fs.fragility(
    model,
    suite.motions,
    im="pga",
    levels="1:12:12",
    configuration="x-z cart right",
    vary=["cart.friction.static=uniform(0.2,0.3)"],
    samples=3,
    both_polarities=True,
    bootstrap=300,
    store=store,
)
print(
    f"{campaign.core.simulations} simulations, {campaign.core.failed} left out:",
    campaign.core.statuses,
)

# %%
# A few simulations fail: the cart, rocking on one wheel, is driven into its
# end stop, where the rigid impact problem has no consistent answer (see
# the time-history guide). They are counted apart and left out of the fits.
#
# The fits, one row per outcome (``to_frame("fits")``): the median theta and
# beta with their bootstrap intervals, and the HCLPF (the intensity at which,
# with 95 % confidence, the probability is at most 5 %). An outcome that
# never occurred, or whose stripes jump from none to all, is not fitted and
# says why:
fits = campaign.to_frame("fits")
print(
    fits[["outcome", "occurrences", "median [m/s^2]", "beta [-]", "hclpf [m/s^2]"]]
    .round(3)
    .to_string(index=False)
)
for row in fits[~fits["fitted"]].itertuples():
    print(f"{row.outcome}: {row.reason}")

# %%
# The stripes, one row per outcome and level (``to_frame()``): counts,
# fractions with their Wilson intervals and the fitted curve at the level.
stripes = campaign.to_frame()
print(stripes[stripes["outcome"] == "cart uplifts"].round(3).to_string(index=False))

# %%
# The curves
# ----------
# One panel per outcome that occurred; the outcomes that never occurred are
# named in the note under the panels.
fig_curves = campaign.plot()

# %%
# Another outcome, from the store
# -------------------------------
# The store holds every simulation's peaks: the fit of another outcome
# needs no new simulation. Here the cart rocking past half its slenderness
# angle alpha, and sliding more than 5 cm:
again = fs.fragility_from_store(store, outcomes=["rotation:cart>0.5alpha", "slide:cart>0.05m"])
print(
    again.to_frame("fits")[["outcome", "occurrences", "median [m/s^2]", "beta [-]"]]
    .round(3)
    .to_string(index=False)
)
fig_from_store = again.plot()
