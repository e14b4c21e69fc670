//! The edge exponents against closed forms derived independently of the transform kernels
//! (`docs/edge.md`), Freund's intersonic crack exponent, the static limit and the refusals.
use lamb::edge::{EdgeLaw, SpeedRange};
use lamb::HalfPlane;

const PI: f64 = std::f64::consts::PI;

/// Closed forms of the steady moving-punch relation (c1 = 1, mu = 1, m = c2/c1): the
/// expected (low, high) exponents and the expected slope symbol's phase class.
fn closed_form(m: f64, d: f64) -> Vec<f64> {
    let a1 = (1.0 - d * d).abs().sqrt();
    let q = d * d / (m * m);
    if d < m {
        vec![-0.5, 0.5]
    } else if d < 1.0 {
        let a = (2.0 - q).powi(2);
        let b = 4.0 * a1 * (q - 1.0).sqrt();
        let theta = (a / b).atan();
        vec![-theta / PI, 1.0 - theta / PI]
    } else {
        vec![0.0]
    }
}

/// The Rayleigh function R(D) = (2 - D^2/c2^2)^2 - 4 sqrt(1 - D^2) sqrt(1 - D^2/c2^2).
fn rayleigh(m: f64, d: f64) -> f64 {
    let q = d * d / (m * m);
    (2.0 - q).powi(2) - 4.0 * (1.0 - d * d).sqrt() * (1.0 - q).sqrt()
}

#[test]
fn exponents_agree_with_the_closed_forms_in_every_range() {
    for nu in [0.1, 0.25, 0.3, 0.45] {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        let (m, sr) = (*hp.m(), *hp.s_r());
        let mut speeds: Vec<f64> = (1..40).map(|i| i as f64 * 0.035).collect();
        speeds.extend([0.5 * sr, 0.999 * sr, 1.001 * sr, 0.999 * m, 1.001 * m, 1.2]);
        for d in speeds {
            if [sr, m, 1.0].iter().any(|c| (d - c).abs() < 1e-6) {
                continue;
            }
            let e = hp.edge_behaviour(d, EdgeLaw::Signorini).unwrap();
            let got: Vec<f64> = e.solutions.iter().map(|s| s.lambda).collect();
            let want = closed_form(m, d);
            assert_eq!(got.len(), want.len(), "nu {nu}, D {d}");
            for (g, w) in got.iter().zip(&want) {
                assert!((g - w).abs() < 1e-12, "nu {nu}, D {d}: {got:?} vs {want:?}");
            }
            // below c2 the symbol is i times a real multiple whose sign is that of -R(D)
            if d < m {
                let (re, im) = e.slope_symbol;
                assert!(re.abs() < 1e-12 * im.abs());
                let k = (1.0 - d * d).sqrt() * d * d / (m * m * rayleigh(m, d));
                assert!(
                    (im + k).abs() < 1e-9 * k.abs(),
                    "nu {nu}, D {d}: {im} vs {}",
                    -k
                );
            }
            let range = if d < sr {
                SpeedRange::SubRayleigh
            } else if d < m {
                SpeedRange::RayleighShear
            } else if d < 1.0 {
                SpeedRange::Transonic
            } else {
                SpeedRange::Supersonic
            };
            assert_eq!(e.range, range);
        }
    }
}

#[test]
fn selection_by_law_and_range() {
    let hp = HalfPlane::from_poisson(0.25).unwrap();
    let (m, sr) = (*hp.m(), *hp.s_r());
    let sel = |d: f64, law| hp.edge_behaviour(d, law).unwrap().selected;
    // free edge: smooth below c_R, square-root singular between c_R and c2
    assert_eq!(sel(0.5 * sr, EdgeLaw::Signorini), 0.5);
    assert_eq!(sel(0.5 * (sr + m), EdgeLaw::Signorini), -0.5);
    // prescribed edge: the singular solution below c2
    assert_eq!(sel(0.5 * sr, EdgeLaw::Kinematic), -0.5);
    assert_eq!(sel(0.5 * (sr + m), EdgeLaw::Kinematic), -0.5);
    // transonic: both laws take the weaker singularity -theta/pi in (-1/2, 0)
    for d in [1.05 * m, 0.5 * (m + 1.0), 0.98] {
        let s = sel(d, EdgeLaw::Signorini);
        let k = sel(d, EdgeLaw::Kinematic);
        assert!(s > -0.5 && s <= 0.0 && s == k, "D {d}: {s} {k}");
    }
    // supersonic: a finite jump for both, p(b) = f'(b)/|S+|
    let e = hp.edge_behaviour(1.5, EdgeLaw::Signorini).unwrap();
    assert_eq!(e.selected, 0.0);
    assert!(e.jump_per_slope.unwrap() > 0.0);
    // one and only one free-edge solution wherever two exist
    for i in 1..60 {
        let d = i as f64 * 0.02;
        if let Ok(e) = hp.edge_behaviour(d, EdgeLaw::Signorini) {
            let n = e
                .solutions
                .iter()
                .filter(|s| s.signorini_admissible)
                .count();
            assert_eq!(n, 1, "D {d}");
        }
    }
}

/// Freund's exponent of the mode-II crack running between c2 and c1,
/// q = (1/pi) atan(4 a1 b2 / (1 - b2^2)^2) with a1 = sqrt(1 - D^2/c1^2),
/// b2 = sqrt(D^2/c2^2 - 1): the contact's singular exponent is q - 1/2 (the dual problem).
#[test]
fn transonic_exponent_is_freunds_crack_exponent_less_one_half() {
    for nu in [0.15, 0.3, 0.4] {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        let m = *hp.m();
        for i in 1..20 {
            let d = m + (1.0 - m) * i as f64 / 20.0;
            let a1 = (1.0 - d * d).sqrt();
            let b2 = (d * d / (m * m) - 1.0).sqrt();
            let q = (4.0 * a1 * b2 / (1.0 - b2 * b2).powi(2)).atan() / PI;
            let e = hp.edge_behaviour(d, EdgeLaw::Kinematic).unwrap();
            assert!((e.selected - (q - 0.5)).abs() < 1e-12, "nu {nu}, D {d}");
        }
        // no singularity at D = sqrt(2) c2, where 1 - b2^2 = 0
        let e = hp
            .edge_behaviour(2f64.sqrt() * m, EdgeLaw::Signorini)
            .unwrap();
        assert!(e.selected.abs() < 1e-7, "{}", e.selected);
    }
}

/// Continuity of the exponents at c2 (from the transonic side towards -1/2), the documented
/// jumps at c_R (the free edge's choice) and at c1 (-1/2 to 0).
#[test]
fn behaviour_at_the_range_boundaries() {
    let hp = HalfPlane::from_poisson(0.3).unwrap();
    let (m, sr) = (*hp.m(), *hp.s_r());
    let k = |d: f64| hp.edge_behaviour(d, EdgeLaw::Kinematic).unwrap().selected;
    let s = |d: f64| hp.edge_behaviour(d, EdgeLaw::Signorini).unwrap().selected;
    assert!((k(m * (1.0 + 1e-8)) + 0.5).abs() < 1e-3);
    assert!((k(1.0 - 1e-8) + 0.5).abs() < 1e-3);
    assert_eq!(k(1.0 + 1e-6), 0.0);
    assert_eq!(s(sr * (1.0 - 1e-6)), 0.5);
    assert_eq!(s(sr * (1.0 + 1e-6)), -0.5);
}

/// The static limit: S+ -> i (1 - nu)/mu (the static w' = -((1 - nu)/mu) H[p]), and the
/// free edge's gap coefficient tends to the 2-D Hertz value. Hertz's line contact has
/// p = (E*/(2 R)) sqrt(b^2 - x^2), E* = 2 mu/(1 - nu), so c = mu sqrt(2 b)/((1 - nu) R) at
/// the edge, and the gap g(x) = (1/(2R)) [x sqrt(x^2 - b^2) - b^2 ln((x + sqrt(x^2 - b^2))/b)]
/// outside, whose leading term at x = b + e is (2 sqrt(2)/3) (sqrt(b)/R) e^(3/2): hence
/// G = g/((c/mu) e^(3/2)) = 2 (1 - nu)/3.
#[test]
fn static_limit() {
    for nu in [0.1, 0.25, 0.45] {
        let hp = HalfPlane::from_poisson(nu).unwrap();
        let e = hp.edge_behaviour(1e-4, EdgeLaw::Signorini).unwrap();
        let (re, im) = e.slope_symbol;
        assert!(
            re.abs() < 1e-12 && (im - (1.0 - nu)).abs() < 1e-6,
            "{re} {im}"
        );
        let g = e.solutions[1].gap_coefficient;
        let want = 2.0 * (1.0 - nu) / 3.0;
        assert!((g - want).abs() < 1e-6, "nu {nu}: G = {g}, Hertz {want}");
        assert_eq!(e.selected, 0.5);
    }
}

#[test]
fn bad_speeds_are_refused_with_the_parameter_named() {
    let hp = HalfPlane::from_poisson(0.25).unwrap();
    let (m, sr) = (*hp.m(), *hp.s_r());
    for d in [0.0, -0.3, f64::NAN, f64::INFINITY, sr, m, 1.0] {
        let e = hp.edge_behaviour(d, EdgeLaw::Signorini).unwrap_err();
        assert!(e.to_string().contains("speed_over_c1"), "{e}");
    }
}

/// The exponents and gap coefficients at the precision of the half-plane: in double-double
/// and on MPFR at 200 bits against the closed forms evaluated on MPFR (sub-Rayleigh: lambda =
/// -1/2, 1/2, S+ = -i sqrt(1 - D^2) D^2/(c2^2 R(D)); transonic: lambda = -theta/pi with
/// tan theta = (2 - q)^2/(4 sqrt(1 - D^2) sqrt(q - 1)), q = D^2/c2^2).
#[test]
fn exponents_and_gaps_at_extended_precision() {
    use complexfn::{Dd, Real};
    use rug::Float;
    let bits = 200;
    let f = |x: f64| Float::with_val(bits, x);
    for nu in [0.25, 0.3] {
        let hp_mp = HalfPlane::from_poisson(f(nu)).unwrap();
        let hp_dd = HalfPlane::from_poisson(Dd::from_f64(nu)).unwrap();
        let m = hp_mp.m().clone();
        for d in [0.1, 0.3, 0.45, 0.7, 0.9] {
            let dm = f(d);
            let q = dm.clone() * &dm / (m.clone() * &m);
            let one = f(1.0);
            let a1 = (one.clone() - dm.clone() * &dm).abs().sqrt();
            let e_mp = hp_mp
                .edge_behaviour(dm.clone(), EdgeLaw::Kinematic)
                .unwrap();
            let e_dd = hp_dd
                .edge_behaviour(Dd::from_f64(d), EdgeLaw::Kinematic)
                .unwrap();
            let lam_mp = e_mp.selected.clone();
            let want_lambda = if e_mp.range == SpeedRange::SubRayleigh {
                // R(D) and the symbol's closed form
                let r = (f(2.0) - q.clone()).square()
                    - f(4.0) * a1.clone() * (one.clone() - q.clone()).sqrt();
                let im = -(a1.clone() * &dm * &dm / (m.clone() * &m * &r));
                let diff = (e_mp.slope_symbol.1.clone() - &im).abs().to_f64();
                assert!(
                    diff < 1e-55 * im.to_f64().abs(),
                    "nu {nu}, D {d}: S+ off by {diff:e}"
                );
                f(-0.5)
            } else {
                let theta = ((f(2.0) - q.clone()).square()
                    / (f(4.0) * a1.clone() * (q.clone() - one.clone()).sqrt()))
                .atan();
                -(theta / Float::with_val(bits, rug::float::Constant::Pi))
            };
            let off = (lam_mp.clone() - &want_lambda).abs().to_f64();
            assert!(off < 1e-55, "nu {nu}, D {d}: MPFR exponent off by {off:e}");
            let off_dd = (e_dd.selected.to_mpfr(bits) - &want_lambda).abs().to_f64();
            assert!(
                off_dd < 1e-30,
                "nu {nu}, D {d}: double-double exponent off by {off_dd:e}"
            );
            let (g_mp, g_dd) = (
                e_mp.solutions[0].gap_coefficient.clone(),
                e_dd.solutions[0].gap_coefficient.to_mpfr(bits),
            );
            let rel = ((g_dd - &g_mp) / &g_mp).abs().to_f64();
            assert!(
                rel < 1e-29,
                "nu {nu}, D {d}: double-double gap off by {rel:e}"
            );
        }
    }
}
