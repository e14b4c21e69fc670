//! Benchmarks of Lamb's surface influence functions (crate `lamb`): one kernel value g(s) (all
//! three components), one step response W(s), one cell integral (Ix or It: two moments) and one
//! space-time cell (constant in time: four corners), in f64 and at 30 and 100 digits, at points
//! of every wave region (nu = 0.3).
//!
//! Run: `cargo bench --bench lamb`.

use std::hint::black_box;

use complexfn::quadrature::CachedRules;
use complexfn::Precision;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lamb::cells::{Cell, TimeShape};
use lamb::HalfPlane;
use rug::Float;

const POINTS: [f64; 4] = [0.2, 0.51, 0.6, 0.9];

fn half_plane<T: CachedRules>(like: &T) -> HalfPlane<T> {
    let hp = HalfPlane::from_poisson(like.lit(0.3)).unwrap();
    // build the partial fractions once, outside the timing
    for n in 0..3 {
        hp.moment(n, &like.lit(0.3)).unwrap();
    }
    hp
}

fn bench_level<T: CachedRules>(c: &mut Criterion, like: T, label: &str) {
    let hp = half_plane(&like);
    let pts: Vec<T> = POINTS.iter().map(|&s| like.lit(s)).collect();
    let mut g = c.benchmark_group("lamb");
    g.throughput(Throughput::Elements(POINTS.len() as u64));
    g.bench_with_input(BenchmarkId::new("kernel_g", label), &pts, |b, pts| {
        b.iter(|| {
            for s in pts {
                black_box(hp.impulse(black_box(s)).unwrap());
            }
        })
    });
    g.bench_with_input(BenchmarkId::new("step_w", label), &pts, |b, pts| {
        b.iter(|| {
            for s in pts {
                black_box(hp.step(black_box(s)).unwrap());
            }
        })
    });
    let cells: Vec<(T, T)> = POINTS
        .iter()
        .map(|&s| (like.lit(s), like.lit(s + 0.05)))
        .collect();
    g.bench_with_input(BenchmarkId::new("cell_ix", label), &cells, |b, cells| {
        b.iter(|| {
            for (sa, sb) in cells {
                black_box(hp.cell(0, black_box(sa), black_box(sb)).unwrap());
            }
        })
    });
    g.bench_with_input(BenchmarkId::new("cell_it", label), &cells, |b, cells| {
        b.iter(|| {
            for (sa, sb) in cells {
                black_box(hp.cell(1, black_box(sa), black_box(sb)).unwrap());
            }
        })
    });
    let st = Cell {
        xa: like.lit(0.0),
        xb: like.lit(0.1),
        ta: like.lit(0.0),
        tb: like.lit(0.1),
    };
    let at: Vec<(T, T)> = POINTS
        .iter()
        .map(|&s| (like.lit(0.05 + s * 0.9), like.lit(1.0)))
        .collect();
    g.bench_with_input(BenchmarkId::new("space_time_cell", label), &at, |b, at| {
        b.iter(|| {
            for (x, t) in at {
                black_box(hp.cell_response(&st, TimeShape::Constant, x, t).unwrap());
            }
        })
    });
    g.finish();
    let mut g = c.benchmark_group("lamb_setup");
    g.bench_function(BenchmarkId::new("half_plane_with_moments", label), |b| {
        b.iter(|| black_box(half_plane(black_box(&like))))
    });
    g.finish();
}

fn benches(c: &mut Criterion) {
    bench_level(c, 0.0f64, "f64");
    for d in [30u32, 100] {
        let bits = Precision::from_digits(d, 16).unwrap().bits();
        bench_level(c, Float::with_val(bits, 0), &format!("{d}_digits"));
    }
}

criterion_group! {
    name = lamb_benches;
    config = Criterion::default().without_plots().sample_size(20);
    targets = benches
}
criterion_main!(lamb_benches);
