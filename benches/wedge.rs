//! Benchmarks: the Rayleigh root, Omega0 with S0 (a case build), a 100-point contact-stress
//! profile, one full solve (Q, V) with friction and coupling, an alpha-V curve and the inverse
//! alpha(V), each in f64 and at 30 and 100 digits (MPFR), the full solve and the curve also
//! in double-double (what `--digits 30` runs on the paper's construction); and one genuine
//! solve (three basis sizes) in f64 and at 30 digits (double-double, and MPFR for comparison).
//!
//! Run: `cargo bench --bench wedge`. The 200-point curve is benchmarked in f64 and at 30
//! digits; at 100 digits a 10-point curve stands for it (per point it costs one full solve).

use std::hint::black_box;

use complexfn::{Dd, Precision, Rayleigh, Real};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use rug::Float;
use wedge::{case_for_speed, Case, Coupling, Indenter, Material, Solution};

fn like(digits: Option<u32>) -> Option<Float> {
    digits.map(
        |d| match Precision::from_digits(d, dyncontact::GUARD_BITS).unwrap() {
            Precision::Bits(b) => Float::with_val(b, 0),
            Precision::F64 => unreachable!(),
        },
    )
}

fn label(digits: Option<u32>) -> String {
    digits
        .map(|d| format!("{d}_digits"))
        .unwrap_or_else(|| "f64".into())
}

const LEVELS: [Option<u32>; 3] = [None, Some(30), Some(100)];

/// The benchmark case: Theta = 89 deg, gamma = 0.6, coupled, the paper's material.
fn paper_case<T: complexfn::quadrature::CachedRules>(p: T) -> Case<T> {
    Case::new(&Material::paper(), &indenter(), p, Solution::Paper).unwrap()
}

fn indenter() -> Indenter {
    Indenter::new(89.0, 0.6, Coupling::On).unwrap()
}

fn bench_rayleigh(c: &mut Criterion) {
    let mut g = c.benchmark_group("rayleigh_root");
    for d in LEVELS {
        match like(d) {
            None => g.bench_function(label(d), |b| {
                b.iter(|| Rayleigh::new(black_box(1000.0 / 1870.83)).unwrap())
            }),
            Some(l) => {
                let m = l.lit(1000.0) / l.lit(1870.83);
                g.bench_function(label(d), |b| {
                    b.iter(|| Rayleigh::new(black_box(m.clone())).unwrap())
                })
            }
        };
    }
    g.finish();
}

fn bench_case_build(c: &mut Criterion) {
    // Omega0 and S0: building a case tabulates Omega on the inner rule.
    let mut g = c.benchmark_group("omega0_s0");
    g.sample_size(10);
    for d in LEVELS {
        match like(d) {
            None => g.bench_function(label(d), |b| b.iter(|| paper_case(black_box(0.3)).s0())),
            Some(l) => {
                let p = l.lit(0.3);
                g.bench_function(label(d), |b| {
                    b.iter(|| paper_case(black_box(p.clone())).s0())
                })
            }
        };
    }
    g.finish();
}

fn bench_stress_profile(c: &mut Criterion) {
    let mut g = c.benchmark_group("stress_profile_100");
    g.sample_size(10);
    g.throughput(Throughput::Elements(100));
    for d in LEVELS {
        match like(d) {
            None => {
                let cs = paper_case(0.3);
                cs.q_hat().unwrap();
                g.bench_function(label(d), |b| {
                    b.iter(|| {
                        (1..=100)
                            .map(|k| cs.stress_hat(&(0.3 * k as f64 / 100.5)).unwrap().value)
                            .sum::<f64>()
                    })
                })
            }
            Some(l) => {
                let cs = paper_case(l.lit(0.3));
                cs.q_hat().unwrap();
                let n = if d == Some(100) { 10 } else { 100 };
                g.bench_function(BenchmarkId::new(label(d), format!("{n}_points")), |b| {
                    b.iter(|| {
                        (1..=n)
                            .map(|k| {
                                cs.stress_hat(&(l.lit(0.3) * (k as f64 / (n as f64 + 0.5))))
                                    .unwrap()
                                    .value
                                    .to_f64()
                            })
                            .sum::<f64>()
                    })
                })
            }
        };
    }
    g.finish();
}

fn bench_full_solve(c: &mut Criterion) {
    let mut g = c.benchmark_group("full_solve");
    g.sample_size(10);
    for d in LEVELS {
        match like(d) {
            None => g.bench_function(label(d), |b| {
                b.iter(|| paper_case(black_box(0.3)).v_hat().unwrap())
            }),
            Some(l) => {
                let p = l.lit(0.3);
                g.bench_function(label(d), |b| {
                    b.iter(|| paper_case(black_box(p.clone())).v_hat().unwrap())
                })
            }
        };
    }
    // what `--digits 30` runs on the paper's construction
    g.bench_function("30_digits_double_double", |b| {
        b.iter(|| paper_case(black_box(Dd::from_f64(0.3))).v_hat().unwrap())
    });
    g.finish();
}

fn bench_curve(c: &mut Criterion) {
    let mut g = c.benchmark_group("alpha_v_curve");
    g.sample_size(10);
    for d in LEVELS {
        let n = if d == Some(100) { 10 } else { 200 };
        g.throughput(Throughput::Elements(n as u64));
        let ps: Vec<f64> = (0..n).map(|k| 0.49 * (k as f64 + 0.5) / n as f64).collect();
        // one material and indenter, many contact speeds
        let (mat, ind) = (Material::paper(), indenter());
        match like(d) {
            None => g.bench_function(BenchmarkId::new(label(d), n), |b| {
                b.iter(|| {
                    ps.iter()
                        .map(|&p| {
                            Case::new(&mat, &ind, p, Solution::Paper)
                                .unwrap()
                                .v_hat()
                                .unwrap()
                        })
                        .sum::<f64>()
                })
            }),
            Some(l) => g.bench_function(BenchmarkId::new(label(d), n), |b| {
                b.iter(|| {
                    ps.iter()
                        .map(|&p| {
                            Case::new(&mat, &ind, l.lit(p), Solution::Paper)
                                .unwrap()
                                .v_hat()
                                .unwrap()
                                .to_f64()
                        })
                        .sum::<f64>()
                })
            }),
        };
        if d == Some(30) {
            g.bench_function(BenchmarkId::new("30_digits_double_double", n), |b| {
                b.iter(|| {
                    ps.iter()
                        .map(|&p| {
                            Case::new(&mat, &ind, Dd::from_f64(p), Solution::Paper)
                                .unwrap()
                                .v_hat()
                                .unwrap()
                                .to_f64()
                        })
                        .sum::<f64>()
                })
            });
        }
    }
    g.finish();
}

fn bench_inverse(c: &mut Criterion) {
    let mut g = c.benchmark_group("inverse_alpha_of_v");
    g.sample_size(10);
    let mat = Material::paper();
    let ind = Indenter::new(89.0, 0.6, Coupling::On).unwrap();
    for d in [None, Some(30)] {
        match like(d) {
            None => g.bench_function(label(d), |b| {
                b.iter(|| {
                    case_for_speed(&mat, &ind, black_box(12.1), &0.0_f64, Solution::Paper)
                        .unwrap()
                        .p()
                        .to_f64()
                })
            }),
            Some(l) => g.bench_function(label(d), |b| {
                b.iter(|| {
                    case_for_speed(&mat, &ind, black_box(12.1), &l, Solution::Paper)
                        .unwrap()
                        .p()
                        .to_f64()
                })
            }),
        };
    }
    g.finish();
}

fn bench_genuine(c: &mut Criterion) {
    let mut g = c.benchmark_group("genuine_solve");
    g.sample_size(10);
    let mat = Material::paper();
    let ind = indenter();
    g.bench_function("f64", |b| {
        b.iter(|| {
            genuine::GenuineCase::solve(
                &mat,
                &ind,
                black_box(0.3),
                genuine::SolveOptions::default(),
            )
            .unwrap()
            .v_hat()
        })
    });
    // what `wedge solve --solution genuine --digits 30` runs: double-double, with the
    // options of its 104 bits
    let dd = Dd::from_f64(0.3);
    let dd_opts = genuine::SolveOptions::for_precision(dd.prec());
    g.bench_function(label(Some(30)), |b| {
        b.iter(|| {
            genuine::GenuineCase::solve(&mat, &ind, black_box(dd), dd_opts.clone())
                .unwrap()
                .v_hat()
                .to_f64()
        })
    });
    // the same on MPFR at the bits of 30 digits plus the guard bits (what it ran before)
    let l = like(Some(30)).unwrap();
    let p = l.lit(0.3);
    let opts = genuine::SolveOptions::for_precision(l.prec());
    g.bench_function("30_digits_mpfr", |b| {
        b.iter(|| {
            genuine::GenuineCase::solve(&mat, &ind, black_box(p.clone()), opts.clone())
                .unwrap()
                .v_hat()
                .to_f64()
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    // no plots: the figures' plotters build carries no system font for criterion's charts
    config = Criterion::default().without_plots();
    targets = bench_rayleigh, bench_case_build, bench_stress_profile, bench_full_solve, bench_curve, bench_inverse, bench_genuine
}
criterion_main!(benches);
