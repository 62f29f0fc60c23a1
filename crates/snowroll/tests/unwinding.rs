//! The unwinding roll (issue 35, `docs/unwinding.md`): a negative snow
//! depth b lays a layer |b| thick down, π r² = π r0² + b x (eq. (8) with
//! b < 0), down to the core radius. Each circular model against a closed
//! form typed here, derived independently of the library's coefficient table
//! (`scripts/derivations/unwinding.py` checks each one with sympy): the
//! textbook energy balance of an unrolling roll for eq. (15), the note's
//! energy (11) for eq. (14), fn. 4 for eq. (4), and the integrals of
//! eqs. (6), (32) and (21).

use std::f64::consts::PI;

use snowroll::{ModelKind, Sampling, Scenario, ScenarioFile, Shape, SimOptions, StopReason};

const G: f64 = 9.81;
/// The roll's radius R, m, and the layer it lays per unit distance, m.
const R: f64 = 0.1;
const B: f64 = -1e-4;
const CORE: f64 = 0.02;

/// The rtol of the runs; the speeds it gives are good to a few times
/// rtol (DOP853 on a smooth right-hand side), well inside [`TOL`].
const RTOL: f64 = 1e-12;
/// The agreement asked of v² (relative): the 1e-9.
const TOL: f64 = 1e-9;

fn roll(shape: Shape, alpha_deg: f64, v0: f64) -> Scenario {
    Scenario::new(ScenarioFile {
        alpha_deg,
        snow_depth: B,
        r0: R,
        g: G,
        v0,
        shape,
        core_radius: Some(CORE),
        ..ScenarioFile::default()
    })
    .unwrap()
}

/// The distance rolled where the radius is `r` (eq. (8)).
fn x_at(r: f64) -> f64 {
    PI * (r * r - R * R) / B
}

/// The end of a run of `model` stopped at distance `x`: (t, v, stop).
fn run_to(model: ModelKind, s: &Scenario, x: f64) -> (f64, f64, StopReason) {
    let mut opts = SimOptions {
        t_end: 1e6,
        x_end: Some(x),
        sampling: Sampling::Ends,
        ..SimOptions::default()
    };
    opts.tolerances.rtol = RTOL;
    opts.tolerances.atol = 1e-14;
    let traj = model.build().simulate(s, &opts).unwrap();
    let end = traj.samples.last().unwrap();
    (end.t_s, end.v_m_s, traj.stop.reason)
}

fn assert_close(what: &str, got: f64, want: f64, tol: f64) {
    assert!(
        (got - want).abs() <= tol * want.abs(),
        "{what}: {got} against {want} (relative {:e})",
        (got - want).abs() / want.abs()
    );
}

/// The radii the speeds are compared at: from just below R to near the core.
const RADII: [f64; 4] = [0.09, 0.07, 0.05, 0.03];

/// Eq. (15) with b < 0 on a level floor is the textbook energy balance of
/// an unrolling roll (Serway, ch. 10): M0 g R = M g r + (3/4) M v², M ∝ r²,
/// the layer's thickness and ṙ² neglected, so v² = 4g(R³ − r³)/(3r²), and
/// at r = R/2, v² = 14gR/3. `quasi-circular-lift` is the same equation.
#[test]
fn eq15_reversed_reproduces_the_textbook_unrolling_speed() {
    let s = roll(Shape::Cylinder, 0.0, 0.0);
    for model in [ModelKind::EnergyThin, ModelKind::QuasiCircularLift] {
        for r in RADII {
            let (_, v, stop) = run_to(model, &s, x_at(r));
            assert_eq!(stop, StopReason::Distance);
            let want = 4.0 * G * (R.powi(3) - r.powi(3)) / (3.0 * r * r);
            assert_close(&format!("{model:?} v² at r = {r}"), v * v, want, TOL);
        }
        let (_, v, _) = run_to(model, &s, x_at(R / 2.0));
        assert_close("v² at R/2", v * v, 14.0 * G * R / 3.0, TOL);
    }
}

/// The time to unwind on eq. (15), level floor: t = ∫ dx/v with
/// dx = 2πr dr/|b|, by Simpson in r from the core to R (the integrand
/// 2πr/(|b| v(r)) behaves as (R − r)^(−1/2) at the start, so it is taken in
/// w = √(R − r), where it is smooth). The run stops with `unwound` there.
#[test]
fn eq15_reversed_unwinds_in_the_time_of_its_quadrature() {
    let s = roll(Shape::Cylinder, 0.0, 0.0);
    let v = |r: f64| (4.0 * G * (R.powi(3) - r.powi(3)) / (3.0 * r * r)).sqrt();
    // r = R − w², dr = −2w dr: t = ∫_0^{√(R − core)} 2w · 2πr/(|b| v(r)) dw.
    let f = |w: f64| {
        if w == 0.0 {
            // v² ≈ 4g(R − r) = 4g w² near R: 2w/v → 1/√g.
            2.0 * PI * R / B.abs() / G.sqrt()
        } else {
            let r = R - w * w;
            2.0 * w * 2.0 * PI * r / (B.abs() * v(r))
        }
    };
    let (n, top) = (20_000, (R - CORE).sqrt());
    let h = top / n as f64;
    let inner: f64 = (1..n)
        .map(|i| if i % 2 == 1 { 4.0 } else { 2.0 } * f(i as f64 * h))
        .sum();
    let t_quad = h / 3.0 * (f(0.0) + inner + f(top));
    let (t, v_end, stop) = run_to(ModelKind::EnergyThin, &s, 1e9);
    assert_eq!(stop, StopReason::Unwound);
    // Simpson with 20 000 panels on a smooth integrand: 1e-12; the run's
    // time is good to about rtol.
    assert_close("time to unwind", t, t_quad, 1e-9);
    assert_close("speed at the core", v_end, v(CORE), TOL);
}

/// Eq. (14) with b < 0 is the derivative of eq. (11): v² from eq. (11)
/// typed here, on a level floor and on a slope.
#[test]
fn eq14_reversed_keeps_the_energy_of_eq11() {
    for alpha_deg in [0.0, 10.0] {
        let s = roll(Shape::Cylinder, alpha_deg, 0.0);
        let (sa, ca) = (s.slope_angle().sin(), s.slope_angle().cos());
        for r in RADII {
            let x = x_at(r);
            // Eq. (11) divided by ρ l: 0 = (3π r²/4 + b²/(8π)) v²
            //   + g [(2π r³ + b² x) cos α + (b x² − 2π r² x) sin α]/2 − π r0³ g cos α.
            let potential = G
                * ((2.0 * PI * r.powi(3) + B * B * x) * ca
                    + (B * x * x - 2.0 * PI * r * r * x) * sa)
                / 2.0
                - PI * R.powi(3) * G * ca;
            let want = -potential / (3.0 * PI * r * r / 4.0 + B * B / (8.0 * PI));
            let (_, v, _) = run_to(ModelKind::Energy, &s, x);
            assert_close(&format!("α = {alpha_deg}, r = {r}"), v * v, want, TOL);
        }
    }
}

/// u = v² for the models whose equation has no lift and no inertia term,
/// `a = push G − c_v b v²/(π r²)` (eqs. (4), (6), (32)): with s = π r²,
/// d(u sⁿ)/ds = (2/b) push G sⁿ, n = 2 c_v, so
/// `u = v0² (s0/s)ⁿ + 2 push G/((n + 1) b) · (s − s0 (s0/s)ⁿ)` (fn. 4's form,
/// which holds for b < 0 as long as s > 0).
fn drag_only(s: &Scenario, push: f64, c_v: f64, r: f64) -> f64 {
    let (s0, sr) = (PI * R * R, PI * r * r);
    let n = 2.0 * c_v;
    let decay = (s0 / sr).powf(n);
    s.initial_speed().powi(2) * decay
        + 2.0 * push * s.g_along() / ((n + 1.0) * B) * (sr - s0 * decay)
}

/// Eqs. (4), (6) and (32) with b < 0: fn. 4's closed form, on a slope from
/// rest and on a level floor pushed off at v0 (where u = v0² (s0/s)ⁿ: the
/// roll speeds up as it thins, from the momentum balance alone).
#[test]
fn eqs_4_6_32_reversed_follow_fn4() {
    for (model, c_v) in [
        (ModelKind::TorqueCm, 7.0 / 6.0),
        (ModelKind::TorqueContact, 1.5),
        (ModelKind::QuasiCircular, 0.5),
    ] {
        for (alpha, v0) in [(10.0, 0.0), (0.0, 0.5)] {
            let s = roll(Shape::Cylinder, alpha, v0);
            for r in RADII {
                let (_, v, _) = run_to(model, &s, x_at(r));
                let want = drag_only(&s, 2.0 / 3.0, c_v, r);
                assert_close(&format!("{model:?} α = {alpha}, r = {r}"), v * v, want, TOL);
            }
        }
    }
    // loney is eq. (4) (its b < 0 runs take the ODE of eq. (4)).
    let s = roll(Shape::Cylinder, 10.0, 0.0);
    let (_, v, _) = run_to(ModelKind::Loney, &s, x_at(0.05));
    assert_close(
        "loney",
        v * v,
        drag_only(&s, 2.0 / 3.0, 7.0 / 6.0, 0.05),
        TOL,
    );
}

/// Eq. (21) as printed with b < 0 on a level floor: with s = π r²,
/// k = b²/(6π), `(s + k) u′ = −2u − 2g r − 2g b/3`, so
/// `u (s + k)² = u0 (s0 + k)² − ∫_{s0}^{s} (σ + k)(2g √(σ/π) + 2g b/3) dσ`,
/// elementary: `∫(σ + k)√σ = (2/5)σ^(5/2) + (2k/3)σ^(3/2)`.
#[test]
fn eq21_reversed_follows_its_integral() {
    let s = roll(Shape::Cylinder, 0.0, 0.0);
    let k = B * B / (6.0 * PI);
    let s0 = PI * R * R;
    let f1 = |q: f64| 0.4 * q.powf(2.5) + 2.0 * k / 3.0 * q.powf(1.5);
    let f2 = |q: f64| q * q / 2.0 + k * q;
    for r in RADII {
        let sr = PI * r * r;
        let want = -(2.0 * G / PI.sqrt() * (f1(sr) - f1(s0))
            + 2.0 * G * B / 3.0 * (f2(sr) - f2(s0)))
            / (sr + k).powi(2);
        let (_, v, _) = run_to(ModelKind::LagrangianPrinted, &s, x_at(r));
        assert_close(&format!("r = {r}"), v * v, want, TOL);
    }
}

/// The ball on its natural swath 2r (the same area law): eq. (15)'s balance
/// for the ball, energy with M ∝ r³, k = 2/5, the layer's thickness and ṙ²
/// neglected: M0 g R = M g r + (7/10) M v², so v² = (10g/7)(R⁴ − r⁴)/r³.
#[test]
fn the_ball_s_eq15_reversed_keeps_its_textbook_energy() {
    let s = roll(Shape::Sphere, 0.0, 0.0);
    for r in RADII {
        let (_, v, _) = run_to(ModelKind::EnergyThin, &s, x_at(r));
        let want = 10.0 * G / 7.0 * (R.powi(4) - r.powi(4)) / r.powi(3);
        assert_close(&format!("ball, r = {r}"), v * v, want, TOL);
    }
}

/// Who starts from rest on a level floor: the energy balances (their lift
/// term, the fall of the centre as r shrinks) and not the momentum and
/// torque balances (a = 0 at v = 0). Those that start unwind to the core,
/// where r is the core radius.
#[test]
fn on_a_level_floor_only_the_energy_balances_start() {
    let s = roll(Shape::Cylinder, 0.0, 0.0);
    for model in ModelKind::ALL
        .into_iter()
        .filter(|m| m.derivation().is_some() || *m == ModelKind::Loney)
    {
        if model == ModelKind::Snowless {
            continue;
        }
        let mut opts = SimOptions {
            t_end: 1e6,
            sampling: Sampling::Ends,
            ..SimOptions::default()
        };
        opts.tolerances.rtol = 1e-10;
        let traj = model.build().simulate(&s, &opts).unwrap();
        let starts = matches!(
            model,
            ModelKind::Energy
                | ModelKind::EnergyThin
                | ModelKind::LagrangianPrinted
                | ModelKind::QuasiCircularLift
        );
        let want = if starts {
            StopReason::Unwound
        } else {
            StopReason::DoesNotStart
        };
        assert_eq!(traj.stop.reason, want, "{model:?}");
        if starts {
            let end = traj.samples.last().unwrap();
            assert_close(&format!("{model:?} core"), end.r_m, CORE, 1e-9);
        }
    }
}

/// The turn models refuse the unwinding roll, saying why; a negative depth
/// needs a core radius, and a core radius needs a negative depth.
#[test]
fn turn_models_refuse_and_the_core_goes_with_a_negative_depth() {
    let s = roll(Shape::Cylinder, 10.0, 0.0);
    for model in [ModelKind::Turns, ModelKind::TurnsExact] {
        let e = model
            .build()
            .simulate(&s, &SimOptions::default())
            .unwrap_err()
            .to_string();
        assert!(e.contains("climbs a step"), "{e}");
    }
    let file = ScenarioFile {
        snow_depth: B,
        ..ScenarioFile::default()
    };
    let e = Scenario::new(file).unwrap_err().to_string();
    assert!(e.contains("needs core_radius"), "{e}");
    let e = Scenario::new(ScenarioFile {
        core_radius: Some(0.05),
        ..ScenarioFile::default()
    })
    .unwrap_err()
    .to_string();
    assert!(e.contains("no core_radius with snow_depth >= 0"), "{e}");
    let e = Scenario::new(ScenarioFile {
        alpha_deg: 0.0,
        ..ScenarioFile::default()
    })
    .unwrap_err()
    .to_string();
    assert!(e.contains("0 <= alpha_deg for an unwinding roll"), "{e}");
    // Compaction: the roll compacts nothing; with b < 0 the term e_c dM/dx
    // would push it (it sped the roll up before it was refused).
    let mut opts = SimOptions::default();
    opts.losses.compaction_energy = 10.0;
    let s = roll(Shape::Cylinder, 5.0, 0.0);
    for model in [ModelKind::EnergyThin, ModelKind::TorqueCm, ModelKind::Loney] {
        let e = model.build().simulate(&s, &opts).unwrap_err().to_string();
        assert!(e.contains("compacts nothing"), "{model:?}: {e}");
    }
    opts.losses.compaction_energy = 0.0;
    opts.losses.rolling_resistance = 0.01;
    assert!(ModelKind::EnergyThin.build().simulate(&s, &opts).is_ok());
}

/// fn. 7's stall slope does not apply to the unwinding roll: every model
/// with a lift term starts on every slope (`snowroll models` lists none),
/// while the same body picking up a layer |b| thick has one.
#[test]
fn fn7_stall_slope_is_none_for_the_unwinding_roll() {
    let unwinding = roll(Shape::Cylinder, 10.0, 0.0);
    let snowy = Scenario::new(ScenarioFile {
        snow_depth: -B,
        core_radius: None,
        ..ScenarioFile::from(unwinding)
    })
    .unwrap();
    for d in [
        snowroll::Derivation::Energy,
        snowroll::Derivation::EnergyLinearised,
        snowroll::Derivation::LagrangianPrinted,
        snowroll::Derivation::QuasiCircularLift,
    ] {
        let none = snowroll::Losses::default();
        assert_eq!(d.stall_slope_in(&unwinding, &none), None, "{d:?}");
        assert!(d.stall_slope_in(&snowy, &none).is_some(), "{d:?}");
    }
}

/// The range of validity in b/r0 holds for the layer's thickness |b|: a
/// roll laying a layer a fifth of its radius thick is warned about, as a
/// log picking it up is.
#[test]
fn validity_warns_on_a_thick_laid_layer() {
    let thick = Scenario::new(ScenarioFile {
        snow_depth: -0.02,
        r0: 0.1,
        core_radius: Some(CORE),
        ..ScenarioFile::default()
    })
    .unwrap();
    let w = snowroll::validity_warnings(ModelKind::EnergyThin, &thick);
    assert!(
        w.iter().any(|w| w.message.contains("b/r0 = 0.2")),
        "{:?}",
        w.iter().map(|w| &w.message).collect::<Vec<_>>()
    );
    let thin = roll(Shape::Cylinder, 10.0, 0.0);
    assert!(snowroll::validity_warnings(ModelKind::EnergyThin, &thin).is_empty());
}

/// A roll nearing its core at hundreds of m/s takes steps of nanoseconds at
/// t ≈ 89 s, where the hop watch's search for an extremum of N asked for a
/// width below the spacing of doubles there and never ended. The run ends
/// (here at the core), well within the 60 s this waits.
#[test]
fn a_fast_roll_near_its_core_ends() {
    let s = Scenario::new(ScenarioFile {
        alpha_deg: 5.0,
        snow_depth: -1e-5,
        r0: R,
        core_radius: Some(1e-5),
        ..ScenarioFile::default()
    })
    .unwrap();
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let opts = SimOptions {
            t_end: 1e4,
            sampling: Sampling::Ends,
            ..SimOptions::default()
        };
        let _ = tx.send(
            ModelKind::Energy
                .build()
                .simulate(&s, &opts)
                .map(|t| t.stop.reason),
        );
    });
    let reason = rx
        .recv_timeout(std::time::Duration::from_secs(60))
        .expect("the run did not end in 60 s")
        .unwrap();
    assert_eq!(reason, StopReason::Unwound);
}
