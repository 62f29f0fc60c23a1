//! The report's figures of the losses of fn. 5 (issue 11,
//! `docs/snowball-and-losses.md` §2–§3): where the released energy goes in a
//! run with all three losses, as shares of it, against time. They only read
//! trajectories and their energy ledgers.

use super::{ClaimId, Figure, Lab, ReportError};
use crate::plot::{Axis, Chart, Marker, Series, Style};
use snowroll::losses::{Losses, AIR_DENSITY_DEFAULT};
use snowroll::models::ModelKind;
use snowroll::scenario::{Scenario, ScenarioFile, Shape};
use snowroll::trajectory::{LedgerRow, Sampling, SimOptions};

/// End of the ledger run, s. At 30 s the default log has rolled about 380 m
/// and grown to r ≈ 1.1 m: still a log on a hill. Longer runs leave that
/// picture (100 s: 3.8 km and r ≈ 3.5 m) without showing anything new, since
/// every share has levelled off or is fading by then.
pub(super) const LEDGER_T_END: f64 = 30.0;
/// First time of the ledger figure's logarithmic grid, s: the log has
/// released about 10⁻⁷ of what it releases by [`LEDGER_T_END`], enough for
/// the shares to be ratios of resolved numbers.
const LEDGER_T_FIRST: f64 = 0.05;
/// Points of the logarithmic grid.
const LEDGER_POINTS: usize = 120;

/// Air drag of a bluff cylinder across the flow, C_d.
pub(super) const DRAG_COEFFICIENT: f64 = 1.0;
/// Rolling resistance of a log on soft snow (wheels on snow: 0.02–0.1), c_rr.
pub(super) const ROLLING_RESISTANCE: f64 = 0.05;
/// Work of compacting the snow picked up, J/kg: a stress of order 10 kPa
/// over a strain of order ½ on snow of 400 kg/m³. Below the
/// π r0² (G − c_rr C)/b = 14 J/kg above which the default log would not
/// start from rest (§2.2).
pub(super) const COMPACTION_ENERGY: f64 = 10.0;

/// The three losses of the ledger figure. `terminal_tol` 0: with snow there
/// is no terminal velocity and nothing to stop at.
pub(super) fn all_losses() -> Losses {
    Losses {
        drag_coefficient: DRAG_COEFFICIENT,
        rolling_resistance: ROLLING_RESISTANCE,
        compaction_energy: COMPACTION_ENERGY,
        terminal_tol: 0.0,
        ..Losses::default()
    }
}

/// One term of the ledger drawn as a share of the released energy.
struct Term {
    name: &'static str,
    of: fn(&LedgerRow) -> f64,
    style: Style,
    marker: Option<Marker>,
}

/// The terms of the ledger of a circular model (§3.1), in drawing order;
/// for a circular model the collision and creation terms are zero.
const TERMS: [Term; 5] = [
    Term {
        name: "kinetic energy",
        of: |l| l.kinetic_j,
        style: Style::Line,
        marker: None,
    },
    Term {
        name: "air drag",
        of: |l| l.drag_j,
        style: Style::Dashed,
        marker: None,
    },
    Term {
        name: "rolling resistance",
        of: |l| l.rolling_j,
        style: Style::Dotted,
        marker: Some(Marker::Square),
    },
    Term {
        name: "compaction",
        of: |l| l.compaction_j,
        style: Style::LongDashed,
        marker: None,
    },
    Term {
        name: "snow pick-up (eq. (4))",
        of: |l| l.model_j,
        style: Style::Dashed,
        marker: Some(Marker::Triangle),
    },
];

/// Legend entry of the sum of the shares.
pub(super) const SUM_NAME: &str = "sum of the shares";

/// The ledger of eq. (4) with drag, rolling resistance and compaction, as
/// shares of the released energy against time (§3.3).
///
/// # Errors
/// [`ReportError`] when the run fails.
pub(super) fn ledger_shares_figure(lab: &Lab) -> Result<Figure, ReportError> {
    let kind = ModelKind::TorqueCm;
    let opts = SimOptions {
        t_end: LEDGER_T_END,
        sampling: Sampling::Times(super::log_grid(LEDGER_T_FIRST, LEDGER_T_END, LEDGER_POINTS)),
        losses: all_losses(),
        ..SimOptions::default()
    };
    // The losses are set for the default slope; on a shallower one they
    // may stop the log before the first sample: then the figure shows the
    // default slope, and says so.
    let mut s = lab.scenario();
    let mut traj = lab.run(kind, s, &opts)?;
    let default = Scenario::default();
    let fell_back = traj.samples.len() < 2 && *s != default;
    if fell_back {
        s = &default;
        traj = lab.run(kind, s, &opts)?;
    }
    // From rest K(0) = 0, so the ledger reads K + ΣD + W_model = released
    // (+ the residual); the shares are each term over the released energy.
    let rows: Vec<(f64, &LedgerRow)> = traj
        .samples
        .iter()
        .zip(&traj.ledger)
        .filter(|(_, l)| l.released_j > 0.0)
        .map(|(p, l)| (p.t_s, l))
        .collect();
    let chart = ledger_chart(&rows);
    let at = |t_wanted: f64| rows.iter().find(|(t, _)| *t >= t_wanted).map(|(_, l)| **l);
    let pct = |l: Option<LedgerRow>, f: fn(&LedgerRow) -> f64| {
        l.map_or(f64::NAN, |l| 100.0 * f(&l) / l.released_j)
    };
    let (early, end) = (at(LEDGER_T_FIRST), rows.last().map(|(_, l)| **l));
    let last_sample = traj.samples.last();
    let worst = rows
        .iter()
        .map(|(_, l)| (l.residual_j / l.released_j).abs())
        .fold(0.0, f64::max);
    let file = ScenarioFile::from(*s);
    let caption = format!(
        "{}The energy ledger of the log of eq. (4) from rest on the default slope with air drag (C_d = {DRAG_COEFFICIENT}, a bluff cylinder), rolling resistance (c_rr = {ROLLING_RESISTANCE}, soft snow) and compaction (e_c = {COMPACTION_ENERGY} J/kg), each term as a share of the potential energy released so far (the project's notes on the snowball and the losses §3.3). \
         The losses were picked so that each one takes more than a few per cent at some time: compaction costs e_c per kilogram picked up while the energy released per kilogram grows like x, so it dominates at first ({:.0} % at {LEDGER_T_FIRST} s) and fades; rolling resistance takes a steady c_rr cot α ≈ {:.1} %; drag grows with v² ({:.1} % at {LEDGER_T_END} s); eq. (4)'s own W_model is the snow's inelastic pick-up (≈ Ṁ v², {:.0} % at the end), negative at first because eq. (4) does not pay for lifting the snow onto the log. \
         The shares add up to 1 at every time (circles): the balance made visible; their largest departure from 1 is {}, the ledger's residual. \
         The run stops at {LEDGER_T_END} s, where the log has rolled x = {:.0} m and grown to r = {:.2} m: still a log on a hill.",
        if fell_back {
            "On the report's scenario these losses stop the log at once; the figure shows the default scenario. "
        } else {
            ""
        },
        pct(early, |l| l.compaction_j),
        pct(end, |l| l.rolling_j),
        pct(end, |l| l.drag_j),
        pct(end, |l| l.model_j),
        super::notation::number(worst, 1),
        last_sample.map_or(f64::NAN, |p| p.x_m),
        last_sample.map_or(f64::NAN, |p| p.r_m),
    );
    Ok(Figure::new(chart, &caption)
        .param("model", kind.id())
        .param("alpha_deg", file.alpha_deg)
        .param("snow_depth", file.snow_depth)
        .param("r0", file.r0)
        .param("drag_coefficient", DRAG_COEFFICIENT)
        .param("rolling_resistance", ROLLING_RESISTANCE)
        .param("compaction_energy", COMPACTION_ENERGY)
        .param("rtol", format!("{:e}", opts.tolerances.rtol))
        .supports(&[ClaimId::EnergyLedgerBalances]))
}

/// The chart of the ledger figure: each term of [`TERMS`] and their sum as
/// shares of the released energy, against time; `rows` are (t in s, ledger).
fn ledger_chart(rows: &[(f64, &LedgerRow)]) -> Chart {
    let mut chart = Chart::new(
        "losses-ledger-shares",
        "Where the released energy goes: the log of eq. (4) with all three losses",
        Axis::log("time t", "s").column("t_s"),
        Axis::linear("share of the potential energy released", "1").column("share"),
    );
    for series in ledger_series(rows, false) {
        chart = chart.with_series(series);
    }
    chart
}

/// The terms of the ledger a turn model adds (§3.2): the collisions'
/// losses, and the energy the note's collision creates (drawn negative: it
/// is subtracted in the balance).
const COLLISION_TERMS: [Term; 2] = [
    Term {
        name: "collisions",
        of: |l| l.collision_j,
        style: Style::LongDashed,
        marker: Some(Marker::Circle),
    },
    Term {
        name: "created by the collisions (−)",
        of: |l| -l.created_j,
        style: Style::Dotted,
        marker: Some(Marker::Triangle),
    },
];

/// Each term of [`TERMS`] (and of [`COLLISION_TERMS`] when `collisions`)
/// as a share of the released energy against time, then their sum
/// ([`SUM_NAME`], markers); `rows` are (t in s, ledger).
pub(super) fn ledger_series(rows: &[(f64, &LedgerRow)], collisions: bool) -> Vec<Series> {
    let terms: Vec<&Term> = TERMS
        .iter()
        .chain(COLLISION_TERMS.iter().filter(|_| collisions))
        .collect();
    let share = |f: &dyn Fn(&LedgerRow) -> f64| -> Vec<(f64, f64)> {
        rows.iter()
            .map(|(t, l)| (*t, f(l) / l.released_j))
            .collect()
    };
    let mut out = Vec::with_capacity(terms.len() + 1);
    for term in &terms {
        let mut series = Series::new(term.name, share(&term.of)).style(term.style);
        if let Some(m) = term.marker {
            series = series.marker(m);
        }
        out.push(series);
    }
    out.push(
        Series::new(
            SUM_NAME,
            share(&|l| terms.iter().map(|term| (term.of)(l)).sum()),
        )
        .style(Style::Markers)
        .marker(Marker::Circle),
    );
    out
}

/// End of the speed figure's runs, s (as the other figures against time).
const SPEED_T_END: f64 = 100.0;
/// First time of the speed figure's logarithmic grid, s.
const SPEED_T_FIRST: f64 = 0.1;
/// Points of its grid.
const SPEED_POINTS: usize = 150;
/// The accreting model of the speed figure: torque about the centre,
/// eq. (4), whose ball is the closed form of the TPT letter (§1.4).
const ACCRETING: ModelKind = ModelKind::TorqueCm;
/// The shapes the speed figure shows, side by side: the log and the ball.
const SPEED_SHAPES: [Shape; 2] = [Shape::Cylinder, Shape::Sphere];

/// Drag alone, C_d of a bluff body, no terminal stop (the figure shows the
/// whole approach).
fn drag_only() -> Losses {
    Losses {
        drag_coefficient: DRAG_COEFFICIENT,
        terminal_tol: 0.0,
        ..Losses::default()
    }
}

/// Speed against time with and without drag, one figure per shape of
/// [`SPEED_SHAPES`] (the two panels shown one after the other): the
/// snowless body and the accreting one of eq. (4), with the closed-form
/// terminal velocity of the snowless body with drag.
///
/// # Errors
/// [`ReportError`] when a run fails.
pub(super) fn speed_with_losses_figures(lab: &Lab) -> Result<Vec<Figure>, ReportError> {
    SPEED_SHAPES
        .iter()
        .map(|&shape| speed_with_losses_figure(lab, shape))
        .collect()
}

/// The speed figure of one shape.
fn speed_with_losses_figure(lab: &Lab, shape: Shape) -> Result<Figure, ReportError> {
    let s = Scenario::new(ScenarioFile {
        shape,
        swath_width: None,
        ..ScenarioFile::from(*lab.scenario())
    })
    .map_err(snowroll::error::SimError::from)?;
    let (name, title, body, extra, ratio) = match shape {
        Shape::Cylinder => (
            "losses-speed",
            "Speed with and without air drag: the log",
            "log",
            "",
            "r² against r",
        ),
        Shape::Sphere => (
            "losses-speed-ball",
            "Speed with and without air drag: the snowball",
            "ball",
            " (a uniform ball, I = (2/5) M r², picking up the layer over its diameter; with eq. (4), the closed form of the TPT letter)",
            "r³ against r²",
        ),
    };
    let mut chart = Chart::new(
        name,
        title,
        Axis::log("time t", "s").column("t_s"),
        Axis::log("speed v", "m/s").column("v_m_s"),
    );
    let times = super::log_grid(SPEED_T_FIRST, SPEED_T_END, SPEED_POINTS);
    chart = with_speed_runs(chart, lab, &s, &times)?;
    // §2.2's closed form, v_t² = M G/(½ ρ_a C_d A). Drag alone on a slope
    // always has one; were it missing, the NaN is refused with the figure's
    // data (nothing non-finite is written), not drawn.
    let vt = snowroll::losses::terminal_velocity(&s, &drag_only()).unwrap_or(f64::NAN);
    // In the colour of the run it is the limit of: snowless, with drag.
    let limit_of = chart
        .series
        .iter()
        .position(|c| c.name.starts_with(ModelKind::Snowless.id()) && c.name.ends_with("drag"));
    let mut vt_series = Series::new(
        VT_NAME,
        times.iter().step_by(10).map(|&t| (t, vt)).collect(),
    )
    .style(Style::Markers)
    .marker(Marker::Square);
    if let Some(k) = limit_of {
        vt_series = vt_series.in_colour_of(k);
    }
    chart = chart.with_series(vt_series);
    let file = ScenarioFile::from(s);
    let caption = format!(
        "Speed of the {body}{extra} against time from rest on the default slope: without losses (solid and long-dashed) and with air drag (C_d = {DRAG_COEFFICIENT}, ρ_a = {AIR_DENSITY_DEFAULT} kg/m³; dashed and dotted), snowless and gathering snow by eq. (4) (torque about the centre). \
         Without snow, drag brings the {body} to the closed-form terminal velocity v_t² = M g sin α/(½ ρ_a C_d A) = ({} m/s)² (squares), where drag balances gravity's pull along the slope (the project's notes on the snowball and the losses §2.2). \
         With snow there is no terminal velocity: the mass grows faster than the frontal area ({ratio}), so drag per unit mass fades and the speed keeps growing, more slowly than without drag (v ∝ t^(1/3) once r is past a crossover of a few metres, §2.2). \
         Log-log axes: a constant acceleration is a line of slope 1. The log and the ball are drawn in two figures on the same axes.",
        super::notation::fixed(vt, 2),
    );
    Ok(Figure::new(chart, &caption)
        .param("shape", shape)
        .param("alpha_deg", file.alpha_deg)
        .param("snow_depth", file.snow_depth)
        .param("r0", file.r0)
        .param("drag_coefficient", DRAG_COEFFICIENT)
        .param(
            "rtol",
            format!("{:e}", SimOptions::default().tolerances.rtol),
        )
        .supports(&[ClaimId::SnowlessDragTerminalVelocity]))
}

/// `chart` with the speed of the snowless and of the accreting model on `s`,
/// each without losses and with drag, at `times` (s).
///
/// # Errors
/// [`ReportError`] when a run fails.
fn with_speed_runs(
    mut chart: Chart,
    lab: &Lab,
    s: &Scenario,
    times: &[f64],
) -> Result<Chart, ReportError> {
    for kind in [ModelKind::Snowless, ACCRETING] {
        for (losses, what) in [(Losses::default(), "no losses"), (drag_only(), "drag")] {
            let opts = SimOptions {
                t_end: SPEED_T_END,
                sampling: Sampling::Times(times.to_vec()),
                losses,
                ..SimOptions::default()
            };
            let traj = lab.run(kind, s, &opts)?;
            let style = match (kind == ModelKind::Snowless, losses.any()) {
                (true, false) => Style::Line,
                (true, true) => Style::Dashed,
                (false, false) => Style::LongDashed,
                (false, true) => Style::Dotted,
            };
            let label = format!("{} ({}), {what}", kind.id(), kind.equation());
            chart = chart.with_series(
                Series::from_samples(&label, &traj.samples, |p| p.t_s, |p| p.v_m_s).style(style),
            );
        }
    }
    Ok(chart)
}

/// Legend entry of the closed-form terminal velocity.
const VT_NAME: &str = "snowless with drag: closed-form vₜ";

#[cfg(test)]
mod tests {
    use super::*;
    use snowroll::scenario::Scenario;

    fn series<'a>(chart: &'a Chart, name: &str) -> &'a Series {
        chart
            .series
            .iter()
            .find(|s| s.name == name)
            .expect("the figure draws every term")
    }

    /// The snowless log and ball with drag follow v_t tanh(t/τ),
    /// τ = (1 + k) v_t/G (from rest, §2.2), and each v_t is the closed form
    /// computed here from the scenario; every curve with drag lies below its
    /// lossless twin.
    #[test]
    fn the_speed_figure_shows_the_terminal_velocity_and_drag_slows() {
        let lab = Lab::new(Scenario::default(), 100);
        let figures = speed_with_losses_figures(&lab).unwrap();
        assert_eq!(figures.len(), 2);
        let s = Scenario::default();
        let (r0, rho, l, g) = (s.initial_radius(), s.density(), s.length(), s.g_along());
        // The log: M = π ρ l r0², A = 2 r0 l; 22.664 m/s with the defaults
        // at 30° (§2.2); τ = (1 + 1/2) v_t/G.
        let mass = std::f64::consts::PI * rho * l * r0 * r0;
        let vt_log = (mass * g / (0.5 * 1.2 * DRAG_COEFFICIENT * 2.0 * r0 * l)).sqrt();
        approx::assert_relative_eq!(vt_log, 22.664, max_relative = 1e-4);
        // The ball: M = (4/3) π ρ r0³, A = π r0², so v_t² = (8/3) ρ r0 G/(ρ_a C_d);
        // τ = (1 + 2/5) v_t/G.
        let vt_ball = (8.0 / 3.0 * rho * r0 * g / (1.2 * DRAG_COEFFICIENT)).sqrt();
        for (fig, vt, tau) in [
            (&figures[0], vt_log, 1.5 * vt_log / g),
            (&figures[1], vt_ball, 1.4 * vt_ball / g),
        ] {
            let chart = &fig.chart;
            approx::assert_relative_eq!(
                series(chart, VT_NAME).points[0].1,
                vt,
                max_relative = 1e-12
            );
            let snowless = ModelKind::Snowless;
            let drag = series(chart, &format!("snowless ({}), drag", snowless.equation()));
            for &(t, v) in &drag.points {
                // Tolerance 1e-8: the integration at rtol 1e-10 over ≤ 15 τ.
                approx::assert_relative_eq!(v, vt * (t / tau).tanh(), max_relative = 1e-8);
            }
            for kind in [snowless, ACCRETING] {
                let name = |what| format!("{} ({}), {what}", kind.id(), kind.equation());
                let (free, dragged) = (
                    series(chart, &name("no losses")),
                    series(chart, &name("drag")),
                );
                for (p, q) in free.points.iter().zip(&dragged.points) {
                    assert!(q.1 < p.1, "{}: {}: t = {} s", chart.name, name("drag"), p.0);
                }
            }
        }
    }

    /// The shares drawn sum to 1 at every time, to the ledger's residual;
    /// and each mechanism takes a visible share at some time.
    #[test]
    fn the_shares_sum_to_one_and_each_mechanism_shows() {
        let lab = Lab::new(Scenario::default(), 100);
        let fig = ledger_shares_figure(&lab).unwrap();
        let chart = &fig.chart;
        let terms: Vec<&Series> = TERMS.iter().map(|t| series(chart, t.name)).collect();
        let n = terms[0].points.len();
        assert!(n > LEDGER_POINTS / 2, "{n} points");
        for i in 0..n {
            let t = terms[0].points[i].0;
            let sum: f64 = terms.iter().map(|s| s.points[i].1).sum();
            // Tolerance 1e-8: the ledger's residual relative to the
            // released energy. The works are quadratures integrated at rtol
            // 1e-10 and K, V are exact at each sample (§3.1); on 2700 random
            // scenarios the residual stays below 2e-9 of the ledger's
            // largest term, which here is the released energy.
            assert!((sum - 1.0).abs() < 1e-8, "t = {t} s: shares sum to {sum}");
            // The series drawn as the sum is that sum.
            approx::assert_relative_eq!(
                series(chart, SUM_NAME).points[i].1,
                sum,
                max_relative = 1e-12
            );
        }
        // Each mechanism is visible: above 5 % of the released energy at
        // some time (a few px on the figure's 0–1 axis would not do).
        for s in &terms {
            let top = s.points.iter().map(|p| p.1).fold(f64::MIN, f64::max);
            assert!(top > 0.05, "{}: largest share {top}", s.name);
        }
        // Rolling resistance on a snowless-like balance takes c_rr cot α of
        // the released energy: N ≈ M g cos α, the work c_rr N x against
        // M g sin α x. The accreted snow adds O(b/r) to N; 10 % covers it.
        let rolling = series(chart, "rolling resistance").points.last().unwrap().1;
        let expected = ROLLING_RESISTANCE / 30f64.to_radians().tan();
        approx::assert_relative_eq!(rolling, expected, max_relative = 0.1);
    }
}
