//! The complex-function layer against independent values: an mpmath reference for the Rayleigh
//! root, limits from off the axis for every boundary value, closed-form principal values, and
//! agreement of the f64 and 256-bit paths.

use complexfn::cauchy::{cauchy_boundary, principal_value};
use complexfn::quadrature::{Point, Quadrature, TsOptions};
use complexfn::scalar::rel_diff;
use complexfn::{p_boundary, p_k, Cx, Precision, Rayleigh, Real, Side};
use rug::Float;

const C1: f64 = 1870.83;
const C2: f64 = 1000.0;

/// (name, m, m_R) at 80 digits from tests/reference/rayleigh_mpmath.py.
fn reference() -> Vec<(String, String, String)> {
    include_str!("../reference/rayleigh.txt")
        .lines()
        .map(|l| {
            let mut it = l.split_whitespace();
            (
                it.next().unwrap().to_string(),
                it.next().unwrap().to_string(),
                it.next().unwrap().to_string(),
            )
        })
        .collect()
}

#[test]
fn rayleigh_root_against_mpmath_f64_and_256_bits() {
    for (name, m, mr) in reference() {
        // f64: m as the nearest double of the reference m
        let m64: f64 = m.parse().unwrap();
        let r64 = Rayleigh::new(m64).unwrap();
        let mr64: f64 = mr.parse().unwrap();
        assert!(
            (r64.m_r() - mr64).abs() <= 1e-15 * mr64,
            "{name}: f64 {} vs {mr64}",
            r64.m_r()
        );
        let mb = Float::parse_prec(&m, 256).unwrap();
        let r = Rayleigh::new(mb).unwrap();
        let exact = Float::parse_prec(&mr, 256).unwrap();
        let d = rel_diff(r.m_r(), &exact);
        assert!(d <= 1e-70, "{name}: 256-bit rel err {d:e}");
    }
}

#[test]
fn rayleigh_speed_of_the_papers_material_is_927_41() {
    let r = Rayleigh::new(C2 / C1).unwrap();
    let c_r = r.m_r() * C1;
    assert!((c_r - 927.41).abs() < 0.005, "c_R = {c_r}");
    // R vanishes there and changes sign
    let lo = r.at_boundary(&(r.m_r() * (1.0 - 1e-9)), Side::Lower).r.re;
    let hi = r.at_boundary(&(r.m_r() * (1.0 + 1e-9)), Side::Lower).r.re;
    assert!(lo > 0.0 && hi < 0.0);
    assert!(r.r_prime_at_root() < 0.0);
}

#[test]
fn boundary_values_of_p_l_r_are_limits_from_off_the_axis() {
    let m = C2 / C1;
    let ray = Rayleigh::new(m).unwrap();
    // points in (0, m), (m, 1) and (1, 2), avoiding the zero of R
    for &xi in &[0.05, 0.3, 0.52, 0.7, 0.95, 1.2, 1.9] {
        for side in [Side::Upper, Side::Lower] {
            let on = ray.at_boundary(&xi, side);
            let mut prev = f64::INFINITY;
            for &eps in &[1e-4, 1e-6, 1e-8] {
                let off = ray.at(&Cx::new(xi, eps * side.sign()));
                let d = [
                    (off.p1.clone() - &on.p1).abs() / on.p1.abs(),
                    (off.p2.clone() - &on.p2).abs() / on.p2.abs(),
                    (off.l.clone() - &on.l).abs() / on.l.abs(),
                    (off.r.clone() - &on.r).abs() / on.r.abs(),
                ]
                .into_iter()
                .fold(0.0, f64::max);
                // converges linearly (or faster) in eps
                assert!(d < 200.0 * eps, "xi {xi} {side:?} eps {eps}: {d:e}");
                assert!(d <= prev);
                prev = d;
            }
        }
    }
    // the closed form p_k and its boundary values agree away from the cut too
    let z = p_k(&Cx::new(1.5, 1e-12), &1.0);
    assert!((z - p_boundary(&1.5, &1.0, Side::Lower)).abs() < 1e-11);
}

#[test]
fn principal_values_in_closed_form_f64_and_256_bits() {
    // PV int_a^b dv/(v - c) = ln((b - c)/(c - a))
    let (a, b) = (0.1_f64, 2.0_f64);
    for c in [0.11, 0.7, 1.05, 1.99] {
        let e: Quadrature<f64> =
            principal_value(&a, &b, &c, TsOptions::new(1e-15), |_: &Point<f64>| 1.0).unwrap();
        assert!((e.value - ((b - c) / (c - a)).ln()).abs() < 1e-14);
    }
    let (a, b, c) = (
        Float::with_val(256, 0.1),
        Float::with_val(256, 2.0),
        Float::with_val(256, 1.05),
    );
    let one = a.one();
    let e: Quadrature<Float> =
        principal_value(&a, &b, &c, TsOptions::new(1e-72), |_: &Point<Float>| {
            one.clone()
        })
        .unwrap();
    let exact = ((b.clone() - &c) / (c.clone() - &a)).ln();
    assert!(rel_diff(&e.value, &exact) < 1e-60);
    // weighted, singular at both ends: PV int_0^1 v^(-1/2)/(v - c) dv with sqrt substitution
    // known in closed form (see the unit tests for more); here at the paper's Rayleigh pole
    let ray = Rayleigh::new(C2 / C1).unwrap();
    let c = *ray.m_r();
    let e: Quadrature<f64> =
        principal_value(&0.0, &1.0, &c, TsOptions::new(1e-15), |p: &Point<f64>| {
            p.from_a.powf(-0.5)
        })
        .unwrap();
    let s = c.sqrt();
    let exact = ((1.0 - s) / (1.0 + s)).ln() / s;
    assert!((e.value - exact).abs() < 1e-14 * exact.abs());
}

#[test]
fn plemelj_jump_of_a_cauchy_integral_is_the_density() {
    let prec = 256;
    let a = Float::with_val(prec, 0);
    let b = Float::with_val(prec, 1);
    let xi = Float::with_val(prec, 0.4);
    let phi = |p: &Point<Float>| Cx::real(p.v.clone().cos() * p.from_a.clone().sqrt());
    let up = cauchy_boundary(&a, &b, &xi, Side::Upper, TsOptions::new(1e-70), phi).unwrap();
    let dn = cauchy_boundary(&a, &b, &xi, Side::Lower, TsOptions::new(1e-70), phi).unwrap();
    let jump = up.estimate.value - &dn.value;
    let exact = xi.clone().cos() * xi.clone().sqrt();
    assert!(rel_diff(&jump.re, &exact) < 1e-70);
    assert!(jump.im.to_f64().abs() < 1e-70);
}

#[test]
fn f64_and_256_bit_paths_agree_on_every_function() {
    let m64 = C2 / C1;
    let r64 = Rayleigh::new(m64).unwrap();
    let rb = Rayleigh::new(Float::with_val(256, m64)).unwrap();
    assert!(rel_diff(&rb.m_r().to_f64(), r64.m_r()) < 4.0 * f64::EPSILON);
    // relative to the size of the terms that cancel in L = 2 - K p1 p2 and R = 4 - K^2 p1 p2
    // (near the Rayleigh root R itself is small, and no formula does better than that)
    let close_to = |a: &Cx<f64>, b: &Cx<Float>, scale: f64| {
        let b = Cx::new(b.re.to_f64(), b.im.to_f64());
        (a.clone() - &b).abs() <= 8.0 * f64::EPSILON * b.abs().max(scale)
    };
    let close = |a: &Cx<f64>, b: &Cx<Float>| close_to(a, b, 1e-300);
    for &xi in &[1e-6, 0.01, 0.3, 0.5, 0.6, 1.3] {
        for side in [Side::Upper, Side::Lower] {
            let x = r64.at_boundary(&xi, side);
            let y = rb.at_boundary(&Float::with_val(256, xi), side);
            for (u, w) in [(&x.p1, &y.p1), (&x.p2, &y.p2), (&x.k, &y.k)] {
                assert!(close(u, w), "xi {xi}: {u} vs {w}");
            }
            let terms = 4.0 * x.k.abs().powi(2) * (x.p1.clone() * &x.p2).abs() / (xi * xi);
            for (u, w) in [(&x.l_over_s, &y.l_over_s), (&x.r_over_s, &y.r_over_s)] {
                assert!(close_to(u, w, terms), "xi {xi}: {u} vs {w}");
            }
        }
    }
    for &(re, im) in &[(0.2, 0.1), (-0.4, -0.3), (1.5, 0.5)] {
        let x = r64.at(&Cx::new(re, im));
        let y = rb.at(&Cx::new(Float::with_val(256, re), Float::with_val(256, im)));
        for (u, w) in [(&x.p1, &y.p1), (&x.p2, &y.p2)] {
            assert!(close(u, w), "({re},{im}): {u} vs {w}");
        }
        let terms = 4.0 * x.k.abs().powi(2) * (x.p1.clone() * &x.p2).abs();
        for (u, w) in [(&x.l, &y.l), (&x.r, &y.r)] {
            assert!(close_to(u, w, terms), "({re},{im}): {u} vs {w}");
        }
    }
}

#[test]
fn invalid_input_names_the_parameter_and_range() {
    let e = Precision::from_digits(0, 10).unwrap_err().to_string();
    assert!(e.contains("digits") && e.contains(">= 1"), "{e}");
    let e = Precision::checked_bits(0).unwrap_err().to_string();
    assert!(e.contains("precision_bits"), "{e}");
    let e = Rayleigh::new(f64::NAN).unwrap_err().to_string();
    assert!(e.contains("m = c2/c1") && e.contains("sqrt(3)/2"), "{e}");
    assert!(complexfn::quadrature::gauss_jacobi(4, -1.0, 0.0).is_err());
}
