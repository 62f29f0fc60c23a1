//! t(x) and x(t) at any point of the closed form, for the samples of a run
//! (`loney`): the panels of the parent module up to z1, where the series of
//! `series.rs` takes over, and that series beyond. Each value is computed as
//! [`SpeedSquared::run_end`] computes the end of a run, so that a sample at
//! the end of the run is that end.

use super::end::{solve_time_from, Walk};
use super::series::Series;
use super::{Form, SpeedSquared};
use crate::error::SimError;

/// t(x) and x(t) of one closed form, with t(z1) computed once.
#[derive(Debug, Clone, Copy)]
pub(super) struct Clock<'a> {
    u: &'a SpeedSquared,
    /// The series, and t at its start z1, s, where the form has one.
    series: Option<(Series, f64)>,
}

impl SpeedSquared {
    /// x at time t without snow collected (constant acceleration P), m.
    pub(super) fn constant_position(&self, t: f64) -> f64 {
        let v0 = self.u0.sqrt();
        v0 * t + 0.5 * self.push * t * t
    }

    /// The time to roll x without snow collected, `2x/(v0 + √(v0² + 2Px))`, s.
    pub(super) fn constant_time(&self, x: f64) -> f64 {
        let v0 = self.u0.sqrt();
        2.0 * x / (v0 + (self.u0 + 2.0 * self.push * x).sqrt())
    }

    /// The time from the start to `w = √x` over the panels, s.
    fn time_by_panels(&self, w: f64) -> Option<f64> {
        match self.walk_panels((0.0, 0.0), w, f64::INFINITY)? {
            Walk::Arrived(t) => Some(t),
            Walk::Passed(_) => None,
        }
    }

    /// The clock of this closed form.
    ///
    /// # Errors
    /// [`SimError::TimeIntegral`] if t(z1) cannot be integrated.
    pub(super) fn clock(&self) -> Result<Clock<'_>, SimError> {
        let series = match self.series() {
            Some(sr) => {
                let x1 = self.x_of_z(sr.z1);
                let t1 = match sr.t_z1 {
                    Some(t1) => t1,
                    None => self
                        .time_by_panels(x1.sqrt())
                        .ok_or(SimError::TimeIntegral { x: x1 })?,
                };
                Some((sr, t1))
            }
            None => None,
        };
        Ok(Clock { u: self, series })
    }
}

impl Clock<'_> {
    /// The time to roll `x` from the start, s.
    ///
    /// # Errors
    /// [`SimError::TimeIntegral`] if the quadrature fails.
    pub(super) fn time_at(&self, x: f64) -> Result<f64, SimError> {
        let u = self.u;
        if let Form::Constant = u.form {
            return Ok(u.constant_time(x));
        }
        let t = match self.series {
            Some((sr, t1)) if x >= u.x_of_z(sr.z1) => {
                Some(t1 + sr.time_from_z1(1.0 + u.b * x / u.s0))
            }
            _ => u.time_by_panels(x.sqrt()),
        };
        t.filter(|t| t.is_finite())
            .ok_or(SimError::TimeIntegral { x })
    }

    /// The position at time `t`, given the position `x_a` at an earlier
    /// time `t_a` (the last sample: the panels before z1 are integrated
    /// from there, not from the start), m.
    ///
    /// # Errors
    /// [`SimError::Inversion`] if t(x) = t has no solution found.
    pub(super) fn position_after(&self, x_a: f64, t_a: f64, t: f64) -> Result<f64, SimError> {
        let u = self.u;
        if t <= t_a {
            return Ok(x_a);
        }
        if let Form::Constant = u.form {
            return Ok(u.constant_position(t));
        }
        let x = match self.series {
            Some((sr, t1)) if t >= t1 => sr.solve_time(t1, t).map(|z| u.x_of_z(z)),
            _ => solve_time_from(u, x_a.sqrt(), t_a, t).map(|w| w * w),
        };
        x.filter(|x| x.is_finite()).ok_or(SimError::Inversion { t })
    }
}
