"""Quickstart, notebook style: every model of the note, one scenario, the
acceleration as a fraction of g sin(alpha).

    pip install ./crates/snowroll-py matplotlib
    python examples/python/quickstart.py [OUT.png]

Runs headless (matplotlib's Agg backend) and writes quickstart.png. In a
notebook, drop the `matplotlib.use` line and the figure shows inline.
"""

import math
import sys
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import snowroll  # noqa: E402

# %% The scenario: a 10 cm log on a 30 degree slope under 1 cm of snow.
scenario = dict(alpha_deg=30.0, snow_depth=0.01, r0=0.1, t_end=20.0)
g_along = 9.81 * math.sin(math.radians(scenario["alpha_deg"]))

# %% Every model, sampled every 10 ms (the turn models' collisions show as
# the jumps of a at each turn's end).
fig, ax = plt.subplots(figsize=(9, 5.5))
for m in snowroll.models():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # validity notes
        r = snowroll.simulate(m["id"], dt=0.01, **scenario)
    label = f"{m['id']} ({m['equation']})"
    if r.stop["reason"] != "end-time":
        label += f", stops: {r.stop['reason']}"
    ax.plot(r.t_s, r.a_m_s2 / g_along, label=label, lw=1.2)
    frac = m["terminal_fraction"]
    print(f"{m['id']:>20}: a/(g sin alpha) at t = {r.t_s[-1]:g} s is "
          f"{r.a_m_s2[-1] / g_along:.4f}; late-time limit "
          f"{'n/a' if frac is None else format(frac, '.4f')}")

ax.axhline(4 / 9, color="k", ls=":", lw=1, label="4/9, the note's eq. (79)")
ax.set_xlabel("t (s)")
ax.set_ylabel("a / (g sin alpha)")
ax.set_ylim(0, 0.75)
ax.set_title("snowroll: every model, alpha = 30 deg, b = 1 cm, r0 = 10 cm")
ax.legend(fontsize=7, ncol=2, loc="lower left")
fig.tight_layout()
out = sys.argv[1] if len(sys.argv) > 1 else "quickstart.png"
fig.savefig(out, dpi=120)
print(f"wrote {out}")
