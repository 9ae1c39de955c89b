//! Throughput benchmark on the dam break.

/// Runs the dam break at each resolution and thread count to t√(g/H) = `end` and prints throughput.
pub fn bench_cli(res: &[f64], end: f64, threads: &[usize]) -> anyhow::Result<()> {
    let _ = (res, end, threads);
    anyhow::bail!("not yet")
}
