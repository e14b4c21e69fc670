//! The local exponent of the contact pressure at an edge moving at a constant speed, fitted to
//! the transient solver's pressures over two decades of the distance from the edge, against
//! `lamb::edge`'s prediction (`docs/impact.md`, section 8).
//!
//! A rigid wedge (half-angle 80 deg) driven at constant speed into the half-plane
//! (nu = 0.25) is self-similar: with the `kinematic` law its edge moves at D = V tan(Theta),
//! chosen in each speed range; with the `signorini` law at the free edge's own speed. The
//! pressures of the last 30 percent of the steps, in the edge's scale s = d/b, are fitted by
//! s^lambda (c_0 + c_1 s + c_2 s^2 + c_3 s^3) over two decades of s = d/b up to 0.5, or up
//! to 80 percent of the way to the nearest wave front from the first contact (at
//! s = 1 - c/D, c the fastest of c1, c2, c_R below D) when that is nearer (b = R at the end,
//! the four cells next to the edge left out; `impact::edge_fit`).
//!
//! `cargo run --release -p impact --example edge_exponent_fit -- [cells [case]]` (b at the end
//! in cells, default 800; one case of the list by its index).
use impact::edge_fit::fit_edge_exponent;
use impact::{Drive, EdgeLaw, ImpactCase, Profile};
use lamb::edge::SpeedRange;
use lamb::HalfPlane;

/// The fit's upper end s = d/b (the wedge's pressure has a logarithmic peak at its apex, s = 1).
const HI: f64 = 0.5;
/// The cells next to the edge left out of the fit (at least; a fast edge leaves out the cells
/// it crosses in two steps).
const MIN_CELLS: f64 = 4.0;

fn main() {
    let cells: f64 = std::env::args()
        .nth(1)
        .map(|a| a.parse().expect("cells: a number"))
        .unwrap_or(800.0);
    let nu = 0.25;
    let theta: f64 = 80.0;
    let hp = HalfPlane::from_poisson(nu).expect("nu");
    let m = *hp.m();
    let c_r = *hp.s_r();
    // an optional second argument runs one case (its index in the list)
    let only: Option<usize> = std::env::args()
        .nth(2)
        .map(|a| a.parse().expect("case index: a number"));
    let cases = [
        (EdgeLaw::Kinematic, 0.3),
        (EdgeLaw::Kinematic, 0.555),
        (EdgeLaw::Kinematic, 0.97),
        (EdgeLaw::Kinematic, 1.5),
        (EdgeLaw::Signorini, 0.3),
    ];
    println!(
        "law        D/c1    range            predicted  fitted     error     decades  seconds"
    );
    for (ci, (law, d)) in cases.into_iter().enumerate() {
        if only.is_some_and(|o| o != ci) {
            continue;
        }
        let v = d / theta.to_radians().tan();
        // the end time that takes the edge to b = R (the free edge's speed from a coarse run)
        let mut case = ImpactCase::new(
            nu,
            Profile::Wedge { theta_deg: theta },
            Drive::Speed(v),
            law,
            1.0 / d,
        );
        case.levels = 1;
        if law == EdgeLaw::Signorini {
            case.dx = 0.02;
            let coarse = case.solve(|_| {}).expect("the coarse case solves");
            let last = coarse.runs[0].steps.last().expect("steps");
            case.end = last.t / last.b;
        }
        case.dx = 1.0 / cells;
        let t0 = std::time::Instant::now();
        let sol = case.solve(|_| {}).expect("the case solves");
        let secs = t0.elapsed().as_secs_f64();
        let run = &sol.runs[0];
        let last = run.steps.last().expect("steps");
        // the edge's actual speed (the free edge's own): b over the last 30 percent
        let t_from = 0.7 * last.t;
        let first = run.steps.iter().find(|s| s.t >= t_from).expect("steps");
        let speed = (last.b - first.b) / (last.t - first.t);
        let e = hp.edge_behaviour(speed, law).expect("edge speed");
        // the cells next to the edge, at least those it crosses in two steps
        let min_cells = MIN_CELLS.max(2.0 * speed * case.kappa);
        let samples = run.edge_samples(t_from, min_cells);
        let bracket = (e.selected - 0.45, e.selected + 0.45);
        // the fronts from the first contact slower than the edge cross the contact at
        // s = 1 - c/D: the fit stays within 80 percent of the nearest
        let front = match e.range {
            SpeedRange::SubRayleigh => None,
            SpeedRange::RayleighShear => Some(c_r),
            SpeedRange::Transonic => Some(m),
            SpeedRange::Supersonic => Some(1.0),
        };
        let hi = front.map_or(HI, |c| HI.min(0.8 * (1.0 - c / speed)));
        let fit = fit_edge_exponent(&samples, (hi / 100.0, hi), bracket, 3, 40);
        match fit {
            Ok(f) => println!(
                "{:<10} {:.4}  {:<15}  {:+.4}    {:+.4}    {:+.1e}  {:.2}     {:.1}",
                law.name(),
                speed,
                e.range.name(),
                e.selected,
                f.lambda,
                f.lambda - e.selected,
                (f.s_range.1 / f.s_range.0).log10(),
                secs
            ),
            Err(err) => println!(
                "{:<10} {:.4}  {:<15}  {:+.4}    no fit: {err}",
                law.name(),
                speed,
                e.range.name(),
                e.selected
            ),
        }
    }
}
