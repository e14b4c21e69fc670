//! One genuine solve (Theta 89 deg, gamma 0.6, coupled, the paper's material) with its error
//! estimate and the raw probes behind it (the contour rule's level doubling, the differences
//! between basis degrees and collocation sets), for studying the estimate against solves with
//! other discretisation parameters:
//! `cargo run --release -p genuine --features examples --example probe_estimate -- BITS P [deg=N] [hq=F] [ht=F] [ct=F] [os=F]`
//! (hq, ht, ct multiply the default steps and tolerance; os sets the oversampling).
use genuine::{GenuineCase, SolveOptions};
use rug::Float;
use std::time::Instant;
use wedge::{Coupling, Indenter, Material};

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let bits: u32 = a[1].parse().unwrap();
    let p: f64 = a[2].parse().unwrap();
    let mut o = SolveOptions::for_precision(bits);
    for kv in &a[3..] {
        let (k, v) = kv.split_once('=').unwrap();
        let f: f64 = v.parse().unwrap();
        match k {
            "deg" => o.degree = f as usize,
            "hq" => o.h_quad *= f,
            "ht" => o.h_tanh *= f,
            "ct" => o.contour_tol *= f,
            "os" => o.oversample = f,
            _ => panic!("{k}"),
        }
    }
    let mat = Material::paper();
    let ind = Indenter::new(89.0, 0.6, Coupling::On).unwrap();
    let t = Instant::now();
    let g = GenuineCase::solve(&mat, &ind, Float::with_val(bits, p), o.clone()).unwrap();
    println!(
        "{:?} V {:.45} F {:.45} est {:.2e} res {:.1e} probe {:?} {:.1}s",
        (o.degree, o.h_quad, o.h_tanh, o.contour_tol),
        g.v_hat(),
        g.force_hat_with_error().0,
        g.error_estimate(),
        g.collocation_residual(),
        (g.contour_probe(), g.degree_differences()),
        t.elapsed().as_secs_f64()
    );
}
