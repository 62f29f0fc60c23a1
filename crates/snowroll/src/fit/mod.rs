//! Fitting the models to a measured trajectory x(t): least squares by
//! Levenberg–Marquardt (`lm.rs`), one fit per model, each model's own runs
//! as the function fitted (ODE runs, or the closed form of fn. 4 for
//! `loney`), then the covariance s² (JᵀJ)⁻¹ at the end point, the
//! combinations the data cannot separate, AIC and BIC, and a ranking.
//!
//! The free parameters are any real parameters of the scenario or the
//! losses (rows of [`PARAMS`](crate::PARAMS)) and two of the measurement:
//! the time t0 at which the body is let go, on the data's clock
//! ([`START_TIME`]), and its position x0 then, on the data's ruler
//! ([`START_POSITION`]). Each starts from its value in the settings given;
//! the box it is kept in is its row's range (`bounds.rs`).
//!
//! Some parameters enter a model only together: eq. (4) depends on r0 and
//! b only through πr0²/b (πr² = πr0² + b x), so a fit of both finds a line
//! of equally good answers. Such directions are found from the eigenvalues
//! of JᵀJ (scaled by each parameter's size) and reported as
//! [`Unseparated`], with the combination the data do fix, instead of two
//! huge standard errors.

mod bounds;
mod dense;
mod error;
mod lm;
mod stats;
mod synthetic;
mod track;

use crate::model_kind::ModelKind;
use crate::params::{Group, Kind, Param, Settings, Value};

pub use error::FitError;
pub use stats::Unseparated;
pub use synthetic::{noisy, Noise};
pub use track::{Track, MIN_POINTS};

/// The key of the start time t0 among the free parameters, s.
pub const START_TIME: &str = "t0";
/// The key of the start position x0 among the free parameters, m.
pub const START_POSITION: &str = "x0";
/// The free parameters when none are named: the depth (the paper's
/// thickness for the unwinding roll), and the release time and position,
/// which a video rarely shows better than the fit finds them.
pub const DEFAULT_FREE: [&str; 3] = ["snow_depth", START_TIME, START_POSITION];
/// Iterations (Jacobians) at most, by default.
pub const MAX_ITERATIONS: usize = 200;

/// What to fit: the settings (the fixed parameters, and the start of the
/// free ones), the free parameters' keys, and the start (or fixed) t0 and
/// x0 (default: the first data point).
#[derive(Debug, Clone, Default)]
pub struct FitSpec {
    /// Every parameter: the fixed ones' values and the free ones' starts.
    pub settings: Settings,
    /// Whether `settings` carries an atol given by the user (else each
    /// model's default, as `simulate` does).
    pub atol_given: bool,
    /// The free parameters' keys, table keys or [`START_TIME`], [`START_POSITION`].
    pub free: Vec<String>,
    /// t0, s: the start (if free) or the value (if fixed); `None` = the first data time.
    pub t0: Option<f64>,
    /// x0, m: as `t0`; `None` = the first data distance.
    pub x0: Option<f64>,
    /// Iterations at most (0 = [`MAX_ITERATIONS`]).
    pub max_iterations: usize,
}

/// A free parameter as fitted.
#[derive(Debug, Clone, PartialEq)]
pub struct FitParam {
    /// Its key.
    pub key: String,
    /// Its unit.
    pub unit: &'static str,
    /// The best value.
    pub value: f64,
    /// Its standard error; `None` when the data do not fix it (it is in an
    /// [`Unseparated`] combination).
    pub stderr: Option<f64>,
    /// Where the search started.
    pub start: f64,
}

/// One model's fit.
#[derive(Debug, Clone)]
pub struct ModelFit {
    /// The model.
    pub model: ModelKind,
    /// The free parameters, in the order asked for.
    pub params: Vec<FitParam>,
    /// Correlations between the free parameters (`None` for one not fixed
    /// by the data).
    pub correlations: Vec<Vec<Option<f64>>>,
    /// Combinations the data cannot separate.
    pub unseparated: Vec<Unseparated>,
    /// Root mean square of the residuals, m.
    pub rms_m: f64,
    /// Sum of squared residuals, m².
    pub ssr: f64,
    /// Directions of parameter space the data fix (the rank of JᵀJ).
    pub rank_params: usize,
    /// Largest over smallest eigenvalue of JᵀJ, scaled by the parameters' sizes.
    pub condition: f64,
    /// Akaike's criterion.
    pub aic: f64,
    /// The Bayesian (Schwarz) criterion.
    pub bic: f64,
    /// 1 for the best model: converged fits first, then by AIC.
    pub rank: usize,
    /// Whether the search converged.
    pub converged: bool,
    /// Why it stopped.
    pub reason: String,
    /// Iterations taken.
    pub iterations: usize,
    /// The residuals (model − data) at the data times, m.
    pub residuals: Vec<f64>,
    /// The settings at the best values.
    pub settings: Settings,
    /// Whether atol was given.
    atol_given: bool,
    /// t0 and x0 at the best values.
    pub t0: f64,
    /// x0, m.
    pub x0: f64,
}

impl ModelFit {
    /// The fitted model's x at `times` (s, on the data's clock), m: for a
    /// figure of the fit.
    ///
    /// # Errors
    /// [`FitError::Start`] if the run fails.
    pub fn curve(&self, times: &[f64]) -> Result<Vec<f64>, FitError> {
        let model = self.model.build();
        let run = track::Run {
            kind: self.model,
            model: model.as_ref(),
            settings: &self.settings,
            atol_given: self.atol_given,
            t0: self.t0,
            x0: self.x0,
        };
        let mut out = Vec::new();
        run.positions(times, &mut out)
            .map_err(|reason| FitError::Start {
                model: self.model.id(),
                reason,
            })?;
        Ok(out)
    }
}

/// A free parameter: a row of the table, or t0, or x0.
#[derive(Debug, Clone, Copy)]
enum Free {
    Row(&'static Param),
    T0,
    X0,
}

impl Free {
    fn parse(key: &str) -> Result<Free, FitError> {
        match key {
            START_TIME => return Ok(Free::T0),
            START_POSITION => return Ok(Free::X0),
            _ => {}
        }
        match Param::find(key) {
            Some(p) if fittable(p) => Ok(Free::Row(p)),
            Some(p) => Err(FitError::Free(format!(
                "{{free {key}}}: {} is not a real parameter of the scenario or the losses; free \
                 parameters are {}",
                p.key,
                fittable_keys().join(", ")
            ))),
            None => Err(FitError::Free(format!(
                "{{free {key}}}: no such parameter; free parameters are {}",
                fittable_keys().join(", ")
            ))),
        }
    }

    fn key(self) -> &'static str {
        match self {
            Free::Row(p) => p.key,
            Free::T0 => START_TIME,
            Free::X0 => START_POSITION,
        }
    }
}

/// Whether a row can be a free parameter: a real number of the scenario or
/// the losses.
fn fittable(p: &Param) -> bool {
    p.settable()
        && matches!(p.kind, Kind::Real | Kind::OptionalReal)
        && matches!(p.group, Group::Scenario | Group::Losses)
}

/// Every key `--free` takes: the table's real scenario and loss parameters,
/// then t0 and x0.
pub fn fittable_keys() -> Vec<&'static str> {
    crate::PARAMS
        .iter()
        .filter(|p| fittable(p))
        .map(|p| p.key)
        .chain([START_TIME, START_POSITION])
        .collect()
}

/// The parsed free parameters with their starts, boxes and sizes.
struct Plan {
    free: Vec<Free>,
    start: Vec<f64>,
    bounds: Vec<bounds::Bounds>,
    typical: Vec<f64>,
    relative: Vec<bool>,
}

fn plan(track: &Track, spec: &FitSpec) -> Result<Plan, FitError> {
    let mut free: Vec<Free> = Vec::new();
    for key in &spec.free {
        let f = Free::parse(key.trim())?;
        if free.iter().any(|g| g.key() == f.key()) {
            return Err(FitError::Free(format!(
                "{{free {}}} is given twice",
                f.key()
            )));
        }
        free.push(f);
    }
    let (t, x) = (track.t(), track.x());
    let span_t = t[t.len() - 1] - t[0];
    let span_x = x
        .iter()
        .fold(0.0_f64, |a, v| a.max((v - x[0]).abs()))
        .max(1e-3);
    let (mut start, mut bounds, mut typical, mut relative) = (vec![], vec![], vec![], vec![]);
    for f in &free {
        let (s, b, ty, rel) = match f {
            Free::Row(p) => {
                let s = match p.get(&spec.settings) {
                    Value::Real(v) => v,
                    _ => {
                        return Err(FitError::Free(format!(
                            "{{free {0}}}: it has no value to start from; give one with {{{0}}}",
                            p.key
                        )))
                    }
                };
                let b = bounds::Bounds::of(p);
                // Measured relative to its size (so that a combination such
                // as r0^2/snow_depth can be named) unless it starts at 0.
                let rel = s != 0.0;
                (s, b, if s != 0.0 { s.abs() } else { 1e-2 }, rel)
            }
            Free::T0 => (
                spec.t0.unwrap_or_else(|| release_time(track)),
                bounds::Bounds::ALL,
                span_t,
                false,
            ),
            Free::X0 => (spec.x0.unwrap_or(x[0]), bounds::Bounds::ALL, span_x, false),
        };
        start.push(s);
        bounds.push(b);
        typical.push(ty);
        relative.push(rel);
    }
    if track.len() < free.len() + 2 {
        return Err(FitError::Data(format!(
            "{} points for {} free parameters: a fit needs at least two points more than free \
             parameters",
            track.len(),
            free.len()
        )));
    }
    Ok(Plan {
        free,
        start,
        bounds,
        typical,
        relative,
    })
}

/// Where a free t0 starts when none is given: the release time of a body
/// let go from rest at x0 = the first distance with a constant
/// acceleration through the middle point and the last (√(x − x0) is then
/// linear in t); the first data time where that gives nothing sensible
/// (no motion, or a time outside [first − span, middle)).
fn release_time(track: &Track) -> f64 {
    let (t, x) = (track.t(), track.x());
    let (mid, last) = (t.len() / 2, t.len() - 1);
    let (a, b) = ((x[mid] - x[0]).abs().sqrt(), (x[last] - x[0]).abs().sqrt());
    let span = t[last] - t[0];
    if b > a && a > 0.0 {
        let t0 = t[mid] - (t[last] - t[mid]) * a / (b - a);
        if t0 >= t[0] - span && t0 < t[mid] {
            return t0;
        }
    }
    t[0]
}

/// The settings, t0 and x0 at the parameters `p`.
fn at(
    plan: &Plan,
    spec: &FitSpec,
    track: &Track,
    p: &[f64],
) -> Result<(Settings, f64, f64), String> {
    let mut settings = spec.settings.clone();
    let mut t0 = spec.t0.unwrap_or(track.t()[0]);
    let mut x0 = spec.x0.unwrap_or(track.x()[0]);
    for (f, &v) in plan.free.iter().zip(p) {
        match f {
            Free::Row(param) => param
                .set(&mut settings, Value::Real(v))
                .map_err(|e| e.to_string())?,
            Free::T0 => t0 = v,
            Free::X0 => x0 = v,
        }
    }
    Ok((settings, t0, x0))
}

/// Fits each of `models` to `track`, and ranks the fits: those that
/// converged first, each group by AIC (1 = best; equal AIC keeps the order
/// given). The result is sorted by rank.
///
/// # Errors
/// [`FitError::Free`] for a free parameter that cannot be one,
/// [`FitError::Data`] for too few points, [`FitError::Start`] for a model
/// that cannot run at the start.
pub fn fit(track: &Track, models: &[ModelKind], spec: &FitSpec) -> Result<Vec<ModelFit>, FitError> {
    let plan = plan(track, spec)?;
    let mut fits = models
        .iter()
        .map(|&m| fit_one(track, m, spec, &plan))
        .collect::<Result<Vec<_>, _>>()?;
    // Converged fits first, each group by AIC, equal ones in the order given.
    let mut order: Vec<usize> = (0..fits.len()).collect();
    order.sort_by(|&i, &j| {
        fits[j]
            .converged
            .cmp(&fits[i].converged)
            .then(fits[i].aic.total_cmp(&fits[j].aic))
            .then(i.cmp(&j))
    });
    for (rank, &i) in order.iter().enumerate() {
        fits[i].rank = rank + 1;
    }
    fits.sort_by_key(|f| f.rank);
    Ok(fits)
}

fn fit_one(
    track: &Track,
    kind: ModelKind,
    spec: &FitSpec,
    plan: &Plan,
) -> Result<ModelFit, FitError> {
    let model = kind.build();
    let keys: Vec<String> = plan.free.iter().map(|f| f.key().to_string()).collect();
    let mut residuals = |p: &[f64], out: &mut Vec<f64>| -> Result<(), String> {
        let (settings, t0, x0) = at(plan, spec, track, p)?;
        let run = track::Run {
            kind,
            model: model.as_ref(),
            settings: &settings,
            atol_given: spec.atol_given,
            t0,
            x0,
        };
        run.positions(track.t(), out)?;
        for (o, x) in out.iter_mut().zip(track.x()) {
            *o -= x;
        }
        Ok(())
    };
    let problem = lm::Problem {
        start: plan.start.clone(),
        bounds: plan.bounds.clone(),
        typical: plan.typical.clone(),
        max_iterations: match spec.max_iterations {
            0 => MAX_ITERATIONS,
            n => n,
        },
        names: keys.clone(),
        floor: track::accuracy_floor(track, spec.settings.options.tolerances.rtol),
    };
    let start_error = |reason| FitError::Start {
        model: kind.id(),
        reason,
    };
    let out = lm::minimise(&problem, &mut residuals).map_err(start_error)?;
    let summary = stats::summarise(
        &keys,
        &out.p,
        &out.r,
        &out.jac,
        &plan.relative,
        &plan.typical,
    );
    let ssr: f64 = out.r.iter().map(|v| v * v).sum();
    let m = track.len();
    let (aic, bic) = stats::criteria(ssr, m, summary.rank);
    let (settings, t0, x0) = at(plan, spec, track, &out.p).map_err(start_error)?;
    let params = fit_params(plan, &keys, &out.p, &summary.stderr);
    let not_started = track::not_started(kind, &settings, spec.atol_given, (t0, x0), track);
    Ok(ModelFit {
        model: kind,
        params,
        correlations: summary.correlations,
        unseparated: summary.unseparated,
        rms_m: (ssr / m as f64).sqrt(),
        ssr,
        rank_params: summary.rank,
        condition: summary.condition,
        aic,
        bic,
        rank: 0,
        converged: out.converged && not_started.is_none(),
        reason: not_started.map_or(out.reason, str::to_string),
        iterations: out.iterations,
        residuals: out.r,
        settings,
        atol_given: spec.atol_given,
        t0,
        x0,
    })
}

/// The free parameters as fitted, with their units, values `p`, errors and
/// starts.
fn fit_params(plan: &Plan, keys: &[String], p: &[f64], stderr: &[Option<f64>]) -> Vec<FitParam> {
    plan.free
        .iter()
        .enumerate()
        .map(|(j, f)| FitParam {
            key: keys[j].clone(),
            unit: match f {
                Free::Row(row) => row.unit,
                Free::T0 => "s",
                Free::X0 => "m",
            },
            value: p[j],
            stderr: stderr[j],
            start: plan.start[j],
        })
        .collect()
}

/// The models that can run `spec`'s scenario at its starting values, of
/// `candidates` (the default list of `snowroll fit`): each is checked as
/// `simulate` checks it. Returns the ones that can, and for the others the
/// reason.
pub fn models_that_take(
    candidates: &[ModelKind],
    spec: &FitSpec,
) -> (Vec<ModelKind>, Vec<(ModelKind, String)>) {
    let mut ok = Vec::new();
    let mut refused = Vec::new();
    let scenario = match crate::Scenario::new(spec.settings.scenario) {
        Ok(s) => s,
        Err(e) => return (ok, candidates.iter().map(|&m| (m, e.to_string())).collect()),
    };
    for &m in candidates {
        let mut opts = spec.settings.options.clone();
        if !spec.atol_given {
            opts.tolerances.atol = crate::default_atol(m, &scenario);
        }
        match m.build().check(&scenario, &opts) {
            Ok(()) => ok.push(m),
            Err(e) => refused.push((m, e.to_string())),
        }
    }
    (ok, refused)
}
