//! The ODE of one circular model on one scenario, `x' = v, v' = a(x, v)`:
//! its contact forces (fn. 10, `docs/contact-forces.md` §2, §5), its stop
//! events, and with the energy ledger the dissipated works as extra states.

use super::rhs::Acceleration;
use super::{Coefficients, Derivation};
use crate::integrate::{Direction, OdeSystem};
use crate::losses::Losses;
use crate::models::contact::{circular_forces, ContactForces};
use crate::models::ledger;
use crate::models::ode::OdeModel;
use crate::scenario::Scenario;
use crate::trajectory::{LedgerRow, OnHop, Sample, SimOptions, StopReason};

/// Event indices of [`CircularSystem`].
const EVENT_STALL: usize = 0;
const EVENT_DISTANCE: usize = 1;
const EVENT_HOP: usize = 2;
const EVENT_SLIP: usize = 3;
const EVENT_TERMINAL: usize = 4;
const EVENT_UNWOUND: usize = 5;

/// The ODE `x' = v, v' = a(x, v)` of one scenario, with the events stall
/// (v = 0), end distance, hop (N = 0), slip (|F| = μN), `docs/contact-forces.md`
/// §2, §5, and terminal velocity (`docs/snowball-and-losses.md` §2.2).
///
/// State `[x, v]` (N = 2), or with the energy ledger (N = 6)
/// `[x, v, D_drag, D_rr, D_comp, W_model]` (J): the dissipated works and the
/// model's own energy defect are integrated as extra states, quadratures on
/// the steps that x and v choose ([`OdeSystem::controlled_components`]):
/// the ledger then closes to the integrator tolerance at every sample,
/// dense output included, and recording it does not change the trajectory.
pub(super) struct CircularSystem<const N: usize> {
    coeffs: Coefficients,
    scenario: Scenario,
    /// `coeffs` bound to `scenario`, for the right-hand side.
    pub(super) accel: Acceleration,
    losses: Losses,
    x_end: Option<f64>,
    mu: Option<f64>,
    stop_on_hop: bool,
    /// `tol × (G − c_rr C)/(1 + k)`, m/s²: the terminal stop's threshold on
    /// |a|, armed only where a terminal velocity exists (§2.2).
    terminal_accel: Option<f64>,
    /// Where an unwinding roll reaches its core, m (`docs/unwinding.md`).
    unwound_at: Option<f64>,
}

impl<const N: usize> CircularSystem<N> {
    pub(super) fn new(
        derivation: Derivation,
        coeffs: Coefficients,
        scenario: &Scenario,
        opts: &SimOptions,
    ) -> Self {
        let l = opts.losses;
        let drive = scenario.g_along() - l.rolling_resistance * scenario.g_normal();
        let (num, den) = coeffs.shape.push_ratio();
        let terminal_accel =
            (!coeffs.accretes && l.drag_coefficient > 0.0 && l.terminal_tol > 0.0 && drive > 0.0)
                .then(|| l.terminal_tol * drive * num / den);
        Self {
            coeffs,
            scenario: *scenario,
            accel: Acceleration::of(derivation, &coeffs, scenario, &l),
            losses: l,
            x_end: opts.x_end,
            mu: opts.mu,
            stop_on_hop: opts.on_hop == OnHop::Stop,
            terminal_accel,
            unwound_at: scenario.unwound_at().filter(|_| coeffs.accretes),
        }
    }

    fn forces(&self, y: &[f64; N]) -> ContactForces {
        let (x, v) = (y[0], y[1]);
        let mut f = circular_forces(&self.coeffs, &self.scenario, x, v, self.accel.at(x, v));
        // Drag is a body force: F = M G − F_d − dp_x/dt (§2.1).
        f.friction_n -= self.mass(x) * self.accel.losses_at(x, v).drag;
        f
    }

    fn mass(&self, x: f64) -> f64 {
        if self.coeffs.accretes {
            crate::physics::mass_at(&self.scenario, x)
        } else {
            self.scenario.initial_mass()
        }
    }

    /// Hop, slip or terminal velocity already at the state `y` (the events
    /// see crossings only).
    pub(super) fn stops_at(&self, y: &[f64; N]) -> Option<StopReason> {
        let f = self.forces(y);
        if self.stop_on_hop && f.normal_n <= 0.0 {
            Some(StopReason::Hop)
        } else if self.mu.is_some_and(|mu| f.slip_margin(mu) >= 0.0) {
            Some(StopReason::Slip)
        } else if self
            .terminal_accel
            .is_some_and(|tol| self.accel.at(y[0], y[1]).abs() <= tol)
        {
            Some(StopReason::Terminal)
        } else {
            None
        }
    }
}

impl<const N: usize> OdeSystem<N> for CircularSystem<N> {
    fn rhs(&self, _t: f64, y: &[f64; N], dy: &mut [f64; N]) {
        let (x, v) = (y[0], y[1]);
        let a = self.accel.at(x, v);
        dy[0] = v;
        dy[1] = a;
        if let Some(rates) = dy.get_mut(2..6) {
            let r = ledger::rates(&self.scenario, &self.coeffs, &self.losses, [x, v, a]);
            rates.copy_from_slice(&r);
        }
    }

    /// x and v; the ledger's works are quadratures (their rates may be
    /// rounding noise about 0, e.g. W_model of `energy`, which the step
    /// control must not chase).
    fn controlled_components(&self) -> usize {
        2
    }

    fn event_count(&self) -> usize {
        6
    }

    fn event(&self, index: usize, _t: f64, y: &[f64; N]) -> f64 {
        match index {
            EVENT_STALL => y[1],
            EVENT_DISTANCE => match self.x_end {
                Some(x_end) => y[0] - x_end,
                None => -1.0,
            },
            EVENT_HOP if self.stop_on_hop => self.forces(y).normal_n,
            EVENT_HOP => 1.0,
            EVENT_SLIP => match self.mu {
                Some(mu) => self.forces(y).slip_margin(mu),
                None => -1.0,
            },
            EVENT_TERMINAL => match self.terminal_accel {
                Some(tol) => self.accel.at(y[0], y[1]).abs() - tol,
                None => 1.0,
            },
            _ => match self.unwound_at {
                Some(x_core) => y[0] - x_core,
                None => -1.0,
            },
        }
    }

    fn event_direction(&self, index: usize) -> Direction {
        match index {
            EVENT_STALL | EVENT_HOP | EVENT_TERMINAL => Direction::Falling,
            _ => Direction::Rising,
        }
    }

    /// N and |F| − μN may have a narrow extremum past zero inside a step
    /// (a peak of |F|/N just above μ, a dip of N just below 0): each step
    /// is searched for it, not only its ends (issue 21).
    fn event_may_turn(&self, index: usize) -> bool {
        match index {
            EVENT_HOP => self.stop_on_hop,
            EVENT_SLIP => self.mu.is_some(),
            _ => false,
        }
    }
}

impl<const N: usize> OdeModel<N> for CircularSystem<N> {
    fn sample(&self, t: f64, y: &[f64; N]) -> Sample {
        let s = &self.scenario;
        let (x, v) = (y[0], y[1]);
        let r = if self.coeffs.accretes {
            crate::physics::radius_at(s, x)
        } else {
            s.initial_radius()
        };
        let a = self.accel.at(x, v);
        let forces = self.forces(y);
        Sample {
            t_s: t,
            x_m: x,
            v_m_s: v,
            a_m_s2: a,
            r_m: r,
            mass_kg: self.mass(x),
            normal_n: forces.normal_n,
            friction_n: forces.friction_n,
            friction_ratio: forces.friction_ratio(),
        }
    }

    fn ledger(&self, _t: f64, y: &[f64; N]) -> Option<LedgerRow> {
        let works = y.get(2..6)?;
        let mut w = [0.0; 4];
        w.copy_from_slice(works);
        Some(ledger::row(&self.scenario, &self.coeffs, y[0], y[1], w))
    }

    fn stop_reason(&self, event: usize) -> StopReason {
        match event {
            EVENT_DISTANCE => StopReason::Distance,
            EVENT_HOP => StopReason::Hop,
            EVENT_SLIP => StopReason::Slip,
            EVENT_TERMINAL => StopReason::Terminal,
            EVENT_UNWOUND => StopReason::Unwound,
            _ => StopReason::Stalled,
        }
    }
}
