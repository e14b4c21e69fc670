//! The history's error estimates against the actual errors, over a sweep of twelve cases
//! (both edge laws; parabola, circle, power law and wedge; V0/c1 from 1e-3 to 0.1; mass
//! ratios from 1 to 1000): each case runs with three levels at dx (the reported values and
//! their stated errors) and on one grid four times finer (the reference). The actual error is
//! bounded by the difference from the reference plus the reference's own error, taken as its
//! difference from the grid twice finer than dx (its error if the order is at least one).
//! Prints, per case and quantity, the largest ratio of that bound to the stated error over
//! the report times (a never-optimistic estimate keeps it below 1), its median (how
//! pessimistic) and the median stated error relative to the value; then the same over all
//! cases per quantity.
//!
//! `cargo run --release -p impact --features examples --example estimate_sweep -- [dx] [raw.csv]`
//! (default dx R/100). With a second argument, every row's level values, reference values and
//! stated error are written there as CSV; `CASE=name` runs the cases whose name contains it.
use std::io::Write;

mod sweep;

use sweep::{cases, compare, median, PICKS};

fn main() {
    let dx: f64 = std::env::args()
        .nth(1)
        .map(|a| a.parse().expect("dx: a number"))
        .unwrap_or(0.01);
    let mut raw = std::env::args().nth(2).map(|p| {
        let mut f = std::fs::File::create(p).expect("the CSV file can be written");
        writeln!(f, "case,quantity,t,fine,mid,coarse,stated,ref4,ref2").unwrap();
        f
    });
    let mut all: Vec<(Vec<f64>, Vec<f64>)> = vec![(Vec::new(), Vec::new()); PICKS.len()];
    println!("case                  quantity  max actual/stated  median actual/stated  median stated (rel)");
    let only = std::env::var("CASE").ok();
    for (name, base) in cases() {
        if only.as_ref().is_some_and(|o| !name.contains(o.as_str())) {
            continue;
        }
        let (sol, _, compared) = compare(&base, dx);
        // each level's reported histories on its own (a one-level solution of its run),
        // matched to the report rows by time
        let levels: Vec<Vec<impact::HistoryRow>> = (0..sol.runs.len())
            .map(|l| {
                let mut one = sol.clone();
                one.runs = vec![sol.runs[l].clone()];
                one.history().0
            })
            .collect();
        let level_value = |l: usize, qi: usize, t: f64| -> f64 {
            levels[l]
                .iter()
                .find(|r| (r.t - t).abs() < 1e-9)
                .and_then(|r| PICKS[qi].1(r))
                .map_or(f64::NAN, |v| v.value)
        };
        for (qi, (q, _)) in PICKS.iter().enumerate() {
            let (mut ratios, mut rel) = (Vec::new(), Vec::new());
            let mut worst = (0.0f64, 0.0);
            for c in &compared {
                let (value, stated, t4, t2) = c.q[qi];
                let Some(err) = stated else { continue };
                if let Some(f) = raw.as_mut() {
                    let lv: Vec<f64> = (0..3).map(|l| level_value(l, qi, c.t)).collect();
                    writeln!(
                        f,
                        "{name},{q},{},{},{},{},{err},{t4},{t2}",
                        c.t, lv[0], lv[1], lv[2]
                    )
                    .unwrap();
                }
                ratios.push(c.bound(qi) / err);
                if c.bound(qi) / err > worst.0 {
                    worst = (c.bound(qi) / err, c.t);
                }
                if value.abs() > 0.0 {
                    rel.push(err / value.abs());
                }
            }
            if ratios.is_empty() {
                continue;
            }
            all[qi].0.extend(&ratios);
            all[qi].1.extend(&rel);
            let max = ratios.iter().copied().fold(0.0, f64::max);
            println!(
                "{name:<21} {q:<9} {max:>10.3}  {:>18.3}  {:>20.2e}  (largest at c1 t/R = {})",
                median(&mut ratios),
                median(&mut rel),
                worst.1
            );
        }
    }
    for (qi, (q, _)) in PICKS.iter().enumerate() {
        let (r, rel) = &mut all[qi];
        let max = r.iter().copied().fold(0.0, f64::max);
        println!(
            "{:<21} {q:<9} {max:>10.3}  {:>18.3}  {:>20.2e}",
            "all cases",
            median(r),
            median(rel)
        );
    }
}
