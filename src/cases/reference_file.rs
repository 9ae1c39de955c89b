//! A case file's reference series (`[[references]]`): reading the measured CSV a case names, so that a missing
//! or malformed file is an error when the case is read, before the run. The comparisons are in
//! `validation::references`.

use super::CaseFile;
use std::path::Path;

/// The (time, value) rows of a reference CSV: its first two numeric columns; rows whose first two fields are
/// not numbers (a header, notes) and `#` lines are skipped; the times must increase.
pub fn load(path: &Path) -> anyhow::Result<(Vec<f64>, Vec<f64>)> {
    let text = std::fs::read_to_string(path).map_err(|e| anyhow::anyhow!("{}: cannot read: {e}", path.display()))?;
    let mut rd = csv::ReaderBuilder::new()
        .has_headers(false)
        .comment(Some(b'#'))
        .flexible(true)
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let (mut t, mut v) = (vec![], vec![]);
    for rec in rd.records() {
        let rec = rec.map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
        let num = |k: usize| rec.get(k).and_then(|s| s.parse::<f64>().ok()).filter(|x| x.is_finite());
        if let (Some(a), Some(b)) = (num(0), num(1)) {
            t.push(a);
            v.push(b);
        }
    }
    anyhow::ensure!(
        t.len() >= 2,
        "{}: expected at least two rows of two numeric columns (time, value), found {}",
        path.display(),
        t.len()
    );
    anyhow::ensure!(
        t.windows(2).all(|w| w[1] > w[0]),
        "{}: expected increasing times in the first column",
        path.display()
    );
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
