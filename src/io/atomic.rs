//! Atomic writes: the data goes to a temporary file with a unique name in the same folder (`tempfile`), is
//! flushed, then renamed over `NAME`, so a reader (or a crash) never sees a half-written file, and two
//! processes writing the same file at once (a study's `--case N` jobs finishing together) each rename a
//! whole file of their own: the last rename wins, and neither fails. Which one wins is the caller's to
//! order (`studies::lock`).

use std::io::Write;
use std::path::Path;

pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    std::fs::create_dir_all(dir)?;
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let mut tmp = tempfile::Builder::new()
        .prefix(&format!(".{name}."))
        .suffix(".tmp")
        .tempfile_in(dir)?;
    tmp.write_all(bytes)?;
    tmp.as_file().sync_all()?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Regression: every writer used the same `NAME.tmp`, so two processes writing one file at once could
    /// rename each other's half-written data or fail on a temporary file the other had already renamed.
    #[test]
    fn concurrent_writers_of_one_file_each_leave_a_whole_file_and_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("table.csv");
        let texts: Vec<Vec<u8>> = (0..8).map(|k| vec![b'a' + k as u8; 200_000]).collect();
        std::thread::scope(|s| {
            for t in &texts {
                let path = &path;
                s.spawn(move || {
                    for _ in 0..5 {
                        write_atomic(path, t).unwrap();
                    }
                });
            }
        });
        let got = std::fs::read(&path).unwrap();
        assert!(texts.contains(&got), "a mixed or partial file");
        let left: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(left, vec![std::ffi::OsString::from("table.csv")]);
    }
}
