//! The small dense linear algebra of a fit: a symmetric matrix of at most
//! a dozen rows (one per free parameter), solved by Cholesky and split into
//! eigenpairs by Jacobi rotations.
//!
//! Written here rather than taken from nalgebra: a fit has n ≤ ~8 free
//! parameters, so the whole of what it needs is these two routines
//! (about a hundred lines), while nalgebra (which the `levenberg-marquardt`
//! crate requires) would be the physics crate's largest dependency by far.
//! Jacobi's method is slow for big matrices and exact enough for small
//! ones: its eigenvalues are accurate relative to the largest, which is what
//! a condition number needs.

/// A symmetric n × n matrix, row-major.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Sym {
    pub n: usize,
    pub a: Vec<f64>,
}

impl Sym {
    pub fn zeros(n: usize) -> Self {
        Self {
            n,
            a: vec![0.0; n * n],
        }
    }

    pub fn at(&self, i: usize, j: usize) -> f64 {
        self.a[i * self.n + j]
    }

    pub fn set(&mut self, i: usize, j: usize, x: f64) {
        self.a[i * self.n + j] = x;
    }

    /// Solves `self · x = rhs` by Cholesky; `None` if the matrix is not
    /// positive definite (to rounding).
    pub fn cholesky_solve(&self, rhs: &[f64]) -> Option<Vec<f64>> {
        let n = self.n;
        let mut l = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..=i {
                let mut s = self.at(i, j);
                for k in 0..j {
                    s -= l[i * n + k] * l[j * n + k];
                }
                if i == j {
                    if s.is_nan() || s <= 0.0 || !s.is_finite() {
                        return None;
                    }
                    l[i * n + i] = s.sqrt();
                } else {
                    l[i * n + j] = s / l[j * n + j];
                }
            }
        }
        let mut y = vec![0.0; n];
        for i in 0..n {
            let mut s = rhs[i];
            for k in 0..i {
                s -= l[i * n + k] * y[k];
            }
            y[i] = s / l[i * n + i];
        }
        let mut x = vec![0.0; n];
        for i in (0..n).rev() {
            let mut s = y[i];
            for k in i + 1..n {
                s -= l[k * n + i] * x[k];
            }
            x[i] = s / l[i * n + i];
        }
        x.iter().all(|v| v.is_finite()).then_some(x)
    }

    /// Eigenvalues (ascending) and unit eigenvectors (`vectors[k]` belongs
    /// to `values[k]`), by cyclic Jacobi rotations until the off-diagonal
    /// part is below 1e-15 of the whole.
    pub fn eigen(&self) -> (Vec<f64>, Vec<Vec<f64>>) {
        let n = self.n;
        let mut a = self.a.clone();
        let mut v = vec![0.0; n * n];
        for i in 0..n {
            v[i * n + i] = 1.0;
        }
        let norm: f64 = a.iter().map(|x| x * x).sum::<f64>().sqrt();
        for _sweep in 0..100 {
            let off: f64 = (0..n)
                .flat_map(|i| (0..n).filter(move |&j| j != i).map(move |j| (i, j)))
                .map(|(i, j)| a[i * n + j] * a[i * n + j])
                .sum::<f64>()
                .sqrt();
            if off <= 1e-15 * norm || off == 0.0 {
                break;
            }
            for p in 0..n {
                for q in p + 1..n {
                    let apq = a[p * n + q];
                    if apq == 0.0 {
                        continue;
                    }
                    let theta = (a[q * n + q] - a[p * n + p]) / (2.0 * apq);
                    let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                    let t = if theta == 0.0 { 1.0 } else { t };
                    let c = 1.0 / (t * t + 1.0).sqrt();
                    let s = t * c;
                    for k in 0..n {
                        let akp = a[k * n + p];
                        let akq = a[k * n + q];
                        a[k * n + p] = c * akp - s * akq;
                        a[k * n + q] = s * akp + c * akq;
                    }
                    for k in 0..n {
                        let apk = a[p * n + k];
                        let aqk = a[q * n + k];
                        a[p * n + k] = c * apk - s * aqk;
                        a[q * n + k] = s * apk + c * aqk;
                    }
                    for k in 0..n {
                        let vkp = v[k * n + p];
                        let vkq = v[k * n + q];
                        v[k * n + p] = c * vkp - s * vkq;
                        v[k * n + q] = s * vkp + c * vkq;
                    }
                }
            }
        }
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&i, &j| a[i * n + i].total_cmp(&a[j * n + j]));
        let values = order.iter().map(|&i| a[i * n + i]).collect();
        let vectors = order
            .iter()
            .map(|&i| (0..n).map(|k| v[k * n + i]).collect())
            .collect();
        (values, vectors)
    }
}

/// JᵀJ and Jᵀr.
pub(crate) fn normal_equations(jac: &[Vec<f64>], r: &[f64]) -> (Sym, Vec<f64>) {
    let n = jac.len();
    let mut a = Sym::zeros(n);
    for i in 0..n {
        for j in 0..=i {
            let x: f64 = jac[i].iter().zip(&jac[j]).map(|(u, v)| u * v).sum();
            a.set(i, j, x);
            a.set(j, i, x);
        }
    }
    // Jᵀr, or nothing when `r` is empty (JᵀJ alone is wanted).
    let g = jac
        .iter()
        .map(|c| c.iter().zip(r).map(|(u, v)| u * v).sum())
        .collect();
    (a, g)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 3 × 3 matrix built from known eigenpairs: Jacobi finds them.
    #[test]
    fn eigen_recovers_a_matrix_built_from_its_eigenpairs() {
        let s = 1.0 / 2f64.sqrt();
        let vecs = [[s, s, 0.0], [s, -s, 0.0], [0.0, 0.0, 1.0]];
        let vals = [1e-9, 2.0, 5.0];
        let mut m = Sym::zeros(3);
        for i in 0..3 {
            for j in 0..3 {
                let x: f64 = (0..3).map(|k| vals[k] * vecs[k][i] * vecs[k][j]).sum();
                m.set(i, j, x);
            }
        }
        let (values, vectors) = m.eigen();
        for (got, want) in values.iter().zip(vals) {
            assert!((got - want).abs() < 1e-14 * 5.0, "{got} vs {want}");
        }
        let dot: f64 = vectors[0].iter().zip(vecs[0]).map(|(a, b)| a * b).sum();
        assert!((dot.abs() - 1.0).abs() < 1e-12);
    }

    /// Cholesky solves a positive definite system and refuses an indefinite one.
    #[test]
    fn cholesky_solves_and_refuses_indefinite() {
        let m = Sym {
            n: 2,
            a: vec![4.0, 2.0, 2.0, 3.0],
        };
        let x = m.cholesky_solve(&[2.0, 1.0]).unwrap();
        assert!((4.0 * x[0] + 2.0 * x[1] - 2.0).abs() < 1e-14);
        assert!((2.0 * x[0] + 3.0 * x[1] - 1.0).abs() < 1e-14);
        let bad = Sym {
            n: 2,
            a: vec![1.0, 2.0, 2.0, 1.0],
        };
        assert!(bad.cholesky_solve(&[1.0, 1.0]).is_none());
    }
}
