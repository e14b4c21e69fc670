//! Independent routes shared by the tests: the transform-domain solution of Lamb's problem by a
//! numerical 2x2 traction solve, and plain quadrature of the impulse responses.
#![allow(dead_code)]

use complexfn::quadrature::{tanh_sinh, CachedRules, TsOptions};
use complexfn::{Cx, Real};
use lamb::HalfPlane;
use rug::Float;

/// Poisson's ratios of the tests: nu = 1/4 hides coincidences, so others too (three real
/// roots of the Rayleigh cubic below 0.2631, a complex pair above).
pub const POISSON: [f64; 5] = [0.25, 0.3, 0.1, 0.45, -0.3];

pub fn fl(bits: u32, x: f64) -> Float {
    Float::with_val(bits, x)
}

/// m = c2/c1 for Poisson's ratio nu at the precision of `like`.
pub fn m_of<T: Real>(like: &T, nu: f64) -> T {
    let nu = like.lit(nu);
    let one = like.one();
    ((one.clone() - nu.clone() * 2.0) / ((one - nu) * 2.0)).sqrt()
}

/// Surface displacement transforms (u_z, u_x) at the slowness xi + i0 (units c1 = 1, mu = 1)
/// due to unit surface forces (F_z, F_x), from the raw potentials of the half-space z > 0:
/// phi = A e^{-lambda(xi x + eta1 z)}, psi = B e^{-lambda(xi x + eta2 z)},
/// u_x = phi_x - psi_z, u_z = phi_z + psi_x, tractions sigma_zz = -F_z, sigma_xz = -F_x at
/// z = 0, solved as a 2x2 linear system (Cramer). No Rayleigh function is formed.
pub fn transform_response<T: Real>(m: &T, xi: &T, fz: f64, fx: f64) -> (Cx<T>, Cx<T>) {
    let one = m.one();
    let zero = m.zero();
    let inv_c2sq = m.clone().sqr().recip();
    // eta_j at xi + i0: sqrt(1/c_j^2 - xi^2) if positive, else -i sqrt(xi^2 - 1/c_j^2)
    let eta = |ic2: &T| -> Cx<T> {
        let d = ic2.clone() - xi.clone().sqr();
        if d >= 0.0 {
            Cx::real(d.sqrt())
        } else {
            Cx::new(zero.clone(), -(-d).sqrt())
        }
    };
    let e1 = eta(&one);
    let e2 = eta(&inv_c2sq);
    let lam_l = inv_c2sq.clone() - 2.0; // lambda_Lame with rho = 1/c2^2, c1 = 1
    let xi_c = Cx::real(xi.clone());
    // rows: sigma_zz and sigma_xz (divided by lambda^2) in terms of A, B
    let a11 = (e1.clone() * &e1 * 2.0).add_re(&lam_l);
    let a12 = xi_c.clone() * &e2 * 2.0;
    let a21 = xi_c.clone() * &e1 * 2.0;
    let a22 = (-(e2.clone() * &e2)).add_re(&xi.clone().sqr());
    let r1 = Cx::real(one.lit(-fz));
    let r2 = Cx::real(one.lit(-fx));
    let det = a11.clone() * &a22 - a12.clone() * &a21;
    let a = (r1.clone() * &a22 - a12 * &r2) / &det;
    let b = (a11 * &r2 - a21 * &r1) / &det;
    let uz = -(e1 * &a) - xi_c.clone() * &b;
    let ux = -(xi_c * &a) + e2 * &b;
    (uz, ux)
}

/// g(s) = (1/s) Im A(1/s + i0) for x > 0 (the jump of the inverse transform along the
/// Cagniard path t = xi x): [g_zz, g_xz, g_xx, g_zx].
pub fn jump_route<T: Real>(m: &T, s: &T) -> [T; 4] {
    let xi = s.clone().recip();
    let (uz_n, ux_n) = transform_response(m, &xi, 1.0, 0.0);
    let (uz_t, ux_t) = transform_response(m, &xi, 0.0, 1.0);
    [uz_n.im / s, ux_n.im / s, ux_t.im / s, uz_t.im / s]
}

/// The raw Rayleigh function D(s) = (2 - s^2/m^2)^2 - 4 sqrt(1 - s^2) sqrt(1 - s^2/m^2), s < m.
pub fn raw_rayleigh<T: Real>(m: &T, s: &T) -> T {
    let one = s.one();
    let x = s.clone().sqr() / m.clone().sqr();
    let k = one.lit(2.0) - &x;
    k.sqr() - ((one.clone() - s.clone().sqr()) * (one - x)).sqrt() * 4.0
}

/// Int_a^b f by tanh-sinh (the ends may carry square-root behaviour); the tolerance is
/// relative to max(|integral|, b - a) (f + 1 is integrated, for integrals that vanish).
pub fn quad<T: CachedRules>(a: &T, b: &T, tol: f64, f: impl Fn(&T) -> T) -> T {
    match tanh_sinh(a, b, TsOptions::new(tol), |p| f(&p.v) + 1.0) {
        Ok(e) => e.estimate.value - (b.clone() - a),
        Err(e) => panic!("quadrature on [{a}, {b}]: {e}"),
    }
}

/// Int_sa^sb g_c(s) s^-n ds by quadrature of the closed-form g, split at m and 1, with the
/// principal value across s_R by symmetric pairing over [s_R - h, s_R + h] and the delta of
/// the cross term added by hand. `comp`: 0 = zz, 1 = xz, 2 = xx.
pub fn moment_by_quadrature<T: CachedRules>(
    hp: &HalfPlane<T>,
    comp: usize,
    n: i32,
    sa: &T,
    sb: &T,
    tol: f64,
) -> T {
    let g = |s: &T| -> T {
        if (*s <= 0.0 && n > 0) || *s == *hp.s_r() {
            return s.zero();
        }
        let v = hp.impulse(s).expect("g");
        let c = match comp {
            0 => v.zz.value,
            1 => v.xz.value,
            _ => v.xx.value,
        };
        c * s.clone().powi(-n)
    };
    let one = sa.one();
    let m = hp.m().clone();
    let sr = hp.s_r().clone();
    let mut breaks = vec![sa.clone()];
    let h = (m.clone() - &sr).min(sr.clone()) / 2.0;
    let (pl, pr) = (sr.clone() - &h, sr.clone() + &h);
    for b in [pl.clone(), pr.clone(), m.clone(), one.clone()] {
        if b > *sa && b < *sb {
            breaks.push(b);
        }
    }
    breaks.push(sb.clone());
    let mut total = sa.zero();
    for w in breaks.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        if *a >= 1.0 {
            break;
        }
        let inside_pole = *a >= pl && *b <= pr && *a < sr && *b > sr;
        if inside_pole {
            // a cell end inside the pole window: pair symmetrically about s_R on the common
            // half-width, the rest plainly
            let d = (sr.clone() - a).min(b.clone() - &sr);
            total += quad(&a.zero(), &d, tol, |e| {
                g(&(sr.clone() + e)) + g(&(sr.clone() - e))
            });
            let (la, lb) = (a.clone(), sr.clone() - &d);
            if lb > la {
                total += quad(&la, &lb, tol, g);
            }
            let (ra, rb) = (sr.clone() + &d, b.clone());
            if rb > ra {
                total += quad(&ra, &rb, tol, g);
            }
        } else {
            total += quad(a, b, tol, g);
        }
    }
    if comp == 1 && *sa < sr && *sb > sr {
        let c = hp.rayleigh_constants();
        total += sa.pi() * &c.k_r * c.s_r.clone().powi(1 - n);
    }
    total
}
