use impact::striker::disk::Disk;
fn main() {
    let d = Disk::new(0.25).unwrap();
    let dx = 0.005;
    let dt = 0.01 * (1.0f64 / 3.0).sqrt();
    for (offs, steps) in [(8, 1000), (64, 1000), (128, 1000)] {
        let t0 = std::time::Instant::now();
        let _l = d
            .lattice_step_response_refined(dx, dt, offs, steps, 0.25)
            .unwrap();
        println!("offsets {offs} steps {steps}: {:?}", t0.elapsed());
    }
}
