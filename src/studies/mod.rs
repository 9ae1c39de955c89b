//! Froude sweeps: a study file (`study_file`) resolved into cases, run resumably and in parallel (`runner`),
//! gathered into tables and a report against the published jets (`collect`, with what the difference was measured
//! to mean for an approximated hull, `gap_reading`) and figures (`figures`);
//! `status` tells where each case stands. Studies orchestrate; they hold no physics.

pub mod collect;
pub mod figures;
pub mod gap_reading;
pub mod lock;
pub mod runner;
pub mod ship3d;
pub mod status;
pub mod study_file;

use std::path::Path;

/// Gathers the finished cases of `study` in `out` into `jets.csv`, `comparison.csv`, `report.md`, the figures
/// and the manifest, holding the study folder's lock ([`lock`]). Returns the number of finished cases.
pub fn collect_all(study: &study_file::Study, out: &Path) -> anyhow::Result<usize> {
    lock::with_study_lock(out, || collect_locked(study, out))
}

fn collect_locked(study: &study_file::Study, out: &Path) -> anyhow::Result<usize> {
    let recs = runner::collect_finished(study, out);
    let hull = crate::geometry::hull_file::HullOffsets::read(&study.hull_path)?;
    let status = format!("{:?}", hull.meta.status).to_lowercase();
    let measured = crate::geometry::station_facts::measure(&crate::geometry::surface::HullSurface::new(&hull));
    let facts = match hull.meta.notes.get("honours") {
        Some(h) => format!("Its header says it honours: {h}. Measured on its surface: {measured}."),
        None => format!("Measured on its surface: {measured}."),
    };
    std::fs::create_dir_all(out).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", out.display()))?;
    collect::write_tables(
        out,
        &study.spec.name,
        &hull.meta.name,
        &status,
        &facts,
        &recs,
        study.cases.len(),
    )?;
    figures::write_all(out, &hull.meta.name, &recs, out)?;
    runner::write_manifest_locked(study, out)?;
    Ok(recs.len())
}
