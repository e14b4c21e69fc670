//! The edge's error on single grids (`docs/impact.md`, section 4):
//!
//! - `edge_error_study REF DX1 DX2 ...`: the reference case (`impact::REFERENCE`, Signorini
//!   law) at each DX against one grid at REF, the largest error of b, h and the force over
//!   c1 t/R in [0.5, 2), [2, 5), [5, 7.5), [7.5, 10) relative to each one's peak, b as
//!   reported (`RAW=1`: the per-step edges interpolated to t_n; `KAPPA=K`: another time step;
//!   `SERIES=T0,T1,EVERY` also prints b's error step by step, in 1e-6 R, at t_n and per step);
//! - `edge_error_study hertz DX1 ...`: a parabola driven at 1e-3 c1, b against Hertz's edge
//!   for its own force, the largest and mean distance in cells over three time ranges
//!   (`THETA=1` prints the distance against the edge's place in its cell);
//! - `edge_error_study wedge P DX1 ...`: the driven wedge of the bridge test at alpha = P c1,
//!   the fitted edge speed, the edge's offset and lag (`SEQ=EVERY` prints
//!   (b_n - alpha t_b)/(alpha dt) step by step).
use impact::{Drive, EdgeLaw, ImpactCase, Profile};

fn single(dx: f64) -> (impact::case::Run, f64) {
    let mut case = ImpactCase::reference(EdgeLaw::Signorini);
    case.dx = dx;
    case.levels = 1;
    if let Ok(k) = std::env::var("KAPPA") {
        case.kappa = k.parse().expect("a number");
    }
    let t0 = std::time::Instant::now();
    let sol = case.solve(|_| {}).expect("solves");
    (sol.runs[0].clone(), t0.elapsed().as_secs_f64())
}

/// The reported edge at t_n, or with `RAW` set the per-step edges interpolated to t_n.
fn edge(run: &impact::case::Run, n: usize) -> f64 {
    if std::env::var("RAW").is_ok() {
        run.edge_interpolated(n).expect("a step")
    } else {
        run.edge_at(n).expect("a step")
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args[0] == "hertz" {
        for a in &args[1..] {
            let dx: f64 = a.parse().unwrap();
            let nu = 0.25;
            let mut c = ImpactCase::new(
                nu,
                Profile::Parabola { radius: 1.0 },
                Drive::Speed(1e-3),
                EdgeLaw::Signorini,
                5.0,
            );
            c.dx = dx;
            c.levels = 1;
            let sol = c.solve(|_| {}).unwrap();
            let run = &sol.runs[0];
            let n = run.steps.len();
            if std::env::var("THETA").is_ok() {
                for m in (1..n).step_by(7) {
                    let st = run.step(m).unwrap();
                    if st.t < 3.0 || st.t > 4.0 {
                        continue;
                    }
                    let (b, force) = (run.edge_at(m).unwrap(), run.force_at(m).unwrap());
                    let hertz = (force * 2.0 * (1.0 - nu) / std::f64::consts::PI).sqrt();
                    let theta = st.b / dx + 0.5 - (st.b / dx + 0.5).floor();
                    print!("{theta:.2}:{:+.4} ", (b - hertz) / dx);
                }
                println!();
            }
            for (lo, hi) in [(1.0, 2.0), (2.0, 3.5), (3.5, 5.0)] {
                let (mut mx, mut sm, mut cnt) = (0.0f64, 0.0, 0.0);
                for m in 1..n {
                    let t = run.step(m).unwrap().t;
                    if t < lo || t >= hi {
                        continue;
                    }
                    let (b, force) = (run.edge_at(m).unwrap(), run.force_at(m).unwrap());
                    let hertz = (force * 2.0 * (1.0 - nu) / std::f64::consts::PI).sqrt();
                    let e = (b - hertz) / dx;
                    mx = mx.max(e.abs());
                    sm += e;
                    cnt += 1.0;
                }
                print!("[{lo},{hi}) max {mx:.4} mean {:+.4} (cells) | ", sm / cnt);
            }
            println!("dx {dx}");
        }
        return;
    }
    if args[0] == "wedge" {
        let p: f64 = args[1].parse().unwrap();
        for a in &args[2..] {
            let dx: f64 = a.parse().unwrap();
            let mat = wedge::Material::paper();
            let theta = 80.0f64;
            let ind = wedge::Indenter::classical(theta).unwrap();
            let case = wedge::Case::new(&mat, &ind, p, wedge::Solution::Paper).unwrap();
            let cot = 1.0 / theta.to_radians().tan();
            let v = case.v_hat().unwrap() * cot;
            let mut c = ImpactCase::new(
                mat.poisson(),
                Profile::Wedge { theta_deg: theta },
                Drive::Speed(v),
                EdgeLaw::Signorini,
                1.0,
            );
            c.dx = dx;
            c.levels = 1;
            let sol = c.solve(|_| {}).unwrap();
            let run = &sol.runs[0];
            let n = run.steps.len();
            let errs: Vec<f64> = run.steps[n - 40..]
                .iter()
                .enumerate()
                .map(|(i, s)| run.edge_at(n - 40 + i + 1).unwrap() / (p * s.t) - 1.0)
                .collect();
            let mean = errs.iter().sum::<f64>() / errs.len() as f64;
            let (lo, hi) = errs
                .iter()
                .fold((f64::MAX, f64::MIN), |a, &e| (a.0.min(e), a.1.max(e)));
            let pts: Vec<(f64, f64)> = run
                .steps
                .iter()
                .filter(|s| s.t >= 0.5)
                .map(|s| (s.t, s.b))
                .collect();
            let nn = pts.len() as f64;
            let (sx, sy, sxx, sxy) = pts.iter().fold((0.0, 0.0, 0.0, 0.0), |a, (x, y)| {
                (a.0 + x, a.1 + y, a.2 + x * x, a.3 + x * y)
            });
            let slope = (nn * sxy - sx * sy) / (nn * sxx - sx * sx);
            let icpt = (sy - slope * sx) / nn;
            println!("dx {dx}: alpha err {:.3e}, intercept/dx {:.3e}, (b - alpha t)/(alpha dt) at end {:.3e}", slope / p - 1.0, icpt / dx, (run.edge_at(n).unwrap() - p * run.steps[n-1].t) / (p * run.dt));
            if std::env::var("SEQ").is_ok() {
                for st in run
                    .steps
                    .iter()
                    .step_by(std::env::var("SEQ").unwrap().parse().unwrap())
                {
                    print!(
                        "{:.2}:{:.3} ",
                        st.t,
                        (st.b - p * st.edge_time) / (p * run.dt)
                    );
                }
                println!();
            }
            println!(
                "dx {dx}: b/(alpha t)-1 last {:.3e} mean {mean:.3e} range [{lo:.3e}, {hi:.3e}]",
                errs[errs.len() - 1]
            );
        }
        return;
    }
    let dref: f64 = args[0].parse().unwrap();
    let (rref, tref) = single(dref);
    let bpk = rref.steps.iter().map(|s| s.b).fold(0.0, f64::max);
    let hpk = rref.steps.iter().map(|s| s.h).fold(0.0, f64::max);
    let fpk = (0..rref.steps.len())
        .filter_map(|n| rref.force_at(n + 1))
        .fold(0.0, f64::max);
    println!("ref dx {dref} ({tref:.2} s): b peak {bpk:.8}");
    let windows = [(0.5, 2.0), (2.0, 5.0), (5.0, 7.5), (7.5, 10.0)];
    for a in &args[1..] {
        let dx: f64 = a.parse().unwrap();
        let (run, el) = single(dx);
        let ratio = (dx / dref).round() as usize;
        let mut eb = [0.0f64; 4];
        let mut eh = [0.0f64; 4];
        let mut ef = [0.0f64; 4];
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
                    print!(
                        "{:.3}:{:+.1}|{:+.1} ",
                        s.t,
                        (edge(&run, n + 1) - edge(&rref, m + 1)) * 1e6,
                        (s.b - r.b) * 1e6
                    );
                }
            }
            println!();
        }
        println!("dx {dx} ({el:.2} s): b {:.2e} {:.2e} {:.2e} {:.2e} | h {:.2e} {:.2e} {:.2e} {:.2e} | F {:.2e} {:.2e} {:.2e} {:.2e}",
            eb[0], eb[1], eb[2], eb[3], eh[0], eh[1], eh[2], eh[3], ef[0], ef[1], ef[2], ef[3]);
    }
}
