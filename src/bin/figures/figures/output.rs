//! The CSV of a figure's data: `#` header lines (library version, parameters, precision, the
//! meaning of each column), one header row of column names, then the rows.
//!
//! Numbers are written in Rust's shortest round-trip scientific form, so that parsing a cell
//! gives back the very f64 that was plotted.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::{FigError, Result};

/// One CSV cell.
#[derive(Clone, Debug)]
pub enum Cell {
    /// A number (non-finite numbers are written as `nan`, `inf`, `-inf`).
    Num(f64),
    /// Text (must not contain commas or newlines).
    Text(String),
    /// An empty cell (the column does not apply to this row).
    Empty,
}

impl From<f64> for Cell {
    fn from(x: f64) -> Self {
        Cell::Num(x)
    }
}

impl From<&str> for Cell {
    fn from(s: &str) -> Self {
        Cell::Text(s.to_string())
    }
}

/// A column: its name (the header row) and its meaning (a `#` line).
#[derive(Clone, Copy, Debug)]
pub struct Column {
    /// Name, spelling out the normalisation (`sigma_over_mu_cot_theta`, ...).
    pub name: &'static str,
    /// Meaning, written into the header.
    pub meaning: &'static str,
}

/// A figure's data table.
#[derive(Clone, Debug)]
pub struct Table {
    /// Figure name.
    pub figure: &'static str,
    /// What the figure shows (one line).
    pub title: String,
    /// Parameter lines (without the leading `# `).
    pub parameters: Vec<String>,
    /// Columns.
    pub columns: Vec<Column>,
    /// Rows, each as long as `columns`.
    pub rows: Vec<Vec<Cell>>,
}

/// The precision line of every header.
pub const PRECISION: &str =
    "precision: f64 (IEEE double, 53-bit significand); library quadrature tolerance eps^0.9";

impl Table {
    /// An empty table.
    pub fn new(figure: &'static str, title: impl Into<String>, columns: Vec<Column>) -> Self {
        Table {
            figure,
            title: title.into(),
            parameters: Vec::new(),
            columns,
            rows: Vec::new(),
        }
    }

    /// Add a parameter line.
    pub fn param(&mut self, line: impl Into<String>) {
        self.parameters.push(line.into());
    }

    /// Add a row; errors if its length differs from the number of columns.
    pub fn push(&mut self, row: Vec<Cell>) -> Result<()> {
        if row.len() != self.columns.len() {
            return Err(FigError(format!(
                "{}: row of {} cells for {} columns",
                self.figure,
                row.len(),
                self.columns.len()
            )));
        }
        self.rows.push(row);
        Ok(())
    }

    /// The CSV text.
    pub fn render(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "# dyncontact {} figures: {}",
            dyncontact::VERSION,
            self.figure
        );
        let _ = writeln!(s, "# {}", self.title);
        for p in &self.parameters {
            let _ = writeln!(s, "# {p}");
        }
        let _ = writeln!(s, "# {PRECISION}");
        for c in &self.columns {
            let _ = writeln!(s, "# column {}: {}", c.name, c.meaning);
        }
        let names: Vec<&str> = self.columns.iter().map(|c| c.name).collect();
        let _ = writeln!(s, "{}", names.join(","));
        for row in &self.rows {
            let cells: Vec<String> = row
                .iter()
                .map(|c| match c {
                    Cell::Num(x) => format!("{x:e}"),
                    Cell::Text(t) => t.clone(),
                    Cell::Empty => String::new(),
                })
                .collect();
            let _ = writeln!(s, "{}", cells.join(","));
        }
        s
    }

    /// Write `<dir>/<figure>.csv`.
    pub fn write(&self, dir: &Path) -> Result<PathBuf> {
        let path = dir.join(format!("{}.csv", self.figure));
        std::fs::write(&path, self.render())
            .map_err(|e| FigError(format!("cannot write {}: {e}", path.display())))?;
        Ok(path)
    }
}
