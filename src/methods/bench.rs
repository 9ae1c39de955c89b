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
    /// The process's resident memory before the scene was built (the program, its libraries and embedded
    /// data), and the peak net of it per particle: what each particle costs, the figure that scales with the
    /// problem (at H/dx 100 the 5.4 MB start is a fifth of the gross peak, at 6 million particles nothing).
    #[serde(default)]
    pub start_rss_bytes: u64,
    #[serde(default)]
    pub net_bytes_per_particle: f64,
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
    let start = crate::process_usage::peak_rss_bytes();
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
    Ok(measured(
        variant,
        res,
        (r.n_fluid, r.sim.ghosts.geom.len()),
        r.steps,
        r.wall_seconds,
        r.sim.timings,
        start,
    ))
}

/// The measurement of a run in this process: `steps` steps of `fluid` particles with `ghosts` ghosts in `wall`
/// seconds (particle-steps per second count the fluid, a step once), the stages' shares of the solver's time,
/// and the peak resident memory per particle, ghosts included, gross and net of the process's resident memory
/// `start` before the scene was built.
fn measured(
    variant: &str,
    res: f64,
    (fluid, ghosts): (usize, usize),
    steps: u64,
    wall: f64,
    t: crate::sph::solver::StageTimings,
    start: u64,
) -> BenchResult {
    let total = (t.neighbour_search + t.ghost_mirroring + t.density_gradient + t.main_loop + t.update).max(1e-12);
    let rss = crate::process_usage::peak_rss_bytes();
    BenchResult {
        variant: variant.to_string(),
        res,
        threads: rayon::current_num_threads(),
        fluid_particles: fluid,
        ghost_particles: ghosts,
        steps,
        wall_seconds: wall,
        particle_steps_per_second: fluid as f64 * steps as f64 / wall.max(1e-12),
        peak_rss_bytes: rss,
        bytes_per_particle: rss as f64 / (fluid + ghosts) as f64,
        start_rss_bytes: start,
        net_bytes_per_particle: rss.saturating_sub(start) as f64 / (fluid + ghosts) as f64,
        share_neighbour_search: t.neighbour_search / total,
        share_ghost_mirroring: t.ghost_mirroring / total,
        share_density_gradient: t.density_gradient / total,
        share_main_loop: t.main_loop / total,
        share_update: t.update / total,
    }
}

/// Name of the 3D benchmark's configuration in the tables (`bench --ship`).
pub const SHIP_VARIANT: &str = "ship3d";

/// One configuration of the 3D benchmark: the towed Wigley hull of `bowwave ship` (Fr 0.5, image tank faces,
/// fixed hull ghosts) at D/dx `res`, `steps` time steps from rest (the ramp's start: the neighbourhoods, and so
/// the cost of a step, are the scene's own from the first step on).
pub fn bench_ship_one(res: f64, steps: u64) -> anyhow::Result<BenchResult> {
    anyhow::ensure!(steps > 0, "bench --ship: expected at least one step");
    let start = crate::process_usage::peak_rss_bytes();
    let opts = crate::compare3d::towed_ship::TowedShip::new(crate::validation::hull_at_rest::wigley(), 0.5, res);
    let mut sim = crate::compare3d::towed_ship::simulation(&opts)?;
    let clock = std::time::Instant::now();
    for _ in 0..steps {
        sim.step().map_err(|b| anyhow::anyhow!("benchmark run blew up: {b}"))?;
    }
    let wall = clock.elapsed().as_secs_f64();
    let counts = (sim.n_fluid(), sim.ghosts.geom.len());
    Ok(measured(SHIP_VARIANT, res, counts, steps, wall, sim.timings, start))
}

/// What `bowwave bench` measures: the dam break to t√(g/H) = `end` with each variant, or the towed 3D ship
/// for `steps` steps (`ship`).
#[derive(Clone, Debug)]
pub enum BenchCase {
    DamBreak { end: f64, variants: Vec<String> },
    Ship { steps: u64 },
}

/// `bowwave bench`: every resolution × thread count in a child process, then a table (resolutions are H/dx for
/// the dam break, D/dx for the ship).
pub fn bench_cli(res: &[f64], threads: &[usize], case: &BenchCase) -> anyhow::Result<()> {
    let exe = std::env::current_exe()?;
    let mut results = vec![];
    let variants = match case {
        BenchCase::DamBreak { variants, .. } => variants.clone(),
        BenchCase::Ship { .. } => vec![SHIP_VARIANT.to_string()],
    };
    for v in &variants {
        for &r in res {
            for &n in threads {
                let mut args = vec![
                    "--threads".to_string(),
                    n.to_string(),
                    "bench-one".into(),
                    "--res".into(),
                    r.to_string(),
                ];
                match case {
                    BenchCase::DamBreak { end, .. } => {
                        eprintln!(
                            "bench: dam break H/dx = {r}, {n} thread(s), variant {v}, to t sqrt(g/H) = {end} ..."
                        );
                        args.extend(["--end".into(), end.to_string(), "--variant".into(), v.clone()]);
                    }
                    BenchCase::Ship { steps } => {
                        eprintln!("bench: towed Wigley, D/dx = {r}, {n} thread(s), {steps} steps ...");
                        args.extend(["--ship".into(), "--steps".into(), steps.to_string()]);
                    }
                }
                let out = std::process::Command::new(&exe).args(&args).output()?;
                if !out.status.success() {
                    anyhow::bail!("bench-one failed: {}", String::from_utf8_lossy(&out.stderr));
                }
                let b: BenchResult = serde_json::from_slice(&out.stdout)?;
                results.push(b);
            }
        }
    }
    println!("| variant | resolution | threads | fluid particles | ghosts | steps | wall time (s) | particle-steps/s | speed-up | peak memory / particle (B) | net of the start (B) | neighbour search | ghost MLS | density gradient | main loop | update |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for b in &results {
        let base = results
            .iter()
            .find(|o| o.variant == b.variant && o.res == b.res && o.threads == 1)
            .map(|o| format!("{:.2}", o.wall_seconds / b.wall_seconds))
            .unwrap_or_else(|| "–".into()); // no 1-thread run of this variant and resolution to compare with
        println!(
            "| {} | {} | {} | {} | {} | {} | {:.1} | {:.3e} | {} | {:.0} | {:.0} | {:.0}% | {:.0}% | {:.0}% | {:.0}% | {:.0}% |",
            b.variant,
            b.res,
            b.threads,
            b.fluid_particles,
            b.ghost_particles,
            b.steps,
            b.wall_seconds,
            b.particle_steps_per_second,
            base,
            b.bytes_per_particle,
            b.net_bytes_per_particle,
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
    /// The 3D benchmark times the towed ship's steps: its particles, ghosts and step count are the scene's, its
    /// stage shares add up to one.
    #[test]
    fn ship_benchmark_counts_the_towed_scene_and_its_stages() {
        let b = super::bench_ship_one(2.0, 2).unwrap();
        assert_eq!((b.variant.as_str(), b.steps), (super::SHIP_VARIANT, 2));
        assert!(b.fluid_particles > 1000 && b.ghost_particles > 0, "{b:?}");
        let shares = b.share_neighbour_search
            + b.share_ghost_mirroring
            + b.share_density_gradient
            + b.share_main_loop
            + b.share_update;
        assert!(
            (shares - 1.0).abs() < 1e-9 && b.particle_steps_per_second > 0.0,
            "{b:?}"
        );
    }

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
