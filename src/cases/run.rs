//! Runs one case: steps the simulation to the end time, samples the time series (energies, probes, gauges,
//! front, wall forces, drop semi-axes), writes VTK snapshots, and on request the CSV and plots.
//! A blow-up stops the run with a diagnosis; what was computed until then is kept and written.

use super::case_file::CaseFile;
use super::setup;
use crate::driver::progress::{Progress, Status};
use crate::driver::{drive, Flow, Observer, Outcome, Watch};
use crate::io::{csv_table::Table, vtk};
use crate::sph::{
    diagnostics,
    solver::{BlowUp, BlowUpReason, Simulation},
};
use nalgebra::Vector2;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// How to run.
#[derive(Clone, Debug, Default)]
pub struct RunOptions {
    /// length/dx; `None`: the case's default.
    pub res: Option<f64>,
    /// End time override (s).
    pub end_time: Option<f64>,
    /// Where to write outputs; `None`: nothing is written (tests, validation).
    pub out_dir: Option<PathBuf>,
    pub progress: bool,
    pub vtk: bool,
    /// Do not stop a run whose mechanical energy grows (see [`ENERGY_GROWTH_LIMIT`]); for studying a drift
    /// that creates energy on purpose, such as the uncorrected density diffusion of the stability tests.
    pub allow_energy_growth: bool,
}

/// What a run produced.
pub struct RunResult {
    pub case: CaseFile,
    pub dx: f64,
    pub series: Table,
    pub blowup: Option<BlowUp>,
    pub steps: u64,
    pub n_fluid: usize,
    pub wall_seconds: f64,
    pub files: Vec<PathBuf>,
    pub sim: Simulation<2>,
    /// The first cavity closure, when the case has a cavity probe and one closed.
    pub cavity: Option<super::cavity_probe::CavityClosure>,
}

impl RunResult {
    /// Fluid particles × time steps / wall second (a step counts once, whatever its RK stages).
    pub fn particle_steps_per_second(&self) -> f64 {
        self.n_fluid as f64 * self.steps as f64 / self.wall_seconds.max(1e-12)
    }
}

/// Index of `de_mechanical_rel` (mechanical energy minus its initial value, over the energy scale) in a row.
const DE_COLUMN: usize = 8;

/// Column names of the time series of a case.
fn columns(case: &CaseFile, nwalls: usize) -> Vec<String> {
    let mut c: Vec<String> = [
        "t",
        "t_star",
        "dt",
        "wall_corrections",
        "e_kinetic",
        "e_potential",
        "e_elastic",
        "e_mechanical",
        "de_mechanical_rel",
        "semi_axis_x",
        "semi_axis_y",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    if case.probes.front {
        c.push("front".into());
        c.push("front_star".into());
    }
    if case.probes.interface_tips {
        c.push("spike_y".into());
        c.push("bubble_y".into());
    }
    for p in &case.probes.pressure {
        c.extend(super::case_file::pressure_columns(p));
    }
    for g in &case.probes.gauge {
        c.push(format!("eta_{}", g.name));
        c.push(format!("depth_{}", g.name));
        c.push(format!("depthstar_{}", g.name));
    }
    for w in case.walls.iter().take(nwalls) {
        c.push(format!("fx_{}", w.name));
        c.push(format!("fy_{}", w.name));
    }
    c
}

/// A probe in the fluid: the kernel average of the pressure at 5 points over `size` along `dir` (Pa).
fn fluid_probe_pressure(sim: &Simulation<2>, pos: &[f64], dir: &[f64], size: f64) -> f64 {
    let (c, d) = (Vector2::new(pos[0], pos[1]), Vector2::new(dir[0], dir[1]));
    let n = if size > 0.0 { 5 } else { 1 };
    let mut s = 0.0;
    for k in 0..n {
        let f = if n == 1 { 0.0 } else { k as f64 / (n - 1) as f64 - 0.5 };
        s += sim.sensor_pressure_at(&(c + d * (f * size)));
    }
    s / n as f64
}

struct Sampler {
    /// The motion carrying each gauge (`moves_with`), in the case's order.
    gauge_motion: Vec<Option<crate::sph::rigid_pose::MotionLaw>>,
    t_scale: f64,
    p_scale: f64,
    e0: f64,
    e_scale: f64,
}

fn sample(case: &CaseFile, sim: &mut Simulation<2>, s: &Sampler) -> Vec<f64> {
    sim.refresh();
    let e = sim.energies();
    let (_, m2) = diagnostics::moments(&sim.fluid);
    let mut row = vec![
        sim.time,
        sim.time / s.t_scale,
        sim.last_dt,
        sim.wall_corrections as f64,
        e.kinetic,
        e.potential,
        e.elastic,
        e.mechanical(),
        (e.mechanical() - s.e0) / s.e_scale,
        2.0 * m2[0].sqrt(),
        2.0 * m2[1].sqrt(),
    ];
    let walls = sim.read_sensors();
    let (peak, impulse) = sim.take_sensor_record();
    // Front and gauges read the water (the first phase) alone: with several phases the others fill the tank.
    let several = sim.cfg.multi_fluid.is_some();
    let water_only = several.then(|| sim.fluid.phase_subset(0));
    let water = water_only.as_ref().unwrap_or(&sim.fluid);
    if case.probes.front {
        let f = diagnostics::front(water, 0, sim.cfg.dx);
        row.push(f);
        row.push(f / case.scales.length);
    }
    if case.probes.interface_tips {
        let (spike, bubble) = diagnostics::interface_tips(&sim.fluid, sim.cfg.dx);
        row.extend([spike, bubble]);
    }
    // The wall sensors, in the order of the case's probes (setup::wall_sensors).
    let mut k = 0;
    for p in &case.probes.pressure {
        if p.in_fluid {
            let dir = p.direction.as_deref().unwrap_or(&[0.0, 1.0]);
            let v = fluid_probe_pressure(sim, &p.position, dir, p.size);
            row.extend([v, v / s.p_scale]);
        } else {
            row.extend([walls[k], walls[k] / s.p_scale, peak[k], peak[k] / s.p_scale, impulse[k]]);
            k += 1;
        }
    }
    for (g, motion) in case.probes.gauge.iter().zip(&s.gauge_motion) {
        let shift = motion
            .as_ref()
            .map_or(nalgebra::Vector2::zeros(), |m| m.pose(sim.time).d);
        let bottom = g.bottom.unwrap_or_else(|| case.floor_under(g.x)) + shift.y;
        let x = g.x + shift.x;
        let eta = diagnostics::water_level(water, x, sim.cfg.dx, bottom, g.connected);
        row.push(eta);
        row.push(eta - bottom);
        row.push((eta - bottom) / case.scales.length);
    }
    let forces = sim.boundary_forces();
    for f in forces.iter().take(case.walls.len()) {
        row.push(f.x);
        row.push(f.y);
    }
    row
}

/// Writes the fluid particles of `sim` as a .vtp file.
pub fn write_snapshot(sim: &Simulation<2>, path: &Path) -> std::io::Result<()> {
    let f = &sim.fluid;
    let pts: Vec<[f64; 3]> = f.pos.iter().map(|p| [p.x, p.y, 0.0]).collect();
    let p = sim.state_pressures();
    vtk::write_vtp(
        path,
        &pts,
        &[
            vtk::PointData::Vector("velocity", f.vel.iter().map(|v| [v.x, v.y, 0.0]).collect()),
            vtk::PointData::Scalar("pressure", p),
            vtk::PointData::Scalar("density", f.rho.clone()),
            vtk::PointData::Scalar("id", f.id.iter().map(|&i| i as f64).collect()),
            vtk::PointData::Scalar("initial_depth", f.tag.clone()),
            vtk::PointData::Scalar("phase", f.phase.iter().map(|&k| k as f64).collect()),
        ],
    )
}

/// Largest rise of the mechanical energy above its initial value, as a fraction of the case's energy scale
/// (M g L with gravity), accepted before a run with fixed walls is stopped: with a conservative body force
/// the scheme should only dissipate, so a rise means an unstable time integration or a non-conservative term.
/// 1e-3 lies 2 000× above what stable runs reach and 5× below the least unstable one measured
/// (`docs/decisions/integrator-cfl.md`).
pub const ENERGY_GROWTH_LIMIT: f64 = 1e-3;

/// Samples the time series at the case's interval (and at the start and the end), watches for the first
/// cavity closure, and stops a run with fixed walls whose mechanical energy grows
/// ([`ENERGY_GROWTH_LIMIT`]).
struct Sampling<'a> {
    case: &'a CaseFile,
    sampler: Sampler,
    end: f64,
    /// Time of the next sample; `None` before the first (the initial state).
    next: Option<f64>,
    series: Table,
    check_energy: bool,
    wall_lines: Vec<Vec<nalgebra::Vector2<f64>>>,
    cavity_watch: super::cavity_probe::CavityWatch,
    cavity: Option<super::cavity_probe::CavityClosure>,
    dx: f64,
}

impl Observer<Simulation<2>> for Sampling<'_> {
    fn observe(&mut self, sim: &mut Simulation<2>) -> anyhow::Result<Flow> {
        let every = self.case.output.series_every;
        let due = match self.next {
            None => true,
            Some(next) => sim.time >= next - 1e-12 || sim.time >= self.end - 1e-12,
        };
        if !due {
            return Ok(Flow::Step);
        }
        let first = self.next.is_none();
        let row = sample(self.case, sim, &self.sampler);
        let gain = row[DE_COLUMN];
        self.series.push(row);
        let mut next = self.next.unwrap_or(0.0);
        if first {
            next = every;
        } else {
            if let Some(spec) = &self.case.probes.cavity {
                if self.cavity.is_none() && sim.time >= spec.after {
                    self.cavity = self.cavity_watch.check(sim, self.dx, &self.wall_lines);
                }
            }
            // The particle shifting's own potential energy is not the integration's (`Simulation::shift_energy`).
            let gain = gain - sim.shift_energy / self.sampler.e_scale;
            if self.check_energy && gain > ENERGY_GROWTH_LIMIT {
                return Ok(Flow::Fail(BlowUp {
                    reason: BlowUpReason::EnergyGrowth {
                        gain,
                        limit: ENERGY_GROWTH_LIMIT,
                    },
                    time: sim.time,
                    step: sim.steps,
                    particle: None,
                }));
            }
            while next <= sim.time + 1e-12 {
                next += every;
            }
        }
        self.next = Some(next);
        Ok(Flow::Step)
    }
}

/// VTK snapshots of the fluid at the case's interval (and of the initial state), with the `.pvd` index
/// rewritten after each, into `dir` when set.
struct Snapshots<'a> {
    case: &'a CaseFile,
    dir: Option<PathBuf>,
    next: Option<f64>,
    pvd: Vec<(f64, String)>,
}

impl Observer<Simulation<2>> for Snapshots<'_> {
    fn observe(&mut self, sim: &mut Simulation<2>) -> anyhow::Result<Flow> {
        let Some(dir) = &self.dir else {
            return Ok(Flow::Step);
        };
        let every = self.case.output.vtk_every;
        if self.next.is_some_and(|next| sim.time < next - 1e-12) {
            return Ok(Flow::Step);
        }
        let name = format!("{}_{:05}.vtp", self.case.name, self.pvd.len());
        write_snapshot(sim, &dir.join(&name))?;
        self.pvd.push((sim.time, name));
        vtk::write_pvd(&dir.join(format!("{}.pvd", self.case.name)), &self.pvd)?;
        let mut next = self.next.unwrap_or(every);
        if self.next.is_some() {
            while next <= sim.time + 1e-12 {
                next += every;
            }
        }
        self.next = Some(next);
        Ok(Flow::Step)
    }
}

/// Runs a case.
pub fn run(case: &CaseFile, opts: &RunOptions) -> anyhow::Result<RunResult> {
    if let Some(end) = opts.end_time {
        // A NaN or negative end ran no step and wrote its outputs as if the run were done.
        anyhow::ensure!(
            end.is_finite() && end > 0.0,
            "case `{}`: end time: expected a positive time in seconds, got {end}",
            case.name
        );
    }
    let mut sim = setup::build(case, opts.res)?;
    let dx = sim.cfg.dx;
    let g = case.gravity_magnitude();
    let l = case.scales.length;
    let e_init = sim.energies();
    let mass = sim.fluid.total_mass();
    let has_gravity = matches!(case.body_force, super::case_file::BodyForceSpec::Gravity { .. });
    let t_scale = (l / g).sqrt();
    let laws = super::wall_motion::laws(case)?;
    let gauge_motion = case
        .probes
        .gauge
        .iter()
        .map(|g| {
            let wall = g.moves_with.as_ref().and_then(|name| case.wall_named(name).ok());
            wall.and_then(|w| laws[w].clone())
        })
        .collect();
    let sampler = Sampler {
        gauge_motion,
        t_scale,
        p_scale: case.fluid.rho0 * g * l,
        e0: e_init.mechanical(),
        e_scale: if has_gravity {
            mass * g * l
        } else {
            (e_init.kinetic + e_init.elastic).abs().max(1e-300)
        },
    };
    let end = opts.end_time.unwrap_or(case.output.end_time);
    let vtk_dir = opts.out_dir.as_ref().map(|d| d.join("vtk"));
    let want_vtk = opts.vtk && case.output.vtk_every > 0.0 && vtk_dir.is_some();
    // Walls that move do work on the fluid, so energy may rise; every body force here is conservative.
    let check_energy =
        !opts.allow_energy_growth && case.walls.iter().all(|w| w.velocity.is_none() && w.motion.is_none());
    let mut sampling = Sampling {
        case,
        sampler,
        end,
        next: None,
        series: Table::new(columns(case, sim.boundaries.len())),
        check_energy,
        wall_lines: case
            .walls
            .iter()
            .map(|w| w.points.iter().map(|p| nalgebra::Vector2::new(p[0], p[1])).collect())
            .collect(),
        cavity_watch: Default::default(),
        cavity: None,
        dx,
    };
    let mut snapshots = Snapshots {
        case,
        dir: vtk_dir.filter(|_| want_vtk),
        next: None,
        pvd: vec![],
    };
    let label = format!("{} ", case.name);
    let mut progress = Progress::new(&label, opts.progress, None, |sim: &Simulation<2>| Status {
        fraction: sim.time / end,
        text: format!("t* = {:.3}", sim.time / t_scale),
        steps: sim.steps,
    });
    let mut until_end = Watch(|sim: &mut Simulation<2>| {
        Ok(if sim.time >= end - 1e-12 {
            Flow::Stop
        } else {
            Flow::Step
        })
    });
    let start = Instant::now();
    let outcome = drive(
        &mut sim,
        &mut [&mut sampling, &mut snapshots, &mut progress, &mut until_end],
    )?;
    let blowup = match outcome {
        Outcome::BlewUp(b) => Some(b),
        Outcome::Finished | Outcome::Halted(_) => None,
    };
    let (series, cavity) = (sampling.series, sampling.cavity);
    let mut files = vec![];
    let wall_seconds = start.elapsed().as_secs_f64();
    if let Some(dir) = &opts.out_dir {
        let p = dir.join(format!("{}_series.csv", case.name));
        series.write(&p)?;
        files.push(p);
        if blowup.is_some() {
            let p = dir.join(format!("{}_last_good_state.vtp", case.name));
            write_snapshot(&sim, &p)?;
            files.push(p);
        }
        if snapshots.dir.is_some() {
            files.push(dir.join("vtk").join(format!("{}.pvd", case.name)));
        }
    }
    let n_fluid = sim.n_fluid();
    Ok(RunResult {
        case: case.clone(),
        dx,
        series,
        blowup,
        steps: sim.steps,
        n_fluid,
        wall_seconds,
        files,
        sim,
        cavity,
    })
}
