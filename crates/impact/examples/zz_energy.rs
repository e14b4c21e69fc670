use impact::striker::disk::Disk;
use impact::*;
fn main() {
    let nu: f64 = 0.25;
    let m = ((1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))).sqrt();
    let mat = StrikerMaterial {
        c1_ratio: 1.0,
        c2_ratio: m,
        density_ratio: 1.0,
    };
    let mut case = ImpactCase::new(
        nu,
        Profile::Parabola { radius: 1.0 },
        Drive::Free {
            mass_ratio: std::f64::consts::PI,
            v0_over_c1: 0.01,
        },
        EdgeLaw::Signorini,
        10.0,
    )
    .with_striker(Striker::Cylinder(mat));
    case.dx = std::env::args()
        .nth(1)
        .map(|a| a.parse().unwrap())
        .unwrap_or(0.01);
    case.levels = 1;
    let sol = case.solve(|_| {}).unwrap();
    let run = &sol.runs[0];
    let g = mat.shear_modulus_ratio(m);
    let pressures: Vec<Vec<f64>> = run
        .steps
        .iter()
        .map(|s| s.pressure.iter().map(|p| p / g).collect())
        .collect();
    let disk = Disk::new(mat.poisson()).unwrap();
    let t0 = std::time::Instant::now();
    let modes = disk.modes(128.0).unwrap();
    println!("modes {} in {:?}", modes.count(), t0.elapsed());
    for wm in [16.0, 32.0, 64.0, 128.0] {
        let sub = modes.below(wm);
        let e = sub.energies(run.dx, run.dt * mat.c2_ratio, &pressures);
        for i in [99usize, 299, 499, 799, 999]
            .iter()
            .filter(|i| **i < e.len())
        {
            let w = run.steps[*i].striker_work;
            println!("wmax {wm} ({} modes) t {:.2} K {:.4e} Umodal {:.4e} K+U {:.5e} work {:.5e} (over G: {:.5e})", sub.count(), run.steps[*i].t, e[*i].0 * g, e[*i].1 * g, (e[*i].0 + e[*i].1) * g, w, w / g);
        }
    }
}
