//! A second, independent route to the Lamb crate's step responses: the transform-domain
//! kernels inverted numerically by the contour representation of the self-similar response.
//!
//! A line load growing linearly in time, F = t delta(x) (the degree-0 point traction of the
//! contour representation), gives u = t U(x/t); its time derivative, the response to a unit
//! step, is U(s) - s U'(s) with s = x/t (c1 = 1, mu = 1). The Lamb crate states
//! u_z = W_zz(s)/pi, u_x = U_xz(s)/pi (normal force, z into the medium) and u_x = U_xx(s)/pi
//! (tangential force). The contour code has y = -z out of the body and surface tractions
//! (T_y, T_x) = (sigma_yy, sigma_xy): a normal force F_z is T_y = -F_z, and u_z = -u_y.

use complexfn::Cx;
use genuine::kernels::{point_load, ContourDisplacement, Lamb};
use lamb::HalfPlane;
use rug::Float;

fn check<T: complexfn::quadrature::CachedRules>(m: T, tol: f64, quad_tol: f64) {
    let hp = HalfPlane::new(m.clone()).unwrap();
    let kern = Lamb::new(m.clone());
    let (mm, sr) = (hp.m().clone(), hp.s_r().clone());
    let zero = || Cx::real(m.zero());
    let points = [
        m.lit(0.2),
        sr.clone() * 0.8,
        (sr.clone() + &mm) / 2.0,
        (mm.clone() + 1.0) / 2.0,
        m.lit(0.97),
        m.lit(1.3),
    ];
    for s in points {
        let want = hp.step(&s).unwrap();
        // normal force F_z = t delta(x): T_y = -t delta(x)
        let (a, _) = kern.displacement(s.clone(), quad_tol, |z| [-point_load(z), zero()]);
        // tangential force F_x = t delta(x): T_x = +t delta(x)
        let (b, _) = kern.displacement(s.clone(), quad_tol, |z| [zero(), point_load(z)]);
        let pi = s.pi();
        let step = |u: &T, du: &T| (u.clone() - s.clone() * du) * &pi;
        let w_zz = -step(&a[0], &a[2]);
        let u_xz = step(&a[1], &a[3]);
        let u_xx = step(&b[1], &b[3]);
        for (name, got, route) in [
            ("W_zz", &want.zz.value, &w_zz),
            ("U_xz", &want.xz.value, &u_xz),
            ("U_xx", &want.xx.value, &u_xx),
        ] {
            let d = (got.clone() - route).abs().to_f64();
            assert!(
                d < tol,
                "s = {}: {name} closed form {} vs contour {} ({d:e})",
                s.to_f64(),
                got.to_f64(),
                route.to_f64()
            );
        }
    }
}

#[test]
fn step_responses_equal_the_inverted_transform_solution_in_f64() {
    for nu in [0.25f64, 0.3, 0.1, 0.45] {
        let m = ((1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))).sqrt();
        check(m, 1e-13, 1e-15);
    }
}

#[test]
fn step_responses_equal_the_inverted_transform_solution_at_200_bits() {
    for nu in [0.3f64, 0.1] {
        let nu = Float::with_val(200, nu);
        let one = Float::with_val(200, 1);
        let num: Float = one.clone() - nu.clone() * 2.0;
        let den: Float = (one - nu) * 2.0;
        let m: Float = (num / den).sqrt();
        check(m, 1e-40, 1e-50);
    }
}
