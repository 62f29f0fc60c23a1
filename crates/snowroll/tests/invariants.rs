//! Invariants at scale (issue 7): random physical scenarios, seeded so that
//! every run checks the same cases, for each model family:
//!
//! - circular ODE models (§2): eq. (8) `π r² = π r0² + b x` and `m = π ρ l r²`
//!   at every sample, radius and position never decreasing, every number
//!   finite; for the models that conserve energy (`energy`, eq. (14), and
//!   `snowless`, App. A, whose `W_model` of `docs/snowball-and-losses.md` §3.1
//!   is zero) `T + V` of eqs. (7), (10) equal to its start value; for
//!   `torque-cm` the sample's acceleration equal to eq. (4) evaluated on the
//!   sample's own v and r;
//! - the closed form (fn. 4): eq. (8), monotonicity, finiteness, and eq. (4)
//!   itself at every sample (the closed form must solve it);
//! - turn models (§3.4): across each collision the angular momentum about the
//!   new contact line, computed here from the mass properties (parallel-axis
//!   theorem), is conserved (eq. (89)); the loss is the drop of kinetic
//!   energy and is not negative; turn k rolls the distance `2π r_k` with
//!   `r_k = r0 + k b`; the speed after a collision starts the next turn;
//!   every number finite.
//!
//! Parameters are drawn over the extremes the issue names: b/r0 from 1e-6 to
//! 10 (log-uniform), α from 0.01 to 89.99 degrees, end times up to 1e6 s; a
//! run may also end with an error, but then a clear one (never a panic, never
//! a non-finite number in an `Ok` result). The counts and run time are in
//! `docs/reliability.md`.

use std::cell::Cell;
use std::f64::consts::PI;
use std::time::Instant;

use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use snowroll::physics::{kinetic_energy, potential_energy};
use snowroll::{
    run_turns, ModelKind, Sample, Sampling, Scenario, ScenarioFile, SimError, SimOptions,
    TurnVariant,
};

/// Scenarios per family: the issue asks for at least 10^4.
const CASES: u32 = 10_000;
/// The seed of every family (the runs are reproducible).
const SEED: [u8; 32] = *b"snowroll issue 7 invariants seed";

/// eq. (8) and `m = π ρ l r²` at a sample: both sides are computed from the
/// state in a few roundings each, so 1e-12 relative covers them.
const EQ8_TOL: f64 = 1e-12;
/// `T + V` against its start value, relative to the energy scale of the run
/// (the largest of T, |V| and m0 g r0 seen): DOP853 at rtol 1e-10 commits
/// ~1e-10 per unit time scale, and runs span up to ~10^4 time scales; 1e-6
/// leaves a margin of ten.
const ENERGY_TOL: f64 = 1e-6;
/// eq. (4) at a sample: a and the right-hand side come from the same v, r
/// (torque-cm: the model's own rhs at the dense-output state; Loney: the
/// closed form's v(x) and a(x)), each a few roundings of O(G) terms.
const EQ4_TOL: f64 = 1e-9;
/// Angular momentum and kinetic energy across a collision: the same v,
/// r_k, b multiplied in a different order; 1e-12 relative.
const COLLISION_TOL: f64 = 1e-12;
/// x at the start of turn k+1 minus x at the start of turn k against
/// `2π r_k`: x is a sum of k such terms, each rounded; 1e-12 relative to x.
const ROLL_TOL: f64 = 1e-12;

/// The least fraction of the generated cases that must run to an `Ok`
/// result (not end with an allowed error): below it the invariants were
/// checked on too few runs to mean anything (issue 32, item 6). Measured:
/// 10 000 of 10 000 in each family.
const MIN_RAN: f64 = 0.9;

/// Fails unless at least [`MIN_RAN`] of the [`CASES`] ran without an
/// allowed error.
fn assert_enough_ran(family: &str, ran: u32, errors: u32) {
    assert_eq!(
        ran + errors,
        CASES,
        "{family}: {ran} ran and {errors} errors are not the {CASES} cases"
    );
    assert!(
        f64::from(ran) >= MIN_RAN * f64::from(CASES),
        "{family}: only {ran} of {CASES} cases ran ({errors} ended with an allowed error), fewer than {MIN_RAN} of them"
    );
}

/// A random scenario over the extremes.
fn scenario() -> impl Strategy<Value = Scenario> {
    (
        -3.0..1.0f64,                         // log10 r0, m
        -6.0..1.0f64,                         // log10 b/r0
        0.01..89.99f64,                       // alpha, degrees
        prop_oneof![Just(0.0), 0.0..10.0f64], // v0, m/s
    )
        .prop_map(|(lr0, lratio, alpha, v0)| {
            let r0 = 10f64.powf(lr0);
            Scenario::new(ScenarioFile {
                alpha_deg: alpha,
                snow_depth: r0 * 10f64.powf(lratio),
                r0,
                v0,
                ..ScenarioFile::default()
            })
            .expect("drawn inside every range")
        })
}

/// End time, s: log-uniform from 0.01 s to 1e6 s.
fn t_end() -> impl Strategy<Value = f64> {
    (-2.0..6.0f64).prop_map(|e| 10f64.powf(e))
}

/// Eight log-spaced output times ending at `t_end`, and 0.
fn times(t_end: f64) -> Sampling {
    let mut ts = vec![0.0];
    ts.extend((0..8).map(|i| t_end * 10f64.powf(-3.0 + 3.0 * f64::from(i) / 7.0)));
    ts.dedup_by(|a, b| *a <= *b);
    Sampling::Times(ts)
}

fn runner() -> TestRunner {
    TestRunner::new_with_rng(
        Config {
            cases: CASES,
            failure_persistence: None,
            ..Config::default()
        },
        TestRng::from_seed(RngAlgorithm::ChaCha, &SEED),
    )
}

/// An error a run may end with on extreme parameters: it must be one of the
/// library's clear errors (all of them are), and it is counted. (A run that
/// uses up its step budget is not an error: it stops with `step-limit`.)
fn allowed_error(e: &SimError) -> bool {
    matches!(e, SimError::StepSizeTooSmall { .. } | SimError::Param(_))
}

fn finite(s: &Sample) -> bool {
    [s.t_s, s.x_m, s.v_m_s, s.a_m_s2, s.r_m, s.mass_kg]
        .iter()
        .all(|x| x.is_finite())
}

/// eq. (8), the mass, monotonicity and finiteness of a circular trajectory.
fn check_circular_samples(s: &Scenario, samples: &[Sample]) -> Result<(), TestCaseError> {
    let (r0, b) = (s.initial_radius(), s.snow_depth());
    let rho_l = s.density() * s.length();
    for pair in samples.windows(2) {
        prop_assert!(pair[1].t_s > pair[0].t_s, "time goes back: {:?}", pair);
        prop_assert!(pair[1].x_m >= pair[0].x_m, "x decreases: {:?}", pair);
        prop_assert!(pair[1].r_m >= pair[0].r_m, "r decreases: {:?}", pair);
    }
    for p in samples {
        prop_assert!(finite(p), "non-finite sample {:?}", p);
        let area = PI * r0 * r0 + b * p.x_m;
        prop_assert!(
            (PI * p.r_m * p.r_m - area).abs() <= EQ8_TOL * area,
            "eq. (8): pi r^2 = {} vs {}",
            PI * p.r_m * p.r_m,
            area
        );
        let mass = rho_l * area;
        prop_assert!(
            (p.mass_kg - mass).abs() <= EQ8_TOL * mass,
            "mass {} vs {}",
            p.mass_kg,
            mass
        );
    }
    Ok(())
}

/// Eq. (4): `a = (2/3) G − 7 b v²/(6π r²)`.
fn eq4(s: &Scenario, v: f64, r: f64) -> f64 {
    2.0 / 3.0 * s.g_along() - 7.0 * s.snow_depth() * v * v / (6.0 * PI * r * r)
}

/// The largest magnitude among the energies of the run, J.
fn energy_scale(s: &Scenario, samples: &[Sample]) -> f64 {
    let base = s.initial_mass() * s.gravity() * s.initial_radius();
    samples.iter().fold(base, |m, p| {
        m.max(kinetic_energy(s, p.x_m, p.v_m_s).abs())
            .max(potential_energy(s, p.x_m).abs())
    })
}

#[test]
fn circular_models_keep_eq8_monotone_radius_energy_and_finite_output() {
    let circular: Vec<ModelKind> = ModelKind::ALL
        .into_iter()
        .filter(|k| k.derivation().is_some())
        .collect();
    let started = Instant::now();
    let (ok, errors, samples) = (Cell::new(0u32), Cell::new(0u32), Cell::new(0u64));
    let strategy = (scenario(), t_end(), 0..circular.len());
    runner()
        .run(&strategy, |(s, t_end, which)| {
            let kind = circular[which];
            // `snowless` is the b = 0 limit: its energy balance holds for b = 0.
            let s = if kind == ModelKind::Snowless {
                Scenario::new(ScenarioFile {
                    snow_depth: 0.0,
                    ..ScenarioFile::from(s)
                })
                .unwrap()
            } else {
                s
            };
            let opts = SimOptions {
                t_end,
                sampling: times(t_end),
                ..SimOptions::default()
            };
            let traj = match kind.build().simulate(&s, &opts) {
                Ok(t) => t,
                Err(e) => {
                    prop_assert!(allowed_error(&e), "{kind}: {e}");
                    errors.set(errors.get() + 1);
                    return Ok(());
                }
            };
            ok.set(ok.get() + 1);
            samples.set(samples.get() + traj.samples.len() as u64);
            check_circular_samples(&s, &traj.samples)?;
            prop_assert!(traj.stop.t_s.is_finite() && traj.stop.x_m.is_finite());
            if matches!(kind, ModelKind::Energy | ModelKind::Snowless) {
                let e0 = kinetic_energy(&s, 0.0, s.initial_speed()) + potential_energy(&s, 0.0);
                let scale = energy_scale(&s, &traj.samples);
                for p in &traj.samples {
                    let e = kinetic_energy(&s, p.x_m, p.v_m_s) + potential_energy(&s, p.x_m);
                    prop_assert!(
                        (e - e0).abs() <= ENERGY_TOL * scale,
                        "{kind}: T + V = {e} vs {e0} (scale {scale}) at t = {}",
                        p.t_s
                    );
                }
            }
            if kind == ModelKind::TorqueCm {
                for p in &traj.samples {
                    let want = eq4(&s, p.v_m_s, p.r_m);
                    prop_assert!(
                        (p.a_m_s2 - want).abs() <= EQ4_TOL * s.g_along().max(want.abs()),
                        "eq. (4): a = {} vs {want}",
                        p.a_m_s2
                    );
                }
            }
            Ok(())
        })
        .unwrap();
    eprintln!(
        "circular: {CASES} scenarios ({} ran, {} clear errors, {} samples checked) in {:.1} s",
        ok.get(),
        errors.get(),
        samples.get(),
        started.elapsed().as_secs_f64()
    );
    assert_enough_ran("circular", ok.get(), errors.get());
    // Each run that ran is sampled at 0 and up to eight later times; at
    // least two samples a run on average, or the invariants saw little.
    assert!(
        samples.get() >= 2 * u64::from(ok.get()),
        "only {} samples checked in {} runs",
        samples.get(),
        ok.get()
    );
}

#[test]
fn the_closed_form_solves_eq4_and_keeps_eq8() {
    let started = Instant::now();
    let (ok, errors, samples) = (Cell::new(0u32), Cell::new(0u32), Cell::new(0u64));
    runner()
        .run(&(scenario(), t_end()), |(s, t_end)| {
            let opts = SimOptions {
                t_end,
                sampling: times(t_end),
                ..SimOptions::default()
            };
            let traj = match ModelKind::Loney.build().simulate(&s, &opts) {
                Ok(t) => t,
                Err(e) => {
                    prop_assert!(
                        matches!(
                            e,
                            SimError::Inversion { .. }
                                | SimError::TimeIntegral { .. }
                                | SimError::Param(_)
                        ),
                        "{e}"
                    );
                    errors.set(errors.get() + 1);
                    return Ok(());
                }
            };
            ok.set(ok.get() + 1);
            samples.set(samples.get() + traj.samples.len() as u64);
            check_circular_samples(&s, &traj.samples)?;
            for p in &traj.samples {
                let want = eq4(&s, p.v_m_s, p.r_m);
                prop_assert!(
                    (p.a_m_s2 - want).abs() <= EQ4_TOL * s.g_along().max(want.abs()),
                    "eq. (4): a = {} vs {want} at x = {}",
                    p.a_m_s2,
                    p.x_m
                );
            }
            Ok(())
        })
        .unwrap();
    eprintln!(
        "closed form: {CASES} scenarios ({} ran, {} clear errors, {} samples checked) in {:.1} s",
        ok.get(),
        errors.get(),
        samples.get(),
        started.elapsed().as_secs_f64()
    );
    assert_enough_ran("closed form", ok.get(), errors.get());
    assert!(
        samples.get() >= 2 * u64::from(ok.get()),
        "only {} samples checked in {} runs",
        samples.get(),
        ok.get()
    );
}

#[test]
fn turn_models_conserve_angular_momentum_across_each_collision() {
    let started = Instant::now();
    let (ok, errors, collisions) = (Cell::new(0u32), Cell::new(0u32), Cell::new(0u64));
    let strategy = (scenario(), 1..6u64, prop::bool::ANY, t_end());
    runner()
        .run(&strategy, |(s, turns, exact, t_end)| {
            let kind = if exact {
                ModelKind::TurnsExact
            } else {
                ModelKind::Turns
            };
            let opts = SimOptions {
                t_end,
                turns: Some(turns),
                sampling: Sampling::Ends,
                ..SimOptions::default()
            };
            let table = match run_turns(kind, &s, &opts) {
                Ok(t) => t,
                Err(e) => {
                    prop_assert!(allowed_error(&e), "{kind}: {e}");
                    errors.set(errors.get() + 1);
                    return Ok(());
                }
            };
            ok.set(ok.get() + 1);
            prop_assert!(table.rows.len() as u64 <= turns);
            let (r0, b) = (s.initial_radius(), s.snow_depth());
            let rho_l = s.density() * s.length();
            for (k, row) in table.rows.iter().enumerate() {
                let numbers = [
                    row.t_start_s,
                    row.x_start_m,
                    row.v_start_m_s,
                    row.t_end_s,
                    row.v_end_m_s,
                    row.v_after_m_s,
                    row.collision_loss_j,
                    row.mean_a_turn_m_s2,
                    row.min_a_m_s2,
                    row.max_a_m_s2,
                    row.mean_a_with_collision_m_s2,
                ];
                prop_assert!(numbers.iter().all(|x| x.is_finite()), "{row:?}");
                prop_assert_eq!(row.turn, k as u64);
                prop_assert!(row.t_end_s > row.t_start_s);
                // Radii of turn k (centre to contact) and of the body after
                // its ring is complete, as in §3.4.
                let r_k = r0 + k as f64 * b;
                let r_next = r_k + b;
                let m_next = PI * rho_l * r_next * r_next;
                // Before: the round body of radius r_next turns about the old
                // contact line, at distance r_k from its centre, with ω = v/r_k;
                // I about that line = m r_next²/2 + m r_k² (parallel axes).
                let omega_end = row.v_end_m_s / r_k;
                let i_end = m_next * (r_next * r_next / 2.0 + r_k * r_k);
                // After: it rolls on its rim, I = m r_next²/2 + m r_next².
                let omega_after = row.v_after_m_s / r_next;
                let i_after = 1.5 * m_next * r_next * r_next;
                let (l_end, l_after) = (i_end * omega_end, i_after * omega_after);
                prop_assert!(
                    (l_end - l_after).abs() <= COLLISION_TOL * l_end.abs().max(f64::MIN_POSITIVE),
                    "eq. (89): L {l_end} before, {l_after} after, turn {k}"
                );
                let loss =
                    0.5 * i_end * omega_end * omega_end - 0.5 * i_after * omega_after * omega_after;
                let k_end = 0.5 * i_end * omega_end * omega_end;
                prop_assert!(
                    (row.collision_loss_j - loss).abs()
                        <= COLLISION_TOL * k_end.max(f64::MIN_POSITIVE),
                    "loss {} vs {loss}",
                    row.collision_loss_j
                );
                prop_assert!(
                    row.collision_loss_j >= 0.0,
                    "a collision created energy: {row:?}"
                );
                collisions.set(collisions.get() + 1);
                if let Some(next) = table.rows.get(k + 1) {
                    let rolled = next.x_start_m - row.x_start_m;
                    prop_assert!(
                        (rolled - 2.0 * PI * r_k).abs() <= ROLL_TOL * next.x_start_m,
                        "turn {k} rolled {rolled}, not 2 pi r_k = {}",
                        2.0 * PI * r_k
                    );
                    prop_assert!(
                        (next.v_start_m_s - row.v_after_m_s).abs()
                            <= COLLISION_TOL * row.v_after_m_s,
                        "speed jumps between turns"
                    );
                    prop_assert!(next.t_start_s >= row.t_end_s);
                }
            }
            let last_rolled = table
                .rows
                .last()
                .map_or(0.0, |r| r.x_start_m + 2.0 * PI * (r0 + r.turn as f64 * b));
            prop_assert!(table.stop.x_m.is_finite() && table.stop.t_s.is_finite());
            prop_assert!(table.stop.x_m + ROLL_TOL * last_rolled >= last_rolled);
            Ok(())
        })
        .unwrap();
    eprintln!(
        "turns: {CASES} scenarios ({} ran, {} clear errors, {} collisions) in {:.1} s",
        ok.get(),
        errors.get(),
        collisions.get(),
        started.elapsed().as_secs_f64()
    );
    assert_enough_ran("turns", ok.get(), errors.get());
    // 1 to 5 turns asked a case: at least one collision a case on average
    // (measured: 18 124 in 10 000 cases), or eq. (89) was hardly checked.
    assert!(
        collisions.get() >= u64::from(CASES),
        "only {} collisions checked in {CASES} cases",
        collisions.get()
    );
}

#[test]
fn variants_are_known() {
    // The families above cover every model: circular ones by derivation,
    // the closed form, and both turn variants.
    for kind in ModelKind::ALL {
        assert!(
            kind.derivation().is_some()
                || TurnVariant::of(kind).is_some()
                || kind == ModelKind::Loney,
            "{kind} is in no family"
        );
    }
}
