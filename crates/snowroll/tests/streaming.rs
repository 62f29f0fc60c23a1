//! `Model::simulate_into` (issue 7, items 2 and 3): samples go to a sink as
//! they are computed, the same samples as `simulate`; limits end a run
//! early without an error, keeping what was computed; a failing sink stops
//! the run at once.

use std::io;

use snowroll::integrate::Tolerances;
use snowroll::{
    Collected, ModelKind, ParamError, Sample, SampleSink, Sampling, Scenario, SimError, SimOptions,
    SinkError, StopReason, TurnState,
};

/// Every model, with options that give it a few hundred samples.
fn opts_for(kind: ModelKind) -> SimOptions {
    SimOptions {
        t_end: 20.0,
        turns: (!kind.is_circular()).then_some(5),
        ..SimOptions::default()
    }
}

#[test]
fn simulate_into_sends_exactly_the_samples_of_simulate() {
    let s = Scenario::default();
    for kind in ModelKind::ALL {
        let model = kind.build();
        for sampling in [
            Sampling::Steps,
            Sampling::Every(0.5),
            Sampling::Times(vec![0.0, 1.0, 2.5, 7.0]),
            Sampling::Ends,
        ] {
            let opts = SimOptions {
                sampling,
                ..opts_for(kind)
            };
            let traj = model.simulate(&s, &opts).unwrap();
            let mut sink = Collected::default();
            let end = model.simulate_into(&s, &opts, &mut sink).unwrap();
            // Same path, so the same numbers to the bit (PartialEq on f64 fields).
            assert_eq!(sink.samples, traj.samples, "{kind}");
            assert_eq!(sink.turn_states, traj.turn_states, "{kind}");
            assert_eq!(end.stop, traj.stop, "{kind}");
        }
    }
}

#[test]
fn regression_7_step_limit_keeps_the_rows_and_is_a_stop_reason() {
    let s = Scenario::default();
    for kind in [ModelKind::TorqueCm, ModelKind::Turns] {
        let opts = SimOptions {
            t_end: 1e9,
            tolerances: Tolerances {
                max_steps: 20,
                ..Tolerances::default()
            },
            ..SimOptions::default()
        };
        let traj = kind.build().simulate(&s, &opts).unwrap();
        assert_eq!(traj.stop.reason, StopReason::StepLimit, "{kind}");
        // Every accepted step is a row, plus the start; rejected steps and
        // events count towards the budget too, so at most 21 rows. (The
        // budget was 200 steps; eq. (4)'s Taylor steps reach t = 1e9 s in
        // fewer.)
        assert!(
            traj.samples.len() > 10 && traj.samples.len() <= 21,
            "{kind}"
        );
        let last = traj.samples.last().unwrap();
        // The stop is the state of the last row, the same number.
        assert_eq!(last.t_s.to_bits(), traj.stop.t_s.to_bits(), "{kind}");
        assert!(traj.stop.t_s < 1e9);
    }
}

#[test]
fn row_limit_stops_a_step_sampled_run_with_its_rows() {
    let s = Scenario::default();
    for kind in [ModelKind::Energy, ModelKind::Loney, ModelKind::TurnsExact] {
        // (17 rows before eq. (14)'s Taylor steps: it now takes fewer to 20 s.)
        let opts = SimOptions {
            max_rows: 7,
            ..opts_for(kind)
        };
        let traj = kind.build().simulate(&s, &opts).unwrap();
        assert_eq!(traj.stop.reason, StopReason::RowLimit, "{kind}");
        assert_eq!(traj.samples.len(), 7, "{kind}");
        let last = traj.samples.last().unwrap();
        assert_eq!(last.t_s.to_bits(), traj.stop.t_s.to_bits(), "{kind}");
    }
}

#[test]
fn a_run_that_ends_exactly_at_the_row_limit_keeps_its_own_stop() {
    let s = Scenario::default();
    let kind = ModelKind::TorqueCm;
    let rows = kind
        .build()
        .simulate(&s, &SimOptions::default())
        .unwrap()
        .samples
        .len();
    let opts = SimOptions {
        max_rows: rows as u64,
        ..SimOptions::default()
    };
    let traj = kind.build().simulate(&s, &opts).unwrap();
    assert_eq!(traj.stop.reason, StopReason::EndTime);
    assert_eq!(traj.samples.len(), rows);
}

#[test]
fn a_known_row_count_over_the_limit_is_refused_before_the_run() {
    let s = Scenario::default();
    let cases = [
        (Sampling::Every(1e-300), 1e302),
        (Sampling::Every(1e-6), 1e8 + 1.0),
        (Sampling::Times((1..=11).map(f64::from).collect()), 11.0),
    ];
    for (sampling, rows) in cases {
        let opts = SimOptions {
            sampling,
            max_rows: 10,
            ..SimOptions::default()
        };
        let err = ModelKind::TorqueCm.build().simulate(&s, &opts).unwrap_err();
        match err {
            SimError::Param(ParamError::TooManyRows { rows: r, max_rows }) => {
                // t_end/dt + 1 = 100/1e-6 + 1 is exact in f64 (< 2^53).
                approx::assert_relative_eq!(r, rows, max_relative = 1e-15);
                assert_eq!(max_rows, 10);
            }
            other => panic!("expected TooManyRows, got {other:?}"),
        }
    }
}

/// A turn count ends a turn model's run at a time not known in advance, so
/// the grid count up to a far t_end is only an upper bound on its rows
/// (`SimOptions::known_rows`): the run is not refused. It records the grid
/// points up to its stop, ⌊t_stop/dt⌋ + 1 of them; and where the turns would
/// need more than max_rows, it stops there with its rows.
#[test]
fn a_turn_count_lets_a_far_grid_run_start_and_the_row_limit_still_holds() {
    let s = Scenario::default();
    let dt = 0.01;
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        let opts = SimOptions {
            t_end: 1e9,
            turns: Some(3),
            sampling: Sampling::Every(dt),
            max_rows: 1000,
            ..SimOptions::default()
        };
        // 1e11 + 1 grid points up to t_end: refused without the turn count.
        let unbounded = SimOptions {
            turns: None,
            ..opts.clone()
        };
        assert!(matches!(
            unbounded.validate(),
            Err(ParamError::TooManyRows { .. })
        ));
        assert_eq!(opts.known_rows(), None);
        let traj = kind.build().simulate(&s, &opts).unwrap();
        assert_eq!(traj.stop.reason, StopReason::Turns, "{kind}");
        // Three turns of a log from rest take about a second: far from
        // t_end, well within max_rows.
        let expected = (traj.stop.t_s / dt).floor() as usize + 1;
        assert_eq!(traj.samples.len(), expected, "{kind}");
        for (i, p) in traj.samples.iter().enumerate() {
            // Grid points are the f64 nearest the decimals i·dt; i·dt in
            // floating point is within a few ulps (1e-15 s at t ~ 1 s) of
            // them, so 1e-12 s only catches a skipped or repeated point.
            assert!(
                (p.t_s - i as f64 * dt).abs() <= 1e-12,
                "{kind} {i}: {}",
                p.t_s
            );
        }
        // Fifty turns on the same grid need more than 40 rows: the run is
        // cut there, rows kept.
        let cut = SimOptions {
            turns: Some(50),
            max_rows: 40,
            ..opts
        };
        let traj = kind.build().simulate(&s, &cut).unwrap();
        assert_eq!(traj.stop.reason, StopReason::RowLimit, "{kind}");
        assert_eq!(traj.samples.len(), 40, "{kind}");
    }
}

/// An end distance, like a turn count, ends a run at a time not known in
/// advance: a grid up to a far t_end is not refused, and the run records
/// the grid points up to where it reaches x_end.
#[test]
fn an_end_distance_lets_a_far_grid_run_start() {
    let s = Scenario::default();
    let dt = 0.01;
    let opts = SimOptions {
        t_end: 1e9,
        x_end: Some(10.0),
        sampling: Sampling::Every(dt),
        max_rows: 1000,
        ..SimOptions::default()
    };
    assert_eq!(opts.known_rows(), None);
    let traj = ModelKind::TorqueCm.build().simulate(&s, &opts).unwrap();
    assert_eq!(traj.stop.reason, StopReason::Distance);
    assert_eq!(
        traj.samples.len(),
        (traj.stop.t_s / dt).floor() as usize + 1
    );
}

/// Accepts `ok` samples, then fails.
struct Failing {
    ok: usize,
    seen: usize,
}

impl SampleSink for Failing {
    fn sample(&mut self, _: &Sample, _: Option<&TurnState>) -> Result<(), SinkError> {
        if self.seen == self.ok {
            return Err(SinkError::new(io::Error::new(
                io::ErrorKind::BrokenPipe,
                "writing the output failed",
            )));
        }
        self.seen += 1;
        Ok(())
    }
}

#[test]
fn a_failing_sink_stops_the_run_at_once_and_is_the_error() {
    let s = Scenario::default();
    for kind in ModelKind::ALL {
        let opts = SimOptions {
            t_end: 1e9,
            turns: (!kind.is_circular()).then_some(1_000_000),
            ..SimOptions::default()
        };
        // The second row fails: `snowless` is one Taylor step (its solution is
        // a polynomial), two rows in all.
        let mut sink = Failing { ok: 1, seen: 0 };
        let err = kind
            .build()
            .simulate_into(&s, &opts, &mut sink)
            .unwrap_err();
        assert!(matches!(err, SimError::Sink(_)), "{kind}: {err:?}");
        assert_eq!(sink.seen, 1, "{kind}");
        let source = std::error::Error::source(&err).unwrap();
        assert!(source.to_string().contains("writing the output failed"));
    }
}

#[test]
fn the_online_turn_summary_equals_the_one_from_all_rows() {
    let s = Scenario::default();
    for turns in [1, 7, 10, 123, 2000] {
        let opts = SimOptions {
            turns: Some(turns),
            t_end: 1e9,
            ..SimOptions::default()
        };
        let table = snowroll::run_turns(ModelKind::Turns, &s, &opts).unwrap();
        assert_eq!(table.rows.len() as u64, turns);
        // The same sums in the same order: equal to the bit.
        let from_rows = snowroll::TurnSummary::new(&table.rows, s.g_along());
        assert_eq!(table.summary, from_rows, "{turns} turns");
    }
}

#[test]
fn after_an_early_stop_the_last_window_starts_at_a_tracked_turn_not_past_n_over_10() {
    let s = Scenario::default();
    // t_end cuts the run short of the turns asked for.
    let opts = SimOptions {
        turns: Some(1_000_000),
        t_end: 300.0,
        ..SimOptions::default()
    };
    let table = snowroll::run_turns(ModelKind::Turns, &s, &opts).unwrap();
    assert_eq!(table.stop.reason, StopReason::EndTime);
    let n = table.rows.len();
    let last = table.summary.overall().unwrap();
    assert_eq!(last.turns as usize, n);
    let first = last.window_first_turn as usize;
    assert!(first <= n / 10 && first >= n / 50, "{first} of {n}");
    // The window's statistics are those of rows first..n, recomputed here.
    let rows = &table.rows[first..];
    let g = s.g_along();
    let lo = rows
        .iter()
        .map(|r| r.min_a_m_s2)
        .fold(f64::INFINITY, f64::min);
    let hi = rows
        .iter()
        .map(|r| r.max_a_m_s2)
        .fold(f64::NEG_INFINITY, f64::max);
    approx::assert_relative_eq!(last.window_min_a_over_g, lo / g, max_relative = 1e-15);
    approx::assert_relative_eq!(last.window_max_a_over_g, hi / g, max_relative = 1e-15);
    let dt = rows.last().unwrap().t_end_s - rows[0].t_start_s;
    let gain: f64 = rows.iter().map(|r| r.v_end_m_s - r.v_start_m_s).sum();
    // Summed in a different order from the running sums: rounding of n terms.
    approx::assert_relative_eq!(
        last.window_mean_a_turn_over_g,
        gain / dt / g,
        max_relative = 1e-10
    );
}
