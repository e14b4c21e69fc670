//! Fixed-step quadrature rules with exact endpoint offsets, generic over the precision layer
//! (the rules behind every integral of this crate).
//!
//! * Tanh-sinh: on (a, b) the node for t = k h is v = a + d_a = b - d_b with
//!   d_a = (b - a)/(1 + e^(-2u)), d_b = (b - a)/(1 + e^(2u)), u = (pi/2) sinh t, and weight
//!   h (b - a)(pi/2) cosh t / (2 cosh^2 u).
//! * The single-exponential tanh rule ([`tanh_rule`]): v = a + (b - a)/(1 + e^(-s)), s = k h.
//!
//! Both offsets are handed to the integrand so that endpoint singularities
//! (p - v)^(-1/2 + Omega), v^(-1 - lambda) are evaluated without cancellation. A rule is built
//! once on (0, 1) ([`UnitNode`]) and placed on an interval by two multiplications per node, so
//! that the transcendentals of a multi-precision rule are paid once.
//!
//! Precision rules. A tail |v - a|^(e - 1) of an integrand, truncated at the offset delta, is
//! lost as delta^e; the truncations ([`t_max`], [`t_max_for`] for tanh-sinh, the reach of
//! [`se_de_unit`]) are therefore chosen from the working precision and the weakest endpoint
//! exponent, so that delta^e < 2^-bits.
//!
//! Why these rules are not those of [`complexfn::quadrature`] (which serve the wedge crate):
//! that module's tanh-sinh rule lives on [-1, 1] at the steps 2^-k only, its levels cached per
//! precision and truncated by the precision alone, and its driver extrapolates the error from
//! three levels and maps endpoint singularities. The collocation solve needs a rule at any
//! step h (an option), its nodes indexed by t = k h in the working precision (the collocation
//! points are the quarter points of the same t-grid, and one sampling of the basis serves all
//! rows), truncated by the case's endpoint exponents ([`t_max_for`]), and the
//! single-exponential and mixed maps of the contour integrals ([`tanh_unit`],
//! [`se_de_unit`]); [`integrate_vec`] sums a vector of integrands and stops on the plain
//! difference of two levels. Replacing either by the other would change the rounding of the
//! nodes, the truncation or the stopping level, and so the solutions' reported digits; the
//! module documentation of [`complexfn::quadrature`] gives the same comparison from its side.

use complexfn::Real;

/// Truncation of the tanh-sinh variable used at 53 bits (offsets down to ~1e-101 of the
/// interval: the truncated tail of an endpoint power v^(-a) is ~1e-101^(1 - a), below 1e-15
/// for every a < 0.85). [`t_max`] gives the value for other precisions.
pub const T_MAX: f64 = 5.0;

/// Truncation of the tanh-sinh variable for `bits` of working precision: the smallest offset
/// 2 e^(-pi sinh t) must reach 2^(-3 bits), so that an endpoint power |v - a|^(-a) with
/// a <= 2/3 loses less than 2^(-bits); never below [`T_MAX`].
pub fn t_max(bits: u32) -> f64 {
    let tail = 3.0 * f64::from(bits) * std::f64::consts::LN_2 + 2.0;
    (tail / std::f64::consts::PI).asinh().max(T_MAX)
}

/// Truncation of the tanh-sinh variable for `bits` of precision and integrands whose weakest
/// endpoint behaviour is offset^(e - 1) (0 < e <= 1): the lost tail delta^e must stay below
/// 2^-bits, so the smallest offset 2 e^(-pi sinh t) reaches 2^(-bits/e - 6); never below
/// [`T_MAX`].
pub fn t_max_for(bits: u32, e: f64) -> f64 {
    let reach = (f64::from(bits) / e.clamp(0.05, 1.0) + 6.0) * std::f64::consts::LN_2;
    (reach / std::f64::consts::PI).asinh().max(T_MAX)
}

/// The mixed rule of (0, 1) behind the F-functions of the contour integrals: single-exponential
/// at 0 and double-exponential at 1,
///
/// ```text
///   v = 1/(1 + e^(-psi(s))),  psi(s) = s + e^s,  s = k h,
/// ```
///
/// so that v ~ e^s as s -> -inf (near 0 the rule is the tanh rule of [`tanh_unit`], whose
/// accuracy for h(v)/(v - z) is uniform in the distance of z from 0: error ~ exp(-pi^2/h)),
/// and 1 - v ~ exp(-e^s) as s -> +inf (the endpoint singularity at 1 costs only ln(reach)/h
/// nodes instead of reach/h). The rule reaches offsets e^(-s_se) at 0 (`s_se`: the integrand
/// is bounded there, so the lost tail is the offset itself) and 2^(-bits/e - 6) at 1, where
/// the integrand behaves like offset^(e - 1). `from_a` is the offset from the
/// single-exponential end.
pub fn se_de_unit<T: Real>(like: &T, h: f64, s_se: f64, bits: u32, e: f64) -> Vec<UnitNode<T>> {
    se_de_unit_indexed(like, h, s_se, bits, e)
        .into_iter()
        .map(|(_, u)| u)
        .collect()
}

/// [`se_de_unit`] with the index k of each node (s = k h): the nodes of even k are the rule of
/// step 2h, the coarser level of the level-doubling error probe.
pub fn se_de_unit_indexed<T: Real>(
    like: &T,
    h: f64,
    s_se: f64,
    bits: u32,
    e: f64,
) -> Vec<(i64, UnitNode<T>)> {
    let reach = (f64::from(bits) / e.clamp(0.05, 1.0) + 6.0) * std::f64::consts::LN_2;
    let s_hi = reach.ln();
    let k_lo = (-s_se / h).floor() as i64;
    let k_hi = (s_hi / h).ceil() as i64;
    let one = like.one();
    let mut out = Vec::with_capacity((k_hi - k_lo + 1) as usize);
    for k in k_lo..=k_hi {
        let s = like.lit(h) * (k as f64);
        let es = s.clone().exp();
        let psi = s + &es;
        let dpsi = es + 1.0;
        let e = (-psi.clone().abs()).exp();
        let opl = one.clone() + &e;
        let small = e.clone() / &opl;
        let large = one.clone() / &opl;
        let (da, db) = if psi >= 0.0 {
            (large, small)
        } else {
            (small, large)
        };
        let w = e * dpsi * h / opl.sqr();
        if da > 0.0 && db > 0.0 && w > 0.0 {
            out.push((
                k,
                UnitNode {
                    from_a: da,
                    to_b: db,
                    w,
                },
            ));
        }
    }
    out
}

/// One node of a rule on (a, b).
#[derive(Clone, Debug)]
pub struct Node<T> {
    /// The abscissa.
    pub v: T,
    /// v - a, exact.
    pub from_a: T,
    /// b - v, exact.
    pub to_b: T,
    /// The weight.
    pub w: T,
}

/// A node of a rule on (0, 1): the two offsets and the weight (all relative to the interval
/// length).
#[derive(Clone, Debug)]
pub struct UnitNode<T> {
    /// v - 0.
    pub from_a: T,
    /// 1 - v.
    pub to_b: T,
    /// The weight on (0, 1).
    pub w: T,
}

impl<T: Real> UnitNode<T> {
    /// The node placed on (a, a + len).
    #[inline]
    pub fn on(&self, a: &T, len: &T) -> Node<T> {
        let da = self.from_a.clone() * len;
        let db = self.to_b.clone() * len;
        let v = if da < db {
            a.clone() + &da
        } else {
            a.clone() + len - &db
        };
        Node {
            v,
            from_a: da,
            to_b: db,
            w: self.w.clone() * len,
        }
    }
}

/// The tanh-sinh node of (0, 1) at t = k h (None when an offset or the weight underflows).
/// t is formed in the working precision, so that the nodes are exactly equally spaced in t.
pub(crate) fn tanh_sinh_unit_node<T: Real>(like: &T, k: i64, h: f64) -> Option<UnitNode<T>> {
    let tt = like.lit(h) * (k as f64);
    let half_pi = like.pi() / 2.0;
    let u = half_pi.clone() * tt.clone().sinh();
    let e = (-(u.clone().abs() * 2.0)).exp();
    let one = like.one();
    let opl = one.clone() + &e;
    // 1/(1 + e^{2u}) and 1/(1 + e^{-2u}) without overflow
    let small = e.clone() / &opl;
    let large = one / &opl;
    let (da, db) = if u >= 0.0 {
        (large, small)
    } else {
        (small, large)
    };
    // sech^2 u = 4 e^{-2|u|}/(1 + e^{-2|u|})^2
    let sech2 = e * 4.0 / opl.sqr();
    let w = half_pi * tt.cosh() * sech2 / 2.0;
    if da > 0.0 && db > 0.0 && w > 0.0 {
        Some(UnitNode {
            from_a: da,
            to_b: db,
            w,
        })
    } else {
        None
    }
}

/// The tanh-sinh rule on (0, 1) with step `h`, |t| <= `t_max`, weights including h, at the
/// precision of `like`.
pub fn tanh_sinh_unit<T: Real>(like: &T, h: f64, t_max: f64) -> Vec<UnitNode<T>> {
    let kmax = (t_max / h).ceil() as i64;
    let mut out = Vec::with_capacity((2 * kmax + 1) as usize);
    for k in -kmax..=kmax {
        if let Some(mut n) = tanh_sinh_unit_node(like, k, h) {
            n.w *= h;
            out.push(n);
        }
    }
    out
}

/// The nodes of the tanh-sinh rule with step `h` on (a, b), |t| <= `t_max` (only those with
/// both offsets positive and a positive weight).
pub fn nodes<T: Real>(a: &T, b: &T, h: f64, t_max: f64) -> Vec<Node<T>> {
    let len = b.clone() - a;
    tanh_sinh_unit(a, h, t_max)
        .iter()
        .map(|n| n.on(a, &len))
        .collect()
}

/// Integral of a vector-valued integrand over (a, b) by nested tanh-sinh levels: the step is
/// halved from 1/2 (reusing every earlier node) until two successive levels agree to
/// `rel_tol` (in the max norm over components, relative to the largest component) or the step
/// reaches `h_min`. Nodes are kept for |t| <= `t_max`. Returns the values and the last
/// difference (an over-estimate of the error once the rule has converged).
pub fn integrate_vec<T, F>(
    a: &T,
    b: &T,
    dim: usize,
    rel_tol: f64,
    h_min: f64,
    t_max: f64,
    f: F,
) -> (Vec<T>, f64)
where
    T: Real,
    F: FnMut(&Node<T>, &mut [T]),
{
    integrate_vec_checked(a, b, dim, dim, rel_tol, h_min, t_max, f)
}

/// [`integrate_vec`] whose stopping test looks at the first `checked` components only: the
/// others are carried on the same levels (for a probe whose own convergence does not matter,
/// only its difference from the checked components).
#[allow(clippy::too_many_arguments)]
pub fn integrate_vec_checked<T, F>(
    a: &T,
    b: &T,
    dim: usize,
    checked: usize,
    rel_tol: f64,
    h_min: f64,
    t_max: f64,
    mut f: F,
) -> (Vec<T>, f64)
where
    T: Real,
    F: FnMut(&Node<T>, &mut [T]),
{
    integrate_vec_dyn(a, b, dim, checked, rel_tol, h_min, t_max, &mut f)
}

/// [`integrate_vec_checked`] behind its generic shim: the rule compiled once per precision,
/// the integrand reached by one dynamic call per node.
#[allow(clippy::too_many_arguments)]
fn integrate_vec_dyn<T: Real>(
    a: &T,
    b: &T,
    dim: usize,
    checked: usize,
    rel_tol: f64,
    h_min: f64,
    t_max: f64,
    f: &mut dyn FnMut(&Node<T>, &mut [T]),
) -> (Vec<T>, f64) {
    let len = b.clone() - a;
    let zero = a.zero();
    let mut buf = vec![zero.clone(); dim];
    // sum over the nodes of the current level set, without the factor h
    let mut sum = vec![zero.clone(); dim];
    let mut add_nodes = |ks: &mut dyn Iterator<Item = i64>, h: f64, sum: &mut [T]| {
        for k in ks {
            let Some(un) = tanh_sinh_unit_node(a, k, h) else {
                continue;
            };
            let nd = un.on(a, &len);
            buf.iter_mut().for_each(|x| *x = zero.clone());
            f(&nd, &mut buf);
            for (s, x) in sum.iter_mut().zip(&buf) {
                *s += x.clone() * &nd.w;
            }
        }
    };
    let mut h = 0.5;
    let kmax = (t_max / h).ceil() as i64;
    add_nodes(&mut (-kmax..=kmax), h, &mut sum);
    let mut prev: Vec<T> = sum.iter().map(|s| s.clone() * h).collect();
    loop {
        let hn = h / 2.0;
        let kmax = (t_max / hn).ceil() as i64;
        // odd multiples of the new step
        add_nodes(&mut (-kmax..=kmax).filter(|k| k % 2 != 0), hn, &mut sum);
        let cur: Vec<T> = sum.iter().map(|s| s.clone() * hn).collect();
        let scale = cur[..checked.min(dim)]
            .iter()
            .fold(0.0_f64, |m, x| m.max(x.to_f64().abs()))
            .max(1e-300);
        let diff = cur[..checked.min(dim)]
            .iter()
            .zip(&prev)
            .fold(0.0_f64, |m, (x, y)| m.max((x.clone() - y).to_f64().abs()));
        h = hn;
        if diff <= rel_tol * scale || h <= h_min {
            return (cur, diff);
        }
        prev = cur;
    }
}

/// The single-exponential tanh rule on (0, 1): v = 1/(1 + e^(-s)), s = k h, |s| <= `s_max`,
/// weight h e^(-|s|)/(1 + e^(-|s|))^2, at the precision of `like`.
///
/// Unlike tanh-sinh, this map keeps the image of a pole at distance y from an endpoint at an
/// angle pi/2 from the real s-axis whatever y is, so one fixed node set integrates
/// h(v)/(v - z) accurately for every z = (endpoint) + i y (error ~ exp(-pi^2/h)); the contour
/// representation needs exactly that.
pub fn tanh_unit<T: Real>(like: &T, h: f64, s_max: f64) -> Vec<UnitNode<T>> {
    let kmax = (s_max / h).floor() as i64;
    let mut out = Vec::with_capacity((2 * kmax + 1) as usize);
    let one = like.one();
    for k in -kmax..=kmax {
        let s = k as f64 * h;
        // |s| in the working precision: the nodes must be exactly equally spaced
        let e = (like.lit(-h) * (k.unsigned_abs() as f64)).exp();
        let opl = one.clone() + &e;
        let small = e.clone() / &opl;
        let large = one.clone() / &opl;
        let (da, db) = if s >= 0.0 {
            (large, small)
        } else {
            (small, large)
        };
        let w = e * h / opl.sqr();
        if da > 0.0 && db > 0.0 && w > 0.0 {
            out.push(UnitNode {
                from_a: da,
                to_b: db,
                w,
            });
        }
    }
    out
}

/// The nodes of the single-exponential tanh rule on (a, b) (see [`tanh_unit`]).
pub fn tanh_rule<T: Real>(a: &T, b: &T, h: f64, s_max: f64) -> Vec<Node<T>> {
    let len = b.clone() - a;
    tanh_unit(a, h, s_max)
        .iter()
        .map(|n| n.on(a, &len))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn endpoint_singularities_are_integrated_to_full_accuracy() {
        // Int_0^1 v^(-0.7) (1 - v)^(-0.4) dv = B(0.3, 0.6)
        let (val, _) = integrate_vec(&0.0, &1.0, 1, 1e-15, 1.0 / 256.0, T_MAX, |n, out| {
            out[0] = n.from_a.powf(-0.7) * n.to_b.powf(-0.4);
        });
        // B(0.3, 0.6) = Gamma(0.3) Gamma(0.6)/Gamma(0.9)
        let exact = 2.991_568_987_687_591 * 1.489_192_248_812_817 / 1.068_628_702_119_319_4;
        assert!(
            (val[0] - exact).abs() < 1e-13 * exact,
            "{} {}",
            val[0],
            exact
        );
    }

    #[test]
    fn endpoint_singularities_at_128_bits() {
        use rug::Float;
        // Int_0^1 v^(-1/2) (1 - v)^(-1/2) dv = pi
        let a = Float::with_val(128, 0);
        let b = Float::with_val(128, 1);
        let (val, _) = integrate_vec(&a, &b, 1, 1e-36, 1.0 / 512.0, t_max(128), |n, out| {
            out[0] = (n.from_a.clone() * &n.to_b).sqrt().recip();
        });
        let err = (val[0].clone() - a.pi()).abs().to_f64();
        assert!(err < 1e-35, "{err:e}");
        // the fixed tanh rule: Int_0^1 v^(-1/2) dv = 2
        let s_max = 2.0 * 128.0 * std::f64::consts::LN_2 + 10.0;
        let r = tanh_rule(&a, &b, 0.1, s_max);
        let mut s = a.zero();
        for n in &r {
            s += n.from_a.clone().sqrt().recip() * &n.w;
        }
        let err = Real::to_f64(&Real::abs(s - 2.0));
        assert!(err < 1e-35, "{err:e}");
    }
}
