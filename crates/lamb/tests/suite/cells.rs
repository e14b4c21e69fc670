//! Space-time cells against quadrature: a double Gauss-Legendre integral of the impulse
//! response where the cell sees one smooth wave region, and an integral over the strip of the
//! (independently checked) step responses where the Rayleigh ray and the wavefronts cross it.

use crate::common;

use common::quad;
use complexfn::quadrature::gauss_legendre;
use lamb::cells::{Cell, TimeShape};
use lamb::HalfPlane;

/// G(X, T) = g(|X|/T)/(pi T), cross term odd in X: [zz, xz, xx].
fn green(hp: &HalfPlane<f64>, x: f64, t: f64) -> [f64; 3] {
    let s = x.abs() / t;
    let g = hp.impulse(&s).unwrap();
    let sg = x.signum();
    let f = 1.0 / (std::f64::consts::PI * t);
    [g.zz.value * f, g.xz.value * f * sg, g.xx.value * f]
}

#[test]
fn a_cell_in_one_smooth_region_equals_a_double_gauss_legendre_integral() {
    let rule = gauss_legendre(40).unwrap();
    for nu in [0.25, 0.3, 0.1] {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        let (m, sr) = (*hp.m(), *hp.s_r());
        // (x, t) and the cell chosen so that every s = |x - xi|/(t - tau) in the cell stays in
        // one region: behind R (but away from 0), between R and S, between S and P
        let cases = [
            (0.1 * sr, 0.5 * sr),
            (sr + 0.2 * (m - sr), sr + 0.8 * (m - sr)),
            (m + 0.1 * (1.0 - m), m + 0.9 * (1.0 - m)),
        ];
        for (lo, hi) in cases {
            let (t, ta, tb) = (10.0, 1.0, 1.05);
            // |x - xi| in [lo (t - ta), hi (t - tb)] needs lo (t - ta) < hi (t - tb)
            let (xa, xb) = (0.0, hi * (t - tb) - lo * (t - ta));
            let x = xb + lo * (t - ta);
            assert!(xb > 0.0);
            let cell = Cell { xa, xb, ta, tb };
            for shape in [TimeShape::Constant, TimeShape::Linear] {
                let got = hp.cell_response(&cell, shape, &x, &t).unwrap();
                let mut want = [0.0; 3];
                for &(u, wu) in &rule.nodes {
                    let xi = xa + (xb - xa) * (u + 1.0) / 2.0;
                    for &(v, wv) in &rule.nodes {
                        let tau = ta + (tb - ta) * (v + 1.0) / 2.0;
                        let load = match shape {
                            TimeShape::Constant => 1.0,
                            TimeShape::Linear => (tau - ta) / (tb - ta),
                        };
                        let g = green(&hp, x - xi, t - tau);
                        let w = wu * wv * (xb - xa) * (tb - ta) / 4.0 * load;
                        for k in 0..3 {
                            want[k] += w * g[k];
                        }
                    }
                }
                for (k, e) in [&got.zz, &got.xz, &got.xx].iter().enumerate() {
                    let d = (e.value - want[k]).abs();
                    let scale = want.iter().map(|w| w.abs()).fold(0.0, f64::max);
                    // the corner differences lose about log10(t/(tb - ta)) digits, twice for a
                    // load linear in time (docs/lamb.md, section 4)
                    let tol = match shape {
                        TimeShape::Constant => 1e-12,
                        TimeShape::Linear => 1e-9,
                    };
                    assert!(
                        d < tol * scale,
                        "nu {nu} [{lo}, {hi}] {shape:?} comp {k}: {} vs {} ({d:e})",
                        e.value,
                        want[k]
                    );
                    assert!(
                        d <= e.error.max(1e-15 * scale),
                        "nu {nu} comp {k}: stated {:e} actual {d:e}",
                        e.error
                    );
                }
            }
        }
    }
}

#[test]
fn cells_crossing_the_wavefronts_equal_the_strip_integral_of_the_step_responses() {
    // u(x, t) = Int_{xa}^{xb} [W(|X|/(t - ta)) - W(|X|/(t - tb))]/pi dxi for a constant load
    // (Int_0^T G dT' = W(|X|/T)/pi); a load linear in time needs Int T G dT =
    // (|X|/pi) [M_2(|X|/(t - ta)) - M_2(|X|/(t - tb))] (times the parity of the component):
    // u = [(t - ta) Int G - Int T G]/(tb - ta).
    for nu in [0.25, 0.45, -0.3] {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        let (m, sr) = (*hp.m(), *hp.s_r());
        let (xa, xb, ta, tb, t, x) = (-0.3, 0.5, 0.0, 0.4, 1.0, 0.37);
        let pi = std::f64::consts::PI;
        let cell = Cell { xa, xb, ta, tb };
        // breakpoints in xi where |x - xi|/(t - ta or tb) meets 0, s_R, m, 1
        let mut br = vec![xa, xb];
        for tt in [t - ta, t - tb] {
            for s in [0.0, sr, m, 1.0] {
                for xi in [x - s * tt, x + s * tt] {
                    if xi > xa && xi < xb {
                        br.push(xi);
                    }
                }
            }
        }
        br.sort_by(|a, b| a.partial_cmp(b).unwrap());
        br.dedup();
        for shape in [TimeShape::Constant, TimeShape::Linear] {
            let got = hp.cell_response(&cell, shape, &x, &t).unwrap();
            for comp in 0..3 {
                let f = |xi: &f64| -> f64 {
                    let xx = x - xi;
                    if xx == 0.0 {
                        // a node on the load line (measure zero; the integrand is logarithmic there)
                        return 0.0;
                    }
                    let parity = if comp == 1 { xx.signum() } else { 1.0 };
                    let pick = |tr: lamb::Triple<lamb::Estimate<f64>>| match comp {
                        0 => tr.zz.value,
                        1 => tr.xz.value,
                        _ => tr.xx.value,
                    };
                    // a node that lands exactly on the Rayleigh ray (a set of measure zero) is
                    // moved by one ulp
                    let mom = |n: usize, s: f64| {
                        let s = if s == sr { s * (1.0 + f64::EPSILON) } else { s };
                        if s >= 1.0 {
                            0.0
                        } else {
                            pick(hp.moment(n, &s).unwrap())
                        }
                    };
                    let (sb, sa) = (xx.abs() / (t - tb), xx.abs() / (t - ta));
                    let w = (mom(1, sa) - mom(1, sb)) / pi;
                    let v = match shape {
                        TimeShape::Constant => w,
                        TimeShape::Linear => {
                            let tg = xx.abs() / pi * (mom(2, sa) - mom(2, sb));
                            ((t - ta) * w - tg) / (tb - ta)
                        }
                    };
                    parity * v
                };
                let mut want = 0.0;
                for win in br.windows(2) {
                    want += quad(&win[0], &win[1], 1e-14, f);
                }
                let e = [&got.zz, &got.xz, &got.xx][comp];
                let d = (e.value - want).abs();
                assert!(
                    d < 1e-11 * want.abs().max(1e-3),
                    "nu {nu} {shape:?} comp {comp}: {} vs {want} ({d:e})",
                    e.value
                );
            }
        }
    }
}

#[test]
fn causality_and_bad_cells() {
    let hp = HalfPlane::from_poisson(0.25).unwrap();
    let cell = Cell {
        xa: 0.0,
        xb: 1.0,
        ta: 1.0,
        tb: 2.0,
    };
    // before the load starts, and outside the P cone, nothing
    let u = hp
        .cell_response(&cell, TimeShape::Constant, &0.5, &0.9)
        .unwrap();
    assert_eq!(u.zz.value, 0.0);
    let u = hp
        .cell_response(&cell, TimeShape::Constant, &5.0, &2.5)
        .unwrap();
    assert!(u.zz.value.abs() < 1e-15 && u.xx.value.abs() < 1e-15);
    let bad = Cell {
        xa: 1.0,
        xb: 0.0,
        ta: 1.0,
        tb: 2.0,
    };
    let e = hp
        .cell_response(&bad, TimeShape::Constant, &0.5, &3.0)
        .unwrap_err();
    assert!(e.to_string().contains("xa < xb"), "{e}");
    let bad = Cell {
        xa: 0.0,
        xb: 1.0,
        ta: 2.0,
        tb: 2.0,
    };
    assert!(hp
        .cell_response(&bad, TimeShape::Linear, &0.5, &3.0)
        .is_err());
}
