//! The spectral basis for h = dS/dx on the contact 0 < x < p.
//!
//! Every function carries the edge factor (p - x)^(-1/2 + Omega(x)) (Omega of eq (31), the
//! exponent of the local Riemann-Hilbert problem at the moving edge; its variation along the
//! contact is kept, because (p - x)^(Omega(x) - Omega(p)) is not analytic at p), and one apex
//! factor x^(-1 - lambda_j(x)) per non-zero root of the apex eigen-equation ([`crate::apex`]),
//! or x^(-1) in the logarithmic case, or 1 (the optional regular family), times Chebyshev
//! polynomials T_n(2x/p - 1), n < N. For gamma = 0 the paper's h = Q e^b cos(pi Omega)
//! x^(-1 - 2 Omega(x)) (p^2 - x^2)^(-1/2 + Omega(x)) (eq (40)) is the first family times an
//! analytic function, so the expansion converges geometrically.

use complexfn::{Rayleigh, Real};
use wedge::omega::OmegaFn;

/// Which apex factor a family carries.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Family {
    /// x^(-1 - lambda_j(x)) with the j-th local root.
    Root(usize),
    /// x^(-1) (double root t = 0: S ~ ln x).
    Log,
    /// No apex factor.
    Regular,
    /// x^(-1 - lambda) with a fixed lambda (diagnostics).
    Fixed(f64),
}

/// The basis: families times Chebyshev polynomials, at the precision of p.
#[derive(Clone, Debug)]
pub struct Basis<T = f64> {
    p: T,
    beta: T,
    gamma: T,
    ray: Rayleigh<T>,
    omega: OmegaFn<T>,
    families: Vec<Family>,
    degree: usize,
}

impl<T: Real> Basis<T> {
    /// The basis for contact speed p, coupling beta, friction gamma, with `degree` Chebyshev
    /// polynomials per family; `regular` adds the family without apex factor; `fixed` replaces
    /// the apex families by fixed exponents.
    pub fn new(
        ray: Rayleigh<T>,
        p: T,
        beta: T,
        gamma: T,
        degree: usize,
        regular: bool,
        fixed: Option<&[f64]>,
    ) -> Self {
        let m = ray.m().clone();
        let ex = crate::apex::exponents(m, beta.clone(), gamma.clone());
        let mut families: Vec<Family> = if ex.kind == wedge::ApexRegime::Logarithmic {
            vec![Family::Log]
        } else {
            (0..ex.lambdas.len()).map(Family::Root).collect()
        };
        if let Some(l) = fixed {
            families = l.iter().map(|&x| Family::Fixed(x)).collect();
        }
        if regular {
            families.push(Family::Regular);
        }
        let omega = OmegaFn::new(ray.clone(), beta.clone() + &gamma, beta.clone() * &gamma);
        Basis {
            p,
            beta,
            gamma,
            ray,
            omega,
            families,
            degree,
        }
    }

    /// Number of basis functions.
    pub fn len(&self) -> usize {
        self.families.len() * self.degree
    }
    /// Always false (a basis has at least one family).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The families.
    pub fn families(&self) -> &[Family] {
        &self.families
    }
    /// Polynomials per family.
    pub fn degree(&self) -> usize {
        self.degree
    }
    /// Omega(x), eq (31).
    pub fn omega(&self, x: &T) -> T {
        self.omega.omega(x)
    }
    /// The Rayleigh family of the material.
    pub fn rayleigh(&self) -> &Rayleigh<T> {
        &self.ray
    }

    /// The family weights at v (edge factor times apex factor), given p - v exactly.
    pub fn weights(&self, v: &T, p_minus_v: &T) -> Vec<T> {
        let edge = p_minus_v.clone().powf(&(self.omega.omega(v) - 0.5));
        let needs_roots = self.families.iter().any(|f| matches!(f, Family::Root(_)));
        let lams = if needs_roots {
            crate::apex::local_exponents(&self.ray, &self.beta, &self.gamma, v)
        } else {
            vec![]
        };
        let ln_v = v.clone().ln();
        self.families
            .iter()
            .map(|f| match f {
                Family::Root(j) => {
                    edge.clone() * (ln_v.clone() * &(-(lams[*j].clone() + 1.0))).exp()
                }
                Family::Log => edge.clone() / v,
                Family::Regular => edge.clone(),
                Family::Fixed(l) => edge.clone() * (ln_v.clone() * (-(1.0 + l))).exp(),
            })
            .collect()
    }

    /// The Chebyshev argument 2v/p - 1, written through the offset nearer to v so that it is
    /// accurate at both ends.
    pub fn cheb_arg(&self, v: &T, p_minus_v: &T) -> T {
        if *p_minus_v < *v {
            v.one() - p_minus_v.clone() * 2.0 / &self.p
        } else {
            v.clone() * 2.0 / &self.p - 1.0
        }
    }

    /// All basis functions h_k(v), written into `out` (length [`Self::len`]), given p - v.
    pub fn eval(&self, v: &T, p_minus_v: &T, out: &mut [T]) {
        let w = self.weights(v, p_minus_v);
        let t = self.cheb_arg(v, p_minus_v);
        self.fill(&w, &t, out);
    }

    /// All basis functions from the family weights `w` ([`Self::weights`]) and the Chebyshev
    /// argument `t` ([`Self::cheb_arg`]) at one point; bases that differ only in the degree
    /// share the weights.
    pub fn fill(&self, w: &[T], t: &T, out: &mut [T]) {
        let n = self.degree;
        let t2 = t.clone() * 2.0;
        for (fi, wf) in w.iter().enumerate() {
            let o = &mut out[fi * n..(fi + 1) * n];
            let (mut t0, mut t1) = (t.one(), t.clone());
            for (k, slot) in o.iter_mut().enumerate() {
                *slot = match k {
                    0 => wf.clone(),
                    1 => wf.clone() * t,
                    _ => {
                        let tn = t2.clone() * &t1 - &t0;
                        t0 = std::mem::replace(&mut t1, tn);
                        wf.clone() * &t1
                    }
                };
            }
        }
    }
}
