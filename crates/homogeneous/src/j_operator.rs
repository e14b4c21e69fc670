//! The operators J_k of eq (13) applied to the kernels of eqs (10) and (11).
//!
//! ```text
//!   J_k(f) = 1/(n-1)! Int_{r/(c1 t)}^{m_k/h_k} v^(-n-2) (v t - r/c1)^(n-1) f(v) dv      (13)
//! ```
//!
//! (lower limit read r/(c1 t), see the crate docs). The integrand is built from
//! W_k = Omega_k(zeta_k) + conj(omega_k(conj zeta_k)) (12a) with Omega_k, omega_k from (16) in the
//! upper and lower half-planes, and
//!
//! ```text
//!   U(W) = Re[p_k(v) W] - i Im W,   V(W) = K(v) Re[p_k(v) W] - 2i Im W.     (12a, b)
//! ```
//!
//! One pass computes, for one k, the four integrals the field needs (see [`JTerms`]). The
//! range is split at v = m_k (behind the front / head-wave wedge, eqs (14a)/(14b)) and at the
//! breakpoints m_R, m, 1 and [`crate::Potentials::breakpoints`]; tanh-sinh quadrature on each piece
//! receives the exact offsets m_k - v and v - r/(c1 t), so the square-root behaviour at the
//! fronts costs nothing.
//!
//! Why these kernels: d^(n+1)u/dt^(n+1) = (1/2r)[U(W_1) - i U(W_2)] at v = r/t, i.e.
//! (1/2)grad Re F_1 + curl-part, where W_k is the derivative of a degree-0 potential with
//! respect to the Chaplygin variable sech^-1(v/m_k) + i theta; J_k is the (n+1)-fold time
//! integral written in v.

use complexfn::quadrature::{tanh_sinh, CachedRules, Point, QuadValue, TsOptions};
use complexfn::{Cx, RayleighValues, Real, Side};

use crate::error::Result;
use crate::zeta_map::{h_k, map_behind, map_head, MapPoint};
use crate::{omegas, Potentials};

/// The four J_k integrals of one wave k at one point (r, theta, t).
#[derive(Clone, Debug)]
pub struct JTerms<T> {
    /// J_k[(v t - r) U(W_k)]: eq (10), (2 c1 n) u = J_1[.] - i J_2[.].
    pub ju: Cx<T>,
    /// J_k[V(W_k)]: eq (11b), (2 c1^2/mu) s_theta = J_1[.] - i J_2[.].
    pub jv: Cx<T>,
    /// J_k[v^2 Re(p_k W_k)]: dilatation Delta = -(1/2) J_1[.], rotation
    /// (curl u)_z = (1/(2 m^2)) J_2[.], and (11a).
    pub jp: T,
    /// 1/(n-1)! Int v^(-n-1) (v t - r)^(n-1) U(W_k) dv: particle velocity,
    /// 2 du/dt = [.]_1 - i [.]_2.
    pub jdt: Cx<T>,
}

impl<T: Real> JTerms<T> {
    /// All four integrals zero (point ahead of the k-front), at the precision of `like`.
    pub fn zero(like: &T) -> Self {
        let z = Cx::real(like.zero());
        JTerms {
            ju: z.clone(),
            jv: z.clone(),
            jp: like.zero(),
            jdt: z,
        }
    }
}

impl<T: Real> QuadValue<T> for JTerms<T> {
    fn zero_like(like: &T) -> Self {
        JTerms::zero(like)
    }
    fn add_scaled(&mut self, v: &Self, w: &T) {
        self.ju.add_scaled(&v.ju, w);
        self.jv.add_scaled(&v.jv, w);
        self.jp += v.jp.clone() * w;
        self.jdt.add_scaled(&v.jdt, w);
    }
    fn magnitude(&self) -> T {
        self.ju.abs() + self.jv.abs() + self.jp.clone().abs() + self.jdt.abs()
    }
    fn scaled(&self, s: &T) -> Self {
        JTerms {
            ju: self.ju.clone().scale(s),
            jv: self.jv.clone().scale(s),
            jp: self.jp.clone() * s,
            jdt: self.jdt.clone().scale(s),
        }
    }
    fn distance(&self, other: &Self) -> T {
        self.minus(other).magnitude()
    }
    fn minus(&self, other: &Self) -> Self {
        JTerms {
            ju: self.ju.clone() - &other.ju,
            jv: self.jv.clone() - &other.jv,
            jp: self.jp.clone() - &other.jp,
            jdt: self.jdt.clone() - &other.jdt,
        }
    }
}

/// Rayleigh values at conj(zeta) from those at zeta: p_k(conj z) = -conj p_k(z) (the branch of
/// `docs/errata.md`, section 1 is odd and real-symmetric up to sign), K, L, R real-symmetric.
fn conj_values<T: Real>(rv: &RayleighValues<T>) -> RayleighValues<T> {
    RayleighValues {
        p1: -rv.p1.clone().conj(),
        p2: -rv.p2.clone().conj(),
        k: rv.k.clone().conj(),
        l: rv.l.clone().conj(),
        r: rv.r.clone().conj(),
        l_over_s: rv.l_over_s.clone().conj(),
        r_over_s: rv.r_over_s.clone().conj(),
    }
}

/// W_k = Omega_k(zeta_k) + conj(omega_k(conj zeta_k)) (eq (12a)) at a mapped point.
pub fn w_k<T: Real, P: Potentials<T> + ?Sized>(pot: &P, k: usize, mp: &MapPoint<T>) -> Cx<T> {
    let ray = pot.rayleigh();
    let pick = |o: (Cx<T>, Cx<T>)| if k == 1 { o.0 } else { o.1 };
    if mp.on_axis {
        // head-wave wedge: zeta real in m <= |zeta| <= 1; F, G analytic there, p_1 on its cut.
        let mut xi = mp.zeta.re.clone();
        // At the head-wave front zeta_2 -> +-1 (branch point of p_1, where Omega_2 has a finite
        // limit); keep a rounded value off the branch point itself.
        let lim = xi.one() - xi.epsilon() * 4.0;
        if xi.clone().abs() > lim {
            xi = lim.copysign(&xi);
        }
        let (f, g) = pot.fg_real(&xi);
        let up = ray.at_boundary(&xi, Side::Upper);
        let lo = ray.at_boundary(&xi, Side::Lower);
        pick(omegas(&up, &f, &g)) + pick(omegas(&lo, &f, &g)).conj()
    } else {
        let z = &mp.zeta;
        let zb = z.clone().conj();
        let rv = ray.at(z);
        let rvb = conj_values(&rv);
        let up = pick(omegas(&rv, &pot.f(z), &pot.g(z)));
        let lo = pick(omegas(&rvb, &pot.f(&zb), &pot.g(&zb)));
        up + lo.conj()
    }
}

/// Quadrature options for the J_k integrals at a given precision: relative tolerance
/// 1e-13 for f64, about eps^0.7 (1e-54 at 256 bits) above.
pub fn default_options(prec: u32) -> TsOptions {
    if prec <= 64 {
        TsOptions::new(1e-13)
    } else {
        TsOptions::new(2f64.powf(-0.7 * f64::from(prec)))
    }
}

struct Segment<T> {
    lo: T,
    hi: T,
    lo_is_a: bool,
    hi_is_mk: bool,
    head: bool,
}

/// Evaluate the four J_k integrals of wave `k` (1 or 2) at (r, theta, t), units c1 = 1.
/// `opts` sets the quadrature tolerance (see [`default_options`]).
#[allow(clippy::too_many_arguments)]
pub fn j_terms<T, P>(
    pot: &P,
    k: usize,
    r: &T,
    theta: &T,
    t: &T,
    opts: TsOptions,
) -> Result<JTerms<T>>
where
    T: CachedRules,
    P: Potentials<T> + ?Sized,
{
    let ray = pot.rayleigh();
    let n = pot.degree();
    let mk = if k == 1 { r.one() } else { ray.m().clone() };
    let a = r.clone() / t;
    let b = mk.clone() / h_k(theta, &mk);
    if a >= b {
        return Ok(JTerms::zero(r));
    }
    let (sin, cos) = theta.clone().sin_cos();
    // pieces
    let mut segs: Vec<Segment<T>> = Vec::new();
    if a < mk {
        let mut cuts: Vec<T> = vec![ray.m_r().clone(), ray.m().clone(), r.one()];
        cuts.extend(pot.breakpoints());
        cuts.retain(|c| {
            *c > a
                && *c < mk
                && (c.clone() - &a) > a.lit(1e-3) * &mk
                && (mk.clone() - c) > a.lit(1e-3)
        });
        cuts.sort_by(|x, y| x.partial_cmp(y).unwrap_or(std::cmp::Ordering::Equal));
        cuts.dedup_by(|x, y| (x.clone() - &*y).abs() < 1e-9);
        let mut lo = a.clone();
        let mut first = true;
        for c in cuts {
            segs.push(Segment {
                lo: lo.clone(),
                hi: c.clone(),
                lo_is_a: first,
                hi_is_mk: false,
                head: false,
            });
            lo = c;
            first = false;
        }
        segs.push(Segment {
            lo,
            hi: mk.clone(),
            lo_is_a: first,
            hi_is_mk: true,
            head: false,
        });
    }
    if b > mk {
        let (lo, lo_is_a) = if a > mk {
            (a.clone(), true)
        } else {
            (mk.clone(), false)
        };
        segs.push(Segment {
            lo,
            hi: b.clone(),
            lo_is_a,
            hi_is_mk: false,
            head: true,
        });
    }
    let mut fact = r.one();
    for j in 1..n {
        fact *= r.lit(f64::from(j));
    }
    let inv_fact = fact.recip();
    let inv_m2 = ray.m2().clone().recip();
    let mut total = JTerms::zero(r);
    for s in &segs {
        let integrand = |pt: &Point<T>| -> JTerms<T> {
            let v = &pt.v;
            let mp = if s.head {
                let vm = if s.lo_is_a {
                    s.lo.clone() - &mk + &pt.from_a
                } else {
                    pt.from_a.clone()
                };
                map_head(v, &vm, &mk, &cos, &sin)
            } else {
                let mv = if s.hi_is_mk {
                    pt.to_b.clone()
                } else {
                    mk.clone() - v
                };
                map_behind(v, &mv, &mk, &cos, &sin)
            };
            let w = w_k(pot, k, &mp);
            let pw = (mp.p_v.clone() * &w).re;
            let kv = v.lit(2.0) - v.clone().sqr() * &inv_m2;
            let u = Cx::new(pw.clone(), -w.im.clone());
            let vv = Cx::new(kv * &pw, -(w.im.clone() * 2.0));
            let d = if s.lo_is_a {
                pt.from_a.clone() * t
            } else {
                v.clone() * t - r
            };
            let dn1 = d.clone().powi(n as i32 - 1);
            let vn1 = v.clone().powi(-(n as i32) - 1);
            let base = vn1.clone() / v * &dn1 * &inv_fact; // v^(-n-2) d^(n-1)/(n-1)!
            JTerms {
                ju: u.clone().scale(&(base.clone() * &d)),
                jv: vv.scale(&base),
                jp: pw * v * v * &base,
                jdt: u.scale(&(vn1 * &dn1 * &inv_fact)),
            }
        };
        let est = tanh_sinh(&s.lo, &s.hi, opts, integrand)?;
        total.add_scaled(&est.value, &r.one());
    }
    Ok(total)
}
