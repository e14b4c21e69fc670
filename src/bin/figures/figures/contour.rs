//! Contour lines of a function tabulated on a rectangular grid (marching squares with linear
//! interpolation along the cell edges).

/// A function tabulated on the grid `xs` x `ys`: `z[i][j]` = `f(xs[i], ys[j])`.
pub struct Grid<'a> {
    /// Abscissae, increasing.
    pub xs: &'a [f64],
    /// Ordinates, increasing.
    pub ys: &'a [f64],
    /// Values, `z[i][j]` at `(xs[i], ys[j])`.
    pub z: &'a [Vec<f64>],
}

/// A straight piece of a contour line.
pub type Segment = ((f64, f64), (f64, f64));

impl Grid<'_> {
    /// The pieces of the level set z = `level`, one or two per grid cell it crosses.
    /// Cells with a non-finite corner are skipped.
    pub fn contour(&self, level: f64) -> Vec<Segment> {
        let mut out = Vec::new();
        let (nx, ny) = (self.xs.len(), self.ys.len());
        if nx < 2 || ny < 2 || self.z.len() < nx {
            return out;
        }
        for i in 0..nx - 1 {
            for j in 0..ny - 1 {
                // corners counter-clockwise from lower left
                let c = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
                let v: Vec<f64> = c
                    .iter()
                    .map(|&(a, b)| self.z[a].get(b).copied().unwrap_or(f64::NAN) - level)
                    .collect();
                if v.iter().any(|x| !x.is_finite()) {
                    continue;
                }
                // crossing points on the four edges (k, k+1)
                let mut pts = Vec::with_capacity(4);
                for k in 0..4 {
                    let (a, b) = (k, (k + 1) % 4);
                    if (v[a] < 0.0) != (v[b] < 0.0) {
                        let t = v[a] / (v[a] - v[b]);
                        let (pa, pb) = (self.point(c[a]), self.point(c[b]));
                        pts.push((pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1)));
                    }
                }
                match pts.len() {
                    2 => out.push((pts[0], pts[1])),
                    4 => {
                        // saddle: pair the crossings by the sign of the cell centre
                        let centre = v.iter().sum::<f64>() / 4.0;
                        if (centre < 0.0) == (v[0] < 0.0) {
                            out.push((pts[0], pts[3]));
                            out.push((pts[1], pts[2]));
                        } else {
                            out.push((pts[0], pts[1]));
                            out.push((pts[2], pts[3]));
                        }
                    }
                    _ => {}
                }
            }
        }
        out
    }

    fn point(&self, (i, j): (usize, usize)) -> (f64, f64) {
        (self.xs[i], self.ys[j])
    }
}

/// Segments as one polyline with NaN breaks (the plotting layer splits at NaN).
pub fn as_polyline(segments: &[Segment]) -> Vec<(f64, f64)> {
    let mut v = Vec::with_capacity(segments.len() * 3);
    for &(a, b) in segments {
        v.push(a);
        v.push(b);
        v.push((f64::NAN, f64::NAN));
    }
    v
}
