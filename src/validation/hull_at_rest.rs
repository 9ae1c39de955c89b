//! A hull at rest in still water in 3D (`hull-at-rest`, issue #31): the Wigley hull (exact geometry,
//! `hulls/wigley.csv`, from its generator) as a 3D wall of fixed ghosts in the 2D+t scene's tank extruded along x
//! ([`crate::compare3d::ship`]), run from its hydrostatic start with U = 0. Before a ship moves, its curved 3D
//! wall must hold a fluid at rest: E_K/(M g D) below 1e-5 after settling, and the pressure on the hull within
//! 1 % of ρ g D of the hydrostatic one (the two conditions).

use super::Check;
use crate::compare3d::ship::{side_points, ShipTank};
use crate::driver::progress::{Progress, Status};
use crate::driver::{drive, Flow, Outcome, Watch};
use crate::geometry::hull_solid::section_polygon;
use crate::geometry::surface::HullSurface;
use crate::sph::polyline_wall::GhostKind;
use crate::sph::solver::{BlowUp, Simulation};
use crate::twodt::scene::SETTLE_DAMPING;

/// End of the run, t√(g/D): the acoustic ringing of the start has died down by about 10 (the 3D tank's).
pub const END_T_STAR: f64 = 20.0;
/// Damped settling until this time (t√(g/D)): every velocity multiplied by [`SETTLE_DAMPING`] after each step,
/// as the 2D+t tank settles before its ship starts (`docs/decisions/settling.md`), but over a quarter of the run
/// rather than one acoustic crossing: undamped, the lattice around the curved hull rearranges over several
/// t√(g/D) and leaves the tank ringing (E_K/(M g D) 2.6–3.8e-5 at t√(g/D) = 20, D/dx 5).
pub const SETTLE_T_STAR: f64 = 5.0;
/// The averages start here (t√(g/D)), the last quarter of the run.
const AVERAGE_FROM: f64 = 15.0;
/// Resolution of `bowwave validate hull-at-rest`, D/dx.
pub const FULL_RESOLUTION: f64 = 8.0;
/// Depths of the hull sensors on the midship section, in D below the calm waterline.
pub const SENSOR_DEPTHS: [f64; 3] = [0.25, 0.5, 0.75];

/// What the hull at rest shows at the end of its run.
#[derive(Clone, Debug)]
pub struct HullAtRest {
    /// D/dx.
    pub res: f64,
    /// As asked of [`hull_at_rest`]: `NormalFlux` for the normal-flux hull in a tank of images.
    pub tank_ghosts: GhostKind,
    /// E_K/(M g D) at the end.
    pub kinetic: f64,
    /// (depth / D, mean wall pressure over t* 15–20 / (ρ0 g D), its hydrostatic value / (ρ0 g D)) per sensor.
    pub sensors: Vec<(f64, f64, f64)>,
    /// Vertical force of the water on the hull's ghosts over ρ0 g ∇/2 (half the displacement: the water is on
    /// one side of the symmetry plane), mean over t* 15–20. Reported: the lattice's hull differs from the
    /// spline's by O(dx/D).
    pub buoyancy: f64,
    /// Mean (p − p_hydrostatic)/(ρ0 g D) of the particles 0.2–0.9 D deep at the end, within 2 dx of the hull's
    /// section and further away: the water's own pressure, beside the sensors' reading of it at the wall.
    pub near_hull: f64,
    pub away: f64,
    pub particles: usize,
    pub hull_ghosts: usize,
    pub steps: u64,
}

/// The Wigley hull of `hulls/wigley.csv`, from its generator (the file is the generator's output).
pub fn wigley() -> HullSurface {
    HullSurface::new(&crate::geometry::wigley::wigley(&Default::default()))
}

/// Runs the Wigley hull at rest at D/dx = `res` to t√(g/D) = `end`, the tank's faces made of `tank_ghosts`
/// (fixed or images, the hull of fixed ghosts; or [`GhostKind::NormalFlux`]: the hull a normal-flux wall, the
/// tank's faces images, the 3D tank's better-measured faces),
/// and measures it.
pub fn hull_at_rest(
    res: f64,
    end: f64,
    tank_ghosts: GhostKind,
    progress: bool,
) -> anyhow::Result<Result<HullAtRest, BlowUp>> {
    anyhow::ensure!(
        res.is_finite() && res >= 2.0,
        "hull-at-rest: resolution D/dx must be a number ≥ 2, got {res}"
    );
    let hull = wigley();
    let d_over_l = hull.meta.draft_m / hull.meta.length_m;
    let mut tank = ShipTank::new(hull.clone(), d_over_l / res, 0.25, 0.25);
    if tank_ghosts == GhostKind::NormalFlux {
        tank.tank_ghosts = GhostKind::Images;
        tank.hull_wall = GhostKind::NormalFlux;
    } else {
        tank.tank_ghosts = tank_ghosts;
    }
    let scene = tank.build()?;
    let (d, g, rho0) = (scene.draft, 9.81, scene.sim.cfg.eos.rho0);
    let eos = scene.sim.cfg.eos;
    let mut sim = scene.sim;
    let x_mid = 0.5 * (hull.x_range.0 + hull.x_range.1);
    let points = side_points(&hull, x_mid, &SENSOR_DEPTHS);
    // The hydrostatic pressure of the water as laid: the weight of the column above at its initial densities.
    let hydrostatic = |depth: f64| {
        let n = 1000;
        let ds = depth / n as f64;
        (0..n)
            .map(|k| eos.density(rho0 * g * (k as f64 + 0.5) * ds) * g * ds)
            .sum::<f64>()
    };
    let ts = (d / g).sqrt();
    // Distance (m) from a point to the hull's section in its transverse plane (infinite beyond the ends).
    let l = scene.length;
    let hull_distance = |x: &nalgebra::Vector3<f64>| match section_polygon(&hull, x.x / l, 400) {
        None => f64::INFINITY,
        Some(p) => p
            .iter()
            .map(|q| (q[0] * l - x.y.abs()).hypot(q[1] * l - x.z))
            .fold(f64::INFINITY, f64::min),
    };
    let m = sim.fluid.total_mass();
    let volume = crate::geometry::hydrostatics::hydrostatics(&hull, 400, 400).0.volume * scene.length.powi(3);
    let mut sums = vec![0.0; points.len()];
    let (mut lift, mut samples) = (0.0f64, 0.0f64);
    let mut averages = Watch(|sim: &mut Simulation<3>| {
        // Called before each step, with the state the last one left: damp it while settling.
        if sim.time <= SETTLE_T_STAR * ts {
            for v in sim.fluid.vel.iter_mut() {
                *v *= SETTLE_DAMPING;
            }
        }
        if sim.time > AVERAGE_FROM * ts && sim.steps.is_multiple_of(5) {
            sim.refresh();
            for (s, (_, x, n)) in sums.iter_mut().zip(&points) {
                *s += sim.wall_pressure(x, n);
            }
            lift += sim.boundary_forces()[1].z;
            samples += 1.0;
        }
        Ok(if sim.time >= end * ts { Flow::Stop } else { Flow::Step })
    });
    let mut bar = Progress::new("hull-at-rest ", progress, None, |sim: &Simulation<3>| Status {
        fraction: sim.time / ts / end,
        text: format!("t* = {:.2}", sim.time / ts),
        steps: sim.steps,
    });
    if let Outcome::BlewUp(b) = drive(&mut sim, &mut [&mut averages, &mut bar])? {
        return Ok(Err(b));
    }
    let scale = rho0 * g * d;
    // The water's own pressure at the end, near the hull and away from it, against the hydrostatic one.
    sim.refresh();
    let (mut near, mut far) = ((0.0, 0.0), (0.0, 0.0));
    for i in 0..sim.n_fluid() {
        let x = sim.fluid.pos[i];
        if -x.z < 0.2 * d || -x.z > 0.9 * d {
            continue;
        }
        let band = if hull_distance(&x) < 2.0 * sim.cfg.dx {
            &mut near
        } else {
            &mut far
        };
        band.0 += (sim.pressure()[i] - hydrostatic(-x.z)) / scale;
        band.1 += 1.0;
    }
    let samples = samples.max(1.0);
    Ok(Ok(HullAtRest {
        res,
        tank_ghosts,
        kinetic: sim.energies().kinetic / (m * g * d),
        sensors: points
            .iter()
            .zip(&sums)
            .map(|((f, x, _), s)| (*f, s / samples / scale, hydrostatic(-x.z) / scale))
            .collect(),
        buoyancy: lift / samples / (rho0 * g * 0.5 * volume),
        near_hull: near.0 / near.1,
        away: far.0 / far.1,
        particles: sim.n_fluid(),
        hull_ghosts: scene.hull_ghosts,
        steps: sim.steps,
    }))
}

impl HullAtRest {
    /// E_K/(M g D) < 1e-5 at the end; each hull sensor within 0.01 ρ0 g D of its hydrostatic pressure (the
    /// issue's 1 %); the water's own pressure near and away from the hull, and the buoyancy, printed with no
    /// tolerance.
    pub fn checks(&self) -> Vec<Check> {
        let case = format!(
            "hull-at-rest (Wigley, D/dx {:.0}{})",
            self.res,
            match self.tank_ghosts {
                GhostKind::Images => ", images",
                GhostKind::NormalFlux => ", normal-flux hull",
                GhostKind::Fixed => "",
            }
        );
        let mut out = vec![Check {
            case: case.clone(),
            quantity: "kinetic energy / (M g D) at the end".into(),
            value: self.kinetic,
            reference: 0.0,
            error: self.kinetic,
            tolerance: Some(1e-5),
        }];
        for (f, p, exact) in &self.sensors {
            out.push(Check {
                case: case.clone(),
                quantity: format!("hull pressure / (ρ g D) at {f} D, midship, mean t* 15–20"),
                value: *p,
                reference: *exact,
                error: (p - exact).abs(),
                tolerance: Some(0.01),
            });
        }
        for (quantity, value) in [
            (
                "water within 2 dx of the hull, 0.2–0.9 D deep: mean (p − p_h)/(ρ g D) at the end",
                self.near_hull,
            ),
            (
                "water further from the hull, 0.2–0.9 D deep: mean (p − p_h)/(ρ g D) at the end",
                self.away,
            ),
        ] {
            out.push(Check {
                case: case.clone(),
                quantity: quantity.into(),
                value,
                reference: 0.0,
                error: value.abs(),
                tolerance: None,
            });
        }
        out.push(Check {
            case,
            quantity: "vertical force on the hull / (ρ g ∇/2), mean t* 15–20".into(),
            value: self.buoyancy,
            reference: 1.0,
            error: (self.buoyancy - 1.0).abs(),
            tolerance: None,
        });
        out
    }
}
