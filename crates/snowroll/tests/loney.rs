//! Loney's closed form (fn. 4) for the log and for the ball on its natural
//! swath 2r, as the one closed-form solver computes it (`loney`, its
//! samples, and `DragOnlyClosedForm`), against fn. 4 typed here from the
//! note and t(x) from a quadrature of its own.

use std::f64::consts::PI;

use snowroll::{
    DragOnlyClosedForm, ModelKind, OnHop, Sampling, Scenario, ScenarioFile, Shape, SimOptions,
};

/// The speed from fn. 4, typed independently of the library: with
/// s = π r0² + b x (eq. (8)), p = 2 c_v and push = 1/(1 + k),
/// `u = v0² (s0/s)^p + 2·push·G/(1 + p) · (s0/b) [s/s0 − (s0/s)^p]`
/// (for the log, push = 2/3: `4G/(3(1 + p))`; the ball replaces 2/3 by 5/7).
/// With ε = b x/s0 the bracket is `ε − ((1 + ε)^(−p) − 1)`, the second
/// term from `ln_1p` and `exp_m1`: written as printed it cancels to about
/// 1e-16/ε relative near the start, where the quadrature of t needs it.
fn fn4_speed_squared(s: &Scenario, push: f64, c_v: f64, x: f64) -> f64 {
    let (g, b, v0) = (s.g_along(), s.snow_depth(), s.initial_speed());
    let r0 = s.initial_radius();
    let s0 = PI * r0 * r0;
    let eps = b * x / s0;
    let p = 2.0 * c_v;
    let decay_m1 = (-p * eps.ln_1p()).exp_m1(); // (s0/s)^p − 1
    v0 * v0 * (1.0 + decay_m1) + 2.0 * push * g / (1.0 + p) * (s0 / b) * (eps - decay_m1)
}

/// The body's push 1/(1 + k) and Loney's c_v (eq. (4): 7/6 for the log,
/// 23/14 for the ball's `torque-cm`, `docs/snowball-and-losses.md` §1.4).
fn fn4_constants(shape: Shape) -> (f64, f64) {
    match shape {
        Shape::Cylinder => (2.0 / 3.0, 7.0 / 6.0),
        Shape::Sphere => (5.0 / 7.0, 23.0 / 14.0),
    }
}

/// t(x) = ∫ dx/v by composite Simpson in w = √x (dx = 2w dw, which makes
/// the integrand smooth at a start from rest, where it tends to
/// 2/√(2 push G)), on the speed of [`fn4_speed_squared`].
fn simpson_time(s: &Scenario, push: f64, c_v: f64, x: f64) -> f64 {
    const PANELS: usize = 20_000;
    let f = |w: f64| {
        if w == 0.0 && s.initial_speed() == 0.0 {
            2.0 / (2.0 * push * s.g_along()).sqrt()
        } else {
            2.0 * w / fn4_speed_squared(s, push, c_v, w * w).sqrt()
        }
    };
    let h = x.sqrt() / PANELS as f64;
    let inner: f64 = (1..PANELS)
        .map(|i| {
            let weight = if i % 2 == 1 { 4.0 } else { 2.0 };
            weight * f(i as f64 * h)
        })
        .sum();
    h / 3.0 * (f(0.0) + inner + f(x.sqrt()))
}

fn body(shape: Shape, alpha_deg: f64, snow_depth: f64, v0: f64) -> Scenario {
    Scenario::new(ScenarioFile {
        alpha_deg,
        snow_depth,
        v0,
        shape,
        ..ScenarioFile::default()
    })
    .unwrap()
}

/// The bodies and starts of the comparison: log and ball, from rest and
/// moving, thin and deep snow.
fn cases() -> Vec<Scenario> {
    let mut all = Vec::new();
    for shape in [Shape::Cylinder, Shape::Sphere] {
        for (alpha, b, v0) in [(30.0, 0.01, 0.0), (60.0, 0.1, 0.0), (15.0, 0.03, 2.0)] {
            all.push(body(shape, alpha, b, v0));
        }
    }
    all
}

/// Speed: both forms of fn. 4 avoid the cancellation near the start, and
/// differ by the order of their few roundings (they agree to 1e-14 here);
/// 1e-13 relative leaves room for the exponentials' own error at large
/// p ln(s/s0).
const SPEED_TOL: f64 = 1e-13;
/// Time: Simpson with 20 000 panels in w (step h ≤ 10/20 000) has a
/// truncation error of order h⁴ f⁗/180 ≈ 1e-15 relative on an integrand that
/// varies on the scale √(s0/b) ≥ 0.5 m^½; the 20 000 rounded terms add
/// about 1e-14, and the solver's panels are good to about 1e-13 each (they
/// agree to 1e-13 here): 1e-12.
const TIME_TOL: f64 = 1e-12;

/// The `loney` samples (t, x, v, a) are fn. 4 on the log and on the ball:
/// v = √u(x) of the typed closed form, a = push·G − c_v b v²/(π r²) (the
/// equation of motion), and each sample's time is the Simpson time to its x.
/// The same formula with the other body's push ratio misses by far more
/// than the tolerances (so the ratio is what is being tested).
#[test]
fn fn4_loney_samples_are_the_typed_closed_form_on_log_and_ball() {
    for s in cases() {
        let (push, c_v) = fn4_constants(s.shape());
        let opts = SimOptions {
            t_end: 20.0,
            sampling: Sampling::Times(vec![0.0, 0.05, 0.3, 1.0, 4.0, 20.0]),
            on_hop: OnHop::Continue,
            ..SimOptions::default()
        };
        let traj = ModelKind::Loney.build().simulate(&s, &opts).unwrap();
        assert_eq!(traj.samples.len(), 6, "{s:?}");
        for p in &traj.samples {
            let v = fn4_speed_squared(&s, push, c_v, p.x_m).sqrt();
            let label = format!("{:?} α {} x {}", s.shape(), s.slope_angle(), p.x_m);
            assert!(
                (p.v_m_s - v).abs() <= SPEED_TOL * v.max(1e-300),
                "{label}: v {} vs {v}",
                p.v_m_s
            );
            let area = PI * p.r_m * p.r_m;
            let a = push * s.g_along() - c_v * s.snow_depth() * p.v_m_s * p.v_m_s / area;
            assert!(
                (p.a_m_s2 - a).abs() <= SPEED_TOL * s.g_along(),
                "{label}: a {} vs {a}",
                p.a_m_s2
            );
            if p.t_s > 0.0 {
                let t = simpson_time(&s, push, c_v, p.x_m);
                assert!(
                    (p.t_s - t).abs() <= TIME_TOL * t,
                    "{label}: t {} vs {t}",
                    p.t_s
                );
            }
            // The other body's push ratio is far off.
            let (other, _) = fn4_constants(match s.shape() {
                Shape::Cylinder => Shape::Sphere,
                Shape::Sphere => Shape::Cylinder,
            });
            if p.x_m > 0.0 {
                let wrong = fn4_speed_squared(&s, other, c_v, p.x_m).sqrt();
                assert!((p.v_m_s - wrong).abs() > 1e3 * SPEED_TOL * v, "{label}");
            }
        }
    }
}

/// `DragOnlyClosedForm` (the same solver's u(x), a(x), t(x) and x(t)) is
/// fn. 4 with Simpson's t(x), and x(t) inverts t(x), on the log and the
/// ball, out to 1 km.
#[test]
fn fn4_drag_only_closed_form_gives_u_a_t_and_x_of_t() {
    for s in cases() {
        let (push, c_v) = fn4_constants(s.shape());
        let cf = DragOnlyClosedForm::new(&s, c_v).unwrap();
        for x in [1e-3, 0.2, 3.0, 50.0, 1e3] {
            let u = fn4_speed_squared(&s, push, c_v, x);
            let label = format!("{:?} α {} x {x}", s.shape(), s.slope_angle());
            assert!((cf.speed_squared(x) - u).abs() <= SPEED_TOL * u, "{label}");
            // a = ½ du/dx of the typed form by central differences (step
            // 1e-4 x: error ~1e-8 u''' x²/u', well inside 1e-7).
            let h = 1e-4 * x;
            let du = (fn4_speed_squared(&s, push, c_v, x + h)
                - fn4_speed_squared(&s, push, c_v, x - h))
                / (2.0 * h);
            let a = cf.acceleration(x);
            assert!(
                (a - 0.5 * du).abs() <= 1e-7 * a.abs().max(1e-3),
                "{label}: a {a}"
            );
            let t = simpson_time(&s, push, c_v, x);
            let t_cf = cf.time_at(x).unwrap();
            assert!((t_cf - t).abs() <= TIME_TOL * t, "{label}: t {t_cf} vs {t}");
            let back = cf.position_at(t_cf).unwrap();
            assert!((back - x).abs() <= 1e-11 * x, "{label}: x(t(x)) = {back}");
        }
    }
}

/// The sweep's fast path for `loney` on the ball: where the friction stays
/// well inside μ (μ = 1.3 times the largest |F|/N of the run, the ball's
/// F/M = G − a − 3q/2 and N/M = C + r′(a + q) of `circular_forces`), it
/// takes the row and ends where `loney` itself ends (the same solver, so to
/// rounding: 1e-14); where the ball slips (μ = 0.8 times that ratio) it
/// leaves the row to `loney`, which stops with `slip`. (With the log's
/// contact terms, F/M = G − a − q, the late ratio is 3/2 of the ball's and
/// the first check fails.)
#[test]
fn loney_on_the_ball_takes_the_fast_path_only_clear_of_a_slip() {
    use snowroll::sweep::{circular_end, ContactCheck};
    use snowroll::{Derivation, StopReason};
    const SAME: f64 = 1e-14;
    let s = body(Shape::Sphere, 30.0, 0.01, 0.0);
    let eq4 = Derivation::TorqueAboutCentre.coefficients_for(Shape::Sphere);
    let loney = |mu: Option<f64>| {
        let opts = SimOptions {
            t_end: 50.0,
            sampling: Sampling::Steps,
            on_hop: OnHop::Continue,
            mu,
            ..SimOptions::default()
        };
        ModelKind::Loney.build().simulate(&s, &opts).unwrap()
    };
    let free = loney(None);
    let ratio_max = free
        .samples
        .iter()
        .filter_map(|p| p.friction_ratio)
        .fold(0.0, f64::max);
    assert!(ratio_max > 0.0);
    let check = |mu: f64| ContactCheck {
        stop_on_hop: false,
        mu: Some(mu),
    };
    let end = circular_end(&eq4, &s, 50.0, None, check(1.3 * ratio_max))
        .expect("the fast path takes a run clear of a slip");
    let stop = &loney(Some(1.3 * ratio_max)).stop;
    assert_eq!(stop.reason, StopReason::EndTime);
    for (fast, own) in [(end.t, stop.t_s), (end.x, stop.x_m), (end.v, stop.v_m_s)] {
        assert!((fast - own).abs() <= SAME * own, "{fast} vs {own}");
    }
    assert!(circular_end(&eq4, &s, 50.0, None, check(0.8 * ratio_max)).is_none());
    assert_eq!(loney(Some(0.8 * ratio_max)).stop.reason, StopReason::Slip);
}
