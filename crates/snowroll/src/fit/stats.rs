//! What a fit's end point says: the covariance s² (JᵀJ)⁻¹, the standard
//! errors and correlations, which combinations of the parameters the data
//! cannot separate, and the information criteria.

use super::dense::{normal_equations, Sym};

/// An eigenvalue of N, JᵀJ with its columns normalised to unit length
/// (its eigenvalues lie between 0 and n), below this is singular to the
/// accuracy of the Jacobian itself (forward differences of runs at rtol
/// 1e-10 are good to about 1e-4 relative, so a column equal to a
/// combination of others shows up at about (1e-4)²): the direction is not
/// determined whatever the noise.
const SINGULAR: f64 = 1e-6;
/// A direction whose standard error, in units of the parameters' sizes,
/// exceeds this is not determined by these data either (the 1-σ change of
/// the combination is larger than the combination).
const LOOSE: f64 = 1.0;
/// A column of JᵀJ whose squared length is below this fraction of the
/// longest one's: the parameter does not change x(t).
const NO_EFFECT: f64 = 1e-20;
/// A parameter takes part in a direction when its share of the unit
/// vector is at least this.
const SHARE: f64 = 0.1;

/// A combination of the free parameters that the data do not fix.
#[derive(Debug, Clone, PartialEq)]
pub struct Unseparated {
    /// The parameters that move along it.
    pub keys: Vec<String>,
    /// In words: for two parameters measured relative to their size, the
    /// combination the data do fix (`r0^2/snow_depth`); else the direction
    /// that leaves x(t) unchanged.
    pub text: String,
    /// The value of the fixed combination where there is one.
    pub value: Option<f64>,
    /// Its relative standard error.
    pub rel_stderr: Option<f64>,
}

/// JᵀJ of some columns, those of no effect at all (`live` leaves them
/// out) set apart and the rest normalised to unit length (N, whose
/// eigenvalues lie between 0 and the count and measure how nearly the
/// columns are combinations of each other, whatever their units), with N's
/// eigenpairs, ascending.
struct Normalised {
    live: Vec<usize>,
    /// The live columns' lengths.
    d: Vec<f64>,
    values: Vec<f64>,
    vectors: Vec<Vec<f64>>,
}

fn normalised(cols: &[Vec<f64>]) -> Normalised {
    let (a, _) = normal_equations(cols, &[]);
    let n = cols.len();
    let top = (0..n).map(|j| a.at(j, j)).fold(0.0_f64, f64::max);
    let live: Vec<usize> = (0..n).filter(|&j| a.at(j, j) > NO_EFFECT * top).collect();
    let d: Vec<f64> = live.iter().map(|&j| a.at(j, j).sqrt()).collect();
    let mut norm = Sym::zeros(live.len());
    for (i, &ji) in live.iter().enumerate() {
        for (k, &jk) in live.iter().enumerate() {
            norm.set(i, k, a.at(ji, jk) / (d[i] * d[k]));
        }
    }
    let (values, vectors) = norm.eigen();
    Normalised {
        live,
        d,
        values,
        vectors,
    }
}

/// The number of directions in which x(t) moves measurably: the
/// eigenvalues of N above [`SINGULAR`].
pub(crate) fn moving_directions(jac: &[Vec<f64>]) -> usize {
    normalised(jac)
        .values
        .iter()
        .filter(|&&l| l > SINGULAR)
        .count()
}

/// The statistics of an end point.
pub(crate) struct Summary {
    pub stderr: Vec<Option<f64>>,
    pub correlations: Vec<Vec<Option<f64>>>,
    pub unseparated: Vec<Unseparated>,
    /// Directions the data fix (the numerical rank of JᵀJ).
    pub rank: usize,
    /// Largest over smallest eigenvalue of N (infinite when a parameter has
    /// no effect at all).
    pub condition: f64,
}

/// The statistics at `p` with residuals `r` and Jacobian `jac`.
/// `relative[j]` says whether parameter j is measured relative to its size
/// (positive by its range), `scale[j]` is its size or typical size.
pub(crate) fn summarise(
    keys: &[String],
    p: &[f64],
    r: &[f64],
    jac: &[Vec<f64>],
    relative: &[bool],
    scale: &[f64],
) -> Summary {
    let n = p.len();
    let m = r.len();
    let ssr: f64 = r.iter().map(|x| x * x).sum();
    let s2 = ssr / (m.saturating_sub(n).max(1)) as f64;
    // Columns in units of each parameter's size: u_j = δp_j / c_j.
    let c: Vec<f64> = (0..n)
        .map(|j| {
            if relative[j] && p[j] != 0.0 {
                p[j].abs()
            } else {
                scale[j]
            }
        })
        .collect();
    let scaled: Vec<Vec<f64>> = jac
        .iter()
        .zip(&c)
        .map(|(col, cj)| col.iter().map(|v| v * cj).collect())
        .collect();
    let nrm = normalised(&scaled);
    let split = split(&nrm, n, s2);
    let cov_u = &split.cov_u;
    let stderr: Vec<Option<f64>> = (0..n)
        .map(|j| {
            (split.loose_share[j] < SHARE * SHARE).then(|| c[j] * cov_u.at(j, j).max(0.0).sqrt())
        })
        .collect();
    let correlations = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    let d = (cov_u.at(i, i) * cov_u.at(j, j)).sqrt();
                    (stderr[i].is_some() && stderr[j].is_some() && d > 0.0)
                        .then(|| (cov_u.at(i, j) / d).clamp(-1.0, 1.0))
                })
                .collect()
        })
        .collect();
    let condition = match (nrm.values.first(), nrm.values.last()) {
        _ if nrm.live.len() < n => f64::INFINITY,
        (Some(&low), Some(&high)) if low > 0.0 => high / low,
        (Some(_), Some(_)) => f64::INFINITY,
        _ => 1.0,
    };
    let mut named: Vec<Unseparated> = Vec::new();
    for (v, unit) in &split.loose {
        let u = name(keys, p, relative, v, unit, cov_u);
        if !named.iter().any(|w| w.text == u.text) {
            named.push(u);
        }
    }
    Summary {
        stderr,
        correlations,
        unseparated: named,
        rank: split.rank,
        condition,
    }
}

/// The directions of N split into those the data fix (their covariance,
/// in u, summed in `cov_u`; `rank` of them) and those they do not
/// (`loose`: each in u, for the combination's powers, and as a unit vector
/// of N kept where parameters take part, zero elsewhere; `loose_share[j]`,
/// parameter j's share of them).
struct Split {
    cov_u: Sym,
    loose_share: Vec<f64>,
    loose: Vec<(Vec<f64>, Vec<f64>)>,
    rank: usize,
}

/// A direction is fixed when its eigenvalue is above [`SINGULAR`] and its
/// 1-σ move (s/√λ) changes no parameter by more than [`LOOSE`] of its size.
fn split(nrm: &Normalised, n: usize, s2: f64) -> Split {
    let mut out = Split {
        cov_u: Sym::zeros(n),
        loose_share: vec![0.0; n],
        loose: Vec::new(),
        rank: 0,
    };
    for j in (0..n).filter(|j| !nrm.live.contains(j)) {
        out.loose_share[j] = 1.0;
        let mut v = vec![0.0; n];
        v[j] = 1.0;
        out.loose.push((v.clone(), v));
    }
    for (lambda, w) in nrm.values.iter().zip(&nrm.vectors) {
        let mut v = vec![0.0; n];
        for (i, &j) in nrm.live.iter().enumerate() {
            v[j] = w[i] / nrm.d[i];
        }
        let sd = if *lambda > 0.0 {
            (s2 / lambda).sqrt()
        } else {
            f64::INFINITY
        };
        let widest = (0..nrm.live.len())
            .map(|i| sd * w[i].abs() / nrm.d[i])
            .fold(0.0_f64, f64::max);
        if *lambda > SINGULAR && widest <= LOOSE {
            out.rank += 1;
            for i in 0..n {
                for j in 0..n {
                    let x = out.cov_u.at(i, j) + s2 * v[i] * v[j] / lambda;
                    out.cov_u.set(i, j, x);
                }
            }
        } else {
            // A parameter takes part when it has a share of the direction
            // and its own 1-σ move along it is at least a tenth of its size
            // (else a parameter correlated with a loose one, t0 with a
            // tube's mass, was called not fixed though the data fix it to
            // a fraction of a percent); at least the largest share does.
            let mut unit = vec![0.0; n];
            for (i, &j) in nrm.live.iter().enumerate() {
                if w[i].abs() >= SHARE && sd * v[j].abs() >= SHARE {
                    unit[j] = w[i];
                }
            }
            if unit.iter().all(|&x| x == 0.0) {
                let top = (0..nrm.live.len())
                    .max_by(|&a, &b| w[a].abs().total_cmp(&w[b].abs()))
                    .unwrap_or(0);
                unit[nrm.live[top]] = w[top];
            }
            for (share, u) in out.loose_share.iter_mut().zip(&unit) {
                *share += u * u;
            }
            out.loose.push((v, unit));
        }
    }
    out
}

/// The combination along `v` in words (see [`Unseparated::text`]).
fn name(
    keys: &[String],
    p: &[f64],
    relative: &[bool],
    v: &[f64],
    unit: &[f64],
    cov_u: &Sym,
) -> Unseparated {
    let big = v.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
    let involved: Vec<usize> = (0..v.len()).filter(|&j| unit[j].abs() >= SHARE).collect();
    let names: Vec<String> = involved.iter().map(|&j| keys[j].clone()).collect();
    if let [j] = involved[..] {
        return Unseparated {
            keys: names,
            text: format!(
                "{} is not fixed by these data (x(t) barely changes with it here)",
                keys[j]
            ),
            value: None,
            rel_stderr: None,
        };
    }
    if let [i, j] = involved[..] {
        if relative[i] && relative[j] && p[i] != 0.0 && p[j] != 0.0 {
            // Along v (u = δp/|p|), ln|p_i| and ln|p_j| move as
            // v_i sgn p_i : v_j sgn p_j, so p_i^{w_i} p_j^{w_j} with
            // w = (v_j sgn p_j, −v_i sgn p_i) stays fixed: that is what the
            // data measure.
            let (mut wi, mut wj) = (v[j] * p[j].signum(), -v[i] * p[i].signum());
            let least = wi.abs().min(wj.abs());
            wi /= least;
            wj /= least;
            if wi < 0.0 {
                wi = -wi;
                wj = -wj;
            }
            let value = power(p[i], wi) * power(p[j], wj);
            let mut var = 0.0;
            for (a, wa) in [(i, wi), (j, wj)] {
                for (b, wb) in [(i, wi), (j, wj)] {
                    var += wa * wb * p[a].signum() * p[b].signum() * cov_u.at(a, b);
                }
            }
            let text = format!(
                "{} and {} are not separated by these data: they fix only {}",
                keys[i],
                keys[j],
                power_text(&keys[i], wi, &keys[j], wj)
            );
            return Unseparated {
                keys: names,
                text,
                value: Some(value),
                rel_stderr: Some(var.max(0.0).sqrt()),
            };
        }
    }
    let terms: Vec<String> = involved
        .iter()
        .map(|&j| {
            let tag = if relative[j] { " (relative)" } else { "" };
            format!("{:+.2} {}{tag}", v[j] / big, keys[j])
        })
        .collect();
    Unseparated {
        keys: names.clone(),
        text: format!(
            "{} are not separated by these data: moving them together along ({}) leaves x(t) \
             unchanged",
            names.join(", "),
            terms.join(", ")
        ),
        value: None,
        rel_stderr: None,
    }
}

/// `x^w`: by whole powers where w is a whole number to 1e-6 (so that a
/// negative b keeps its sign), else of |x|.
fn power(x: f64, w: f64) -> f64 {
    if (w - w.round()).abs() < 1e-6 && w.abs() < 64.0 {
        x.powi(w.round() as i32)
    } else {
        x.abs().powf(w)
    }
}

/// `a^wa b^wb` with positive powers above a slash (`r0^2/snow_depth`).
fn power_text(a: &str, wa: f64, b: &str, wb: f64) -> String {
    let power = |k: &str, w: f64| {
        let w = w.abs();
        if (w - 1.0).abs() < 0.05 {
            k.to_string()
        } else if (w - w.round()).abs() < 0.05 {
            format!("{k}^{}", w.round())
        } else {
            format!("{k}^{w:.2}")
        }
    };
    if wb < 0.0 {
        format!("{}/{}", power(a, wa), power(b, wb))
    } else {
        format!("{}*{}", power(a, wa), power(b, wb))
    }
}

/// AIC and BIC of a least-squares fit with Gaussian errors of unknown σ:
/// m ln(S/m) + 2k and m ln(S/m) + k ln m, k the directions fixed plus one
/// (σ itself).
pub(crate) fn criteria(ssr: f64, m: usize, rank: usize) -> (f64, f64) {
    let m_f = m as f64;
    let k = (rank + 1) as f64;
    let fit = m_f * (ssr / m_f).max(f64::MIN_POSITIVE).ln();
    (fit + 2.0 * k, fit + k * m_f.ln())
}
