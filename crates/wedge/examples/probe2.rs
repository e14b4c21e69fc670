use rug::Float;
use wedge::*;
fn main() {
    let mat = Material::paper();
    let ind = Indenter::new(89.0, 0.6, Coupling::On).unwrap();
    let c = Case::new(&mat, &ind, 0.3, Solution::Paper).unwrap();
    let a = c.apex().unwrap();
    println!(
        "regime {:?} exp {} amp {}",
        a.regime, a.exponent, a.amplitude
    );
    for x in [1e-2, 1e-4, 1e-6] {
        let s = c.stress_hat(&(x * 0.3)).unwrap();
        println!(
            "  x {x:e} stress {} lead {} ratio {}",
            s.value,
            c.apex_leading_term(&(x * 0.3)).unwrap(),
            s.value / c.apex_leading_term(&(x * 0.3)).unwrap()
        );
    }
    let t0 = std::time::Instant::now();
    let adm = c.admissibility().unwrap();
    println!("adm {:?} {:?}", adm, t0.elapsed());
    let b = Case::new(
        &mat,
        &Indenter::new(86.0, 0.001, Coupling::On).unwrap(),
        0.3,
        Solution::Paper,
    )
    .unwrap();
    let a = b.apex().unwrap();
    println!(
        "B regime {:?} amp {} stress(1e-6) {}",
        a.regime,
        a.amplitude,
        b.stress_hat(&1e-7).unwrap().value
    );
    println!("B adm {:?}", b.admissibility().unwrap());
    for bits in [128u32, 256, 512] {
        let like = Float::with_val(bits, 0);
        let t0 = std::time::Instant::now();
        let c = Case::with_alpha(&mat, &ind, 0.3 * 1870.83, &like, Solution::Paper).unwrap();
        let m = c.matching().unwrap();
        println!(
            "{bits}: q {} v {} err {:e} n {} t {:?}",
            m.q_hat.to_string_radix(10, Some(40)),
            m.v_hat.to_string_radix(10, Some(40)),
            m.rel_error,
            c.inner().len(),
            t0.elapsed()
        );
    }
    let t0 = std::time::Instant::now();
    let c = case_for_speed(&mat, &ind, 10.0, &0.0f64, Solution::Paper).unwrap();
    println!(
        "inverse V=10: alpha {} V {} {:?}",
        c.p() * 1870.83,
        c.v_hat().unwrap() * 1870.83 * ind.cot_theta(&0.0f64),
        t0.elapsed()
    );
}
