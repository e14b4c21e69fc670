//! The closed forms of the Lamb crate against independent quantities: the transform-domain
//! solution by a numerical 2x2 traction solve (pointwise, every region), limits (Flamant, the
//! plane-wave momentum, Flamant's tangential displacement, Rayleigh-wave ellipticity),
//! derivatives of the raw Rayleigh function, and plain quadrature of g for every moment.

use crate::common;

use common::*;
use complexfn::Real;
use lamb::{HalfPlane, LambError};
use rug::Float;

/// Points of every region for the half-plane `hp`: behind R, between R and S, between S and
/// P, ahead of P, and next to each front.
fn region_points(hp: &HalfPlane<f64>) -> Vec<f64> {
    let (m, sr) = (*hp.m(), *hp.s_r());
    vec![
        0.05,
        0.2,
        0.5 * sr,
        sr - 1e-3,
        sr + 1e-3,
        0.5 * (sr + m),
        m - 1e-9,
        m + 1e-9,
        0.5 * (m + 1.0),
        1.0 - 1e-9,
        1.0,
        1.3,
    ]
}

#[test]
fn impulse_responses_equal_the_jump_of_the_transform_solution_in_f64() {
    for nu in POISSON {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        // the same material (the f64 m, exactly) at 256 bits
        let m_hi = fl(256, *hp.m());
        for s in region_points(&hp) {
            let g = hp.impulse(&s).unwrap();
            let want = jump_route(&m_hi, &fl(256, s));
            let got = [g.zz.value, g.xz.value, g.xx.value];
            // reciprocity of the independent route: u_z due to F_x is -u_x due to F_z
            let recip = (want[3].clone() + &want[1]).abs().to_f64();
            assert!(recip < 1e-60, "nu {nu} s {s}: reciprocity {recip:e}");
            for (k, (a, b)) in got.iter().zip(&want[..3]).enumerate() {
                let b = b.to_f64();
                let scale = b.abs().max(1e-3);
                let e = (a - b).abs() / scale;
                let stated = [&g.zz, &g.xz, &g.xx][k].error;
                assert!(
                    (a - b).abs() <= stated,
                    "nu {nu} s {s} comp {k}: stated {stated:e}"
                );
                if (s - hp.s_r()).abs() > 1e-2 {
                    assert!(e < 1e-13, "nu {nu} s {s} comp {k}: {a:e} vs {b:e} ({e:e})");
                }
            }
        }
    }
}

#[test]
fn impulse_responses_equal_the_jump_of_the_transform_solution_at_200_bits() {
    for nu in POISSON {
        let hp = HalfPlane::new(m_of(&fl(200, 0.0), nu)).unwrap();
        let hp64 = HalfPlane::from_poisson(nu).unwrap();
        let m_hi = m_of(&fl(330, 0.0), nu);
        for s in region_points(&hp64) {
            let s_hp = fl(200, s);
            let g = hp.impulse(&s_hp).unwrap();
            let want = jump_route(&m_hi, &fl(330, s));
            let got = [g.zz.value, g.xz.value, g.xx.value];
            for (k, (a, b)) in got.iter().zip(&want[..3]).enumerate() {
                let d = Float::with_val(330, a - b).abs().to_f64();
                let scale = b.to_f64().abs().max(1e-3);
                assert!(d / scale < 1e-50, "nu {nu} s {s} comp {k}: {:e}", d / scale);
            }
        }
    }
}

#[test]
fn flamant_limits_and_plane_wave_momentum() {
    for nu in POISSON {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        let m = *hp.m();
        let g = hp.impulse(&1e-9).unwrap();
        assert!((g.zz.value - (1.0 - nu)).abs() < 1e-14, "nu {nu}");
        assert!((g.xx.value - (1.0 - nu)).abs() < 1e-14, "nu {nu}");
        // Int_0^1 g_zz ds = pi m^2/2, Int_0^1 g_xx ds = pi m/2 (principal values)
        let total = hp.moment(0, &0.0).unwrap();
        let pi = std::f64::consts::PI;
        assert!(
            (total.zz.value - pi * m * m / 2.0).abs() < 1e-13,
            "nu {nu}: {}",
            total.zz.value
        );
        assert!(
            (total.xx.value - pi * m / 2.0).abs() < 1e-13,
            "nu {nu}: {}",
            total.xx.value
        );
        // Flamant's tangential displacement behind the Rayleigh front: -(1 - 2 nu) P/(4 mu)
        for s in [0.9 * hp.s_r(), 0.5 * hp.s_r(), 1e-6] {
            let u = hp.step(&s).unwrap().xz.value;
            assert!(
                (u + pi * (1.0 - 2.0 * nu) / 4.0).abs() < 1e-14,
                "nu {nu} s {s}: {u}"
            );
        }
        // slopes: W_zz(s1) - W_zz(s2) -> (1 - nu) ln(s2/s1) as s -> 0 (Flamant)
        let (s1, s2) = (1e-7, 2e-7);
        let d = hp.step(&s1).unwrap().zz.value - hp.step(&s2).unwrap().zz.value;
        assert!((d - (1.0 - nu) * 2f64.ln()).abs() < 1e-12, "nu {nu}: {d}");
        let d = hp.step(&s1).unwrap().xx.value - hp.step(&s2).unwrap().xx.value;
        assert!((d - (1.0 - nu) * 2f64.ln()).abs() < 1e-12, "nu {nu}: {d}");
    }
}

#[test]
fn flamant_tangential_displacement_at_200_bits() {
    for nu in POISSON {
        let like = fl(200, 0.0);
        let hp = HalfPlane::new(m_of(&like, nu)).unwrap();
        let nu_hp = hp.poisson();
        let u = hp.step(&fl(200, 0.25)).unwrap().xz.value;
        let one_m2nu: Float = like.one() - nu_hp * 2.0;
        let want: Float = -(Real::pi(&like) * one_m2nu) / 4.0;
        let e = Float::with_val(200, &u - &want).abs().to_f64();
        assert!(e < 1e-55, "nu {nu}: {e:e}");
    }
}

#[test]
fn square_root_onset_at_the_p_front_and_continuity_at_s() {
    for nu in POISSON {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        let m = *hp.m();
        // g ~ C sqrt(1 - s): the ratio converges, no jump
        let r = |d: f64| {
            let g = hp.impulse(&(1.0 - d)).unwrap();
            [
                g.zz.value / d.sqrt(),
                g.xz.value / d.sqrt(),
                g.xx.value / d.sqrt(),
            ]
        };
        let (a, b) = (r(1e-8), r(1e-10));
        for k in 0..3 {
            assert!(
                (a[k] - b[k]).abs() < 1e-3 * a[k].abs().max(1e-12),
                "nu {nu} comp {k}"
            );
        }
        // continuity at the S arrival (square-root kink)
        let lo = hp.impulse(&(m * (1.0 - 1e-12))).unwrap();
        let hi = hp.impulse(&(m * (1.0 + 1e-12))).unwrap();
        assert!((lo.zz.value - hi.zz.value).abs() < 1e-5);
        assert!((lo.xx.value - hi.xx.value).abs() < 1e-5);
        assert!((lo.xz.value - hi.xz.value).abs() < 1e-5);
    }
}

#[test]
fn rayleigh_constants_against_the_raw_rayleigh_function() {
    for nu in POISSON {
        let bits = 400;
        let like = fl(bits, 0.0);
        let m = m_of(&like, nu);
        let hp = HalfPlane::new(m.clone()).unwrap();
        let c = hp.rayleigh_constants();
        let sr = c.s_r.clone();
        // the root itself
        assert!(raw_rayleigh(&m, &sr).abs().to_f64() < 1e-85, "nu {nu}");
        // D'(s_R) by a central difference with step 1e-35 (truncation ~ 1e-70, rounding ~ 1e-85)
        let h = like.lit(1e-35);
        let dd: Float = (raw_rayleigh(&m, &(sr.clone() + &h))
            - raw_rayleigh(&m, &(sr.clone() - &h)))
            / (h * 2.0);
        let one = like.one();
        let v = (one.clone() - sr.clone().sqr()).sqrt();
        let x = sr.clone().sqr() / m.clone().sqr();
        let w = (one.clone() - &x).sqrt();
        let k = one.lit(2.0) - &x;
        // g_zz = -s^2 v/(m^2 D(s)), g_xx = -s^2 w/(m^2 D(s)) behind S
        let r_zz: Float = -(sr.clone().sqr() * &v / (m.clone().sqr() * &dd));
        let r_xx: Float = -(sr.clone().sqr() * &w / (m.clone().sqr() * &dd));
        // the cross transform s (2 v w - K)/D has residue -(2 v w - K)/(s_R D') in 1/s
        let k_r: Float = (v.clone() * &w * 2.0 - &k) / (sr.clone() * &dd);
        for (name, got, want) in [
            ("r_zz", &c.r_zz, &r_zz),
            ("r_xx", &c.r_xx, &r_xx),
            ("K_R", &c.k_r, &k_r),
        ] {
            let e = Float::with_val(bits, got - want).abs().to_f64() / want.to_f64().abs();
            assert!(e < 1e-65, "nu {nu} {name}: {e:e}");
        }
        // classical Rayleigh-wave ellipticity |u_x/u_z| = 2 sqrt(1 - c_R^2/c2^2)/(2 - c_R^2/c2^2)
        let ell = (c.k_r.clone() * &sr / &c.r_zz).abs();
        let classical = w * 2.0 / k;
        let e = Float::with_val(bits, &ell - &classical).abs().to_f64();
        assert!(e < 1e-65, "nu {nu}: ellipticity {e:e}");
        // nu = 1/4 only: K_R = -(1 - 2 nu)/4 by coincidence
        if nu == 0.25 {
            assert!((c.k_r.to_f64() + 0.125).abs() < 1e-15);
        } else {
            assert!((c.k_r.to_f64() + (1.0 - 2.0 * nu) / 4.0).abs() > 1e-4);
        }
    }
}

/// Cells [sa, sb] of s for the moment checks: at the origin, across and next to the Rayleigh
/// arrival, between the fronts, across the P front, and `last`.
fn moment_cells(hp: &HalfPlane<f64>, last: (f64, f64)) -> [(f64, f64); 8] {
    let (m, sr) = (*hp.m(), *hp.s_r());
    [
        (0.0, 0.2),
        (0.02, sr - 0.01),
        (0.1, 0.95),
        (sr + 1e-3, m),
        (m, 1.0),
        (0.5 * (m + 1.0), 1.2),
        (sr - 1e-3, sr + 2e-3),
        last,
    ]
}

#[test]
fn moments_equal_quadrature_of_the_impulse_responses() {
    for nu in POISSON {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        let (m, sr) = (*hp.m(), *hp.s_r());
        for (sa, sb) in moment_cells(&hp, (0.3 * sr, 0.5 * (sr + m))) {
            for n in 0..3usize {
                if n > 0 && sa == 0.0 {
                    continue;
                }
                let got = hp.cell(n, &sa, &sb).unwrap();
                for (comp, e) in [(0, &got.zz), (1, &got.xz), (2, &got.xx)] {
                    let want = moment_by_quadrature(&hp, comp, n as i32, &sa, &sb, 1e-15);
                    let d = (e.value - want).abs();
                    let tol = 2e-13 * want.abs().max(1.0);
                    assert!(
                        d < tol,
                        "nu {nu} [{sa}, {sb}] n {n} comp {comp}: {} vs {want} ({d:e})",
                        e.value
                    );
                    assert!(
                        e.error < 1e-11 * want.abs().max(1.0),
                        "nu {nu} n {n} comp {comp}: err {:e}",
                        e.error
                    );
                }
            }
        }
    }
}

#[test]
fn moments_at_200_bits_equal_quadrature() {
    let bits = 200;
    for nu in [0.25, 0.45, 0.1] {
        let like = fl(bits, 0.0);
        let hp = HalfPlane::new(m_of(&like, nu)).unwrap();
        let (m, sr) = (hp.m().clone(), hp.s_r().clone());
        let cells = [
            (like.lit(0.05), sr.clone() - 0.01),
            (like.lit(0.1), like.lit(0.95)),
            (m.clone(), like.one()),
        ];
        for (sa, sb) in cells {
            for n in 0..3usize {
                let got = hp.cell(n, &sa, &sb).unwrap();
                for (comp, e) in [(0, &got.zz), (1, &got.xz), (2, &got.xx)] {
                    let want = moment_by_quadrature(&hp, comp, n as i32, &sa, &sb, 1e-50);
                    let d = Float::with_val(bits, &e.value - &want).abs().to_f64();
                    assert!(d < 1e-45, "nu {nu} n {n} comp {comp}: {d:e}");
                    assert!(
                        e.error < 1e-45,
                        "nu {nu} n {n} comp {comp}: err {:e}",
                        e.error
                    );
                }
            }
        }
        let _ = m;
    }
}

#[test]
fn error_estimates_cover_the_f64_error() {
    for nu in POISSON {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        let hp_hi = HalfPlane::new(fl(160, *hp.m())).unwrap();
        let sr = *hp.s_r();
        for s in [
            1e-8,
            1e-3,
            0.1,
            0.5 * sr,
            sr * (1.0 - 1e-9),
            sr * (1.0 + 1e-9),
            0.6,
            0.7,
            0.8,
            0.99,
            1.0 - 1e-12,
        ] {
            if s >= 1.0 {
                continue;
            }
            for n in 0..3usize {
                let a = hp.moment(n, &s).unwrap();
                let b = hp_hi.moment(n, &fl(160, s)).unwrap();
                for (x, y) in [(&a.zz, &b.zz), (&a.xz, &b.xz), (&a.xx, &b.xx)] {
                    let actual = (x.value - y.value.to_f64()).abs();
                    assert!(
                        actual <= x.error.max(1e-300),
                        "nu {nu} s {s} n {n} value {}: actual {actual:e} > stated {:e}",
                        x.value,
                        x.error
                    );
                }
            }
        }
    }
}

#[test]
fn bad_input_is_refused_with_the_parameter_named() {
    assert!(matches!(
        HalfPlane::from_poisson(0.5),
        Err(LambError::InvalidParameter { .. })
    ));
    assert!(matches!(
        HalfPlane::from_poisson(-1.0),
        Err(LambError::InvalidParameter { .. })
    ));
    assert!(HalfPlane::from_poisson(f64::NAN).is_err());
    let hp = HalfPlane::from_poisson(0.3).unwrap();
    let sr = *hp.s_r();
    assert!(matches!(
        hp.impulse(&-0.1),
        Err(LambError::InvalidParameter(complexfn::InvalidParameter {
            name: "s",
            ..
        }))
    ));
    assert!(matches!(
        hp.impulse(&sr),
        Err(LambError::AtRayleighArrival { .. })
    ));
    assert!(matches!(
        hp.step(&sr),
        Err(LambError::AtRayleighArrival { .. })
    ));
    assert!(hp.step(&0.0).is_err());
    assert!(matches!(
        hp.cell(0, &0.5, &0.4),
        Err(LambError::InvalidParameter { .. })
    ));
    let msg = hp.cell(0, &0.5, &0.4).unwrap_err().to_string();
    assert!(msg.contains("sa <= sb"), "{msg}");
}

#[test]
fn no_non_finite_value_leaves_the_library() {
    // points within an ulp of the Rayleigh arrival, the fronts, and a pseudo-random sweep
    let mut seed = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for nu in POISSON {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        let (m, sr) = (*hp.m(), *hp.s_r());
        let mut pts = vec![
            sr * (1.0 + f64::EPSILON),
            sr * (1.0 - f64::EPSILON / 2.0),
            m * (1.0 + f64::EPSILON),
            m * (1.0 - f64::EPSILON / 2.0),
            1.0 - f64::EPSILON / 2.0,
            1e-300,
            f64::MIN_POSITIVE,
        ];
        pts.extend((0..400).map(|_| 1.2 * next()));
        for s in pts {
            let ok = |t: lamb::Triple<lamb::Estimate<f64>>| {
                for e in [t.zz, t.xz, t.xx] {
                    assert!(
                        e.value.is_finite() && e.error.is_finite(),
                        "nu {nu} s {s:e}"
                    );
                }
            };
            if let Ok(t) = hp.impulse(&s) {
                ok(t);
            }
            for n in 0..3 {
                if let Ok(t) = hp.moment(n, &s) {
                    ok(t);
                }
            }
        }
    }
}

/// The first moment of g_zz (order n = -1, behind the cell means of the space-time cells)
/// against plain quadrature of s g_zz(s) (principal value by symmetric pairing), in f64 for
/// five materials and at 200 bits for three.
#[test]
fn first_moment_equals_quadrature_of_the_impulse_response() {
    let m1 = |hp: &HalfPlane<f64>, s: f64| hp.first_moment_zz(&s).unwrap();
    for nu in POISSON {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        let sr = *hp.s_r();
        for (sa, sb) in moment_cells(&hp, (0.0, 1.0)) {
            let (a, b) = (m1(&hp, sa), m1(&hp, sb));
            let got = a.value - b.value;
            let want = moment_by_quadrature(&hp, 0, -1, &sa, &sb, 1e-15);
            let d = (got - want).abs();
            assert!(
                d < 2e-13 * want.abs().max(1.0),
                "nu {nu} [{sa}, {sb}]: {got} vs {want} ({d:e})"
            );
            assert!(
                a.error + b.error < 1e-11,
                "nu {nu}: err {:e}",
                a.error + b.error
            );
        }
        assert_eq!(m1(&hp, 1.5).value, 0.0);
        assert!(hp.first_moment_zz(&sr).is_err());
        assert!(hp.first_moment_zz(&-0.1).is_err());
    }
    let bits = 200;
    for nu in [0.25, 0.45, 0.1] {
        let like = fl(bits, 0.0);
        let hp = HalfPlane::new(m_of(&like, nu)).unwrap();
        let sr = hp.s_r().clone();
        for (sa, sb) in [
            (like.zero(), sr.clone() - 0.01),
            (like.lit(0.1), like.lit(0.95)),
            (hp.m().clone(), like.one()),
        ] {
            let a = hp.first_moment_zz(&sa).unwrap();
            let b = hp.first_moment_zz(&sb).unwrap();
            let want = moment_by_quadrature(&hp, 0, -1, &sa, &sb, 1e-50);
            let d = (Float::with_val(bits, &a.value - &b.value) - &want)
                .abs()
                .to_f64();
            assert!(d < 1e-45, "nu {nu}: {d:e}");
            assert!(
                a.error + b.error < 1e-45,
                "nu {nu}: err {:e}",
                a.error + b.error
            );
        }
    }
}

/// The cell-mean primitive Xi(X, T) = Int_0^X Phi dX': its X-derivative is Phi (a centred
/// difference), it is even in X, zero at X = 0 and for T <= 0, and a corner on the Rayleigh
/// ray gives a finite value continuous with its neighbours.
#[test]
fn cell_mean_primitive_is_the_space_integral_of_phi() {
    for nu in POISSON {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        let sr = *hp.s_r();
        let xi = |x: f64, t: f64| hp.cell_mean_primitive_zz(&x, &t).unwrap();
        for (x, t) in [
            (0.3, 1.0),
            (0.8, 1.0),
            (1.7, 1.0),
            (2.0, 30.0),
            (sr * 2.0 + 0.1, 2.0),
        ] {
            let h = 1e-4;
            let d = (xi(x + h, t).value - xi(x - h, t).value) / (2.0 * h);
            let phi = hp.space_time_primitive(1, &x, &t).unwrap().zz.value;
            assert!(
                (d - phi).abs() < 1e-7 * phi.abs().max(1.0),
                "nu {nu} ({x}, {t}): dXi/dX {d}, Phi {phi}"
            );
            assert_eq!(xi(-x, t).value, xi(x, t).value);
        }
        assert_eq!(xi(0.0, 1.0).value, 0.0);
        assert_eq!(xi(0.5, 0.0).value, 0.0);
        assert_eq!(xi(0.5, -1.0).value, 0.0);
        // on the Rayleigh ray
        let on = xi(sr, 1.0);
        let near = xi(sr * (1.0 + 1e-9), 1.0);
        assert!(on.value.is_finite() && on.error < 1e-12);
        assert!(
            (on.value - near.value).abs() < 1e-8,
            "{} vs {}",
            on.value,
            near.value
        );
        assert!(hp.cell_mean_primitive_zz(&f64::NAN, &1.0).is_err());
    }
}

/// Behind s_R/2 the cell-mean primitive comes from the Taylor series of g_zz; it must equal
/// the combination of moments xi = (s^2/2) M_1 + s [M_0(0) - M_0(s)] - [M_-1(0) - M_-1(s)]/2
/// formed at 200 bits (where their cancellation costs nothing), in f64 and at 200 bits, on
/// both sides of the switch at s_R/2.
#[test]
fn cell_mean_series_equals_the_moments_at_200_bits() {
    let bits = 200;
    for nu in POISSON {
        let like = fl(bits, 0.0);
        let hp = HalfPlane::new(m_of(&like, nu)).unwrap();
        let hp64 = HalfPlane::from_poisson(nu).unwrap();
        let sr = hp.s_r().to_f64();
        let xi_moments = |s: &Float| -> Float {
            let total0 = hp.moment(0, &like.zero()).unwrap().zz.value;
            let total1 = hp.first_moment_zz(&like.zero()).unwrap().value;
            let m1 = hp.moment(1, s).unwrap().zz.value;
            let m0 = hp.moment(0, s).unwrap().zz.value;
            let mm = hp.first_moment_zz(s).unwrap().value;
            let s2 = Float::with_val(bits, s * s);
            let a = Float::with_val(bits, &s2 * &m1) / 2u32;
            let b = Float::with_val(bits, s * Float::with_val(bits, &total0 - &m0));
            let c = Float::with_val(bits, &total1 - &mm) / 2u32;
            a + b - c
        };
        for s in [
            1e-4,
            1e-3,
            0.01,
            0.05,
            0.5 * sr * 0.999,
            0.5 * sr * 1.001,
            0.8 * sr,
        ] {
            let sf = fl(bits, s);
            // Xi(s, 1) = xi(s)/pi
            let want = xi_moments(&sf) / Float::with_val(bits, rug::float::Constant::Pi);
            let got = hp.cell_mean_primitive_zz(&sf, &like.one()).unwrap();
            let d = (Float::with_val(bits, &got.value - &want)).abs().to_f64();
            let w = want.to_f64().abs();
            assert!(d < 1e-50 * w, "nu {nu}, s {s}: 200 bits off by {:e}", d / w);
            assert!(
                got.error < 1e-50 * w && got.error >= 0.0,
                "nu {nu}, s {s}: err {:e}",
                got.error
            );
            let g64 = hp64.cell_mean_primitive_zz(&s, &1.0).unwrap();
            let d64 = (g64.value - want.to_f64()).abs();
            assert!(
                d64 <= g64.error,
                "nu {nu}, s {s}: f64 off by {d64:e}, stated {:e}",
                g64.error
            );
            let tol = if s < 0.5 * sr { 1e-13 } else { 1e-12 };
            assert!(
                g64.error < tol * w,
                "nu {nu}, s {s}: f64 stated {:e}",
                g64.error / w
            );
        }
    }
}
