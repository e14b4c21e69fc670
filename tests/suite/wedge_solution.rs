//! The wedge solution shown to solve the problem: boundary-condition residuals through the
//! homogeneous-function crate's surface formulas (18)/(19) (independent of the matching
//! formulas), closed forms, limits, an independent contour formula, apex asymptotics, and
//! agreement across precisions.

use complexfn::plemelj::Face;
use complexfn::quadrature::{tanh_sinh, Point, TsOptions};
use complexfn::scalar::rel_diff;
use complexfn::{p_k, Cx, Real};
use homogeneous::surface;
use rug::Float;
use wedge::{case_for_speed, ApexRegime, Case, Coupling, Indenter, Material, Solution};

fn paper() -> Material {
    Material::paper()
}

fn case(theta: f64, gamma: f64, coupling: Coupling, p: f64, sol: Solution) -> Case<f64> {
    Case::new(
        &paper(),
        &Indenter::new(theta, gamma, coupling).unwrap(),
        p,
        sol,
    )
    .unwrap()
}

/// (Theta, gamma, coupling) over the three regimes and both couplings.
const CASES: &[(f64, f64, Coupling)] = &[
    (89.0, 0.6, Coupling::On),
    (86.0, 0.001, Coupling::On),
    (86.0, 0.0, Coupling::Off),
    (89.0, 0.0, Coupling::On),
    (80.0, 0.4, Coupling::Off),
];

#[test]
fn residual_of_contact_condition_friction_law_and_free_surface_f64() {
    for &(th, g, c) in CASES {
        for p in [0.1, 0.3, 0.45] {
            let cs = case(th, g, c, p, Solution::Paper);
            let pot = cs.potentials().unwrap();
            let v = cs.v_hat().unwrap();
            let beta = *cs.beta();
            // (7) at 50 points across the contact: u_theta + beta u_r = -V t + r cot Theta.
            // On theta = -pi both polar unit vectors point the other way (e_theta = -e_y), so
            // the condition there reads -u_theta + beta u_r = -V t + r cot Theta.
            for k in 0..50 {
                let x = p * (k as f64 + 0.5) / 50.0;
                for (face, sign) in [(Face::Right, 1.0), (Face::Left, -1.0)] {
                    let u = surface::displacement(&pot, &x, face).unwrap();
                    let res = (sign * u.im + beta * u.re - (x - v)).abs() / v;
                    assert!(
                        res <= 1e-12,
                        "(7) {th} {g} {c:?} p {p} x {x} {face:?}: {res:e}"
                    );
                }
            }
            // (4b) on the contact and (4c) outside, from (19)
            for k in 0..5 {
                let x = p * (k as f64 + 0.5) / 5.0;
                let s = surface::stress(&pot, &x, Face::Right).unwrap();
                let (sig, tau) = (s.re, -s.im);
                assert!(
                    (tau + g * sig).abs() <= 1e-13 * sig.abs(),
                    "(4b) {th} {g} x {x}: {tau} {sig}"
                );
                let st = cs.stress_hat(&x).unwrap().value;
                assert!(
                    (sig - st).abs() <= 1e-12 * st.abs(),
                    "(19) vs (40): {sig} {st}"
                );
            }
            for x in [p * 1.05, (p + 1.0) / 2.0, 0.97] {
                let s = surface::stress(&pot, &x, Face::Right).unwrap();
                assert!(s.abs() < 1e-13, "(4c) at {x}: {s}");
            }
        }
    }
}

#[test]
fn residual_of_contact_condition_at_40_digits() {
    let bits = 180;
    let like = Float::with_val(bits, 0);
    let ind = Indenter::new(89.0, 0.6, Coupling::On).unwrap();
    let p: Float = Float::with_val(bits, 3) / 10.0;
    let cs = Case::new(&paper(), &ind, p.clone(), Solution::Paper).unwrap();
    let pot = cs.potentials().unwrap();
    let v = cs.v_hat().unwrap();
    for f in [0.05, 0.5, 0.95] {
        let x = p.clone() * like.lit(f);
        let u = surface::displacement(&pot, &x, Face::Right).unwrap();
        let lhs = u.im + cs.beta().clone() * &u.re;
        let rhs = x - &v;
        let res = ((lhs - rhs) / &v).abs().to_f64();
        assert!(res <= 1e-35, "x {f}: {res:e}");
    }
}

#[test]
fn as_printed_matching_violates_the_contact_condition_with_friction() {
    // The printed (53)-(57) omit the Rayleigh-pole terms: (7) fails by 1e-2 .. 2e-1 of V t.
    let cs = case(89.0, 0.6, Coupling::On, 0.3, Solution::AsPrinted);
    let pot = cs.potentials().unwrap();
    let v = cs.v_hat().unwrap();
    let x = 0.15;
    let u = surface::displacement(&pot, &x, Face::Right).unwrap();
    let res = (u.im + cs.beta() * u.re - (x - v)).abs() / v;
    assert!(res > 1e-2, "{res}");
    // but in the classical case the pole terms vanish and both variants coincide
    let a = case(86.0, 0.0, Coupling::Off, 0.3, Solution::AsPrinted);
    let b = case(86.0, 0.0, Coupling::Off, 0.3, Solution::Paper);
    assert_eq!(a.v_hat().unwrap(), b.v_hat().unwrap());
}

#[test]
fn classical_case_closed_forms() {
    // beta = gamma = 0: b = 0, (41) is exact, and P/(a mu cot Theta) = 2/(1 - nu) for every
    // alpha (the force per unit half-width does not depend on the contact speed).
    let nu = paper().poisson();
    for p in [0.01, 0.1, 0.3, 0.45, 0.49] {
        let cs = case(86.0, 0.0, Coupling::Off, p, Solution::Paper);
        let f = cs.force_hat().unwrap();
        assert!((f - 2.0 / (1.0 - nu)).abs() < 1e-13, "p {p}: {f}");
        let q = cs.q_hat().unwrap();
        for x in [1e-9, 1e-3, 0.5, 0.999] {
            let s = cs.stress_hat(&(x * p)).unwrap().value;
            let exact = -(q / p) * (1.0 / x).acosh();
            assert!(
                (s - exact).abs() <= 1e-13 * exact.abs(),
                "p {p} x {x}: {s} {exact}"
            );
        }
        assert_eq!(cs.regime(), ApexRegime::Logarithmic);
    }
}

#[test]
fn quasi_static_limit_is_johnsons_static_wedge() {
    // As alpha -> 0 the classical force tends to 2/(1 - nu); with coupling and friction the
    // limit exists (the force converges) and approaches Johnson's value as cot Theta -> 0.
    let nu = paper().poisson();
    let f = case(86.0, 0.0, Coupling::Off, 1e-5, Solution::Paper)
        .force_hat()
        .unwrap();
    assert!((f - 2.0 / (1.0 - nu)).abs() < 1e-12);
    for (th, g) in [(86.0, 0.001), (86.0, 0.6)] {
        let f1 = case(th, g, Coupling::On, 1e-4, Solution::Paper)
            .force_hat()
            .unwrap();
        let f2 = case(th, g, Coupling::On, 1e-5, Solution::Paper)
            .force_hat()
            .unwrap();
        assert!((f1 - f2).abs() < 2e-3 * f2, "{f1} {f2}");
    }
    let f = case(89.99, 0.0, Coupling::On, 1e-5, Solution::Paper)
        .force_hat()
        .unwrap();
    assert!((f - 2.0 / (1.0 - nu)).abs() < 1e-3, "{f}");
}

#[test]
fn force_from_integrating_the_contact_stress_equals_eq_47() {
    for &(th, g, c) in CASES {
        let cs = case(th, g, c, 0.3, Solution::Paper);
        let p = 0.3;
        // P/(a mu cot Theta) = -(2/p) Int_0^p sigma dx, in the variable ln x near the apex
        let upper = tanh_sinh(&(p / 8.0), &p, TsOptions::new(1e-13), |pt: &Point<f64>| {
            if pt.to_b <= 0.0 {
                0.0
            } else {
                cs.stress_hat(&pt.v).unwrap().value
            }
        })
        .unwrap();
        let lower = tanh_sinh(
            &(-40.0_f64),
            &(p / 8.0).ln(),
            TsOptions::new(1e-13),
            |pt: &Point<f64>| {
                let x = pt.v.exp();
                cs.stress_hat(&x).unwrap().value * x
            },
        )
        .unwrap();
        let integrated = -(2.0 / p) * (upper.value + lower.value);
        let eq47 = cs.force_hat().unwrap();
        assert!(
            (integrated - eq47).abs() < 1e-9 * eq47,
            "{th} {g}: {integrated} vs {eq47}"
        );
    }
}

#[test]
fn apex_tangential_displacement_vanishes_without_friction() {
    for (th, c) in [
        (86.0, Coupling::Off),
        (89.0, Coupling::On),
        (80.0, Coupling::On),
    ] {
        let cs = case(th, 0.0, c, 0.3, Solution::Paper);
        let u = cs.apex_u_r_over_speed_t().unwrap().value;
        assert!(u.abs() < 1e-13, "{th} {c:?}: {u:e}");
    }
    // ... but not with the printed matching (the pole terms restore the symmetry)
    let u = case(89.0, 0.0, Coupling::On, 0.3, Solution::AsPrinted)
        .apex_u_r_over_speed_t()
        .unwrap()
        .value;
    assert!(u.abs() > 1e-2);
}

#[test]
fn apex_dislocation_equals_the_contour_formula() {
    // Errata section 6: u_r(0+) = (gamma/m^2)(Q t/c1) Int_0^inf p1(iy) y H(iy)/R(iy) dy, an
    // integral along the image of the symmetry line that shares nothing with the real-axis
    // evaluation but H.
    for (th, g, p) in [(89.0, 0.6, 0.3), (86.0, 0.001, 0.3), (85.0, 1.0, 0.2)] {
        let cs = case(th, g, Coupling::On, p, Solution::Paper);
        let ray = cs.rayleigh().clone();
        let m2 = cs.m() * cs.m();
        let half_pi = std::f64::consts::FRAC_PI_2;
        let e = tanh_sinh(&0.0, &1.0, TsOptions::new(1e-14), |pt: &Point<f64>| {
            let y = (half_pi * pt.to_b).tan().recip();
            let dy = half_pi / (half_pi * pt.to_b).sin().powi(2);
            let z = Cx::new(0.0, y);
            (p_k(&z, &1.0) * cs.h(&z) / ray.at(&z).r).scale(&(y * dy))
        })
        .unwrap();
        let contour = e.value.re * g / m2 * cs.q_hat().unwrap() / cs.v_hat().unwrap();
        let real_axis = cs.apex_u_r_over_speed_t().unwrap().value;
        assert!(
            (contour - real_axis).abs() < 1e-12 * real_axis.abs(),
            "{th} {g}: {contour} {real_axis}"
        );
        assert!(e.value.im.abs() < 1e-12 * e.value.re.abs());
    }
    // Errata's figures: u_r(0+) ~ 1.03 Q t/c1 at 89 deg, gamma 0.6; 0.0016 at 86 deg, gamma 0.001.
    let a = case(89.0, 0.6, Coupling::On, 0.3, Solution::Paper);
    let ur_q = a.apex_u_r_over_speed_t().unwrap().value * a.v_hat().unwrap() / a.q_hat().unwrap();
    assert!((ur_q - 1.03).abs() < 0.01, "{ur_q}");
}

#[test]
fn apex_asymptotics_power_finite_and_logarithmic() {
    // power: sigma = A (p/x)^(2 Omega0) + const + o(1), so differences of sigma follow the
    // differences of the leading term
    let cs = case(89.0, 0.6, Coupling::On, 0.3, Solution::Paper);
    let apex = cs.apex().unwrap();
    assert_eq!(apex.regime, ApexRegime::Power);
    assert!((apex.exponent - 2.0 * cs.omega0()).abs() < 1e-16);
    let (x1, x2) = (0.3e-7, 0.3e-9);
    let ds = cs.stress_hat(&x1).unwrap().value - cs.stress_hat(&x2).unwrap().value;
    let dl = cs.apex_leading_term(&x1).unwrap() - cs.apex_leading_term(&x2).unwrap();
    assert!((ds / dl - 1.0).abs() < 1e-6, "{}", ds / dl);
    // the two-term expansion C + A (p/x)^(2 Omega0) itself
    for x in [0.3e-7, 0.3e-11] {
        let s = cs.stress_hat(&x).unwrap().value;
        let lead = cs.apex_leading_term(&x).unwrap();
        assert!((s - lead).abs() < 1e-4 * s.abs(), "x {x}: {s} {lead}");
    }
    // finite: sigma(x) - sigma(0) ~ Q c0 x^(-2 Omega0)/(-2 Omega0)
    let cs = case(86.0, 0.001, Coupling::On, 0.3, Solution::Paper);
    let apex = cs.apex().unwrap();
    assert_eq!(apex.regime, ApexRegime::Finite);
    let o0 = cs.omega0();
    let c0 = cs.s0().exp() * (std::f64::consts::PI * o0).cos() * 0.3_f64.powf(2.0 * o0 - 1.0);
    let q = cs.q_hat().unwrap();
    for x in [1e-8, 1e-10] {
        let s = cs.stress_hat(&x).unwrap().value;
        let pred = apex.amplitude + q * c0 * x.powf(-2.0 * o0) / (-2.0 * o0);
        assert!((s - pred).abs() < 1e-6 * s.abs(), "x {x}: {s} {pred}");
    }
    // logarithmic on the regime boundary gamma = cot Theta: (41) exact
    let cot = Indenter::new(86.0, 0.0, Coupling::On)
        .unwrap()
        .cot_theta(&0.0_f64);
    let cs = case(86.0, cot, Coupling::On, 0.3, Solution::Paper);
    assert!(cs.on_regime_boundary());
    assert_eq!(cs.regime(), ApexRegime::Logarithmic);
    let q = cs.q_hat().unwrap();
    for x in [1e-6, 0.1, 0.29] {
        let s = cs.stress_hat(&x).unwrap().value;
        assert!((s + q / 0.3 * (0.3 / x).acosh()).abs() < 1e-13 * s.abs());
    }
    // just off the boundary the regime is decided by the sign of gamma - cot Theta
    assert_eq!(
        case(
            86.0,
            cot * (1.0 - 1e-12),
            Coupling::On,
            0.3,
            Solution::Paper
        )
        .regime(),
        ApexRegime::Finite
    );
    assert_eq!(
        case(
            86.0,
            cot * (1.0 + 1e-12),
            Coupling::On,
            0.3,
            Solution::Paper
        )
        .regime(),
        ApexRegime::Power
    );
}

#[test]
fn f64_and_256_bits_agree_and_256_and_512_bits_agree_to_70_digits() {
    let ind = Indenter::new(89.0, 0.6, Coupling::On).unwrap();
    let mut q = Vec::new();
    for bits in [256u32, 512] {
        let p: Float = Float::with_val(bits, 3) / 10.0;
        let cs = Case::new(&paper(), &ind, p.clone(), Solution::Paper).unwrap();
        let x = p.clone() / 2;
        q.push((
            cs.q_hat().unwrap(),
            cs.v_hat().unwrap(),
            cs.stress_hat(&x).unwrap().value,
            cs.s0(),
        ));
    }
    let cs = case(89.0, 0.6, Coupling::On, 0.3, Solution::Paper);
    let f64s = [
        cs.q_hat().unwrap(),
        cs.v_hat().unwrap(),
        cs.stress_hat(&0.15).unwrap().value,
        cs.s0(),
    ];
    let (a, b) = (&q[0], &q[1]);
    for (x, y) in [(&a.0, &b.0), (&a.1, &b.1), (&a.2, &b.2), (&a.3, &b.3)] {
        assert!(rel_diff(x, y) < 1e-70, "{x} {y}");
    }
    for (x, y) in f64s.iter().zip([&b.0, &b.1, &b.2, &b.3]) {
        assert!(((x - y.to_f64()) / x).abs() < 1e-14, "{x} {y}");
    }
}

#[test]
fn inverse_solve_recovers_alpha() {
    let mat = paper();
    for &(th, g, c) in CASES {
        let ind = Indenter::new(th, g, c).unwrap();
        let cs = Case::with_alpha(&mat, &ind, 400.0, &0.0_f64, Solution::Paper).unwrap();
        let speed = cs.v_hat().unwrap() * 1870.83 * ind.cot_theta(&0.0_f64);
        let back = case_for_speed(&mat, &ind, speed, &0.0_f64, Solution::Paper).unwrap();
        assert!(
            (back.p() * 1870.83 - 400.0).abs() < 1e-9,
            "{th} {g}: {}",
            back.p() * 1870.83
        );
    }
    // at 30 digits
    let like = Float::with_val(130, 0);
    let ind = Indenter::new(86.0, 0.4, Coupling::On).unwrap();
    let cs = Case::with_alpha(&mat, &ind, 400.0, &like, Solution::Paper).unwrap();
    let speed =
        (cs.v_hat().unwrap() * Float::with_val(130, 1870.83) * ind.cot_theta(&like)).to_f64();
    let back = case_for_speed(&mat, &ind, speed, &like, Solution::Paper).unwrap();
    let alpha = back.p().clone() * Float::with_val(130, 1870.83);
    assert!((alpha.to_f64() - 400.0).abs() < 1e-10);
    let too_fast = case_for_speed(&mat, &ind, 1e9, &0.0_f64, Solution::Paper)
        .unwrap_err()
        .to_string();
    assert!(too_fast.contains("speed"), "{too_fast}");
}

#[test]
fn admissibility_of_the_papers_cases() {
    // Signorini holds; (8) holds for strong friction, fails for weak friction with the
    // consistent matching (errata, section 7).
    let a = case(89.0, 0.6, Coupling::On, 0.3, Solution::Paper)
        .admissibility()
        .unwrap();
    assert!(a.contact_compressive && a.no_interpenetration && a.slip_direction_ok);
    let b = case(86.0, 0.001, Coupling::On, 0.3, Solution::Paper)
        .admissibility()
        .unwrap();
    assert!(b.contact_compressive && b.no_interpenetration);
    assert!(!b.slip_direction_ok && b.min_slip_rate < 0.0);
    // the gap closes smoothly at the edge: g(p) = 0 by (53), g ~ (x - p)^(3/2 + Omega(p))
    let cs = case(89.0, 0.6, Coupling::On, 0.3, Solution::Paper);
    let g1 = cs.normal_gap(&(0.3 + 1e-6)).unwrap();
    let g2 = cs.normal_gap(&(0.3 + 1e-4)).unwrap();
    let expo = (g2 / g1).ln() / 100f64.ln();
    let om_p = cs.omega(&0.3);
    assert!(
        (expo - (1.5 + om_p)).abs() < 0.02,
        "{expo} vs {}",
        1.5 + om_p
    );
}

#[test]
fn bad_input_is_refused_with_the_parameter_and_its_range() {
    let mat = paper();
    let msg = |e: wedge::WedgeError| e.to_string();
    assert!(msg(Indenter::new(90.0, 0.1, Coupling::On).unwrap_err()).contains("theta_deg"));
    assert!(msg(Indenter::new(45.0, -0.1, Coupling::On).unwrap_err()).contains("gamma"));
    assert!(msg(Indenter::new(45.0, f64::NAN, Coupling::On).unwrap_err()).contains("gamma"));
    assert!(msg(Material::new(1000.0, 900.0).unwrap_err()).contains("c2"));
    assert!(msg(Material::from_poisson(0.5, 1000.0).unwrap_err()).contains("poisson"));
    let ind = Indenter::new(86.0, 0.1, Coupling::On).unwrap();
    for alpha in [0.0, -1.0, 927.5, f64::INFINITY] {
        let e = msg(Case::with_alpha(&mat, &ind, alpha, &0.0_f64, Solution::Paper).unwrap_err());
        assert!(e.contains("alpha") && e.contains("c_R"), "{e}");
    }
    let e = msg(Case::new(&mat, &ind, 0.3, Solution::Genuine).unwrap_err());
    assert!(e.contains("genuine"));
    let cs = case(86.0, 0.1, Coupling::On, 0.3, Solution::Paper);
    assert!(cs.stress_hat(&0.31).is_err());
    assert!(cs.stress_hat(&f64::NAN).is_err());
}
