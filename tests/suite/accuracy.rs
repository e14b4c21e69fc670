//! The f64 alpha-V curve against a high-precision reference: the accuracy that the benchmark
//! target (200 points, relative error <= 1e-12) relies on, checked on every third point of the
//! benchmark's speeds (the full 200 points are in `cargo run --release --bin accuracy`).

use dyncontact::accuracy::curve_check;

#[test]
fn f64_alpha_v_curve_is_accurate_to_1e12_and_within_its_stated_error() {
    let c = curve_check(67, 160).unwrap();
    assert!(c.max_error <= 1e-12, "largest error {:.2e}", c.max_error);
    assert!(
        c.worst_ratio <= 1.0,
        "stated error exceeded: actual/stated {:.2}",
        c.worst_ratio
    );
}

#[test]
fn quick_report_errors_stay_within_the_precision() {
    // f64, 64 and 100 bits against 200 bits: every quantity to its precision's epsilon
    // (within a factor 1e4 of the unit round-off; conditioning of the stress near the apex)
    let rows = dyncontact::accuracy::report(true).unwrap();
    for r in &rows {
        let eps = 2f64.powi(1 - r.bits as i32);
        for (q, e) in dyncontact::accuracy::QUANTITIES.iter().zip(&r.errors) {
            assert!(*e <= 1e4 * eps, "{} {q}: {e:.2e}", r.precision);
        }
        // the stated error of V covers the actual one
        assert!(r.errors[3] <= r.estimate, "{}: V", r.precision);
    }
}
