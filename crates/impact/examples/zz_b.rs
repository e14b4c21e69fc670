use impact::{EdgeLaw, ImpactCase};
fn main() {
    let dx: f64 = std::env::args().nth(1).unwrap().parse().unwrap();
    let mut case = ImpactCase::reference(EdgeLaw::Signorini);
    case.dx = dx;
    case.levels = 1;
    let sol = case.solve(|_| {}).unwrap();
    let run = &sol.runs[0];
    for (i, s) in run.steps.iter().enumerate() {
        println!(
            "{:.4} {:.10} {:.10e} {:.10e} {}",
            s.t,
            s.b,
            s.h,
            run.force_at(i + 1).unwrap(),
            s.k
        );
    }
}
