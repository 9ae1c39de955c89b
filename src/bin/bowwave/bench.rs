//! `bench` (throughput of the dam break in particle-steps per second) and its hidden one-configuration
//! worker `bench-one`, which `bench` runs in a child process per configuration.

use bowwave::methods::bench;
use clap::Args;

#[derive(Args)]
pub struct BenchArgs {
    /// Resolutions H/dx, comma separated.
    #[arg(long, value_delimiter = ',', default_value = "100")]
    pub res: Vec<f64>,
    /// End time in t sqrt(g/H).
    #[arg(long, default_value_t = 6.0)]
    pub end: f64,
    /// Thread counts to compare, comma separated.
    #[arg(long, value_delimiter = ',', default_value = "1,2")]
    pub threads: Vec<usize>,
    /// Method variants to compare, comma separated (as in `chart speed-accuracy`, e.g. `delta-sph,table`);
    /// `delta-sph` is the case's defaults.
    #[arg(long, value_delimiter = ',', default_value = "delta-sph")]
    pub variants: Vec<String>,
}

impl BenchArgs {
    pub fn run(self) -> anyhow::Result<()> {
        bench::bench_cli(&self.res, self.end, &self.threads, &self.variants)
    }
}

#[derive(Args)]
pub struct BenchOneArgs {
    /// Resolution of the dam break, H/dx.
    #[arg(long)]
    pub res: f64,
    /// End time in units of √(H/g) (t√(g/H)).
    #[arg(long)]
    pub end: f64,
    /// Method variant, as in `bench --variants`: delta-sph, molteni, wcsph, wendland, pc, rk4, table,
    /// exact-kernel, images, fixed-ghosts, or alpha=A, delta=D, cfl=C, h=H.
    #[arg(long, default_value = "delta-sph")]
    pub variant: String,
}

impl BenchOneArgs {
    /// Prints the configuration's measurement as one JSON line.
    pub fn run(self) -> anyhow::Result<()> {
        let r = bench::bench_one(self.res, self.end, &self.variant)?;
        println!("{}", serde_json::to_string(&r)?);
        Ok(())
    }
}
