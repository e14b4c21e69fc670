//! Single-grid histories of the reference case (`impact::REFERENCE`, Signorini law) on a
//! sequence of grids, printed at a few times, for the convergence study of `docs/impact.md`
//! (section 5): `cargo run --release -p impact --features examples --example grid_study -- KAPPA DX1 DX2 ...`.
use impact::{EdgeLaw, ImpactCase};

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("a number"))
        .collect();
    let kappa = args.first().copied().unwrap_or(2.0);
    let times = [0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 6.76, 8.0, 9.6];
    for &dx in &args[1..] {
        let mut case = ImpactCase::reference(EdgeLaw::Signorini);
        case.dx = dx;
        case.kappa = kappa;
        case.levels = 1;
        let t0 = std::time::Instant::now();
        let sol = case.solve(|_| {}).expect("solves");
        let el = t0.elapsed();
        let (rows, _) = sol.history();
        print!("dx {dx} ({:.3} s):", el.as_secs_f64());
        for &t in &times {
            if let Some(r) = rows.iter().find(|r| (r.t - t).abs() < 1e-6) {
                print!(
                    " | t {t}: b {:.8} h {:.8} F {:.8}",
                    r.b.value, r.h.value, r.force.value
                );
            }
        }
        println!();
    }
}
