use wedge::*;
fn main() {
    let mat = Material::paper();
    let nu = mat.poisson();
    let cases = [
        ("A", 89.0, 0.6, Coupling::On, 0.3),
        ("B", 86.0, 0.001, Coupling::On, 0.3),
        ("C", 86.0, 0.6, Coupling::On, 0.3),
        ("D", 86.0, 0.0, Coupling::Off, 0.3),
        ("E", 89.0, 0.0, Coupling::On, 0.2),
        ("F", 86.0, 0.4, Coupling::On, 0.45),
        ("G", 89.0, 0.4, Coupling::Off, 0.1),
    ];
    for (name, th, g, c, p) in cases {
        let ind = Indenter::new(th, g, c).unwrap();
        for sol in [Solution::Paper, Solution::AsPrinted] {
            let t0 = std::time::Instant::now();
            let case = Case::new(&mat, &ind, p, sol).unwrap();
            let mt = case.matching().unwrap();
            let dt = t0.elapsed();
            println!("{name} {:?} omega0 {:.12} s0 {:.12} q {:.15} v {:.15} force {:.12} (2/(1-nu) = {:.12}) err {:.1e} inner n {} t {:?}",
                sol, case.omega0(), case.s0(), mt.q_hat, mt.v_hat, case.force_hat().unwrap(), 2.0/(1.0-nu), mt.rel_error, case.inner().len(), dt);
            println!(
                "   edge slip {:.12} follow {:.12} apex {:.12}",
                case.edge_slip_velocity_over_speed().unwrap(),
                case.edge_following_rate_over_speed().unwrap(),
                case.apex_u_r_over_speed_t()
                    .map(|w| w.value)
                    .unwrap_or(f64::NAN)
            );
            if sol == Solution::Paper {
                let s: Vec<String> = [0.05, 0.3, 0.6, 0.9]
                    .iter()
                    .map(|f| format!("{:.12}", case.stress_hat(&(f * p)).unwrap().value))
                    .collect();
                println!("   stress {}", s.join(" "));
            }
        }
    }
}
