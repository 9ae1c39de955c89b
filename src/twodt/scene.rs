//! The 2D+t scene (thesis §10.1.2, Fig. 10.3), non-dimensional with L, g and ρ0: half domain by symmetry,
//! the section on the left, a symmetry wall y = 0 below the keel, bottom at depth Z = 2D, a wall at y = W =
//! 4B, open top (with `--air`, an air layer above the water under a lid that keeps the enclosed area,
//! `lid.rs`); graded resolution at constant h.

use super::lattice;
use super::lid::{enclose, Lid};
use super::profile::SectionProfile;
use crate::geometry::surface::HullSurface;
use crate::sph::body_force::BodyForce;
use crate::sph::boundary::{Boundary, RigidMotion};
use crate::sph::deforming_wall::DeformingWall;
use crate::sph::equations::viscosity::Viscosity;
use crate::sph::multi_fluid::{equal_stiffness_sound_speed, MultiFluid, Phase};
use crate::sph::particles::{Fluid, MAX_PARTICLES};
use crate::sph::polyline_wall::{solid_side, FluidSide, PolylineWall};
use crate::sph::solver::{Simulation, SolverConfig};
use nalgebra::Vector2;
use std::sync::Arc;

type V2 = Vector2<f64>;

pub use super::config::{ConfigError, ConfigOption, Packing, PlungeCirculation, TwoDtConfig, Until};

/// Estimated bow-wave height H_pj/D at plunge: the straight line through Table 10.1 of the thesis (Athena,
/// Fr 0.30–0.64), H_pj/D ≈ 0.88 Fr − 0.005, used for every hull as an order of magnitude only.
pub fn estimated_hpj_over_d(fr: f64) -> f64 {
    (0.88 * fr - 0.005).max(0.1)
}

/// dx_f/L from H_pj/dx = 25 (eq. 10.9 asks for > 20; 25 leaves a margin for the estimate).
pub fn auto_dx(fr: f64, draft: f64) -> f64 {
    estimated_hpj_over_d(fr) * draft / 25.0
}

/// Ratio of the expected fastest water to the fastest point of the section (dimensionless): the run-up sheet
/// is faster than the wall that pushes it (`docs/decisions/twodt-sound-speed.md`).
pub const RUN_UP_SPEED_FACTOR: f64 = 2.5;

/// Expected maximum fluid speed / √(gL): the larger of [`RUN_UP_SPEED_FACTOR`] times the largest expansion
/// velocity |w_n| met between x0 and x_end over the whole girth, and the free-fall speed √(2 g H_pj) of the crest
/// (`docs/decisions/twodt-sound-speed.md`, which also records why the wetted girth alone was tried and not kept).
pub fn expected_max_speed(hull: &HullSurface, fr: f64, x0: f64, x_end: f64, draft: f64) -> f64 {
    let mut wn = 0.0f64;
    let n = 200;
    for k in 0..=n {
        let x = x0 + (x_end - x0) * k as f64 / n as f64;
        if let Some(s) = hull.section(x, draft / 20.0) {
            for p in s {
                wn = wn.max((p.w_n_over_u * fr).abs());
            }
        }
    }
    (RUN_UP_SPEED_FACTOR * wn).max((2.0 * estimated_hpj_over_d(fr) * draft).sqrt())
}

/// How many times longer a scene with air settles: the rows on either side of the interface take about three
/// acoustic crossings of the depth to find their rest (a still Athena tank, dx/L 4e-3, 1 D of air: E_K/(M g D)
/// 2.6e-5 when the ship would start after one crossing, 1.3e-5 after three, and 5e-7 0.14 L later against
/// 4e-6 after one).
pub const AIR_SETTLE_FACTOR: f64 = 3.0;

/// Duration of the damped settling (time units √(L/g)): `settle` crossings of the depth at c0, three times as
/// many with air ([`AIR_SETTLE_FACTOR`]).
pub fn settle_time(cfg: &TwoDtConfig, depth: f64, c0: f64) -> f64 {
    let air = if cfg.air.is_some() { AIR_SETTLE_FACTOR } else { 1.0 };
    air * cfg.settle_crossings * depth / c0
}

/// Everything fixed once the case is resolved.
#[derive(Clone, Debug)]
pub struct SceneGeometry {
    pub draft: f64,
    pub beam: f64,
    pub width: f64,
    pub depth: f64,
    pub dx_f: f64,
    pub dx_c: f64,
    pub c0: f64,
    pub x0: f64,
    pub x_end: f64,
    pub z_top: f64,
    pub z_cut: f64,
}

/// A ready-to-run scene.
pub struct Scene {
    pub geom: SceneGeometry,
    pub profile: SectionProfile,
    pub sim: Simulation<2>,
    /// Initial depth of each particle (indexed by particle id), and its row (0: the top row).
    pub initial_depth: Vec<f64>,
    pub initial_row: Vec<usize>,
    /// What the packing did, when it ran ([`TwoDtConfig::packing`]).
    pub packing: Option<crate::sph::packing::PackingReport>,
}

/// Factor applied to every velocity after each settling step (with air, the same per unit of time).
pub const SETTLE_DAMPING: f64 = 0.9;

impl Scene {
    /// Damped settling (see [`TwoDtConfig::settle_crossings`]): steps until the ship starts at
    /// `profile.t_start`, multiplying every velocity by [`SETTLE_DAMPING`] after each step. Returns the
    /// kinetic energy of the last state before the start: the step that crosses `t_start` already moves the
    /// section in its later stages (with Wigley's full-depth stem that one step gave 1.24e-4 M g D, which was
    /// reported as what the settling left; regression test `settling_energy_is_measured_before_the_ship_starts`).
    pub fn settle(&mut self) -> anyhow::Result<f64> {
        use crate::driver::{drive, Flow, Outcome, Watch};
        let kinetic = |sim: &Simulation<2>| sim.energies().kinetic;
        let t_start = self.profile.t_start;
        let mut ke = kinetic(&self.sim);
        let steps0 = self.sim.steps;
        // With air the step is c_air/c_water times shorter: the same damping per unit of time, or the
        // particles, held by a damping that many times stronger, would not reach their rest positions.
        let damping = match &self.sim.cfg.multi_fluid {
            None => SETTLE_DAMPING,
            Some(mf) => SETTLE_DAMPING.powf(self.sim.cfg.eos.c0 / mf.max_sound_speed()),
        };
        let mut damped = Watch(|sim: &mut Simulation<2>| {
            if sim.steps > steps0 {
                for v in sim.fluid.vel.iter_mut() {
                    *v *= damping;
                }
                if sim.time <= t_start {
                    ke = kinetic(sim);
                }
            }
            Ok(if sim.time >= t_start { Flow::Stop } else { Flow::Step })
        });
        match drive(&mut self.sim, &mut [&mut damped])? {
            Outcome::BlewUp(b) => anyhow::bail!("settling blew up: {b}"),
            Outcome::Finished | Outcome::Halted(_) => Ok(ke),
        }
    }
}

/// Builds the scene: hull draft and beam from its metadata (D = draft_m/length_m, B = beam_m/length_m).
pub fn build(hull: Arc<HullSurface>, cfg: &TwoDtConfig) -> anyhow::Result<Scene> {
    let meta = &hull.meta;
    let draft = meta.draft_m / meta.length_m;
    let beam = meta.beam_m / meta.length_m;
    cfg.check()?;
    let dx_f = cfg.dx.unwrap_or_else(|| auto_dx(cfg.fr, draft));
    anyhow::ensure!(
        dx_f > 0.0 && dx_f <= draft / 4.0,
        "dx/L: expected in (0, D/4 = {}], at least 4 particles over the draft, got {dx_f}",
        draft / 4.0
    );
    let dx_c = cfg.coarse_ratio * dx_f;
    let width = cfg.width_over_beam * beam;
    let depth = cfg.depth_over_draft * draft;
    // At most the whole tank at the fine spacing: a bound on what the graded rows will hold.
    let bound = width * depth / (dx_f * dx_f);
    anyhow::ensure!(
        bound <= MAX_PARTICLES,
        "dx/L = {dx_f:e} in a tank {:.3} L wide and {:.3} L deep: up to {bound:.3e} particles, expected at most {:e} \
         (a larger dx/L, or a smaller W/B or Z/D)",
        width,
        depth,
        MAX_PARTICLES
    );
    let x0 = cfg.x0.unwrap_or(hull.x_range.0);
    let x_end = match cfg.until {
        Until::X(x) => x,
        Until::Transom => hull.x_range.1,
        Until::Plunge => cfg.give_up_at.unwrap_or(hull.x_range.1).min(hull.x_range.1),
    };
    anyhow::ensure!(x_end > x0, "--until: x/L = {x_end} is not after the start x0 = {x0}");
    let c0 = cfg
        .c0
        .unwrap_or_else(|| 10.0 * expected_max_speed(&hull, cfg.fr, x0, x_end.min(hull.x_range.1), draft));
    let h = 1.33 * dx_f;
    let support = 3.0 * h;
    let z_hull_top = (0..=100)
        .filter_map(|k| hull.curve(hull.x_range.0 + (hull.x_range.1 - hull.x_range.0) * k as f64 / 100.0))
        .map(|c| c.point(1.0).z)
        .fold(0.0, f64::max);
    let z_top = z_hull_top + draft;
    // The moving symmetry wall starts below the deepest keel by two supports, half a spacing above the end of
    // the fixed tank wall, so that both walls' ghosts lie on one lattice across the junction (a junction
    // off the lattice drove a jet of 0.08 √(gL) up the symmetry plane; regression test
    // `junction_of_symmetry_walls_leaves_the_tank_at_rest`).
    let keel_min = draft;
    let n_cut = (((depth - keel_min - 2.0 * support) / dx_f).floor() - 1.0).max(1.0);
    let z_cut = -depth + (n_cut + 0.5) * dx_f;
    anyhow::ensure!(
        z_cut < -keel_min,
        "Z/D = {} leaves no room below the keel at this resolution; expected a deeper domain",
        cfg.depth_over_draft
    );
    if let Some(a) = cfg.air {
        anyhow::ensure!(
            a * draft <= z_top - 2.0 * support,
            "--air: an air layer {a} D high reaches above the tank's walls (their top {:.3} D above the calm \
             level, less two kernel supports); expected at most {:.3}",
            z_top / draft,
            (z_top - 2.0 * support) / draft
        );
        anyhow::ensure!(
            a * draft >= 2.0 * dx_f,
            "--air: an air layer {a} D high holds fewer than two rows at dx/L = {dx_f:e}; expected at least {:.3}",
            2.0 * dx_f / draft
        );
    }
    let geom = SceneGeometry {
        draft,
        beam,
        width,
        depth,
        dx_f,
        dx_c,
        c0,
        x0,
        x_end,
        z_top,
        z_cut,
    };
    let profile = SectionProfile {
        hull: hull.clone(),
        u: cfg.fr,
        x0,
        ds: dx_f,
        z_cut,
        z_top,
        t_start: settle_time(cfg, depth, c0),
    };
    // The air layer's height (units of L), its top a whole number of spacings above the bottom so that the
    // far wall's ghosts stay on the fluid's lattice, and its weight on the water, ρ_a g h_air / (ρ_w g L).
    let air_height = cfg.air.map(|a| ((a * draft + depth) / dx_f).round() * dx_f - depth);
    let air_weight = air_height.map_or(0.0, |h| cfg.air_density * h);
    let tank = PolylineWall::new(
        "tank",
        vec![
            V2::new(width, z_top),
            V2::new(width, -depth),
            V2::new(0.0, -depth),
            V2::new(0.0, z_cut - 0.5 * dx_f),
        ],
        FluidSide::Right,
        RigidMotion::Fixed,
        dx_f,
        support,
    );
    let p0 = profile.at(0.0);
    let pf = profile.clone();
    // With air, one wall: the section up to the lid, the lid, the tank (`lid.rs`).
    let wall: Box<dyn Fn(f64) -> crate::sph::deforming_wall::Profile + Send + Sync> = match air_height {
        None => Box::new(move |t| pf.at(t)),
        Some(h) => {
            let lid = Lid::new(&profile, width, h);
            Box::new(move |t| enclose(&pf.at(t), lid.motion(t), width, depth, z_cut - 0.5 * dx_f))
        }
    };
    let section = DeformingWall::new("section", wall, FluidSide::Right, dx_f, support);

    // Particles: graded rows, hydrostatic pressure, none inside the section at t = 0.
    let d1 = cfg.fine_depth_over_draft * draft;
    let d2 = (depth - cfg.coarse_height_over_draft * draft).max(d1);
    let rows = lattice::rows(depth, width, dx_f, dx_c, d1, d2);
    let mut fluid = Fluid::<2>::default();
    let mut cfg_s = SolverConfig::new(dx_f, 1.0, c0, BodyForce::Uniform(V2::new(0.0, -1.0)));
    cfg_s.h = h;
    cfg_s.diffusion = cfg.diffusion;
    cfg_s.gradient_stage = cfg.gradient_stage;
    cfg_s.kernel_table = !cfg.exact_kernel;
    cfg_s.shifting = cfg.shifting();
    if let Some(alpha) = cfg.alpha {
        cfg_s.viscosity = Viscosity::Artificial { alpha };
    }
    if let Some(cfl) = cfg.cfl {
        cfg_s.cfl = cfl;
    }
    cfg_s.domain = Some((
        V2::new(-support, -depth - support),
        V2::new(width + support, z_top + 10.0 * draft),
    ));
    let mut initial_depth = vec![];
    let mut initial_row = vec![];
    let mut lattice_particles = lattice::particles(&rows, width);
    let packing = cfg
        .packing
        .applies(cfg.coarse_ratio)
        .then(|| pack_rows(&mut lattice_particles, width, depth, d1, dx_f, h));
    // Particles inside the section, or closer to it than a quarter spacing, are not created. (A test at half a
    // spacing removed the whole first column along the symmetry plane whenever the row spacing W/round(W/dx)
    // fell just below dx, and the water collapsed into the gap as a jet up the plane: regression test
    // `first_column_along_the_symmetry_plane_is_kept`.)
    let inside = |p: &V2| {
        solid_side(&p0.points, FluidSide::Right, p, support).is_some()
            || (crate::sph::polyline_wall::nearest_point(&p0.points, p) - p).norm() < 0.25 * dx_f
    };
    cfg_s.multi_fluid = air_height.map(|_| air_phases(&cfg_s.eos, cfg.air_density));
    for (p, area, row) in lattice_particles {
        if inside(&p) {
            continue;
        }
        // Hydrostatic, under the air's weight when there is air.
        let rho = cfg_s.eos.density(-p.y + air_weight);
        fluid.push(p, V2::zeros(), rho, rho * area, -p.y);
        initial_depth.push(-p.y);
        initial_row.push(row);
    }
    if let (Some(h_air), Some(mf)) = (air_height, &cfg_s.multi_fluid) {
        let air_eos = *mf.eos(AIR);
        // The rows of a uniform layer of height h_air, turned upside down: from half a spacing above the calm
        // level to half a spacing below the air's free surface.
        let rows = lattice::rows(h_air, width, dx_f, dx_f, h_air, h_air);
        for (q, area, _) in lattice::particles(&rows, width) {
            let p = V2::new(q.x, -q.y);
            if inside(&p) {
                continue;
            }
            let rho = air_eos.density(air_eos.rho0 * (h_air - p.y));
            fluid.push(p, V2::zeros(), rho, rho * area, -p.y);
            *fluid.phase.last_mut().expect("just pushed") = AIR;
            initial_depth.push(-p.y);
            // Not a row of the water (pictures mark the water's top two rows).
            initial_row.push(usize::MAX);
        }
    }
    let boundaries: Vec<Box<dyn Boundary<2>>> = match cfg_s.multi_fluid.as_mut() {
        None => vec![Box::new(tank), Box::new(section)],
        Some(mf) => {
            // Closed by the lid, with Hammani et al.'s background pressure (`--air-background`).
            mf.background_pressure = cfg.air_background * (depth + air_weight);
            vec![Box::new(section)]
        }
    };
    let sim = Simulation::new(cfg_s, fluid, boundaries);
    Ok(Scene {
        geom,
        profile,
        sim,
        initial_depth,
        initial_row,
        packing,
    })
}

/// The phase index of the air in a 2D+t scene with air (the water is phase 0).
pub const AIR: u8 = 1;

/// Tait exponent of the air (Hammani et al. eq. 23; Grenier et al. §4.2).
pub const AIR_GAMMA: f64 = 1.4;

/// The water (the single-phase state equation, unchanged) and the air above it (`density_ratio` ρ_a/ρ_w, Tait
/// with γ 1.4), for the multi-fluid δ-SPH of Hammani et al. The air's sound speed is their eq. 23 for Tait
/// water (γ_w 7): c_a = c_w √(γ_a ρ_w / (γ_w ρ_a)), 14.1 c_w at a ratio of 1000, whichever law the water
/// uses, so that the air's bulk modulus ρ_a c_a² is a fifth of the water's as in their pair (with the linear
/// water law the literal rule would give 37 c_w and a step 2.6 times smaller still). No background pressure yet:
/// [`build`] sets it once the lid closes the tank (`lid.rs`).
pub fn air_phases(water: &crate::sph::eos::Eos, density_ratio: f64) -> MultiFluid {
    use crate::sph::eos::{Eos, EosKind, TAIT_GAMMA_WATER};
    let tait_water = Eos {
        kind: EosKind::Tait,
        gamma: TAIT_GAMMA_WATER,
        ..*water
    };
    let mut air = Eos {
        kind: EosKind::Tait,
        rho0: water.rho0 * density_ratio,
        c0: 0.0,
        gamma: AIR_GAMMA,
    };
    air.c0 = equal_stiffness_sound_speed(&tait_water, &air);
    MultiFluid {
        phases: vec![
            Phase {
                name: "water".into(),
                eos: *water,
            },
            Phase {
                name: "air".into(),
                eos: air,
            },
        ],
        background_pressure: 0.0,
        interface_repulsion: 0.0,
        diffusion: Default::default(),
        density: Default::default(),
    }
}

/// Fraction of the fine layer, from the calm level down, whose rows the packing holds in place. Measured on
/// the still tank (Athena before the stem, dx/L = 2e-3, r = 1.5) and on the Athena Fr 0.5 crest at x/L = 0.2
/// (dx/L = 1.5e-3; uniform rows: 0.988 D): holding nothing, 7.6e-7 M g D and 0.930 D; the whole fine layer,
/// 1.0e-6 and 0.989; half of it, 7.0e-7 and 0.993; a quarter, 8.6e-7 and 1.016 (docs/reference/twodt.md).
pub const PACKING_HELD_FRACTION: f64 = 0.5;

/// Packs the initial rows (thesis chapter 6) below the upper part of the fine layer (depth `fine_depth`,
/// see [`PACKING_HELD_FRACTION`]) inside the rectangle [0, W] × [−Z, 0], closed by fixed particles of
/// spacing dx_f on all four sides (the lid on top stands in for the free surface, as the thesis prescribes)
/// and by the held rows; each particle keeps its area as its volume. The fixed layers sit at half a spacing
/// outside each side whatever W/dx_f and Z/dx_f are: on one global lattice they left a gap of up to 1.5 dx_f
/// at the far wall and the bottom, the particles there were pushed into it against the clamp and kept moving
/// (specific E_K after packing 1e-2 instead of 1e-7; regression test
/// `packing_converges_when_the_tank_is_not_a_whole_number_of_spacings`).
fn pack_rows(
    particles: &mut [(V2, f64, usize)],
    width: f64,
    depth: f64,
    fine_depth: f64,
    dx_f: f64,
    h: f64,
) -> crate::sph::packing::PackingReport {
    let kernel = crate::sph::kernel::Kernel::<2>::new(crate::sph::kernel::KernelKind::RenormalizedGaussian, h);
    // Layers at half a spacing outside each side, on a dx_f lattice along it, carried through the corners.
    // (Mirror images of the initial rows across each side, which carry the local spacing, left 3e-6 M g D of
    // spurious flow instead of 7e-7: the run's ghosts mirror the packed positions, not the initial ones.)
    let layers = (kernel.support / dx_f).ceil() as i64 + 1;
    let along = |len: f64| {
        let n = (len / dx_f).round().max(1.0);
        (0..n as i64).map(move |k| (k as f64 + 0.5) * len / n)
    };
    let out = |k: i64| (k as f64 + 0.5) * dx_f;
    let mut fixed = vec![];
    for k in 0..layers {
        for s in along(depth) {
            fixed.push(V2::new(-out(k), -s));
            fixed.push(V2::new(width + out(k), -s));
        }
        for s in along(width) {
            fixed.push(V2::new(s, out(k)));
            fixed.push(V2::new(s, -depth - out(k)));
        }
        for k2 in 0..layers {
            for (cx, sx) in [(0.0, -1.0), (width, 1.0)] {
                for (cy, sy) in [(0.0, 1.0), (-depth, -1.0)] {
                    fixed.push(V2::new(cx + sx * out(k), cy + sy * out(k2)));
                }
            }
        }
    }
    let mut fixed_v = vec![dx_f * dx_f; fixed.len()];
    // The rows of the upper half of the fine layer are a lattice already at rest: they are held, with the
    // free surface they carry, and only the rows below move.
    let moves = |p: &V2| p.y < -PACKING_HELD_FRACTION * fine_depth;
    for (p, area, _) in particles.iter().filter(|p| !moves(&p.0)) {
        fixed.push(*p);
        fixed_v.push(*area);
    }
    let index: Vec<usize> = (0..particles.len()).filter(|&i| moves(&particles[i].0)).collect();
    let mut pos: Vec<V2> = index.iter().map(|&i| particles[i].0).collect();
    let vol: Vec<f64> = index.iter().map(|&i| particles[i].1).collect();
    let m = 0.25 * dx_f;
    let report = crate::sph::packing::pack(&kernel, &mut pos, &vol, &fixed, &fixed_v, &Default::default(), |x| {
        x.x = x.x.clamp(m, width - m);
        x.y = x.y.clamp(-depth + m, -m);
    });
    log::info!("packing: {report:?}");
    for (i, x) in index.into_iter().zip(pos) {
        particles[i].0 = x;
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::wigley;

    /// Wigley's y = (B/2)(1 − ξ²)(1 − (z/D)²), ξ = 2x/L − 1, wall-sided above the waterline: |w_n|/U =
    /// |∂y/∂x| / √(1 + (∂y/∂z)²) is largest at the stem and stern from the waterline up, 2B/L, so the expected speed
    /// is 2.5 Fr · 2B/L.
    #[test]
    fn expected_speed_is_two_and_a_half_times_the_wigley_waterline_entry_speed() {
        let spec = wigley::WigleySpec::default();
        let s = HullSurface::new(&wigley::wigley(&spec));
        let (fr, d) = (0.5, 1.0 / spec.l_over_d);
        let exact = RUN_UP_SPEED_FACTOR * fr * 2.0 / spec.l_over_b;
        let got = expected_max_speed(&s, fr, s.x_range.0, s.x_range.1, d);
        assert!((got / exact - 1.0).abs() < 0.01, "expected speed {got} against {exact}");
        // Above the free fall of the crest, which would otherwise decide.
        assert!(exact > (2.0 * estimated_hpj_over_d(fr) * d).sqrt());
    }

    /// The Wigley hull at Fr 0.5 at the coarsest accepted spacing, D/dx 4, uniform: the hull, the case and D/L.
    fn coarsest_wigley_scene() -> (Arc<HullSurface>, TwoDtConfig, f64) {
        let spec = wigley::WigleySpec::default();
        let hull = Arc::new(HullSurface::new(&wigley::wigley(&spec)));
        let draft = hull.meta.draft_m / hull.meta.length_m;
        let cfg = TwoDtConfig {
            fr: 0.5,
            dx: Some(draft / 4.0),
            coarse_ratio: 1.0,
            ..TwoDtConfig::default()
        };
        (hull, cfg, draft)
    }

    /// The 3D ship pairs with a 2D+t run at the same spacing, `--dx (D/L)/res`; at D/dx 4 that is the bound
    /// itself. Regression: the bound was open, so `twodt --dx (D/L)/4` was refused and the 3D run at D/dx 4 had
    /// no 2D+t partner at its spacing.
    #[test]
    fn four_particles_over_the_draft_are_accepted_and_fewer_refused() {
        let (hull, mut cfg, draft) = coarsest_wigley_scene();
        assert!(build(hull.clone(), &cfg).is_ok());
        cfg.dx = Some(draft / 3.9);
        let e = build(hull, &cfg)
            .err()
            .expect("a spacing over D/4 is refused")
            .to_string();
        assert!(e.contains("dx/L") && e.contains("D/4"), "{e}");
    }

    /// `--alpha` sets the solver's artificial viscosity (eq. 4.11); without it the solver's default stays.
    #[test]
    fn alpha_option_sets_the_artificial_viscosity_and_its_absence_keeps_the_default() {
        let (hull, mut cfg, _) = coarsest_wigley_scene();
        let scene = build(hull.clone(), &cfg).expect("coarse Wigley scene");
        assert_eq!(scene.sim.cfg.viscosity, Viscosity::default());
        cfg.alpha = Some(0.04);
        let scene = build(hull, &cfg).expect("coarse Wigley scene");
        assert_eq!(scene.sim.cfg.viscosity, Viscosity::Artificial { alpha: 0.04 });
    }
}
