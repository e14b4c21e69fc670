//! The stability grid (both solution variants), every case reported in f64 as the command
//! line reports it and (every N-th, default all) compared quantity by quantity with a
//! high-precision solve: a summary per corner of the parameter space, for the README.
//! Run: `cargo run --release --example stability_report [-- --compare-every N]`.

use std::collections::BTreeMap;

use dyncontact::stability::{check, grid, Outcome};
use rayon::prelude::*;

#[derive(Default)]
struct Corner {
    cases: usize,
    refused: usize,
    compared: usize,
    optimistic: usize,
    worst: f64,
    /// stated relative error of V: <=1e-13, <=1e-11, <=1e-9, <=1e-6, larger
    buckets: [usize; 5],
    unavailable: BTreeMap<String, usize>,
}

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
    let pts = grid();
    let t0 = std::time::Instant::now();
    let results: Vec<_> = pts
        .par_iter()
        .enumerate()
        .map(|(i, pt)| check(pt, i % every == 0))
        .collect();
    let mut corners: BTreeMap<(String, &'static str), Corner> = BTreeMap::new();
    let mut failures = 0;
    for (pt, res) in pts.iter().zip(results) {
        let c = corners
            .entry((pt.solution.name().to_string(), pt.corner()))
            .or_default();
        c.cases += 1;
        match res {
            Err(e) => {
                failures += 1;
                println!("FAIL {e}");
            }
            Ok(Outcome::Refused(msg)) => {
                c.refused += 1;
                println!("refused {}: {msg}", pt.label());
            }
            Ok(Outcome::Solved {
                stated,
                unavailable,
                worst,
                optimistic,
            }) => {
                for (k, why) in unavailable {
                    let why: String = why.chars().take(60).collect();
                    *c.unavailable.entry(format!("{k}: {why}")).or_default() += 1;
                }
                if let Some((w, _)) = worst {
                    c.compared += 1;
                    c.worst = c.worst.max(w);
                }
                for (k, a, s) in &optimistic {
                    println!("OPTIMISTIC {}: {k} actual {a:e} stated {s:e}", pt.label());
                }
                c.optimistic += usize::from(!optimistic.is_empty());
                let k = [1e-13, 1e-11, 1e-9, 1e-6]
                    .iter()
                    .position(|&t| stated <= t)
                    .unwrap_or(4);
                c.buckets[k] += 1;
            }
        }
    }
    println!(
        "\n{} cases in {:.0} s, {failures} defects\n",
        pts.len(),
        t0.elapsed().as_secs_f64()
    );
    println!("| solution | corner | cases | refused | compared | optimistic | worst actual/stated | V stated <=1e-13 / 1e-11 / 1e-9 / 1e-6 / worse |");
    println!("|---|---|---|---|---|---|---|---|");
    for ((sol, corner), c) in &corners {
        let b = c.buckets;
        println!(
            "| {sol} | {corner} | {} | {} | {} | {} | {:.2} | {} / {} / {} / {} / {} |",
            c.cases, c.refused, c.compared, c.optimistic, c.worst, b[0], b[1], b[2], b[3], b[4]
        );
    }
    for ((sol, corner), c) in &corners {
        for (why, n) in &c.unavailable {
            println!("unavailable ({sol}, {corner}) x{n}: {why}");
        }
    }
}
