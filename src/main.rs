//! The `bowwave` command line: a thin layer over the library.

use anyhow::Context;
use bowwave::{bench, cases, validation};
use clap::{Parser, Subcommand};
use std::path::PathBuf;

#[derive(Parser)]
#[command(name = "bowwave", version, about = "δ-SPH simulation of breaking bow waves (2D+t), with its validation cases", long_about = None)]
struct Cli {
    /// Number of worker threads (default: all cores). Results are bit-identical for any thread count.
    #[arg(long, global = true)]
    threads: Option<usize>,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a case (built-in name or TOML file) and write its time series, VTK snapshots and plots.
    Run {
        /// Built-in case name (see `bowwave cases`) or path to a case TOML file.
        #[arg(default_value = "dam-break")]
        case: String,
        /// Resolution: reference length / particle spacing (e.g. H/dx for the dam break). Default: the case's.
        #[arg(long)]
        res: Option<f64>,
        /// Output folder (default: out/CASE_NAME).
        #[arg(long)]
        out: Option<PathBuf>,
        /// End time in seconds (default: the case's).
        #[arg(long)]
        end: Option<f64>,
        /// Do not write VTK snapshots.
        #[arg(long)]
        no_vtk: bool,
        /// No progress bar.
        #[arg(long, short)]
        quiet: bool,
    },
    /// Run validation cases and print their errors against analytic solutions and published data;
    /// exits non-zero when a tolerance is missed.
    Validate {
        /// A built-in case to validate (default: all of them).
        case: Option<String>,
        /// Resolution (reference length / dx); default: each case's validation resolution.
        #[arg(long)]
        res: Option<f64>,
        /// Write series and plots of each validation run under this folder.
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Measure throughput (particle-steps per second) on the dam break.
    Bench {
        /// Resolutions H/dx, comma separated.
        #[arg(long, value_delimiter = ',', default_value = "100")]
        res: Vec<f64>,
        /// End time in t sqrt(g/H).
        #[arg(long, default_value_t = 6.0)]
        end: f64,
        /// Thread counts to compare, comma separated.
        #[arg(long, value_delimiter = ',', default_value = "1,2")]
        threads: Vec<usize>,
    },
    /// (Internal) one benchmark configuration, printed as JSON; used by `bench`.
    #[command(hide = true)]
    BenchOne {
        #[arg(long)]
        res: f64,
        #[arg(long)]
        end: f64,
    },
    /// List the built-in cases, or print one as TOML to start a case file from.
    Cases {
        /// Print this built-in case's TOML.
        name: Option<String>,
    },
}

fn main() -> anyhow::Result<()> {
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    let cli = Cli::parse();
    if let Some(n) = cli.threads {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build_global()
            .context("setting the thread count")?;
    }
    match cli.command {
        Command::Run {
            case,
            res,
            out,
            end,
            no_vtk,
            quiet,
        } => {
            let case = cases::load(&case)?;
            let out = out.unwrap_or_else(|| PathBuf::from("out").join(&case.name));
            let code = validation::run_and_report(&case, res, end, &out, !no_vtk, !quiet)?;
            std::process::exit(code);
        }
        Command::Validate { case, res, out } => {
            let ok = validation::validate_cli(case.as_deref(), res, out.as_deref())?;
            std::process::exit(if ok { 0 } else { 1 });
        }
        Command::Bench { res, end, threads } => {
            bench::bench_cli(&res, end, &threads)?;
        }
        Command::BenchOne { res, end } => {
            let r = bench::bench_one(res, end)?;
            println!("{}", serde_json::to_string(&r)?);
        }
        Command::Cases { name } => match name {
            None => {
                for (n, text) in cases::builtin::BUILTIN {
                    let c = cases::CaseFile::parse(text, n)?;
                    println!("{n:18} {}", c.description);
                }
            }
            Some(n) => match cases::builtin::builtin_text(&n) {
                Some(t) => print!("{t}"),
                None => anyhow::bail!(
                    "no built-in case `{n}`; built-ins: {}",
                    cases::builtin::builtin_names().join(", ")
                ),
            },
        },
    }
    Ok(())
}
