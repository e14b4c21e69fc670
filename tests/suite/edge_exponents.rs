//! The edge exponent of the Lamb crate against the self-similar wedge of the first paper:
//! at its sub-Rayleigh edge the contact stress behaves as (p^2 - v^2)^(1/2 - Omega) (eq (40)),
//! and the frictionless, uncoupled wedge is a free edge (Signorini) moving at alpha.
use lamb::edge::EdgeLaw;
use lamb::HalfPlane;
use wedge::{Case, Indenter, Material, Solution};

#[test]
fn classical_wedge_edge_agrees_with_the_free_edge_exponent() {
    let mat = Material::paper();
    let m = mat.m(&0.0_f64);
    let hp = HalfPlane::new(m).unwrap();
    for theta in [80.0, 86.0, 89.0] {
        let ind = Indenter::classical(theta).unwrap();
        for p in [0.05, 0.2, 0.35, 0.45] {
            let case = Case::new(&mat, &ind, p, Solution::Paper).unwrap();
            // the stress exponent of eq (40) at the edge, from the wedge crate's Omega
            let wedge_exponent = 0.5 - case.omega(&p);
            let e = hp.edge_behaviour(p, EdgeLaw::Signorini).unwrap();
            assert!(
                (wedge_exponent - e.selected).abs() < 1e-12,
                "Theta {theta}, p {p}: wedge {wedge_exponent}, edge call {}",
                e.selected
            );
            // and H's declared edge exponent is -1/2 + Omega
            assert!((case.edge_exponent() + e.selected).abs() < 1e-12);
        }
    }
}
