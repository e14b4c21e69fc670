//! The plotting layer: a figure is a [`Page`] of side-by-side [`Panel`]s, each a set of line
//! [`Series`] (solid, dashed or dotted), filled [`Cell`]s and text [`Note`]s on linear or
//! logarithmic axes. [`save`] draws a page into `<name>.svg` and renders that SVG,
//! anti-aliased, into `<name>.png` ([`render_png`]); both use the DejaVu Sans font embedded
//! from the `dejavu` crate (no system font library is needed).

use std::path::{Path, PathBuf};
use std::sync::{Arc, Once, OnceLock};

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{register_font, FontStyle};
use resvg::tiny_skia::{self, Pixmap, Transform};
use resvg::usvg::{fontdb, Options, Tree};

use super::{FigError, Result};

/// A colour as (red, green, blue).
pub type Rgb = (u8, u8, u8);

/// Line dash.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dash {
    /// Solid line.
    Solid,
    /// Dashed line.
    Dashed,
    /// Dotted line.
    Dotted,
}

/// A polyline with its style and legend label.
#[derive(Clone, Debug)]
pub struct Series {
    /// Legend label (`None`: not in the legend).
    pub label: Option<String>,
    /// Points in data coordinates.
    pub points: Vec<(f64, f64)>,
    /// Colour.
    pub color: Rgb,
    /// Dash.
    pub dash: Dash,
    /// Stroke width in pixels.
    pub width: u32,
}

impl Series {
    /// A series of width 2.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, color: Rgb, dash: Dash) -> Self {
        Series {
            label: Some(label.into()),
            points,
            color,
            dash,
            width: 2,
        }
    }
    /// The same series with another stroke width.
    pub fn width(mut self, w: u32) -> Self {
        self.width = w;
        self
    }
}

/// A filled rectangle in data coordinates (a cell of a map).
#[derive(Clone, Debug)]
pub struct Cell {
    /// Lower-left corner.
    pub from: (f64, f64),
    /// Upper-right corner.
    pub to: (f64, f64),
    /// Fill colour.
    pub color: Rgb,
}

/// A text label in data coordinates (its upper-left corner at the point).
#[derive(Clone, Debug)]
pub struct Note {
    /// Position.
    pub at: (f64, f64),
    /// Text.
    pub text: String,
    /// Colour.
    pub color: Rgb,
    /// Font size in pixels.
    pub size: u32,
}

/// An axis: label, range, linear or logarithmic.
#[derive(Clone, Debug)]
pub struct Axis {
    /// Label (with the normalisation).
    pub label: String,
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
    /// Logarithmic scale.
    pub log: bool,
}

impl Axis {
    /// A linear axis.
    pub fn lin(label: impl Into<String>, lo: f64, hi: f64) -> Self {
        Axis {
            label: label.into(),
            lo,
            hi,
            log: false,
        }
    }
    /// A logarithmic axis.
    pub fn log(label: impl Into<String>, lo: f64, hi: f64) -> Self {
        Axis {
            label: label.into(),
            lo,
            hi,
            log: true,
        }
    }
    /// A linear axis spanning `values` with a margin of `pad` times the span on each side.
    pub fn fit(label: impl Into<String>, values: impl IntoIterator<Item = f64>, pad: f64) -> Self {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in values.into_iter().filter(|v| v.is_finite()) {
            lo = lo.min(v);
            hi = hi.max(v);
        }
        if lo >= hi || !lo.is_finite() || !hi.is_finite() {
            let c = if lo.is_finite() { lo } else { 0.0 };
            lo = c - 1.0;
            hi = c + 1.0;
        }
        let d = (hi - lo) * pad;
        Axis::lin(label, lo - d, hi + d)
    }
    /// A logarithmic axis spanning the positive `values`, widened to whole decades.
    pub fn fit_log(label: impl Into<String>, values: impl IntoIterator<Item = f64>) -> Self {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in values.into_iter().filter(|v| v.is_finite() && *v > 0.0) {
            lo = lo.min(v);
            hi = hi.max(v);
        }
        if lo >= hi || !lo.is_finite() || !hi.is_finite() {
            let c = if lo.is_finite() { lo } else { 1.0 };
            lo = c / 10.0;
            hi = c * 10.0;
        }
        Axis::log(
            label,
            10f64.powf(lo.log10().floor()),
            10f64.powf(hi.log10().ceil()),
        )
    }
}

/// A colour bar drawn at the right of a panel: a strip of colours from the bottom (`colors[0]`)
/// to the top, ticks at fractions of its height, and a label above it.
#[derive(Clone, Debug)]
pub struct ColorBar {
    /// Label, drawn above the bar.
    pub label: String,
    /// Colours, bottom to top, evenly spaced.
    pub colors: Vec<Rgb>,
    /// Ticks: position as a fraction of the height (0 bottom, 1 top) and text.
    pub ticks: Vec<(f64, String)>,
}

/// Width in pixels taken from a panel by its colour bar.
pub const COLORBAR_WIDTH: u32 = 150;

/// Where the legend goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Legend {
    /// Upper left corner.
    UpperLeft,
    /// Upper right corner.
    UpperRight,
    /// Lower right corner.
    LowerRight,
}

/// One chart.
#[derive(Clone, Debug)]
pub struct Panel {
    /// Caption.
    pub title: String,
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
    /// Filled cells, drawn first.
    pub cells: Vec<Cell>,
    /// Lines, in legend order.
    pub series: Vec<Series>,
    /// Text labels, drawn last.
    pub notes: Vec<Note>,
    /// Legend position.
    pub legend: Legend,
    /// Colour bar at the right (`None`: no colour bar).
    pub colorbar: Option<ColorBar>,
}

impl Panel {
    /// A panel without data.
    pub fn new(title: impl Into<String>, x: Axis, y: Axis, legend: Legend) -> Self {
        Panel {
            title: title.into(),
            x,
            y,
            cells: Vec::new(),
            series: Vec::new(),
            notes: Vec::new(),
            legend,
            colorbar: None,
        }
    }
}

/// A figure: panels side by side.
#[derive(Clone, Debug)]
pub struct Page {
    /// File stem.
    pub name: &'static str,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Panels, left to right (or top to bottom when `stacked`; more than three side by side
    /// fill two columns row by row).
    pub panels: Vec<Panel>,
    /// Panels one above the other instead of side by side.
    pub stacked: bool,
}

/// Font family name under which DejaVu Sans is registered.
pub const FONT: &str = "sans-serif";

/// Register the embedded DejaVu Sans fonts (once per process).
pub fn register_fonts() -> Result<()> {
    static ONCE: Once = Once::new();
    let mut ok = true;
    ONCE.call_once(|| {
        ok = register_font(FONT, FontStyle::Normal, dejavu::sans::regular()).is_ok()
            && register_font(FONT, FontStyle::Bold, dejavu::sans::bold()).is_ok()
            && register_font(FONT, FontStyle::Italic, dejavu::sans::oblique()).is_ok();
    });
    if ok {
        Ok(())
    } else {
        Err(FigError("cannot register the embedded DejaVu font".into()))
    }
}

fn draw_err<E: std::fmt::Display>(name: &str) -> impl Fn(E) -> FigError + '_ {
    move |e| FigError(format!("drawing {name}: {e}"))
}

/// Draw `page` into `<dir>/<name>.svg`, and render that SVG into `<dir>/<name>.png` of the
/// page's size in pixels.
pub fn save(dir: &Path, page: &Page) -> Result<Vec<PathBuf>> {
    register_fonts()?;
    let png = dir.join(format!("{}.png", page.name));
    let svg = dir.join(format!("{}.svg", page.name));
    let mut text = String::new();
    {
        let root =
            SVGBackend::with_string(&mut text, (page.width, page.height)).into_drawing_area();
        draw_page(&root, page)?;
        root.present().map_err(draw_err(page.name))?;
    }
    let write = |path: &Path, bytes: &[u8]| {
        std::fs::write(path, bytes)
            .map_err(|e| FigError(format!("cannot write {}: {e}", path.display())))
    };
    write(&svg, text.as_bytes())?;
    let bytes = render_png(&text, page.width, page.height)
        .map_err(|e| FigError(format!("drawing {}: {}", page.name, e.0)))?;
    write(&png, &bytes)?;
    Ok(vec![png, svg])
}

/// Family of the DejaVu Sans faces embedded from the `dejavu` crate.
const DEJAVU_SANS: &str = "DejaVu Sans";

/// The font database of [`render_png`]: the embedded DejaVu Sans faces (regular, bold,
/// oblique, bold oblique), which also stand for the generic `sans-serif` family that the SVG
/// names and for `serif`, the renderer's last resort (built once per process).
fn font_db() -> Arc<fontdb::Database> {
    static DB: OnceLock<Arc<fontdb::Database>> = OnceLock::new();
    DB.get_or_init(|| {
        let mut db = fontdb::Database::new();
        for face in [
            dejavu::sans::regular(),
            dejavu::sans::bold(),
            dejavu::sans::oblique(),
            dejavu::sans::bold_oblique(),
        ] {
            db.load_font_data(face.to_vec());
        }
        db.set_sans_serif_family(DEJAVU_SANS);
        db.set_serif_family(DEJAVU_SANS);
        Arc::new(db)
    })
    .clone()
}

/// Render an SVG document, anti-aliased, on a white background into a PNG of `width` by
/// `height` pixels (the document scaled to fill it); text is set in the embedded DejaVu Sans.
///
/// The drawing is moved by half a pixel: plotters writes whole-pixel coordinates meaning the
/// pixel itself, so a one-pixel line then covers its pixel exactly instead of half of two.
/// Rectangles (the cells of a map, the background) are filled with crisp edges: shifted, they
/// would otherwise leave half-covered seams between neighbouring cells.
pub fn render_png(svg: &str, width: u32, height: u32) -> Result<Vec<u8>> {
    let opt = Options {
        font_family: DEJAVU_SANS.into(),
        fontdb: font_db(),
        style_sheet: Some("rect { shape-rendering: crispEdges; }".into()),
        ..Options::default()
    };
    let tree = Tree::from_str(svg, &opt).map_err(|e| FigError(format!("parsing SVG: {e}")))?;
    let mut pixmap = Pixmap::new(width, height)
        .ok_or_else(|| FigError(format!("cannot make a {width}x{height} image")))?;
    pixmap.fill(tiny_skia::Color::WHITE);
    let size = tree.size();
    let scale = Transform::from_scale(width as f32 / size.width(), height as f32 / size.height())
        .pre_translate(0.5, 0.5);
    resvg::render(&tree, scale, &mut pixmap.as_mut());
    pixmap
        .encode_png()
        .map_err(|e| FigError(format!("encoding PNG: {e}")))
}

fn draw_page<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, page: &Page) -> Result<()> {
    root.fill(&WHITE).map_err(draw_err(page.name))?;
    let n = page.panels.len().max(1);
    let areas = root.split_evenly(if page.stacked {
        (n, 1)
    } else if n > 3 {
        (n.div_ceil(2), 2)
    } else {
        (1, n)
    });
    for (area, panel) in areas.iter().zip(&page.panels) {
        let (x, y) = (&panel.x, &panel.y);
        match (x.log, y.log) {
            (false, false) => draw_panel(area, panel, page.name, x.lo..x.hi, y.lo..y.hi)?,
            (true, true) => draw_panel(
                area,
                panel,
                page.name,
                (x.lo..x.hi).log_scale(),
                (y.lo..y.hi).log_scale(),
            )?,
            (true, false) => {
                draw_panel(area, panel, page.name, (x.lo..x.hi).log_scale(), y.lo..y.hi)?
            }
            (false, true) => {
                draw_panel(area, panel, page.name, x.lo..x.hi, (y.lo..y.hi).log_scale())?
            }
        }
    }
    Ok(())
}

/// Tick label: powers of ten as `1e-6` on a log axis; otherwise as few digits as the spacing
/// of the axis needs.
fn tick(v: f64, axis: &Axis) -> String {
    if axis.log {
        let e = v.log10().round();
        if (v / 10f64.powf(e) - 1.0).abs() < 1e-9 {
            return format!("1e{e}");
        }
        return format!("{v:.1e}");
    }
    let span = (axis.hi - axis.lo).abs();
    let digits = if span > 0.0 {
        (-(span / 10.0).log10().floor()).clamp(0.0, 8.0) as usize
    } else {
        2
    };
    let s = format!("{v:.digits$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

fn rgb(c: Rgb) -> RGBColor {
    RGBColor(c.0, c.1, c.2)
}

fn in_range(v: f64, a: &Axis) -> bool {
    v.is_finite() && (!a.log || v > 0.0)
}

/// The drawable runs of a polyline: split wherever a point is not finite (NaN marks a break)
/// or cannot be shown on a log axis; runs of one point are dropped.
fn runs(points: &[(f64, f64)], x: &Axis, y: &Axis) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    for &(px, py) in points {
        if in_range(px, x) && in_range(py, y) {
            cur.push((px, py));
        } else if !cur.is_empty() {
            out.push(std::mem::take(&mut cur));
        }
    }
    out.push(cur);
    out.retain(|r| r.len() > 1);
    out
}

fn draw_panel<DB, X, Y>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    name: &str,
    xs: X,
    ys: Y,
) -> Result<()>
where
    DB: DrawingBackend,
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let err = draw_err(name);
    let (w, _) = area.dim_in_pixel();
    let (main, bar) = match &panel.colorbar {
        Some(_) => {
            let (a, b) = area.split_horizontally(w.saturating_sub(COLORBAR_WIDTH));
            (a, Some(b))
        }
        None => (area.clone(), None),
    };
    let mut chart = ChartBuilder::on(&main)
        .caption(&panel.title, (FONT, 22))
        .margin(16)
        .x_label_area_size(60)
        .y_label_area_size(85)
        .build_cartesian_2d(xs, ys)
        .map_err(&err)?;
    let (xa, ya) = (panel.x.clone(), panel.y.clone());
    let xf = move |v: &f64| tick(*v, &xa);
    let yf = move |v: &f64| tick(*v, &ya);
    chart
        .configure_mesh()
        .x_desc(panel.x.label.as_str())
        .y_desc(panel.y.label.as_str())
        .label_style((FONT, 16))
        .axis_desc_style((FONT, 19))
        .x_labels(8)
        .y_labels(8)
        .x_label_formatter(&xf)
        .y_label_formatter(&yf)
        .light_line_style(RGBColor(235, 235, 235))
        .bold_line_style(RGBColor(210, 210, 210))
        .draw()
        .map_err(&err)?;

    chart
        .draw_series(
            panel
                .cells
                .iter()
                .map(|c| Rectangle::new([c.from, c.to], rgb(c.color).filled())),
        )
        .map_err(&err)?;

    let mut labelled = false;
    for s in &panel.series {
        let style = rgb(s.color).stroke_width(s.width);
        for (k, run) in runs(&s.points, &panel.x, &panel.y).into_iter().enumerate() {
            let anno = match s.dash {
                Dash::Solid => chart.draw_series(LineSeries::new(run, style)),
                Dash::Dashed => chart.draw_series(DashedLineSeries::new(run, 12, 7, style)),
                Dash::Dotted => chart.draw_series(DashedLineSeries::new(run, 3, 5, style)),
            }
            .map_err(&err)?;
            let Some(label) = s.label.as_ref().filter(|_| k == 0) else {
                continue;
            };
            labelled = true;
            // four strokes of a 26-pixel legend sample: overlapping (solid) or with gaps
            let segs: [(i32, i32); 4] = match s.dash {
                Dash::Solid => [(0, 7), (6, 13), (12, 20), (19, 26)],
                Dash::Dashed => [(0, 10), (16, 26), (16, 26), (16, 26)],
                Dash::Dotted => [(0, 3), (8, 11), (16, 19), (23, 26)],
            };
            anno.label(label.as_str()).legend(move |(x, y)| {
                let seg = |i: usize| PathElement::new(vec![(segs[i].0, 0), (segs[i].1, 0)], style);
                EmptyElement::at((x, y)) + seg(0) + seg(1) + seg(2) + seg(3)
            });
        }
    }

    for n in &panel.notes {
        chart
            .draw_series(std::iter::once(Text::new(
                n.text.clone(),
                n.at,
                (FONT, n.size).into_font().color(&rgb(n.color)),
            )))
            .map_err(&err)?;
    }

    if labelled {
        let pos = match panel.legend {
            Legend::UpperLeft => SeriesLabelPosition::UpperLeft,
            Legend::UpperRight => SeriesLabelPosition::UpperRight,
            Legend::LowerRight => SeriesLabelPosition::LowerRight,
        };
        chart
            .configure_series_labels()
            .position(pos)
            .margin(12)
            .legend_area_size(34)
            .background_style(WHITE.mix(0.9))
            .border_style(RGBColor(120, 120, 120))
            .label_font((FONT, 16))
            .draw()
            .map_err(&err)?;
    }
    if let (Some(cb), Some(bar)) = (&panel.colorbar, bar) {
        let (_, ys) = chart.plotting_area().get_pixel_range();
        draw_colorbar(&bar, cb, ys, name)?;
    }
    Ok(())
}

/// Draw a colour bar into `area`, its strip spanning the absolute pixel rows `ys` (those of the
/// panel's plotting area).
fn draw_colorbar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    cb: &ColorBar,
    ys: std::ops::Range<i32>,
    name: &str,
) -> Result<()> {
    let err = draw_err(name);
    let (_, top) = area.get_base_pixel();
    let (_, h) = area.dim_in_pixel();
    let above = (ys.start - top).max(0);
    let below = (top + h as i32 - ys.end).max(0);
    let mut chart = ChartBuilder::on(area)
        .margin_top(above as u32)
        .margin_bottom(below as u32)
        .margin_left(8)
        .margin_right(4)
        .build_cartesian_2d(0.0..1.0, 0.0..1.0)
        .map_err(&err)?;
    let n = cb.colors.len().max(1) as f64;
    let strip = 0.26;
    chart
        .draw_series(cb.colors.iter().enumerate().map(|(k, c)| {
            let (a, b) = (k as f64 / n, (k + 1) as f64 / n);
            Rectangle::new([(0.0, a), (strip, b)], rgb(*c).filled())
        }))
        .map_err(&err)?;
    chart
        .draw_series(std::iter::once(Rectangle::new(
            [(0.0, 0.0), (strip, 1.0)],
            BLACK.stroke_width(1),
        )))
        .map_err(&err)?;
    let font = (FONT, 15).into_font().color(&BLACK);
    for (pos, text) in &cb.ticks {
        chart
            .draw_series(std::iter::once(PathElement::new(
                vec![(strip, *pos), (strip + 0.06, *pos)],
                BLACK.stroke_width(1),
            )))
            .map_err(&err)?;
        let style = font.clone().pos(Pos::new(HPos::Left, VPos::Center));
        chart
            .draw_series(std::iter::once(Text::new(
                text.clone(),
                (strip + 0.1, *pos),
                style,
            )))
            .map_err(&err)?;
    }
    area.draw_text(
        &cb.label,
        &(FONT, 16).into_font().color(&BLACK),
        (4, (above - 26).max(0)),
    )
    .map_err(&err)?;
    Ok(())
}
