//! The stability grid, every case solved in f64 and (every N-th, default all) at 256 bits: a
//! summary for the README.
//! Run: `cargo run --release --example stability_report [-- --compare-every N]`.

use dyncontact::stability::{check, grid, Outcome};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let every: usize = match args.as_slice() {
        [] => 1,
        [flag, n] if flag == "--compare-every" => n.parse().unwrap_or(1).max(1),
        _ => {
            eprintln!("usage: stability_report [--compare-every N]");
            std::process::exit(2);
        }
    };
    let (mut n, mut refused, mut failures, mut compared) = (0, 0, 0, 0);
    let mut buckets = [0usize; 5]; // stated error: <=1e-13, <=1e-11, <=1e-9, <=1e-6, larger
    let mut worst = 0.0_f64;
    for (i, pt) in grid().into_iter().enumerate() {
        n += 1;
        match check(&pt, i % every == 0) {
            Err(e) => {
                failures += 1;
                println!("FAIL {e}");
            }
            Ok(Outcome::Refused(msg)) => {
                refused += 1;
                println!("refused {}: {msg}", pt.label());
            }
            Ok(Outcome::Solved { stated, actual }) => {
                compared += usize::from(actual.is_some());
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
    println!("{n} cases ({compared} compared at 256 bits): {refused} refused, {failures} failures; worst actual/stated = {worst:.3}");
    println!(
        "stated f64 accuracy: <=1e-13: {}, <=1e-11: {}, <=1e-9: {}, <=1e-6: {}, worse: {}",
        buckets[0], buckets[1], buckets[2], buckets[3], buckets[4]
    );
}
