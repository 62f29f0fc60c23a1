//! One row of a sweep: a trajectory's parameters and its summary.

use super::axis::{AxisParam, AXES};
use super::grid::Point;
use crate::models::{run_warnings, warning_codes, CollisionModel, ModelKind};
use crate::params::Settings;
use crate::scenario::{Scenario, ScenarioFile};
use crate::trajectory::{OnHop, Sample, StopReason, Trajectory};

/// One trajectory of a sweep: its grid index, its parameters (every one,
/// swept or not, under the command line's names in snake case) and its
/// summary. Results are empty when the run failed (`error` says why).
///
/// The parameters' columns are the parameter table's: one per sweep axis
/// ([`AxisParam::ALL`], the table's numeric rows with `sweep: true`), in
/// [`SweepRow::params`], named by the row's key; a new axis is a new row of
/// the table and nothing here. A new result (such as the time of a first
/// hop or slip) is one more field here, its column in [`SweepRow::COLUMNS`]
/// and in the serde impls (`row_serde.rs`), and one more line in
/// [`SweepRow::new`].
#[derive(Debug, Clone, PartialEq)]
pub struct SweepRow {
    /// Index of the point in grid order, from 0.
    pub index: u64,
    /// The model.
    pub model: ModelKind,
    /// The value of each axis, in [`AxisParam::ALL`] order (read them with
    /// [`SweepRow::param_value`]); `None` for an optional one that is unset
    /// (`x_end`, `mu`).
    pub params: AxisValues,
    /// What the run does where N reaches 0.
    pub on_hop: OnHop,
    /// The collision law of the turn models.
    pub collision: CollisionModel,
    /// Why the run ended.
    pub stop: Option<StopReason>,
    /// Time at the end of the run, s (t_end, or the time x_end was reached, or of the stall).
    pub t_s: Option<f64>,
    /// Distance rolled at the end, m.
    pub x_m: Option<f64>,
    /// Speed at the end, m/s.
    pub v_m_s: Option<f64>,
    /// Acceleration at the end as a fraction of g sin α (the late-time
    /// value of eq. (35) for a long run of a circular model; instantaneous,
    /// within a turn, for the turn models); empty on a level floor (α = 0).
    pub a_over_g_sin_alpha: Option<f64>,
    /// Full turns completed: for the circular models the angle rolled
    /// without slipping, ∫dx/r = 2π(r − r0)/b with eq. (8), over 2π, which is
    /// `x/(π (r + r0))` (x/(2π r0) without snow); for the turn models the
    /// turn counter of §3.4.
    pub turns: Option<u64>,
    /// Why the run failed; empty when it did not.
    pub error: Option<String>,
    /// The codes of the warnings a single run of this point gets
    /// ([`run_warnings`], what `simulate` prints), `;`-separated; empty when
    /// there is none. They depend on the point only, so a failed run has
    /// them too.
    pub warnings: Option<String>,
}

impl SweepRow {
    /// The column names, in order: `index`, `model`, the axes' keys in
    /// [`AxisParam::ALL`] order, then the choices and the results (a test
    /// checks them against the serialised header).
    pub const COLUMNS: [&'static str; COLUMN_COUNT] = {
        let mut all = [""; COLUMN_COUNT];
        all[0] = "index";
        all[1] = "model";
        let mut k = 0;
        while k < AXES {
            all[2 + k] = AxisParam::ALL[k].key_const();
            k += 1;
        }
        let mut j = 0;
        while j < TAIL.len() {
            all[2 + AXES + j] = TAIL[j];
            j += 1;
        }
        all
    };

    /// The row of `point` with its parameters and no results.
    pub fn parameters(point: &Point) -> SweepRow {
        let settings = Settings {
            scenario: ScenarioFile::from(point.scenario),
            options: point.options.clone(),
            per_turn: false,
        };
        let o = &point.options;
        SweepRow {
            index: point.index,
            model: point.model,
            params: AxisParam::ALL.map(|p| p.get(&settings)),
            on_hop: o.on_hop,
            collision: o.collision,
            stop: None,
            t_s: None,
            x_m: None,
            v_m_s: None,
            a_over_g_sin_alpha: None,
            turns: None,
            error: None,
            warnings: point_warnings(point),
        }
    }

    /// The row of `point` from the run's result.
    pub fn new(point: &Point, run: Result<&Trajectory, String>) -> SweepRow {
        let mut row = Self::parameters(point);
        let traj = match run {
            Ok(traj) => traj,
            Err(e) => {
                row.error = Some(e);
                return row;
            }
        };
        let Some(end) = traj.samples.last() else {
            row.error = Some("the run recorded no sample".to_string());
            return row;
        };
        let turns = match traj.turn_states.last() {
            Some(k) => k.turn,
            None if traj.stop.reason == StopReason::Unwound => unwound_turns(&point.scenario),
            None => circular_turns(end.x_m, end.r_m, point.scenario.initial_radius()),
        };
        row.set_results(point, traj.stop.reason, end, turns);
        row
    }
}

impl SweepRow {
    /// The value of parameter `p` in this row (NaN for an unset `x_end` or `mu`).
    pub fn param(&self, p: AxisParam) -> f64 {
        self.param_value(p).unwrap_or(f64::NAN)
    }

    /// The value of parameter `p` in this row; `None` for an unset `x_end`
    /// or `mu` (an empty cell). The writers of the CSV, Parquet and Python
    /// columns go through this, axis by axis in [`AxisParam::ALL`] order,
    /// which is the columns' order.
    pub fn param_value(&self, p: AxisParam) -> Option<f64> {
        self.params[p.axis_index()]
    }

    /// The numeric results, each with its column's name: empty (`None`)
    /// for a failed run.
    pub fn results(&self) -> [(&'static str, Option<f64>); 4] {
        [
            ("t_s", self.t_s),
            ("x_m", self.x_m),
            ("v_m_s", self.v_m_s),
            ("a_over_g_sin_alpha", self.a_over_g_sin_alpha),
        ]
    }

    /// This row, or, when one of its results is not a finite number, the
    /// row of a failed run whose `error` names it: a sweep never writes
    /// NaN or an infinity (CSV, Parquet, Python alike).
    pub(crate) fn finite_or_error(mut self) -> SweepRow {
        let bad = self
            .results()
            .into_iter()
            .find_map(|(name, v)| v.filter(|x| !x.is_finite()).map(|x| (name, x)));
        if let Some((name, value)) = bad {
            self.error = Some(format!(
                "the run gave {name} = {value}, not a finite number: the scenario is outside \
                 the range this model can compute"
            ));
            (self.stop, self.t_s, self.x_m, self.v_m_s) = (None, None, None, None);
            (self.a_over_g_sin_alpha, self.turns) = (None, None);
        }
        self
    }

    /// Fills in the results from the state at the end of the run.
    pub(crate) fn set_results(
        &mut self,
        point: &Point,
        stop: StopReason,
        end: &Sample,
        turns: u64,
    ) {
        self.stop = Some(stop);
        self.t_s = Some(end.t_s);
        self.x_m = Some(end.x_m);
        self.v_m_s = Some(end.v_m_s);
        // Empty on a level floor (the unwinding roll's α = 0), where there
        // is no g sin α to measure the acceleration by.
        let g_along = point.scenario.g_along();
        self.a_over_g_sin_alpha = (g_along != 0.0).then(|| end.a_m_s2 / g_along);
        self.turns = Some(turns);
    }
}

/// The `warnings` cell of `point`: the codes of [`run_warnings`] for its
/// model, scenario and options, `;`-separated; `None` when there is none.
pub fn point_warnings(point: &Point) -> Option<String> {
    warning_codes(&run_warnings(point.model, &point.scenario, &point.options))
}

/// The value of each sweep axis in a row, in [`AxisParam::ALL`] order.
pub type AxisValues = [Option<f64>; AXES];

/// The columns after the axes', in order.
pub(super) const TAIL: [&str; 10] = [
    "on_hop",
    "collision",
    "stop",
    "t_s",
    "x_m",
    "v_m_s",
    "a_over_g_sin_alpha",
    "turns",
    "error",
    "warnings",
];

/// How many columns a row has: `index`, `model`, the axes, [`TAIL`].
const COLUMN_COUNT: usize = 2 + AXES + TAIL.len();

/// Full turns of a circular log that rolled `x` without slipping and grew
/// from `r0` to `r` (eq. (8)): `⌊x/(π (r + r0))⌋`.
pub(crate) fn circular_turns(x: f64, r: f64, r0: f64) -> u64 {
    let turns = x / (std::f64::consts::PI * (r + r0));
    // Finite and non-negative for any run that produced samples.
    if turns.is_finite() && turns >= 0.0 {
        turns.floor() as u64
    } else {
        0
    }
}

/// Full turns of a roll that unwound to its core: (r0 − r_c)/|b| by
/// eq. (8) (the angle 2π(r − r0)/b over 2π), taken from the scenario rather
/// than from the end's x and r, whose rounding put a whole count a hair
/// below itself (399 turns for 400). A count within 1e-9 of a whole number is
/// that number: the last turn ends within 1e-9 of a turn of the core.
fn unwound_turns(s: &Scenario) -> u64 {
    let (Some(core), b) = (s.core_radius(), s.snow_depth()) else {
        return 0;
    };
    let turns = (s.initial_radius() - core) / b.abs();
    let whole = turns.round();
    if (turns - whole).abs() <= 1e-9 * whole {
        whole as u64
    } else {
        turns.floor() as u64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sweep::Grid;

    fn point() -> Point {
        Grid::new(vec![ModelKind::Energy], vec![])
            .unwrap()
            .point(0)
            .unwrap()
    }

    /// A row whose result is not finite becomes the row of a failed run,
    /// naming the column and the value; a finite row is kept as it is.
    /// Fed a finite value in place of the infinity, the first check fails.
    #[test]
    fn a_non_finite_result_becomes_an_error_row() {
        let point = point();
        let sample = Sample {
            t_s: 0.0,
            x_m: 0.0,
            v_m_s: 0.0,
            a_m_s2: f64::NEG_INFINITY,
            r_m: 0.1,
            mass_kg: 1.0,
            normal_n: 1.0,
            friction_n: 0.0,
            friction_ratio: Some(0.0),
        };
        let mut row = SweepRow::parameters(&point);
        row.set_results(&point, StopReason::DoesNotStart, &sample, 0);
        let failed = row.clone().finite_or_error();
        let error = failed.error.clone().unwrap_or_default();
        assert!(error.contains("a_over_g_sin_alpha = -inf"), "{error}");
        assert!(failed.results().iter().all(|r| r.1.is_none()));
        assert_eq!((failed.stop, failed.turns), (None, None));
        assert_eq!(SweepRow::parameters(&point).params, failed.params);
        let fine = Sample {
            a_m_s2: -1.0,
            ..sample
        };
        let mut row = SweepRow::parameters(&point);
        row.set_results(&point, StopReason::DoesNotStart, &fine, 0);
        assert_eq!(row.clone().finite_or_error(), row);
    }

    /// The names [`SweepRow::results`] gives are columns of the sweep.
    #[test]
    fn result_names_are_columns() {
        for (name, _) in SweepRow::parameters(&point()).results() {
            assert!(SweepRow::COLUMNS.contains(&name), "{name}");
        }
    }
}
