//! The apex: the Mellin eigen-equation and its exponents (`docs/errata.md`, section 6b, re-derived).
//!
//! Near x = 0 the second-derivative contact condition (see [`crate::solver`]) reads, with
//! h = dS/dx, H_y = PV Int_0^p h 2v/(v^2 - x^2) dv, H_x = PV Int_0^p h 2v^2/(x (v^2 - x^2)) dv,
//!
//! ```text
//!   H_y/|p1| - gamma beta H_x/|p2| - pi (beta + gamma) c(x) h = 0,   c |p1| |p2| = m^2 L/x^2.
//! ```
//!
//! For S ~ x^(-lambda), h ~ x^(-1-lambda), the Mellin integrals
//! PV Int_0^inf 2 u^(-lambda)/(u^2 - 1) du = -pi tan(pi lambda/2) and
//! PV Int_0^inf 2 u^(1-lambda)/(u^2 - 1) du = pi cot(pi lambda/2) give, with t = tan(pi lambda/2),
//! |p_k| -> 1 and c -> -m^2,
//!
//! ```text
//!   t^2 - m^2 (beta + gamma) t + beta gamma = 0.
//! ```
//!
//! Freezing the coefficients at x gives the local equation
//! |p2| t^2 + (beta + gamma) m^2 (L/x^2) t + beta gamma |p1| = 0, whose roots lambda(x) are the
//! varying exponents carried by the basis; for gamma = 0 the non-zero root is exactly 2 Omega(x)
//! of the paper (tan(pi Omega) = -m^2 beta (L/s)/|p2|), so the paper's solution lies in the span.

use complexfn::{Rayleigh, Real};

/// What the genuine apex stress does: the paper's three regimes ([`ApexRegime`]), decided
/// here by the roots of the eigen-equation: `Finite` (gamma = 0 with coupling: only a negative
/// root), `Logarithmic` (beta = gamma = 0: double root t = 0), `Power` (a root lambda > 0,
/// S ~ x^(-lambda)).
pub use wedge::ApexRegime;

/// The roots of the apex eigen-equation.
#[derive(Clone, Debug, PartialEq)]
pub struct ApexExponents<T = f64> {
    /// The exponents lambda (S ~ x^(-lambda)) of the families present in the solution, ordered
    /// from the most singular.
    pub lambdas: Vec<T>,
    /// The regime.
    pub kind: ApexRegime,
}

impl<T: Real> ApexExponents<T> {
    /// The exponent of the leading apex behaviour S ~ x^(-lambda): the largest root for a power
    /// singularity, 0 for a finite or logarithmic apex.
    pub fn leading(&self) -> Option<&T> {
        match self.kind {
            ApexRegime::Power => self.lambdas.first(),
            _ => None,
        }
    }
}

/// Roots t of A t^2 + B t + C = 0 (A > 0), with the convention that for C = 0 the root t = 0
/// is dropped unless B = 0 as well (a double root at 0: the logarithmic case). Real roots
/// only, in decreasing order; the stable form q = -(B + sgn(B) sqrt(disc))/2, roots q/A, C/q.
fn quadratic_roots<T: Real>(a: &T, b: &T, c: &T) -> Vec<T> {
    if *c == 0.0 {
        if *b == 0.0 {
            return vec![b.zero()];
        }
        return vec![-(b.clone() / a)];
    }
    let disc = (b.clone().sqr() - a.clone() * c * 4.0).max(b.zero());
    let sq = disc.sqrt();
    let q = if b.is_sign_negative() {
        (sq - b) / 2.0
    } else {
        -(sq + b) / 2.0
    };
    if q == 0.0 {
        // b = 0 and disc = 0 with c != 0: complex roots, refused
        return vec![];
    }
    let (r1, r2) = (q.clone() / a, c.clone() / &q);
    if r1 >= r2 {
        vec![r1, r2]
    } else {
        vec![r2, r1]
    }
}

/// lambda = (2/pi) atan t.
pub fn lambda_of_t<T: Real>(t: T) -> T {
    let pi = t.pi();
    t.atan() * 2.0 / pi
}

/// The apex exponents of the genuine solution for m = c2/c1, coupling beta and friction gamma:
/// the roots of t^2 - m^2 (beta + gamma) t + beta gamma = 0 (a root t = 0 from beta gamma = 0
/// is the constant family and is not listed unless it is double).
pub fn exponents<T: Real>(m: T, beta: T, gamma: T) -> ApexExponents<T> {
    let bpg = beta.clone() + &gamma;
    let b = -(m.clone().sqr() * &bpg);
    let ts = quadratic_roots(&m.one(), &b, &(beta * &gamma));
    let lambdas: Vec<T> = ts.into_iter().map(lambda_of_t).collect();
    let kind = if lambdas.len() == 1 && lambdas[0] == 0.0 {
        ApexRegime::Logarithmic
    } else if lambdas.iter().any(|l| *l > 0.0) {
        ApexRegime::Power
    } else {
        ApexRegime::Finite
    };
    ApexExponents { lambdas, kind }
}

/// The local exponents lambda_j(x) at 0 < x < m (same ordering and count as [`exponents`]):
/// the roots of |p2| t^2 + (beta + gamma) m^2 (L/x^2) t + beta gamma |p1| = 0.
pub fn local_exponents<T: Real>(ray: &Rayleigh<T>, beta: &T, gamma: &T, x: &T) -> Vec<T> {
    let (p1, p2, l_s) = ray.cut_values(x);
    let b = (beta.clone() + gamma) * ray.m2() * l_s;
    let c = beta.clone() * gamma * p1;
    quadratic_roots(&p2, &b, &c)
        .into_iter()
        .map(lambda_of_t)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_zero_root_is_twice_omega0() {
        let m: f64 = 1000.0 / 1870.83;
        let beta = -(80.0_f64.to_radians()).cos() / (80.0_f64.to_radians()).sin();
        let e = exponents(m, beta, 0.0);
        let omega0 = (m * m * beta).atan() / std::f64::consts::PI;
        assert_eq!(e.lambdas.len(), 1);
        assert!((e.lambdas[0] - 2.0 * omega0).abs() < 1e-15);
        assert_eq!(e.kind, ApexRegime::Finite);
        assert_eq!(exponents(m, 0.0, 0.0).kind, ApexRegime::Logarithmic);
        let f = exponents(m, beta, 0.001);
        assert_eq!(f.kind, ApexRegime::Power);
        assert!(f.lambdas[0] > 0.0 && f.lambdas[1] < 0.0);
    }

    #[test]
    fn local_exponents_tend_to_the_apex_ones() {
        let m: f64 = 1000.0 / 1870.83;
        let ray = Rayleigh::new(m).unwrap();
        let (beta, gamma) = (-0.1, 0.6);
        let a = exponents(m, beta, gamma).lambdas;
        let b = local_exponents(&ray, &beta, &gamma, &1e-6);
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).abs() < 1e-10, "{x} {y}");
        }
    }
}
