//! The free elastic disk (`impact::striker::disk`, `docs/strikers.md`, section 6) against an
//! independent derivation at 40 digits (`tests/reference/disk_mpmath.py`: mpmath's Bessel
//! functions, the frequency equation's roots by bracketing and `findroot`, the Laplace-domain
//! response from its own boundary-value problem): the natural frequencies of orders 0, 2 and
//! 3 (four radial orders each) to 1e-10, and the harmonic response W_n(s) at real and
//! complex s for n = 0, 1, 2, 3 and 10 to 1e-10; and the limits that need no reference.

use impact::striker::disk::Disk;
use rustfft::num_complex::Complex64;
use serde_json::Value;

fn reference() -> Value {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/reference/disk_reference.json"
    );
    serde_json::from_str(&std::fs::read_to_string(path).expect("reference file")).unwrap()
}

fn num(v: &Value) -> f64 {
    match v {
        Value::String(s) => s.parse().unwrap(),
        other => other.as_f64().unwrap(),
    }
}

#[test]
fn frequencies_match_the_independent_frequency_equation() {
    let r = reference();
    let mut checked = 0;
    for case in r["cases"].as_array().unwrap() {
        let disk = Disk::new(num(&case["nu"])).unwrap();
        assert!((disk.c1() - num(&case["c1"])).abs() < 1e-14);
        for (n, want) in case["frequencies"].as_object().unwrap() {
            let n: u32 = n.parse().unwrap();
            let want: Vec<f64> = want.as_array().unwrap().iter().map(num).collect();
            let got = disk.frequencies(n, want.len()).unwrap();
            for (g, w) in got.iter().zip(&want) {
                assert!(
                    (g - w).abs() < 1e-10 * w,
                    "nu {} n {n}: {g} vs {w}",
                    disk.poisson()
                );
                checked += 1;
            }
        }
    }
    assert!(checked >= 24, "{checked}");
}

#[test]
fn harmonic_response_matches_the_independent_solution() {
    let r = reference();
    let mut checked = 0;
    for case in r["cases"].as_array().unwrap() {
        let disk = Disk::new(num(&case["nu"])).unwrap();
        for p in case["laplace"].as_array().unwrap() {
            let n = p["n"].as_u64().unwrap() as u32;
            let s = Complex64::new(num(&p["s_re"]), num(&p["s_im"]));
            let want = Complex64::new(num(&p["w_re"]), num(&p["w_im"]));
            let got = disk.harmonic(n, s).unwrap();
            assert!(
                (got - want).norm() < 1e-10 * want.norm(),
                "nu {} n {n} s {s}: {got} vs {want}",
                disk.poisson()
            );
            checked += 1;
        }
    }
    assert!(checked >= 40, "{checked}");
}

/// The limits of section 6: uniform pressure on the plane-strain disk (n = 0), the rigid
/// translation of the disk of mass pi (n = 1, W_1 s^2 -> 1), the static cos 2 theta load,
/// W_2(0) = (3 - 2 nu)/6 and W_3(0) = (5 - 4 nu)/16 (Airy stress function); and bad input refused with its name.
#[test]
fn static_and_rigid_limits_and_refusals() {
    for nu in [0.1, 0.25, 0.3, 0.45] {
        let disk = Disk::new(nu).unwrap();
        let lambda = disk.c1().powi(2) - 2.0;
        let s = Complex64::new(1e-3, 0.0);
        let w0 = disk.harmonic(0, s).unwrap();
        assert!(
            (w0.re - 1.0 / (2.0 * (lambda + 1.0))).abs() < 1e-6,
            "{nu}: {w0}"
        );
        let w1 = disk.harmonic(1, s).unwrap() * s * s;
        assert!((w1.re - 1.0).abs() < 1e-6, "{nu}: {w1}");
        let w2 = disk.harmonic(2, s).unwrap();
        assert!((w2.re - (3.0 - 2.0 * nu) / 6.0).abs() < 1e-6, "{nu}: {w2}");
        let w3 = disk.harmonic(3, s).unwrap();
        assert!((w3.re - (5.0 - 4.0 * nu) / 16.0).abs() < 1e-6, "{nu}: {w3}");
    }
    let disk = Disk::new(0.25).unwrap();
    let msg = |e: impact::ImpactError| e.to_string();
    assert!(msg(Disk::new(0.5).unwrap_err()).contains("poisson"));
    assert!(msg(disk.harmonic(2, Complex64::new(1e-6, 0.0)).unwrap_err()).contains('s'));
    assert!(msg(disk.harmonic(2, Complex64::new(-1.0, 0.0)).unwrap_err()).contains("Re s"));
}
