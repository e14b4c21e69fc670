//! The half-space's axisymmetric response (`lamb::half_space`, `docs/half_space.md`) against
//! independent routes: the plane-strain impulse response projected by the Abel inversion
//! (section 2), the plane-wave identity, Boussinesq's static closed forms and an independent
//! mpmath implementation checked in the Laplace-Hankel domain
//! (`tests/reference/half_space_mpmath.py`).

use complexfn::quadrature::gauss_legendre_rule;
use complexfn::{Dd, Real};
use lamb::{Annulus, HalfPlane, HalfSpace};
use rug::Float;
use serde_json::Value;

use crate::common::{m_of, POISSON};

/// Int_l^r f by `pieces` Gauss-Legendre panels of 48 nodes after the map
/// u = l + (r - l)(1 - cos pi v)/2 (square-root ends become analytic).
fn cosine_gl(l: f64, r: f64, pieces: usize, f: impl Fn(f64) -> f64) -> f64 {
    let rule = gauss_legendre_rule::<f64>(48, 53).unwrap();
    let mut q = 0.0;
    for k in 0..pieces {
        let (v0, v1) = (k as f64 / pieces as f64, (k + 1) as f64 / pieces as f64);
        for (x, w) in rule.iter() {
            let v = v0 + (v1 - v0) * (x + 1.0) / 2.0;
            let u = l + (r - l) * (1.0 - (std::f64::consts::PI * v).cos()) / 2.0;
            let jac = (r - l) * std::f64::consts::PI * (std::f64::consts::PI * v).sin() / 2.0;
            q += w * (v1 - v0) / 2.0 * jac * f(u);
        }
    }
    q
}

/// V(s) by the second route: (1/pi) Int_s^1 g_zz(u) s/(u sqrt(u^2 - s^2)) du, the plane
/// strain impulse response through the Abel inversion (docs/half_space.md, eq (2.2)), for
/// s_R < s < 1 (no pole on the path); u = s cosh theta removes the end's inverse square root.
fn projected(hp: &HalfPlane<f64>, s: f64) -> f64 {
    let m = *hp.m();
    let g = |u: f64| hp.impulse(&u).unwrap().zz.value;
    let f = |th: f64| {
        let c = th.cosh();
        let u = (s * c).min(1.0);
        g(u) / c
    };
    let top = (1.0 / s).acosh();
    let q = if s < m {
        let mid = (m / s).acosh();
        cosine_gl(0.0, mid, 4, f) + cosine_gl(mid, top, 4, f)
    } else {
        cosine_gl(0.0, top, 4, f)
    };
    q / std::f64::consts::PI
}

/// The same for s < s_R: the principal value across the Rayleigh pole, its two sides paired
/// symmetrically (u = s_R +- e), so that the pole cancels node by node.
fn projected_behind_rayleigh(hp: &HalfPlane<f64>, s: f64) -> f64 {
    let sr = *hp.s_r();
    let m = *hp.m();
    let g = |u: f64| hp.impulse(&u).unwrap().zz.value;
    let phi = |u: f64| s / (u * (u * u - s * s).sqrt());
    let d = ((sr - s) / 2.0).min((m - sr) / 2.0);
    // [s, s_R - d] through u = s cosh theta
    let lower = cosine_gl(0.0, ((sr - d) / s).acosh(), 4, |th| {
        let c = th.cosh();
        g(s * c) / c
    });
    let paired = cosine_gl(0.0, d, 4, |e| {
        g(sr + e) * phi(sr + e) + g(sr - e) * phi(sr - e)
    });
    let upper =
        cosine_gl(sr + d, m, 4, |u| g(u) * phi(u)) + cosine_gl(m, 1.0, 4, |u| g(u) * phi(u));
    (lower + paired + upper) / std::f64::consts::PI
}

#[test]
fn point_response_is_the_projected_plane_impulse_response() {
    let mut worst: f64 = 0.0;
    for nu in POISSON {
        let m = m_of(&1.0f64, nu);
        let hp = HalfPlane::new(m).unwrap();
        let hs = HalfSpace::new(m).unwrap();
        let sr = *hs.s_r();
        let v0 = *hs.static_value();
        // behind the Rayleigh arrival: the principal value is Boussinesq's static value
        for k in 1..6 {
            let s = sr * k as f64 / 6.0;
            let want = projected_behind_rayleigh(&hp, s);
            let got = hs.point_step(&s).unwrap();
            assert!(
                (got - want).abs() < 1e-11,
                "nu {nu}, s {s}: {got} vs {want}"
            );
            assert_eq!(got, v0);
        }
        // between the Rayleigh and P arrivals
        for k in 1..40 {
            let s = sr + (1.0 - sr) * k as f64 / 40.0;
            if (s - m).abs() < 1e-3 {
                continue;
            }
            let want = projected(&hp, s);
            let got = hs.point_step(&s).unwrap();
            let d = (got - want).abs() / want.abs().max(v0);
            worst = worst.max(d);
            assert!(d < 1e-11, "nu {nu}, s {s}: {got} vs {want} ({d:e})");
        }
        assert_eq!(hs.point_step(&1.0).unwrap(), 0.0);
        assert!(hs.point_step(&sr).is_err());
        assert!(hs.point_step(&0.0).is_err());
    }
    eprintln!("point response against the projected plane response: {worst:e}");
}

#[test]
fn point_response_carries_the_plane_wave() {
    // A uniform pressure over the whole surface is a plane P wave: u = p c1 t/(rho c1^2)
    // = m^2 t (mu = c1 = 1). A point force's response integrated over the plane,
    // Int 2 pi rho u d rho = 2 t Int_0^1 V(s) ds, must equal it: Int_0^1 V = m^2/2.
    for nu in POISSON {
        let m = m_of(&1.0f64, nu);
        let hs = HalfSpace::new(m).unwrap();
        let sr = *hs.s_r();
        let v = |s: f64| hs.point_step(&s).unwrap();
        let q = sr * hs.static_value() + cosine_gl(sr, m, 8, v) + cosine_gl(m, 1.0, 8, v);
        assert!(
            (q - m * m / 2.0).abs() < 1e-12,
            "nu {nu}: Int V = {q}, m^2/2 = {}",
            m * m / 2.0
        );
        // the ring response inside a wide loaded disk is the plane wave while the edge's
        // waves have not arrived: U = m^2 t for t < (A - 1/2)
        let rec = Annulus::ring_cell(0, &1.0).unwrap();
        let src = Annulus::new(0.0, 40.0).unwrap();
        for t in [0.3, 2.0, 11.0, 39.0] {
            let u = hs.ring_step(&rec, &src, &t).unwrap();
            assert!(
                (u.value - m * m * t).abs() < 1e-12 * t,
                "nu {nu}, t {t}: {} vs {}",
                u.value,
                m * m * t
            );
            assert!(u.error < 1e-12 * t);
        }
    }
}

#[test]
fn ring_responses_reach_boussinesq() {
    for nu in POISSON {
        let m = m_of(&1.0f64, nu);
        let hs = HalfSpace::new(m).unwrap();
        let sr = *hs.s_r();
        // a disk on itself: Int Int dA dA'/|x - x'| = 16 pi a^3/3, so the mean is
        // (1 - nu) 8 a/(3 pi mu), a = 1/2
        let disk = Annulus::ring_cell(0, &1.0).unwrap();
        let u = hs.ring_static(&disk, &disk).unwrap();
        let want = (1.0 - nu) * 4.0 / (3.0 * std::f64::consts::PI);
        assert!(
            (u.value - want).abs() < 1e-14,
            "nu {nu}: {} vs {want}",
            u.value
        );
        // the centre of a loaded disk of radius a: (1 - nu) a, less (1 - nu) eps^2/(8 a)
        // over a receiving disk of radius eps (Boussinesq's E(r/a) expanded)
        let (a, eps) = (3.0, 1e-3);
        let centre = Annulus::new(0.0, eps).unwrap();
        let src = Annulus::new(0.0, a).unwrap();
        let u = hs.ring_static(&centre, &src).unwrap();
        let want = (1.0 - nu) * a - (1.0 - nu) * eps * eps / (8.0 * a);
        assert!(
            (u.value - want).abs() < 1e-12,
            "nu {nu}: {} vs {want}",
            u.value
        );
        // the step response is static once s_R t >= the two outer radii
        for (i, j) in [(0, 0), (3, 5), (10, 11)] {
            let r = Annulus::ring_cell(i, &1.0).unwrap();
            let s = Annulus::ring_cell(j, &1.0).unwrap();
            let t = (r.outer + s.outer) / sr;
            let stat = hs.ring_static(&r, &s).unwrap().value;
            for tt in [t, 1.5 * t] {
                let u = hs.ring_step(&r, &s, &tt).unwrap().value;
                assert!((u - stat).abs() < 1e-14 * stat.abs().max(1.0));
            }
            let p = hs.ring_pulse(&r, &s, &t, &(t + 1.0)).unwrap();
            assert!(p.value.abs() < 1e-15);
            let p = hs.ring_pulse(&r, &s, &(1.01 * t), &(t + 1.0)).unwrap();
            assert_eq!(p.value, 0.0);
            // reciprocity of the area-weighted form
            let u_rs = hs.ring_step(&r, &s, &(0.7 * t)).unwrap().value * r.area();
            let u_sr = hs.ring_step(&s, &r, &(0.7 * t)).unwrap().value * s.area();
            assert!((u_rs - u_sr).abs() < 1e-12 * u_rs.abs().max(1.0));
        }
    }
}

#[test]
fn ring_pulse_is_the_difference_of_steps() {
    let hs = HalfSpace::new(m_of(&1.0f64, 0.3)).unwrap();
    for (i, j) in [(0, 0), (0, 1), (4, 2), (7, 7)] {
        let r = Annulus::ring_cell(i, &1.0).unwrap();
        let s = Annulus::ring_cell(j, &1.0).unwrap();
        for (t0, t1) in [(0.5, 1.0), (2.0, 2.5), (6.0, 8.0)] {
            let p = hs.ring_pulse(&r, &s, &t0, &t1).unwrap();
            let d =
                hs.ring_step(&r, &s, &t1).unwrap().value - hs.ring_step(&r, &s, &t0).unwrap().value;
            assert!(
                (p.value - d).abs() < 1e-13,
                "({i},{j}) {t0}..{t1}: {} vs {d}",
                p.value
            );
        }
    }
}

#[test]
fn bad_input_is_refused_with_the_parameter_named() {
    let hs = HalfSpace::new(m_of(&1.0f64, 0.25)).unwrap();
    let disk = Annulus::ring_cell(0, &1.0).unwrap();
    let e = hs.ring_step(&disk, &disk, &-1.0).unwrap_err().to_string();
    assert!(e.contains("c1 t"), "{e}");
    let e = hs
        .ring_pulse(&disk, &disk, &2.0, &1.0)
        .unwrap_err()
        .to_string();
    assert!(e.contains("c1 t1"), "{e}");
    let e = Annulus::new(1.0, 0.5).unwrap_err().to_string();
    assert!(e.contains("outer radius"), "{e}");
    let e = Annulus::new(-1.0, 0.5).unwrap_err().to_string();
    assert!(e.contains("inner radius"), "{e}");
    let e = HalfSpace::from_poisson(0.5f64).unwrap_err().to_string();
    assert!(e.contains("Poisson"), "{e}");
    let e = hs.point_step(&f64::NAN).unwrap_err().to_string();
    assert!(e.contains("s = rho/(c1 t)"), "{e}");
}

fn parse(v: &Value) -> Option<Float> {
    let v = if v.is_object() { &v["value"] } else { v };
    let s = v.as_str()?;
    Float::parse(s.trim()).ok().map(|p| Float::with_val(200, p))
}

#[test]
fn agrees_with_the_independent_mpmath_values() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/reference/half_space_reference.json"
    );
    let text = std::fs::read_to_string(path).expect("reference file");
    let v: Value = serde_json::from_str(&text).unwrap();
    let cases = v["cases"].as_array().unwrap();
    let (mut worst64, mut worst_dd, mut count) = (0.0f64, 0.0f64, 0);
    for case in cases {
        let m = parse(&case["m"]).unwrap();
        let hs = HalfSpace::new(m.to_f64()).unwrap();
        // double-double: the same formulas at 106 bits against the reference's digits
        let hs_dd = HalfSpace::new(Dd::from_mpfr(&m, 106)).unwrap();
        let dd_err = |got: &Dd, want: &Float| -> f64 {
            let d = Float::with_val(200, got.to_mpfr(200) - want).abs().to_f64();
            d / want.to_f64().abs().max(1e-3)
        };
        let nu = case["nu"].as_str().unwrap_or("?").to_string();
        for p in case["V"].as_array().unwrap() {
            let s_hp = parse(&p["s"]).unwrap();
            let want_hp = parse(p).unwrap();
            let got_dd = hs_dd.point_step(&Dd::from_mpfr(&s_hp, 106)).unwrap();
            worst_dd = worst_dd.max(dd_err(&got_dd, &want_hp));
            let s = s_hp.to_f64();
            let want = want_hp.to_f64();
            let got = hs.point_step(&s).unwrap();
            let d = (got - want).abs() / want.abs().max(0.1);
            worst64 = worst64.max(d);
            assert!(d < 1e-13, "nu {nu}: V({s}) = {got} vs {want} ({d:e})");
            count += 1;
        }
        for p in case["U"].as_array().unwrap() {
            let i = p["i"].as_u64().unwrap() as usize;
            let j = p["j"].as_u64().unwrap() as usize;
            let r = Annulus::ring_cell(i, &1.0).unwrap();
            let s = Annulus::ring_cell(j, &1.0).unwrap();
            let want_hp = parse(p).unwrap();
            let want = want_hp.to_f64();
            let t = p["T"].as_str().unwrap();
            // double-double on the small rings (its quadratures cost more)
            if i + j <= 2 && (t == "inf" || t == "1") {
                let (r2, s2) = (
                    Annulus::ring_cell(i, &Dd::from_f64_prec(1.0, 106)).unwrap(),
                    Annulus::ring_cell(j, &Dd::from_f64_prec(1.0, 106)).unwrap(),
                );
                let got_dd = if t == "inf" {
                    hs_dd.ring_static(&r2, &s2).unwrap()
                } else {
                    hs_dd
                        .ring_step(&r2, &s2, &Dd::from_f64_prec(1.0, 106))
                        .unwrap()
                };
                worst_dd = worst_dd.max(dd_err(&got_dd.value, &want_hp));
            }
            let got = if t == "inf" {
                hs.ring_static(&r, &s).unwrap()
            } else {
                let t: f64 = t.parse().unwrap();
                hs.ring_step(&r, &s, &t).unwrap()
            };
            let d = (got.value - want).abs() / want.abs().max(1e-3);
            worst64 = worst64.max(d);
            assert!(
                d < 1e-10,
                "nu {nu}: U_{i}{j}(T = {t}) = {} vs {want} ({d:e})",
                got.value
            );
            assert!(
                (got.value - want).abs() <= got.error.max(1e-15 * want.abs().max(1.0)) * 10.0,
                "nu {nu}: U_{i}{j}(T = {t}) error {} against the actual {}",
                got.error,
                (got.value - want).abs()
            );
            count += 1;
        }
    }
    assert!(count > 100, "only {count} values compared");
    eprintln!("half-space against mpmath: {count} values, worst f64 {worst64:e}, double-double {worst_dd:e}");
    // V to 1e-27; the ring means near the P front's nearby singularity (nu = 0.1, -0.3) to
    // 5e-26 (docs/half_space.md, section 4)
    assert!(worst_dd < 1e-25, "double-double {worst_dd:e}");
}
