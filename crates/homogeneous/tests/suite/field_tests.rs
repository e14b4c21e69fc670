//! Tests of the homogeneous-function field against the equations of motion, the wavefront and
//! surface conditions, the surface forms and a closed-form case (units c1 = mu = t = 1).
use crate::common;
use common::{rel, Test};
use complexfn::plemelj::Face;
use complexfn::Real;
use homogeneous::j_operator::default_options;
use homogeneous::{field, surface, Region};
use rug::Float;

const M: f64 = 0.55;
const P: f64 = 0.3;

fn f(x: f64) -> Float {
    Float::with_val(256, x)
}

/// Cartesian displacement at (x, y, t), 256 bits.
fn u_xy(pot: &Test<Float>, x: &Float, y: &Float, t: &Float) -> [Float; 2] {
    let fv = field::at_time(pot, x, y, t).unwrap();
    let c = fv.cartesian();
    [c.ux, c.uy]
}

/// Second derivative along a line, 5-point 4th-order stencil: values at -2h..2h.
fn d2(v: &[Float; 5], h: &Float) -> Float {
    let s = (v[1].clone() + &v[3]) * 16.0 - (v[0].clone() + &v[4]) - v[2].clone() * 30.0;
    s / (h.clone() * h * 12.0)
}
fn d1(v: &[Float; 5], h: &Float) -> Float {
    let s = (v[3].clone() - &v[1]) * 8.0 - (v[4].clone() - &v[0]);
    s / (h.clone() * 12.0)
}

/// Navier residual, Hooke's law, velocity, dilatation and curl checked by finite differences
/// in x, y and t at one point; returns (relative Navier residual, worst relative mismatch of
/// the other quantities).
fn check_point(pot: &Test<Float>, x0: f64, y0: f64) -> (f64, f64) {
    let (x, y, t) = (f(x0), f(y0), f(1.0));
    let h = f(1e-10);
    let m2 = f(M).sqr(); // the library's m^2 of the double M, at 256 bits
    let line = |dx: f64, dy: f64, dt: f64| -> [[Float; 5]; 2] {
        let mut out: [[Float; 5]; 2] = std::array::from_fn(|_| std::array::from_fn(|_| f(0.0)));
        for (j, k) in (-2i32..=2).enumerate() {
            let kk = f(f64::from(k)) * &h;
            let u = u_xy(
                pot,
                &(x.clone() + kk.clone() * dx),
                &(y.clone() + kk.clone() * dy),
                &(t.clone() + kk * dt),
            );
            out[0][j] = u[0].clone();
            out[1][j] = u[1].clone();
        }
        out
    };
    let lx = line(1.0, 0.0, 0.0);
    let ly = line(0.0, 1.0, 0.0);
    let ld = line(1.0, 1.0, 0.0);
    let la = line(1.0, -1.0, 0.0);
    let lt = line(0.0, 0.0, 1.0);
    let mut res = 0.0f64;
    let mut scale = 0.0f64;
    let uxy = |c: usize| -> Float { (d2(&ld[c], &h) - d2(&la[c], &h)) / 4.0 };
    // u_tt = u_xx + m^2 u_yy + (1 - m^2) v_xy (x) and the mirror for y
    for c in 0..2 {
        let o = 1 - c;
        let (a, b) = if c == 0 {
            (f(1.0), m2.clone())
        } else {
            (m2.clone(), f(1.0))
        };
        let rhs = d2(&lx[c], &h) * &a + d2(&ly[c], &h) * &b + uxy(o) * (f(1.0) - &m2);
        let lhs = d2(&lt[c], &h);
        res = res.max((lhs.clone() - &rhs).abs().to_f64());
        scale = scale.max(lhs.abs().to_f64()).max(rhs.abs().to_f64());
    }
    // other quantities from the formulas vs finite differences
    let fv = field::at_time(pot, &x, &y, &t).unwrap();
    let cv = fv.cartesian();
    let (uxx, uyy) = (d1(&lx[0], &h), d1(&ly[1], &h));
    let (uxy_, uyx) = (d1(&ly[0], &h), d1(&lx[1], &h));
    let lam = f(1.0) / &m2 - 2.0;
    let sxx = uxx.clone() * (f(1.0) / &m2) + uyy.clone() * &lam;
    let syy = uyy.clone() * (f(1.0) / &m2) + uxx.clone() * &lam;
    let sxy = uxy_.clone() + &uyx;
    let div = uxx + &uyy;
    let curl = uyx - &uxy_;
    let pairs = [
        (cv.sxx, sxx),
        (cv.syy, syy),
        (cv.sxy, sxy),
        (cv.vx, d1(&lt[0], &h)),
        (cv.vy, d1(&lt[1], &h)),
        (fv.dilatation.clone(), div),
        (fv.curl.clone(), curl),
    ];
    let size = pairs
        .iter()
        .map(|p| p.1.clone().abs().to_f64())
        .fold(0.0, f64::max);
    let worst = pairs
        .iter()
        .map(|p| (p.0.clone() - &p.1).abs().to_f64() / size)
        .fold(0.0, f64::max);
    (res / scale, worst)
}

#[test]
fn residual_of_navier_equations_in_every_wave_region_at_256_bits() {
    let pot: Test<Float> = Test::new(M, P, 1.0, 0.4, 1, 256);
    // (x, y, expected region)
    let pts = [
        (
            0.3 * (-1.0f64).cos(),
            0.3 * (-1.0f64).sin(),
            Region::BehindS,
        ),
        (
            0.8 * (-1.2f64).cos(),
            0.8 * (-1.2f64).sin(),
            Region::BetweenPAndS,
        ),
        (
            0.65 * (-0.25f64).cos(),
            0.65 * (-0.25f64).sin(),
            Region::HeadWave,
        ),
        (
            0.62 * (-2.95f64).cos(),
            0.62 * (-2.95f64).sin(),
            Region::HeadWave,
        ),
    ];
    let results: Vec<(f64, f64)> = std::thread::scope(|s| {
        let hs: Vec<_> = pts
            .iter()
            .map(|&(x, y, reg)| {
                let pot = &pot;
                s.spawn(move || {
                    let fv = field::at(pot, &f(x), &f(y)).unwrap();
                    assert_eq!(fv.region, reg);
                    check_point(pot, x, y)
                })
            })
            .collect();
        hs.into_iter().map(|h| h.join().unwrap()).collect()
    });
    for (p, (res, other)) in pts.iter().zip(&results) {
        println!("residual at {p:?}: navier {res:e}, stress/velocity/div/curl {other:e}");
        assert!(*res < 1e-20, "Navier residual {res:e} at {p:?}");
        assert!(
            *other < 1e-20,
            "Hooke/velocity/div/curl mismatch {other:e} at {p:?}"
        );
    }
}

#[test]
fn residual_degree_two_and_euler_relation_for_velocity() {
    let pot: Test<Float> = Test::new(M, P, 1.0, 0.4, 2, 256);
    let (x, y) = (0.35 * (-0.9f64).cos(), 0.35 * (-0.9f64).sin());
    let (res, other) = check_point(&pot, x, y);
    println!("degree 2: navier {res:e}, others {other:e}");
    assert!(res < 1e-20 && other < 1e-20);
    // n u = r du/dr + t du/dt  (homogeneity of degree n), f64 with a 4th-order difference
    let p64: Test<f64> = Test::new(M, P, 1.0, 0.4, 2, 53);
    let (r, th) = (0.35f64, -0.9f64);
    let o = default_options(53);
    let fv = field::at_polar(&p64, &r, &th, &1.0, o).unwrap();
    let h = 1e-3;
    let u = |rr: f64| field::at_polar(&p64, &rr, &th, &1.0, o).unwrap().u;
    let dr = (u(r - 2.0 * h) - u(r + 2.0 * h) + (u(r + h) - u(r - h)) * 8.0) / (12.0 * h);
    let lhs = fv.u.clone() * 2.0;
    let rhs = dr * r + fv.velocity.clone();
    let e = (lhs.clone() - rhs).abs() / lhs.abs();
    println!("Euler relation: {e:e}");
    assert!(e < 1e-9);
}

#[test]
fn front_conditions_p_front_and_s_front_rotation() {
    let pot: Test<f64> = Test::new(M, P, 1.0, 0.4, 1, 53);
    let o = default_options(53);
    let at = |r: f64, th: f64| field::at_polar(&pot, &r, &th, &1.0, o).unwrap();
    // P front r = c1 t: u, du/dt -> 0 (like (1 - r)^(3/2), (1 - r)^(1/2))
    for th in [-0.5, -1.5, -2.7] {
        let (a, b) = (at(1.0 - 1e-4, th), at(1.0 - 1e-6, th));
        let ref_u = at(0.5, th).u.abs();
        println!(
            "P front theta {th}: |u| {:e} -> {:e}, |v| {:e} -> {:e}",
            a.u.abs(),
            b.u.abs(),
            a.velocity.abs(),
            b.velocity.abs()
        );
        assert!(b.u.abs() < 1e-7 * ref_u && b.u.abs() < 0.01 * a.u.abs());
        assert!(b.velocity.abs() < 0.2 * a.velocity.abs());
        assert_eq!(at(1.0 + 1e-9, th).u.abs(), 0.0);
    }
    // S front (circle r = c2 t where h_2 = 1; head-wave line elsewhere, located geometrically:
    // x cos(psi) -+ ... the tangent from (+-1, 0) to the circle r = m).
    let psi = M.acos();
    for th in [-1.2f64, -2.0, -0.25, -2.95] {
        let (s, c) = th.sin_cos();
        let front = if th > -psi || th < psi - std::f64::consts::PI {
            M / (c.abs() * psi.cos() - s * psi.sin())
        } else {
            M
        };
        let behind = at(front * 0.9, th).curl.abs();
        let a = at(front - 1e-4, th).curl.abs();
        let b = at(front - 1e-6, th).curl.abs();
        let ahead = at(front + 1e-6, th).curl.abs();
        println!(
            "S front theta {th} at r = {front}: rot {behind:e}, {a:e}, {b:e}, ahead {ahead:e}"
        );
        assert!(
            b < 0.2 * a && b < 0.02 * behind,
            "rotation does not vanish at the S front"
        );
        assert_eq!(ahead, 0.0);
    }
}

#[test]
fn traction_free_outside_the_loaded_segment() {
    let pot: Test<f64> = Test::new(M, P, 1.0, 0.4, 1, 53);
    let o = default_options(53);
    let pi = std::f64::consts::PI;
    for &r in &[0.4, 0.5, 0.7, 0.95] {
        for (th0, sg) in [(0.0, -1.0), (-pi, 1.0)] {
            let s = |d: f64| {
                field::at_polar(&pot, &r, &(th0 + sg * d), &1.0, o)
                    .unwrap()
                    .s_theta
            };
            let (a, b) = (s(1e-3), s(1e-4));
            let loaded = field::at_polar(&pot, &0.15, &(th0 + sg * 1e-4), &1.0, o)
                .unwrap()
                .s_theta
                .abs();
            println!(
                "traction at r {r} face {th0}: {:e} (d=1e-3), {:e} (d=1e-4); loaded {loaded:e}",
                a.abs(),
                b.abs()
            );
            assert!(b.abs() < 1e-3 * loaded, "traction not vanishing");
            assert!(b.abs() < 0.2 * a.abs() + 1e-12);
            // the surface form (19) gives zero there too
            let face = if th0 == 0.0 { Face::Right } else { Face::Left };
            assert!(surface::stress(&pot, &r, face).unwrap().abs() < 1e-13);
        }
    }
}

#[test]
fn consistency_surface_forms_equal_the_full_field_at_the_faces() {
    let pot: Test<f64> = Test::new(M, P, 1.0, 0.4, 1, 53);
    let o = default_options(53);
    let pi = std::f64::consts::PI;
    let mut worst = 0.0f64;
    for &r in &[0.1, 0.2, 0.45, 0.7, 0.9] {
        for (th0, sg, face) in [(0.0, -1.0, Face::Right), (-pi, 1.0, Face::Left)] {
            let fld = |d: f64| field::at_polar(&pot, &r, &(th0 + sg * d), &1.0, o).unwrap();
            let (a, b) = (fld(2e-4), fld(1e-4));
            // Richardson extrapolation to d = 0 (the field is smooth in theta up to the face)
            let u0 = b.u.clone() * 2.0 - a.u.clone();
            let s0 = b.s_theta.clone() * 2.0 - a.s_theta.clone();
            let us = surface::displacement(&pot, &r, face).unwrap();
            let ss = surface::stress(&pot, &r, face).unwrap();
            let eu = (u0 - us.clone()).abs() / us.abs();
            let es = (s0 - ss.clone()).abs() / ss.abs().max(us.abs());
            println!("r {r} face {face:?}: u {us} (rel {eu:e}), s_theta {ss} (rel {es:e})");
            worst = worst.max(eu).max(es);
        }
    }
    assert!(
        worst < 1e-4,
        "surface forms (18)/(19) disagree with (10)/(11): {worst:e}"
    );
}

#[test]
fn closed_form_frictionless_uncoupled_wedge() {
    // F = -i Q zeta^2 (zeta^2 - p^2)^(-1/2), G = 0: s_theta = -(Q/p) arccosh(p/r) on 0 < r < p,
    // u_theta linear in r there.
    let q = 0.7;
    let pot: Test<f64> = Test::new(M, P, q, 0.0, 1, 53);
    let mut ut = Vec::new();
    let rs = [0.03, 0.1, 0.17, 0.24, 0.29];
    for face in [Face::Right, Face::Left] {
        ut.clear();
        for &r in &rs {
            let s = surface::stress(&pot, &r, face).unwrap();
            let exact = -(q / P) * (P / r).acosh();
            println!(
                "{face:?} r {r}: s_theta {} vs {exact} ({:e})",
                s.re,
                rel(s.re, exact)
            );
            assert!(rel(s.re, exact) < 1e-12 && s.im.abs() < 1e-13);
            ut.push(surface::displacement(&pot, &r, face).unwrap().im);
        }
        // collinearity of (r, u_theta)
        let slope = (ut[4] - ut[0]) / (rs[4] - rs[0]);
        for (r, u) in rs.iter().zip(&ut) {
            let lin = ut[0] + slope * (r - rs[0]);
            println!("u_theta({r}) = {u}, linear fit {lin}");
            assert!((u - lin).abs() < 1e-11 * ut[0].abs().max(slope.abs()));
        }
    }
    // and at 256 bits
    let big: Test<Float> = Test::new(M, P, q, 0.0, 1, 256);
    let r = f(0.1);
    let s = surface::stress(&big, &r, Face::Right).unwrap();
    let exact = -(f(q) / f(P)) * (f(P) / &r).acosh();
    let e = complexfn::scalar::rel_diff(&s.re, &exact);
    println!("256 bits: rel {e:e}");
    assert!(e < 1e-45);
    // equispaced at 256 bits: 1/20, 3/20, 5/20
    let us: Vec<Float> = [1.0, 3.0, 5.0]
        .iter()
        .map(|&k| {
            surface::displacement(&big, &(f(k) / 20.0), Face::Right)
                .unwrap()
                .im
        })
        .collect();
    let second: Float = us[0].clone() - us[1].clone() * 2.0 + &us[2];
    println!(
        "256 bits: second difference of u_theta {:e}",
        second.to_f64()
    );
    assert!(Real::abs(second).to_f64() < 1e-40 * Real::abs(us[0].clone()).to_f64());
}

#[test]
fn bad_input_is_refused_with_its_range() {
    let pot: Test<f64> = Test::new(M, P, 1.0, 0.0, 1, 53);
    let e = field::at(&pot, &0.1, &0.1).unwrap_err();
    assert!(e.to_string().contains("y"), "{e}");
    let e = surface::stress(&pot, &1.5, Face::Right).unwrap_err();
    assert!(e.to_string().contains("(0, 1)"), "{e}");
    let e = field::at_polar(&pot, &-1.0, &-1.0, &1.0, default_options(53)).unwrap_err();
    assert!(e.to_string().contains("r"), "{e}");
    let bad: Test<f64> = Test::new(M, P, 1.0, 0.0, 0, 53);
    assert!(field::at(&bad, &0.1, &-0.1).is_err());
}

#[test]
fn default_real_axis_values_by_circle_mean() {
    // the head-wave field with the default fg_real equals the one with exact real values
    let mut pot: Test<f64> = Test::new(M, P, 1.0, 0.4, 1, 53);
    let o = default_options(53);
    let a = field::at_polar(&pot, &0.65, &-0.25, &1.0, o).unwrap().u;
    pot.exact_real = false;
    let b = field::at_polar(&pot, &0.65, &-0.25, &1.0, o).unwrap().u;
    let d: f64 = (a.clone() - b).abs();
    assert!(d < 1e-13 * a.abs(), "{d:e}");
}
