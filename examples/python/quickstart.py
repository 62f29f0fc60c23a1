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

# %% Every model. The circular ones (§2) are smooth: their a/(g sin alpha)
# against time, sampled every 10 ms, tends to the late-time fraction that
# models() lists. The turn models (§3) jump at each turn's end (the collision,
# eq. (89)), so for them the mean over each turn, collision included, is
# plotted (snowroll.turns, one row per turn) beside the note's 4/9, eq. (79).
fig, (ax, ax_turns) = plt.subplots(1, 2, figsize=(12, 5), sharey=True)
for m in snowroll.models():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # validity notes
        if m["id"].startswith("turns"):
            t = snowroll.turns(m["id"], turns=300, **{k: v for k, v in scenario.items() if k != "t_end"})
            ax_turns.plot(t.t_end_s, t.mean_a_with_collision_m_s2 / g_along,
                          label=f"{m['id']} ({m['equation']})", lw=1.2)
            last = t.summary["checkpoints"][-1]
            print(f"{m['id']:>20}: mean a/(g sin alpha) over {t.summary['turns']} turns "
                  f"{last['mean_a_with_collision_over_g']:.4f} (note, eq. (79): 4/9 = 0.4444)")
            continue
        r = snowroll.simulate(m["id"], dt=0.01, **scenario)
    ax.plot(r.t_s, r.a_m_s2 / g_along, label=f"{m['id']} ({m['equation']})", lw=1.2)
    frac = m["terminal_fraction"]
    print(f"{m['id']:>20}: a/(g sin alpha) at t = {r.t_s[-1]:g} s is "
          f"{r.a_m_s2[-1] / g_along:.4f}; late-time limit "
          f"{'n/a' if frac is None else format(frac, '.4f')}")

for a in (ax, ax_turns):
    a.axhline(4 / 9, color="k", ls=":", lw=1, label="4/9, the note's eq. (79)")
    a.set_xlabel("t (s)")
    a.legend(fontsize=7, loc="upper right")
ax.set_ylabel("a / (g sin alpha)")
ax.set_ylim(0, 0.75)
ax.set_title("circular models (§2): a(t)")
ax_turns.set_title("turn models (§3): mean a over each turn, with its collision")
fig.suptitle("snowroll: alpha = 30 deg, b = 1 cm, r0 = 10 cm")
fig.tight_layout()
out = sys.argv[1] if len(sys.argv) > 1 else "quickstart.png"
fig.savefig(out, dpi=120)
print(f"wrote {out}")
