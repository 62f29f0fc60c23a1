//! The turn-by-turn model of §3 and §3.4 (`turns`, `turns-exact`): limits,
//! invariants within a turn and across a collision, the agreement of the
//! note's three derivations of the first turn, the exact mass properties
//! against the note's first-order forms and against direct quadrature, the
//! stall threshold, and the long-run means the note's eqs. (77)–(79) leave open.
//!
//! Reference formulae are written out here from the note (and `docs/turn-model.md`)
//! rather than taken from the library.

use std::f64::consts::PI;

use proptest::prelude::*;
use snowroll::integrate::Tolerances;
use snowroll::{
    run_turns, ModelKind, Sampling, Scenario, ScenarioFile, SectorBody, SimOptions, StopReason,
    TurnDynamics, TurnMethod, TurnModel, TurnRow, TurnVariant,
};

/// b/r0 of the b → 0 limit.
const TINY_SNOW_RATIO: f64 = 1e-9;
/// a = 2G/3 [1 + O((b/r0)(1 + v²/(G r0)))] (the drag term bv²/r² grows with
/// v), and v²/(G r0) < 30 over five turns: ≤ 3e-8, with margin.
const SNOWLESS_TOL: f64 = 1e-7;
/// Energy drift within one turn at rtol 1e-10: a few accepted steps per
/// turn, each with a local error below rtol, on O(1) state.
const ENERGY_TOL: f64 = 1e-9;
/// Tight integrator tolerances for the identities that hold exactly.
const TIGHT: Tolerances = Tolerances {
    rtol: 1e-14,
    atol: 1e-16,
    max_step: f64::INFINITY,
    max_steps: 100_000_000,
};
/// Eq. (88) for `turns-exact` at rtol 1e-14: integration error plus the
/// rounding of the T and V sums (~1e-15 each), accumulated over 10 turns.
const EQ88_EXACT_TOL: f64 = 1e-12;
/// Fitted power of b/r in a log–log fit over b/r = 0.0025…0.04: the next
/// order, O((b/r)³), shifts the fitted slope by ≲ 0.05 there.
const SLOPE_TOL: f64 = 0.1;
/// Snow depths of the scaling fits, m (b/r0 = 0.0025…0.04, r0 = 0.1 m).
const SCALING_DEPTHS: [f64; 5] = [0.00025, 0.0005, 0.001, 0.002, 0.004];
/// Angular momentum and energy ratio across a collision: a few roundings.
const COLLISION_TOL: f64 = 1e-14;
/// The collision loss is a difference of kinetic energies up to ~25× larger
/// than it (loss fraction 4b/3r ≥ 0.04 here): 25× the rounding of each.
const LOSS_TOL: f64 = 1e-13;
/// Eqs. (55), (58), (64), (69) against each other: a few roundings of the O(1) terms.
const SAME_EQUATION_TOL: f64 = 1e-14;
/// Stall position against the root of W(θ) = 0: the energy error at rtol
/// 1e-14 (≲ 1e-13 relative) over the slope W′ ≳ 1e-3 G r0 at the root.
const STALL_THETA_TOL: f64 = 1e-10;

fn scenario(alpha_deg: f64, snow_depth: f64) -> Scenario {
    Scenario::new(ScenarioFile {
        alpha_deg,
        snow_depth,
        ..ScenarioFile::default()
    })
    .unwrap()
}

fn opts(turns: u64, tolerances: Tolerances) -> SimOptions {
    SimOptions {
        t_end: 1e7,
        turns: Some(turns),
        tolerances,
        ..SimOptions::default()
    }
}

fn rows(kind: ModelKind, s: &Scenario, turns: u64, tol: Tolerances) -> Vec<TurnRow> {
    let table = run_turns(kind, s, &opts(turns, tol)).unwrap();
    assert_eq!(table.stop.reason, StopReason::Turns);
    assert_eq!(table.rows.len() as u64, turns);
    table.rows
}

fn rho_l(s: &Scenario) -> f64 {
    s.density() * s.length()
}

/// r_k = r0 + k b (eq. (74), 0-based).
fn radius(s: &Scenario, k: u64) -> f64 {
    s.initial_radius() + k as f64 * s.snow_depth()
}

/// m_k = πρl r_k² (eq. (75)).
fn mass(s: &Scenario, k: u64) -> f64 {
    PI * rho_l(s) * radius(s, k).powi(2)
}

/// Least-squares slope of ln y against ln x.
fn log_slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (lx, ly): (Vec<f64>, Vec<f64>) = points.iter().map(|(x, y)| (x.ln(), y.ln())).unzip();
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let cov: f64 = lx.iter().zip(&ly).map(|(x, y)| (x - mx) * (y - my)).sum();
    let var: f64 = lx.iter().map(|x| (x - mx).powi(2)).sum();
    cov / var
}

/// Residual of eq. (88) with the corrected eq. (87), in the 0-based turn k:
/// `T_beg − T_end − V_end` with `T_beg = 3m_k v_beg²/4` (eq. (82)),
/// `T_end = m_{k+1}(1 + r_{k+1}²/2r_k²) v_end²/2` (eq. (86)),
/// `V_end = (m_{k+1} − m_k) g (r_k + b/2) cos α − [m_{k+1} − ½(m_{k+1} − m_k)] g 2πr_k sin α`
/// (`docs/errata.md`, (87)). Returned over the work scale `m_k G 2π r_k`.
fn eq88_residual(s: &Scenario, row: &TurnRow) -> f64 {
    let k = row.turn;
    let (r, r1, b) = (radius(s, k), radius(s, k + 1), s.snow_depth());
    let (m, m1) = (mass(s, k), mass(s, k + 1));
    let (gs, gc) = (s.g_along(), s.g_normal());
    let t_beg = 0.75 * m * row.v_start_m_s.powi(2);
    let t_end = m1 * (1.0 + r1 * r1 / (2.0 * r * r)) * row.v_end_m_s.powi(2) / 2.0;
    let v_end = (m1 - m) * gc * (r + b / 2.0) - (m1 - 0.5 * (m1 - m)) * gs * 2.0 * PI * r;
    (t_beg - t_end - v_end) / (m * gs * 2.0 * PI * r)
}

/// `I/m_k` and `W/m_k` of the `paper` variant, as `docs/turn-model.md` states them.
fn paper_inertia_potential(s: &Scenario, r: f64, theta: f64) -> (f64, f64) {
    let (b, gs, gc) = (s.snow_depth(), s.g_along(), s.g_normal());
    let i = 1.5 * r * r + (2.0 * b * r / PI) * (theta - theta.sin());
    let w = -gs * r * theta - (b / PI) * (theta * theta / 2.0 - 1.0 + theta.cos()) * gs
        + (b / PI) * (theta - theta.sin()) * gc;
    (i, w)
}

#[test]
fn b_to_zero_both_variants_roll_at_two_thirds_g_sin_alpha() {
    let s = scenario(30.0, TINY_SNOW_RATIO * 0.1);
    let want = 2.0 * s.g_along() / 3.0;
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        let traj = kind
            .build()
            .simulate(&s, &opts(5, Tolerances::default()))
            .unwrap();
        assert_eq!(traj.stop.reason, StopReason::Turns);
        for sample in &traj.samples {
            assert!(
                (sample.a_m_s2 / want - 1.0).abs() < SNOWLESS_TOL,
                "{kind}: a = {} at t = {}",
                sample.a_m_s2,
                sample.t_s
            );
        }
        let last = traj.samples.last().unwrap();
        assert!((last.v_m_s / (want * last.t_s) - 1.0).abs() < SNOWLESS_TOL);
        for row in rows(kind, &s, 5, Tolerances::default()) {
            for a in [
                row.mean_a_with_collision_m_s2,
                row.min_a_m_s2,
                row.max_a_m_s2,
            ] {
                assert!((a / want - 1.0).abs() < SNOWLESS_TOL, "{kind}: {row:?}");
            }
        }
    }
}

#[test]
fn energy_is_conserved_within_each_turn() {
    let s = Scenario::default();
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        let traj = kind
            .build()
            .simulate(&s, &opts(20, Tolerances::default()))
            .unwrap();
        assert_eq!(traj.samples.len(), traj.turn_states.len());
        // Energy per turn: the truncated one of docs/turn-model.md for `turns`,
        // the exact I_C ω²/2 + V of the disk plus sector for `turns-exact`.
        // Per unit m_k, J/kg.
        let energy = |k: u64, theta: f64, omega: f64| -> f64 {
            let r = radius(&s, k);
            match kind {
                ModelKind::Turns => {
                    let (i, w) = paper_inertia_potential(&s, r, theta);
                    i * omega * omega / 2.0 + w
                }
                _ => {
                    let body = SectorBody::new(r, s.snow_depth(), rho_l(&s));
                    let t = body.kinetic_energy(theta, omega);
                    let v = body.potential_energy(theta, s.g_along(), s.g_normal());
                    (t + v) / mass(&s, k)
                }
            }
        };
        let mut start: Option<(u64, f64)> = None;
        let mut worst: f64 = 0.0;
        for ts in &traj.turn_states {
            let e = energy(ts.turn, ts.theta_rad, ts.omega_rad_s);
            match start {
                Some((k, e0)) if k == ts.turn => {
                    // Relative to the kinetic energy at the start plus the work of gravity over the turn.
                    let r = radius(&s, k);
                    let scale = e0.abs() + 2.0 * PI * s.g_along() * r;
                    worst = worst.max((e - e0).abs() / scale);
                }
                _ => start = Some((ts.turn, e)),
            }
        }
        assert!(worst < ENERGY_TOL, "{kind}: worst relative drift {worst:e}");
    }
}

#[test]
fn eq88_holds_to_rounding_for_turns_exact() {
    let s = Scenario::default();
    for row in rows(ModelKind::TurnsExact, &s, 10, TIGHT) {
        let residual = eq88_residual(&s, &row);
        assert!(
            residual.abs() < EQ88_EXACT_TOL,
            "turn {}: {residual:e}",
            row.turn
        );
    }
}

#[test]
fn eq88_holds_for_turns_only_to_second_order_in_b_over_r() {
    for k in [0u64, 2] {
        let points: Vec<(f64, f64)> = SCALING_DEPTHS
            .iter()
            .map(|&b| {
                let s = scenario(30.0, b);
                let row = rows(ModelKind::Turns, &s, k + 1, TIGHT)[k as usize];
                (b / radius(&s, k), eq88_residual(&s, &row).abs())
            })
            .collect();
        let slope = log_slope(&points);
        assert!(
            (slope - 2.0).abs() < SLOPE_TOL,
            "turn {k}: slope {slope}, {points:?}"
        );
    }
}

#[test]
fn collision_conserves_contact_angular_momentum_and_loses_the_closed_form_energy() {
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        let s = scenario(20.0, 0.02);
        for row in rows(kind, &s, 30, Tolerances::default()) {
            let k = row.turn;
            let (r, r1, m1) = (radius(&s, k), radius(&s, k + 1), mass(&s, k + 1));
            // eq. (85): before, a disk r_{k+1} turning about a line at distance r_k.
            let i_end = m1 * (r1 * r1 / 2.0 + r * r);
            // eq. (81): after, a disk r_{k+1} on its own contact line.
            let i_beg = 1.5 * m1 * r1 * r1;
            let (omega_before, omega_after) = (row.v_end_m_s / r, row.v_after_m_s / r1);
            let (l_before, l_after) = (i_end * omega_before, i_beg * omega_after);
            assert!(
                (l_after / l_before - 1.0).abs() < COLLISION_TOL,
                "{kind} {k}"
            );
            let t_before = i_end * omega_before.powi(2) / 2.0;
            let t_after = i_beg * omega_after.powi(2) / 2.0;
            let ratio = (r1 * r1 + 2.0 * r * r) / (3.0 * r1 * r1);
            assert!((t_after / t_before / ratio - 1.0).abs() < COLLISION_TOL);
            assert!(((t_before - t_after) / row.collision_loss_j - 1.0).abs() < LOSS_TOL);
        }
    }
}

#[test]
fn turns_and_turns_exact_agree_to_second_order_on_the_first_turn() {
    let points: Vec<(f64, f64)> = SCALING_DEPTHS
        .iter()
        .map(|&b| {
            let s = scenario(30.0, b);
            let paper = rows(ModelKind::Turns, &s, 1, TIGHT)[0];
            let exact = rows(ModelKind::TurnsExact, &s, 1, TIGHT)[0];
            let dv = (paper.v_end_m_s / exact.v_end_m_s - 1.0).abs();
            let dt = (paper.t_end_s / exact.t_end_s - 1.0).abs();
            // First order agrees: the differences are far below b/r0.
            assert!(dv < b / s.initial_radius() && dt < b / s.initial_radius());
            (b / s.initial_radius(), dv)
        })
        .collect();
    let slope = log_slope(&points);
    assert!((slope - 2.0).abs() < SLOPE_TOL, "slope {slope}, {points:?}");
}

/// dv/dt of the first turn from the note's equations as written (with the
/// corrections of `docs/errata.md`), for one (θ, v): eqs. (55) (in θ̈), (58), (64), (69) via (67)–(68).
fn note_first_turn_accelerations(s: &Scenario, theta: f64, v: f64) -> [f64; 4] {
    let (b, r0, g, alpha) = (
        s.snow_depth(),
        s.initial_radius(),
        s.gravity(),
        s.slope_angle(),
    );
    let m0 = s.initial_mass();
    let (sa, ca) = alpha.sin_cos();
    let i_c =
        1.5 * m0 * r0 * r0 + 2.0 * m0 * b * r0 * theta / PI - 2.0 * m0 * b * r0 * theta.sin() / PI; // (56)
    let bracket =
        (r0 + b * theta / PI - b * theta.sin() / PI) * sa - (b / PI) * (1.0 - theta.cos()) * ca;
    // (55): m0[3r0²/2 + (br0/π)(2θ − 2 sin θ)] θ̈ + (m0br0/π)(1 − cos θ) θ̇² = m0 g [..]
    let omega = v / r0;
    let theta_dd = (m0 * g * bracket - (m0 * b * r0 / PI) * (1.0 - theta.cos()) * omega * omega)
        / (m0 * (1.5 * r0 * r0 + (b * r0 / PI) * (2.0 * theta - 2.0 * theta.sin())));
    let eq55 = r0 * theta_dd;
    // (58) with m → m0 (`docs/errata.md`): I_C dv/dt + m0bv²(1 − cos θ)/π ≈ m0 g r0 [..]
    let eq58 = (m0 * g * r0 * bracket - m0 * b * v * v * (1.0 - theta.cos()) / PI) / i_c;
    // (64): I_C dv/dt = m0 g r0 [..] − m0bv²(1 − cos θ)/π
    let eq64 = (m0 * g * r0 * bracket - m0 * b * v * v * (1.0 - theta.cos()) / PI) / i_c;
    // (67) = (68) with r → r0 and b/π → bθ/π (`docs/errata.md`):
    // (I_C/r0) dv/dt + 2m0bv²(1 − cos θ)/(πr0) = m0bv²(1 − cos θ)/(πr0)
    //   + m0 g sin α (r0 + bθ/π − (b/π) sin θ) − m0 g cos α (b/π)(1 − cos θ)
    let d_dtheta_l = m0 * b * v * v * (1.0 - theta.cos()) / (PI * r0)
        + m0 * g * sa * (r0 + b * theta / PI - b * theta.sin() / PI)
        - m0 * g * ca * (b / PI) * (1.0 - theta.cos());
    let eq69 = (d_dtheta_l - 2.0 * m0 * b * v * v * (1.0 - theta.cos()) / (PI * r0)) * r0 / i_c;
    [eq55, eq58, eq64, eq69]
}

proptest! {
    #[test]
    fn eq58_eq64_eq69_are_one_equation_and_the_turns_model(
        theta in 0.0..2.0 * PI,
        v in 0.0..20.0f64,
        alpha_deg in 1.0..89.0f64,
        b in 0.0..0.05f64,
    ) {
        let s = scenario(alpha_deg, b);
        let forms = note_first_turn_accelerations(&s, theta, v);
        let model = TurnDynamics::new(TurnVariant::Paper, s.initial_radius(), b, s.g_along(), s.g_normal())
            .acceleration(theta, v / s.initial_radius());
        let scale = s.gravity() + v * v / s.initial_radius();
        for (name, a) in ["(55)", "(58)", "(64)", "(69)"].iter().zip(forms) {
            prop_assert!((a - forms[2]).abs() < SAME_EQUATION_TOL * scale, "{} vs (64): {} {}", name, a, forms[2]);
            prop_assert!((a - model).abs() < SAME_EQUATION_TOL * scale, "{} vs turns: {} {}", name, a, model);
        }
    }
}

#[test]
fn exact_mass_properties_reduce_to_eqs_38_43_48_56_at_first_order() {
    /// If the first-order forms were wrong, (exact − first order)/(b/r0)²
    /// would grow 10× per decade of b; with them right it tends to the b²
    /// coefficient, changing by the O(b³) term only (≤ 10 % per decade here).
    const GROWTH: f64 = 1.2;
    /// Rounding of O(1) quantities divided by (b/r0)² = 1e-8 at the finest b.
    const ROUNDING_FLOOR: f64 = 1e-6;
    let (r0, rho_l) = (0.1, 400.0);
    let m0 = PI * rho_l * r0 * r0;
    // (exact − first order)/(b/r0)², each in its natural unit (m0, r0, m0 r0²).
    let second_order = |ratio: f64, theta: f64| -> [f64; 6] {
        let b = ratio * r0;
        let body = SectorBody::new(r0, b, rho_l);
        let (dx, y) = body.centre_of_mass(theta);
        let i_first = 0.5 * m0 * r0 * r0 + m0 * b * r0 * theta / PI; // (48)
        [
            (body.accreted_mass(theta) - m0 * b * theta / (PI * r0)) / m0, // (38)
            (dx + (b / PI) * (1.0 - theta.cos())) / r0,                    // (43)
            (y - (r0 - (b / PI) * theta.sin())) / r0,                      // (43)
            (body.inertia_contact(theta)
                - (1.5 * m0 * r0 * r0 + 2.0 * m0 * b * r0 * (theta - theta.sin()) / PI))
                / (m0 * r0 * r0), // (56)
            (body.inertia_axis(theta) - i_first) / (m0 * r0 * r0),         // (48)
            (body.inertia_cm(theta) - i_first) / (m0 * r0 * r0),           // (48)
        ]
        .map(|d| d / (ratio * ratio))
    };
    for theta in [0.3, 1.0, PI, 4.5, 2.0 * PI] {
        let q = [1e-2, 1e-3, 1e-4].map(|ratio| second_order(ratio, theta));
        for pair in q.windows(2) {
            for (quantity, (coarse, fine)) in pair[0].iter().zip(&pair[1]).enumerate() {
                assert!(
                    fine.abs() <= GROWTH * coarse.abs() + ROUNDING_FLOOR,
                    "θ = {theta}, quantity {quantity}: {coarse} then {fine}"
                );
            }
        }
    }
}

/// Composite Gauss–Legendre (3 points) over [lo, hi] in `n` panels.
fn integrate(f: impl Fn(f64) -> f64, lo: f64, hi: f64, n: usize) -> f64 {
    let nodes = [-(0.6f64.sqrt()), 0.0, 0.6f64.sqrt()];
    let weights = [5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0];
    let h = (hi - lo) / n as f64;
    (0..n)
        .map(|i| {
            let mid = lo + (i as f64 + 0.5) * h;
            nodes
                .iter()
                .zip(weights)
                .map(|(x, w)| w * f(mid + x * h / 2.0))
                .sum::<f64>()
                * h
                / 2.0
        })
        .sum()
}

#[test]
fn sector_mass_properties_match_direct_quadrature() {
    /// 3-point Gauss–Legendre is exact in r′ (integrands of degree ≤ 3) and
    /// errs by ≤ 6.4e-5 (h/2)⁷ max|f⁽⁶⁾| per θ-panel: ~3e-15 over 200 panels
    /// of h ≤ 2π/200; the rest is rounding of ~1e5 terms.
    const QUADRATURE_TOL: f64 = 1e-12;
    let (r0, b, rho_l) = (0.1, 0.03, 400.0);
    let body = SectorBody::new(r0, b, rho_l);
    for theta in [0.7, 2.5, 2.0 * PI] {
        // ∫∫ ρl r′ dr′ dθ′ f(r′, θ′) over the sector r0 < r′ < r0 + b, 0 < θ′ < θ.
        let sector = |f: &dyn Fn(f64, f64) -> f64| {
            integrate(
                |rp| integrate(|tp| rho_l * rp * f(rp, tp), 0.0, theta, 200),
                r0,
                r0 + b,
                4,
            )
        };
        let m_s = sector(&|_, _| 1.0);
        // Element at (x − r′ sin θ′, r0 − r′ cos θ′) relative to the contact line (x, 0).
        let mx = sector(&|rp, tp| -rp * tp.sin());
        let my = sector(&|rp, tp| r0 - rp * tp.cos());
        let ic = sector(&|rp, tp| (rp * tp.sin()).powi(2) + (r0 - rp * tp.cos()).powi(2));
        let m0 = PI * rho_l * r0 * r0;
        // The disk: mass m0 at (0, r0), I about the contact line 3m0r0²/2.
        let mass = m0 + m_s;
        let (dx, y) = body.centre_of_mass(theta);
        for (got, want) in [
            (body.accreted_mass(theta), m_s),
            (body.mass(theta), mass),
            (dx, mx / mass),
            (y, (m0 * r0 + my) / mass),
            (body.inertia_contact(theta), 1.5 * m0 * r0 * r0 + ic),
        ] {
            assert!(
                (got - want).abs() < QUADRATURE_TOL * want.abs().max(r0),
                "θ = {theta}: {got} vs {want}"
            );
        }
    }
}

/// Largest W(θ)/m0 over the first turn, for the stall threshold from rest:
/// the log completes the turn iff W < 0 on (0, 2π] (energy integral, T = −W).
fn max_potential(kind: ModelKind, s: &Scenario) -> f64 {
    let r0 = s.initial_radius();
    let body = SectorBody::new(r0, s.snow_depth(), rho_l(s));
    (1..=20_000)
        .map(|j| {
            let theta = 2.0 * PI * j as f64 / 20_000.0;
            match kind {
                ModelKind::Turns => paper_inertia_potential(s, r0, theta).1,
                _ => body.potential_energy(theta, s.g_along(), s.g_normal()) / s.initial_mass(),
            }
        })
        .fold(f64::NEG_INFINITY, f64::max)
}

#[test]
fn stall_on_both_sides_of_the_threshold() {
    /// Slopes 1 % either side of the threshold.
    const MARGIN: f64 = 0.01;
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        // Bisection on the slope for max W = 0 (b = 1 cm, r0 = 10 cm: ~1.8°).
        let (mut lo, mut hi) = (0.01, 20.0);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if max_potential(kind, &scenario(mid, 0.01)) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let threshold = 0.5 * (lo + hi);
        assert!(threshold > 1.0 && threshold < 3.0, "{kind}: {threshold}°");

        let below = scenario(threshold * (1.0 - MARGIN), 0.01);
        let traj = kind.build().simulate(&below, &opts(1, TIGHT)).unwrap();
        assert_eq!(traj.stop.reason, StopReason::Stalled, "{kind}");
        let last = traj.turn_states.last().unwrap();
        assert_eq!(last.turn, 0);
        // Where it stops, the energy integral gives θ̇ = 0: W(θ) = 0.
        let dynamics = TurnDynamics::new(
            TurnVariant::of(kind).unwrap(),
            0.1,
            0.01,
            below.g_along(),
            below.g_normal(),
        );
        // First grid point past the stall (W > 0), then bisection for W = 0.
        let grid = 2.0 * PI / 20_000.0;
        let past = (1..=20_000)
            .map(|j| j as f64 * grid)
            .find(|&theta| dynamics.potential(theta).0 > 0.0)
            .unwrap();
        let (mut a, mut c) = (past - grid, past);
        for _ in 0..100 {
            let m = 0.5 * (a + c);
            if dynamics.potential(m).0 < 0.0 {
                a = m;
            } else {
                c = m;
            }
        }
        assert!(
            (last.theta_rad - a).abs() < STALL_THETA_TOL,
            "{kind}: stalled at {} vs W = 0 at {a}",
            last.theta_rad
        );

        let above = scenario(threshold * (1.0 + MARGIN), 0.01);
        let traj = kind.build().simulate(&above, &opts(1, TIGHT)).unwrap();
        assert_eq!(traj.stop.reason, StopReason::Turns, "{kind}");
    }
}

#[test]
fn range_of_a_in_a_turn_matches_a_fine_scan_of_the_energy_integral() {
    /// Scan spacing 2π/2e5: the scan misses an extreme by ≤ a″(1.6e-5)²/2,
    /// a″ ≲ 10 G per rad², i.e. 1.3e-9 G.
    const SCAN_TOL: f64 = 2e-9;
    /// The refined extreme is an evaluated value: it cannot beat the true
    /// one by more than rounding.
    const ROUNDING: f64 = 1e-13;
    let s = Scenario::default();
    let (b, gs, gc) = (s.snow_depth(), s.g_along(), s.g_normal());
    let table = rows(ModelKind::Turns, &s, 60, Tolerances::default());
    for row in table.iter().filter(|r| r.turn < 5 || r.turn == 59) {
        let r = radius(&s, row.turn);
        let omega0 = row.v_start_m_s / r;
        // a(θ) = r(−W′ − ½I′θ̇²)/I with θ̇² = [I(0)θ̇₀² − 2W]/I (docs/turn-model.md, multi-turn algorithm, step 2).
        let a = |theta: f64| {
            let (i, w) = paper_inertia_potential(&s, r, theta);
            let di = (2.0 * b * r / PI) * (1.0 - theta.cos());
            let dw = -gs * r - (b / PI) * (theta - theta.sin()) * gs
                + (b / PI) * (1.0 - theta.cos()) * gc;
            let omega2 = (1.5 * r * r * omega0 * omega0 - 2.0 * w) / i;
            r * (-dw - 0.5 * di * omega2) / i
        };
        let (lo, hi) = (0..=200_000)
            .map(|j| a(2.0 * PI * j as f64 / 200_000.0))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
                (lo.min(x), hi.max(x))
            });
        assert!(
            row.min_a_m_s2 <= lo + ROUNDING * gs && row.min_a_m_s2 >= lo - SCAN_TOL * gs,
            "turn {}: min {} vs scan {lo}",
            row.turn,
            row.min_a_m_s2
        );
        assert!(
            row.max_a_m_s2 >= hi - ROUNDING * gs && row.max_a_m_s2 <= hi + SCAN_TOL * gs,
            "turn {}: max {} vs scan {hi}",
            row.turn,
            row.max_a_m_s2
        );
    }
}

#[test]
fn stops_at_x_end_and_t_end_with_continuous_x() {
    let s = Scenario::default();
    let x_end = 5.0;
    let o = SimOptions {
        x_end: Some(x_end),
        t_end: 1e3,
        ..SimOptions::default()
    };
    let traj = ModelKind::Turns.build().simulate(&s, &o).unwrap();
    assert_eq!(traj.stop.reason, StopReason::Distance);
    assert!((traj.stop.x_m - x_end).abs() < 1e-9);
    // x never decreases, even across the collisions (θ resets, X_k jumps).
    assert!(traj.samples.windows(2).all(|w| w[1].x_m >= w[0].x_m));
    let o = SimOptions {
        t_end: 0.8,
        sampling: Sampling::Ends,
        ..SimOptions::default()
    };
    let traj = ModelKind::TurnsExact.build().simulate(&s, &o).unwrap();
    assert_eq!(traj.stop.reason, StopReason::EndTime);
    assert_eq!(traj.turn_states.last().unwrap().turn, 1);
}

#[test]
fn run_turns_rejects_a_circular_model_by_name() {
    let err = run_turns(ModelKind::Energy, &Scenario::default(), &opts(1, TIGHT)).unwrap_err();
    let text = err.to_string();
    assert!(
        text.contains("energy") && text.contains("turns-exact"),
        "{text}"
    );
}

/// The long-run behaviour that eqs. (77)–(79) leave open, against the
/// leading order in 1/k: with r = kb, energy over a turn gives
/// `(3/4 + 2b/r) v_end² = (3/4) v_beg² + 2πG r`, the collision
/// `v_after² = v_end²(1 − 2b/3r)`, so `v_beg² = (πGb/2) k²`: per turn
/// `Δt = 2πr/v`, the mean with collisions is G/4, within turns G/3, and
/// `a(θ) = (2/3)G − (1/3)G(1 − cos θ)` ranges over [0, 2G/3]. Not 4G/9.
#[test]
fn long_run_means_tend_to_a_third_in_turn_and_a_quarter_with_collisions() {
    /// Means over turns 1000 ≤ k < 10000: corrections O(1/k) ≤ 1e-3, times
    /// the O(1) coefficients seen in the convergence table.
    const LONG_RUN_TOL: f64 = 1e-3;
    let s = Scenario::default();
    for kind in [ModelKind::Turns, ModelKind::TurnsExact] {
        let table = run_turns(kind, &s, &opts(10_000, Tolerances::default())).unwrap();
        let last = table.summary.overall().unwrap();
        assert_eq!(last.turns, 10_000);
        assert_eq!(last.window_first_turn, 1000);
        let checks = [
            (last.window_mean_a_turn_over_g, 1.0 / 3.0),
            (last.window_mean_a_with_collision_over_g, 0.25),
            (last.window_min_a_over_g, 0.0),
            (last.window_max_a_over_g, 2.0 / 3.0),
        ];
        for (got, want) in checks {
            assert!((got - want).abs() < LONG_RUN_TOL, "{kind}: {got} vs {want}");
        }
        assert!((last.mean_a_with_collision_over_g - 4.0 / 9.0).abs() > 0.1);
        // The integrator's work per turn does not grow with k: ten times the
        // turns cost at most ~10× the steps (7.4× measured: the first turns
        // need more steps). The integrator's: the closed form takes no steps.
        let ode = |n| {
            let model = TurnModel::new(TurnVariant::of(kind).unwrap()).with_method(TurnMethod::Ode);
            model
                .run_table(&s, &opts(n, Tolerances::default()))
                .unwrap()
        };
        let ratio = ode(10_000).stats.accepted as f64 / ode(1000).stats.accepted as f64;
        assert!(ratio < 12.0, "{kind}: steps grow as {ratio}");
    }
}
