//! Benchmarks of the impact engine (crate `impact`), f64, one thread: the reference case (free
//! rigid cylinder, m0/(rho R^2) = 10, V0/c1 = 0.01, c2/c1 = 1000/1870.83, to c1 t/R = 10) on one
//! grid at dx = R/50 and R/100, and with three grids (the error estimates) at R/100 and R/200,
//! with the default start on grids 64 times finer (`docs/impact.md`, section 11) and, at R/200,
//! beside the same three grids throughout without it; the same
//! case with a thin-shell striker of equal mass (h_s/R = 0.05, steel) on one grid at R/100.
//! The reference case in double-double (`ImpactCase::solve_at`, `impact run --digits`) on one
//! grid at R/50 and with three grids at R/50, beside its f64 rows.
//! The scaling group: the reference case on one grid throughout at R/50, R/100, R/200 and R/400, and the
//! fitted exponent of its time against its space-time cells N_t N_x (printed after the group,
//! beside the exponent N log N would have over the same cells). The cost against N_t and N_x
//! separately: `cargo run --release -p impact --features examples --example cost_scaling`.
//!
//! The striker-green group: the free cylinder's own influence function
//! (`Disk::arc_step_response`, `impact striker-green`) for the README's example (arc 0.02, four
//! angles, c2s t/R = 0.1, 1, 8), for arc 0.05 to c2s t/R = 10 and for arc 0.02 to 50 (the
//! cost grows like t_max/arc^2), all threads.
//!
//! The cylinder group: the reference case's parabola (to c1 t/R = 10, V0/c1 = 0.01) with the
//! full elastic cylinder of the half-plane's own material (mass pi rho R^2) beside the rigid
//! striker of the same mass, three grids at R/200 (the ratio of their times printed after the
//! group), and the cylinder on one grid at R/50, R/100 and R/200 (its cost against 1/dx), all
//! threads.
//!
//! Run: `cargo bench --bench impact`.

use std::cell::RefCell;
use std::hint::black_box;
use std::time::Instant;

use complexfn::Dd;
use criterion::{BenchmarkId, Criterion};
use impact::cost::fitted_exponent;
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
    // the default grid on one grid throughout, without the start on finer grids
    let mut case = reference(0.005, 3, 10.0);
    case.start_halvings = 0;
    g.bench_with_input(
        BenchmarkId::new(
            "rigid_reference_one_grid_throughout",
            "R_over_dx=200, levels=3",
        ),
        &case,
        |b, case| b.iter(|| black_box(case.solve(|_| {}).unwrap())),
    );
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

/// The reference case on one grid at four cell widths; prints the fitted exponent of the time
/// against the space-time cells N_t N_x (N_x the widest contact in cells).
fn scaling(c: &mut Criterion) {
    let mut g = c.benchmark_group("impact_scaling");
    g.sample_size(10);
    let mut rows = Vec::new();
    for r_over_dx in [50.0, 100.0, 200.0, 400.0] {
        // one grid throughout (the start on finer grids is not this grid's cells)
        let mut case = reference(1.0 / r_over_dx, 1, 10.0);
        case.start_halvings = 0;
        let sol = case.solve(|_| {}).unwrap();
        let run = &sol.runs[0];
        let nx = run
            .steps
            .iter()
            .map(|s| s.pressure.len())
            .max()
            .unwrap_or(0);
        let cells = (run.steps.len() * nx) as f64;
        let median = timed(
            &mut g,
            BenchmarkId::new(
                "rigid_reference",
                format!("R_over_dx={r_over_dx}, levels=1"),
            ),
            &case,
        );
        if let Some(median) = median {
            rows.push((r_over_dx, run.steps.len(), nx, cells, median));
        }
    }
    g.finish();
    if rows.len() < 2 {
        return;
    }
    println!("reference case, one grid: time against the space-time cells N = N_t N_x");
    for (r, nt, nx, cells, t) in &rows {
        println!("  R/dx = {r:4}  N_t = {nt:5}  N_x = {nx:4}  N = {cells:9.0}  {t:.4} s");
    }
    let pts: Vec<(f64, f64)> = rows.iter().map(|r| (r.3, r.4)).collect();
    let nlogn: Vec<(f64, f64)> = rows.iter().map(|r| (r.3, r.3 * r.3.ln())).collect();
    println!(
        "  fitted exponent of N: {:.2} (N log N over the same N: {:.2})",
        fitted_exponent(&pts).unwrap_or(f64::NAN),
        fitted_exponent(&nlogn).unwrap_or(f64::NAN)
    );
}

/// The cylinder's arc step response at three costs.
fn striker_green(c: &mut Criterion) {
    let mut g = c.benchmark_group("striker_green");
    g.sample_size(10);
    let disk = impact::striker::disk::Disk::new(0.25).unwrap();
    let deg = |d: &[f64]| d.iter().map(|a: &f64| a.to_radians()).collect::<Vec<_>>();
    for (name, arc, angles, times) in [
        (
            "arc=0.02, 4 angles, t=0.1,1,8",
            0.02,
            deg(&[0.0, 1.1459, 90.0, 180.0]),
            vec![0.1, 1.0, 8.0],
        ),
        ("arc=0.05, t=10", 0.05, deg(&[0.0]), vec![10.0]),
        ("arc=0.02, t=50", 0.02, deg(&[0.0]), vec![50.0]),
    ] {
        g.bench_function(name, |b| {
            b.iter(|| black_box(disk.arc_step_response(arc, &angles, &times).unwrap()))
        });
    }
    g.finish();
}

/// The median time per solve of `case` over criterion's samples, benched under `name`.
fn timed(
    g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    name: BenchmarkId,
    case: &ImpactCase,
) -> Option<f64> {
    let times = RefCell::new(Vec::new());
    g.bench_with_input(name, case, |b, case| {
        b.iter_custom(|iters| {
            let t0 = Instant::now();
            for _ in 0..iters {
                black_box(case.solve(|_| {}).unwrap());
            }
            let e = t0.elapsed();
            times.borrow_mut().push(e.as_secs_f64() / iters as f64);
            e
        })
    });
    let mut t = times.into_inner();
    t.sort_by(f64::total_cmp);
    t.get(t.len() / 2).copied()
}

/// The cylinder striker beside the rigid one of the same mass (the reference grid), and its
/// cost against the cell width.
fn cylinder(c: &mut Criterion) {
    let mut g = c.benchmark_group("cylinder");
    g.sample_size(10);
    let m = ImpactCase::reference(EdgeLaw::Signorini).poisson;
    let m = ((1.0 - 2.0 * m) / (2.0 * (1.0 - m))).sqrt();
    let own = Striker::Cylinder(StrikerMaterial {
        c1_ratio: 1.0,
        c2_ratio: m,
        density_ratio: 1.0,
    });
    let parabola = |dx: f64, levels: usize| {
        let mut case = reference(dx, levels, std::f64::consts::PI);
        case.profile = impact::Profile::Parabola { radius: 1.0 };
        case
    };
    let rigid = timed(
        &mut g,
        BenchmarkId::new("rigid_mass_pi", "R_over_dx=200, levels=3"),
        &parabola(0.005, 3),
    );
    let cyl = timed(
        &mut g,
        BenchmarkId::new("cylinder_own_material", "R_over_dx=200, levels=3"),
        &parabola(0.005, 3).with_striker(own),
    );
    let mut rows = Vec::new();
    for r_over_dx in [50.0, 100.0, 200.0] {
        let t = timed(
            &mut g,
            BenchmarkId::new(
                "cylinder_own_material",
                format!("R_over_dx={r_over_dx}, levels=1"),
            ),
            &parabola(1.0 / r_over_dx, 1).with_striker(own),
        );
        if let Some(t) = t {
            rows.push((r_over_dx, t));
        }
    }
    g.finish();
    if let (Some(r), Some(c)) = (rigid, cyl) {
        println!("cylinder against the rigid striker of mass pi, three grids at R/200: {c:.3} s against {r:.3} s, ratio {:.2}", c / r);
    }
    for (r, t) in &rows {
        println!("  cylinder, one grid, R/dx = {r:4}: {t:.3} s");
    }
    let pts: Vec<(f64, f64)> = rows.iter().map(|r| (r.0, r.1)).collect();
    if pts.len() > 1 {
        println!(
            "  fitted exponent of R/dx: {:.2}",
            fitted_exponent(&pts).unwrap_or(f64::NAN)
        );
    }
}

fn main() {
    // no plots: criterion's plotting backend needs a system font
    let mut c = Criterion::default().without_plots().configure_from_args();
    bench(&mut c);
    scaling(&mut c);
    striker_green(&mut c);
    cylinder(&mut c);
    c.final_summary();
}
