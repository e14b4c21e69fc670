//! Extreme materials: Poisson's ratio near -1, near 0 (a root of the Rayleigh cubic near the P
//! front), near 0.2631 (the two other roots nearly coincide) and near 1/2 (s_R -> m). Every
//! value is finite or refused, and the stated f64 error covers the actual error against 200
//! bits of the same material.

use crate::common;

use common::fl;
use lamb::HalfPlane;

/// The materials at both ends of the admissible range and next to the one where the Rayleigh
/// cubic's two other roots coincide
/// (the others in the `--ignored` tier).
#[test]
fn stated_errors_hold_for_extreme_materials() {
    check_materials(&[-0.99, 0.26312, 0.4999]);
}

/// Every extreme material.
#[test]
#[ignore]
fn stated_errors_hold_for_every_extreme_material() {
    check_materials(&[
        -0.99, -0.5, -1e-6, 1e-6, 0.2631, 0.26312, 0.2632, 0.49, 0.4999,
    ]);
}

/// Each material on its own thread (a failure fails the test when the threads are joined).
fn check_materials(materials: &[f64]) {
    let worst: Vec<(f64, f64)> = std::thread::scope(|scope| {
        let threads: Vec<_> = materials
            .iter()
            .map(|&nu| scope.spawn(move || (nu, check_material(nu))))
            .collect();
        threads
            .into_iter()
            .map(|t| t.join().expect("a material failed"))
            .collect()
    });
    for (nu, w) in &worst {
        eprintln!("nu {nu}: largest stated relative error of a moment {w:.1e}");
    }
}

/// The largest stated relative error of a moment of material `nu`, the checks asserted.
fn check_material(nu: f64) -> f64 {
    let hp = match HalfPlane::from_poisson(nu) {
        Ok(h) => h,
        Err(e) => panic!("nu {nu} refused: {e}"),
    };
    let hq = HalfPlane::new(fl(200, *hp.m())).unwrap();
    let (m, sr) = (*hp.m(), *hp.s_r());
    let mut stated_max: f64 = 0.0;
    for s in [
        1e-6,
        0.3 * sr,
        0.99 * sr,
        1.01 * sr,
        0.5 * (sr + m),
        0.5 * (m + 1.0),
        0.999,
        1.0 - 1e-9,
    ] {
        if s <= 0.0 || s >= 1.0 || s == sr {
            continue;
        }
        let a = hp.impulse(&s).unwrap();
        let b = hq.impulse(&fl(200, s)).unwrap();
        for (x, y) in [(&a.zz, &b.zz), (&a.xz, &b.xz), (&a.xx, &b.xx)] {
            let actual = (x.value - y.value.to_f64()).abs();
            assert!(
                actual <= x.error.max(1e-300),
                "nu {nu} s {s} g: {actual:e} > {:e}",
                x.error
            );
        }
        for n in 0..3 {
            let a = hp.moment(n, &s).unwrap();
            let b = hq.moment(n, &fl(200, s)).unwrap();
            for (x, y) in [(&a.zz, &b.zz), (&a.xz, &b.xz), (&a.xx, &b.xx)] {
                let actual = (x.value - y.value.to_f64()).abs();
                assert!(
                    actual <= x.error.max(1e-300),
                    "nu {nu} s {s} n {n}: actual {actual:e} > stated {:e} (value {})",
                    x.error,
                    x.value
                );
                let scale = y.value.to_f64().abs().max(1e-300);
                stated_max = stated_max.max(x.error / scale.max(1e-3));
            }
        }
    }
    stated_max
}

#[test]
fn poisson_zero_is_refused_with_the_reason() {
    let e = HalfPlane::from_poisson(0.0).unwrap_err().to_string();
    assert!(e.contains("P front"), "{e}");
}
