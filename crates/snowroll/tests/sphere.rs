//! The snowball (issue 11, `docs/snowball-and-losses.md` §1): a uniform ball,
//! I = (2/5) M r², rolling through the layer in every circular model.
//! The oracles are closed forms derived in the doc, and invariants that do
//! not use the models' coefficients (energy, momentum, collected volume).

use std::f64::consts::PI;

use snowroll::integrate::Tolerances;
use snowroll::physics::mechanical_energy;
use snowroll::{
    Derivation, ModelKind, Sampling, Scenario, ScenarioFile, Shape, SimOptions, SwathWidth,
    Trajectory,
};

fn ball(alpha_deg: f64, b: f64, r0: f64, swath_width: Option<f64>) -> Scenario {
    Scenario::new(ScenarioFile {
        alpha_deg,
        snow_depth: b,
        r0,
        shape: Shape::Sphere,
        swath_width: swath_width.map(SwathWidth::Metres),
        ..ScenarioFile::default()
    })
    .unwrap()
}

fn run(kind: ModelKind, s: &Scenario, opts: &SimOptions) -> Trajectory {
    kind.build().simulate(s, opts).unwrap()
}

fn opts(t_end: f64, x_end: Option<f64>, rtol: f64) -> SimOptions {
    SimOptions {
        t_end,
        x_end,
        tolerances: Tolerances {
            rtol,
            atol: 1e-14,
            ..Tolerances::default()
        },
        ..SimOptions::default()
    }
}

/// "Exact to rounding": the snowless ball's 5G/7 is one multiplication and
/// one division of G = g sin α, each correctly rounded, so the computed value
/// is within 2 ulp of the exact (5/7) g sin α evaluated independently here.
const ROUNDING: f64 = 2.0 * f64::EPSILON;

/// Integrated solution against a closed form at rtol 1e-11: the 8th-order
/// integrator's global error stays within a few times rtol over these runs;
/// 1e-9 leaves a factor ~100.
const CLOSED_FORM_TOL: f64 = 1e-9;

#[test]
fn snowless_ball_accelerates_at_five_sevenths_g_sin_alpha_exactly() {
    for alpha_deg in [1.0, 17.0, 30.0, 45.0, 80.0] {
        let s = ball(alpha_deg, 0.01, 0.1, None);
        let g_sin = 9.81 * alpha_deg.to_radians().sin();
        let want = 5.0 / 7.0 * g_sin;
        // Sampled on a grid: the run is one Taylor step (its solution is a
        // polynomial), so the interior samples come from its dense output.
        let sampled = SimOptions {
            sampling: Sampling::Every(0.25),
            ..opts(3.0, None, 1e-10)
        };
        let t = run(ModelKind::Snowless, &s, &sampled);
        assert!(t.samples.len() > 2);
        let m0 = 4.0 / 3.0 * PI * 400.0 * 0.1f64.powi(3);
        for p in &t.samples {
            assert!((p.a_m_s2 - want).abs() <= ROUNDING * want, "{}", p.a_m_s2);
            // x = (5/14) G t² from rest: a closed form of the whole run.
            let x = 5.0 / 14.0 * g_sin * p.t_s * p.t_s;
            assert!((p.x_m - x).abs() <= 1e-12 * x.max(1e-12), "{} {x}", p.x_m);
            assert!((p.mass_kg - m0).abs() <= 1e-14 * m0);
            // N = M g cos α, F = (2/7) M g sin α (doc §1.2): μ_min = (2/7) tan α.
            let c = 9.81 * alpha_deg.to_radians().cos();
            assert!((p.normal_n - m0 * c).abs() <= 1e-13 * m0 * c);
            assert!((p.friction_n - 2.0 / 7.0 * m0 * g_sin).abs() <= 1e-13 * m0 * g_sin);
        }
    }
}

#[test]
fn sphere_terminal_fractions_are_the_docs_rationals() {
    // doc §1.3, ball with w = 2r: 1/[(1 + k)(1 + 2Σ/(n − p))], k = 2/5, n = 3, p = 1.
    let want = [
        (ModelKind::Snowless, 5.0 / 7.0),
        (ModelKind::TorqueCm, 1.0 / 6.0),
        (ModelKind::Loney, 1.0 / 6.0),
        (ModelKind::TorqueContact, 1.0 / 7.0),
        (ModelKind::Energy, 2.0 / 7.0),
        (ModelKind::EnergyThin, 2.0 / 7.0),
        (ModelKind::QuasiCircular, 2.0 / 7.0),
        (ModelKind::QuasiCircularLift, 2.0 / 7.0),
        (ModelKind::LagrangianPrinted, 5.0 / 28.0),
    ];
    let s = ball(30.0, 0.01, 0.1, None);
    for (kind, f) in want {
        let got = kind.terminal_fraction_on(&s).unwrap();
        assert!((got - f).abs() <= 1e-15, "{kind}: {got} vs {f}");
    }
    // A fixed swath (p = 0): torque-cm 15/67 (doc §1.3).
    let fixed = ball(30.0, 0.01, 0.1, Some(0.2));
    let got = ModelKind::TorqueCm.terminal_fraction_on(&fixed).unwrap();
    assert!((got - 15.0 / 67.0).abs() <= 1e-15, "{got}");
    // The turn models have none, and refuse the ball.
    assert!(ModelKind::Turns.terminal_fraction_on(&s).is_none());
    assert!(ModelKind::Turns
        .build()
        .simulate(&s, &SimOptions::default())
        .unwrap_err()
        .to_string()
        .contains("does not support shape = sphere"));
}

#[test]
fn sphere_models_reach_their_terminal_fractions_in_simulation() {
    // Without lift the approach is a power (s0/s)^{1 + 2c_v} (the exact
    // solution u = A s + K s^{−2c_v}); with lift, a − a∞ ≈ −λ₁ C b/((1 + 4c_v) π r)
    // (from u = A s + B √s, derived in `Coefficients::approach_power_in_r`),
    // and what is left is O((b/r)²): 1e-6 relative bounds it at r ≈ 40 m with
    // b = 1 cm (≈ (b/r)² × coefficients of order 10), far above the
    // integrator's 1e-11.
    let s = ball(30.0, 0.01, 0.1, None);
    let (g_along, g_normal) = (s.g_along(), s.g_normal());
    for kind in [
        ModelKind::TorqueCm,
        ModelKind::TorqueContact,
        ModelKind::Energy,
        ModelKind::EnergyThin,
        ModelKind::LagrangianPrinted,
        ModelKind::QuasiCircular,
        ModelKind::QuasiCircularLift,
    ] {
        let t = run(kind, &s, &opts(1e7, Some(5e5), 1e-11));
        let last = t.samples.last().unwrap();
        let c = kind.derivation().unwrap().coefficients_for(Shape::Sphere);
        let a_inf = kind.terminal_fraction_on(&s).unwrap() * g_along;
        let approach = -c.lift * g_normal * 0.01 / ((1.0 + 4.0 * c.drag) * PI * last.r_m);
        let rel = (last.a_m_s2 - a_inf - approach).abs() / a_inf;
        assert!(
            rel < 1e-6,
            "{kind}: a/G = {}, rel {rel:e}",
            last.a_m_s2 / g_along
        );
    }
}

#[test]
fn tpt_letter_closed_form_is_the_balls_torque_cm() {
    // doc §1.4: v² = (G s/(3b)) [1 − (s0/s)^{30/7}], a = (G/6)[1 + (23/7)(s0/s)^{30/7}],
    // and in the letter's variables V = dr/dt: V² = (g b sin α/(12π)) [1 − (r0/r)^{60/7}].
    for (alpha, b, r0) in [(30.0, 0.01, 0.1), (15.0, 0.05, 0.3), (60.0, 0.002, 0.05)] {
        let s = ball(alpha, b, r0, None);
        let g_along = s.g_along();
        let s0 = PI * r0 * r0;
        for kind in [ModelKind::TorqueCm, ModelKind::Loney] {
            let o = SimOptions {
                sampling: Sampling::Every(0.5),
                ..opts(40.0, None, 1e-11)
            };
            let t = run(kind, &s, &o);
            for p in t.samples.iter().skip(1) {
                let area = PI * p.r_m * p.r_m;
                let decay = (s0 / area).powf(30.0 / 7.0);
                let v2 = g_along * area / (3.0 * b) * (1.0 - decay);
                let a = g_along / 6.0 * (1.0 + 23.0 / 7.0 * decay);
                assert!(
                    (p.v_m_s * p.v_m_s - v2).abs() <= CLOSED_FORM_TOL * v2,
                    "{kind}"
                );
                assert!((p.a_m_s2 - a).abs() <= CLOSED_FORM_TOL * a, "{kind}");
                let big_v = b * p.v_m_s / (2.0 * PI * p.r_m);
                let letter = g_along * b / (12.0 * PI) * (1.0 - (r0 / p.r_m).powf(60.0 / 7.0));
                assert!((big_v * big_v - letter).abs() <= CLOSED_FORM_TOL * letter);
            }
            // It starts at (5/7) G ...
            assert!((t.samples[0].a_m_s2 - 5.0 / 7.0 * g_along).abs() <= 1e-12 * g_along);
        }
    }
    // ... and the other derivations do not follow it: at s = 10 s0 their
    // speeds differ from the letter's by more than 1 %.
    let s = ball(30.0, 0.01, 0.1, None);
    let x = 9.0 * PI * 0.01 / 0.01;
    for kind in [
        ModelKind::TorqueContact,
        ModelKind::Energy,
        ModelKind::QuasiCircular,
    ] {
        let t = run(kind, &s, &opts(1e4, Some(x), 1e-11));
        let p = t.samples.last().unwrap();
        let v2 = s.g_along() * 10.0 * PI * 0.01 / (3.0 * 0.01) * (1.0 - 0.1f64.powf(30.0 / 7.0));
        assert!((p.v_m_s * p.v_m_s / v2 - 1.0).abs() > 0.01, "{kind}");
    }
}

#[test]
fn fixed_swath_torque_cm_follows_its_closed_form() {
    // doc §1.1, §1.3 with w fixed: r³ = (3bw/(4π)) X, X = x + x0,
    // x0 = 4π r0³/(3bw); torque-cm a = 5G/7 − (23/7) v²/(3X), so
    // u = v² = A (X − x0^{1+m} X^{−m}) with m = 46/21, A = (10G/7)/(1 + m).
    let (b, r0, w) = (0.01, 0.1, 0.15);
    let s = ball(30.0, b, r0, Some(w));
    let g_along = s.g_along();
    let x0 = 4.0 * PI * r0.powi(3) / (3.0 * b * w);
    let m = 46.0 / 21.0;
    let a_coef = 10.0 / 7.0 * g_along / (1.0 + m);
    let o = SimOptions {
        sampling: Sampling::Every(1.0),
        ..opts(200.0, None, 1e-11)
    };
    let t = run(ModelKind::TorqueCm, &s, &o);
    for p in t.samples.iter().skip(1) {
        let big_x = p.x_m + x0;
        let u = a_coef * (big_x - x0.powf(1.0 + m) * big_x.powf(-m));
        assert!((p.v_m_s * p.v_m_s - u).abs() <= CLOSED_FORM_TOL * u);
        // The growth law and the mass it carries: M = M0 + ρ b w x.
        let r3 = r0.powi(3) + 3.0 * b * w * p.x_m / (4.0 * PI);
        assert!((p.r_m.powi(3) - r3).abs() <= 1e-13 * r3);
        let m0 = 4.0 / 3.0 * PI * 400.0 * r0.powi(3);
        let mass = m0 + 400.0 * b * w * p.x_m;
        assert!((p.mass_kg - mass).abs() <= 1e-12 * mass);
    }
    let last = t.samples.last().unwrap();
    assert!((last.a_m_s2 / g_along - 15.0 / 67.0).abs() < 1e-6);
}

#[test]
fn natural_swath_collects_the_snow_under_the_ball() {
    // π r² = π r0² + b x (doc §1.1), and dM/dx = ρ b (2r): the mass gained
    // over a short distance is the layer under the ball's diameter.
    let (b, r0) = (0.02, 0.1);
    let s = ball(30.0, b, r0, None);
    let o = SimOptions {
        sampling: Sampling::Every(0.25),
        ..opts(30.0, None, 1e-11)
    };
    let t = run(ModelKind::Energy, &s, &o);
    for p in &t.samples {
        let area = PI * r0 * r0 + b * p.x_m;
        assert!((PI * p.r_m * p.r_m - area).abs() <= 1e-13 * area);
        assert!((p.mass_kg - 4.0 / 3.0 * PI * 400.0 * p.r_m.powi(3)).abs() <= 1e-12 * p.mass_kg);
    }
    for pair in t.samples.windows(2).skip(1) {
        let (p, q) = (&pair[0], &pair[1]);
        let dm_dx = (q.mass_kg - p.mass_kg) / (q.x_m - p.x_m);
        // At the midpoint in x the difference quotient is a central
        // difference: its error h² M‴/(24 M′) is at most 2e-4 relative for
        // these steps (h up to 0.9 m while r < 0.35 m); 1e-3 bounds it.
        let r_mid = (r0 * r0 + b * (p.x_m + q.x_m) / (2.0 * PI)).sqrt();
        let want = 400.0 * b * 2.0 * r_mid;
        assert!((dm_dx - want).abs() <= 1e-3 * want, "{dm_dx} {want}");
    }
}

#[test]
fn ball_energy_model_conserves_its_energy() {
    // The ball's `energy` equation is d(T + V)/dt = 0 with
    // T = ½ M (1 + k + r′²) v², V = C[M r − M0 r0 + (b/2)(M − M0)] − G ∫M dx
    // (doc §1.2), for either growth law: an invariant that uses none of the
    // model's coefficients. Tolerance: 1e-9 of the largest |V| reached.
    for w in [None, Some(0.05)] {
        let s = ball(25.0, 0.02, 0.1, w);
        let o = SimOptions {
            sampling: Sampling::Every(0.5),
            ..opts(60.0, None, 1e-11)
        };
        let t = run(ModelKind::Energy, &s, &o);
        let scale = t
            .samples
            .iter()
            .map(|p| snowroll::physics::potential_energy(&s, p.x_m).abs())
            .fold(0.0, f64::max);
        for p in &t.samples {
            let e = mechanical_energy(&s, p.x_m, p.v_m_s);
            assert!(e.abs() <= 1e-9 * scale, "w {w:?}: E = {e} of {scale}");
        }
    }
}

#[test]
fn ball_contact_forces_are_the_momentum_balance() {
    // doc §1.2: N = dp_y/dt + M C, F = M G − dp_x/dt with p = M (v, ṙ); here
    // dp/dt by central differences of p along the integrated run (error
    // O(h²) ≈ 1e-7 relative with h = 1e-3 s), independent of the formulae.
    for w in [None, Some(0.08)] {
        let s = ball(30.0, 0.02, 0.1, w);
        let o = SimOptions {
            sampling: Sampling::Every(1e-3),
            ..opts(5.0, None, 1e-12)
        };
        let t = run(ModelKind::TorqueContact, &s, &o);
        let p_of = |i: usize| {
            let p = &t.samples[i];
            let rdot = if i == 0 {
                0.0
            } else {
                // ṙ from the radius samples themselves.
                (t.samples[i + 1].r_m - t.samples[i - 1].r_m)
                    / (t.samples[i + 1].t_s - t.samples[i - 1].t_s)
            };
            (p.mass_kg * p.v_m_s, p.mass_kg * rdot)
        };
        for i in (100..t.samples.len() - 2).step_by(500) {
            let (px_a, py_a) = p_of(i - 1);
            let (px_b, py_b) = p_of(i + 1);
            let h = t.samples[i + 1].t_s - t.samples[i - 1].t_s;
            let p = &t.samples[i];
            let n = (py_b - py_a) / h + p.mass_kg * s.g_normal();
            let f = p.mass_kg * s.g_along() - (px_b - px_a) / h;
            assert!(
                (p.normal_n - n).abs() <= 1e-6 * n,
                "N {} vs {n}",
                p.normal_n
            );
            assert!(
                (p.friction_n - f).abs() <= 1e-6 * f.abs().max(1.0),
                "F {} vs {f}",
                p.friction_n
            );
        }
    }
}

#[test]
fn the_log_coefficients_follow_from_the_general_balance() {
    // doc §1.2: the generic equations with k = ½, n = 2 reproduce the
    // note's printed coefficients; with k = 2/5, n = 3 the doc's ball column.
    for d in [
        Derivation::Snowless,
        Derivation::TorqueAboutCentre,
        Derivation::TorqueAboutContact,
        Derivation::Energy,
        Derivation::EnergyLinearised,
        Derivation::LagrangianPrinted,
        Derivation::QuasiCircular,
        Derivation::QuasiCircularLift,
    ] {
        let printed = d.coefficients();
        let general = d
            .balance()
            .area_law_coefficients(Shape::Cylinder, printed.accretes);
        assert!((printed.drag - general.drag).abs() < 1e-15, "{d:?}");
        assert!((printed.lift - general.lift).abs() < 1e-15, "{d:?}");
        assert!((printed.lift_b2 - general.lift_b2).abs() < 1e-15, "{d:?}");
        if printed.inertia_b2 != 0.0 || general.inertia_b2 != 0.0 {
            assert!(
                (printed.inertia_b2 - general.inertia_b2).abs() < 1e-15,
                "{d:?}"
            );
        }
        assert!(general.drag_b3.abs() < 1e-15, "{d:?}");
    }
    // The ball, w = 2r (doc §1.2 table): q-coefficients 23/14, 2, 3/4, 3/2.
    let ball = |d: Derivation| d.coefficients_for(Shape::Sphere);
    let close = |a: f64, b: f64| (a - b).abs() < 1e-15;
    assert!(close(ball(Derivation::TorqueAboutCentre).drag, 23.0 / 14.0));
    assert!(close(ball(Derivation::TorqueAboutContact).drag, 2.0));
    assert!(close(ball(Derivation::Energy).drag, 0.75));
    assert!(close(ball(Derivation::LagrangianPrinted).drag, 1.5));
    assert!(close(ball(Derivation::Energy).lift, 10.0 / 7.0));
    assert!(close(ball(Derivation::Energy).lift_b2 / 3.0, 15.0 / 28.0));
    assert!(close(ball(Derivation::Energy).inertia_b2 / 6.0, 5.0 / 28.0));
    assert!(close(ball(Derivation::Energy).drag_b3, 5.0 / 112.0));
    assert!(close(
        ball(Derivation::LagrangianPrinted).drag_b3,
        5.0 / 56.0
    ));
}

/// The sympy values of `scripts/derivations/sphere.py` are printed to 15
/// digits; the library's evaluation differs by rounding only.
const REFERENCE_TOL: f64 = 1e-12;

#[test]
fn ball_accelerations_and_forces_match_the_independent_reference() {
    // `reference/sphere_models.csv`: a, N/M, F/M of the ball (w = 2r) at
    // three states per model, from the generic equations derived in sympy.
    let text = include_str!("../../../scripts/derivations/reference/sphere_models.csv");
    let mut checked = 0;
    for line in text.lines().filter(|l| l.starts_with("sphere,")) {
        let f: Vec<&str> = line.split(',').collect();
        let kind: ModelKind = f[1].parse().unwrap();
        let n = |i: usize| f[i].parse::<f64>().unwrap();
        let (x, v) = (n(3), n(4));
        // Start a run at the state (x, v) of the reference: r0 = r(x).
        let r = (0.1f64 * 0.1 + 0.01 * x / PI).sqrt();
        let s = Scenario::new(ScenarioFile {
            r0: r,
            v0: v,
            shape: Shape::Sphere,
            ..ScenarioFile::default()
        })
        .unwrap();
        let o = SimOptions {
            t_end: 1e-9,
            sampling: Sampling::Ends,
            ..SimOptions::default()
        };
        let p = run(kind, &s, &o).samples[0];
        let close = |got: f64, want: f64| (got - want).abs() <= REFERENCE_TOL * want.abs().max(1.0);
        assert!(close(p.a_m_s2, n(5)), "{line}: a {}", p.a_m_s2);
        assert!(close(p.normal_n / p.mass_kg, n(6)), "{line}: N/M");
        assert!(close(p.friction_n / p.mass_kg, n(7)), "{line}: F/M");
        let (num, den) = f[2].split_once('/').unwrap();
        let fraction = num.parse::<f64>().unwrap() / den.parse::<f64>().unwrap();
        assert!((kind.terminal_fraction_on(&s).unwrap() - fraction).abs() < 1e-15);
        checked += 1;
    }
    assert_eq!(checked, 22);
}

#[test]
fn ball_runs_match_the_independent_rk4_reference() {
    // `reference/circular_mu_min.csv`: each ball model from rest for 100 s
    // (RK4, dt 1e-3, printed to 10 digits): x, v and a/G at the end, and the
    // largest |F|/N of the run (at t = 0 or 100 s for every model). 1e-8
    // relative covers the printed digits and RK4's error (~dt⁴).
    let text = include_str!("../../../scripts/derivations/reference/circular_mu_min.csv");
    let s = ball(30.0, 0.01, 0.1, None);
    let mut checked = 0;
    for line in text.lines().filter(|l| l.starts_with("sphere,")) {
        let f: Vec<&str> = line.split(',').collect();
        let kind: ModelKind = f[1].parse().unwrap();
        let n = |i: usize| f[i].parse::<f64>().unwrap();
        let t = run(kind, &s, &opts(100.0, None, 1e-11));
        let last = t.samples.last().unwrap();
        let mu = t
            .samples
            .iter()
            .filter_map(|p| p.friction_ratio)
            .fold(0.0, f64::max);
        let close = |got: f64, want: f64| (got - want).abs() <= 1e-8 * want.abs();
        assert!(close(mu, n(3)), "{line}: mu {mu}");
        assert!(close(last.x_m, n(6)), "{line}: x {}", last.x_m);
        assert!(close(last.v_m_s, n(7)), "{line}: v {}", last.v_m_s);
        assert!(close(last.a_m_s2 / s.g_along(), n(8)), "{line}: a/G");
        checked += 1;
    }
    assert_eq!(checked, 8);
}
