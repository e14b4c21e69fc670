//! The figures of the `figures` binary: shared context, errors, the solution-variant styles,
//! the CSV writer ([`output`]), the plotting layer ([`plot`]), contour extraction
//! ([`contour`]) and the figures themselves ([`paper`]: the paper's Figs 3-7;
//! [`regime_map`]: the apex-regime map; [`field_snapshot`]: the stress field over the
//! half-plane at one instant).
//!
//! Every figure is a function `fn(&Ctx) -> Result<Summary>` that computes only the data it
//! draws, writes `<name>.csv`, `<name>.png` and `<name>.svg` into [`Ctx::out`], and reports
//! its progress through [`Ctx::progress`].

pub mod contour;
pub mod edge_exponents;
pub mod error_vs_time;
pub mod field_snapshot;
pub mod impact_accuracy;
pub mod impact_history;
pub mod impact_strikers;
pub mod output;
pub mod paper;
pub mod plot;
pub mod regime_map;
pub mod sphere_impact;

use std::fmt;
use std::path::PathBuf;

use indicatif::ProgressBar;
use wedge::{Indenter, Material, Solution, WedgeError};

use plot::{Dash, Rgb};

/// What every figure gets: where to write, how many points, where to report progress.
pub struct Ctx {
    /// Output directory (created if missing).
    pub out: PathBuf,
    /// Fewer points (for tests and previews); the data are computed exactly as in full mode.
    pub quick: bool,
    /// Progress of all figures together (units: computed points).
    pub progress: ProgressBar,
}

impl Ctx {
    /// `full` points, or `quick` points in quick mode.
    pub fn points(&self, full: usize, quick: usize) -> usize {
        if self.quick {
            quick
        } else {
            full
        }
    }
    /// Announce `n` more units of work.
    pub fn plan(&self, n: usize) {
        self.progress.inc_length(n as u64);
    }
    /// One unit of work done.
    pub fn tick(&self) {
        self.progress.inc(1);
    }
}

/// What a figure reports when done: the files written.
pub struct Summary {
    /// Paths written (CSV, PNG, SVG).
    pub files: Vec<PathBuf>,
    /// Number of computed data points.
    pub points: usize,
}

/// An error of a figure, as one line of text.
#[derive(Debug, Clone, PartialEq)]
pub struct FigError(pub String);

impl fmt::Display for FigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for FigError {}

impl From<WedgeError> for FigError {
    fn from(e: WedgeError) -> Self {
        FigError(e.to_string())
    }
}

impl From<impact::ImpactError> for FigError {
    fn from(e: impact::ImpactError) -> Self {
        FigError(e.to_string())
    }
}

/// Result alias of the figures.
pub type Result<T> = std::result::Result<T, FigError>;

/// How a solution variant is drawn: line dash and the name in legends and CSV columns.
#[derive(Clone, Copy, Debug)]
pub struct VariantStyle {
    /// The variant.
    pub solution: Solution,
    /// Its line dash.
    pub dash: Dash,
}

/// The solution variants of the paper's construction drawn side by side in fig3 and fig5, in
/// legend order: `paper` solid, `as-printed` dashed. The genuine solution ([`GENUINE`]) joins
/// them in fig5, fig6 and fig7.
pub const VARIANTS: &[VariantStyle] = &[
    VariantStyle {
        solution: Solution::Paper,
        dash: Dash::Solid,
    },
    VariantStyle {
        solution: Solution::AsPrinted,
        dash: Dash::Dashed,
    },
];

/// The genuine solution, drawn dotted (fig5, fig6, fig7).
pub const GENUINE: VariantStyle = VariantStyle {
    solution: Solution::Genuine,
    dash: Dash::Dotted,
};

/// V/(c1 cot Theta) in f64 for any solution variant ([`dyncontact::solve_at`]; the genuine
/// solution's error estimate, from its basis sizes, is far below plotting accuracy).
pub fn v_hat(mat: &Material, ind: &Indenter, p: f64, solution: Solution) -> Result<f64> {
    Ok(dyncontact::solve_at(mat, ind, solution, p)?.v_hat()?.value)
}

/// The paper's material (c1 = 1870.83 m/s, c2 = 1000 m/s).
pub fn material() -> Material {
    Material::paper()
}

/// Palette (colour-blind safe, after Okabe and Ito).
pub mod palette {
    use super::Rgb;
    /// Black.
    pub const BLACK: Rgb = (0, 0, 0);
    /// Blue.
    pub const BLUE: Rgb = (0, 114, 178);
    /// Vermillion.
    pub const RED: Rgb = (213, 94, 0);
    /// Grey.
    pub const GREY: Rgb = (120, 120, 120);
    /// Eight distinguishable colours (Okabe-Ito), cycled.
    pub const CYCLE: [Rgb; 8] = [
        (0, 0, 0),
        (230, 159, 0),
        (86, 180, 233),
        (0, 158, 115),
        (213, 94, 0),
        (0, 114, 178),
        (204, 121, 167),
        (120, 120, 120),
    ];
}

/// The k-th colour of [`palette::CYCLE`].
pub fn cycle_color(k: usize) -> Rgb {
    palette::CYCLE[k % palette::CYCLE.len()]
}

/// Shortest round-trip text of an f64, for legends and headers.
pub fn fmt_num(x: f64) -> String {
    format!("{x}")
}

/// n points of (0, 1): the interior points i/(n + 1), i = 1..n.
pub fn interior(n: usize) -> Vec<f64> {
    (1..=n).map(|i| i as f64 / (n + 1) as f64).collect()
}

/// n log-spaced points from `lo` to `hi` (both included), n >= 2.
pub fn logspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let (a, b) = (lo.ln(), hi.ln());
    (0..n)
        .map(|i| (a + (b - a) * i as f64 / (n - 1) as f64).exp())
        .collect()
}
