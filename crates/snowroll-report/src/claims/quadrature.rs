//! Integrals over the log's cross-section computed element by element, so
//! that the checks obtain masses, centres of mass, moments of inertia and
//! angular momenta from the body itself, not from the closed forms the
//! models use.
//!
//! A body is a list of annular sectors in the note's parametrisation (§3,
//! eq. (39)): the element at radius r′ and angle θ′ (measured back from the
//! contact line) of a sector centred at `(cx, cy)` sits at
//! `(cx − r′ sin θ′, cy − r′ cos θ′)`. Each sector is integrated by the
//! 8-point Gauss–Legendre rule in r′ (exact for polynomials of degree 15:
//! every integrand here is a polynomial of degree ≤ 5 in r′) and in θ′ on
//! panels of at most π/4 (the integrands are trigonometric polynomials of
//! degree ≤ 2 in θ′, for which the rule's error on such a panel is below
//! 1e-16 relative).

use std::f64::consts::PI;

/// Gauss–Legendre nodes on [−1, 1] (the positive half; the rule is symmetric).
const GL_X: [f64; 4] = [
    0.183_434_642_495_649_8,
    0.525_532_409_916_329,
    0.796_666_477_413_626_7,
    0.960_289_856_497_536_3,
];
/// The weights of [`GL_X`].
const GL_W: [f64; 4] = [
    0.362_683_783_378_362,
    0.313_706_645_877_887_3,
    0.222_381_034_453_374_5,
    0.101_228_536_290_376_3,
];
/// Widest θ′ panel, rad.
const PANEL: f64 = PI / 4.0;

/// ∫ₐᵇ f by the 8-point rule.
fn gauss(f: &mut impl FnMut(f64) -> f64, a: f64, b: f64) -> f64 {
    let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
    let mut sum = 0.0;
    for (x, w) in GL_X.iter().zip(GL_W) {
        sum += w * (f(c - h * x) + f(c + h * x));
    }
    sum * h
}

/// An annular sector of density ρl (mass per area times length).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Sector {
    /// Centre (x, y), m.
    pub centre: (f64, f64),
    /// Inner and outer radius, m.
    pub radii: (f64, f64),
    /// Angle range θ′ ∈ [from, to], rad, measured back from the bottom.
    pub angles: (f64, f64),
    /// ρ l, kg/m.
    pub rho_l: f64,
}

impl Sector {
    /// A full disk (or ring) of radii `radii` centred at `centre`.
    pub fn full(centre: (f64, f64), radii: (f64, f64), rho_l: f64) -> Self {
        Self {
            centre,
            radii,
            angles: (0.0, 2.0 * PI),
            rho_l,
        }
    }
}

/// `∫ f(x, y, r′, θ′) dm` over the body: `f` gets the element's position
/// and its polar coordinates about its sector's centre.
pub(super) fn integrate(body: &[Sector], f: impl Fn(f64, f64, f64, f64) -> f64) -> f64 {
    let mut total = 0.0;
    for s in body {
        let (t0, t1) = s.angles;
        let panels = ((t1 - t0) / PANEL).ceil().max(1.0) as usize;
        let width = (t1 - t0) / panels as f64;
        for p in 0..panels {
            let (a, b) = (t0 + p as f64 * width, t0 + (p + 1) as f64 * width);
            total += s.rho_l
                * gauss(
                    &mut |theta| {
                        let (sin, cos) = theta.sin_cos();
                        gauss(
                            &mut |r| {
                                let (x, y) = (s.centre.0 - r * sin, s.centre.1 - r * cos);
                                f(x, y, r, theta) * r
                            },
                            s.radii.0,
                            s.radii.1,
                        )
                    },
                    a,
                    b,
                );
        }
    }
    total
}

/// Mass, centre of mass and moment of inertia about `point` of a body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct MassProperties {
    /// Mass, kg.
    pub mass: f64,
    /// Centre of mass (x, y), m.
    pub centre: (f64, f64),
    /// Moment of inertia about the axis through `point`, kg m².
    pub inertia: f64,
}

/// The mass properties of `body` about `point`.
pub(super) fn mass_properties(body: &[Sector], point: (f64, f64)) -> MassProperties {
    let mass = integrate(body, |_, _, _, _| 1.0);
    let mx = integrate(body, |x, _, _, _| x);
    let my = integrate(body, |_, y, _, _| y);
    let inertia = integrate(body, |x, y, _, _| {
        (x - point.0).powi(2) + (y - point.1).powi(2)
    });
    MassProperties {
        mass,
        centre: (mx / mass, my / mass),
        inertia,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Quadrature of polynomials within the rule's degree: rounding only.
    const EXACT_TOL: f64 = 1e-13;

    #[test]
    fn a_disk_has_its_textbook_mass_properties() {
        let (r, rho_l) = (0.3, 2.0);
        let body = [Sector::full((0.0, r), (0.0, r), rho_l)];
        let p = mass_properties(&body, (0.0, 0.0));
        let m = PI * rho_l * r * r;
        assert!((p.mass / m - 1.0).abs() < EXACT_TOL);
        assert!(p.centre.0.abs() < EXACT_TOL && (p.centre.1 / r - 1.0).abs() < EXACT_TOL);
        // I about a point on the rim: m r²/2 + m r² (eq. (90)).
        assert!((p.inertia / (1.5 * m * r * r) - 1.0).abs() < EXACT_TOL);
    }
}
