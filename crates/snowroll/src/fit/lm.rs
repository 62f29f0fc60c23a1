//! Levenberg–Marquardt on a box, with finite-difference Jacobians.
//!
//! Minimises S(p) = Σ rᵢ(p)² where r is the model's x at the data times
//! minus the data. Each iteration takes the Jacobian J by forward
//! differences (one model run per free parameter: the models are ODE runs
//! or closed forms with no derivative of their own with respect to the
//! scenario), then tries steps δ from (JᵀJ + λ D) δ = −Jᵀr, D the diagonal
//! of JᵀJ (Marquardt's scaling, so that parameters of any unit are treated
//! alike), moved into the box of the table's ranges. A step that lowers S
//! is taken and λ shrinks by Nielsen's rule; one that does not, or whose
//! model run fails (a scenario the library refuses, a run that stops before
//! the last data time), is refused and λ grows.

use super::bounds::Bounds;
use super::dense::{normal_equations, Sym};
use super::stats::moving_directions;

/// A least-squares problem: the start, the box, and each parameter's
/// typical size (the scale of its difference step and of the step test).
pub(crate) struct Problem {
    pub start: Vec<f64>,
    pub bounds: Vec<Bounds>,
    pub typical: Vec<f64>,
    pub max_iterations: usize,
    /// Each parameter's name, for errors.
    pub names: Vec<String>,
    /// The S below which the model matches the data to its own accuracy
    /// (the runs' rtol times the size of the distances, per point, squared,
    /// summed): there a step that still promises a relative gain is noise
    /// of the runs and of the difference Jacobian, not a way down.
    pub floor: f64,
}

/// Where the search ended.
#[derive(Debug, Clone)]
pub(crate) struct Outcome {
    /// The parameters.
    pub p: Vec<f64>,
    /// The residuals there (model − data), m.
    pub r: Vec<f64>,
    /// The Jacobian there, one column per parameter.
    pub jac: Vec<Vec<f64>>,
    /// Jacobians taken.
    pub iterations: usize,
    /// Whether a convergence test passed.
    pub converged: bool,
    /// Why the search stopped, in words.
    pub reason: String,
}

/// Relative size of a difference step: about √ of the models' relative
/// accuracy (rtol 1e-10 by default), so that the step's truncation error
/// and the run's own error in the difference are of the same order.
const DIFF_STEP: f64 = 1e-6;
/// The step test: converged when no parameter moves by more than this
/// fraction of its size (or typical size) in an accepted step…
const STEP_TOL: f64 = 1e-8;
/// …or when an accepted step lowers S by less than this fraction of S and
/// moves no parameter by more than [`LOOSE_STEP_TOL`].
const SUM_TOL: f64 = 1e-12;
const LOOSE_STEP_TOL: f64 = 1e-5;
/// Negligible steps while an unlimited Gauss–Newton step would lower S by
/// more than this fraction of it: the search is stuck, not converged.
const STUCK: f64 = 1e-4;
/// Margin inside an open end of a range, relative to the end.
const MARGIN: f64 = 1e-9;

/// A model's residuals at `p`, written into the vector; `Err` with the
/// reason when the model cannot be run there.
pub(crate) type Residuals<'a> = dyn FnMut(&[f64], &mut Vec<f64>) -> Result<(), String> + 'a;

/// Whether a Gauss–Newton gain in S is too small to matter: below 1e-10 of S,
/// or below 0.01 of the residuals' variance S/(N − p), the change of χ² by
/// 0.01 that moves the parameters by a tenth of their standard errors. The
/// finite-difference Jacobian (steps of 1e-6) estimates the gain only to
/// about 1e-8 of S, so with correlated parameters the first test alone took
/// the minimum for a search stuck beside it.
fn negligible(gain: f64, s: f64, dof: usize) -> bool {
    gain <= 1e-10 * s || gain <= 0.01 * s / dof.max(1) as f64
}

/// Why a search that stopped on negligible steps is not converged.
const STUCK_REASON: &str = "stuck: the steps became negligible while a step without limits would \
     still lower the residuals much (the model refuses the parameters just beyond, e.g. a depth \
     reaching 0 or a radius its limit): start nearer the answer";

/// Whether a search that found no step lowering S is at the minimum, and
/// why: the Gauss–Newton `gain` still promised, against S = `s` with `dof`
/// degrees of freedom and the runs' accuracy `floor`.
fn without_a_step(gain: f64, s: f64, dof: usize, floor: f64) -> (bool, &'static str) {
    if gain <= 1e-10 * s || s <= floor {
        (
            true,
            "no step lowers the residuals further (at the minimum to rounding)",
        )
    } else if negligible(gain, s, dof) {
        (
            true,
            "no step lowers the residuals further (within a tenth of the standard errors of the \
             minimum)",
        )
    } else {
        (
            false,
            "no step lowers the residuals, yet the gradient is not zero (stuck, e.g. on a bound or \
             where the model cannot run)",
        )
    }
}

/// Runs the search.
///
/// # Errors
/// The reason the model cannot be run at the start.
pub(crate) fn minimise(problem: &Problem, f: &mut Residuals<'_>) -> Result<Outcome, String> {
    let n = problem.start.len();
    let mut p: Vec<f64> = problem
        .start
        .iter()
        .zip(&problem.bounds)
        .map(|(&x, b)| b.clamp(x, MARGIN))
        .collect();
    let mut r = Vec::new();
    f(&p, &mut r)?;
    let mut s = sum_sq(&r);
    let mut damping = Damping {
        lambda: 1e-3,
        nu: 2.0,
    };
    let mut trial_r = Vec::new();
    let mut iterations = 0;
    let mut moving: Option<usize> = None;
    loop {
        let jac = jacobian(problem, f, &p, &r)?;
        iterations += 1;
        // The parameters that move x(t) at the start (a parameter that
        // stops moving it later has led the search onto a plateau).
        let moving = *moving.get_or_insert_with(|| moving_directions(&jac));
        if n == 0 || s == 0.0 {
            return Ok(done(p, r, jac, iterations, true, "nothing left to fit"));
        }
        let (a, g) = normal_equations(&jac, &r);
        let top = (0..n).map(|j| a.at(j, j)).fold(0.0_f64, f64::max);
        let diag: Vec<f64> = (0..n).map(|j| a.at(j, j).max(1e-12 * top)).collect();
        if top == 0.0 {
            return Ok(done(
                p,
                r,
                jac,
                iterations,
                false,
                "x(t) does not depend on the free parameters",
            ));
        }
        let here = Point {
            p: &p,
            r: &r,
            s,
            jac: &jac,
        };
        let step = damping.step(problem, f, &here, (&a, &g, &diag), &mut trial_r);
        let Some((trial, s_new, taken)) = step else {
            // No step lowers S: converged if the gradient promises nothing
            // measurable, else stuck.
            let gain = gauss_newton_gain(&a, &g, &diag);
            let (stationary, reason) = without_a_step(gain, s, r.len() - n, problem.floor);
            return Ok(plateau(
                done(p, r, jac, iterations, stationary, reason),
                moving,
            ));
        };
        let moved = (0..n)
            .map(|j| taken[j].abs() / (p[j].abs().max(problem.typical[j])))
            .fold(0.0_f64, f64::max);
        let gain = (s - s_new) / s;
        // What a Gauss–Newton step from here promised: about nothing at a
        // minimum; much when the steps were cut short (λ raised) by trial
        // points the model refused, at a limit of its range.
        let promised = gauss_newton_gain(&a, &g, &diag) / s;
        p = trial;
        std::mem::swap(&mut r, &mut trial_r);
        s = s_new;
        let small = moved <= STEP_TOL || (gain <= SUM_TOL && moved <= LOOSE_STEP_TOL);
        let stuck = small
            && promised > STUCK
            && !negligible(promised * s, s, r.len() - n)
            && s > problem.floor;
        if small || iterations >= problem.max_iterations {
            let jac = jacobian(problem, f, &p, &r)?;
            let reason = match (stuck, small) {
                (true, _) => STUCK_REASON,
                (false, true) => "the steps became negligible",
                (false, false) => "reached the most iterations allowed",
            };
            return Ok(plateau(
                done(p, r, jac, iterations, small && !stuck, reason),
                moving,
            ));
        }
    }
}

/// `out`, not converged, when x(t) moves in fewer directions of the
/// parameters at the end than at the start: the search has run onto a
/// plateau (a body that no longer starts, or stops before the data), where
/// every step is negligible but nothing is fitted.
fn plateau(mut out: Outcome, moving: usize) -> Outcome {
    let now = moving_directions(&out.jac);
    if out.converged && now < moving {
        out.converged = false;
        out.reason = format!(
            "the search ran onto a plateau where x(t) changes in {now} direction(s) of the free \
             parameters instead of {moving} at the start (e.g. a body that does not start, or \
             stops before the data): start nearer the answer"
        );
    }
    out
}

/// Where the search stands: the parameters, residuals, S and Jacobian.
struct Point<'a> {
    p: &'a [f64],
    r: &'a [f64],
    s: f64,
    jac: &'a [Vec<f64>],
}

/// Marquardt's λ and Nielsen's factor ν by which a refused step raises it.
struct Damping {
    lambda: f64,
    nu: f64,
}

impl Damping {
    /// Raises λ until a step from `at` lowers S, with the normal equations
    /// `(JᵀJ, Jᵀr, D)`; the trial point, its S and the step taken (moved
    /// into the box), with its residuals in `trial_r`; `None` when λ passes
    /// 10¹⁶ first.
    fn step(
        &mut self,
        problem: &Problem,
        f: &mut Residuals<'_>,
        at: &Point<'_>,
        (a, g, diag): (&Sym, &[f64], &[f64]),
        trial_r: &mut Vec<f64>,
    ) -> Option<(Vec<f64>, f64, Vec<f64>)> {
        let n = at.p.len();
        let rhs: Vec<f64> = g.iter().map(|x| -x).collect();
        while self.lambda <= 1e16 {
            let mut m = a.clone();
            for (j, d) in diag.iter().enumerate() {
                m.set(j, j, a.at(j, j) + self.lambda * d);
            }
            let Some(delta) = m.cholesky_solve(&rhs) else {
                self.lambda *= 10.0;
                continue;
            };
            let trial: Vec<f64> = (0..n)
                .map(|j| problem.bounds[j].clamp(at.p[j] + delta[j], MARGIN))
                .collect();
            let taken: Vec<f64> = (0..n).map(|j| trial[j] - at.p[j]).collect();
            let predicted = at.s - predicted_sum(at.jac, at.r, &taken);
            if f(&trial, trial_r).is_ok() && sum_sq(trial_r) < at.s {
                let s_new = sum_sq(trial_r);
                let rho = if predicted > 0.0 {
                    (at.s - s_new) / predicted
                } else {
                    0.0
                };
                self.lambda *= (1.0 - (2.0 * rho - 1.0).powi(3)).max(1.0 / 3.0);
                self.lambda = self.lambda.max(1e-15);
                self.nu = 2.0;
                return Some((trial, s_new, taken));
            }
            self.lambda *= self.nu;
            self.nu *= 2.0;
        }
        None
    }
}

fn done(
    p: Vec<f64>,
    r: Vec<f64>,
    jac: Vec<Vec<f64>>,
    iterations: usize,
    converged: bool,
    reason: &str,
) -> Outcome {
    Outcome {
        p,
        r,
        jac,
        iterations,
        converged,
        reason: reason.to_string(),
    }
}

fn sum_sq(r: &[f64]) -> f64 {
    r.iter().map(|x| x * x).sum()
}

/// |r + J δ|²: S after the step `delta` as the linear model predicts it.
fn predicted_sum(jac: &[Vec<f64>], r: &[f64], delta: &[f64]) -> f64 {
    (0..r.len())
        .map(|i| {
            let lin = r[i] + jac.iter().zip(delta).map(|(c, d)| c[i] * d).sum::<f64>();
            lin * lin
        })
        .sum()
}

/// The drop in S a lightly damped Gauss–Newton step promises, gᵀ(JᵀJ + εD)⁻¹g.
fn gauss_newton_gain(a: &Sym, g: &[f64], diag: &[f64]) -> f64 {
    let mut m = a.clone();
    for (j, d) in diag.iter().enumerate() {
        m.set(j, j, a.at(j, j) + 1e-9 * d);
    }
    m.cholesky_solve(g)
        .map_or(f64::INFINITY, |x| x.iter().zip(g).map(|(a, b)| a * b).sum())
}

/// Forward differences, one run per parameter; backwards where the step
/// forwards leaves the box or the model cannot run there.
fn jacobian(
    problem: &Problem,
    f: &mut Residuals<'_>,
    p: &[f64],
    r: &[f64],
) -> Result<Vec<Vec<f64>>, String> {
    let mut jac = Vec::with_capacity(p.len());
    let mut moved = p.to_vec();
    let mut out = Vec::new();
    for j in 0..p.len() {
        let h = DIFF_STEP * p[j].abs().max(problem.typical[j]);
        let b = &problem.bounds[j];
        let mut column = None;
        for step in [h, -h] {
            let x = p[j] + step;
            if !b.contains(x, MARGIN) {
                continue;
            }
            moved[j] = x;
            let ok = f(&moved, &mut out);
            moved[j] = p[j];
            if ok.is_ok() {
                let actual = x - p[j];
                column = Some(out.iter().zip(r).map(|(a, b)| (a - b) / actual).collect());
                break;
            }
        }
        jac.push(column.ok_or_else(|| {
            format!(
                "the model cannot be run on either side of {} = {}",
                problem.names[j],
                crate::format_number(p[j])
            )
        })?);
    }
    Ok(jac)
}
