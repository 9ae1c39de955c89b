//! `bench` (throughput of the dam break, or of the towed 3D ship, in particle-steps per second) and its hidden
//! one-configuration worker `bench-one`, which `bench` runs in a child process per configuration.

use bowwave::methods::bench;
use clap::Args;

#[derive(Args)]
pub struct BenchArgs {
    /// Resolutions, comma separated: H/dx of the dam break, or D/dx of the ship with `--ship` (D/dx 5: 89 436
    /// particles, D/dx 6.5: about 2e5).
    #[arg(long, value_delimiter = ',', default_value = "100")]
    pub res: Vec<f64>,
    /// Measure the 3D mode instead: the towed Wigley hull of `bowwave ship` (Fr 0.5) for `--steps` steps from rest.
    #[arg(long)]
    pub ship: bool,
    /// With `--ship`: time steps per configuration.
    #[arg(long, default_value_t = 30)]
    pub steps: u64,
    /// End time in t sqrt(g/H).
    #[arg(long, default_value_t = 6.0)]
    pub end: f64,
    /// Thread counts to compare, comma separated.
    #[arg(long, value_delimiter = ',', default_value = "1,2")]
    pub threads: Vec<usize>,
    /// Method variants to compare, comma separated (as in `chart speed-accuracy`, e.g. `delta-sph,table`;
    /// `+` combines, e.g. `wendland+h=1.4`); `delta-sph` is the case's defaults.
    #[arg(long, value_delimiter = ',', default_value = "delta-sph")]
    pub variants: Vec<String>,
}

impl BenchArgs {
    pub fn run(self) -> anyhow::Result<()> {
        let case = if self.ship {
            bench::BenchCase::Ship { steps: self.steps }
        } else {
            bench::BenchCase::DamBreak {
                end: self.end,
                variants: self.variants,
            }
        };
        bench::bench_cli(&self.res, &self.threads, &case)
    }
}

#[derive(Args)]
pub struct BenchOneArgs {
    /// Resolution of the dam break, H/dx (of the ship, D/dx, with `--ship`).
    #[arg(long)]
    pub res: f64,
    /// End time in units of √(H/g) (t√(g/H)).
    #[arg(long, default_value_t = 6.0)]
    pub end: f64,
    /// The towed 3D ship instead of the dam break.
    #[arg(long)]
    pub ship: bool,
    /// With `--ship`: time steps.
    #[arg(long, default_value_t = 30)]
    pub steps: u64,
    /// Method variant, as in `bench --variants`: delta-sph, molteni, wcsph, wendland, pc, rk4, table,
    /// exact-kernel, sun2017, sun2017-walls, sun2017-leaving, no-shifting, lagged-gradient, images, fixed-ghosts, normal-flux, normal-flux-thesis, or alpha=A, delta=D, cfl=C,
    /// h=H; `+` combines them.
    #[arg(long, default_value = "delta-sph")]
    pub variant: String,
}

impl BenchOneArgs {
    /// Prints the configuration's measurement as one JSON line.
    pub fn run(self) -> anyhow::Result<()> {
        let r = if self.ship {
            bench::bench_ship_one(self.res, self.steps)?
        } else {
            bench::bench_one(self.res, self.end, &self.variant)?
        };
        println!("{}", serde_json::to_string(&r)?);
        Ok(())
    }
}
