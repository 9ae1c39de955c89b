//! A table of named f64 columns (time series, error tables), written as CSV.

use super::atomic::write_atomic;
use std::path::Path;

/// Named columns of equal length; rows are appended one at a time.
#[derive(Clone, Debug, Default)]
pub struct Table {
    pub columns: Vec<String>,
    pub rows: Vec<Vec<f64>>,
}

impl Table {
    pub fn new(columns: Vec<String>) -> Self {
        Table { columns, rows: vec![] }
    }

    pub fn push(&mut self, row: Vec<f64>) {
        assert_eq!(row.len(), self.columns.len(), "row length does not match the header");
        self.rows.push(row);
    }

    /// A column by name.
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let k = self.columns.iter().position(|c| c == name)?;
        Some(self.rows.iter().map(|r| r[k]).collect())
    }

    pub fn to_csv(&self) -> Vec<u8> {
        let mut w = csv::Writer::from_writer(vec![]);
        w.write_record(&self.columns).expect("write to memory");
        for r in &self.rows {
            w.write_record(r.iter().map(|x| format!("{x:.9e}")))
                .expect("write to memory");
        }
        w.into_inner().expect("flush to memory")
    }

    pub fn write(&self, path: &Path) -> std::io::Result<()> {
        write_atomic(path, &self.to_csv())
    }
}
