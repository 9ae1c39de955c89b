//! Turns a [`CaseFile`] into a ready-to-run 2D [`Simulation`]: particles on the lattice (rectangles) or on
//! concentric rings (discs), initial pressure and density, walls as ghost layers.

use super::case_file::{BlockSpec, BodyForceSpec, CaseFile, CutSide, PressureSpec};
use crate::sph::multi_fluid::{equal_stiffness_sound_speed, MultiFluid, Phase};
use crate::sph::polyline_wall::GhostKind;
use crate::sph::{
    body_force::BodyForce,
    boundary::{Boundary, RigidMotion},
    eos::Eos,
    particles::{Fluid, MAX_PARTICLES},
    polyline_wall::PolylineWall,
    rigid_pose::MotionLaw,
    solver::{Simulation, SolverConfig},
    wall_sensor::{SensorFrame, WallSensor},
};
use nalgebra::{Matrix2, Vector2};
use std::sync::Arc;

type V2 = Vector2<f64>;

fn v2(v: &[f64]) -> V2 {
    V2::new(v[0], v[1])
}

/// Resolution actually used: `res` (length/dx) if given, else the case's default.
pub fn spacing(case: &CaseFile, res: Option<f64>) -> f64 {
    case.scales.length / res.unwrap_or(case.scales.resolution)
}

/// The solver configuration of a case at spacing `dx`.
pub fn solver_config(case: &CaseFile, dx: f64) -> SolverConfig<2> {
    let body = match &case.body_force {
        BodyForceSpec::Gravity { g } => BodyForce::Uniform(v2(g)),
        BodyForceSpec::Central { omega, centre } => BodyForce::Central {
            omega: *omega,
            centre: v2(centre),
        },
        BodyForceSpec::None => BodyForce::Uniform(V2::zeros()),
    };
    let c0 = case.c0();
    let mut cfg = SolverConfig::new(dx, case.fluid.rho0, c0, body);
    let n = &case.numerics;
    cfg.kernel = n.kernel;
    cfg.h = n.h_over_dx.unwrap_or(n.kernel.default_h_over_dx()) * dx;
    cfg.eos = Eos {
        kind: case.fluid.eos,
        rho0: case.fluid.rho0,
        c0,
        gamma: crate::sph::eos::TAIT_GAMMA_WATER,
    };
    cfg.viscosity = n.viscosity;
    cfg.diffusion = n.density_diffusion;
    cfg.delta = n.delta;
    cfg.integrator = n.integrator;
    cfg.cfl = n.cfl.unwrap_or(n.integrator.default_cfl());
    cfg.domain = Some((v2(&case.domain.min), v2(&case.domain.max)));
    cfg.dt_floor = 1e-3 * cfg.h / c0;
    cfg.ghost_interpolation = n.ghost_interpolation;
    cfg.kernel_table = n.kernel_table;
    cfg.shifting = case.shifting();
    cfg.wall_slip = n.wall_slip;
    cfg.gradient_stage = n.gradient_stage;
    cfg.normal_flux = n.normal_flux;
    cfg.multi_fluid = multi_fluid(case, &cfg.eos);
    cfg
}

/// The phases of a case with `[[phases]]` (`None` without): `[fluid]` first, then the others, each light
/// phase's sound speed by the equal-stiffness rule unless given.
fn multi_fluid(case: &CaseFile, water: &Eos) -> Option<MultiFluid> {
    if case.phases.is_empty() && !case.multi_fluid.with_one_phase {
        return None;
    }
    let mut phases = vec![Phase {
        name: case.fluid.name.clone(),
        eos: *water,
    }];
    for p in &case.phases {
        let mut eos = Eos {
            kind: p.eos,
            rho0: p.rho0,
            c0: 0.0,
            gamma: p.gamma,
        };
        eos.c0 = p.c0.unwrap_or_else(|| equal_stiffness_sound_speed(water, &eos));
        phases.push(Phase {
            name: p.name.clone(),
            eos,
        });
    }
    let m = &case.multi_fluid;
    Some(MultiFluid {
        phases,
        background_pressure: m.background_pressure,
        interface_repulsion: m.interface_repulsion,
        diffusion: m.diffusion,
        density: m.density,
    })
}

/// The fluid particles of a case at spacing `dx`; `phase_eos[k]` is phase k's state equation (one entry for a
/// single phase).
pub fn fluid(case: &CaseFile, dx: f64, phase_eos: &[Eos], body: &BodyForce<2>) -> Fluid<2> {
    let mut f = Fluid::default();
    let g_down = match body {
        BodyForce::Uniform(g) => -g.y,
        _ => 0.0,
    };
    for b in &case.blocks {
        match b {
            BlockSpec::Rectangle {
                min,
                max,
                phase,
                pressure,
                velocity,
                velocity_gradient,
                cut,
            } => {
                let k = case
                    .phase_index(phase.as_deref())
                    .expect("checked when the case was read");
                let eos = &phase_eos[k as usize];
                let (lo, hi) = (v2(min), v2(max));
                let nx = ((hi.x - lo.x) / dx).round() as usize;
                let ny = ((hi.y - lo.y) / dx).round() as usize;
                let centre = (lo + hi) * 0.5;
                for j in 0..ny {
                    for i in 0..nx {
                        let x = lo + V2::new((i as f64 + 0.5) * dx, (j as f64 + 0.5) * dx);
                        if cut.as_ref().is_some_and(|c| !c.keeps(x.x, x.y)) {
                            continue;
                        }
                        // The block's top at this x: its rectangle's, or the curve it is cut below.
                        let y_top = match cut {
                            Some(c) if c.keep == CutSide::Below => c.height(x.x).min(hi.y),
                            _ => hi.y,
                        };
                        let p = match pressure {
                            PressureSpec::Zero => 0.0,
                            PressureSpec::Hydrostatic { top, overburden } => {
                                let over = overburden.as_ref().map_or(0.0, |o| o.rho0 * g_down * (o.up_to - y_top));
                                top + over + eos.rho0 * g_down * (y_top - x.y)
                            }
                            PressureSpec::Paraboloid { p_centre, p_rim } => {
                                p_rim
                                    + (p_centre - p_rim)
                                        * (1.0 - (x - centre).norm_squared() / (0.5 * (hi - lo)).norm_squared())
                            }
                        };
                        let u = velocity_at(velocity, velocity_gradient, &x, &centre);
                        let rho = eos.density(p);
                        f.push(x, u, rho, rho * dx * dx, hi.y - x.y);
                        *f.phase.last_mut().expect("just pushed") = k;
                    }
                }
            }
            BlockSpec::Disc {
                centre,
                radius,
                inner_radius,
                phase,
                pressure,
                velocity,
                velocity_gradient,
            } => {
                let kp = case
                    .phase_index(phase.as_deref())
                    .expect("checked when the case was read");
                let eos = &phase_eos[kp as usize];
                let c = v2(centre);
                let nr = ((radius - inner_radius) / dx).round().max(1.0) as usize;
                let dr = (radius - inner_radius) / nr as f64;
                for k in 0..nr {
                    let r = inner_radius + (k as f64 + 0.5) * dr;
                    let n = ((2.0 * std::f64::consts::PI * r / dr).round() as usize).max(1);
                    // Area of the ring shared equally by its n particles.
                    let area = std::f64::consts::PI * ((r + 0.5 * dr).powi(2) - (r - 0.5 * dr).powi(2)) / n as f64;
                    // Rings alternate their angular offset, counted from the centre (an annulus continues the
                    // disc inside it).
                    let ring = (inner_radius / dr).round() as usize + k;
                    let offset = if ring.is_multiple_of(2) { 0.0 } else { 0.5 };
                    for m in 0..n {
                        let th = 2.0 * std::f64::consts::PI * (m as f64 + offset) / n as f64;
                        let x = c + V2::new(r * th.cos(), r * th.sin());
                        let p = match pressure {
                            PressureSpec::Zero => 0.0,
                            PressureSpec::Hydrostatic { .. } => 0.0,
                            PressureSpec::Paraboloid { p_centre, p_rim } => {
                                p_rim + (p_centre - p_rim) * (1.0 - (r / radius).powi(2))
                            }
                        };
                        let u = velocity_at(velocity, velocity_gradient, &x, &c);
                        let rho = eos.density(p);
                        f.push(x, u, rho, rho * area, radius - r);
                        *f.phase.last_mut().expect("just pushed") = kp;
                    }
                }
            }
        }
    }
    f
}

fn velocity_at(velocity: &Option<Vec<f64>>, gradient: &Option<Vec<Vec<f64>>>, x: &V2, centre: &V2) -> V2 {
    let mut u = velocity.as_ref().map(|v| v2(v)).unwrap_or_else(V2::zeros);
    if let Some(g) = gradient {
        let m = Matrix2::new(g[0][0], g[0][1], g[1][0], g[1][1]);
        u += m * (x - centre);
    }
    u
}

/// The walls of a case as ghost-particle boundaries, each moving with its law (`laws`, from
/// [`super::wall_motion::laws`]).
pub fn walls(case: &CaseFile, dx: f64, support: f64, laws: &[Option<MotionLaw>]) -> Vec<Box<dyn Boundary<2>>> {
    case.walls
        .iter()
        .zip(laws)
        .map(|(w, law)| {
            let mut wall = PolylineWall::new(
                &w.name,
                w.points.iter().map(|p| v2(p)).collect(),
                w.fluid_side,
                RigidMotion::Fixed,
                dx,
                support,
            )
            .with_ghosts(w.ghosts);
            if let Some(law) = law {
                wall = wall.with_motion_law(law.clone());
            }
            Box::new(wall) as Box<dyn Boundary<2>>
        })
        .collect()
}

/// The case's wall sensors (its pressure probes not `in_fluid`, in order) as faces on their walls, moving
/// with them (`laws`, from [`super::wall_motion::laws`]).
pub fn wall_sensors(case: &CaseFile, dx: f64, laws: &[Option<MotionLaw>]) -> anyhow::Result<Vec<WallSensor<2>>> {
    let mut out = vec![];
    for (k, p) in case.probes.pressure.iter().enumerate().filter(|(_, p)| !p.in_fluid) {
        let pl = super::sensor_placement::place(case, k, p)
            .map_err(|(field, expected)| anyhow::anyhow!("case `{}`: {field}: expected {expected}", case.name))?;
        let frame = laws[pl.wall]
            .clone()
            .map(|law| SensorFrame(Arc::new(move |t| law.pose(t).affine())));
        out.push(WallSensor::face(pl.centre, pl.tangent, p.size, pl.inward, frame, dx));
    }
    Ok(out)
}

/// About how many fluid particles and wall ghosts a case holds at spacing `dx` (kernel support `support`):
/// the blocks' lattice counts and, per wall segment, its length in spacings (plus the ends) times the ghost
/// layers. An estimate made before anything is allocated.
pub fn estimated_particles(case: &CaseFile, dx: f64, support: f64) -> f64 {
    let fluid: f64 = case
        .blocks
        .iter()
        .map(|b| match b {
            BlockSpec::Rectangle { min, max, .. } => {
                ((max[0] - min[0]) / dx).round() * ((max[1] - min[1]) / dx).round()
            }
            BlockSpec::Disc { radius, .. } => std::f64::consts::PI * (radius / dx).powi(2) + 3.0,
        })
        .sum();
    let layers = (support / dx).ceil() + 1.0;
    let ghosts: f64 = case
        .walls
        .iter()
        .flat_map(|w| w.points.windows(2))
        .map(|p| ((p[1][0] - p[0][0]).hypot(p[1][1] - p[0][1]) / dx + 2.0 * layers) * layers)
        .sum();
    fluid + ghosts
}

/// Whether a case can be built at spacing `dx` (kernel support `support`): `dx` positive and finite, every
/// rectangular block at least one spacing across, and the particles ([`estimated_particles`]) and the cells
/// of the domain within [`MAX_PARTICLES`]. The error names the case, the field and what was expected.
pub fn check_size(case: &CaseFile, dx: f64, support: f64) -> anyhow::Result<()> {
    let name = &case.name;
    anyhow::ensure!(
        dx.is_finite() && dx > 0.0,
        "case `{name}`: resolution: expected a positive number of particles per reference length (dx = {dx} m)"
    );
    for (k, b) in case.blocks.iter().enumerate() {
        if let BlockSpec::Rectangle { min, max, .. } = b {
            anyhow::ensure!(
                ((max[0] - min[0]) / dx).round() >= 1.0 && ((max[1] - min[1]) / dx).round() >= 1.0,
                "case `{name}`: blocks[{k}]: expected at least one spacing across, but dx = {dx:e} m at this \
                 resolution: raise `scales.resolution` (or --res)"
            );
        }
    }
    let (lo, hi) = (&case.domain.min, &case.domain.max);
    let cells: f64 = (0..2)
        .map(|i| (hi[i] - lo[i] + 2.0 * support) / support + 1.0)
        .product();
    for (what, n) in [
        (
            "particles (fluid and wall ghosts)",
            estimated_particles(case, dx, support),
        ),
        ("neighbour-search cells over the domain", cells),
    ] {
        anyhow::ensure!(
            n <= MAX_PARTICLES,
            "case `{name}`: about {n:.3e} {what} at dx = {dx:e} m: expected at most {MAX_PARTICLES:e} \
             (lower the resolution, or shrink the blocks, walls or domain)"
        );
    }
    Ok(())
}

/// The whole simulation of a case at resolution `res` (length/dx; `None`: the case's default), or an error
/// if the case cannot be built at that resolution ([`check_size`]).
pub fn build(case: &CaseFile, res: Option<f64>) -> anyhow::Result<Simulation<2>> {
    let dx = spacing(case, res);
    let cfg = solver_config(case, dx);
    let support = cfg.kernel.support_over_h() * cfg.h;
    check_size(case, dx, support)?;
    if !case.phases.is_empty() {
        if let Some(k) = case.walls.iter().position(|w| w.ghosts == GhostKind::NormalFlux) {
            anyhow::bail!(
                "case `{}`: walls[{k}].ghosts is `normal-flux`, but the case has `[[phases]]`; expected `fixed` or \
                 `images` (the normal-flux terms are single phase)",
                case.name
            );
        }
    }
    let phase_eos = cfg.multi_fluid.as_ref().map_or(vec![cfg.eos], |m| m.eoses());
    let fl = fluid(case, dx, &phase_eos, &cfg.body_force);
    let laws = super::wall_motion::laws(case)?;
    let mut sim = Simulation::new(cfg, fl, walls(case, dx, support, &laws));
    sim.set_sensors(wall_sensors(case, dx, &laws)?);
    Ok(sim)
}
