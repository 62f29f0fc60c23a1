//! Sweeps: grid order under parallelism, bit-identical rows for any thread
//! count, chunk size and shard split, and rows that agree with single runs.

use snowroll::sweep::{
    run_chunks, run_point, shard_range, Axis, AxisParam, Grid, Method, SweepRow, Values,
};
use snowroll::{ModelKind, ParamError, Sampling, SimOptions, StopReason};

fn axis(param: AxisParam, text: &str) -> Axis {
    Axis {
        param,
        values: Values::parse(param.key(), text).unwrap(),
    }
}

/// A small grid over every kind of model: circular, closed form, turn.
fn grid() -> Grid {
    Grid::new(
        vec![
            ModelKind::TorqueCm,
            ModelKind::Energy,
            ModelKind::Loney,
            ModelKind::Turns,
        ],
        vec![
            axis(AxisParam::named("alpha_deg"), "5:60:7"),
            axis(AxisParam::named("snow_depth"), "0,0.01,0.05"),
            axis(AxisParam::named("t_end"), "3"),
        ],
    )
    .unwrap()
}

fn collect(
    grid: &Grid,
    threads: usize,
    chunk: usize,
    range: std::ops::Range<u64>,
) -> Vec<SweepRow> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    let mut rows = Vec::new();
    pool.install(|| {
        run_chunks(grid, range, chunk, Method::Auto, |c| {
            rows.extend_from_slice(c);
            Ok::<(), ParamError>(())
        })
    })
    .unwrap();
    rows
}

/// Bit-for-bit comparison: `{:?}` of f64 round-trips, so equal strings are
/// equal bits (and NaN compares equal to itself, unlike `==`).
fn bits(rows: &[SweepRow]) -> String {
    format!("{rows:?}")
}

#[test]
fn rows_come_in_grid_order_identical_for_any_threads_chunks_and_shards() {
    let g = grid();
    let one = collect(&g, 1, 5, 0..g.len());
    assert_eq!(one.len() as u64, g.len());
    for (i, row) in one.iter().enumerate() {
        assert_eq!(row.index, i as u64);
    }
    let two = collect(&g, 2, 7, 0..g.len());
    assert_eq!(bits(&one), bits(&two));
    for shards in [1, 2, 3, 10] {
        let mut joined = Vec::new();
        for k in 0..shards {
            let r = shard_range(g.len(), k, shards).unwrap();
            joined.extend(collect(&g, 2, 3, r));
        }
        assert_eq!(bits(&one), bits(&joined), "{shards} shards");
    }
}

#[test]
fn shards_partition_the_grid() {
    for len in [0u64, 1, 7, 100, u64::MAX] {
        for n in [1u64, 2, 3, 7, 1000] {
            let mut next = 0;
            for k in 0..n {
                let r = shard_range(len, k, n).unwrap();
                assert_eq!(r.start, next);
                // Sizes differ by at most one: floor or ceil of len/n.
                let size = r.end - r.start;
                assert!(size == len / n || size == len / n + 1, "{len} {n} {k}");
                next = r.end;
            }
            assert_eq!(next, len);
        }
    }
    assert!(shard_range(10, 3, 3).is_err());
    assert!(shard_range(10, 0, 0).is_err());
}

/// Each row holds what a single `simulate` of its point gives.
#[test]
fn rows_summarise_single_runs() {
    let g = grid();
    for i in 0..g.len() {
        let row = run_point(&g, i, Method::Ode).unwrap();
        let p = g.point(i).unwrap();
        let opts = SimOptions {
            sampling: Sampling::Steps,
            ..p.options.clone()
        };
        let traj = p.model.build().simulate(&p.scenario, &opts).unwrap();
        let end = traj.samples.last().unwrap();
        assert_eq!(row.stop, Some(traj.stop.reason), "row {i}");
        // The same integration, sampled differently: the end state is the
        // same step sequence, so agreement is to rounding.
        let close = |a: Option<f64>, b: f64| (a.unwrap() - b).abs() <= 1e-12 * b.abs().max(1.0);
        assert!(close(row.t_s, end.t_s), "row {i}");
        assert!(close(row.x_m, end.x_m), "row {i}");
        assert!(close(row.v_m_s, end.v_m_s), "row {i}");
        assert_eq!(row.model, p.model);
        assert!(row.error.is_none());
    }
}

/// Snowless rolling (b = 0): a = (2/3) g sin α (App. A), x = a t²/2, and the
/// turns are x/(2π r0).
#[test]
fn app_a_snowless_rows_match_the_closed_form() {
    let g = Grid::new(
        vec![ModelKind::TorqueCm],
        vec![
            axis(AxisParam::named("alpha_deg"), "10:50:5"),
            axis(AxisParam::named("snow_depth"), "0"),
            axis(AxisParam::named("t_end"), "4"),
        ],
    )
    .unwrap();
    for i in 0..g.len() {
        let row = run_point(&g, i, Method::Ode).unwrap();
        let a = 2.0 / 3.0
            * row.param(AxisParam::named("g"))
            * row.param(AxisParam::named("alpha_deg")).to_radians().sin();
        let x = 0.5 * a * 16.0;
        // DOP853 at rtol 1e-10 on a constant acceleration: exact to rounding.
        assert!((row.x_m.unwrap() - x).abs() < 1e-9 * x, "{row:?}");
        assert!((row.a_over_g_sin_alpha.unwrap() - 2.0 / 3.0).abs() < 1e-12);
        assert_eq!(row.stop, Some(StopReason::EndTime));
        let turns =
            (x / (2.0 * std::f64::consts::PI * row.param(AxisParam::named("r0")))).floor() as u64;
        assert_eq!(row.turns, Some(turns));
    }
}

#[test]
fn columns_are_the_serialised_header() {
    let g = grid();
    let row = run_point(&g, 0, Method::Auto).unwrap();
    let mut w = csv::Writer::from_writer(Vec::new());
    w.serialize(&row).unwrap();
    let text = String::from_utf8(w.into_inner().unwrap()).unwrap();
    assert_eq!(text.lines().next().unwrap(), SweepRow::COLUMNS.join(","));
}

/// The fast path (closed-form v(x), quadrature for t) and the ODE path at
/// rtol 1e-13 agree to 1e-9 relative on every circular model, from rest and
/// moving, to t_end and to x_end, on thin and thick snow. The ODE's own
/// error at rtol 1e-13 is about 1e-12 over these runs; 1e-9 is the issue's
/// requirement.
#[test]
fn fast_path_agrees_with_the_ode_to_1e_9() {
    const AGREE: f64 = 1e-9;
    let models: Vec<ModelKind> = ModelKind::ALL
        .into_iter()
        .filter(|m| m.derivation().is_some() || *m == ModelKind::Loney)
        .collect();
    let g = Grid::new(
        models,
        vec![
            axis(AxisParam::named("alpha_deg"), "3,10,25,45,80"),
            axis(AxisParam::named("snow_depth"), "0,0.001,0.05,0.3"),
            axis(AxisParam::named("v0"), "0,0.01,2"),
            axis(AxisParam::named("t_end"), "0.5,100"),
            axis(AxisParam::named("x_end"), "3,1e9"),
            axis(AxisParam::named("rtol"), "1e-12"),
            axis(AxisParam::named("atol"), "1e-14"),
        ],
    )
    .unwrap();
    let mut fast_rows = 0;
    for i in 0..g.len() {
        let fast = run_point(&g, i, Method::Auto).unwrap();
        let mut p = g.point(i).unwrap();
        p.options.tolerances.rtol = 1e-13;
        p.options.tolerances.atol = 1e-15;
        let traj = p.model.build().simulate(&p.scenario, &p.options).unwrap();
        let end = traj.samples.last().unwrap();
        assert_eq!(fast.stop, Some(traj.stop.reason), "{fast:?}");
        let close = |a: Option<f64>, b: f64| (a.unwrap() - b).abs() <= AGREE * b.abs().max(1e-6);
        assert!(close(fast.t_s, end.t_s), "t: {fast:?} vs {end:?}");
        assert!(close(fast.x_m, end.x_m), "x: {fast:?} vs {end:?}");
        assert!(close(fast.v_m_s, end.v_m_s), "v: {fast:?} vs {end:?}");
        let ode = run_point(&g, i, Method::Ode).unwrap();
        // A row that took the fast path differs from the ODE's somewhere in
        // its last bits (the ODE's Taylor steps often agree with the closed
        // form to the bit in x alone).
        let row_bits =
            |r: &SweepRow| format!("{:?}", (r.t_s, r.x_m, r.v_m_s, r.a_over_g_sin_alpha));
        if row_bits(&fast) != row_bits(&ode) {
            fast_rows += 1;
        }
    }
    // Most rows took the fast path (the others stall or do not start).
    assert!(fast_rows * 2 > g.len(), "{fast_rows} of {}", g.len());
}

/// The series path (eqs. (4), (6), (32) from rest and moving: t beyond the
/// start from a binomial series, from rest with no quadrature at all) on
/// the benchmark's grid of slopes, to t = 100 s and to a distance in the
/// series' range: x, v and t agree with DOP853 at rtol 1e-13 to 1e-12,
/// the ODE's own error over these runs (the two differ by about 2e-15).
#[test]
fn series_path_agrees_with_the_ode_to_1e_12() {
    const AGREE: f64 = 1e-12;
    let g = Grid::new(
        vec![
            ModelKind::TorqueCm,
            ModelKind::TorqueContact,
            ModelKind::QuasiCircular,
        ],
        vec![
            axis(AxisParam::named("alpha_deg"), "29:31:7"),
            axis(AxisParam::named("snow_depth"), "0.01"),
            axis(AxisParam::named("r0"), "0.1"),
            axis(AxisParam::named("v0"), "0,0.5"),
            axis(AxisParam::named("t_end"), "100"),
            axis(AxisParam::named("x_end"), "200,1e9"),
            axis(AxisParam::named("rtol"), "1e-10"),
            axis(AxisParam::named("atol"), "1e-12"),
        ],
    )
    .unwrap();
    for i in 0..g.len() {
        let fast = run_point(&g, i, Method::Auto).unwrap();
        let mut p = g.point(i).unwrap();
        p.options.tolerances.rtol = 1e-13;
        p.options.tolerances.atol = 1e-15;
        let traj = p.model.build().simulate(&p.scenario, &p.options).unwrap();
        let end = traj.samples.last().unwrap();
        assert_eq!(fast.stop, Some(traj.stop.reason), "{fast:?}");
        let close = |a: Option<f64>, b: f64| (a.unwrap() - b).abs() <= AGREE * b.abs();
        assert!(close(fast.t_s, end.t_s), "t: {fast:?} vs {end:?}");
        assert!(close(fast.x_m, end.x_m), "x: {fast:?} vs {end:?}");
        assert!(close(fast.v_m_s, end.v_m_s), "v: {fast:?} vs {end:?}");
    }
}

/// A run that hops (fast start, strong drag: N reaches 0, issue 10) is
/// left to the ODE, which locates the hop: the row says so under either
/// method.
#[test]
fn rows_that_hop_are_not_taken_by_the_fast_path() {
    let g = Grid::new(
        vec![ModelKind::TorqueCm, ModelKind::TorqueContact],
        vec![
            axis(AxisParam::named("v0"), "80,200"),
            axis(AxisParam::named("t_end"), "10"),
        ],
    )
    .unwrap();
    for i in 0..g.len() {
        let auto = run_point(&g, i, Method::Auto).unwrap();
        let ode = run_point(&g, i, Method::Ode).unwrap();
        assert_eq!(auto.stop, Some(StopReason::Hop), "{auto:?}");
        assert_eq!(format!("{auto:?}"), format!("{ode:?}"));
    }
}

/// A roll that unwound to its core turned (r0 − r_c)/|b| times (eq. (8): the
/// angle 2π(r − r0)/b): whole numbers here, which the end's rounded x and r
/// put a hair below themselves (399 for 400) on the cases a tester found.
#[test]
fn an_unwound_roll_counts_its_whole_turns() {
    // (model, snow_depth, r0, core_radius, core_mass, turns)
    let cases = [
        (
            ModelKind::EnergyThin,
            "-1e-4",
            "0.06",
            "0.02",
            "0.001,0.005,0.088",
            400,
        ),
        (
            ModelKind::LagrangianPrinted,
            "-1e-4",
            "0.06",
            "0.03",
            "0.005",
            300,
        ),
        (ModelKind::EnergyThin, "-2e-4", "0.1", "0.01", "0.005", 450),
    ];
    for (model, b, r0, core, mass, want) in cases {
        let g = Grid::new(
            vec![model],
            vec![
                axis(AxisParam::named("alpha_deg"), "0,10"),
                axis(AxisParam::named("snow_depth"), b),
                axis(AxisParam::named("r0"), r0),
                axis(AxisParam::named("core_radius"), core),
                axis(AxisParam::named("core_mass"), mass),
                axis(AxisParam::named("density"), "700"),
                axis(AxisParam::named("length"), "0.1"),
                axis(AxisParam::named("t_end"), "1000"),
            ],
        )
        .unwrap();
        for i in 0..g.len() {
            let row = run_point(&g, i, Method::Auto).unwrap();
            assert_eq!(row.stop, Some(StopReason::Unwound), "{row:?}");
            assert_eq!(row.turns, Some(want), "{model:?} {b} {core} {row:?}");
        }
    }
}
