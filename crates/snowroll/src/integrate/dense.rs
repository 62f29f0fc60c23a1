//! The dense output of a step (DOP853's 7th-order interpolant, or a Taylor
//! step's own series) and the view of a step that the observer gets.

// The polynomial is evaluated component by component, as on paper.
#![allow(clippy::needless_range_loop)]

/// Coefficient vectors of the dense polynomial (Hairer's `CONT(2..8)`).
pub(super) const DENSE_TERMS: usize = 7;

/// The dense polynomial of one accepted step `(t, y) → (t + h, y_new)`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Polynomial<'a, const N: usize> {
    /// Start of the full step.
    pub t: f64,
    /// Length of the full step.
    pub h: f64,
    /// The polynomial's coefficients, by the method that took the step.
    pub form: Form<'a, N>,
}

/// The coefficients of a [`Polynomial`].
#[derive(Debug, Clone, Copy)]
pub(super) enum Form<'a, const N: usize> {
    /// DOP853's 7th-order interpolant: the state `y` at `t` and Hairer's `F0..F6`.
    Hairer {
        /// State at `t`.
        y: &'a [f64; N],
        /// Coefficients `F0..F6`.
        f: &'a [[f64; N]; DENSE_TERMS],
    },
    /// A Taylor step's own series: `c[k] = y⁽ᵏ⁾(t)/k!`, `c[0] = y`.
    Taylor(&'a [[f64; N]]),
}

impl<const N: usize> Polynomial<'_, N> {
    /// The state at time `tt`. DOP853: with `s = (tt − t)/h`,
    /// `y + s(F0 + (1−s)(F1 + s(F2 + (1−s)(F3 + s(F4 + (1−s)(F5 + s F6))))))`
    /// (Hairer's `CONTD8`); Taylor: `Σ c[k] (tt − t)^k` by Horner's rule.
    pub fn at(&self, tt: f64) -> [f64; N] {
        match self.form {
            Form::Hairer { y, f } => {
                let s = (tt - self.t) / self.h;
                let mut out = [0.0; N];
                for (i, fi) in f.iter().rev().enumerate() {
                    let factor = if i % 2 == 0 { s } else { 1.0 - s };
                    for n in 0..N {
                        out[n] = (out[n] + fi[n]) * factor;
                    }
                }
                for n in 0..N {
                    out[n] += y[n];
                }
                out
            }
            Form::Taylor(c) => horner(c, tt - self.t),
        }
    }
}

/// `Σ c[k] dt^k`, component by component, by Horner's rule.
#[inline]
pub(super) fn horner<const N: usize>(c: &[[f64; N]], dt: f64) -> [f64; N] {
    let Some((last, rest)) = c.split_last() else {
        return [0.0; N];
    };
    let mut out = *last;
    for ck in rest.iter().rev() {
        for n in 0..N {
            out[n] = out[n] * dt + ck[n];
        }
    }
    out
}

/// One accepted step as the observer sees it: the interval `(t_old, t_new]`
/// and, when asked for, the 7th-order dense output on it.
///
/// A step that contains located events is cut at each of them, so the
/// observer sees the pieces and the events in time order.
#[derive(Debug)]
pub struct DenseStep<'a, const N: usize> {
    /// Start of the step (or of the piece after an event).
    pub t_old: f64,
    /// End of the step (earlier than the full step when cut at an event).
    pub t_new: f64,
    /// State at `t_old`.
    pub y_old: &'a [f64; N],
    /// State at `t_new`.
    pub y_new: &'a [f64; N],
    dense: Option<Polynomial<'a, N>>,
}

impl<'a, const N: usize> DenseStep<'a, N> {
    /// The piece `(t_old, t_new]` of a step, with its polynomial if any.
    pub(super) fn new(
        (t_old, y_old): (f64, &'a [f64; N]),
        (t_new, y_new): (f64, &'a [f64; N]),
        dense: Option<Polynomial<'a, N>>,
    ) -> Self {
        Self {
            t_old,
            t_new,
            y_old,
            y_new,
            dense,
        }
    }

    /// The state at `t` in `[t_old, t_new]` from the dense output (`y_new`
    /// itself at `t >= t_new`); `None` when the observer did not ask for
    /// dense output on this step.
    pub fn eval(&self, t: f64) -> Option<[f64; N]> {
        if t >= self.t_new {
            return Some(*self.y_new);
        }
        self.dense.map(|p| p.at(t))
    }
}
