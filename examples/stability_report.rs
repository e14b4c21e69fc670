//! The whole stability grid at 256 bits: a summary for the README.
//! Run: `cargo run --release --example stability_report`.

use dyncontact::stability::{check, grid, Outcome};

fn main() {
    let (mut n, mut refused, mut failures) = (0, 0, 0);
    let mut buckets = [0usize; 5]; // stated error: <=1e-13, <=1e-11, <=1e-9, <=1e-6, larger
    let mut worst = 0.0_f64;
    for pt in grid() {
        n += 1;
        match check(&pt, true) {
            Err(e) => {
                failures += 1;
                println!("FAIL {e}");
            }
            Ok(Outcome::Refused(msg)) => {
                refused += 1;
                println!("refused {}: {msg}", pt.label());
            }
            Ok(Outcome::Solved { stated, actual }) => {
                let a = actual.unwrap_or(0.0);
                if a > stated {
                    failures += 1;
                    println!("OPTIMISTIC {}: actual {a:e} stated {stated:e}", pt.label());
                }
                worst = worst.max(a / stated);
                let k = [1e-13, 1e-11, 1e-9, 1e-6]
                    .iter()
                    .position(|&t| stated <= t)
                    .unwrap_or(4);
                buckets[k] += 1;
            }
        }
    }
    println!("{n} cases: {refused} refused, {failures} failures; worst actual/stated = {worst:.3}");
    println!(
        "stated f64 accuracy: <=1e-13: {}, <=1e-11: {}, <=1e-9: {}, <=1e-6: {}, worse: {}",
        buckets[0], buckets[1], buckets[2], buckets[3], buckets[4]
    );
}
