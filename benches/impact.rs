//! Benchmarks of the impact engine (crate `impact`), f64, one thread: the reference case (free
//! rigid cylinder, m0/(rho R^2) = 10, V0/c1 = 0.01, c2/c1 = 1000/1870.83, to c1 t/R = 10) on one
//! grid at dx = R/50 and R/100, and with three grids (the error estimates) at R/100 and R/200; the same
//! case with a thin-shell striker of equal mass (h_s/R = 0.05, steel) on one grid at R/100.
//! The reference case in double-double (`ImpactCase::solve_at`, `impact run --digits`) on one
//! grid at R/50 and with three grids at R/50, beside its f64 rows.
//! The cost against N_t and N_x with fitted exponents: `cargo run --release -p impact
//! --example cost_scaling`.
//!
//! Run: `cargo bench --bench impact`.

use std::hint::black_box;

use complexfn::Dd;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use impact::{Drive, EdgeLaw, ImpactCase, ShellStriker, Striker, StrikerMaterial};

fn reference(dx: f64, levels: usize, mass_ratio: f64) -> ImpactCase {
    let mut c = ImpactCase::reference(EdgeLaw::Signorini);
    c.drive = Drive::Free {
        mass_ratio,
        v0_over_c1: 0.01,
    };
    c.dx = dx;
    c.levels = levels;
    c
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("impact");
    g.sample_size(10);
    for (dx, levels) in [(0.02, 1), (0.01, 1), (0.01, 3), (0.005, 3)] {
        let case = reference(dx, levels, 10.0);
        g.bench_with_input(
            BenchmarkId::new(
                "rigid_reference",
                format!("R_over_dx={}, levels={levels}", (1.0 / dx).round()),
            ),
            &case,
            |b, case| b.iter(|| black_box(case.solve(|_| {}).unwrap())),
        );
    }
    let shell = ShellStriker {
        thickness: 0.05,
        material: StrikerMaterial {
            c1_ratio: 5900.0 / 1870.83,
            c2_ratio: 3200.0 / 1870.83,
            density_ratio: 3.0,
        },
    };
    let case = reference(0.01, 1, shell.mass_ratio()).with_striker(Striker::Shell(shell));
    g.bench_with_input(
        BenchmarkId::new("shell_reference", "R_over_dx=100, levels=1"),
        &case,
        |b, case| b.iter(|| black_box(case.solve(|_| {}).unwrap())),
    );
    let case = reference(0.01, 1, shell.mass_ratio());
    g.bench_with_input(
        BenchmarkId::new("rigid_equal_mass", "R_over_dx=100, levels=1"),
        &case,
        |b, case| b.iter(|| black_box(case.solve(|_| {}).unwrap())),
    );
    for levels in [1, 3] {
        let case = reference(0.02, levels, 10.0);
        g.bench_with_input(
            BenchmarkId::new(
                "rigid_reference_double_double",
                format!("R_over_dx=50, levels={levels}"),
            ),
            &case,
            |b, case| b.iter(|| black_box(case.solve_at::<Dd>(|_| {}).unwrap())),
        );
    }
    g.finish();
}

criterion_group! {
    name = benches;
    // no plots: criterion's plotting backend needs a system font
    config = Criterion::default().without_plots();
    targets = bench
}
criterion_main!(benches);
