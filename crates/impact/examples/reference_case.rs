//! The reference case of the benchmark (free rigid cylinder, parabolic profile,
//! m0/(rho R^2) = 10, V0/c1 = 0.01, c2/c1 = 1000/1870.83, to c1 t/R = 10): prints the history
//! at a few times with error estimates. `cargo run --release -p impact --features examples --example reference_case -- DX KAPPA`.
use impact::{EdgeLaw, ImpactCase};

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("a number"))
        .collect();
    let (dx, kappa, end) = (
        args.first().copied().unwrap_or(0.02),
        args.get(1).copied().unwrap_or(4.0),
        args.get(2).copied().unwrap_or(10.0),
    );
    let mut case = ImpactCase::reference(EdgeLaw::Signorini);
    case.end = end;
    case.dx = dx;
    case.kappa = kappa;
    let t0 = std::time::Instant::now();
    let sol = case.solve(|_| {}).expect("solves");
    let el = t0.elapsed();
    let (rows, ord) = sol.history();
    let every = (rows.len() / 10).max(1);
    for r in rows.iter().step_by(every) {
        println!(
            "t={:.3} h={:.6e}±{:.1e} b={:.5e}±{:.1e} F={:.6e}±{:.1e} {} W={:.4e} KE={:.4e}",
            r.t,
            r.h.value,
            r.h.error.unwrap_or(0.0),
            r.b.value,
            r.b.error.unwrap_or(0.0),
            r.force.value,
            r.force.error.unwrap_or(0.0),
            r.stage.name(),
            r.work.value,
            r.kinetic.map(|k| k.value).unwrap_or(0.0)
        );
    }
    println!(
        "orders {:?} peak {:?} separation {:?}",
        ord,
        sol.peak_force(),
        sol.separation()
    );
    eprintln!("elapsed {el:?}");
}
