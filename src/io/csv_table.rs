//! A table of named f64 columns (time series, error tables), written as CSV (and read back).

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

    /// Reads a table this module wrote (a header, then numeric rows); the error names the file, and the row
    /// and column of a bad value.
    pub fn read(path: &Path) -> anyhow::Result<Table> {
        let file = path.display();
        let mut r = csv::Reader::from_path(path).map_err(|e| anyhow::anyhow!("{file}: cannot read: {e}"))?;
        let columns: Vec<String> = r
            .headers()
            .map_err(|e| anyhow::anyhow!("{file}: header: {e}"))?
            .iter()
            .map(String::from)
            .collect();
        let mut t = Table::new(columns);
        for (k, rec) in r.records().enumerate() {
            let rec = rec.map_err(|e| anyhow::anyhow!("{file}: row {}: {e}", k + 1))?;
            let row = rec
                .iter()
                .enumerate()
                .map(|(c, v)| {
                    v.trim().parse::<f64>().map_err(|_| {
                        anyhow::anyhow!(
                            "{file}: row {}, column `{}`: expected a number, got `{v}`",
                            k + 1,
                            t.columns[c]
                        )
                    })
                })
                .collect::<anyhow::Result<Vec<f64>>>()?;
            anyhow::ensure!(
                row.len() == t.columns.len(),
                "{file}: row {}: expected {} values, got {}",
                k + 1,
                t.columns.len(),
                row.len()
            );
            t.rows.push(row);
        }
        Ok(t)
    }
}
