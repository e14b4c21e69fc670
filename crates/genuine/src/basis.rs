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

use complexfn::Rayleigh;
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

/// The basis: families times Chebyshev polynomials.
#[derive(Clone, Debug)]
pub struct Basis {
    p: f64,
    beta: f64,
    gamma: f64,
    ray: Rayleigh<f64>,
    omega: OmegaFn<f64>,
    families: Vec<Family>,
    degree: usize,
}

impl Basis {
    /// The basis for contact speed p, coupling beta, friction gamma, with `degree` Chebyshev
    /// polynomials per family; `regular` adds the family without apex factor; `fixed` replaces
    /// the apex families by fixed exponents.
    pub fn new(
        ray: Rayleigh<f64>,
        p: f64,
        beta: f64,
        gamma: f64,
        degree: usize,
        regular: bool,
        fixed: Option<&[f64]>,
    ) -> Self {
        let m = *ray.m();
        let ex = crate::apex::exponents(m, beta, gamma);
        let mut families: Vec<Family> = if ex.kind == crate::apex::ApexKind::Logarithmic {
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
        let omega = OmegaFn::new(ray.clone(), beta + gamma, beta * gamma);
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
    pub fn omega(&self, x: f64) -> f64 {
        self.omega.omega(&x)
    }
    /// The Rayleigh family of the material.
    pub fn rayleigh(&self) -> &Rayleigh<f64> {
        &self.ray
    }

    /// The family weights at v (edge factor times apex factor), given p - v exactly.
    pub fn weights(&self, v: f64, p_minus_v: f64) -> Vec<f64> {
        let edge = p_minus_v.powf(-0.5 + self.omega.omega(&v));
        let needs_roots = self.families.iter().any(|f| matches!(f, Family::Root(_)));
        let lams = if needs_roots {
            crate::apex::local_exponents(&self.ray, self.beta, self.gamma, v)
        } else {
            vec![]
        };
        self.families
            .iter()
            .map(|f| match f {
                Family::Root(j) => edge * v.powf(-1.0 - lams[*j]),
                Family::Log => edge / v,
                Family::Regular => edge,
                Family::Fixed(l) => edge * v.powf(-1.0 - l),
            })
            .collect()
    }

    /// All basis functions h_k(v), written into `out` (length [`Self::len`]), given p - v.
    pub fn eval(&self, v: f64, p_minus_v: f64, out: &mut [f64]) {
        let w = self.weights(v, p_minus_v);
        let t = 2.0 * v / self.p - 1.0;
        let n = self.degree;
        for (fi, wf) in w.iter().enumerate() {
            let o = &mut out[fi * n..(fi + 1) * n];
            let (mut t0, mut t1) = (1.0, t);
            for (k, slot) in o.iter_mut().enumerate() {
                let tk = if k == 0 {
                    1.0
                } else if k == 1 {
                    t
                } else {
                    let t2 = 2.0 * t * t1 - t0;
                    t0 = t1;
                    t1 = t2;
                    t2
                };
                *slot = wf * tk;
            }
        }
    }
}
