//! The study folder's lock: whoever writes the study's shared files (`manifest.json`, `jets.csv`,
//! `comparison.csv`, `report.md`, the figures) holds an exclusive lock on `OUT/.study.lock` while it gathers
//! the finished cases and writes them. Several `--case N` jobs (a batch scheduler's array) finishing together
//! then write one after the other, and the last writer has gathered every case finished before it took the
//! lock, so the tables end complete whatever the order (test `concurrent_case_jobs_write_the_serial_tables`).
//! An OS file lock (`File::lock`, flock on Unix) is released when its holder exits, even by a crash.

use std::path::Path;

/// Name of the lock file in a study's output folder.
pub const FILE: &str = ".study.lock";

/// Runs `f` holding the study folder's lock (the folder is created if needed).
pub fn with_study_lock<T>(out: &Path, f: impl FnOnce() -> anyhow::Result<T>) -> anyhow::Result<T> {
    std::fs::create_dir_all(out).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", out.display()))?;
    let path = out.join(FILE);
    let file = std::fs::OpenOptions::new()
        .create(true)
        .truncate(false)
        .write(true)
        .open(&path)
        .map_err(|e| anyhow::anyhow!("cannot open the study lock {}: {e}", path.display()))?;
    file.lock()
        .map_err(|e| anyhow::anyhow!("cannot lock {}: {e}", path.display()))?;
    let r = f();
    drop(file);
    r
}
