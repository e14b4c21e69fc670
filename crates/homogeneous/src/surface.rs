//! The surface forms (18), (19) with D(.) of eq (20), by contour deformation.
//!
//! On theta = 0 (face [`Face::Right`], x > 0) and theta = -pi ([`Face::Left`], x < 0), for
//! 0 < r < c1 t, with x = r/(c1 t) and units c1 = mu = t = 1:
//!
//! ```text
//!   u       = 1/(2 n!)      Int_x^1 v^(-n-2) (v - x)^n     [D(L F/R - i p1 v^2 G/(m^2 R)) + i D(L G/R + i p2 v^2 F/(m^2 R))] dv   (18)
//!   s_theta = 1/(2 (n-1)!)  Int_x^1 v^(-n-2) (v - x)^(n-1) [D(F) + i D(G)] dv                                              (19)
//!   D(f) = Re[f(sigma v + i0) - f(sigma v - i0)],  sigma = +1 (theta = 0), -1 (theta = -pi)                               (20)
//! ```
//!
//! p_k, L, R and v^2 = zeta^2 sit inside D: all are taken at zeta = sigma v +- i0.
//!
//! **Method.** Every function under D is analytic off the real axis in the half-plane
//! sigma Re zeta > 0, and the weight w(v) = v^(-n-2)(v - x)^j is analytic for Re v > 0. Hence
//! Int_x^1 w(v) f(sigma v +- i0) dv equals the integral of w(v) f(sigma v) dv along any path
//! v = tau +- i sigma h(tau) from x to 1 in the upper (lower) zeta half-plane; we take
//! h(tau) = (tau - x)(1 - tau)/(1 - x) (height (1 - x)/4, leaving the axis at 45 degrees), so
//!
//! ```text
//!   Int_x^1 w D(f) dv = Re[ Int_{path+} w f dv - Int_{path-} w f dv ].
//! ```
//!
//! No boundary value, principal value or delta term is needed: the Rayleigh-pole contribution
//! (a delta function at v = m_R in the real-axis picture) and the cut of F are passed at a
//! distance. The path stays in sigma Re zeta >= x > 0, so it never meets the imaginary axis where
//! G may be non-analytic. The integrand's endpoint singularities (the cut of F at v = x, the
//! branch point of p_1 at v = 1) are integrable; tanh-sinh in tau handles them, with the offsets
//! zeta -+ 1 and v - x formed exactly from the node's distances to the ends.
//!
//! **Side of p_k.** Along path+ the closed form p_k(zeta) = -i m_k/(sqrt(zeta - m_k) sqrt(zeta + m_k))
//! tends to p_k(sigma v + i0) = -|p_k| on the cut, which is the value the full field (10) uses at
//! theta -> 0- (zeta_k -> v + i0) and theta -> -pi+ (zeta_k -> -v + i0); the identities
//! U(W_1) - i U(W_2) = D(L F/R - i p1 v^2 G/(m^2 R)) + i D(L G/R + i p2 v^2 F/(m^2 R)) and
//! V(W_1) - i V(W_2) = D(F) + i D(G) at theta = 0 (from (16) with L = 2 - K p1 p2) then give
//! (18), (19) from (10), (11b); the tests check this numerically.

pub use complexfn::plemelj::Face;
use complexfn::quadrature::{tanh_sinh, CachedRules, Point, QuadValue};
use complexfn::{Cx, Real};

use crate::error::{invalid, Result};
use crate::j_operator::default_options;
use crate::Potentials;

/// The two path integrals (upper, lower) of the two functions under D, kept apart so that the
/// quadrature's relative error test sees their size even when D(.) vanishes (unloaded surface).
#[derive(Clone, Debug)]
struct Paths<T>([Cx<T>; 4]);

impl<T: Real> QuadValue<T> for Paths<T> {
    fn zero_like(like: &T) -> Self {
        let z = Cx::real(like.zero());
        Paths([z.clone(), z.clone(), z.clone(), z])
    }
    fn add_scaled(&mut self, v: &Self, w: &T) {
        for (a, b) in self.0.iter_mut().zip(v.0.iter()) {
            a.add_scaled(b, w);
        }
    }
    fn magnitude(&self) -> T {
        let mut m = self.0[0].abs();
        for a in &self.0[1..] {
            m += a.abs();
        }
        m
    }
    fn scaled(&self, s: &T) -> Self {
        Paths(self.0.clone().map(|a| a.scale(s)))
    }
    fn distance(&self, other: &Self) -> T {
        self.minus(other).magnitude()
    }
    fn minus(&self, other: &Self) -> Self {
        let mut out = self.clone();
        for (a, b) in out.0.iter_mut().zip(other.0.iter()) {
            *a = a.clone() - b;
        }
        out
    }
}

/// Which surface quantity to integrate.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Displacement,
    Stress,
}

fn check<T: Real>(x: &T, n: u32) -> Result<()> {
    if n == 0 {
        return invalid("degree n", 0.0, ">= 1");
    }
    if !(x.is_finite() && *x > 0.0 && *x < 1.0) {
        return invalid("x = r/(c1 t)", x.to_f64(), "(0, 1)");
    }
    Ok(())
}

fn surface_integral<T, P>(pot: &P, x: &T, face: Face, kind: Kind) -> Result<Cx<T>>
where
    T: CachedRules,
    P: Potentials<T> + ?Sized,
{
    let n = pot.degree();
    check(x, n)?;
    let ray = pot.rayleigh();
    let sigma = match face {
        Face::Right => 1.0,
        Face::Left => -1.0,
    };
    let one = x.one();
    let len = one.clone() - x;
    let inv_m2 = ray.m2().clone().recip();
    let j = match kind {
        Kind::Displacement => n as i32,
        Kind::Stress => n as i32 - 1,
    };
    // 1/(2 j!) with j = n (18) or n - 1 (19)
    let mut fact = one.clone();
    for i in 2..=j {
        fact *= x.lit(f64::from(i as u32));
    }
    let pref = (fact * 2.0).recip();
    let integrand = |pt: &Point<T>| -> Paths<T> {
        let h = pt.from_a.clone() * &pt.to_b / &len;
        let dh = (pt.to_b.clone() - &pt.from_a) / &len;
        let mut acc = Paths::zero_like(x);
        for side in [1.0, -1.0] {
            // v = tau + i s h, zeta = sigma v, s = side * sigma so that Im zeta = side * h
            let s = side * sigma;
            let v = Cx::new(pt.v.clone(), h.clone() * s);
            let dv = Cx::new(one.clone(), dh.clone() * s);
            let v_minus_x = Cx::new(pt.from_a.clone(), h.clone() * s);
            let zeta = Cx::new(pt.v.clone() * sigma, h.clone() * side);
            let mut rv = ray.at(&zeta);
            if pt.to_b < 0.25 {
                // p_1 with zeta -+ 1 formed exactly near the branch point sigma * 1
                let near = Cx::new(-(pt.to_b.clone() * sigma), h.clone() * side); // zeta - sigma
                let far = near.clone().add_re(&one.lit(2.0 * sigma)); // zeta + sigma
                let (zm1, zp1) = if sigma > 0.0 {
                    (near, far)
                } else {
                    (far, near)
                };
                rv.p1 = Cx::imag(-one.clone()) / &(zm1.sqrt() * &zp1.sqrt());
                let q = rv.p1.clone() * &rv.p2;
                rv.l = Cx::real(one.lit(2.0)) - rv.k.clone() * &q;
                rv.r = Cx::real(one.lit(4.0)) - rv.k.clone() * &rv.k * &q;
            }
            let f = pot.f(&zeta);
            let g = pot.g(&zeta);
            let (a, b) = match kind {
                Kind::Stress => (f, g),
                Kind::Displacement => {
                    let z2 = zeta.clone() * &zeta;
                    let lr = rv.l.clone() / &rv.r;
                    let z2mr = z2.scale(&inv_m2) / &rv.r;
                    let a = lr.clone() * &f - (rv.p1.clone() * &z2mr * &g).mul_i();
                    let b = lr * &g + (rv.p2.clone() * &z2mr * &f).mul_i();
                    (a, b)
                }
            };
            let vn = v.clone().recip();
            let mut w = vn.clone() * &vn;
            for _ in 0..n {
                w *= &vn;
            }
            for _ in 0..j {
                w *= &v_minus_x;
            }
            let w = w * &dv;
            let wa = w.clone() * &a;
            let wb = w * &b;
            let o = if side > 0.0 { 0 } else { 2 };
            acc.0[o] = wa;
            acc.0[o + 1] = wb;
        }
        acc
    };
    let est = tanh_sinh(x, &one, default_options(x.prec()), integrand)?;
    let [ap, bp, am, bm] = est.estimate.value.0;
    Ok(Cx::new((ap.re - am.re) * &pref, (bp.re - bm.re) * &pref))
}

/// Surface displacement u = u_r + i u_theta of eq (18) at r/(c1 t) = `x` in (0, 1) on `face`
/// (units c1 = t = 1: u in units of c1^n t^n times the scale of F, G). On theta = -pi the polar
/// components are u_r = -u_x, u_theta = -u_y.
pub fn displacement<T, P>(pot: &P, x: &T, face: Face) -> Result<Cx<T>>
where
    T: CachedRules,
    P: Potentials<T> + ?Sized,
{
    surface_integral(pot, x, face, Kind::Displacement)
}

/// Surface stress s_theta = sigma_theta - i sigma_rtheta of eq (19) at r/(c1 t) = `x` in (0, 1)
/// on `face` (units mu = c1 = t = 1).
pub fn stress<T, P>(pot: &P, x: &T, face: Face) -> Result<Cx<T>>
where
    T: CachedRules,
    P: Potentials<T> + ?Sized,
{
    surface_integral(pot, x, face, Kind::Stress)
}
