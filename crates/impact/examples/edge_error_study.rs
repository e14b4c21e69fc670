//! The edge's error on single grids (`docs/impact.md`, section 4):
//!
//! - `edge_error_study REF DX1 DX2 ...`: the reference case (`impact::REFERENCE`, Signorini
//!   law) at each DX against one grid at REF, the largest error of b, h and the force over
//!   c1 t/R in [0.5, 2), [2, 5), [5, 7.5), [7.5, 10) relative to each one's peak, b as
//!   reported (`RAW=1`: the per-step edges interpolated to t_n; `KAPPA=K`: another time step;
//!   `LAW=kinematic`: the kinematic law; `DRIVEN=V`: the parabola driven at V/c1; `END=T`:
//!   another end; `WINDOWS=0.02:0.1,0.1:0.5`: other ranges; `START=K`, `REF_START=K`: the
//!   start on grids 2^K times finer, `START_GRID=DX`: every run's start on the hand-over
//!   schedule of DX; `SERIES=T0,T1,EVERY` also prints b's error step by step, in 1e-6 R, at
//!   t_n and per step, and the force's in 1e-6 of its peak).
//!
//! The slowly driven parabola against Hertz's edge and the driven wedge's edge against the
//! wedge crate are the tests `slow_free_edge_follows_hertz` (`tests/suite/physics.rs`) and
//! `edge_model_makes_the_edge_error_smooth` (`tests/suite/bridge.rs`), which print what they
//! measure (`--nocapture`).
use impact::{EdgeLaw, ImpactCase};

fn single(dx: f64, start: usize, grid: Option<f64>) -> (impact::run::Run, f64) {
    let law = match std::env::var("LAW").as_deref() {
        Ok("kinematic") => EdgeLaw::Kinematic,
        _ => EdgeLaw::Signorini,
    };
    let mut case = ImpactCase::reference(law);
    if let Ok(v) = std::env::var("DRIVEN") {
        case.drive = impact::Drive::Speed(v.parse().expect("a speed V/c1"));
    }
    if let Ok(end) = std::env::var("END") {
        case.end = end.parse().expect("an end time");
    }
    case.dx = dx;
    case.levels = 1;
    case.start_halvings = start;
    case.start_grid = grid;
    if let Ok(k) = std::env::var("KAPPA") {
        case.kappa = k.parse().expect("a number");
    }
    let t0 = std::time::Instant::now();
    let sol = case.solve(|_| {}).expect("solves");
    (sol.runs[0].clone(), t0.elapsed().as_secs_f64())
}

/// The reported edge at t_n, or with `RAW` set the per-step edges interpolated to t_n.
fn edge(run: &impact::run::Run, n: usize) -> f64 {
    if std::env::var("RAW").is_ok() {
        run.edge_interpolated(n).expect("a step")
    } else {
        run.edge_at(n).expect("a step")
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let dref: f64 = args[0].parse().unwrap();
    let env = |k: &str| std::env::var(k).map_or(0, |v| v.parse().expect("a count"));
    let grid = std::env::var("START_GRID")
        .ok()
        .map(|v| v.parse().expect("a width"));
    let (rref, tref) = single(dref, env("REF_START"), grid);
    let bpk = rref.steps.iter().map(|s| s.b).fold(0.0, f64::max);
    let hpk = rref.steps.iter().map(|s| s.h).fold(0.0, f64::max);
    let fpk = (0..rref.steps.len())
        .filter_map(|n| rref.force_at(n + 1))
        .fold(0.0, f64::max);
    println!("ref dx {dref} ({tref:.2} s): b peak {bpk:.8}");
    let windows: Vec<(f64, f64)> = match std::env::var("WINDOWS") {
        Ok(v) => v
            .split(',')
            .map(|w| {
                let (lo, hi) = w.split_once(':').expect("LO:HI");
                (lo.parse().expect("a number"), hi.parse().expect("a number"))
            })
            .collect(),
        Err(_) => vec![(0.5, 2.0), (2.0, 5.0), (5.0, 7.5), (7.5, 10.0)],
    };
    for a in &args[1..] {
        let dx: f64 = a.parse().unwrap();
        let (run, el) = single(dx, env("START"), grid);
        let ratio = (dx / dref).round() as usize;
        let mut eb = vec![0.0f64; windows.len()];
        let mut eh = vec![0.0f64; windows.len()];
        let mut ef = vec![0.0f64; windows.len()];
        for (n, s) in run.steps.iter().enumerate() {
            let m = (n + 1) * ratio - 1;
            let Some(r) = rref.steps.get(m) else { continue };
            for (w, &(lo, hi)) in windows.iter().enumerate() {
                if s.t >= lo && s.t < hi {
                    let (bs, br) = (edge(&run, n + 1), edge(&rref, m + 1));
                    eb[w] = eb[w].max((bs - br).abs() / bpk);
                    eh[w] = eh[w].max((s.h - r.h).abs() / hpk);
                    if let (Some(f), Some(g)) = (run.force_at(n + 1), rref.force_at(m + 1)) {
                        ef[w] = ef[w].max((f - g).abs() / fpk);
                    }
                }
            }
        }
        if let Ok(v) = std::env::var("SERIES") {
            let mut it = v.split(',').map(|x| x.parse::<f64>().unwrap());
            let (lo, hi, every) = (
                it.next().unwrap(),
                it.next().unwrap(),
                it.next().unwrap() as usize,
            );
            for (n, s) in run.steps.iter().enumerate().step_by(every) {
                let m = (n + 1) * ratio - 1;
                let Some(r) = rref.steps.get(m) else { continue };
                if s.t >= lo && s.t < hi {
                    let df = match (run.force_at(n + 1), rref.force_at(m + 1)) {
                        (Some(f), Some(g)) => (f - g) / fpk * 1e6,
                        _ => f64::NAN,
                    };
                    print!(
                        "{:.3}:{:+.1}|{:+.1}|F{:+.0} ",
                        s.t,
                        (edge(&run, n + 1) - edge(&rref, m + 1)) * 1e6,
                        (s.b - r.b) * 1e6,
                        df
                    );
                }
            }
            println!();
        }
        let row = |e: &[f64]| {
            e.iter()
                .map(|v| format!("{v:.2e}"))
                .collect::<Vec<_>>()
                .join(" ")
        };
        println!(
            "dx {dx} ({el:.2} s): b {} | h {} | F {}",
            row(&eb),
            row(&eh),
            row(&ef)
        );
    }
}
