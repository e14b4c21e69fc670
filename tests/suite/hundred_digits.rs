//! One solve of the paper's construction at 100 digits (the working precision of
//! `--digits 100`: bits for 100 digits plus `GUARD_BITS`) against a solve at 160 digits: Q, V
//! and the contact stress at three points are within their stated estimates, and those
//! estimates reach the 100 digits. The quadratures' tails, power maps and level choices, the
//! inner rule's size and the arctangent are all exercised at this precision here.

use complexfn::{Precision, Real};
use rug::Float;
use wedge::{Case, Coupling, Indenter, Material, Solution};

fn like(digits: u32) -> Float {
    match Precision::from_digits(digits, dyncontact::GUARD_BITS).unwrap() {
        Precision::Bits(b) => Float::with_val(b, 0),
        Precision::F64 => unreachable!(),
    }
}

fn rel(a: &Float, b: &Float) -> f64 {
    complexfn::scalar::rel_diff(&b.to_mpfr(b.prec()), &a.to_mpfr(b.prec()))
}

#[test]
fn one_solve_at_100_digits_is_within_its_estimates() {
    let mat = Material::paper();
    // (Theta deg, gamma, coupling, alpha m/s): the benchmark case, strong friction, slow
    // contact, close to the Rayleigh speed (c_R = 927.4 m/s), uncoupled
    let cases = [
        (89.0, 0.6, Coupling::On, 561.249),
        (45.0, 3.0, Coupling::On, 464.0),
        (80.0, 0.3, Coupling::On, 93.0),
        (86.0, 1.0, Coupling::On, 900.0),
        (89.5, 0.3, Coupling::Off, 835.0),
    ];
    let (lo, hi) = (like(100), like(160));
    for (theta, gamma, coupling, alpha) in cases {
        let ind = Indenter::new(theta, gamma, coupling).unwrap();
        let label = format!("Theta {theta}, gamma {gamma}, {coupling:?}, alpha {alpha}");
        let c = Case::with_alpha(&mat, &ind, alpha, &lo, Solution::Paper).unwrap();
        let r = Case::with_alpha(&mat, &ind, alpha, &hi, Solution::Paper).unwrap();
        let m = c.matching().unwrap();
        assert!(m.rel_error < 1e-100, "{label}: estimate {:e}", m.rel_error);
        let ref_m = r.matching().unwrap();
        for (name, a, b) in [("Q", &m.q_hat, &ref_m.q_hat), ("V", &m.v_hat, &ref_m.v_hat)] {
            let err = rel(a, b);
            assert!(
                err <= m.rel_error,
                "{label}: {name} error {err:e} > stated {:e}",
                m.rel_error
            );
        }
        for frac in [0.1, 0.5, 0.97] {
            let x = c.p().clone() * frac;
            let xr = Float::with_val(hi.prec(), &x);
            let s = c.stress_hat(&x).unwrap();
            let sr = r.stress_hat(&xr).unwrap();
            let err = (s.value.to_mpfr(hi.prec()) - &sr.value).abs().to_f64();
            assert!(
                err <= s.error,
                "{label}: stress at {frac} p error {err:e} > stated {:e}",
                s.error
            );
            assert!(
                s.error <= 1e-98 * sr.value.to_f64().abs(),
                "{label}: stress at {frac} p estimate {:e}",
                s.error
            );
        }
    }
}
