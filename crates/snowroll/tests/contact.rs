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

fn scenario(alpha_deg: f64) -> Scenario {
    Scenario::new(ScenarioFile {
        alpha_deg,
        ..ScenarioFile::default()
    })
    .unwrap()
}

#[test]
fn app_a_snowless_run_has_n_mg_cos_alpha_and_f_mg_sin_alpha_over_3_exactly() {
    let s = scenario(30.0);
    // Sampled on a grid: the run is one Taylor step (its solution is a
    // polynomial), so the interior samples come from its dense output.
    let opts = SimOptions {
        sampling: Sampling::Every(5.0),
        ..SimOptions::default()
    };
    let traj = ModelKind::Snowless.build().simulate(&s, &opts).unwrap();
    let m = s.initial_mass();
    let (n_want, f_want) = (m * s.g_normal(), m * s.g_along() / 3.0);
    assert!(traj.samples.len() > 2);
    for p in &traj.samples {
        assert!((p.normal_n - n_want).abs() <= ROUNDING * n_want, "{p:?}");
        assert!((p.friction_n - f_want).abs() <= ROUNDING * f_want, "{p:?}");
        let ratio = s.slope_angle().tan() / 3.0;
        let got = p.friction_ratio.expect("N > 0: the ratio is defined");
        assert!((got - ratio).abs() <= ROUNDING * ratio);
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

fn turn_opts(turns: u64) -> SimOptions {
    SimOptions {
        t_end: 1e7,
        turns: Some(turns),
        ..SimOptions::default()
    }
}

/// fn. 10, `docs/contact-forces.md` §4.4: at 30° (defaults otherwise) the
/// log never hops in 2000 turns, and the smallest N/(M g) of the last turn
/// approaches the late-turn closed form cos α − ½ sin α (§4.2) to O(b/r_K)
/// ≈ 5e-4: tolerance 1e-3, the doc's check recipe §7.4.
#[test]
fn fn10_a_log_at_30_degrees_never_hops_in_2000_turns() {
    let s = scenario(30.0);
    let alpha = s.slope_angle();
    let late = alpha.cos() - 0.5 * alpha.sin();
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        let table = snowroll::run_turns(kind, &s, &turn_opts(2000)).unwrap();
        assert_eq!(table.stop.reason, snowroll::StopReason::Turns, "{kind}");
        assert_eq!(table.rows.len(), 2000);
        let last = table.rows.last().unwrap().min_normal_over_mg;
        assert!((last - late).abs() < 1e-3, "{kind}: {last} vs {late}");
        assert!(table.rows.iter().all(|r| r.min_normal_over_mg > late));
    }
}

/// fn. 10, §4.4: at 80° the log hops in turn 1 (its minimum of N, at
/// θ = 4.811 rad, is negative; `reference/min_normal_per_turn.csv`). N first
/// reaches 0 at θ = 3.982884176 rad (`turns`), 3.924131324 rad
/// (`turns-exact`): bisection on N(θ) of `turn_numerics.py`'s `Turn` from the
/// reference's turn-1 start speed 2.57226072709 m/s (`turns`; 2.54939869357
/// for `turns-exact`). Tolerance 1e-8 rad: the start speed is given to 12 digits.
#[test]
fn fn10_a_log_at_80_degrees_hops_in_its_second_turn() {
    let s = scenario(80.0);
    for (kind, theta) in [
        (ModelKind::Turns, 3.982_884_176),
        (ModelKind::TurnsExact, 3.924_131_324),
    ] {
        let traj = kind.build().simulate(&s, &turn_opts(10)).unwrap();
        assert_eq!(traj.stop.reason, snowroll::StopReason::Hop, "{kind}");
        let at = traj.stop.turn.unwrap();
        assert_eq!(at.turn, 1);
        assert!(
            (at.theta_rad - theta).abs() < 1e-8,
            "{kind}: {}",
            at.theta_rad
        );
        // At the stop N = 0 (the event's root, to the locator's precision).
        let last = traj.samples.last().unwrap();
        assert!(last.normal_n.abs() < 1e-6 * last.mass_kg * s.gravity());
    }
}

/// Per-turn minimum of N/(M g) and maximum of |F|/N against the independent
/// Python computation (`reference/min_normal_per_turn.csv`: the energy
/// integral of each turn, a fine grid, collision eq. (89)). Both sides are
/// accurate to ~1e-9; 1e-7 leaves margin for the grid of the reference.
#[test]
fn per_turn_contact_extremes_match_the_reference() {
    let text = include_str!("../../../scripts/derivations/reference/min_normal_per_turn.csv");
    let mut checked = 0;
    for alpha in [10.0, 30.0, 45.0, 60.0] {
        let s = scenario(alpha);
        for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
            let table = snowroll::run_turns(kind, &s, &turn_opts(1000)).unwrap();
            let prefix = format!("{},{},", kind.id(), alpha as u32);
            for line in text.lines().filter(|l| l.starts_with(&prefix)) {
                let f: Vec<&str> = line.split(',').collect();
                let k: usize = f[2].parse().unwrap();
                let n = |i: usize| f[i].parse::<f64>().unwrap();
                let Some(row) = table.rows.get(k) else {
                    continue;
                };
                assert!(
                    (row.min_normal_over_mg - n(4)).abs() < 1e-7,
                    "{line}: {}",
                    row.min_normal_over_mg
                );
                let ratio = row.max_friction_ratio.expect("N > 0 below 63°");
                assert!(
                    (ratio - n(6)).abs() < 1e-7 * n(6).max(1.0),
                    "{line}: {ratio}"
                );
                checked += 1;
            }
        }
    }
    assert!(checked >= 80, "{checked}");
}

/// §5.3: the smallest μ that keeps a turn model rolling over 2000 turns is
/// the largest per-turn |F|/N (`reference/turn_mu_min.csv`), tolerance as above.
#[test]
fn turn_mu_min_over_2000_turns_matches_the_reference() {
    let s = scenario(30.0);
    for (kind, want) in [
        (ModelKind::Turns, 0.2202896127),
        (ModelKind::TurnsExact, 0.2335088413),
    ] {
        let table = snowroll::run_turns(kind, &s, &turn_opts(2000)).unwrap();
        let mu_min = table
            .rows
            .iter()
            .map(|r| r.max_friction_ratio.expect("N > 0 below 63°"))
            .fold(0.0, f64::max);
        assert!((mu_min - want).abs() < 1e-7, "{kind}: {mu_min}");
        // A μ just below the maximum stops the run with a slip there; just above, it rolls on.
        let opts = |mu: f64| SimOptions {
            mu: Some(mu),
            sampling: Sampling::Ends,
            ..turn_opts(2000)
        };
        let slips = kind
            .build()
            .simulate(&s, &opts(mu_min * (1.0 - 1e-6)))
            .unwrap();
        assert_eq!(slips.stop.reason, snowroll::StopReason::Slip, "{kind}");
        let rolls = kind
            .build()
            .simulate(&s, &opts(mu_min * (1.0 + 1e-6)))
            .unwrap();
        assert_eq!(rolls.stop.reason, snowroll::StopReason::Turns, "{kind}");
    }
}

/// §5.2, check recipe §7.5: eq. (4) from rest has the closed form
/// v² = A s (1 − (s0/s)^{1+2c_v}), s = πr², A = 4G/(3b(1 + 2c_v)), so with
/// q = b v²/s, F/M = G/3 + (c_v − 1) q and N/M = C + (b/(2πr))(2G/3 + (½ − c_v) q)
/// are known along the run; the slip event must fall where their ratio
/// crosses μ (bisection here). Tolerance: the event is located to ~1e-12 s
/// and the integration is accurate to rtol 1e-10: 1e-8 relative in x.
#[test]
fn slip_of_eq4_falls_where_the_closed_form_ratio_crosses_mu() {
    let s = scenario(30.0);
    let (g, c, b, r0) = (
        s.g_along(),
        s.g_normal(),
        s.snow_depth(),
        s.initial_radius(),
    );
    let c_v = 7.0 / 6.0;
    let s0 = PI * r0 * r0;
    let ratio = |x: f64| {
        let area = s0 + b * x;
        let a_coef = 4.0 * g / (3.0 * b * (1.0 + 2.0 * c_v));
        let u = a_coef * area * (1.0 - (s0 / area).powf(1.0 + 2.0 * c_v));
        let q = b * u / area;
        let r = (area / PI).sqrt();
        let f = g / 3.0 + (c_v - 1.0) * q;
        let n = c + b / (2.0 * PI * r) * (2.0 * g / 3.0 + (0.5 - c_v) * q);
        f / n
    };
    let mu = 0.5 * (ratio(0.0) + ratio(100.0));
    let (mut lo, mut hi) = (0.0, 100.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if ratio(mid) < mu {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let opts = SimOptions {
        mu: Some(mu),
        ..SimOptions::default()
    };
    let traj = ModelKind::TorqueCm.build().simulate(&s, &opts).unwrap();
    assert_eq!(traj.stop.reason, snowroll::StopReason::Slip);
    assert!(
        (traj.stop.x_m - lo).abs() < 1e-8 * lo,
        "{} vs {lo}",
        traj.stop.x_m
    );
    // Loney's closed form of eq. (4) carries the same event: its stop is
    // located on the closed form itself (bisection in x to rounding, t by
    // quadrature), so it meets the same crossing to the same 1e-8.
    let loney = ModelKind::Loney.build().simulate(&s, &opts).unwrap();
    assert_eq!(loney.stop.reason, snowroll::StopReason::Slip);
    assert!(
        (loney.stop.x_m - lo).abs() < 1e-8 * lo,
        "{} vs {lo}",
        loney.stop.x_m
    );
    assert!((loney.stop.t_s - traj.stop.t_s).abs() < 1e-8 * traj.stop.t_s);
}

/// A hop of eq. (4) and of Loney's closed form: N/M = C + (b/2πr)(a + q/2)
/// with a = 2G/3 − (7/6) q (eq. (4)), q = b v²/(π r²), is negative at the
/// start iff q > G + (3/2)(2π r0/b) C, i.e. v0 > 50.3 m/s at 30° with the
/// defaults; both runs then stop with `hop` at t = 0, and just below the
/// threshold neither hops (q only falls from there, and N grows with it).
#[test]
fn loney_and_eq4_hop_where_the_start_speed_makes_n_negative() {
    let base = scenario(30.0);
    let (g, c, b, r0) = (
        base.g_along(),
        base.g_normal(),
        base.snow_depth(),
        base.initial_radius(),
    );
    let q_star = g + 1.5 * (2.0 * PI * r0 / b) * c;
    let v_star = (q_star * PI * r0 * r0 / b).sqrt();
    assert!((v_star - 50.3).abs() < 0.1, "{v_star}");
    let opts = SimOptions {
        t_end: 2.0,
        ..SimOptions::default()
    };
    for (v0, hops) in [(1.001 * v_star, true), (0.999 * v_star, false)] {
        let s = Scenario::new(ScenarioFile {
            alpha_deg: 30.0,
            v0,
            ..ScenarioFile::default()
        })
        .unwrap();
        for kind in [ModelKind::Loney, ModelKind::TorqueCm] {
            let traj = kind.build().simulate(&s, &opts).unwrap();
            if hops {
                assert_eq!(traj.stop.reason, snowroll::StopReason::Hop, "{kind}");
                assert!(traj.stop.t_s <= 0.0, "{kind}: {}", traj.stop.t_s);
            } else {
                assert_eq!(traj.stop.reason, snowroll::StopReason::EndTime, "{kind}");
            }
        }
    }
}

/// Where a run of a circular model without losses starts with a ≥ 0, a stays
/// ≥ 0 (the common form differentiated along the run is `a′ = α a + β` with a
/// source β ≥ 0, `Acceleration::stays_non_negative_from`), so N/M = C + r′(a +
/// q/2) ≥ C for the log and C + r′a + 2r′²v²/r ≥ C for the ball
/// (`docs/contact-forces.md` §2): N ≥ M g cos α at every step, and no such
/// run hops (its hop event is then not even evaluated). Checked on every
/// circular model, both shapes, slopes 5° to 85°, from rest and from 3 m/s
/// and 20 m/s; the runs with a < 0 at the start (none hops here, but the
/// bound does not apply) are left out. Tolerance 1e-12 relative: N is a few
/// operations on numbers of order M g. A run started above the hop
/// threshold does hop (`loney_and_eq4_hop_where_the_start_speed_makes_n_negative`).
#[test]
fn a_run_that_starts_with_a_non_negative_keeps_n_at_least_m_g_cos_alpha() {
    let opts = SimOptions {
        t_end: 200.0,
        sampling: Sampling::Steps,
        ..SimOptions::default()
    };
    let mut checked = 0;
    for kind in ModelKind::ALL
        .into_iter()
        .filter(|k| k.derivation().is_some())
    {
        for shape in snowroll::Shape::ALL {
            for alpha_deg in [5.0, 30.0, 60.0, 85.0] {
                for v0 in [0.0, 3.0, 20.0] {
                    let s = Scenario::new(ScenarioFile {
                        alpha_deg,
                        v0,
                        shape,
                        ..ScenarioFile::default()
                    })
                    .unwrap();
                    let Ok(traj) = kind.build().simulate(&s, &opts) else {
                        continue; // a model that does not support the ball
                    };
                    if traj.samples[0].a_m_s2 < 0.0 {
                        continue;
                    }
                    checked += 1;
                    assert_ne!(traj.stop.reason, snowroll::StopReason::Hop, "{kind}");
                    for p in &traj.samples {
                        let floor = p.mass_kg * s.g_normal();
                        assert!(
                            p.normal_n >= floor * (1.0 - 1e-12),
                            "{kind} {shape:?} {alpha_deg}° v0 {v0}: N {} < M C {floor} at t {}",
                            p.normal_n,
                            p.t_s
                        );
                    }
                }
            }
        }
    }
    assert!(checked >= 60, "{checked} runs checked");
}
