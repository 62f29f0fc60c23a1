//! The three ways to climb the step of each new layer (issue 10,
//! `docs/contact-forces.md` §6): angular momentum about the impact line
//! conserved by the `pivot` impact, the first step against the independent
//! Python values (`reference/pivot_first_step.csv`), and the energy
//! accounting of `charged`.

use std::f64::consts::PI;

use snowroll::{
    charged_collision_speed, collision_speed, CollisionModel, ModelKind, PivotImpact, Sampling,
    Scenario, ScenarioFile, SimOptions, StopReason,
};

fn scenario(alpha_deg: f64, v0: f64) -> Scenario {
    Scenario::new(ScenarioFile {
        alpha_deg,
        v0,
        ..ScenarioFile::default()
    })
    .unwrap()
}

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n).
fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 0.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let kf = k as f64;
                    (p0, p1) = (p1, ((2.0 * kf - 1.0) * x * p1 - (kf - 1.0) * p0) / kf);
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                x -= p1 / dp;
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

/// ∫ f(X) dm over the body at θ_c (disk of radius r centred at (0, r), plus
/// the annular sector r < r′ < r + b over the angle θ_c behind the contact
/// line C at the origin), per unit ρl, by Gauss–Legendre quadrature in polar
/// coordinates about the disk's centre: independent of the code's mass
/// properties.
fn integrate_body(r: f64, b: f64, theta_c: f64, f: impl Fn(f64, f64) -> f64) -> f64 {
    let nodes = gauss_legendre(40);
    let polar = |r_lo: f64, r_hi: f64, phi_lo: f64, phi_hi: f64| {
        let mut sum = 0.0;
        for &(u, wu) in &nodes {
            let rr = 0.5 * (r_lo + r_hi) + 0.5 * (r_hi - r_lo) * u;
            for &(v, wv) in &nodes {
                // φ from the downward vertical, backwards (towards −x).
                let phi = 0.5 * (phi_lo + phi_hi) + 0.5 * (phi_hi - phi_lo) * v;
                let (x, y) = (-rr * phi.sin(), r - rr * phi.cos());
                sum += wu * wv * f(x, y) * rr;
            }
        }
        sum * 0.25 * (r_hi - r_lo) * (phi_hi - phi_lo)
    };
    // The disk in four quarters (the integrand is smooth on each).
    let disk: f64 = (0..4)
        .map(|q| polar(0.0, r, q as f64 * PI / 2.0, (q + 1) as f64 * PI / 2.0))
        .sum();
    let sector: f64 = (0..8)
        .map(|q| {
            polar(
                r,
                r + b,
                q as f64 * theta_c / 8.0,
                (q + 1) as f64 * theta_c / 8.0,
            )
        })
        .sum();
    disk + sector
}

/// "To rounding": sums of a few thousand terms of order r² m.
const ROUNDING: f64 = 1e-12;

/// §6.3: L_E = −θ̇ ∫(X − E)·(X − C) dm before the impact (rotation about C),
/// −θ̇₊ ∫|X − E|² dm after (rotation about E): equal, with the integrals by
/// quadrature over the body, θ̇₊ from the code.
#[test]
fn pivot_impact_conserves_angular_momentum_about_the_impact_line() {
    for (r, b) in [(0.1, 0.01), (0.5, 0.01), (0.1, 0.05), (1.0, 0.002)] {
        let p = PivotImpact::new(r, b);
        // θ_c: where the corner (r + b at the leading edge) touches y = 0.
        let corner_y = r - (r + b) * p.theta_c.cos();
        assert!(corner_y.abs() < ROUNDING * r);
        let d = p.d;
        let before = integrate_body(r, b, p.theta_c, |x, y| (x - d) * x + y * y);
        let after = integrate_body(r, b, p.theta_c, |x, y| (x - d) * (x - d) + y * y);
        let omega = 7.0;
        let (l_before, l_after) = (omega * before, p.omega_after(omega) * after);
        assert!(
            (l_before - l_after).abs() < ROUNDING * l_before,
            "r {r}, b {b}: {l_before} vs {l_after}"
        );
    }
}

/// The first step with `pivot` (defaults, from rest) against
/// `reference/pivot_first_step.csv`: θ̇ before and after the impact, after
/// the pivot and at the start of turn 1. The Python side integrates with
/// RK4 to ~1e-9 relative; 1e-7 leaves margin.
#[test]
fn pivot_first_step_matches_the_reference() {
    let text = include_str!("../../../scripts/derivations/reference/pivot_first_step.csv");
    let mut checked = 0;
    for line in text.lines().filter(|l| l.starts_with("turns")) {
        let f: Vec<&str> = line.split(',').collect();
        let n = |i: usize| f[i].parse::<f64>().unwrap();
        let kind: ModelKind = f[0].parse().unwrap();
        let (alpha, w_minus, w_plus, w_next) = (n(1), n(4), n(5), n(11));
        let s = scenario(alpha, 0.0);
        let p = PivotImpact::new(s.initial_radius(), s.snow_depth());
        assert!((p.theta_c - n(2)).abs() < 1e-10);
        assert!(
            (p.omega_after(w_minus) / w_plus - 1.0).abs() < 1e-9,
            "{line}"
        );
        let opts = SimOptions {
            turns: Some(2),
            t_end: 100.0,
            collision: CollisionModel::Pivot,
            sampling: Sampling::Steps,
            ..SimOptions::default()
        };
        let traj = kind.build().simulate(&s, &opts).unwrap();
        if n(8) < 0.0 {
            // N_E < 0 right after the impact: the log leaves the edge.
            assert_eq!(traj.stop.reason, StopReason::Hop, "{line}");
            let at = traj.stop.turn.unwrap();
            assert!((at.omega_rad_s / w_minus - 1.0).abs() < 1e-7, "{line}");
        } else {
            // Turn 0's row: v after the collision over r_1 is θ̇ at the start of turn 1.
            let table = snowroll::run_turns(kind, &s, &opts).unwrap();
            let r1 = s.initial_radius() + s.snow_depth();
            let w = table.rows[0].v_after_m_s / r1;
            assert!((w / w_next - 1.0).abs() < 1e-7, "{line}: {w}");
        }
        checked += 1;
    }
    assert_eq!(checked, 6);
}

/// §6.2: `charged` takes exactly the potential energy of the jump,
/// m_{k+1} g b cos α, from the kinetic energy (3/4) m_{k+1} v′² of the new
/// turn that eq. (89) leaves; and at 1°, v0 = 0.45 m/s it cannot climb the
/// first step (stuck) while `note` rolls on.
#[test]
fn charged_collision_pays_the_potential_energy_of_the_jump() {
    let (r, b, g_normal) = (0.1, 0.01, 9.81 * (30f64).to_radians().cos());
    for v_end in [0.5, 2.0, 20.0] {
        let v_note = collision_speed(r, b, v_end);
        let v = charged_collision_speed(r, b, g_normal, v_end).unwrap();
        let m_next = 1.0; // per unit m_{k+1}
        let paid = 0.75 * m_next * (v_note * v_note - v * v);
        let want = m_next * g_normal * b;
        assert!((paid - want).abs() < 1e-12 * want.max(v_note * v_note));
    }
    assert!(charged_collision_speed(r, b, g_normal, 0.1).is_none());
    let s = scenario(1.0, 0.45);
    let run = |collision| {
        let opts = SimOptions {
            turns: Some(3),
            t_end: 100.0,
            collision,
            sampling: Sampling::Ends,
            ..SimOptions::default()
        };
        ModelKind::Turns.build().simulate(&s, &opts).unwrap().stop
    };
    let stuck = run(CollisionModel::Charged);
    assert_eq!(stuck.reason, StopReason::Stuck);
    assert_eq!(stuck.turn.unwrap().turn, 0);
    let note = run(CollisionModel::Note);
    assert_ne!(note.reason, StopReason::Stuck);
    assert!(note.turn.unwrap().turn >= 1);
}
