//! Shared test potentials: the frictionless uncoupled wedge F = -i Q zeta^2 (zeta^2 - p^2)^(-1/2)
//! (principal powers of zeta - p and zeta + p separately, cut [-p, p]) and a G of the same
//! family, G = c zeta^3 (zeta^2 - p^2)^(-1/2) (nonzero to exercise every term of (16)).
#![allow(dead_code)]

use complexfn::{Cx, Rayleigh, Real};
use homogeneous::Potentials;

pub struct Test<T: Real> {
    pub ray: Rayleigh<T>,
    pub p: T,
    pub q: T,
    pub c: T,
    pub n: u32,
    pub exact_real: bool,
}

impl<T: Real> Test<T> {
    pub fn new(m: f64, p: f64, q: f64, c: f64, n: u32, prec: u32) -> Self {
        let like = T::from_f64_prec(0.0, prec);
        Test {
            ray: Rayleigh::new(like.lit(m)).unwrap(),
            p: like.lit(p),
            q: like.lit(q),
            c: like.lit(c),
            n,
            exact_real: true,
        }
    }
    fn base(&self, z: &Cx<T>) -> Cx<T> {
        // zeta^2 (zeta - p)^(-1/2) (zeta + p)^(-1/2)
        let a = z.clone().add_re(&-self.p.clone()).sqrt();
        let b = z.clone().add_re(&self.p).sqrt();
        z.clone() * z / &(a * &b)
    }
}

impl<T: Real> Potentials<T> for Test<T> {
    fn degree(&self) -> u32 {
        self.n
    }
    fn rayleigh(&self) -> &Rayleigh<T> {
        &self.ray
    }
    fn f(&self, z: &Cx<T>) -> Cx<T> {
        self.base(z).scale(&self.q).mul_neg_i()
    }
    fn g(&self, z: &Cx<T>) -> Cx<T> {
        (self.base(z) * z).scale(&self.c)
    }
    fn breakpoints(&self) -> Vec<T> {
        vec![self.p.clone()]
    }
    fn fg_real(&self, xi: &T) -> (Cx<T>, Cx<T>) {
        if self.exact_real {
            let z = Cx::real(xi.clone());
            (self.f(&z), self.g(&z))
        } else {
            homogeneous::circle_mean(xi, self.ray.m_r(), |z| (self.f(z), self.g(z)))
        }
    }
}

pub fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}
