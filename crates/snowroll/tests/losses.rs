//! The losses of fn. 5 and the energy ledger (issue 11, parts 2 and 3):
//! each mechanism alone against its closed form of
//! `docs/snowball-and-losses.md` §2.2, the terminal velocity of the snowless
//! log with drag, and the ledger of §3.1 on random scenarios of every
//! circular family.

use std::f64::consts::PI;

use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use snowroll::losses::{terminal_time_constant, terminal_velocity};
use snowroll::{
    ChordWord, LedgerRow, Losses, ModelKind, ParamError, Sampling, Scenario, ScenarioFile, Shape,
    SimError, SimOptions, StopReason, SwathWidth, Trajectory,
};

/// Closed forms evaluated along a DOP853 run at rtol 1e-12, atol 1e-14:
/// the global error of x and v stays below ~1e-11 relative over the tens of
/// time constants of these runs; 1e-9 leaves a margin of a hundred.
const CLOSED_FORM_TOL: f64 = 1e-9;
/// The run's tolerances for the closed-form checks.
const TIGHT: (f64, f64) = (1e-12, 1e-14);

fn scenario(f: ScenarioFile) -> Scenario {
    Scenario::new(f).expect("valid scenario")
}

fn run(kind: ModelKind, s: &Scenario, losses: Losses, t_end: f64) -> Trajectory {
    let mut opts = SimOptions {
        t_end,
        losses,
        ..SimOptions::default()
    };
    opts.tolerances.rtol = TIGHT.0;
    opts.tolerances.atol = TIGHT.1;
    kind.build().simulate(s, &opts).expect("run")
}

fn rel(got: f64, want: f64) -> f64 {
    (got - want).abs() / want.abs().max(f64::MIN_POSITIVE)
}

fn drag(cd: f64) -> Losses {
    Losses {
        drag_coefficient: cd,
        terminal_tol: 0.0,
        ..Losses::default()
    }
}

/// §2.2: v(t) = v_t tanh(t/τ + artanh(v0/v_t)) and
/// x(t) = τ v_t ln[cosh(t/τ + c)/cosh c], c = artanh(v0/v_t), for the snowless log with drag.
#[test]
fn snowless_log_with_drag_follows_the_tanh_law() {
    for (alpha, v0, cd) in [(30.0, 0.0, 1.0), (10.0, 3.0, 0.5), (60.0, 1.0, 2.0)] {
        let s = scenario(ScenarioFile {
            alpha_deg: alpha,
            v0,
            ..ScenarioFile::default()
        });
        let l = drag(cd);
        let vt = terminal_velocity(&s, &l).unwrap();
        let tau = terminal_time_constant(&s, &l).unwrap();
        let c = (v0 / vt).atanh();
        let traj = run(ModelKind::Snowless, &s, l, 5.0 * tau);
        let m = s.initial_mass();
        for (p, row) in traj.samples.iter().zip(&traj.ledger) {
            let phase = p.t_s / tau + c;
            let v = vt * phase.tanh();
            // ln(cosh p/cosh c) = ln(1 + 2 sinh((p+c)/2) sinh((p−c)/2)/cosh c), without cancellation.
            let ratio_m1 = 2.0 * ((phase + c) / 2.0).sinh() * ((phase - c) / 2.0).sinh() / c.cosh();
            let x = tau * vt * ratio_m1.ln_1p();
            assert!(rel(p.v_m_s, v) <= CLOSED_FORM_TOL, "v {} vs {v}", p.v_m_s);
            if p.t_s > 0.0 {
                assert!(rel(p.x_m, x) <= CLOSED_FORM_TOL, "x {} vs {x}", p.x_m);
            }
            // The drag's work is what gravity released less the kinetic energy gained.
            let d = m * s.g_along() * x - 0.75 * m * (v * v - v0 * v0);
            assert!(
                (row.drag_j - d).abs() <= CLOSED_FORM_TOL * m * s.g_along() * x.max(1.0),
                "D_drag {} vs {d}",
                row.drag_j
            );
        }
    }
}

/// The check: the measured terminal velocity of the snowless log
/// with drag equals `v_t² = m g sin α/(½ ρ_a C_d A)` to 1e-9. The run stops
/// where |a| ≤ 1e-10 of the initial drive, i.e. |1 − v²/v_t²| ≤ 1e-10, so
/// |1 − v/v_t| ≤ 5e-11 plus the integration error (~1e-12).
#[test]
fn terminal_velocity_of_the_snowless_log_matches_the_closed_form_to_1e_9() {
    let s = Scenario::default();
    let l = Losses {
        drag_coefficient: 1.0,
        terminal_tol: 1e-10,
        ..Losses::default()
    };
    let traj = run(ModelKind::Snowless, &s, l, 1e4);
    assert_eq!(traj.stop.reason, StopReason::Terminal);
    let (m, area) = (s.initial_mass(), 2.0 * s.initial_radius() * s.length());
    let vt = (m * s.g_along() / (0.5 * 1.2 * 1.0 * area)).sqrt();
    assert!(
        rel(traj.stop.v_m_s, vt) <= 1e-9,
        "{} vs {vt}",
        traj.stop.v_m_s
    );
    // §2.2 with the defaults: v_t = 22.664 m/s, τ = 6.931 s.
    assert!((vt - 22.664).abs() < 1e-3);
    assert!((terminal_time_constant(&s, &l).unwrap() - 6.931).abs() < 1e-3);
    // Stop time: t = τ artanh(1 − tol/2) to first order.
    let tau = terminal_time_constant(&s, &l).unwrap();
    let t_want = tau * (1.0 - 0.5e-10f64).atanh();
    assert!((traj.stop.t_s - t_want).abs() < 1e-3 * t_want);
}

/// From above (v0 > v_t) the log slows down to the same v_t.
#[test]
fn terminal_velocity_is_reached_from_above() {
    let s = scenario(ScenarioFile {
        v0: 40.0,
        ..ScenarioFile::default()
    });
    let l = Losses {
        drag_coefficient: 1.0,
        ..Losses::default()
    };
    let traj = run(ModelKind::Snowless, &s, l, 1e4);
    assert_eq!(traj.stop.reason, StopReason::Terminal);
    let vt = terminal_velocity(&s, &l).unwrap();
    assert!(traj.stop.v_m_s > vt && rel(traj.stop.v_m_s, vt) <= 1e-9);
}

/// The ball of radius r0 and density ρ, derived here from the parameters
/// (not from the library): M = (4/3) π ρ r0³, frontal area π r0², k = 2/5.
fn ball_terminal_velocity(f: &ScenarioFile, cd: f64, rho_air: f64) -> f64 {
    let mass = 4.0 / 3.0 * PI * f.density * f.r0.powi(3);
    let area = PI * f.r0 * f.r0;
    let g_sin = f.g * f.alpha_deg.to_radians().sin();
    (2.0 * mass * g_sin / (rho_air * cd * area)).sqrt()
}

/// The check for the ball: the snowless ball with drag stops at
/// `v_t² = 2 M g sin α/(ρ_a C_d π r²)` to 1e-9 (stop at |a| ≤ 1e-10 of
/// the drive, |1 − v/v_t| ≤ 5e-11, plus the integration error ~1e-12), and
/// follows `v = v_t tanh(t/τ)` with τ = (7/5) v_t/(g sin α) on the way.
/// The same run judged with the log's frontal area 2 r l fails the check:
/// the test tells the ball's drag from the log's.
#[test]
fn terminal_velocity_of_the_snowless_ball_matches_the_closed_form_to_1e_9() {
    for (alpha, cd, rho_air, r0) in [
        (30.0, 1.0, 1.2, 0.1),
        (12.0, 0.47, 1.2, 0.3),
        (55.0, 2.0, 0.9, 0.05),
    ] {
        let f = ScenarioFile {
            alpha_deg: alpha,
            r0,
            shape: Shape::Sphere,
            ..ScenarioFile::default()
        };
        let s = scenario(f);
        let l = Losses {
            drag_coefficient: cd,
            air_density: rho_air,
            terminal_tol: 1e-10,
            ..Losses::default()
        };
        let vt = ball_terminal_velocity(&f, cd, rho_air);
        let traj = run(ModelKind::Snowless, &s, l, 1e4);
        assert_eq!(traj.stop.reason, StopReason::Terminal);
        assert!(
            rel(traj.stop.v_m_s, vt) <= 1e-9,
            "{} vs {vt}",
            traj.stop.v_m_s
        );
        assert!(rel(terminal_velocity(&s, &l).unwrap(), vt) <= 1e-14);
        let tau = 1.4 * vt / (f.g * alpha.to_radians().sin());
        for p in &traj.samples {
            let v = vt * (p.t_s / tau).tanh();
            assert!(rel(p.v_m_s, v) <= CLOSED_FORM_TOL, "v {} vs {v}", p.v_m_s);
        }
        // Wrong model: the log's area 2 r0 l for the ball.
        let mass = 4.0 / 3.0 * PI * f.density * r0.powi(3);
        let g_sin = f.g * alpha.to_radians().sin();
        let wrong = (2.0 * mass * g_sin / (rho_air * cd * 2.0 * r0 * f.length)).sqrt();
        assert!(rel(traj.stop.v_m_s, wrong) > 1e-2, "{wrong}");
    }
}

/// The ball's rolling resistance and compaction, against closed forms
/// derived in the test: the snowless ball with c_rr accelerates at
/// `(5/7)(G − c_rr C)` (N = M C) and loses `c_rr M C x`; on a fixed swath w
/// the compaction work is `e_c ρ b w x` (M − M0 = ρ b w x), on the natural
/// swath `e_c (4/3) π ρ (r³ − r0³)`.
#[test]
fn rolling_resistance_and_compaction_of_the_ball() {
    let f = ScenarioFile {
        shape: Shape::Sphere,
        ..ScenarioFile::default()
    };
    let s = scenario(f);
    let (g_sin, g_cos) = (
        f.g * f.alpha_deg.to_radians().sin(),
        f.g * f.alpha_deg.to_radians().cos(),
    );
    let l = Losses {
        rolling_resistance: 0.2,
        ..Losses::default()
    };
    let traj = run(ModelKind::Snowless, &s, l, 20.0);
    let m = 4.0 / 3.0 * PI * f.density * f.r0.powi(3);
    for (p, row) in traj.samples.iter().zip(&traj.ledger) {
        assert!(rel(p.a_m_s2, 5.0 / 7.0 * (g_sin - 0.2 * g_cos)) <= 1e-14);
        let d = 0.2 * m * g_cos * p.x_m;
        assert!((row.rolling_j - d).abs() <= CLOSED_FORM_TOL * d.max(1.0));
    }
    let l = Losses {
        compaction_energy: 4.0,
        ..Losses::default()
    };
    for width in [None, Some(0.05)] {
        let swath_width = width.map(SwathWidth::Metres);
        let s = scenario(ScenarioFile { swath_width, ..f });
        let traj = run(ModelKind::TorqueCm, &s, l, 30.0);
        assert!(traj.samples.last().unwrap().x_m > 10.0);
        for (p, row) in traj.samples.iter().zip(&traj.ledger) {
            let picked = match width {
                Some(w) => f.density * f.snow_depth * w * p.x_m,
                None => {
                    let r = (f.r0 * f.r0 + f.snow_depth * p.x_m / PI).sqrt();
                    4.0 / 3.0 * PI * f.density * (r.powi(3) - f.r0.powi(3))
                }
            };
            let d = 4.0 * picked;
            assert!(
                (row.compaction_j - d).abs() <= CLOSED_FORM_TOL * d.max(1.0),
                "{swath_width:?}: {} vs {d}",
                row.compaction_j
            );
        }
    }
}

/// §2.2: the snowless log with rolling resistance alone accelerates at
/// `(G − c_rr C)/(1 + k)`, and its loss is `c_rr M C x` (N = M C).
#[test]
fn rolling_resistance_alone_on_the_snowless_log() {
    let s = Scenario::default();
    let l = Losses {
        rolling_resistance: 0.2,
        ..Losses::default()
    };
    let traj = run(ModelKind::Snowless, &s, l, 20.0);
    let a = (s.g_along() - 0.2 * s.g_normal()) / 1.5;
    let m = s.initial_mass();
    for (p, row) in traj.samples.iter().zip(&traj.ledger) {
        assert!(rel(p.a_m_s2, a) <= 1e-14);
        let d = 0.2 * m * s.g_normal() * p.x_m;
        assert!((row.rolling_j - d).abs() <= CLOSED_FORM_TOL * d.max(1.0));
    }
    // Held by the couple: c_rr ≥ tan α, from rest, does not start.
    let held = Losses {
        rolling_resistance: 0.6,
        ..Losses::default()
    };
    let traj = run(ModelKind::Snowless, &s, held, 20.0);
    assert_eq!(traj.stop.reason, StopReason::DoesNotStart);
}

/// §2.2, accretion with compaction, eq. (4) (c_v = 7/6): with s = π r²,
/// `v² = A s + B + K s^{−2c_v}`, A = 4G/(3b(1 + 2c_v)), B = −e_c/(c_v(1 + k));
/// and the compaction work is exactly `e_c (M − M0)`.
#[test]
fn compaction_alone_on_the_torque_cm_log() {
    let s = Scenario::default();
    let e_c = 5.0;
    let l = Losses {
        compaction_energy: e_c,
        ..Losses::default()
    };
    let traj = run(ModelKind::TorqueCm, &s, l, 100.0);
    let (b, r0) = (s.snow_depth(), s.initial_radius());
    let cv = 7.0 / 6.0;
    let a_coef = 4.0 * s.g_along() / (3.0 * b * (1.0 + 2.0 * cv));
    let b_coef = -e_c / (cv * 1.5);
    let s0 = PI * r0 * r0;
    let k = (0.0 - a_coef * s0 - b_coef) * s0.powf(2.0 * cv);
    for (p, row) in traj.samples.iter().zip(&traj.ledger) {
        let area = s0 + b * p.x_m;
        let u = a_coef * area + b_coef + k * area.powf(-2.0 * cv);
        assert!(
            (p.v_m_s * p.v_m_s - u).abs() <= CLOSED_FORM_TOL * (a_coef * area),
            "v^2 {} vs {u}",
            p.v_m_s * p.v_m_s
        );
        let d = e_c * (p.mass_kg - s.initial_mass());
        assert!((row.compaction_j - d).abs() <= CLOSED_FORM_TOL * d.max(1.0));
    }
    // §2.2: from rest the drag-only log starts only if e_c < π r0² G/b (15.4 J/kg).
    let limit = s0 * s.g_along() / b;
    assert!((limit - 15.4).abs() < 0.05);
    for (e, reason) in [
        (1.01 * limit, StopReason::DoesNotStart),
        (0.99 * limit, StopReason::EndTime),
    ] {
        let l = Losses {
            compaction_energy: e,
            ..Losses::default()
        };
        assert_eq!(run(ModelKind::TorqueCm, &s, l, 1.0).stop.reason, reason);
    }
}

/// §3.1: the lossless eq. (4) from rest destroys, by Loney's u(s) (fn. 4),
/// `W_4(s) = ρl ∫u ds − ρl C [π(r³ − r0³) + b²x/2] − (ρl b²/4π)[(2G/3) x − (7/6) ∫(u/s) ds]`,
/// with u = (2G/5b) s [1 − (s0/s)^{10/3}]: both integrals in closed form.
#[test]
fn torque_cm_model_defect_matches_the_closed_form() {
    let s = Scenario::default();
    let l = Losses {
        ledger: true,
        ..Losses::default()
    };
    let traj = run(ModelKind::TorqueCm, &s, l, 100.0);
    let (b, r0, rho_l) = (s.snow_depth(), s.initial_radius(), s.density() * s.length());
    let (g_along, g_normal) = (s.g_along(), s.g_normal());
    let s0 = PI * r0 * r0;
    let c = 2.0 * g_along / (5.0 * b);
    let p = 10.0 / 3.0;
    // ∫ u ds = c [s²/2 − s0^p s^{2−p}/(2−p)] from s0; ∫ u/s ds = c [s − s0^p s^{1−p}/(1−p)].
    let int_u = |x: f64| c * (x * x / 2.0 - s0.powf(p) * x.powf(2.0 - p) / (2.0 - p));
    let int_u_s = |x: f64| c * (x - s0.powf(p) * x.powf(1.0 - p) / (1.0 - p));
    let mut checked = 0;
    for (q, row) in traj.samples.iter().zip(&traj.ledger) {
        let area = s0 + b * q.x_m;
        let r = (area / PI).sqrt();
        let w = rho_l * (int_u(area) - int_u(s0))
            - rho_l * g_normal * (PI * (r.powi(3) - r0.powi(3)) + b * b * q.x_m / 2.0)
            - rho_l * b * b / (4.0 * PI)
                * (2.0 * g_along / 3.0 * q.x_m - 7.0 / 6.0 * (int_u_s(area) - int_u_s(s0)));
        let scale = row.kinetic_j.max(row.released_j).max(1.0);
        assert!(
            (row.model_j - w).abs() <= CLOSED_FORM_TOL * scale,
            "W_4 {} vs {w} at x = {}",
            row.model_j,
            q.x_m
        );
        checked += 1;
    }
    assert!(checked > 10);
    // It destroys energy: the snow's inelastic pick-up outweighs the lift it does not pay.
    assert!(traj.ledger.last().unwrap().model_j > 0.0);
}

/// `energy` (eq. (14)) is an energy balance: with all three losses its
/// W_model stays 0, so the forces the ledger computes from their
/// definitions are those the equation of motion took in (§2.1) — for the
/// log, and for the ball on each growth law (its frontal area π r², its
/// N and dM/dx; on the chord also its potential energy's ∫ M dx, a closed
/// form of its own).
#[test]
fn energy_model_with_all_losses_has_no_model_defect() {
    let s = Scenario::default();
    let l = Losses {
        drag_coefficient: 1.0,
        rolling_resistance: 0.05,
        compaction_energy: 3.0,
        ..Losses::default()
    };
    let ball = |swath_width| {
        scenario(ScenarioFile {
            shape: Shape::Sphere,
            swath_width,
            ..ScenarioFile::default()
        })
    };
    for (kind, s) in [
        (ModelKind::Energy, s),
        (ModelKind::Snowless, s),
        (ModelKind::Energy, ball(None)),
        (ModelKind::Energy, ball(Some(SwathWidth::Metres(0.03)))),
        (
            ModelKind::Energy,
            ball(Some(SwathWidth::Chord(ChordWord::Chord))),
        ),
        (ModelKind::Snowless, ball(None)),
    ] {
        let traj = run(kind, &s, l, 100.0);
        let last = traj.ledger.last().unwrap();
        let scale = last.released_j;
        for row in &traj.ledger {
            assert!(
                row.model_j.abs() <= CLOSED_FORM_TOL * scale,
                "{kind}: {row:?}"
            );
        }
        assert!(last.drag_j > 0.0 && last.rolling_j > 0.0);
    }
}

/// The ledger on random scenarios: `kinetic + Σ losses + model − released =
/// initial` at every sample, for every circular family with random losses,
/// on the log and on the ball (both growth laws).
/// The residual is relative to the largest term of the ledger; the works
/// are quadratures on the steps of a run at rtol 1e-10 lasting up to
/// ~10^3 time scales: the largest seen is 2.0e-9 (a ball), so 1e-8.
const LEDGER_TOL: f64 = 1e-8;
/// Scenarios per family (9 circular families): the issue asks for at least 1000 in all.
const CASES: u32 = 300;
const SEED: [u8; 32] = *b"snowroll issue 11 ledger seed 00";

/// A random scenario: the log, the ball with its natural swath 2r, or the
/// ball with a fixed swath of 0.1 to 10 times r0.
fn random_case() -> impl Strategy<Value = (Scenario, Losses, f64)> {
    (
        (
            -2.0..0.5f64,
            -4.0..-0.5f64,
            5.0..80.0f64,
            prop_oneof![Just(0.0), 0.0..5.0f64],
        ),
        (
            prop_oneof![Just(0.0), 0.1..2.0f64],
            prop_oneof![Just(0.0), 0.0..0.1f64],
            prop_oneof![Just(0.0), 0.0..5.0f64],
        ),
        (0.0..3.0f64),
        prop_oneof![
            Just(None),
            Just(Some(None)),
            (-1.0..1.0f64).prop_map(|lw| Some(Some(lw)))
        ],
    )
        .prop_map(|((lr0, lratio, alpha, v0), (cd, crr, ec), lt, ball)| {
            let r0 = 10f64.powf(lr0);
            let (shape, swath_width) = match ball {
                None => (Shape::Cylinder, None),
                Some(None) => (Shape::Sphere, None),
                Some(Some(lw)) => (Shape::Sphere, Some(r0 * 10f64.powf(lw))),
            };
            let s = scenario(ScenarioFile {
                alpha_deg: alpha,
                snow_depth: r0 * 10f64.powf(lratio),
                r0,
                v0,
                shape,
                swath_width: swath_width.map(SwathWidth::Metres),
                ..ScenarioFile::default()
            });
            let l = Losses {
                drag_coefficient: cd,
                rolling_resistance: crr,
                compaction_energy: ec,
                ledger: true,
                ..Losses::default()
            };
            (s, l, 10f64.powf(lt))
        })
}

fn ledger_scale(row: &LedgerRow, initial: f64) -> f64 {
    [
        row.kinetic_j,
        row.released_j.abs(),
        row.drag_j,
        row.rolling_j,
        row.compaction_j,
        row.model_j.abs(),
        initial,
    ]
    .into_iter()
    .fold(f64::MIN_POSITIVE, f64::max)
}

#[test]
fn ledger_sums_to_the_initial_energy_on_random_scenarios() {
    let kinds: Vec<ModelKind> = ModelKind::ALL
        .into_iter()
        .filter(|k| k.is_circular())
        .collect();
    let mut total = 0;
    let balls = std::cell::Cell::new(0);
    for kind in kinds {
        let mut runner = TestRunner::new_with_rng(
            Config {
                cases: CASES,
                failure_persistence: None,
                ..Config::default()
            },
            TestRng::from_seed(RngAlgorithm::ChaCha, &SEED),
        );
        runner
            .run(&random_case(), |(s, l, t_end)| {
                let opts = SimOptions {
                    t_end,
                    losses: l,
                    sampling: Sampling::Every(t_end / 16.0),
                    ..SimOptions::default()
                };
                let traj = match kind.build().simulate(&s, &opts) {
                    Ok(t) => t,
                    Err(SimError::Param(_)) => return Ok(()),
                    Err(e) => return Err(TestCaseError::fail(format!("{kind}: {e}"))),
                };
                if s.shape() == Shape::Sphere {
                    balls.set(balls.get() + 1);
                }
                prop_assert_eq!(traj.ledger.len(), traj.samples.len());
                let first = traj.ledger[0];
                let initial = first.kinetic_j - first.released_j;
                for row in &traj.ledger {
                    let scale = ledger_scale(row, initial);

                    prop_assert!(
                        row.residual_j.abs() <= LEDGER_TOL * scale,
                        "{}: residual {} of {} ({:?})",
                        kind,
                        row.residual_j,
                        scale,
                        row
                    );
                    prop_assert!(
                        row.drag_j >= 0.0 && row.rolling_j >= 0.0 && row.compaction_j >= 0.0
                    );
                }
                Ok(())
            })
            .unwrap();
        total += CASES;
    }
    assert!(total >= 1000);
    // About a third of the cases are balls with each growth law; at least
    // 500 balls ran (loney refuses a fixed swath).
    assert!(balls.get() >= 500, "{} balls", balls.get());
}

/// The turn models take no losses (their slip and extremes come from the
/// energy integral of a turn, §2.1): they refuse, naming the flag.
#[test]
fn turn_models_refuse_losses() {
    let l = Losses {
        drag_coefficient: 1.0,
        ..Losses::default()
    };
    let opts = SimOptions {
        losses: l,
        turns: Some(3),
        ..SimOptions::default()
    };
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        let err = kind
            .build()
            .simulate(&Scenario::default(), &opts)
            .unwrap_err();
        assert!(
            matches!(
                err,
                SimError::Param(ParamError::Unsupported {
                    what: "drag_coefficient",
                    ..
                })
            ),
            "{err}"
        );
    }
}

/// Without losses or `ledger` there is no ledger; asking for it does not
/// change the trajectory (the works are quadratures outside the step
/// control). The run without the ledger takes Taylor steps and the run with
/// it DOP853's (the works' rates have no Taylor recurrence), so they are
/// compared on the same grid of times to the run's rtol, 1e-10: between its
/// steps DOP853's values come from its 7th-order dense output, which is
/// good to about the tolerance, not to its steps' 1e-14; a = P − c_v b v²/s
/// loses up to a factor 10 of that to the cancellation (1.6e-10 apart for
/// eq. (14)), so a gets 1e-9. Before the Taylor steps both runs took the
/// same steps and gave the same bits.
#[test]
fn the_ledger_does_not_change_the_trajectory() {
    const METHODS_AGREE: f64 = 1e-10;
    for kind in [ModelKind::TorqueCm, ModelKind::Energy, ModelKind::Snowless] {
        let grid = SimOptions {
            sampling: snowroll::Sampling::Every(5.0),
            ..SimOptions::default()
        };
        let plain = kind.build().simulate(&Scenario::default(), &grid).unwrap();
        assert!(plain.ledger.is_empty());
        let opts = SimOptions {
            losses: Losses {
                ledger: true,
                ..Losses::default()
            },
            ..grid.clone()
        };
        let with = kind.build().simulate(&Scenario::default(), &opts).unwrap();
        assert_eq!(with.samples.len(), plain.samples.len(), "{kind}");
        for (a, b) in with.samples.iter().zip(&plain.samples) {
            assert_eq!(a.t_s.to_bits(), b.t_s.to_bits(), "{kind}");
            for (p, q, tol) in [
                (a.x_m, b.x_m, METHODS_AGREE),
                (a.v_m_s, b.v_m_s, METHODS_AGREE),
                (a.a_m_s2, b.a_m_s2, 10.0 * METHODS_AGREE),
            ] {
                assert!(
                    (p - q).abs() <= tol * q.abs().max(1e-9),
                    "{kind}: {p} vs {q}"
                );
            }
        }
        assert_eq!(with.ledger.len(), with.samples.len());
    }
}
