//! The first case of the 3D comparison mode: the dam break of issue #2 run twice at the same spacing, in 2D
//! and as a 3D slab between free-slip side walls, so that the 3D engine is checked against the 2D one on a
//! flow that is 2D, and the cost of the third dimension is measured. Both runs use
//! [`crate::cases::box_tank::BoxTank`] (the 2D box tank has the polyline tank's ghosts), with the physics of
//! the built-in case `cases/dam-break.toml` read from it (`DamBreak`: H, g, ρ0, c0, the column, the tank's
//! length, the sensors P1 and P2), and the tank's length rounded to a whole number of spacings (within dx/2).

use crate::cases::box_tank::BoxTank;
use crate::driver::progress::{Progress, Status};
use crate::driver::{drive, Flow, Outcome, Watch};
use crate::sph::diagnostics::front;
use crate::sph::polyline_wall::GhostKind;
use crate::sph::solver::Simulation;
use nalgebra::{SVector, Vector2, Vector3};
use std::time::Instant;

/// The dam break's physics, from the built-in case `cases/dam-break.toml`.
#[derive(Clone, Copy, Debug)]
struct DamBreak {
    /// Water column height H (m): the case's length scale.
    h: f64,
    /// |g| (m/s²).
    g: f64,
    rho0: f64,
    /// c0 (m/s).
    c0: f64,
    /// Column width / H.
    column: f64,
    /// Tank length / H (the wall's furthest point).
    tank: f64,
    /// Wall sensors P1 and P2: centre heights (m) and size (m), averaged over 5 points along the wall, as the
    /// 2D case's probes (Buchner's sensors, thesis §8.4).
    sensors: [f64; 2],
    sensor_size: f64,
}

impl DamBreak {
    fn read() -> anyhow::Result<DamBreak> {
        let case = crate::cases::load("dam-break")?;
        let h = case.scales.length;
        let probe = |name: &str| {
            case.probes
                .pressure
                .iter()
                .find(|p| p.name == name)
                .ok_or_else(|| anyhow::anyhow!("the dam-break case has no probe {name}"))
        };
        let (p1, p2) = (probe("P1")?, probe("P2")?);
        let column = match case.blocks.first() {
            Some(crate::cases::case_file::BlockSpec::Rectangle { min, max, .. }) => max[0] - min[0],
            _ => anyhow::bail!("the dam-break case's water is not a rectangle"),
        };
        let tank = case
            .walls
            .first()
            .and_then(|w| w.points.iter().map(|p| p[0]).reduce(f64::max))
            .ok_or_else(|| anyhow::anyhow!("the dam-break case has no tank"))?;
        Ok(DamBreak {
            h,
            g: case.gravity_magnitude(),
            rho0: case.fluid.rho0,
            c0: case.c0(),
            column: column / h,
            tank: tank / h,
            sensors: [p1.position[1], p2.position[1]],
            sensor_size: p1.size,
        })
    }
}

/// What to run.
#[derive(Clone, Debug)]
pub struct SlabOptions {
    /// H/dx.
    pub res: f64,
    /// Slab width in particle spacings (the 3D run's particle count is this times the 2D run's).
    pub width_cells: usize,
    /// End time t√(g/H).
    pub end: f64,
    /// Ghosts of the tank's faces (both runs).
    pub ghosts: GhostKind,
    /// Sampling interval in t√(g/H).
    pub every: f64,
    /// CFL number of both runs (`None`: the integrator's default, RK4 2.0, docs/reference/method.md).
    pub cfl: Option<f64>,
}

/// One run's history at the sampling times.
#[derive(Clone, Debug, Default)]
pub struct RunHistory {
    /// t√(g/H) of each sample.
    pub t_star: Vec<f64>,
    /// Front x/H (the farthest particle plus dx/2).
    pub front: Vec<f64>,
    /// P1 and P2 over ρ0 g H.
    pub p1: Vec<f64>,
    pub p2: Vec<f64>,
    pub n_fluid: usize,
    pub n_ghosts_end: usize,
    pub steps: u64,
    pub wall_seconds: f64,
    /// Why the run stopped before the end time, if it did (a blow-up's diagnosis); the history holds the
    /// samples taken until then.
    pub stopped: Option<String>,
}

impl RunHistory {
    /// Fluid particle-steps per wall second (a step counts once, whatever its RK stages).
    pub fn throughput(&self) -> f64 {
        self.n_fluid as f64 * self.steps as f64 / self.wall_seconds
    }
}

/// The two runs.
#[derive(Clone, Debug)]
pub struct SlabComparison {
    pub options: SlabOptions,
    pub two: RunHistory,
    pub three: RunHistory,
}

impl SlabComparison {
    /// The first blow-up's diagnosis, if a run stopped early.
    pub fn stopped(&self) -> Option<&str> {
        self.two.stopped.as_deref().or(self.three.stopped.as_deref())
    }

    /// Sample indices k whose time (2D run's) lies in [from, to]; both runs sample at the first step past each
    /// multiple of the interval, so sample k is the same nominal time in both.
    fn samples(&self, from: f64, to: f64) -> impl Iterator<Item = usize> + '_ {
        let n = self.two.t_star.len().min(self.three.t_star.len());
        (0..n).filter(move |&k| (from..=to).contains(&self.two.t_star[k]))
    }

    /// Largest |x_3D − x_2D|/H of the front over t√(g/H) ≤ `until` (before the impact, at about 2.4).
    pub fn max_front_gap(&self, until: f64) -> f64 {
        self.samples(0.0, until)
            .map(|k| (self.three.front[k] - self.two.front[k]).abs())
            .fold(0.0, f64::max)
    }

    /// Mean |p_3D − p_2D|/(ρ0 g H) at sensor P1 (`sensor` = 0) or P2 (1) over t√(g/H) in [from, to].
    pub fn mean_pressure_gap(&self, sensor: usize, from: f64, to: f64) -> f64 {
        let (a, b) = match sensor {
            0 => (&self.two.p1, &self.three.p1),
            _ => (&self.two.p2, &self.three.p2),
        };
        let gaps: Vec<f64> = self.samples(from, to).map(|k| (b[k] - a[k]).abs()).collect();
        gaps.iter().sum::<f64>() / gaps.len() as f64
    }

    /// The histories side by side: t*, then front, P1 and P2 of the 2D and of the 3D run (one row per 2D
    /// sample).
    pub fn table(&self) -> crate::io::csv_table::Table {
        let cols = ["t_star", "front_2d", "front_3d", "p1_2d", "p1_3d", "p2_2d", "p2_3d"];
        let mut t = crate::io::csv_table::Table::new(cols.iter().map(|c| c.to_string()).collect());
        let (a, b) = (&self.two, &self.three);
        // A 3D run that stopped early (or did not run) leaves NaN in its columns past its last sample.
        let at = |v: &Vec<f64>, k: usize| v.get(k).copied().unwrap_or(f64::NAN);
        for k in 0..a.t_star.len() {
            t.push(vec![
                a.t_star[k],
                a.front[k],
                at(&b.front, k),
                a.p1[k],
                at(&b.p1, k),
                a.p2[k],
                at(&b.p2, k),
            ]);
        }
        t
    }
}

/// Runs `sim` to `opts.end`, sampling front and sensors; `at_wall(height)` is the sensor point on the right
/// wall at that height (m).
fn run_one<const D: usize>(
    db: &DamBreak,
    mut sim: Simulation<D>,
    opts: &SlabOptions,
    at_wall: impl Fn(f64) -> SVector<f64, D>,
    label: &str,
    progress: bool,
) -> anyhow::Result<RunHistory> {
    let (big_h, g, rho0) = (db.h, db.g, db.rho0);
    let ts = (big_h / g).sqrt();
    let dx = big_h / opts.res;
    let mut h = RunHistory {
        n_fluid: sim.n_fluid(),
        ..Default::default()
    };
    let mut next = 0.0;
    let mut samples = Watch(|sim: &mut Simulation<D>| {
        let t_star = sim.time / ts;
        if t_star >= next {
            sim.refresh();
            let sensor = |centre: f64| -> f64 {
                (0..5)
                    .map(|k| sim.sensor_pressure_at(&at_wall(centre + db.sensor_size * (k as f64 / 4.0 - 0.5))))
                    .sum::<f64>()
                    / 5.0
                    / (rho0 * g * big_h)
            };
            h.t_star.push(t_star);
            h.front.push(front(&sim.fluid, 0, dx) / big_h);
            h.p1.push(sensor(db.sensors[0]));
            h.p2.push(sensor(db.sensors[1]));
            next += opts.every;
        }
        Ok(if t_star >= opts.end { Flow::Stop } else { Flow::Step })
    });
    let end = opts.end;
    let mut bar = Progress::new(&format!("{label} "), progress, None, |sim: &Simulation<D>| Status {
        fraction: sim.time / ts / end,
        text: format!("t* = {:.2}", sim.time / ts),
        steps: sim.steps,
    });
    let clock = Instant::now();
    let outcome = drive(&mut sim, &mut [&mut samples, &mut bar])?;
    if let Outcome::BlewUp(e) = outcome {
        h.stopped = Some(format!("the {label} run blew up at t* = {:.3}: {e}", sim.time / ts));
    }
    h.steps = sim.steps;
    h.wall_seconds = clock.elapsed().as_secs_f64();
    h.n_ghosts_end = sim.ghosts.geom.pos.len();
    Ok(h)
}

/// Runs the dam break in 2D, then as the 3D slab (not if the 2D run blew up). A run that blows up stops with
/// its diagnosis in [`RunHistory::stopped`] and keeps the samples it took ([`SlabComparison::stopped`]).
pub fn compare(opts: &SlabOptions, progress: bool) -> anyhow::Result<SlabComparison> {
    let cfl_ok = opts.cfl.is_none_or(|c| c > 0.0);
    if !(opts.res >= 4.0 && opts.width_cells >= 1 && opts.end > 0.0 && opts.every > 0.0 && cfl_ok) {
        anyhow::bail!(
            "slab comparison: expected H/dx ≥ 4, a width of at least 1 spacing, positive end time, sampling \
             interval and CFL; got {opts:?}"
        );
    }
    let db = DamBreak::read()?;
    let h = db.h;
    let dx = h / opts.res;
    let long = (db.tank * opts.res).round() * dx;
    let width = opts.width_cells as f64 * dx;
    let tank2 = BoxTank {
        tank: Vector2::new(long, 5.0 * h),
        water: Vector2::new(db.column * h, h),
        dx,
        rho0: db.rho0,
        c0: db.c0,
        g: db.g,
    };
    let tank3 = BoxTank {
        tank: Vector3::new(long, width, 3.0 * h),
        water: Vector3::new(db.column * h, width, h),
        dx,
        rho0: db.rho0,
        c0: db.c0,
        g: db.g,
    };
    let sim2 = tank2
        .build_with_ghosts(tank2.config(), opts.ghosts)
        .map_err(anyhow::Error::msg)?;
    let sim3 = tank3
        .build_with_ghosts(tank3.config(), opts.ghosts)
        .map_err(anyhow::Error::msg)?;
    let two = run_one(&db, sim2, opts, |y| Vector2::new(long, y), "2D", progress)?;
    let three = if two.stopped.is_none() {
        run_one(&db, sim3, opts, |z| Vector3::new(long, 0.5 * width, z), "3D", progress)?
    } else {
        RunHistory::default()
    };
    Ok(SlabComparison {
        options: opts.clone(),
        two,
        three,
    })
}

/// Time before which the fronts are compared (t√(g/H)): the front meets the wall at about 2.4.
pub const BEFORE_IMPACT: f64 = 2.3;

/// A terminal summary: the runs' sizes and costs, the front gap before the impact and the wall-pressure gaps
/// after it.
pub fn summary(c: &SlabComparison) -> String {
    let o = &c.options;
    let mut s = format!(
        "dam break, H/dx {}, {:?} ghosts, to t* = {}: 2D against a 3D slab {} spacings wide\n",
        o.res, o.ghosts, o.end, o.width_cells
    );
    for (name, r) in [("2D", &c.two), ("3D", &c.three)] {
        s += &format!(
            "  {name}: {} fluid particles, {} ghosts at the end, {} steps, {:.1} s, {:.3e} particle-steps/s\n",
            r.n_fluid,
            r.n_ghosts_end,
            r.steps,
            r.wall_seconds,
            r.throughput()
        );
    }
    s += &format!(
        "  front, max |x_3D − x_2D|/H for t* ≤ {BEFORE_IMPACT}: {:.4}\n",
        c.max_front_gap(BEFORE_IMPACT)
    );
    if let Some(why) = c.stopped() {
        s += &format!("  stopped early: {why}\n");
    }
    if o.end > BEFORE_IMPACT {
        for (k, name) in ["P1", "P2"].iter().enumerate() {
            s += &format!(
                "  {name}, mean |p_3D − p_2D|/(ρgH) over t* {BEFORE_IMPACT}–{}: {:.4}\n",
                o.end,
                c.mean_pressure_gap(k, BEFORE_IMPACT, o.end)
            );
        }
    }
    s
}

/// Writes `slab_front.png` (front x/H against t*, 2D and 3D) and `slab_pressure.png` (P1 and P2 against t*) in
/// `dir`.
pub fn write_plots(c: &SlabComparison, dir: &std::path::Path) -> anyhow::Result<()> {
    use crate::io::plot::{line_plot, Series, Style};
    let series = |name: &str, r: &RunHistory, pick: fn(&RunHistory) -> &Vec<f64>| Series {
        name: name.to_string(),
        points: r.t_star.iter().copied().zip(pick(r).iter().copied()).collect(),
        style: Style::Line,
    };
    let title = format!("dam break, H/dx {}, {:?} ghosts", c.options.res, c.options.ghosts);
    line_plot(
        &dir.join("slab_front.png"),
        &format!("{title}: front"),
        "t sqrt(g/H)",
        "front x/H",
        &[
            series("2D", &c.two, |r| &r.front),
            series("3D slab", &c.three, |r| &r.front),
        ],
    )?;
    line_plot(
        &dir.join("slab_pressure.png"),
        &format!("{title}: wall pressure"),
        "t sqrt(g/H)",
        "p/(rho g H)",
        &[
            series("P1 2D", &c.two, |r| &r.p1),
            series("P1 3D slab", &c.three, |r| &r.p1),
            series("P2 2D", &c.two, |r| &r.p2),
            series("P2 3D slab", &c.three, |r| &r.p2),
        ],
    )
}
