//! Lamb's kernels and the contour representation against closed-form half-plane solutions.
use genuine::kernels::{point_load, uniform_load, ContourDisplacement, Lamb, C64};

const M: f64 = 1000.0 / 1870.83; // the paper's material

fn nu(m: f64) -> f64 {
    (1.0 - 2.0 * m * m) / (2.0 * (1.0 - m * m))
}

/// A uniform load spreading at a supersonic speed P > 1 (c1 = 1): for 1 < x0 < P only the
/// nearer front has been felt, and the surface field is the exact plane-wave (trace slowness
/// 1/P) field u_j = K_jk(1/P) sigma_k (t - x/P); ahead of the front (x0 > P) it is zero.
#[test]
fn supersonic_uniform_load_reproduces_the_plane_wave_field() {
    let lamb = Lamb::new(M);
    let big_p = 1.6;
    let k = lamb.kernels(&C64::new(1.0 / big_p, 0.0));
    for &x0 in &[1.05, 1.2, 1.45] {
        // normal pressure S_y = -1
        let (u, _) =
            lamb.displacement(x0, 1e-14, |z| [-uniform_load(big_p, z), C64::new(0.0, 0.0)]);
        let ey = -k[0][0].re * (1.0 - x0 / big_p);
        let ex = -k[1][0].re * (1.0 - x0 / big_p);
        assert!(
            (u[0] - ey).abs() < 1e-12 * ey.abs(),
            "U_y {x0}: {} vs {}",
            u[0],
            ey
        );
        assert!(
            (u[1] - ex).abs() < 1e-12 * ex.abs(),
            "U_x {x0}: {} vs {}",
            u[1],
            ex
        );
        // slope: dU/dx0 = K sigma / P
        assert!((u[2] - k[0][0].re / big_p).abs() < 1e-11 * (k[0][0].re / big_p).abs());
        // uniform shear S_x = +1 (same direction on both sides)
        let (v, _) = lamb.displacement(x0, 1e-14, |z| [C64::new(0.0, 0.0), uniform_load(big_p, z)]);
        let vy = k[0][1].re * (1.0 - x0 / big_p);
        let vx = k[1][1].re * (1.0 - x0 / big_p);
        assert!(
            (v[0] - vy).abs() < 1e-12 * vy.abs(),
            "shear U_y {x0}: {} vs {}",
            v[0],
            vy
        );
        assert!(
            (v[1] - vx).abs() < 1e-12 * vx.abs(),
            "shear U_x {x0}: {} vs {}",
            v[1],
            vx
        );
    }
    // nothing ahead of the front
    let (u, _) = lamb.displacement(1.8, 1e-14, |z| {
        [-uniform_load(big_p, z), C64::new(0.0, 0.0)]
    });
    assert!(u[0].abs() < 1e-13 && u[1].abs() < 1e-13, "{u:?}");
    // the one-dimensional limit: K_yy(0) sigma = -m^2 (c2^2/c1 per unit pressure)
    let k0 = lamb.kernels(&C64::new(0.0, 0.0));
    assert!((k0[0][0].re - M * M).abs() < 1e-15);
}

/// A compressive line load growing as P = t (S_y = -delta): close to the load the response is
/// quasi-static (Flamant): u_y = (1 - nu) P ln|x| / (pi mu) + C, u_x = -(1 - 2 nu) P sgn(x)/(4 mu).
#[test]
fn slow_limit_is_flamant() {
    let lamb = Lamb::new(M);
    let nu = nu(M);
    let x0 = 1e-4;
    let f = |z: C64| [-point_load(z), C64::new(0.0, 0.0)];
    let (a, _) = lamb.displacement(x0, 1e-14, f);
    let (b, _) = lamb.displacement(2.0 * x0, 1e-14, f);
    let log_coeff = (b[0] - a[0]) / 2f64.ln();
    let expect = (1.0 - nu) / std::f64::consts::PI;
    assert!(
        (log_coeff - expect).abs() < 1e-6 * expect,
        "{log_coeff} vs {expect}"
    );
    // slope form of the same: x U_y' = (1 - nu)/pi
    assert!((x0 * a[2] - expect).abs() < 1e-6 * expect, "{}", x0 * a[2]);
    // the dynamic correction is linear in x0: Richardson-extrapolate to x0 -> 0+
    let ux = -(1.0 - 2.0 * nu) / 4.0;
    let got = 2.0 * a[1] - b[1];
    assert!((got - ux).abs() < 1e-7 * ux.abs(), "{got} vs {ux}");
    // and without extrapolation it is already within O(x0)
    assert!((a[1] - ux).abs() < 1e-3 * ux.abs());
}

/// A tangential line load Q = t in +x (S_x = delta): quasi-static Cerruti field
/// u_x = -(1 - nu) Q ln|x|/(pi mu) + C, u_y = -(1 - 2 nu) Q sgn(x)/(4 mu).
#[test]
fn slow_limit_is_cerruti() {
    let lamb = Lamb::new(M);
    let nu = nu(M);
    let x0 = 1e-4;
    let f = |z: C64| [C64::new(0.0, 0.0), point_load(z)];
    let (a, _) = lamb.displacement(x0, 1e-14, f);
    let (b, _) = lamb.displacement(2.0 * x0, 1e-14, f);
    let log_coeff = (b[1] - a[1]) / 2f64.ln();
    let expect = -(1.0 - nu) / std::f64::consts::PI;
    assert!(
        (log_coeff - expect).abs() < 1e-6 * expect.abs(),
        "{log_coeff} vs {expect}"
    );
    let uy = -(1.0 - 2.0 * nu) / 4.0;
    let got = 2.0 * a[0] - b[0];
    assert!((got - uy).abs() < 1e-7 * uy.abs(), "{got} vs {uy}");
}

/// Reciprocity: K_xy = -K_yx at every slowness, and hence the tangential displacement under a
/// normal line load equals minus the normal displacement under a tangential one, at every
/// self-similar station (not only in the static limit).
#[test]
fn reciprocity() {
    let lamb = Lamb::new(M);
    for xi in [
        C64::new(0.3, -0.1),
        C64::new(2.5, -0.01),
        C64::new(-1.2, -3.0),
        C64::new(0.5, 0.0),
    ] {
        let k = lamb.kernels(&xi);
        assert!((k[0][1].clone() + &k[1][0]).abs() < 1e-15 * k[0][1].abs());
    }
    for &x0 in &[0.05, 0.3, 0.52, 0.8, 1.3] {
        let (a, _) = lamb.displacement(x0, 1e-14, |z| [point_load(z), C64::new(0.0, 0.0)]);
        let (b, _) = lamb.displacement(x0, 1e-14, |z| [C64::new(0.0, 0.0), point_load(z)]);
        assert!(
            (a[1] + b[0]).abs() < 1e-12 * a[1].abs().max(1e-3),
            "{x0}: {} {}",
            a[1],
            b[0]
        );
    }
}
