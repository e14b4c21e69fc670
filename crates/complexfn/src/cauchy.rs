//! Cauchy integrals over a segment, their Sokhotski-Plemelj boundary values, and principal
//! values with the pole part subtracted analytically.
//!
//! For a density phi on [a, b],
//!
//! ```text
//!   Phi(zeta) = (1/(2 pi i)) Int_a^b phi(v)/(v - zeta) dv,
//!   Phi^{+-}(xi) = +- phi(xi)/2 + (1/(2 pi i)) PV Int_a^b phi(v)/(v - xi) dv,   a < xi < b.
//! ```
//!
//! Both are computed with the singular part taken out in closed form:
//!
//! ```text
//!   Int_a^b phi(v)/(v - c) dv = Int_a^b (phi(v) - phi(x0))/(v - c) dv + phi(x0) ln((b - c)/(a - c)),
//! ```
//!
//! with x0 = Re c for an off-contour c (so the remaining integrand stays bounded however
//! close c is to the contour) and x0 = c on the contour, where the logarithm becomes
//! ln((b - c)/(c - a)) for the principal value. No interval is cut out around the pole.

use crate::cx::Cx;
use crate::error::Result;
use crate::plemelj::Side;
use crate::quadrature::{tanh_sinh, CachedRules, Point, QuadValue, Quadrature, TsOptions};
use crate::scalar::Real;

/// A split point of [a, b] about a third of the way from c to the farther end.
fn split_point<T: Real>(a: &T, b: &T, c: &T) -> T {
    let to_a = c.clone() - a;
    let to_b = b.clone() - c;
    if to_b > to_a {
        c.clone() + to_b * 0.381_966_011_250_105
    } else {
        c.clone() - to_a * 0.381_966_011_250_105
    }
}

/// Int_a^b g as Int_a^s + Int_s^b, each half's points carrying their distances to a and b.
fn split_at<T, V, G>(
    a: &T,
    b: &T,
    s: &T,
    left_opts: TsOptions,
    right_opts: TsOptions,
    mut g: G,
) -> Result<Quadrature<V>>
where
    T: CachedRules,
    V: QuadValue<T>,
    G: FnMut(&Point<T>) -> V,
{
    let left = tanh_sinh(a, s, left_opts, |p: &Point<T>| {
        g(&Point {
            v: p.v.clone(),
            from_a: p.from_a.clone(),
            to_b: b.clone() - &p.v,
        })
    })?;
    let right = tanh_sinh(s, b, right_opts, |p: &Point<T>| {
        g(&Point {
            v: p.v.clone(),
            from_a: p.v.clone() - a,
            to_b: p.to_b.clone(),
        })
    })?;
    Ok(combine(left, right))
}

/// Sum of two estimates over adjacent intervals.
fn combine<T: Real, V: QuadValue<T>>(l: Quadrature<V>, r: Quadrature<V>) -> Quadrature<V> {
    let mut value = l.estimate.value;
    value.add_scaled(&r.value, &value.magnitude().one());
    Quadrature::new(value, l.estimate.error + r.error, l.evals + r.evals)
}

fn point_at<T: Real>(a: &T, b: &T, v: &T) -> Point<T> {
    Point {
        v: v.clone(),
        from_a: v.clone() - a,
        to_b: b.clone() - v,
    }
}

/// Principal value PV Int_a^b phi(v)/(v - c) dv for a < c < b (phi real or complex and
/// Hölder-continuous at c; integrable algebraic singularities at a, b are allowed).
///
/// The subtracted integrand (phi(v) - phi(c))/(v - c) is bounded at c; should a node fall
/// within sqrt(eps)(b - a) of c, its value there is replaced by a central difference.
pub fn principal_value<T, V, F>(
    a: &T,
    b: &T,
    c: &T,
    opts: TsOptions,
    mut phi: F,
) -> Result<Quadrature<V>>
where
    T: CachedRules,
    V: QuadValue<T>,
    F: FnMut(&Point<T>) -> V,
{
    let len = b.clone() - a;
    let to_a = c.clone() - a;
    let to_b = b.clone() - c;
    if to_a.clone().min(to_b.clone()) < len.clone() / 8.0 {
        return near_end_principal_value(a, b, c, opts, phi);
    }
    let phi_c = phi(&point_at(a, b, c));
    let near = a.epsilon().sqrt() * &len;
    let delta = a.epsilon().powf(&a.lit(1.0 / 3.0)) * &len;
    // The subtracted integrand is smooth at c. Split [a, b] at a point well away from c so
    // that no node of either half sits on c (c at the midpoint of [a, b] would be a node).
    let s = split_point(a, b, c);
    let mut g = |p: &Point<T>| -> V {
        let d = p.v.clone() - c;
        if d.clone().abs() < near {
            let up = phi(&point_at(a, b, &(c.clone() + &delta)));
            let dn = phi(&point_at(a, b, &(c.clone() - &delta)));
            up.minus(&dn).scaled(&(delta.clone() * 2.0).recip())
        } else {
            phi(p).minus(&phi_c).scaled(&d.recip())
        }
    };
    let left_opts = TsOptions {
        right_exponent: None,
        ..opts
    };
    let right_opts = TsOptions {
        left_exponent: None,
        ..opts
    };
    let mut est = split_at(a, b, &s, left_opts, right_opts, &mut g)?;
    let log = ((b.clone() - c) / (c.clone() - a)).ln();
    let cancel = (est.value.magnitude() + phi_c.magnitude() * log.clone().abs()).to_f64()
        * a.epsilon().to_f64()
        * 16.0;
    est.value.add_scaled(&phi_c, &log);
    est.error += cancel;
    Ok(est)
}

/// Principal value with the pole c close to an end of [a, b] (within (b - a)/8), where phi may
/// be singular: with d the distance from c to the nearer end, the part symmetric about c is
/// Int_0^d [phi(c + u) - phi(c - u)]/u du (no pole left; distances to a and b passed exactly),
/// and the rest, Int phi(v)/(v - c) dv over the far side, has v - c >= d passed exactly too, so
/// the near-singular factor 1/(v - c) is resolved however small d is.
fn near_end_principal_value<T, V, F>(
    a: &T,
    b: &T,
    c: &T,
    opts: TsOptions,
    mut phi: F,
) -> Result<Quadrature<V>>
where
    T: CachedRules,
    V: QuadValue<T>,
    F: FnMut(&Point<T>) -> V,
{
    let to_a = c.clone() - a;
    let to_b = b.clone() - c;
    let near_a = to_a < to_b;
    let d = if near_a { to_a.clone() } else { to_b.clone() };
    let tiny = a.epsilon() * &d;
    let near_exp = if near_a {
        opts.left_exponent
    } else {
        opts.right_exponent
    };
    // symmetric part: singular at u = d (the near end) only
    let sym_opts = TsOptions {
        left_exponent: None,
        right_exponent: near_exp,
        ..opts
    };
    let sym = tanh_sinh(&d.zero(), &d, sym_opts, |p: &Point<T>| {
        let u = &p.v;
        if *u < tiny {
            return V::zero_like(u);
        }
        // c + u and c - u with their distances to a and b
        let plus = Point {
            v: c.clone() + u,
            from_a: to_a.clone() + u,
            to_b: if near_a {
                to_b.clone() - u
            } else {
                p.to_b.clone()
            },
        };
        let minus = Point {
            v: c.clone() - u,
            from_a: if near_a {
                p.to_b.clone()
            } else {
                to_a.clone() - u
            },
            to_b: to_b.clone() + u,
        };
        phi(&plus).minus(&phi(&minus)).scaled(&u.clone().recip())
    })?;
    // far side: (c + d, b] when c is near a, [a, c - d) when c is near b
    let rest = if near_a {
        let lo = c.clone() + &d;
        let o = TsOptions {
            left_exponent: None,
            ..opts
        };
        tanh_sinh(&lo, b, o, |p: &Point<T>| {
            let vc = p.from_a.clone() + &d;
            let q = Point {
                v: p.v.clone(),
                from_a: vc.clone() + &d,
                to_b: p.to_b.clone(),
            };
            phi(&q).scaled(&vc.recip())
        })?
    } else {
        let hi = c.clone() - &d;
        let o = TsOptions {
            right_exponent: None,
            ..opts
        };
        tanh_sinh(a, &hi, o, |p: &Point<T>| {
            let cv = p.to_b.clone() + &d;
            let q = Point {
                v: p.v.clone(),
                from_a: p.from_a.clone(),
                to_b: cv.clone() + &d,
            };
            phi(&q).scaled(&(-cv).recip())
        })?
    };
    // The two parts can be much larger than their sum (by (L/d)^(1/2) for an inverse square
    // root at the near end): charge their round-off to the error estimate.
    let cancel =
        (sym.value.magnitude() + rest.value.magnitude()).to_f64() * a.epsilon().to_f64() * 16.0;
    let mut est = combine(sym, rest);
    est.error += cancel;
    Ok(est)
}

/// The Cauchy integral Phi(zeta) = (1/(2 pi i)) Int_a^b phi(v)/(v - zeta) dv for zeta off
/// the segment (it may be arbitrarily close to it).
pub fn cauchy_integral<T, F>(
    a: &T,
    b: &T,
    zeta: &Cx<T>,
    opts: TsOptions,
    mut phi: F,
) -> Result<Quadrature<Cx<T>>>
where
    T: CachedRules,
    F: FnMut(&Point<T>) -> Cx<T>,
{
    let x0 = zeta.re.clone();
    let inside = x0 > *a && x0 < *b;
    let phi0 = if inside {
        phi(&point_at(a, b, &x0))
    } else {
        Cx::real(a.zero())
    };
    let mut g = |p: &Point<T>| -> Cx<T> {
        let num = if inside { phi(p) - &phi0 } else { phi(p) };
        let den = Cx::new(p.v.clone() - &zeta.re, -zeta.im.clone());
        num / &den
    };
    // For Re zeta inside the segment, split there: the integrand varies on the scale
    // |Im zeta| around Re zeta, where the nodes of both halves then cluster.
    let mut est = if inside {
        split_at(a, b, &x0, opts, opts, &mut g)?
    } else {
        tanh_sinh(a, b, opts, &mut g)?
    };
    if inside {
        let bz = Cx::real(b.clone()) - zeta;
        let az = Cx::real(a.clone()) - zeta;
        // ln(b - zeta) - ln(a - zeta): for Im zeta != 0 the difference of principal logs is
        // the continuous branch along the segment.
        let log = bz.ln() - az.ln();
        est.value += phi0 * &log;
    }
    let two_pi = a.pi() * 2.0;
    // divide by 2 pi i: (x + iy)/(i 2pi) = (y - ix)/(2pi)
    est.estimate.value = est.estimate.value.mul_neg_i().scale(&two_pi.recip());
    est.error /= 2.0 * std::f64::consts::PI;
    Ok(est)
}

/// Sokhotski-Plemelj boundary value Phi^{+-}(xi) = +-phi(xi)/2 + (1/(2 pi i)) PV Int phi/(v - xi)
/// of the Cauchy integral, for a < xi < b.
pub fn cauchy_boundary<T, F>(
    a: &T,
    b: &T,
    xi: &T,
    side: Side,
    opts: TsOptions,
    mut phi: F,
) -> Result<Quadrature<Cx<T>>>
where
    T: CachedRules,
    F: FnMut(&Point<T>) -> Cx<T>,
{
    let phi_xi = phi(&point_at(a, b, xi));
    let mut est = principal_value(a, b, xi, opts, &mut phi)?;
    let two_pi = a.pi() * 2.0;
    let pv = est.value.clone().mul_neg_i().scale(&two_pi.recip());
    let half = phi_xi.scale(&a.lit(0.5 * side.sign()));
    est.value = pv + half;
    est.error /= 2.0 * std::f64::consts::PI;
    Ok(est)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::rel_diff;
    use rug::Float;

    #[test]
    fn plain_principal_value_is_a_logarithm_f64() {
        let (a, b) = (0.2_f64, 1.3_f64);
        for c in [0.25, 0.75, 1.29] {
            let e: Quadrature<f64> =
                principal_value(&a, &b, &c, TsOptions::new(1e-15), |_p: &Point<f64>| 1.0).unwrap();
            let exact = ((b - c) / (c - a)).ln();
            assert!((e.value - exact).abs() < 1e-14, "{c}: {} {exact}", e.value);
        }
    }

    #[test]
    fn weighted_principal_value_with_endpoint_singularity() {
        // PV int_0^1 v^(-1/2)/(v - c) dv = ln((1 - sqrt c)/(1 + sqrt c))/sqrt c
        for c in [0.09_f64, 0.5, 0.81] {
            let e: Quadrature<f64> =
                principal_value(&0.0, &1.0, &c, TsOptions::new(1e-15), |p: &Point<f64>| {
                    p.from_a.powf(-0.5)
                })
                .unwrap();
            let s = c.sqrt();
            let exact = ((1.0 - s) / (1.0 + s)).ln() / s;
            assert!(
                (e.value - exact).abs() < 1e-14 * exact.abs(),
                "{c}: {} {exact}",
                e.value
            );
        }
        let prec = 256;
        let a = Float::with_val(prec, 0);
        let b = Float::with_val(prec, 1);
        let c = Float::with_val(prec, 0.3);
        let e: Quadrature<Float> =
            principal_value(&a, &b, &c, TsOptions::new(1e-70), |p: &Point<Float>| {
                p.from_a.clone().sqrt().recip()
            })
            .unwrap();
        let s = c.clone().sqrt();
        let exact = ((b.clone() - &s) / (b.clone() + &s)).ln() / s;
        assert!(rel_diff(&e.value, &exact) < 1e-60);
    }

    #[test]
    fn principal_value_with_the_pole_next_to_a_singular_end() {
        // PV int_0^1 v^(-1/2)/(v - c) dv = ln((1 - sqrt c)/(1 + sqrt c))/sqrt c, c -> 0, and
        // its mirror PV int_0^1 (1 - v)^(-1/2)/(v - c) dv with c -> 1. The two parts of the
        // near-end splitting are each O(c^(-1/2)) and cancel to O(1): the stated accuracy is
        // eps c^(-1/2) (times a small factor).
        for c in [1e-3_f64, 1e-8, 1e-12] {
            let s = c.sqrt();
            let exact = ((1.0 - s) / (1.0 + s)).ln() / s;
            let tol = 1e-14 / s;
            let e: Quadrature<f64> =
                principal_value(&0.0, &1.0, &c, TsOptions::new(1e-15), |p: &Point<f64>| {
                    p.from_a.powf(-0.5)
                })
                .unwrap();
            assert!(
                (e.value - exact).abs() < tol * exact.abs(),
                "{c}: {} {exact}",
                e.value
            );
            let e: Quadrature<f64> = principal_value(
                &0.0,
                &1.0,
                &(1.0 - c),
                TsOptions::new(1e-15),
                |p: &Point<f64>| p.to_b.powf(-0.5),
            )
            .unwrap();
            assert!(
                (e.value + exact).abs() < tol * exact.abs(),
                "1 - {c}: {} {}",
                e.value,
                -exact
            );
        }
    }

    #[test]
    fn plemelj_jump_and_limits_of_the_cauchy_integral() {
        // phi(v) = exp(v) (1 - v)^(1/2) on [0, 1]: the boundary values from the principal value
        // agree with the off-contour integral at xi +- i eps, and their difference is phi.
        let phi = |p: &Point<f64>| Cx::real(p.v.exp() * p.to_b.sqrt());
        let (a, b) = (0.0_f64, 1.0_f64);
        for xi in [0.2, 0.5, 0.9] {
            let up = cauchy_boundary(&a, &b, &xi, Side::Upper, TsOptions::new(1e-15), phi)
                .unwrap()
                .estimate
                .value;
            let dn = cauchy_boundary(&a, &b, &xi, Side::Lower, TsOptions::new(1e-15), phi)
                .unwrap()
                .estimate
                .value;
            let eps = 1e-9;
            let off_up = cauchy_integral(&a, &b, &Cx::new(xi, eps), TsOptions::new(1e-15), phi)
                .unwrap()
                .estimate
                .value;
            let off_dn = cauchy_integral(&a, &b, &Cx::new(xi, -eps), TsOptions::new(1e-15), phi)
                .unwrap()
                .estimate
                .value;
            let jump = off_up.clone() - &off_dn;
            let phi_xi = xi.exp() * (1.0 - xi).sqrt();
            assert!(
                (jump.re - phi_xi).abs() < 1e-8 && jump.im.abs() < 1e-8,
                "{jump}"
            );
            assert!((up.clone() - &off_up).abs() < 1e-8, "{up} {off_up}");
            assert!((dn.clone() - &off_dn).abs() < 1e-8, "{dn} {off_dn}");
            assert!(((up - &dn).re - phi_xi).abs() < 1e-15);
        }
    }

    #[test]
    fn f64_and_256_bit_principal_values_agree() {
        let c64 = 0.37_f64;
        let e64: Quadrature<f64> =
            principal_value(&0.0, &1.0, &c64, TsOptions::new(1e-15), |p: &Point<f64>| {
                p.v.cos() * p.from_a.powf(0.25)
            })
            .unwrap();
        let a = Float::with_val(256, 0);
        let b = Float::with_val(256, 1);
        let c = Float::with_val(256, 0.37);
        let quarter = Float::with_val(256, 0.25);
        let e: Quadrature<Float> =
            principal_value(&a, &b, &c, TsOptions::new(1e-70), |p: &Point<Float>| {
                p.v.clone().cos() * p.from_a.clone().powf(&quarter)
            })
            .unwrap();
        assert!((e64.value - e.value.to_f64()).abs() < 2e-15 * e64.value.abs());
    }
}
