//! Throughput benchmark on the dam break: wall time to t√(g/H) = `end`, particle-steps per second
//! (fluid particles × time steps / wall second; one step counts once whatever its number of RK stages —
//! RK4 evaluates the right-hand side 4 times per step), peak memory per particle and the share of time in
//! each stage. Each configuration runs in a child process (`bowwave bench-one`), so its thread pool and
//! peak resident memory are its own.

use crate::cases::{
    self,
    run::{run, RunOptions},
};
use serde::{Deserialize, Serialize};

/// The result of one benchmark configuration.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct BenchResult {
    pub variant: String,
    pub res: f64,
    pub threads: usize,
    pub fluid_particles: usize,
    pub ghost_particles: usize,
    pub steps: u64,
    pub wall_seconds: f64,
    pub particle_steps_per_second: f64,
    pub peak_rss_bytes: u64,
    pub bytes_per_particle: f64,
    pub share_neighbour_search: f64,
    pub share_ghost_mirroring: f64,
    pub share_density_gradient: f64,
    pub share_main_loop: f64,
    pub share_update: f64,
}

/// The benchmark's case: the dam break with a method variant, and without its cavity probe.
pub fn bench_case(variant: &str) -> anyhow::Result<cases::CaseFile> {
    let mut case = cases::load("dam-break")?;
    crate::methods::charts::apply_variant(&mut case, variant)?;
    // The solver is measured, not the validation's post-processing: the cavity probe (a level set of the
    // whole flow at every series sample from t√(g/H) = 4.85 on, to find the plunging wave's cavity) cost
    // 2 % of the wall time and 40 % more peak memory to t√(g/H) = 6 at H/dx = 100 (BENCHMARKS.md, session 14).
    case.probes.cavity = None;
    Ok(case)
}

/// Runs one configuration in this process (the thread count must already be set).
pub fn bench_one(res: f64, end_star: f64, variant: &str) -> anyhow::Result<BenchResult> {
    let case = bench_case(variant)?;
    let end = end_star * (case.scales.length / case.gravity_magnitude()).sqrt();
    let r = run(
        &case,
        &RunOptions {
            res: Some(res),
            end_time: Some(end),
            ..Default::default()
        },
    )?;
    if let Some(b) = &r.blowup {
        anyhow::bail!("benchmark run blew up: {b}");
    }
    let t = r.sim.timings;
    let total = (t.neighbour_search + t.ghost_mirroring + t.density_gradient + t.main_loop + t.update).max(1e-12);
    let rss = crate::process_usage::peak_rss_bytes();
    Ok(BenchResult {
        variant: variant.to_string(),
        res,
        threads: rayon::current_num_threads(),
        fluid_particles: r.n_fluid,
        ghost_particles: r.sim.ghosts.geom.len(),
        steps: r.steps,
        wall_seconds: r.wall_seconds,
        particle_steps_per_second: r.particle_steps_per_second(),
        peak_rss_bytes: rss,
        bytes_per_particle: rss as f64 / (r.n_fluid + r.sim.ghosts.geom.len()) as f64,
        share_neighbour_search: t.neighbour_search / total,
        share_ghost_mirroring: t.ghost_mirroring / total,
        share_density_gradient: t.density_gradient / total,
        share_main_loop: t.main_loop / total,
        share_update: t.update / total,
    })
}

/// `bowwave bench`: every resolution × thread count in a child process, then a table.
pub fn bench_cli(res: &[f64], end: f64, threads: &[usize], variants: &[String]) -> anyhow::Result<()> {
    let exe = std::env::current_exe()?;
    let mut results = vec![];
    for v in variants {
        for &r in res {
            for &n in threads {
                eprintln!("bench: dam break H/dx = {r}, {n} thread(s), variant {v}, to t sqrt(g/H) = {end} ...");
                let out = std::process::Command::new(&exe)
                    .args([
                        "--threads",
                        &n.to_string(),
                        "bench-one",
                        "--res",
                        &r.to_string(),
                        "--end",
                        &end.to_string(),
                        "--variant",
                        v,
                    ])
                    .output()?;
                if !out.status.success() {
                    anyhow::bail!("bench-one failed: {}", String::from_utf8_lossy(&out.stderr));
                }
                let b: BenchResult = serde_json::from_slice(&out.stdout)?;
                results.push(b);
            }
        }
    }
    println!("| variant | H/dx | threads | fluid particles | steps | wall time (s) | particle-steps/s | speed-up | peak memory / particle (B) | neighbour search | ghost MLS | density gradient | main loop | update |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for b in &results {
        let base = results
            .iter()
            .find(|o| o.variant == b.variant && o.res == b.res && o.threads == 1)
            .map(|o| format!("{:.2}", o.wall_seconds / b.wall_seconds))
            .unwrap_or_else(|| "–".into()); // no 1-thread run of this variant and resolution to compare with
        println!(
            "| {} | {:.0} | {} | {} | {} | {:.1} | {:.3e} | {} | {:.0} | {:.0}% | {:.0}% | {:.0}% | {:.0}% | {:.0}% |",
            b.variant,
            b.res,
            b.threads,
            b.fluid_particles,
            b.steps,
            b.wall_seconds,
            b.particle_steps_per_second,
            base,
            b.bytes_per_particle,
            100.0 * b.share_neighbour_search,
            100.0 * b.share_ghost_mirroring,
            100.0 * b.share_density_gradient,
            100.0 * b.share_main_loop,
            100.0 * b.share_update
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    /// Regression: from session 11 to 13 the benchmark also ran the dam break's cavity probe (validation
    /// post-processing), which raised the measured peak memory by 40 % (BENCHMARKS.md, session 14).
    #[test]
    fn benchmark_measures_the_solver_without_the_cavity_probe() {
        assert!(crate::cases::load("dam-break").unwrap().probes.cavity.is_some());
        for variant in ["delta-sph", "images", "wendland"] {
            let case = super::bench_case(variant).unwrap();
            assert!(case.probes.cavity.is_none(), "{variant}");
        }
    }
}
