//! A case file's reference series (`[[references]]`): reading the measured CSV a case names, so that a missing
//! or malformed file is an error when the case is read, before the run. The comparisons are in
//! `validation::references`.

use super::CaseFile;
use std::path::Path;

/// The first `n` columns of the rows of a CSV whose first `n` fields are all finite numbers (rows that are not:
/// a header, notes, and `#` lines, are skipped), as `n` columns; the first (a time) must increase. An error names
/// the file.
pub fn numeric_columns(path: &Path, n: usize) -> anyhow::Result<Vec<Vec<f64>>> {
    let text = std::fs::read_to_string(path).map_err(|e| anyhow::anyhow!("{}: cannot read: {e}", path.display()))?;
    let mut rd = csv::ReaderBuilder::new()
        .has_headers(false)
        .comment(Some(b'#'))
        .flexible(true)
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let mut cols = vec![Vec::new(); n];
    for rec in rd.records() {
        let rec = rec.map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
        let row: Option<Vec<f64>> = (0..n)
            .map(|k| rec.get(k).and_then(|s| s.parse::<f64>().ok()).filter(|x| x.is_finite()))
            .collect();
        if let Some(row) = row {
            for (c, v) in cols.iter_mut().zip(row) {
                c.push(v);
            }
        }
    }
    anyhow::ensure!(
        cols[0].windows(2).all(|w| w[1] > w[0]),
        "{}: expected increasing times in the first column",
        path.display()
    );
    Ok(cols)
}

/// The (time, value) rows of a reference CSV: its first two numeric columns ([`numeric_columns`]).
pub fn load(path: &Path) -> anyhow::Result<(Vec<f64>, Vec<f64>)> {
    let mut cols = numeric_columns(path, 2)?;
    anyhow::ensure!(
        cols[0].len() >= 2,
        "{}: expected at least two rows of two numeric columns (time, value), found {}",
        path.display(),
        cols[0].len()
    );
    let v = cols.pop().unwrap_or_default();
    let t = cols.pop().unwrap_or_default();
    Ok((t, v))
}

/// Checks that every reference file of a case read from disk can be loaded (called when the case is read,
/// so that a missing or malformed file is an error before the run).
pub fn check_files(case: &CaseFile, file: &str) -> Result<(), crate::input_error::InputError> {
    for (k, r) in case.references.iter().enumerate() {
        load(&r.path(case)).map_err(|e| {
            crate::input_error::InputError::field(
                file,
                &format!("references[{k}].file"),
                format!("a readable reference: {e}"),
            )
        })?;
    }
    Ok(())
}
