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
//! stated error are written there as CSV.
use std::io::Write;

use impact::{Drive, EdgeLaw, HistoryRow, ImpactCase, Profile, Value};

/// The sweep's cases: (name, case).
fn cases() -> Vec<(&'static str, ImpactCase)> {
    let free = |nu: f64, profile: Profile, mass: f64, v0: f64, law: EdgeLaw, end: f64| {
        ImpactCase::new(
            nu,
            profile,
            Drive::Free {
                mass_ratio: mass,
                v0_over_c1: v0,
            },
            law,
            end,
        )
    };
    let parabola = Profile::Parabola { radius: 1.0 };
    let (sig, kin) = (EdgeLaw::Signorini, EdgeLaw::Kinematic);
    vec![
        ("reference", ImpactCase::reference(sig)),
        ("reference kinematic", ImpactCase::reference(kin)),
        (
            "light fast nu .3",
            free(0.3, parabola.clone(), 1.0, 0.1, sig, 3.2),
        ),
        (
            "heavy slow nu .1",
            free(0.1, parabola.clone(), 1000.0, 0.001, sig, 10.0),
        ),
        ("nu .45", free(0.45, parabola.clone(), 10.0, 0.01, sig, 8.0)),
        (
            "power k 3",
            free(
                0.25,
                Profile::Power { a: 1.0, k: 3.0 },
                10.0,
                0.01,
                sig,
                6.0,
            ),
        ),
        (
            "circle M 100 V .05",
            free(0.25, Profile::Circle { radius: 1.0 }, 100.0, 0.05, sig, 6.0),
        ),
        (
            "wedge 80",
            free(
                0.25,
                Profile::Wedge { theta_deg: 80.0 },
                10.0,
                0.01,
                sig,
                4.0,
            ),
        ),
        (
            "kinematic M 100 V .05",
            free(0.25, parabola.clone(), 100.0, 0.05, kin, 6.0),
        ),
        (
            "kinematic power k 3",
            free(
                0.2,
                Profile::Power { a: 1.0, k: 3.0 },
                30.0,
                0.003,
                kin,
                8.0,
            ),
        ),
        (
            "slow M 300 nu .2",
            free(0.2, parabola.clone(), 300.0, 0.003, sig, 10.0),
        ),
        (
            "kinematic wedge 80",
            free(0.3, Profile::Wedge { theta_deg: 80.0 }, 3.0, 0.03, kin, 3.2),
        ),
    ]
}

type Pick = fn(&HistoryRow) -> Value;
const PICKS: [(&str, Pick); 3] = [("h", |r| r.h), ("b", |r| r.b), ("force", |r| r.force)];

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

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
    for (name, base) in cases() {
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
        let find = |rs: &[HistoryRow], t: f64| rs.iter().find(|r| (r.t - t).abs() < 1e-9).cloned();
        // each level's value at report row i (the levels share the report times)
        let dtr = sol.report_dt();
        let level_value = |l: usize, qi: usize, i: usize| -> f64 {
            let r = &sol.runs[l];
            let n = (i + 1) * (dtr / r.dt).round().max(1.0) as usize;
            let v = match qi {
                0 => r.step(n).map(|s| s.h),
                1 => r.edge_at(n),
                _ => r.force_at(n),
            };
            // the force is reported over rho c1^2 R = mu R/m^2
            let scale = if qi == 2 { sol.m * sol.m } else { 1.0 };
            v.map_or(f64::NAN, |v| v * scale)
        };
        for (qi, (q, pick)) in PICKS.iter().enumerate() {
            let (mut ratios, mut rel) = (Vec::new(), Vec::new());
            for (i, r) in rows.iter().enumerate() {
                let (Some(a), Some(b)) = (find(&r4, r.t), find(&r2, r.t)) else {
                    continue;
                };
                let v = pick(r);
                let Some(err) = v.error else { continue };
                let (t4, t2) = (pick(&a).value, pick(&b).value);
                if let Some(f) = raw.as_mut() {
                    let lv: Vec<f64> = (0..3).map(|l| level_value(l, qi, i)).collect();
                    writeln!(
                        f,
                        "{name},{q},{},{},{},{},{err},{t4},{t2}",
                        r.t, lv[0], lv[1], lv[2]
                    )
                    .unwrap();
                }
                let own = (t4 - t2).abs();
                let actual = (v.value - t4).abs();
                ratios.push((actual + own) / err);
                if v.value.abs() > 0.0 {
                    rel.push(err / v.value.abs());
                }
            }
            if ratios.is_empty() {
                continue;
            }
            all[qi].0.extend(&ratios);
            all[qi].1.extend(&rel);
            let max = ratios.iter().copied().fold(0.0, f64::max);
            println!(
                "{name:<21} {q:<9} {max:>10.3}  {:>18.3}  {:>20.2e}",
                median(&mut ratios),
                median(&mut rel)
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
