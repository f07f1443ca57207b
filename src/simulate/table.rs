//! Tables of numbers written as CSV, and the atomic file write shared with the plots.

use std::path::Path;

use super::SimError;

/// How numbers are written in CSV. Both forms are deterministic, locale-free, and read by
/// pgfplots, spreadsheets, Python and Rust alike; non-finite values are written `nan`, `inf`,
/// `-inf`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum NumberFormat {
    /// The shortest scientific notation that reads back to the very same `f64` (Rust's `{:e}`):
    /// `1e-3`, `-2.5e0`, `3.3333333333333335e-1`.
    #[default]
    Shortest,
    /// Scientific notation with this many digits after the point (Rust's `{:.N$e}`):
    /// `Scientific(9)` writes `1.000000000e-3`.
    Scientific(usize),
}

impl NumberFormat {
    /// Formats one number.
    pub fn format(self, v: f64) -> String {
        if v.is_nan() {
            "nan".to_string()
        } else if v.is_infinite() {
            if v > 0.0 { "inf" } else { "-inf" }.to_string()
        } else {
            match self {
                Self::Shortest => format!("{v:e}"),
                Self::Scientific(digits) => format!("{v:.digits$e}"),
            }
        }
    }
}

/// A table of `f64` columns with a header row, written as CSV (comma-separated, `\n` line
/// ends, headers quoted when they hold a comma, a quote or a line break).
///
/// ```
/// use torseur::simulate::Table;
///
/// let mut table = Table::new(&["t (s)", "x (m)"]);
/// table.push_row(&[0.0, 1.0])?;
/// table.push_row(&[0.5, 0.25])?;
/// assert_eq!(table.to_csv(), "t (s),x (m)\n0e0,1e0\n5e-1,2.5e-1\n");
/// # Ok::<(), torseur::simulate::SimError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    headers: Vec<String>,
    columns: Vec<Vec<f64>>,
    format: NumberFormat,
}

impl Table {
    /// An empty table with these column headers (units included, e.g. `"t (s)"`).
    pub fn new(headers: &[&str]) -> Self {
        Self {
            headers: headers.iter().map(|h| h.to_string()).collect(),
            columns: vec![Vec::new(); headers.len()],
            format: NumberFormat::default(),
        }
    }

    /// The same table, written with `format`.
    pub fn with_format(mut self, format: NumberFormat) -> Self {
        self.format = format;
        self
    }

    /// The column headers.
    pub fn headers(&self) -> &[String] {
        &self.headers
    }

    /// Number of data rows.
    pub fn n_rows(&self) -> usize {
        self.columns.first().map_or(0, Vec::len)
    }

    /// Number of columns.
    pub fn n_cols(&self) -> usize {
        self.headers.len()
    }

    /// Column `j`, if `j < n_cols()`.
    pub fn column(&self, j: usize) -> Option<&[f64]> {
        self.columns.get(j).map(Vec::as_slice)
    }

    /// Appends a row.
    ///
    /// # Errors
    /// [`SimError::InvalidInput`] if `row.len() != n_cols()`.
    pub fn push_row(&mut self, row: &[f64]) -> Result<(), SimError> {
        if row.len() != self.n_cols() {
            return Err(SimError::InvalidInput(format!(
                "row of {} values for a table of {} columns",
                row.len(),
                self.n_cols()
            )));
        }
        for (column, v) in self.columns.iter_mut().zip(row) {
            column.push(*v);
        }
        Ok(())
    }

    /// Appends a column (e.g. a quantity computed from a trajectory, like a motor torque).
    ///
    /// # Errors
    /// [`SimError::InvalidInput`] if the table has columns and `values.len() != n_rows()`.
    pub fn push_column(&mut self, header: &str, values: Vec<f64>) -> Result<(), SimError> {
        if self.n_cols() > 0 && values.len() != self.n_rows() {
            return Err(SimError::InvalidInput(format!(
                "column \"{header}\" has {} values for a table of {} rows",
                values.len(),
                self.n_rows()
            )));
        }
        self.headers.push(header.to_string());
        self.columns.push(values);
        Ok(())
    }

    /// The CSV text.
    pub fn to_csv(&self) -> String {
        let mut out = String::new();
        let headers: Vec<String> = self.headers.iter().map(|h| csv_field(h)).collect();
        out.push_str(&headers.join(","));
        out.push('\n');
        for i in 0..self.n_rows() {
            for (j, column) in self.columns.iter().enumerate() {
                if j > 0 {
                    out.push(',');
                }
                out.push_str(&self.format.format(column[i]));
            }
            out.push('\n');
        }
        out
    }

    /// Writes the CSV text to `path`, atomically (see [`write_atomic`]).
    ///
    /// # Errors
    /// [`SimError::Io`] if the file cannot be written.
    pub fn write_csv(&self, path: impl AsRef<Path>) -> Result<(), SimError> {
        write_atomic(path.as_ref(), self.to_csv().as_bytes())
    }
}

/// Quotes a CSV field if it holds a comma, a double quote or a line break (RFC 4180).
fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// Writes `bytes` to `path` atomically ([`crate::output::write_atomic`]), as a [`SimError`].
///
/// # Errors
/// [`SimError::Io`] if the directory is not writable or the disk is full.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), SimError> {
    crate::atomic::write_atomic(path, bytes).map_err(|source| SimError::Io {
        op: "write",
        path: path.to_path_buf(),
        source,
    })
}
