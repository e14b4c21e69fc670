//! Plemelj boundary values f^{+-}(xi) = f(xi +- i0) and the operator D of eq (20).
//!
//! A sectionally analytic function is supplied through [`Sectional`]: its value off the real
//! axis and its boundary values on each side, computed by the caller from explicit formulas
//! (never by evaluating at a tiny imaginary offset). The paper's surface formulas (18), (19)
//! use
//!
//! ```text
//!   D(f) = Re[f^+ - f^-],   f^{+-} = f(v +- i0) on theta = 0,   f^{+-} = f(-v +- i0) on theta = -pi.
//! ```

pub use crate::branch::Side;
use crate::cx::Cx;
use crate::scalar::Real;

/// Which face of the half-plane's surface a boundary value refers to (eq (20)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Face {
    /// theta = 0 (x > 0): boundary values at +v.
    Right,
    /// theta = -pi (x < 0): boundary values at -v.
    Left,
}

impl Face {
    /// The real abscissa at which eq (20) evaluates boundary values for the surface variable v.
    pub fn abscissa<T: Real>(self, v: &T) -> T {
        match self {
            Face::Right => v.clone(),
            Face::Left => -v.clone(),
        }
    }
}

/// A sectionally analytic function of zeta, analytic off (part of) the real axis.
pub trait Sectional<T: Real> {
    /// Value at a point off the real axis.
    fn at(&self, zeta: &Cx<T>) -> Cx<T>;
    /// Boundary value f(xi +- i0).
    fn boundary(&self, xi: &T, side: Side) -> Cx<T>;

    /// f^+(xi) - f^-(xi).
    fn jump(&self, xi: &T) -> Cx<T> {
        self.boundary(xi, Side::Upper) - self.boundary(xi, Side::Lower)
    }
    /// D(f) = Re[f^+ - f^-] at surface variable v on the given face (eq (20)).
    fn d(&self, v: &T, face: Face) -> T {
        self.jump(&face.abscissa(v)).re
    }
}

/// D of two given boundary values: Re[plus - minus].
pub fn d_of<T: Real>(plus: &Cx<T>, minus: &Cx<T>) -> T {
    plus.re.clone() - &minus.re
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::branch::{p_boundary, p_k};

    struct P1;
    impl Sectional<f64> for P1 {
        fn at(&self, z: &Cx<f64>) -> Cx<f64> {
            p_k(z, &1.0)
        }
        fn boundary(&self, xi: &f64, side: Side) -> Cx<f64> {
            p_boundary(xi, &1.0, side)
        }
    }

    #[test]
    fn d_of_p1_is_minus_twice_its_modulus_on_the_cut() {
        // p1^+ - p1^- = -2|p1| on (-1, 1); zero outside; the same value at +-v by evenness of
        // the jump of an odd function with an odd cut convention.
        for v in [0.1, 0.5, 0.9] {
            let m = 1.0 / (1.0 - v * v).sqrt();
            assert!((P1.d(&v, Face::Right) + 2.0 * m).abs() < 1e-14);
            assert!((P1.d(&v, Face::Left) + 2.0 * m).abs() < 1e-14);
            let eps = 1e-9;
            let lim = P1.at(&Cx::new(v, eps)) - P1.at(&Cx::new(v, -eps));
            assert!((lim.re - P1.d(&v, Face::Right)).abs() < 1e-6);
        }
        assert!(P1.d(&1.5, Face::Right).abs() < 1e-15);
    }
}
