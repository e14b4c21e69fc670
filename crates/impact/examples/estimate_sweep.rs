//! The history's error estimates against the actual errors, over a sweep of cases: each case
//! runs with three levels at dx (the reported values and their stated errors) and on one grid
//! four times finer (the reference). The actual error is bounded by the difference from the
//! reference plus the reference's own error, taken as its difference from the grid twice
//! finer than dx (its error if the order is at least one). Prints, per case and quantity, the
//! largest ratio of that bound to the stated error over the report times (a never-optimistic
//! estimate keeps it below 1), its median (how pessimistic) and the median stated error
//! relative to the value.
//!
//! `cargo run --release -p impact --features examples --example estimate_sweep -- [dx]` (default R/100).
use impact::{Drive, EdgeLaw, ImpactCase, Profile};

fn main() {
    let dx: f64 = std::env::args()
        .nth(1)
        .map(|a| a.parse().expect("dx: a number"))
        .unwrap_or(0.01);
    let free = |nu: f64, mass: f64, v0: f64, law: EdgeLaw, end: f64| {
        ImpactCase::new(
            nu,
            Profile::Parabola { radius: 1.0 },
            Drive::Free {
                mass_ratio: mass,
                v0_over_c1: v0,
            },
            law,
            end,
        )
    };
    let cases: Vec<(&str, ImpactCase)> = vec![
        ("reference", ImpactCase::reference(EdgeLaw::Signorini)),
        (
            "reference kinematic",
            ImpactCase::reference(EdgeLaw::Kinematic),
        ),
        (
            "light, fast, nu 0.3",
            free(0.3, 2.0, 0.02, EdgeLaw::Signorini, 4.0),
        ),
        (
            "heavy, slow, nu 0.1",
            free(0.1, 40.0, 0.005, EdgeLaw::Signorini, 8.0),
        ),
        ("nu 0.45", free(0.45, 10.0, 0.01, EdgeLaw::Signorini, 8.0)),
        (
            "power law k = 3",
            ImpactCase::new(
                0.25,
                Profile::Power { a: 1.0, k: 3.0 },
                Drive::Free {
                    mass_ratio: 10.0,
                    v0_over_c1: 0.01,
                },
                EdgeLaw::Signorini,
                6.0,
            ),
        ),
    ];
    println!("case                  quantity  max actual/stated  median actual/stated  median stated (rel)");
    for (name, base) in cases {
        let mut case = base.clone();
        case.dx = dx;
        let sol = case.solve(|_| {}).expect("the case solves");
        let (rows, _) = sol.history();
        let reference = |d: f64| {
            let mut c = base.clone();
            c.dx = d;
            c.levels = 1;
            c.solve(|_| {}).expect("the reference solves").history().0
        };
        let (r4, r2) = (reference(dx / 4.0), reference(dx / 2.0));
        let find =
            |rs: &[impact::HistoryRow], t: f64| rs.iter().find(|r| (r.t - t).abs() < 1e-9).cloned();
        type Pick = fn(&impact::HistoryRow) -> impact::Value;
        let picks: [(&str, Pick); 3] = [("h", |r| r.h), ("b", |r| r.b), ("force", |r| r.force)];
        for (q, pick) in picks {
            let mut ratios = Vec::new();
            let mut rel = Vec::new();
            for r in &rows {
                let (Some(a), Some(b)) = (find(&r4, r.t), find(&r2, r.t)) else {
                    continue;
                };
                let v = pick(r);
                let Some(err) = v.error else { continue };
                let (t4, t2) = (pick(&a).value, pick(&b).value);
                // the reference's own error: its difference from the grid twice coarser,
                // over 2^1 - 1 (first order), a bound when the order is at least one
                let own = (t4 - t2).abs();
                let actual = (v.value - t4).abs();
                ratios.push((actual + own) / err);
                if v.value.abs() > 0.0 {
                    rel.push(err / v.value.abs());
                }
            }
            ratios.sort_by(|a, b| a.total_cmp(b));
            rel.sort_by(|a, b| a.total_cmp(b));
            if ratios.is_empty() {
                continue;
            }
            println!(
                "{name:<21} {q:<9} {:>10.3}  {:>18.3}  {:>20.2e}",
                ratios[ratios.len() - 1],
                ratios[ratios.len() / 2],
                rel[rel.len() / 2]
            );
        }
    }
}
