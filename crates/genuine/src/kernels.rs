//! The contour representation of the self-similar surface response (Lamb's kernels of
//! [`lamb::transform`]) used by the genuine wedge solver.
//!
//! Degree-0 tractions S_k(x/t) and displacements u_j = t U_j(x/t): with z = 1/xi the traction
//! transform is z^2 F_k(z)/s^2, F_k(z) = Int S_k(w)/(w - z)^2 dw, and the displacement one is
//! -(2 z^3/s^3) Int U_j(w)/(w - z)^3 dw. Hence Phi_j(z) = Int U_j(w)/(w - z) dw satisfies
//! Phi_j'' = -K_jk(1/z) F_k(z)/z; integrating twice from infinity along z = x0 + i y and
//! taking the jump U = Im Phi(x0 + i0)/pi gives the representation used here,
//!
//! ```text
//!   U_j(x0)  = (1/pi) Im Int_0^inf y K_jk(1/z) F_k(z)/z dy,
//!   U_j'(x0) = (1/pi) Re Int_0^inf   K_jk(1/z) F_k(z)/z dy,        z = x0 + i y,
//! ```
//!
//! which needs no principal values and no Rayleigh-pole terms.
//!
use complexfn::{Cx, Real};

pub use lamb::transform::{Kernels, Lamb, C64};

/// The contour representation of the displacement on the surface (module docs), for the
/// kernels of [`Lamb`].
pub trait ContourDisplacement<T: Real> {
    /// The displacements (U_y, U_x)(x0) and their slopes (U_y', U_x')(x0) produced by degree-0
    /// tractions whose F-functions are given by `f(z) = [F_y(z), F_x(z)]`, from the contour
    /// representation along z = x0 + i y (module docs). `rel_tol` is the tolerance of the
    /// nested tanh-sinh rule in y (mapped by y = Y u/(1 - u), Y = max(|x0|, 0.05); step down
    /// to 2^-8 at 53 bits, one more halving per doubling of the precision). Returns the values
    /// and the estimated absolute error.
    fn displacement<F>(&self, x0: T, rel_tol: f64, f: F) -> ([T; 4], f64)
    where
        F: FnMut(Cx<T>) -> [Cx<T>; 2];
}

impl<T: Real> ContourDisplacement<T> for Lamb<T> {
    fn displacement<F>(&self, x0: T, rel_tol: f64, mut f: F) -> ([T; 4], f64)
    where
        F: FnMut(Cx<T>) -> [Cx<T>; 2],
    {
        let prec = x0.prec();
        let (v, err) = y_integral(&x0, 4, rel_tol, prec, |y, z, jac, out| {
            let fz = f(z.clone());
            let kk = self.kernels(&z.clone().recip());
            let zi = z.clone().recip();
            for j in 0..2 {
                let g = (kk[j][0].clone() * &fz[0] + kk[j][1].clone() * &fz[1]) * &zi;
                out[j] = g.im.clone() * y * jac;
                out[2 + j] = g.re * jac;
            }
        });
        let mut it = v.into_iter();
        let mut next = || it.next().unwrap_or_else(|| x0.zero());
        ([next(), next(), next(), next()], err)
    }
}

/// Smallest step of the nested tanh-sinh rule of the contour integrals at `bits` of precision:
/// 2^-8 at 53 bits, halved once more for every doubling of the precision (the rule converges
/// quadratically once resolved, so the number of correct digits doubles per level).
pub fn contour_h_min(bits: u32) -> f64 {
    let extra = (f64::from(bits.max(53)) / 53.0).log2().ceil() as i32;
    0.5_f64.powi(8 + extra)
}

/// The scale Y = max(|x0|, 0.05) of the map y = Y u/(1 - u) of the y-integral.
pub(crate) fn y_scale<T: Real>(x0: &T) -> T {
    x0.clone().abs().max(x0.lit(0.05))
}

/// The margin of the y-rule's reach ([`y_rule_t_max`]): the bound of the u-integrand at the
/// ends over the integral, taken as at most 2^24 (`docs/contour-sums.md`).
pub const Y_RULE_TAIL_MARGIN: f64 = 16_777_216.0;

/// Truncation of the tanh-sinh variable of the y-integral for the relative tolerance
/// `rel_tol`: in u = y/(Y + y) the integrands of the contour representation are bounded at
/// both ends (U ~ y, U' ~ F(x0)/x0 as y -> 0; both ~ 1/Y as u -> 1, where F ~ 1/z^2), so the
/// lost tails are the smallest offsets 2 e^(-pi sinh t) times that bound; they reach
/// `rel_tol` / [`Y_RULE_TAIL_MARGIN`]. (At 104 bits and the solver's tolerance 2^-97, t <= 4.0
/// instead of the 5 of [`crate::quad::t_max`], a fifth fewer nodes.)
pub fn y_rule_t_max(rel_tol: f64) -> f64 {
    let reach = (2.0 * Y_RULE_TAIL_MARGIN / rel_tol.clamp(1e-300, 1e-3)).ln();
    (reach / std::f64::consts::PI).asinh()
}

/// The integral over y in (0, inf) along z = x0 + i y of `g(y, z, jac, out)` (which writes
/// `dim` real components, already multiplied by the Jacobian `jac`), divided by pi; the
/// y-variable is mapped by y = Y u/(1 - u), Y = max(|x0|, 0.05), and the u-integral done by
/// nested tanh-sinh to `rel_tol`.
pub(crate) fn y_integral<T, G>(x0: &T, dim: usize, rel_tol: f64, prec: u32, g: G) -> (Vec<T>, f64)
where
    T: Real,
    G: FnMut(&T, Cx<T>, &T, &mut [T]),
{
    y_integral_checked(x0, dim, dim, rel_tol, prec, g)
}

/// [`y_integral`] whose convergence test looks at the first `checked` components only
/// ([`crate::quad::integrate_vec_checked`]).
pub(crate) fn y_integral_checked<T, G>(
    x0: &T,
    dim: usize,
    checked: usize,
    rel_tol: f64,
    prec: u32,
    mut g: G,
) -> (Vec<T>, f64)
where
    T: Real,
    G: FnMut(&T, Cx<T>, &T, &mut [T]),
{
    let scale = y_scale(x0);
    let zero = x0.zero();
    let one = x0.one();
    let pi = x0.pi();
    let (mut vals, err) = crate::quad::integrate_vec_checked(
        &zero,
        &one,
        dim,
        checked,
        rel_tol,
        contour_h_min(prec),
        y_rule_t_max(rel_tol),
        |nd, out| {
            // y = Y u/(1 - u), dy = Y du/(1 - u)^2
            let one_minus = &nd.to_b;
            let y = scale.clone() * &nd.from_a / one_minus;
            let jac = scale.clone() / one_minus.clone().sqr();
            if !y.is_finite() || !jac.is_finite() || y == 0.0 {
                return;
            }
            let z = Cx::new(x0.clone(), y.clone());
            g(&y, z, &jac, out);
        },
    );
    vals.iter_mut().for_each(|v| *v /= &pi);
    let err = err / pi.to_f64();
    (vals, err)
}

/// F(z) = Int S(w)/(w - z)^2 dw for a point traction S(w) = delta(w) (that is, a line load
/// P t delta(x) growing linearly in time): F = 1/z^2.
pub fn point_load<T: Real>(z: Cx<T>) -> Cx<T> {
    (z.clone() * &z).recip()
}

/// F(z) for a uniform traction S(w) = 1 on |w| < p: F = [-1/(w - z)]_{-p}^{p} = -2p/(p^2 - z^2).
pub fn uniform_load<T: Real>(p: T, z: Cx<T>) -> Cx<T> {
    let d = (-(z.clone() * &z)).add_re(&p.clone().sqr());
    Cx::real(p * -2.0) / &d
}

/// The Cauchy sums behind the F-functions of sampled loads: for each load c and each class k of
/// samples (the contour probe sums the nodes of the coarser level apart),
///
/// ```text
///   A_ck(z) = Sum_{i in k} a_ci/(v_i^2 - z^2),   B_ck(z) = Sum_{i in k} a_ci v_i/(v_i^2 - z^2),
/// ```
///
/// with a_ci = 2 (v h w)_ci, so that F_y = A and F_x = -gamma B/z. Near the contact the sums
/// are taken term by term; far from it (|z|^2 > p^2/r_max, see `docs/contour-sums.md`) from the
/// moment expansion 1/(v^2 - z^2) = -Sum_m v^(2m)/z^(2m + 2), truncated where its remainder
/// lies below one unit of round-off of the term-by-term sum.
#[derive(Clone, Debug)]
pub(crate) struct CauchySums<S> {
    loads: usize,
    classes: usize,
    /// v_i^2, the samples ordered by class
    v2: Vec<S>,
    /// the range of each class in that order
    ranges: Vec<std::ops::Range<usize>>,
    /// per load, per sample in that order: a and b = a v
    a: Vec<Vec<S>>,
    b: Vec<Vec<S>>,
    /// ones, for sums and additions of a constant through the slice operations
    ones: Vec<S>,
    /// per class, per load, per power m < `terms`: (Sum a v^(2m), Sum b v^(2m))
    moments: Vec<(S, S)>,
    terms: usize,
    /// the largest v^2, rounded up
    v2_max: f64,
    /// the relative level of the truncation, 2^-bits
    eps: f64,
}

impl<S: Real> CauchySums<S> {
    /// The sums for samples at `v` (of class `class[i] < classes`) and loads `vhw[c][i]` (v
    /// times the slope times the rule's weight), at the precision of the values, with at most
    /// `terms` terms of the moment expansion.
    pub(crate) fn new(
        v: &[S],
        class: &[usize],
        classes: usize,
        vhw: &[&[S]],
        terms: usize,
        like: &S,
    ) -> Self {
        let loads = vhw.len();
        let n = v.len();
        let zero = like.zero();
        // the samples ordered by class (each class then a contiguous range)
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by_key(|&i| class[i]);
        let ranges = (0..classes)
            .map(|k| {
                let start = order.partition_point(|&i| class[i] < k);
                let end = order.partition_point(|&i| class[i] <= k);
                start..end
            })
            .collect();
        let v2: Vec<S> = order.iter().map(|&i| v[i].clone().sqr()).collect();
        let a: Vec<Vec<S>> = vhw
            .iter()
            .map(|h| order.iter().map(|&i| h[i].clone() * 2.0).collect())
            .collect();
        let b: Vec<Vec<S>> = a
            .iter()
            .map(|ac| {
                ac.iter()
                    .zip(&order)
                    .map(|(x, &i)| x.clone() * &v[i])
                    .collect()
            })
            .collect();
        let mut moments = vec![(zero.clone(), zero.clone()); classes * loads * terms];
        let mut pw = zero.clone();
        for (j, &i) in order.iter().enumerate() {
            // v^(2m) by repeated products: the moments carry the same relative round-off as
            // the terms they sum
            pw.clone_from(&like.one());
            for m in 0..terms {
                for c in 0..loads {
                    let slot = &mut moments[(class[i] * loads + c) * terms + m];
                    slot.0.mul_add_assign(&a[c][j], &pw);
                    slot.1.mul_add_assign(&b[c][j], &pw);
                }
                pw *= &v2[j];
            }
        }
        let v2_max = v2.iter().fold(0.0_f64, |m, x| m.max(x.to_f64())) * (1.0 + 1e-12);
        CauchySums {
            loads,
            classes,
            v2,
            ranges,
            a,
            b,
            ones: vec![like.one(); n],
            moments,
            terms,
            v2_max,
            eps: 2f64.powi(-(like.prec() as i32)),
        }
    }

    /// Terms of the moment expansion needed at z (`None`: sum term by term): the smallest M
    /// with r^M <= eps (1 - r)/(1 + r), r = max v^2/|z|^2, if at most the terms stored.
    fn terms_at(&self, z: &Cx<S>) -> Option<usize> {
        let z2 = z.norm_sqr().to_f64() * (1.0 - 1e-12);
        let r = self.v2_max / z2;
        if r.is_nan() || r >= 1.0 || self.terms == 0 {
            return None;
        }
        if r == 0.0 {
            return Some(1);
        }
        let m = ((self.eps * (1.0 - r) / (1.0 + r)).ln() / r.ln()).ceil();
        (m >= 1.0 && m <= self.terms as f64).then_some(m as usize)
    }

    /// (A_ck(z), B_ck(z)) for every class k and load c, at index k * loads + c.
    pub(crate) fn at(&self, z: &Cx<S>) -> Vec<(Cx<S>, Cx<S>)> {
        let zero = z.re.zero();
        let nl = self.loads;
        let z2 = z.clone() * z;
        if let Some(mt) = self.terms_at(z) {
            // A = -w Sum_m mu_m w^m, w = 1/z^2, by Horner's rule
            let w = z2.recip();
            return (0..self.classes * nl)
                .map(|j| {
                    let mu = &self.moments[j * self.terms..j * self.terms + mt];
                    let horner = |pick: fn(&(S, S)) -> &S| {
                        let mut acc = Cx::real(pick(&mu[mt - 1]).clone());
                        for m in (0..mt - 1).rev() {
                            acc = (acc * &w).add_re(pick(&mu[m]));
                        }
                        -(acc * &w)
                    };
                    (horner(|x| &x.0), horner(|x| &x.1))
                })
                .collect();
        }
        let (zr, zi) = (z2.re, z2.im);
        let zi2 = zi.clone().sqr();
        let n = self.v2.len();
        let ones = &self.ones;
        // 1/(v^2 - z^2) = (q + i Im z^2)/(q^2 + (Im z^2)^2), q = v^2 - Re z^2, by the slice
        // operations of the precision layer
        let mut q = self.v2.clone();
        S::mul_add_slice(&mut q, ones, &-zr);
        let mut den = vec![zero.clone(); n];
        S::mul_slice(&mut den, &q, &q);
        S::mul_add_slice(&mut den, ones, &zi2);
        let mut inv = vec![zero.clone(); n];
        S::div_slice(&mut inv, ones, &den);
        let mut t = den;
        let mut out = Vec::with_capacity(self.classes * nl);
        for r in &self.ranges {
            for c in 0..nl {
                // Sum a q/|.|^2 + i Im z^2 Sum a/|.|^2, and the same for b
                let mut sum = |w: &[S]| {
                    S::mul_slice(&mut t[r.clone()], &w[r.clone()], &inv[r.clone()]);
                    let (mut re, mut im) = (zero.clone(), zero.clone());
                    re.dot_add(&t[r.clone()], &q[r.clone()]);
                    im.dot_add(&t[r.clone()], &ones[r.clone()]);
                    Cx::new(re, im * &zi)
                };
                let fa = sum(&self.a[c]);
                let fb = sum(&self.b[c]);
                out.push((fa, fb));
            }
        }
        out
    }
}

/// The displacement integrands (U_y, U_x, U_y', U_x' before the y-integral) at z = x0 + i y of
/// a load with Cauchy sums (A, B) ([`CauchySums`]): F_y = A, F_x = -gamma B/z, and
/// g_j = K_jk(1/z) F_k(z)/z, giving (Im g_y y jac, Im g_x y jac, Re g_y jac, Re g_x jac).
pub(crate) fn contour_integrand<S: Real>(
    k: &Kernels<S>,
    sums: &(Cx<S>, Cx<S>),
    zinv: &Cx<S>,
    gamma: &S,
    y: &S,
    jac: &S,
) -> [S; 4] {
    let fy = &sums.0;
    let fx = (sums.1.clone() * zinv).scale(&-gamma.clone());
    let mut out: [S; 4] = std::array::from_fn(|_| y.zero());
    for j in 0..2 {
        let g = (k[j][0].clone() * fy + k[j][1].clone() * &fx) * zinv;
        out[j] = g.im.clone() * y * jac;
        out[2 + j] = g.re * jac;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use complexfn::Dd;

    /// The moment expansion against the term-by-term sums, wherever it is used, at f64 and at
    /// double-double: within a few units of round-off of Sum |a_i/(v_i^2 - z^2)|.
    fn moments_agree<S: Real>(like: &S) {
        let p = like.lit(0.3);
        let n = 200;
        let v: Vec<S> = (0..n)
            .map(|i| p.clone() * ((i as f64 + 0.5) / n as f64).powf(1.3))
            .collect();
        let hw: Vec<S> = (0..n)
            .map(|i| like.lit(((i * 7919) % 101) as f64 / 50.0 - 1.0) / 3.0 * &v[i])
            .collect();
        let class: Vec<usize> = (0..n).map(|i| i % 2).collect();
        let far = CauchySums::new(&v, &class, 2, &[&hw], like.prec() as usize, like);
        let near = CauchySums::new(&v, &class, 2, &[&hw], 0, like);
        // the reference: the term-by-term sums of the same inputs at 200 bits
        let big = |x: &S| x.to_mpfr(200);
        let vb: Vec<rug::Float> = v.iter().map(big).collect();
        let hb: Vec<rug::Float> = hw.iter().map(big).collect();
        let exact = CauchySums::new(&vb, &class, 2, &[&hb], 0, &vb[0]);
        let mut used = 0;
        for (x, y) in [
            (0.15, 0.3),
            (0.15, 0.4),
            (0.15, 1.0),
            (0.15, 30.0),
            (0.5, 0.1),
            (0.6, 0.0),
        ] {
            let z = Cx::new(like.lit(x), like.lit(y));
            if far.terms_at(&z).is_some() {
                used += 1;
            }
            let zb = Cx::new(big(&z.re), big(&z.im));
            let (a, b, r) = (far.at(&z), near.at(&z), exact.at(&zb));
            for k in 0..2 {
                // the size of the terms: Sum |a_i|/|v_i^2 - z^2| (a_i = 2 v hw, |b_i| <= |a_i|)
                let mut size = 0.0;
                for i in (0..n).filter(|i| class[*i] == k) {
                    let d = (Cx::real(v[i].clone().sqr()) - z.clone() * &z)
                        .abs()
                        .to_f64();
                    size += 2.0 * hw[i].to_f64().abs() / d;
                }
                let tol = 16.0 * 2f64.powi(-(like.prec() as i32)) * size;
                for (what, s) in [("moments", &a[k]), ("terms", &b[k])] {
                    let ea = (big(&s.0.re) - r[k].0.re.clone()).abs().to_f64()
                        + (big(&s.0.im) - r[k].0.im.clone()).abs().to_f64();
                    let eb = (big(&s.1.re) - r[k].1.re.clone()).abs().to_f64()
                        + (big(&s.1.im) - r[k].1.im.clone()).abs().to_f64();
                    assert!(
                        ea <= tol && eb <= tol,
                        "{what}, z = {x} + {y}i: {ea:e} {eb:e} > {tol:e}"
                    );
                }
            }
        }
        assert!(
            used >= 3,
            "the moment expansion is used at {used} points only"
        );
    }

    /// The y-rule truncated by [`y_rule_t_max`] on an integrand of the worst shape for it
    /// (bounded and non-zero at both ends of u, 1/Y = 20 times the integral at u = 1):
    /// Int_0^inf dy/(1 + y)^2 = 1, to the tolerance at f64, double-double and 200 bits.
    fn truncated_y_rule<S: Real>(like: &S, rel_tol: f64) {
        let x0 = like.zero();
        let (v, _) = y_integral(&x0, 1, rel_tol, like.prec(), |y, _z, jac, out| {
            out[0] = jac.clone() / (y.clone() + 1.0).sqr();
        });
        let err = (v[0].clone() * like.pi() - 1.0).abs().to_f64();
        assert!(
            err <= rel_tol,
            "{} bits: {err:e} > {rel_tol:e}",
            like.prec()
        );
    }

    #[test]
    fn truncated_y_rule_meets_the_tolerance() {
        truncated_y_rule(&0.0_f64, 2f64.powi(-46));
        truncated_y_rule(&Dd::from_f64(0.0), 2f64.powi(-97));
        truncated_y_rule(&rug::Float::with_val(200, 0), 2f64.powi(-193));
    }

    #[test]
    fn moment_expansion_agrees_with_the_term_by_term_sums() {
        moments_agree(&0.0_f64);
        moments_agree(&Dd::from_f64(0.0));
    }
}
