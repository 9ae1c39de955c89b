//! The still tank in three dimensions (`tank-3d`): water H deep in a box tank 1 × 0.5 H (free-slip walls,
//! [`crate::sph::box_wall::BoxWall`]), run from its hydrostatic start to t√(g/H) = 20 and checked as the 2D
//! hydrostatic tank is: at rest, held by its walls, at the hydrostatic pressure. Built from code (case files
//! are 2D); `tests/three_d.rs` runs it at H/dx = 10, `bowwave validate tank-3d` at H/dx = 20.

use super::Check;
use crate::cases::box_tank::BoxTank;
use crate::driver::progress::{Progress, Status};
use crate::driver::{drive, Flow, Outcome, Watch};
use crate::sph::polyline_wall::GhostKind;
use crate::sph::solver::{BlowUp, Simulation};
use nalgebra::Vector3;

const G: f64 = 9.81;
const RHO0: f64 = 1000.0;
/// Water depth H (m); the tank is 1 × 0.5 H and 1.2 H high.
const H: f64 = 1.0;
/// Sound speed / √(gH): 10, as the 2D tank (the water is at rest, so any c0 ≫ 0 would do).
const C0: f64 = 10.0;
/// End of the run, t√(g/H): the 2D tank runs to 50; 20 is past the acoustic oscillations (damped by t* ≈ 10)
/// at a fifth of a 3D run's cost.
pub const END_T_STAR: f64 = 20.0;
/// The averages start here (t√(g/H)), the last quarter of the run.
const AVERAGE_FROM: f64 = 15.0;
/// Resolution of `bowwave validate tank-3d` (H/dx). At 10 (the CI level) the tank is 5 particles wide and every
/// particle sits within a wall's kernel reach; at 20 it is 10 wide.
pub const FULL_RESOLUTION: f64 = 20.0;

/// What the 3D still tank shows at the end of its run.
#[derive(Clone, Copy, Debug)]
pub struct TankAtRest {
    pub res: f64,
    pub ghosts: GhostKind,
    /// E_K/(MgH) at the end.
    pub kinetic: f64,
    /// Vertical force of the water on the tank, eqs. (7.12)–(7.13), over its weight, averaged over t* = 15–20.
    pub wall_force: f64,
    /// Bottom sensor at the tank's centre, averaged over t* = 15–20, over the weight per unit floor area M g / A
    /// (the exact value at rest; about 1.005 ρ0 g H, the water being ρ0 (1 + p/(ρ0 c0²)) dense).
    pub bottom: f64,
    /// Pressure gradient between the layers 0.2–0.3 H and 0.7–0.8 H above the floor at the end, over ρ̄ g, ρ̄ the
    /// mean density between them (the exact value at rest is 1).
    pub gradient: f64,
    pub particles: usize,
    pub steps: u64,
}

/// Runs the tank at H/dx = `res` with faces of `ghosts` (edges and vertices are fixed ghosts either way) and
/// measures it. Averages every 5 steps from t* = 15 (about 40 samples at H/dx 10).
///
/// The outer error is a tank that cannot be built (a bad resolution); the inner one, a run that blew up, with its
/// diagnosis, so that a caller running several cases can record it and go on.
pub fn tank_at_rest(res: f64, ghosts: GhostKind, progress: bool) -> anyhow::Result<Result<TankAtRest, BlowUp>> {
    anyhow::ensure!(
        res.is_finite() && res >= 2.0,
        "tank-3d: resolution H/dx must be a number ≥ 2, got {res}"
    );
    let tank = BoxTank::<3> {
        tank: Vector3::new(1.0, 0.5, 1.2) * H,
        water: Vector3::new(1.0, 0.5, 1.0) * H,
        dx: H / res,
        rho0: RHO0,
        c0: C0 * (G * H).sqrt(),
        g: G,
    };
    let mut sim = tank
        .build_with_ghosts(tank.config(), ghosts)
        .map_err(|e| anyhow::anyhow!("tank-3d at H/dx {res}: {e}"))?;
    let ts = (H / G).sqrt();
    let m = sim.fluid.total_mass();
    let (mut force, mut bottom, mut samples) = (0.0, 0.0, 0.0);
    // Step first, then sample: the state after each step is observed (the initial one is before the window).
    let mut averages = Watch(|sim: &mut Simulation<3>| {
        if sim.time > AVERAGE_FROM * ts && sim.steps.is_multiple_of(5) {
            sim.refresh();
            force -= sim.boundary_forces()[0].z / (m * G);
            bottom += sim.sensor_pressure_at(&Vector3::new(0.5 * tank.tank.x, 0.5 * tank.tank.y, 0.0)) / (RHO0 * G);
            samples += 1.0;
        }
        Ok(if sim.time >= END_T_STAR * ts {
            Flow::Stop
        } else {
            Flow::Step
        })
    });
    let mut bar = Progress::new("tank-3d ", progress, None, |sim: &Simulation<3>| Status {
        fraction: sim.time / ts / END_T_STAR,
        text: format!("t* = {:.2}", sim.time / ts),
        steps: sim.steps,
    });
    if let Outcome::BlewUp(b) = drive(&mut sim, &mut [&mut averages, &mut bar])? {
        return Ok(Err(b));
    }
    sim.refresh();
    let layer_mean = |z0: f64, z1: f64| {
        let (mut s, mut z, mut n) = (0.0, 0.0, 0.0);
        for (i, x) in sim.fluid.pos.iter().enumerate() {
            if x.z >= z0 && x.z < z1 {
                s += sim.pressure()[i];
                z += x.z;
                n += 1.0;
            }
        }
        (s / n, z / n)
    };
    let (p_low, z_low) = layer_mean(0.2 * H, 0.3 * H);
    let (p_high, z_high) = layer_mean(0.7 * H, 0.8 * H);
    let between: Vec<f64> = (0..sim.n_fluid())
        .filter(|&i| (z_low..z_high).contains(&sim.fluid.pos[i].z))
        .map(|i| sim.fluid.rho[i])
        .collect();
    let rho_mean = between.iter().sum::<f64>() / between.len() as f64;
    let weight_per_area = m * G / (tank.tank.x * tank.tank.y);
    Ok(Ok(TankAtRest {
        res,
        ghosts,
        kinetic: sim.energies().kinetic / (m * G * H),
        wall_force: force / samples,
        bottom: bottom / samples * RHO0 * G / weight_per_area,
        gradient: (p_low - p_high) / (z_high - z_low) / (rho_mean * G),
        particles: sim.n_fluid(),
        steps: sim.steps,
    }))
}

impl TankAtRest {
    /// The checks, with the 2D tank's tolerances: E_K/(MgH) < 1e-5 at the end; the wall force, the bottom
    /// pressure and the interior gradient within 1 % of their exact values at rest (a fluid at rest is held
    /// by its walls alone, M g; M g / A; ρ̄ g).
    pub fn checks(&self) -> Vec<Check> {
        let case = format!(
            "tank-3d (res {:.0}{})",
            self.res,
            if self.ghosts == GhostKind::Images {
                ", images"
            } else {
                ""
            }
        );
        let check = |quantity: &str, value: f64, reference: f64, tolerance: f64| Check {
            case: case.clone(),
            quantity: quantity.into(),
            value,
            reference,
            error: (value - reference).abs(),
            tolerance: Some(tolerance),
        };
        vec![
            check("kinetic energy / (M g H) at t* = 20", self.kinetic, 0.0, 1e-5),
            check("vertical wall force / (M g), mean t* 15–20", self.wall_force, 1.0, 0.01),
            check("bottom pressure / (M g / A), mean t* 15–20", self.bottom, 1.0, 0.01),
            check("interior dp/dz / (mean ρ g) at t* = 20", self.gradient, 1.0, 0.01),
        ]
    }
}
