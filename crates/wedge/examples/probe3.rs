use wedge::*;
fn main() {
    let mat = Material::paper();
    let ind = Indenter::new(89.0, 0.6, Coupling::On).unwrap();
    let c = Case::new(&mat, &ind, 0.3, Solution::Paper).unwrap();
    for x in [
        0.3000001, 0.301, 0.35, 0.45, 0.49, 0.5, 0.52, 0.54, 0.6, 0.9, 0.99,
    ] {
        println!("x {x} gap {:?}", c.normal_gap(&x));
    }
}
