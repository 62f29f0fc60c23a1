//! Where a circular run can never hop or slip, so that its ODE need not
//! watch for either (`docs/contact-forces.md` §2).
//!
//! For a log whose equation has neither lift nor the inertia term
//! (eqs. (4), (6), (32): `a = P − D w` with `w = v²/s`, `s = π r²`,
//! `D = c_v b`) the contact forces per unit mass are, as
//! [`circular_forces`](crate::circular_forces) computes them with
//! `q = b w`,
//!
//! `N/M = C + (b/(2π)) (1/r) (P + (b/2 − D) w)`,   `F/M = G − P + (D − b) w`.
//!
//! Along the run `u = v²` is `α1 z + (u0 − α1) z^(−n)` (fn. 4 generalised,
//! `z = s/s0`, `n = 2 c_v`, `α1 = 2 s0 P/(b (n + 1))`), so
//! `w = (α1 + (u0 − α1) z^(−(n+1)))/s0` is monotone in z and stays between
//! `u0/s0` and `α1/s0` for the whole run, however long; `1/r` stays in
//! `(0, 1/r0]`. `N/M` is bilinear in `(1/r, w)` and `|F|/M − μ N/M` is,
//! for each `1/r`, convex in w: their extremes over that rectangle are at
//! its corners. Where N and the friction margin are at least
//! [`MARGIN`] of `M C` at every corner of the rectangle widened by
//! [`WIDEN`] (the integrator's v² is not exactly the closed form's), no
//! state of the run comes near a hop or a slip, and the events are left
//! out: the run is the same, without the cost of watching for them (a
//! third of an ODE sweep row's time).

use std::f64::consts::PI;

use super::Coefficients;
use crate::losses::Losses;
use crate::scenario::{Scenario, Shape};

/// The least normal force and friction margin the bound must leave, as a
/// fraction of M g cos α (that of the closed-form path's contact check).
const MARGIN: f64 = 0.05;
/// The range of `w` is widened by this fraction at each end.
const WIDEN: f64 = 0.01;
/// The loosest rtol for which the integrator's `v²` is taken to stay
/// within [`WIDEN`] of the closed form's.
const MAX_RTOL: f64 = 1e-6;

/// Which contact events of a circular run can never fire.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(super) struct NeverFires {
    /// N stays above [`MARGIN`] M C: no hop.
    pub hop: bool,
    /// μN − |F| stays above [`MARGIN`] μ M C: no slip.
    pub slip: bool,
}

/// The events of the run of `c` in `s` that the bound of the module doc
/// rules out; none where it does not apply (a ball, lift or the inertia
/// term, no snow, losses, rtol looser than [`MAX_RTOL`]).
pub(super) fn never_fires(
    c: &Coefficients,
    s: &Scenario,
    losses: &Losses,
    rtol: f64,
    mu: Option<f64>,
) -> NeverFires {
    let b = s.snow_depth();
    let plain = s.shape() == Shape::Cylinder
        && c.shape == Shape::Cylinder
        && c.accretes
        && c.lift == 0.0
        && c.lift_b2 == 0.0
        && c.inertia_b2 == 0.0
        && c.drag_b3 == 0.0
        && !losses.any()
        && b > 0.0
        && rtol <= MAX_RTOL;
    if !plain {
        return NeverFires::default();
    }
    let (g_along, g_normal) = (s.g_along(), s.g_normal());
    let r0 = s.initial_radius();
    let s0 = PI * r0 * r0;
    let (num, den) = s.shape().push_ratio();
    let push = num * g_along / den;
    let drag = c.drag * b;
    let n = 2.0 * c.drag;
    let alpha1 = 2.0 * s0 * push / (b * (n + 1.0));
    let (w0, w_inf) = (s.initial_speed().powi(2) / s0, alpha1 / s0);
    let ws = [w0.min(w_inf) * (1.0 - WIDEN), w0.max(w_inf) * (1.0 + WIDEN)];
    let margin = MARGIN * g_normal;
    let corners = ws.into_iter().flat_map(|w| [(0.0, w), (1.0 / r0, w)]);
    let (mut hop, mut slip) = (true, mu.is_some());
    for (inv_r, w) in corners {
        let normal = g_normal + b / (2.0 * PI) * inv_r * (push + (b / 2.0 - drag) * w);
        let friction = g_along - push + (drag - b) * w;
        hop &= normal >= margin;
        if let Some(mu) = mu {
            slip &= mu * normal - friction.abs() >= mu * margin;
        }
    }
    let finite = [push, alpha1, ws[0], ws[1]].iter().all(|x| x.is_finite());
    NeverFires {
        hop: hop && finite,
        slip: slip && finite,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::ModelKind;
    use crate::scenario::ScenarioFile;
    use crate::trajectory::{OnHop, SimOptions};

    /// Wherever the bound rules a hop or a slip out, the integrated run
    /// (every step, its forces from `circular_forces`, neither event
    /// watched) keeps N above half the margin of M C, and μN − |F| above
    /// half of μ M C; the grid holds runs that hop and slip (so those are
    /// not ruled out) and runs where the bound rules both out. Fed a sign
    /// error in the bound (`b/2 + D` in N), runs that hop are ruled out and
    /// the check fails.
    #[test]
    fn ruled_out_events_do_not_come_near() {
        let (mut ruled_out, mut kept, mut near) = ([0; 2], [0; 2], [0; 2]);
        for kind in [
            ModelKind::TorqueCm,
            ModelKind::TorqueContact,
            ModelKind::QuasiCircular,
        ] {
            let c = kind.derivation().unwrap().coefficients();
            for alpha_deg in [5.0, 20.0, 40.0, 60.0, 75.0, 85.0] {
                for snow_depth in [0.001, 0.01, 0.1, 0.3] {
                    for r0 in [0.05, 0.1, 0.5] {
                        for v0 in [0.0, 1.0, 5.0, 20.0] {
                            let s = Scenario::new(ScenarioFile {
                                alpha_deg,
                                snow_depth,
                                r0,
                                v0,
                                ..ScenarioFile::default()
                            })
                            .unwrap();
                            let opts = SimOptions {
                                on_hop: OnHop::Continue,
                                t_end: 30.0,
                                ..SimOptions::default()
                            };
                            let mu = 0.3;
                            let never = never_fires(&c, &s, &opts.losses, 1e-10, Some(mu));
                            let run = kind.build().simulate(&s, &opts).unwrap();
                            let mc = |m: f64| m * s.g_normal();
                            let (mut hop_near, mut slip_near) = (false, false);
                            for p in &run.samples {
                                hop_near |= p.normal_n < 0.5 * MARGIN * mc(p.mass_kg);
                                slip_near |= mu * p.normal_n - p.friction_n.abs()
                                    < 0.5 * MARGIN * mu * mc(p.mass_kg);
                            }
                            for (k, (out, close)) in
                                [(never.hop, hop_near), (never.slip, slip_near)]
                                    .into_iter()
                                    .enumerate()
                            {
                                assert!(
                                    !(out && close),
                                    "{kind:?} {alpha_deg} {snow_depth} {r0} {v0}: event {k} \
                                     ruled out but the run comes near it"
                                );
                                ruled_out[k] += usize::from(out);
                                kept[k] += usize::from(!out);
                                near[k] += usize::from(close);
                            }
                        }
                    }
                }
            }
        }
        for k in 0..2 {
            assert!(
                ruled_out[k] > 100 && kept[k] > 10 && near[k] > 0,
                "{ruled_out:?} {kept:?} {near:?}"
            );
        }
    }

    /// Losses, lift, the inertia term, the ball and loose tolerances keep
    /// every event.
    #[test]
    fn outside_the_bound_nothing_is_ruled_out() {
        let s = Scenario::default();
        let c = ModelKind::TorqueCm.derivation().unwrap().coefficients();
        let none = Losses::default();
        assert!(never_fires(&c, &s, &none, 1e-10, Some(1.0)).hop);
        let drag = Losses {
            drag_coefficient: 1.0,
            ..Losses::default()
        };
        assert_eq!(
            never_fires(&c, &s, &drag, 1e-10, Some(1.0)),
            NeverFires::default()
        );
        assert_eq!(
            never_fires(&c, &s, &none, 1e-3, Some(1.0)),
            NeverFires::default()
        );
        for kind in [
            ModelKind::Energy,
            ModelKind::QuasiCircularLift,
            ModelKind::Snowless,
        ] {
            let c = kind.derivation().unwrap().coefficients();
            assert_eq!(
                never_fires(&c, &s, &none, 1e-10, Some(1.0)),
                NeverFires::default()
            );
        }
        let ball = Scenario::new(ScenarioFile {
            shape: Shape::Sphere,
            ..ScenarioFile::default()
        })
        .unwrap();
        let c = ModelKind::TorqueCm
            .derivation()
            .unwrap()
            .coefficients_for(Shape::Sphere);
        assert_eq!(
            never_fires(&c, &ball, &none, 1e-10, Some(1.0)),
            NeverFires::default()
        );
    }
}
