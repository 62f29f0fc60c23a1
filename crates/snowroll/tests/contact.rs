//! Contact forces (issue 10, `docs/contact-forces.md`): N and F of every
//! model against closed forms, against the momentum balance evaluated by
//! finite differences of the trajectory, and against the independent Python
//! values of `scripts/derivations/reference/circular_forces.csv`.

use std::f64::consts::PI;

use snowroll::{
    circular_forces, ModelKind, Sampling, Scenario, ScenarioFile, SimOptions, Trajectory,
};

/// "Exact to rounding": N and F are a few operations on numbers of order m g.
const ROUNDING: f64 = 1e-13;
/// The reference CSV prints 15 significant digits and both sides evaluate the
/// same closed form: agreement to 1e-12 relative.
const REFERENCE_TOL: f64 = 1e-12;

fn scenario(slope_deg: f64) -> Scenario {
    Scenario::new(ScenarioFile {
        slope_deg,
        ..ScenarioFile::default()
    })
    .unwrap()
}

#[test]
fn app_a_snowless_run_has_n_mg_cos_alpha_and_f_mg_sin_alpha_over_3_exactly() {
    let s = scenario(30.0);
    let traj = ModelKind::Snowless
        .build()
        .simulate(&s, &SimOptions::default())
        .unwrap();
    let m = s.initial_mass();
    let (n_want, f_want) = (m * s.g_normal(), m * s.g_along() / 3.0);
    assert!(traj.samples.len() > 2);
    for p in &traj.samples {
        assert!((p.normal_n - n_want).abs() <= ROUNDING * n_want, "{p:?}");
        assert!((p.friction_n - f_want).abs() <= ROUNDING * f_want, "{p:?}");
        let ratio = s.slope_angle().tan() / 3.0;
        assert!((p.friction_ratio - ratio).abs() <= ROUNDING * ratio);
    }
}

/// Rows `cylinder,model,x,v,a,N/M,F/M,|F|/N` of the Python reference.
#[test]
fn circular_forces_match_the_independent_reference() {
    let text = include_str!("../../../scripts/derivations/reference/circular_forces.csv");
    let s = scenario(30.0);
    let mut checked = 0;
    for line in text
        .lines()
        .filter(|l| l.starts_with("cylinder,"))
        .filter(|l| !l.contains(",loney,"))
    {
        let f: Vec<&str> = line.split(',').collect();
        let kind: ModelKind = f[1].parse().unwrap();
        let n = |i: usize| f[i].parse::<f64>().unwrap();
        let (x, v) = (n(2), n(3));
        let c = kind.derivation().unwrap().coefficients();
        let a = c.acceleration(&s, x, v);
        assert!(
            (a - n(4)).abs() <= REFERENCE_TOL * n(4).abs().max(1.0),
            "{line}: a {a}"
        );
        let forces = circular_forces(&c, &s, x, v, a);
        let m = if c.accretes {
            snowroll::physics::mass_at(&s, x)
        } else {
            s.initial_mass()
        };
        let (n_over_m, f_over_m) = (forces.normal_n / m, forces.friction_n / m);
        assert!(
            (n_over_m - n(5)).abs() <= REFERENCE_TOL * n(5),
            "{line}: N/M {n_over_m}"
        );
        assert!(
            (f_over_m - n(6)).abs() <= REFERENCE_TOL * 10.0,
            "{line}: F/M {f_over_m}"
        );
        checked += 1;
    }
    assert!(checked >= 35, "only {checked} rows");
}

/// Samples at `t − h, t, t + h` for each t, from the dense output.
fn triples(kind: ModelKind, s: &Scenario, centres: &[f64], h: f64, turns: u64) -> Trajectory {
    let times: Vec<f64> = centres.iter().flat_map(|&t| [t - h, t, t + h]).collect();
    let opts = SimOptions {
        t_end: 1e3,
        turns: (!kind.is_circular()).then_some(turns),
        sampling: Sampling::Times(times),
        tolerances: snowroll::integrate::Tolerances {
            rtol: 1e-12,
            atol: 1e-14,
            ..Default::default()
        },
        ..SimOptions::default()
    };
    kind.build().simulate(s, &opts).unwrap()
}

/// Central differences of the momentum need h small against the time scale
/// (~0.01 s) and large against the integration error: h = 1e-4 s gives a
/// truncation of h² p‴/6 ~ 1e-8 g and a rounding/integration part ~1e-12/h
/// = 1e-8 g; 1e-6 g leaves a margin of 100.
const FD_H: f64 = 1e-4;
const FD_TOL_OVER_G: f64 = 1e-6;

/// Circular models: p = M(v, ṙ), ṙ = b v/(2πr) (eq. (1)); N = dp_y/dt + M C,
/// F = M G − dp_x/dt, by finite differences of the run.
#[test]
fn circular_forces_are_the_momentum_balance_of_the_run() {
    let s = scenario(30.0);
    let b = s.snow_depth();
    for kind in [
        ModelKind::TorqueCm,
        ModelKind::Energy,
        ModelKind::QuasiCircular,
    ] {
        let traj = triples(kind, &s, &[0.3, 2.0, 20.0], FD_H, 0);
        assert_eq!(traj.samples.len(), 9);
        let p = |i: usize| {
            let q = &traj.samples[i];
            let r_dot = b * q.v_m_s / (2.0 * PI * q.r_m);
            (q.mass_kg * q.v_m_s, q.mass_kg * r_dot)
        };
        for j in 0..3 {
            let mid = &traj.samples[3 * j + 1];
            let (lo, hi) = (p(3 * j), p(3 * j + 2));
            let m = mid.mass_kg;
            let n_fd = (hi.1 - lo.1) / (2.0 * FD_H) + m * s.g_normal();
            let f_fd = m * s.g_along() - (hi.0 - lo.0) / (2.0 * FD_H);
            let tol = FD_TOL_OVER_G * m * s.gravity();
            assert!(
                (mid.normal_n - n_fd).abs() < tol,
                "{kind}: N {} vs {n_fd}",
                mid.normal_n
            );
            assert!(
                (mid.friction_n - f_fd).abs() < tol,
                "{kind}: F {} vs {f_fd}",
                mid.friction_n
            );
        }
    }
}

/// Turn models: the body (disk + annular sector over [0, θ] behind the
/// contact line) turns about the contact line C, so p = θ̇ (S_y, −S_x) with
/// the first moment about C. For the exact body, from the integrals over
/// the sector (D_n = (r + b)ⁿ − rⁿ, Q = ρl D₃/3):
/// S_x = −Q(1 − cos θ), S_y = (m_k + ρl θ D₂/2) r − Q sin θ
/// (`docs/contact-forces.md` §3); for `turns` the note's first-order body
/// (sector mass m_k b θ/(πr), eq. (38)): the same form with D₂/2 → b r,
/// D₃/3 → b r².
#[test]
fn turn_forces_are_the_momentum_balance_of_the_run() {
    for slope in [30.0, 80.0] {
        let s = scenario(slope);
        let (b, rho_l) = (s.snow_depth(), s.density() * s.length());
        for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
            // Inside turns 0 and 1 (turn 0 of the defaults lasts ~0.55 s at 30°).
            let traj = triples(kind, &s, &[0.1, 0.25, 0.4], FD_H, 3);
            assert_eq!(traj.samples.len(), 9, "{kind} at {slope}°");
            let p = |i: usize| {
                let q = &traj.samples[i];
                let ts = &traj.turn_states[i];
                let r = q.r_m;
                let m_k = PI * rho_l * r * r;
                let (half_d2, third_d3) = if kind == ModelKind::TurnsExact {
                    (
                        ((r + b).powi(2) - r * r) / 2.0,
                        ((r + b).powi(3) - r.powi(3)) / 3.0,
                    )
                } else {
                    (b * r, b * r * r)
                };
                let theta = ts.theta_rad;
                let q_moment = rho_l * third_d3;
                let s_x = -q_moment * (1.0 - theta.cos());
                let s_y = (m_k + rho_l * theta * half_d2) * r - q_moment * theta.sin();
                let w = ts.omega_rad_s;
                (w * s_y, -w * s_x)
            };
            for j in 0..3 {
                let same_turn = (0..3)
                    .all(|i| traj.turn_states[3 * j + i].turn == traj.turn_states[3 * j].turn);
                assert!(same_turn, "{kind}: a collision inside a difference");
                let mid = &traj.samples[3 * j + 1];
                let (lo, hi) = (p(3 * j), p(3 * j + 2));
                let m = mid.mass_kg;
                let n_fd = (hi.1 - lo.1) / (2.0 * FD_H) + m * s.g_normal();
                let f_fd = m * s.g_along() - (hi.0 - lo.0) / (2.0 * FD_H);
                let tol = FD_TOL_OVER_G * m * s.gravity();
                assert!(
                    (mid.normal_n - n_fd).abs() < tol,
                    "{kind} {slope}°: N {} vs {n_fd}",
                    mid.normal_n
                );
                assert!(
                    (mid.friction_n - f_fd).abs() < tol,
                    "{kind} {slope}°: F {} vs {f_fd}",
                    mid.friction_n
                );
            }
        }
    }
}
