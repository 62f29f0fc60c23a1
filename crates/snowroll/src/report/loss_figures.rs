//! The report's figures of the losses of fn. 5 (issue 11,
//! `docs/snowball-and-losses.md` §2–§3): where the released energy goes in a
//! run with all three losses, as shares of it, against time. They only read
//! trajectories and their energy ledgers.

use super::{Figure, Lab, ReportError};
use crate::losses::Losses;
use crate::models::ModelKind;
use crate::plot::{Axis, Chart, Legend, Marker, Series, Style};
use crate::scenario::ScenarioFile;
use crate::trajectory::{LedgerRow, Sampling, SimOptions};

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
        name: "snow pick-up (W_model of eq. (4))",
        of: |l| l.model_j,
        style: Style::Dashed,
        marker: Some(Marker::Triangle),
    },
];

/// Legend entry of the sum of the shares.
pub(super) const SUM_NAME: &str = "sum of the shares";

fn log_grid(first: f64, last: f64, n: usize) -> Vec<f64> {
    let (a, b) = (first.ln(), last.ln());
    let mut times: Vec<f64> = (0..n)
        .map(|i| (a + (b - a) * i as f64 / (n - 1) as f64).exp())
        .collect();
    // exp(ln t_end) may round above t_end, past the end of the run: pin it.
    if let Some(t) = times.last_mut() {
        *t = last;
    }
    times
}

/// The ledger of eq. (4) with drag, rolling resistance and compaction, as
/// shares of the released energy against time (§3.3).
///
/// # Errors
/// [`ReportError`] when the run fails.
pub(super) fn ledger_shares_figure(lab: &Lab) -> Result<Figure, ReportError> {
    let s = lab.scenario();
    let kind = ModelKind::TorqueCm;
    let opts = SimOptions {
        t_end: LEDGER_T_END,
        sampling: Sampling::Times(log_grid(LEDGER_T_FIRST, LEDGER_T_END, LEDGER_POINTS)),
        losses: all_losses(),
        ..SimOptions::default()
    };
    let traj = lab.run(kind, s, &opts)?;
    // From rest K(0) = 0, so the ledger reads K + ΣD + W_model = released
    // (+ the residual); the shares are each term over the released energy.
    let rows: Vec<(f64, &LedgerRow)> = traj
        .samples
        .iter()
        .zip(&traj.ledger)
        .filter(|(_, l)| l.released_j > 0.0)
        .map(|(p, l)| (p.t_s, l))
        .collect();
    let share = |f: &dyn Fn(&LedgerRow) -> f64| -> Vec<(f64, f64)> {
        rows.iter()
            .map(|(t, l)| (*t, f(l) / l.released_j))
            .collect()
    };
    let mut chart = Chart::new(
        "losses-ledger-shares",
        "Where the released energy goes: the log of eq. (4) with all three losses",
        Axis::log("time t", "s").column("t_s"),
        Axis::linear("share of the potential energy released", "1").column("share"),
    )
    .with_legend(Legend::UpperLeft);
    for term in &TERMS {
        let mut series = Series::new(term.name, share(&term.of)).style(term.style);
        if let Some(m) = term.marker {
            series = series.marker(m);
        }
        chart = chart.with_series(series);
    }
    chart = chart.with_series(
        Series::new(
            SUM_NAME,
            share(&|l| TERMS.iter().map(|term| (term.of)(l)).sum()),
        )
        .style(Style::Markers)
        .marker(Marker::Circle),
    );
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
        "The energy ledger of the log of eq. (4) from rest on the default slope with air drag (C_d = {DRAG_COEFFICIENT}, a bluff cylinder), rolling resistance (c_rr = {ROLLING_RESISTANCE}, soft snow) and compaction (e_c = {COMPACTION_ENERGY} J/kg), each term as a share of the potential energy released so far (docs/snowball-and-losses.md §3.3). \
         The losses were picked so that each one takes more than a few per cent at some time: compaction costs e_c per kilogram picked up while the energy released per kilogram grows like x, so it dominates at first ({:.0} % at {LEDGER_T_FIRST} s) and fades; rolling resistance takes a steady c_rr cot α ≈ {:.1} %; drag grows with v² ({:.1} % at {LEDGER_T_END} s); eq. (4)'s own W_model is the snow's inelastic pick-up (≈ Ṁ v², {:.0} % at the end), negative at first because eq. (4) does not pay for lifting the snow onto the log. \
         The shares add up to 1 at every time (circles): the balance made visible; their largest departure from 1 is {}, the ledger's residual. \
         The run stops at {LEDGER_T_END} s, where the log has rolled x = {:.0} m and grown to r = {:.2} m: still a log on a hill.",
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
        .supports(&["energy-ledger-balances"]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::Scenario;

    fn series<'a>(chart: &'a Chart, name: &str) -> &'a Series {
        chart
            .series
            .iter()
            .find(|s| s.name == name)
            .expect("the figure draws every term")
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
