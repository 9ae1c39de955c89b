//! What this process has used: CPU seconds (user + system) and its peak resident memory, from
//! `getrusage(RUSAGE_SELF)` (POSIX; microsecond resolution, no clock-tick rate to assume); and the memory the
//! machine can still give, before a large run allocates.

fn usage() -> Option<libc::rusage> {
    let mut u = std::mem::MaybeUninit::<libc::rusage>::zeroed();
    // SAFETY: getrusage writes a whole rusage into the pointer it is given and reads nothing from it.
    let r = unsafe { libc::getrusage(libc::RUSAGE_SELF, u.as_mut_ptr()) };
    // SAFETY: on success the struct was filled; it was zeroed before in any case.
    (r == 0).then(|| unsafe { u.assume_init() })
}

/// CPU time of this process, user + system, in s (every thread); 0 where unavailable.
pub fn cpu_seconds() -> f64 {
    usage().map_or(0.0, |u| {
        let t = |tv: libc::timeval| tv.tv_sec as f64 + tv.tv_usec as f64 * 1e-6;
        t(u.ru_utime) + t(u.ru_stime)
    })
}

/// Peak resident set size of this process, in bytes (Linux reports `ru_maxrss` in KiB); 0 where unavailable.
pub fn peak_rss_bytes() -> u64 {
    usage().map_or(0, |u| u.ru_maxrss.max(0) as u64 * 1024)
}

/// Memory the machine can still give without swapping, in bytes: `MemAvailable` of `/proc/meminfo` (Linux);
/// None where that is not readable.
pub fn available_memory_bytes() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

#[cfg(test)]
mod tests {
    #[test]
    fn cpu_time_grows_with_work_and_memory_is_counted() {
        let c0 = super::cpu_seconds();
        let mut x = 0u64;
        let start = std::time::Instant::now();
        while start.elapsed().as_millis() < 50 {
            x = x.wrapping_mul(6364136223846793005).wrapping_add(1);
        }
        std::hint::black_box(x);
        assert!(super::cpu_seconds() > c0, "no CPU time counted");
        assert!(super::peak_rss_bytes() > 1 << 20, "under 1 MiB resident");
        if cfg!(target_os = "linux") {
            let free = super::available_memory_bytes().expect("/proc/meminfo's MemAvailable");
            assert!(free > 1 << 20, "{free} bytes available");
        }
    }
}
