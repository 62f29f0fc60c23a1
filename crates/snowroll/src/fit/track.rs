//! A measured trajectory (times and distances) and a model's x at its
//! times: the run the fit repeats for every trial of the parameters.

use crate::error::SinkError;
use crate::models::{default_atol, Model};
use crate::params::Settings;
use crate::scenario::Scenario;
use crate::trajectory::{Sample, SampleSink, Sampling, StopReason, TurnState};
use crate::ModelKind;

use super::FitError;

/// Fewest points a track may have: a fit of one parameter and its error
/// need two more points than parameters, and a trajectory of fewer than 5
/// points shows no curvature to tell models apart.
pub const MIN_POINTS: usize = 5;

/// Times and distances along the slope, s and m, the times strictly
/// increasing, every value finite.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    t: Vec<f64>,
    x: Vec<f64>,
}

impl Track {
    /// Checks and keeps `t` and `x`.
    ///
    /// # Errors
    /// [`FitError::Data`] naming the first bad point (counted from 1):
    /// lengths that differ, fewer than [`MIN_POINTS`], a value not finite,
    /// a time not after the one before.
    pub fn new(t: Vec<f64>, x: Vec<f64>) -> Result<Self, FitError> {
        if t.len() != x.len() {
            return Err(FitError::Data(format!(
                "{} times but {} distances: give one distance per time",
                t.len(),
                x.len()
            )));
        }
        if t.len() < MIN_POINTS {
            return Err(FitError::Data(format!(
                "{} points: a fit needs at least {MIN_POINTS}",
                t.len()
            )));
        }
        for (i, (&ti, &xi)) in t.iter().zip(&x).enumerate() {
            if !ti.is_finite() || !xi.is_finite() {
                return Err(FitError::Data(format!(
                    "point {}: t = {ti}, x = {xi}: every value must be a finite number",
                    i + 1
                )));
            }
            if i > 0 && ti <= t[i - 1] {
                return Err(FitError::Data(format!(
                    "point {}: t = {ti} s is not after the point before (t = {} s): times must \
                     increase",
                    i + 1,
                    t[i - 1]
                )));
            }
        }
        Ok(Self { t, x })
    }

    /// The times, s.
    pub fn t(&self) -> &[f64] {
        &self.t
    }

    /// The distances, m.
    pub fn x(&self) -> &[f64] {
        &self.x
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.t.len()
    }

    /// Always false: a track has at least [`MIN_POINTS`] points.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }
}

/// x of each sample, m.
struct Positions(Vec<f64>);

impl SampleSink for Positions {
    fn sample(&mut self, sample: &Sample, _turn: Option<&TurnState>) -> Result<(), SinkError> {
        self.0.push(sample.x_m);
        Ok(())
    }
}

/// One model run as the fit sees it: the model, the settings, and the
/// start time t0 and position x0 of the run on the data's clock and ruler.
pub(crate) struct Run<'a> {
    pub kind: ModelKind,
    pub model: &'a dyn Model,
    pub settings: &'a Settings,
    /// Whether the settings' atol was given (else the model's default).
    pub atol_given: bool,
    pub t0: f64,
    pub x0: f64,
}

impl Run<'_> {
    /// x at each of `times`, into `out`: x0 before t0 (the body is let go
    /// at t0), x0 plus the run's distance after. A run that stalls or does
    /// not start stays where it stopped. Returns why the run stopped (`None`
    /// when every time is before t0, so that nothing ran).
    ///
    /// # Errors
    /// The reason in words: a scenario or options the library refuses, a
    /// failed run, a run that stops (a hop, a slip, …) before the last time.
    pub fn positions(
        &self,
        times: &[f64],
        out: &mut Vec<f64>,
    ) -> Result<Option<StopReason>, String> {
        out.clear();
        let taus: Vec<f64> = times
            .iter()
            .map(|t| t - self.t0)
            .filter(|&tau| tau > 0.0)
            .collect();
        let before = times.len() - taus.len();
        out.resize(before, self.x0);
        let Some(&last) = taus.last() else {
            return Ok(None);
        };
        let scenario = Scenario::new(self.settings.scenario).map_err(|e| e.to_string())?;
        let mut opts = self.settings.options.clone();
        opts.sampling = Sampling::Times(taus);
        opts.t_end = last;
        opts.x_end = None;
        if !self.atol_given {
            opts.tolerances.atol = default_atol(self.kind, &scenario);
        }
        let mut sink = Positions(Vec::with_capacity(times.len() - before));
        let end = self
            .model
            .simulate_into(&scenario, &opts, &mut sink)
            .map_err(|e| e.to_string())?;
        let wanted = times.len() - before;
        if sink.0.len() < wanted {
            let rests = matches!(
                end.stop.reason,
                StopReason::Stalled | StopReason::DoesNotStart
            );
            if !rests {
                return Err(format!(
                    "the run stopped at t = {} s ({}) before the last data time",
                    crate::format_number(end.stop.t_s + self.t0),
                    end.stop.reason.describe()
                ));
            }
            let held = sink.0.last().copied().unwrap_or(0.0);
            sink.0.resize(wanted, held);
        }
        out.extend(sink.0.iter().map(|x| self.x0 + x));
        if out.iter().any(|x| !x.is_finite()) {
            return Err("the run gave a distance that is not finite".into());
        }
        Ok(Some(end.stop.reason))
    }
}

/// S at which the runs match the data to their own accuracy: each point off
/// by `rtol` times the largest distance of the track ([`super::lm::Problem::floor`]).
pub(crate) fn accuracy_floor(track: &Track, rtol: f64) -> f64 {
    let size = track.x().iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    let off = rtol * size;
    track.len() as f64 * off * off
}

/// Why a fit is not converged though its search is, when the run of `kind`
/// at the fitted `settings`, let go at `(t0, x0)`, does not start: it then
/// stays at x0 and cannot follow data that move; `None` otherwise (or when
/// it cannot run).
pub(crate) fn not_started(
    kind: ModelKind,
    settings: &Settings,
    atol_given: bool,
    (t0, x0): (f64, f64),
    track: &Track,
) -> Option<&'static str> {
    let model = kind.build();
    let run = Run {
        kind,
        model: model.as_ref(),
        settings,
        atol_given,
        t0,
        x0,
    };
    let stop = run.positions(track.t(), &mut Vec::new()).ok().flatten()?;
    (stop == StopReason::DoesNotStart).then_some(
        "the model does not start from rest here (its acceleration at rest is not positive, e.g. \
         a torque balance on a level floor), so x(t) stays at x0 and cannot follow the data",
    )
}
