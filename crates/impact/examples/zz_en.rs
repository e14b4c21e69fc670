use impact::striker::disk::Disk;
use rustfft::num_complex::Complex64 as C;
fn f(c1: f64, n: f64, s: C) -> C {
    let q = s * s;
    let n2 = n * n;
    let ic2 = 1.0 / (c1 * c1);
    let a = (q * ic2 + n2).sqrt();
    let b = (q + n2).sqrt();
    s * s * a / ((2.0 * n2 + q) * (2.0 * n2 + q) - 4.0 * n2 * a * b)
}
fn main() {
    let d = Disk::new(0.25).unwrap();
    let c1 = d.c1();
    for sv in [0.1, 10.0, 100.0, 1000.0] {
        for im in [0.0f64, 1.0] {
            let s = C::new(0.4, sv * im + if im == 0.0 { sv } else { 0.0 });
            print!("s={s:.1}: ");
            for n in [2u32, 5, 10, 30, 100, 300, 1000, 3000, 10000] {
                let w = d.harmonic(n, s).unwrap();
                let e = w - f(c1, n as f64, s);
                print!("n{n}:{:.3e} ", (e * (n as f64).powi(2)).norm());
            }
            println!();
        }
    }
}
