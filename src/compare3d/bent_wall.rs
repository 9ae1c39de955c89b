//! The bent-wall channel of thesis §10.2.1 in 2D+t: the cut of the ruled surface of eq. (10.8)
//! ([`crate::geometry::bent_wall`]) is a plate whose foot slides along the floor at U/4 while it turns from the
//! vertical to 45° over the water; here it pushes water at rest, depth H, towards a straight side wall at
//! y = W. The 3D channel (a stream of depth H along the ruled surface) is the same flow with x = 5 + U t; the
//! thesis runs it in 3D only and prints neither the wall's length L nor the channel's width W, so both are
//! ours ([`BentWallOptions`]).
//!
//! Non-dimensional with H, g and ρ0 (time in √(H/g), Fr_H = U/√(gH)). The wall is one deforming polyline:
//! the plate's top (the ruled surface's, 5 H to 3.5 H above the floor), its foot, the floor to the side wall
//! and the side wall up, so the moving corner at the foot (fluid angle 90° − θ, from 90° to 45°) gets its
//! ghosts as any polyline corner does.
//! The water starts at rest and hydrostatic; the plate starts moving at t = 0 (the kink where the straight
//! channel side meets the ruled surface). The run records the run-up on the plate and the crest away from it,
//! and watches for the first air cavity a plunging jet closes ([`crate::cases::cavity_probe`]).

use crate::cases::cavity_probe::{CavityClosure, CavityWatch};
use crate::driver::progress::{Progress, Status};
use crate::driver::{drive, Flow, Outcome, Watch};
use crate::geometry::bent_wall::BentWall;
use crate::io::atomic::write_atomic;
use crate::io::csv_table::Table;
use crate::io::vtk;
use crate::sph::body_force::BodyForce;
use crate::sph::boundary::Boundary;
use crate::sph::deforming_wall::{DeformingWall, Profile};
use crate::sph::particles::Fluid;
use crate::sph::polyline_wall::{FluidSide, VertexMotion};
use crate::sph::solver::{Simulation, SolverConfig};
use nalgebra::Vector2;
use std::path::Path;
use std::time::Instant;

type V2 = Vector2<f64>;

/// Height of the side wall (units of H), as high as the bent wall's start (eq. 10.8: t up to 5); the plate
/// itself is the cut of the ruled surface, t from 0 to 5, so its top falls from 5 H to 3.5 H.
pub const SIDE_WALL_TOP: f64 = crate::geometry::bent_wall::T_MAX;

/// Samples per passage of the wall (the series' rows).
pub const SAMPLES: usize = 400;

/// What to run (lengths in H).
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct BentWallOptions {
    /// Fr_H = U/√(gH). Default 2 (ours, with L/H 12): the jet plunges at 0.8 of the wall's length, inside it
    /// (`docs/decisions/bent-wall-channel.md`).
    pub fr_h: f64,
    /// L/H, the length of the bent wall. Default 12 (ours): shorter walls (8, 6) at Fr_H 2 plunge only past
    /// their end, where the plate stops turning.
    pub length: f64,
    /// W/H, the channel's width (the straight side wall at y = W). Default 10: the foot ends at L/4 = 3 H and
    /// the crest plunges about 6 H from the wall's start, 4 H before the side wall.
    pub width: f64,
    /// H/dx.
    pub res: f64,
    /// c0/√(gH); `None`: 10 times the expected largest speed (see [`expected_max_speed`]).
    pub c0: Option<f64>,
    /// Run until this fraction of the wall has passed (1: its end; up to 2). Past its end the channel's side
    /// goes on as the wall's last cut, a 45° wall along the channel (ours: the thesis's figure 10.24 is not
    /// described in its text), so in 2D+t the plate stands still there.
    pub s_end: f64,
    /// Stop at the first closed cavity (the plunge) instead of running to `s_end`.
    pub stop_at_plunge: bool,
    /// ParaView frames per passage of the wall (0: none).
    pub frames: usize,
}

impl Default for BentWallOptions {
    fn default() -> Self {
        BentWallOptions {
            fr_h: 2.0,
            length: 12.0,
            width: 10.0,
            res: 20.0,
            c0: None,
            s_end: 1.0,
            stop_at_plunge: true,
            frames: 20,
        }
    }
}

impl BentWallOptions {
    /// The checks: a clear error naming the option, before anything runs.
    pub fn check(&self) -> anyhow::Result<()> {
        let bad = |name: &str, want: &str, got: f64| anyhow::anyhow!("bent wall: --{name}: expected {want}, got {got}");
        if !(self.fr_h.is_finite() && self.fr_h > 0.0) {
            return Err(bad("fr-h", "a positive Froude number U/sqrt(gH)", self.fr_h));
        }
        if !(self.length.is_finite() && self.length > 0.0) {
            return Err(bad("length", "a positive L/H", self.length));
        }
        if !(self.width.is_finite() && self.width > self.length / 4.0 + 1.0) {
            return Err(bad("width", "W/H more than L/4 + 1 (the foot ends at L/4)", self.width));
        }
        if !(self.res.is_finite() && (4.0..=400.0).contains(&self.res)) {
            return Err(bad("res", "H/dx in [4, 400]", self.res));
        }
        if let Some(c) = self.c0 {
            if !(c.is_finite() && c > 0.0) {
                return Err(bad("c0", "a positive c0/sqrt(gH)", c));
            }
        }
        if !(self.s_end > 0.0 && self.s_end <= 2.0) {
            return Err(bad("until", "a fraction of the wall's length in (0, 2]", self.s_end));
        }
        Ok(())
    }
}

/// Expected largest water speed / √(gH): the larger of the 2D+t rule's
/// [`RUN_UP_SPEED_FACTOR`](crate::twodt::scene::RUN_UP_SPEED_FACTOR) times the fastest point of the
/// plate up to 2 H above the floor over the whole passage, and √(2 g H) (a crest of height H falling back).
pub fn expected_max_speed(wall: &BentWall, fr_h: f64) -> f64 {
    let mut v = 0.0f64;
    for k in 0..=200 {
        let p = wall.plate(k as f64 / 200.0, fr_h);
        let r = 2.0 / p.theta.cos();
        v = v.max(p.point(r).1.norm()).max(p.foot_velocity.norm());
    }
    (crate::twodt::scene::RUN_UP_SPEED_FACTOR * v).max(2f64.sqrt())
}

/// The wall at time t: the plate (the cut of eq. 10.8 for t from 5 down to 0) from its top down to the foot,
/// the floor, the side wall.
pub fn profile(wall: &BentWall, fr_h: f64, width: f64, t: f64) -> Profile {
    let s = wall.s_at(t, fr_h);
    let p = wall.plate(s, fr_h);
    let top = wall.surface_point(crate::geometry::bent_wall::T_MAX, 1.0 - s.clamp(0.0, 1.0));
    let r_top = (V2::new(top.y, top.z) - p.foot).norm();
    let (top, v_top, a_top) = p.point(r_top);
    Profile {
        points: vec![top, p.foot, V2::new(width, 0.0), V2::new(width, SIDE_WALL_TOP)],
        motion: VertexMotion {
            vel: vec![v_top, p.foot_velocity, V2::zeros(), V2::zeros()],
            acc: vec![a_top, V2::zeros(), V2::zeros(), V2::zeros()],
        },
    }
}

/// The scene: the water at rest (hydrostatic) between the plate and the side wall, the wall, the solver.
pub fn build(opts: &BentWallOptions) -> anyhow::Result<(Simulation<2>, f64)> {
    opts.check()?;
    let wall = BentWall { length: opts.length };
    let dx = 1.0 / opts.res;
    let c0 = opts.c0.unwrap_or_else(|| 10.0 * expected_max_speed(&wall, opts.fr_h));
    let mut cfg = SolverConfig::new(dx, 1.0, c0, BodyForce::Uniform(V2::new(0.0, -1.0)));
    let support = 3.0 * cfg.h;
    // The side wall on the fluid's lattice: W a whole number of spacings.
    let width = (opts.width / dx).round() * dx;
    cfg.domain = Some((
        V2::new(-support, -support),
        V2::new(width + support, SIDE_WALL_TOP + 2.0),
    ));
    let (fr, w) = (opts.fr_h, wall);
    let wall_fn = move |t: f64| profile(&w, fr, width, t);
    let boundary = DeformingWall::new("bent-wall", Box::new(wall_fn), FluidSide::Left, dx, support);
    let mut fluid = Fluid::<2>::default();
    let (ny, nz) = ((width / dx).round() as usize, opts.res.round() as usize);
    for i in 0..ny {
        for j in 0..nz {
            let p = V2::new((i as f64 + 0.5) * dx, (j as f64 + 0.5) * dx);
            let depth = 1.0 - p.y;
            let rho = cfg.eos.density(depth);
            fluid.push(p, V2::zeros(), rho, rho * dx * dx, depth);
        }
    }
    let boundaries: Vec<Box<dyn Boundary<2>>> = vec![Box::new(boundary)];
    Ok((Simulation::new(cfg, fluid, boundaries), width))
}

/// One row of the history.
#[derive(Clone, Copy, Debug, Default, serde::Serialize, serde::Deserialize)]
pub struct Sample {
    /// t√(g/H), the fraction s of the wall passed, and the channel's x/H = 5 + s L (eq. 10.8).
    pub t: f64,
    pub s: f64,
    pub x: f64,
    /// θ (deg) of the plate.
    pub theta_deg: f64,
    /// Run-up on the plate: the highest water within 1.5 dx of it (its highest particle plus dx/2), above the
    /// calm level (/H).
    pub run_up: f64,
    /// The crest away from the plate (the highest particle farther than 3h from it, plus dx/2): elevation
    /// above the calm level and lateral position y/H.
    pub crest: f64,
    pub crest_y: f64,
    /// Kinetic energy / (M g H).
    pub kinetic: f64,
}

/// The plunge: the first air cavity closed by the jet.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct Plunge {
    /// t√(g/H) of the first check that found it closed, and of the check before (it closed in between).
    pub t: f64,
    pub t_before: f64,
    /// s and x/H of that check.
    pub s: f64,
    pub x: f64,
    /// The cavity's centroid (y, z)/H, area /H², circulation around it /(√(gH) H), positive clockwise.
    pub centroid: [f64; 2],
    pub area: f64,
    pub circulation: f64,
    /// The highest crest away from the plate before the closure, above the calm level (/H).
    pub crest_max: f64,
}

/// What a run measured.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct BentWallResult {
    pub options: BentWallOptions,
    /// The channel width actually used (W rounded to whole spacings) and c0/√(gH).
    pub width: f64,
    pub c0: f64,
    pub particles: usize,
    pub steps: u64,
    pub wall_seconds: f64,
    pub samples: Vec<Sample>,
    pub plunge: Option<Plunge>,
    /// Why the run stopped early (a blow-up's diagnosis); the samples hold what it had.
    pub stopped: Option<String>,
    /// The crate's git commit (BOWWAVE_GIT_COMMIT at build time), for the record.
    pub commit: String,
    /// The particles (y, z), their pressure / (ρ0 g H) and the wall polyline at the plunge (for the picture;
    /// not written to the JSON).
    #[serde(skip)]
    pub plunge_snapshot: Option<PlungeSnapshot>,
}

/// The scene at the plunge, for [`write_outputs`]'s picture.
#[derive(Clone, Debug, Default)]
pub struct PlungeSnapshot {
    pub points: Vec<(f64, f64)>,
    pub pressure: Vec<f64>,
    pub wall: Vec<(f64, f64)>,
}

/// The water's top (highest particle + dx/2) above the calm level within 1.5 dx of the plate (above the foot),
/// and farther than `far` from it, with the latter's y.
fn heights(sim: &Simulation<2>, wall: &BentWall, s: f64, fr_h: f64, dx: f64, far: f64) -> (f64, f64, f64) {
    let band = 1.5 * dx;
    let p = wall.plate(s, fr_h);
    let (n, e) = (p.normal(), p.up());
    let (mut run_up, mut crest, mut crest_y) = (f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NAN);
    for x in &sim.fluid.pos {
        let d = (x - p.foot).dot(&n);
        if d < band && (x - p.foot).dot(&e) > 0.0 {
            run_up = run_up.max(x.y);
        } else if d > far && x.y > crest {
            crest = x.y;
            crest_y = x.x;
        }
    }
    let top = |z: f64| z + 0.5 * dx - 1.0;
    (top(run_up), top(crest), crest_y)
}

/// Runs the channel's 2D+t analogue; writes frames into `frames_dir` when given (`bent_wall_NNNN.vtp` and
/// `bent_wall.pvd`). A run that blows up keeps its samples and says why in [`BentWallResult::stopped`].
pub fn run(opts: &BentWallOptions, frames_dir: Option<&Path>, progress: bool) -> anyhow::Result<BentWallResult> {
    let (mut sim, width) = build(opts)?;
    let wall = BentWall { length: opts.length };
    let dx = 1.0 / opts.res;
    let h = sim.kernel.support / 3.0;
    let t_pass = opts.length / opts.fr_h;
    let t_end = opts.s_end * t_pass;
    let every = t_pass / SAMPLES as f64;
    let frame_every = SAMPLES.checked_div(opts.frames).map_or(usize::MAX, |e| e.max(1));
    let mass: f64 = sim.fluid.mass.iter().sum();
    let mut samples: Vec<Sample> = vec![];
    let mut plunge: Option<Plunge> = None;
    let mut plunge_snapshot: Option<PlungeSnapshot> = None;
    let mut watch = CavityWatch::default();
    let mut pvd: Vec<(f64, String)> = vec![];
    // Index of the next sample time k·every, and of the next frame's interval. A step longer than the interval
    // skips the samples it jumps over instead of delaying every later one.
    let (mut k, mut next_frame) = (0usize, 0usize);
    let clock = Instant::now();
    let mut observer = Watch(|sim: &mut Simulation<2>| {
        if sim.time + 1e-12 >= k as f64 * every {
            let now = k.max(((sim.time + 1e-12) / every).floor() as usize);
            sim.refresh();
            let s = wall.s_at(sim.time, opts.fr_h);
            let (run_up, crest, crest_y) = heights(sim, &wall, s, opts.fr_h, dx, 3.0 * h);
            samples.push(Sample {
                t: sim.time,
                s,
                x: wall.x_of(s),
                theta_deg: wall.plate(s, opts.fr_h).theta.to_degrees(),
                run_up,
                crest,
                crest_y,
                kinetic: sim.energies().kinetic / mass,
            });
            if let Some(dir) = frames_dir {
                if now >= next_frame {
                    next_frame = (now / frame_every + 1).saturating_mul(frame_every);
                    let name = format!("bent_wall_{:04}.vtp", pvd.len());
                    write_frame(sim, &dir.join(&name))?;
                    pvd.push((sim.time, name));
                    vtk::write_pvd(&dir.join("bent_wall.pvd"), &pvd)?;
                }
            }
            if plunge.is_none() && s > 0.02 {
                let walls = vec![profile(&wall, opts.fr_h, width, sim.time).points];
                if let Some(c) = watch.check(sim, dx, &walls) {
                    plunge = Some(to_plunge(&c, &wall, opts.fr_h, &samples));
                    plunge_snapshot = Some(PlungeSnapshot {
                        points: sim.fluid.pos.iter().map(|p| (p.x, p.y)).collect(),
                        pressure: sim.pressure().to_vec(),
                        wall: walls[0].iter().map(|p| (p.x, p.y)).collect(),
                    });
                }
            }
            k = now + 1;
        }
        let done = sim.time >= t_end || (opts.stop_at_plunge && plunge.is_some());
        Ok(if done { Flow::Stop } else { Flow::Step })
    });
    let mut bar = Progress::new("bent wall ", progress, None, |sim: &Simulation<2>| Status {
        fraction: sim.time / t_end,
        text: format!("x/L = {:.3}", wall.s_at(sim.time, opts.fr_h)),
        steps: sim.steps,
    });
    let outcome = drive(&mut sim, &mut [&mut observer, &mut bar])?;
    let stopped = match outcome {
        Outcome::BlewUp(b) => Some(format!("blew up at t√(g/H) = {:.3}: {b}", sim.time)),
        _ => None,
    };
    Ok(BentWallResult {
        options: opts.clone(),
        width,
        c0: sim.cfg.eos.c0,
        particles: sim.n_fluid(),
        steps: sim.steps,
        wall_seconds: clock.elapsed().as_secs_f64(),
        samples,
        plunge,
        stopped,
        commit: option_env!("BOWWAVE_GIT_COMMIT").unwrap_or("unknown").to_string(),
        plunge_snapshot,
    })
}

fn to_plunge(c: &CavityClosure, wall: &BentWall, fr_h: f64, samples: &[Sample]) -> Plunge {
    let s = wall.s_at(c.time, fr_h);
    Plunge {
        t: c.time,
        t_before: c.previous_time,
        s,
        x: wall.x_of(s),
        centroid: [c.centroid.x, c.centroid.y],
        area: c.area,
        circulation: c.circulation,
        crest_max: samples.iter().map(|r| r.crest).fold(f64::NEG_INFINITY, f64::max),
    }
}

fn write_frame(sim: &Simulation<2>, path: &Path) -> anyhow::Result<()> {
    let f = &sim.fluid;
    let pts: Vec<[f64; 3]> = f.pos.iter().map(|p| [p.x, p.y, 0.0]).collect();
    let data = vec![
        vtk::PointData::Scalar("pressure", sim.pressure().to_vec()),
        vtk::PointData::Vector("velocity", f.vel.iter().map(|v| [v.x, v.y, 0.0]).collect()),
    ];
    vtk::write_vtp(path, &pts, &data).map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))
}

/// The history as a table (one row per sample).
pub fn table(r: &BentWallResult) -> Table {
    let cols = [
        "t_star",
        "s",
        "x_over_h",
        "theta_deg",
        "run_up_over_h",
        "crest_over_h",
        "crest_y_over_h",
        "kinetic",
    ];
    let mut t = Table::new(cols.iter().map(|c| c.to_string()).collect());
    for s in &r.samples {
        t.push(vec![
            s.t,
            s.s,
            s.x,
            s.theta_deg,
            s.run_up,
            s.crest,
            s.crest_y,
            s.kinetic,
        ]);
    }
    t
}

/// Writes bent_wall.csv, bent_wall.json (options, result, the plunge), bent_wall_heights.png and, when it
/// plunged, bent_wall_plunge.png (the particles by pressure and the wall at the closure) into `out`.
pub fn write_outputs(r: &BentWallResult, out: &Path) -> anyhow::Result<()> {
    let csv = out.join("bent_wall.csv");
    table(r)
        .write(&csv)
        .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", csv.display()))?;
    let json = out.join("bent_wall.json");
    write_atomic(&json, serde_json::to_string_pretty(r)?.as_bytes())
        .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", json.display()))?;
    use crate::io::plot::{line_plot, Series, Style};
    let series = |name: &str, f: fn(&Sample) -> f64| Series {
        name: name.to_string(),
        points: r.samples.iter().map(|s| (s.s, f(s))).collect(),
        style: Style::Line,
    };
    line_plot(
        &out.join("bent_wall_heights.png"),
        &format!(
            "Bent wall in 2D+t, Fr_H {}, L/H {}, W/H {}, H/dx {}",
            r.options.fr_h, r.options.length, r.width, r.options.res
        ),
        "s = (x - 5 H)/L, fraction of the wall passed",
        "elevation above the calm level / H",
        &[
            series("run-up on the plate", |s| s.run_up),
            series("crest away from the plate", |s| s.crest),
        ],
    )?;
    if let (Some(p), Some(snap)) = (&r.plunge, &r.plunge_snapshot) {
        crate::io::plot::scatter_plot(
            &out.join("bent_wall_plunge.png"),
            &format!(
                "Bent wall in 2D+t at the plunge: s = {:.3}, x = {:.2} H (Fr_H {}, L/H {}, H/dx {})",
                p.s, p.x, r.options.fr_h, r.options.length, r.options.res
            ),
            ("y / H", "z / H"),
            &snap.points,
            &snap.pressure,
            (0.0, 1.5),
            Some("p / (rho0 g H)"),
            std::slice::from_ref(&snap.wall),
            // Up to the wall's top: a wall point outside the range would be drawn clamped to its edge.
            (
                0.0,
                r.width,
                0.0,
                snap.wall.iter().map(|p| p.1).fold(SIDE_WALL_TOP, f64::max),
            ),
            1400,
        )?;
    }
    Ok(())
}

/// A short summary for the terminal.
pub fn summary(r: &BentWallResult) -> String {
    let mut s = format!(
        "bent wall, Fr_H {}, L/H {}, W/H {}, H/dx {}: {} particles, {} steps, {:.1} s, c0 {:.2} sqrt(gH)\n",
        r.options.fr_h, r.options.length, r.width, r.options.res, r.particles, r.steps, r.wall_seconds, r.c0
    );
    let max = |f: fn(&Sample) -> f64| r.samples.iter().map(f).fold(f64::NEG_INFINITY, f64::max);
    s += &format!(
        "  highest run-up on the plate {:.3} H, highest crest away from it {:.3} H\n",
        max(|s| s.run_up),
        max(|s| s.crest)
    );
    match &r.plunge {
        Some(p) => {
            s += &format!(
                "  plunge: a cavity closed between t* {:.3} and {:.3}, at s = {:.3} (x = {:.2} H), centroid y {:.3} H, z {:.3} H, \
                 area {:.4} H², circulation {:.3} sqrt(gH) H; highest crest before it {:.3} H\n",
                p.t_before, p.t, p.s, p.x, p.centroid[0], p.centroid[1], p.area, p.circulation, p.crest_max
            )
        }
        None => s += &format!("  no closed cavity up to s = {:.3}\n", r.samples.last().map_or(0.0, |x| x.s)),
    }
    if let Some(b) = &r.stopped {
        s += &format!("  STOPPED EARLY: {b}\n");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At rest before the plate moves: the wall is the channel's straight side (vertical at y = 0), the floor
    /// and the side wall, none of them moving; once moving, the foot slides at U/4.
    #[test]
    fn the_wall_starts_as_a_straight_channel_and_its_foot_slides_at_a_quarter_of_u() {
        let w = BentWall { length: 8.0 };
        let p = profile(&w, 1.5, 8.0, 0.0);
        assert_eq!(p.points[0], V2::new(0.0, SIDE_WALL_TOP));
        assert_eq!(p.points[1], V2::zeros());
        assert_eq!(p.motion.vel[1], V2::new(1.5 / 4.0, 0.0));
        let later = profile(&w, 1.5, 8.0, 8.0 / 1.5 * 0.5);
        assert!(
            (later.points[1].x - 1.0).abs() < 1e-12,
            "foot at s = 0.5: {:?}",
            later.points[1]
        );
    }

    /// Bad options are refused with the option's name.
    #[test]
    fn bad_options_name_the_option() {
        let o = BentWallOptions {
            width: 2.0,
            ..Default::default()
        };
        let e = o.check().unwrap_err().to_string();
        assert!(e.contains("--width"), "{e}");
        let o = BentWallOptions {
            res: 2.0,
            ..Default::default()
        };
        assert!(o.check().unwrap_err().to_string().contains("--res"));
    }
}
