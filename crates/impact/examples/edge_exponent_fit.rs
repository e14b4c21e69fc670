//! The local exponent of the contact pressure at an edge moving at a constant speed, fitted to
//! the transient solver's pressures over two decades of the distance from the edge, against
//! `lamb::edge`'s prediction (`docs/impact.md`, section 8).
//!
//! A rigid wedge (half-angle 80 deg) driven at constant speed into the half-plane
//! (nu = 0.25) is self-similar: with the `kinematic` law its edge moves at D = V tan(Theta),
//! chosen in each speed range (between c_R and c1 the kinematic problem has no solution,
//! `docs/edge.md`, section 5); with the `signorini` law at the free edge's own speed, driven at
//! V = 0.3, 0.523, 0.9, 0.958 and 0.54637 s c1 (s the face slope: sub-Rayleigh, Rayleigh-shear
//! at 0.555 c1, two transonic edges, Rayleigh-shear at 0.572 c1). The
//! pressures of the last 30 percent of the steps, in the edge's scale s = d/b, are fitted by
//! s^lambda (c_0 + c_1 s + c_2 s^2 + c_3 s^3) over two decades of s
//! (`impact::edge_fit::fit_self_similar_edge`; b = R at the end).
//!
//! `cargo run --release -p impact --features examples --example edge_exponent_fit -- [cells [case]]` (b at the end
//! in cells, default 800; one case of the list by its index).
use impact::edge_fit::{fit_self_similar_edge, EdgeExponentCheck};
use impact::{Drive, EdgeLaw, ImpactCase, Profile};

fn main() {
    let cells: f64 = std::env::args()
        .nth(1)
        .map(|a| a.parse().expect("cells: a number"))
        .unwrap_or(800.0);
    let nu = 0.25;
    let theta: f64 = 80.0;
    // an optional second argument runs one case (its index in the list)
    let only: Option<usize> = std::env::args()
        .nth(2)
        .map(|a| a.parse().expect("case index: a number"));
    let cases = [
        (EdgeLaw::Kinematic, 0.3),
        (EdgeLaw::Kinematic, 0.555),
        (EdgeLaw::Kinematic, 0.97),
        (EdgeLaw::Kinematic, 2.0),
        (EdgeLaw::Signorini, 0.3),
        (EdgeLaw::Signorini, 0.523),
        (EdgeLaw::Signorini, 0.9),
        (EdgeLaw::Signorini, 0.958),
        (EdgeLaw::Signorini, 0.5463666),
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
        let fit = fit_self_similar_edge(&sol);
        match fit {
            Ok(EdgeExponentCheck {
                behaviour: e,
                fit: f,
            }) => println!(
                "{:<10} {:.4}  {:<15}  {:+.4}    {:+.4}    {:+.1e}  {:.2}     {:.1}",
                law.name(),
                e.speed_over_c1,
                e.range.name(),
                e.selected,
                f.lambda,
                f.lambda - e.selected,
                (f.s_range.1 / f.s_range.0).log10(),
                secs
            ),
            Err(err) => println!("{:<10} {d:.4}  no fit: {err}", law.name()),
        }
    }
}
