//! The transcendental functions of every model, from the `libm` crate (a
//! pure-Rust port of musl's) rather than the platform's C library: the
//! same bits on every target. `f64::sin` and its kin call the platform's
//! libm, which on Linux (glibc) and in WebAssembly (musl's, through
//! compiler-builtins) differ in the last bit now and then; with these the
//! explorer's WebAssembly build writes the same bytes as the command line
//! (`scripts/explorer/compare-cli.js` checks it for every model).
//! Square roots and `powi` are exact or target-independent already and
//! stay `f64`'s own.

/// `f64`'s transcendental functions, computed by the `libm` crate.
pub(crate) trait Portable: Sized {
    /// sin x.
    fn sin_p(self) -> f64;
    /// cos x.
    fn cos_p(self) -> f64;
    /// (sin x, cos x).
    fn sin_cos_p(self) -> (f64, f64);
    /// tan x.
    fn tan_p(self) -> f64;
    /// arccos x.
    fn acos_p(self) -> f64;
    /// arctan x.
    fn atan_p(self) -> f64;
    /// The angle of the point (x, y) = (other, self).
    fn atan2_p(self, other: f64) -> f64;
    /// The cube root.
    fn cbrt_p(self) -> f64;
    /// e^x.
    fn exp_p(self) -> f64;
    /// e^x - 1.
    fn exp_m1_p(self) -> f64;
    /// ln x.
    fn ln_p(self) -> f64;
    /// ln(1 + x).
    fn ln_1p_p(self) -> f64;
    /// x^y.
    fn powf_p(self, y: f64) -> f64;
    /// sqrt(x² + y²).
    fn hypot_p(self, y: f64) -> f64;
}

impl Portable for f64 {
    fn sin_p(self) -> f64 {
        libm::sin(self)
    }
    fn cos_p(self) -> f64 {
        libm::cos(self)
    }
    fn sin_cos_p(self) -> (f64, f64) {
        libm::sincos(self)
    }
    fn tan_p(self) -> f64 {
        libm::tan(self)
    }
    fn acos_p(self) -> f64 {
        libm::acos(self)
    }
    fn atan_p(self) -> f64 {
        libm::atan(self)
    }
    fn atan2_p(self, other: f64) -> f64 {
        libm::atan2(self, other)
    }
    fn cbrt_p(self) -> f64 {
        libm::cbrt(self)
    }
    fn exp_p(self) -> f64 {
        libm::exp(self)
    }
    fn exp_m1_p(self) -> f64 {
        libm::expm1(self)
    }
    fn ln_p(self) -> f64 {
        libm::log(self)
    }
    fn ln_1p_p(self) -> f64 {
        libm::log1p(self)
    }
    fn powf_p(self, y: f64) -> f64 {
        libm::pow(self, y)
    }
    fn hypot_p(self, y: f64) -> f64 {
        libm::hypot(self, y)
    }
}
