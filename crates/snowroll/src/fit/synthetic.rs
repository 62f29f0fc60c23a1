//! Gaussian noise of a known σ from a fixed seed: the synthetic data of
//! the fit's tests and of the worked example (`examples/unrolling/`).
//! SplitMix64 (Steele, Lea and Flood 2014) for the uniform numbers and
//! Box–Muller for the normal ones: small, portable, the same numbers on
//! every platform, and no dependency for what a test needs.

/// A stream of normal numbers with mean 0 and standard deviation 1.
#[derive(Debug, Clone)]
pub struct Noise {
    state: u64,
    spare: Option<f64>,
}

impl Noise {
    /// The stream of `seed`.
    pub fn new(seed: u64) -> Self {
        Self {
            state: seed,
            spare: None,
        }
    }

    fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in (0, 1], 53 bits.
    fn uniform(&mut self) -> f64 {
        ((self.next_u64() >> 11) + 1) as f64 / (1u64 << 53) as f64
    }

    /// The next standard normal number.
    pub fn normal(&mut self) -> f64 {
        if let Some(z) = self.spare.take() {
            return z;
        }
        let (u1, u2) = (self.uniform(), self.uniform());
        let radius = (-2.0 * u1.ln()).sqrt();
        let angle = std::f64::consts::TAU * u2;
        self.spare = Some(radius * angle.sin());
        radius * angle.cos()
    }
}

/// `x` with independent normal noise of standard deviation `sigma` (m)
/// added, from `seed`.
pub fn noisy(x: &[f64], sigma: f64, seed: u64) -> Vec<f64> {
    let mut noise = Noise::new(seed);
    x.iter().map(|v| v + sigma * noise.normal()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 100 000 draws: mean 0 and variance 1 within 5 standard errors of
    /// each (the mean's is 1/√n, the variance's √(2/n)).
    #[test]
    fn noise_is_standard_normal() {
        let n = 100_000;
        let mut noise = Noise::new(7);
        let z: Vec<f64> = (0..n).map(|_| noise.normal()).collect();
        let mean = z.iter().sum::<f64>() / n as f64;
        let var = z.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n as f64;
        let nf = n as f64;
        assert!(mean.abs() < 5.0 / nf.sqrt(), "mean {mean}");
        assert!(
            (var - 1.0).abs() < 5.0 * (2.0 / nf).sqrt(),
            "variance {var}"
        );
        let inside = z.iter().filter(|v| v.abs() <= 1.0).count() as f64 / nf;
        assert!((inside - 0.6827).abs() < 0.01, "{inside} within 1 sigma");
    }
}
