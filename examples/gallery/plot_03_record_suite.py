"""
A record suite from a design spectrum, with its acceptance checks
=================================================================

Time histories for a site are rarely at hand; a design spectrum is. This
example generates a suite of spectrum-compatible records with two
horizontal components and a vertical one, checks them as US NRC SRP 3.7.1
asks (each spectrum within 0.9-1.3 times its target, the suite mean not
below it, the peak at the zero-period acceleration, components
statistically independent), and filters one record through a building's
mode to get the motion of the floor the equipment stands on.
"""

# %%
# Generating the suite
# --------------------
# The targets are the US NRC RG 1.60 shapes anchored at 0.3 g, horizontal
# and vertical, 5 % damping. Eight records of 15 s with the seed 3: the same
# seed gives the same records. Each seed is a stochastic ground motion
# (Rezaeian and Der Kiureghian 2010) matched to its target by wavelets
# (Montejo and Suarez 2013) and baseline corrected.
import freestand as fs

horizontal = "rg1.60:pga=0.3g,damping=5%"
vertical = "rg1.60:pga=0.3g,damping=5%,direction=vertical"
suite = fs.generate_suite(
    horizontal, count=8, duration=15.0, seed=3, horizontal_y=True, vertical=vertical
)
print(suite.status, "|", len(suite.motions), "records with", suite.motions[0].components)

# %%
# The acceptance checks
# ---------------------
# One row per record and component (``to_frame()``). The ratios are those
# of the record's spectrum to its target at 100 frequencies per decade
# between 0.2 and 50 Hz:
checks = suite.to_frame()
print(
    checks.groupby("component")
    .agg(
        lowest_ratio=("min_ratio [-]", "min"),
        highest_ratio=("max_ratio [-]", "max"),
        largest_peak_ratio=("peak_ratio [-]", "max"),
        shortest_duration_5_75=("duration_5_75 [s]", "min"),
        all_passed=("passed", "all"),
    )
    .round(3)
    .to_string()
)

# %%
# The suite's mean spectrum must not fall below the target anywhere; the
# lowest ratio of the mean to the target, per component:
print({component: round(ratio, 3) for component, ratio in checks.attrs["mean_ratio_min"].items()})

# %%
# and the components of each record must be statistically independent: the
# largest absolute correlation coefficient between two components of a
# record, against the limit 0.3:
independence = suite.independence()
print(
    f"largest {independence['max']:.3f} (limit {independence['limit']}), "
    f"passed: {independence['passed']}"
)

# %%
# The spectra of every record (grey), their mean (red) and the target with
# its band, one column per component; below, each record's ratio to the
# target:
fig_suite = suite.plot()

# %%
# Writing the suite
# -----------------
# ``output=`` (or :meth:`~freestand.GeneratedSuite.write`) writes the
# records, a suite file that ``fs.load_suite`` and ``freestand fragility
# --suite`` read, and ``acceptance.json`` (the document above):
import tempfile
from pathlib import Path

folder = Path(tempfile.mkdtemp()) / "suite"
written = suite.write(folder)
print(sorted(path.name for path in folder.iterdir())[:5], "...")
loaded = fs.load_suite(written.suite_file)
print(f"{loaded.name}: {len(loaded.motions)} records, components {loaded.motions[0].components}")

# %%
# Spectra of any records
# ----------------------
# :func:`freestand.response_spectrum` computes the pseudo-acceleration
# spectra of any records (files or motions) against targets, by the exact
# Nigam-Jennings recursion: here the first three generated records. The
# table has one row per record, component and frequency (0.1 to 100 Hz);
# the acceptance band is 0.2 to 50 Hz:
spectra = fs.response_spectrum(suite.motions[:3], target=horizontal, vertical_target=vertical)
table = spectra.to_frame()
band = table[table["frequency [Hz]"].between(0.2, 50.0)]
print(band.groupby(["record", "component"])["ratio [-]"].agg(["min", "max"]).round(3).to_string())

# %%
# The floor of a building
# -----------------------
# Equipment inside a building feels the building's response, not the
# ground's. :func:`freestand.floor_motion` filters a record through the
# structure's dominant mode (2.5 Hz, 5 % damping): the floor motion is
# narrow-band and amplified.
floor = fs.floor_motion(suite.motions[0], frequency=2.5, damping=0.05)
print(
    f"ground peak {floor.to_dict()['ground_peak']:.2f} m/s^2, "
    f"floor peak {floor.to_dict()['floor_peak']:.2f} m/s^2, "
    f"amplification {floor.to_dict()['amplification']:.2f}"
)
fig_floor = floor.plot()
