//! The wedge check of the 2D+t machinery: a "hull" whose sections are wedges of fixed deadrise β whose
//! apex sinks linearly with x is, in 2D+t, a rigid wedge entering the water at constant speed V = U k.
//! The same scene is run twice, once with the hull-section wall built from the spline surface (w_n from
//! (10.4)) and once with a rigid wedge profile translated at −V, and both are compared with Wagner's
//! flat-plate theory (data/reference/wagner_*_DERIVED.csv; thesis-independent, see its README):
//! wetted (pile-up) height above the apex z_wet = (π/2) V t and vertical force per unit length
//! F = (π³/4) ρ V³ t cot²β for the whole wedge (half of it in our half domain).

use super::scene::{build, TwoDtConfig, Until};
use crate::driver::checkpoint::{self, CheckpointPolicy, RunProgress, Saver};
use crate::driver::{drive, Ended, Flow, Observer, Outcome};
use crate::geometry::hull_file::{HullMeta, HullOffsets, HullStatus, Station};
use crate::geometry::surface::HullSurface;
use crate::sph::deforming_wall::{DeformingWall, Profile};
use crate::sph::polyline_wall::{FluidSide, VertexMotion};
use crate::sph::solver::Simulation;
use nalgebra::Vector2;
use std::cell::RefCell;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::{Duration, Instant};

type V2 = Vector2<f64>;

/// The wedge case (units of L, g, ρ0).
#[derive(Clone, Copy, Debug)]
pub struct WedgeSpec {
    pub deadrise_deg: f64,
    /// Ship speed U (Froude number).
    pub fr: f64,
    /// Apex slope: the apex sinks by `slope` per unit x, so V = U·slope.
    pub slope: f64,
    /// Penetration at the end of the run.
    pub penetration: f64,
    /// Fine spacing dx/L.
    pub dx: f64,
    /// Sound speed / √(gL); `None`: the 2D+t scene's rule (10 × the expected largest speed from w_n).
    pub c0: Option<f64>,
    /// Water depth / `penetration` (the scene's Z/D; the similarity solution is for infinite depth).
    pub depth_over_draft: f64,
    /// Particle shifting after each step (default the near-wall band, as every single-phase scene).
    pub shifting: crate::sph::particle_shifting::ParticleShifting,
}

impl Default for WedgeSpec {
    fn default() -> Self {
        WedgeSpec {
            deadrise_deg: 30.0,
            fr: 1.0,
            slope: 0.5,
            penetration: 0.03,
            dx: 1.0e-3,
            c0: None,
            depth_over_draft: 2.0,
            shifting: Default::default(),
        }
    }
}

/// The x/L at which the apex touches the calm level.
const X_TOUCH: f64 = 0.01;

impl WedgeSpec {
    /// The entry speed V = U × slope.
    pub fn entry_speed(&self) -> f64 {
        self.fr * self.slope
    }

    /// A sound speed that keeps the spray root below Mach 0.1: 10 × Wagner's root speed ċ = V π/(2 tanβ)
    /// (Faltinsen 1990, eq. 9.17). The scene's own rule follows w_n ≈ V cosβ, which at 10°–20° leaves the
    /// root, 4–9 V fast, at Mach 0.2–0.4.
    pub fn mach_safe_c0(&self) -> f64 {
        10.0 * self.entry_speed() * std::f64::consts::FRAC_PI_2 / self.tan_beta()
    }

    fn tan_beta(&self) -> f64 {
        self.deadrise_deg.to_radians().tan()
    }
    fn apex(&self, x: f64) -> f64 {
        -self.slope * (x - X_TOUCH)
    }
    fn deck(&self) -> f64 {
        4.0 * self.penetration
    }
    /// Hull offsets of the wedge hull: 21 stations over x ∈ [0, X_TOUCH + 2 penetration/slope].
    pub fn offsets(&self) -> HullOffsets {
        let x_end = X_TOUCH + 2.0 * self.penetration / self.slope;
        let stations = (0..21)
            .map(|k| {
                let x = x_end * k as f64 / 20.0;
                let za = self.apex(x);
                let y_top = (self.deck() - za) / self.tan_beta();
                Station {
                    x,
                    points: (0..11)
                        .map(|j| {
                            let f = j as f64 / 10.0;
                            [f * y_top, za + f * (self.deck() - za)]
                        })
                        .collect(),
                }
            })
            .collect();
        HullOffsets {
            meta: HullMeta {
                name: format!("wedge{}", self.deadrise_deg),
                status: HullStatus::Exact,
                length_m: 1.0,
                draft_m: self.penetration,
                beam_m: 2.0 * self.penetration / self.tan_beta(),
                model_scale: 1.0,
                transom: false,
                transom_immersion_m: 0.0,
                source: "bowwave::twodt::wedge (analytic wedge)".into(),
                notes: Default::default(),
            },
            stations,
        }
    }
}

/// One sample of a wedge run.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct WedgeSample {
    /// Penetration depth V t.
    pub penetration: f64,
    /// Wagner-equivalent wetted height above the apex, (π/2) × the centre of pressure along the side
    /// (times sinβ), / (V t).
    pub pileup_over_vt: f64,
    /// Vertical force on the half wedge / (ρ V³ t), from the impulse 2 ∫F dt / (ρ V³ t²).
    pub force_coefficient: f64,
    /// The pressure along the face, Cp = (p − ρ g max(−z, 0)) / (½ ρ V²) (the dynamic part: the similarity
    /// solution has no gravity), one spacing into the fluid, averaged over the last quarter of the interval
    /// in bins of z/(V t) of width [`PROFILE_BIN`]: (z/(Vt) at the bin's centre, Cp), bins with samples only.
    pub cp_profile: Vec<(f64, f64)>,
    /// The profile's largest Cp and its z/(V t) (−∞ and NaN for an empty profile).
    #[serde(with = "crate::io::json_float")]
    pub cp_max: f64,
    #[serde(with = "crate::io::json_float")]
    pub z_cpmax_over_vt: f64,
}

/// Width of the bins of z/(V t) of the pressure profile.
pub const PROFILE_BIN: f64 = 0.025;

/// Result of the comparison.
#[derive(Clone, Debug, serde::Serialize)]
pub struct WedgeComparison {
    pub spec_deadrise_deg: f64,
    pub dx: f64,
    pub twodt: Vec<WedgeSample>,
    pub rigid: Vec<WedgeSample>,
    /// Wagner: z_wet/(V t) = π/2.
    pub wagner_pileup_over_vt: f64,
    /// Wagner, half wedge: F/(ρ V³ t) = (π³/8) cot²β.
    pub wagner_force_coefficient: f64,
    /// Wagner: Cp_max = (π²/4) cot²β at the spray root z/(V t) = π/2 − 1 (Faltinsen 1990, eq. 9.18).
    pub wagner_cp_max: f64,
    /// The exact similarity solution at this deadrise, where a citable value exists.
    pub similarity: Option<Similarity>,
}

/// The Zhao & Faltinsen (1993) similarity solution of constant-speed wedge entry without gravity
/// (`data/reference/zhao_faltinsen1993_wedge_similarity_summary.csv`; Iafrati 2013, Table 1).
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct Similarity {
    pub cp_max: f64,
    /// z/(V t) of the pressure peak (calm level 0, apex −1).
    pub z_cpmax_over_vt: f64,
    /// Vertical force on the half wedge / (ρ V³ t): half the integrated force of both faces (20° and 30°
    /// only).
    pub force_coefficient: Option<f64>,
}

impl Similarity {
    /// The reference at `deadrise_deg`, if the table has it.
    pub fn at(deadrise_deg: f64) -> Option<Similarity> {
        let t = crate::reference::load("wedge_similarity_summary");
        let beta = crate::reference::named(&t, "deadrise_deg");
        let k = beta.iter().position(|b| (b - deadrise_deg).abs() < 1e-9)?;
        let force = crate::reference::named(&t, "F_over_rho_V3_t_DERIVED")[k];
        Some(Similarity {
            cp_max: crate::reference::named(&t, "cp_max_READ")[k],
            z_cpmax_over_vt: crate::reference::named(&t, "z_cpmax_over_Vt_READ")[k],
            force_coefficient: force.is_finite().then_some(0.5 * force),
        })
    }
}

/// One run of the wedge scene (the deforming sections, or with `rigid` the rigid wedge), sampled at the
/// penetrations `at`. With a checkpoint policy it goes on from its folder's checkpoint of the same
/// configuration, saves itself every `policy.every` and halts, saved, at the policy's limits.
pub fn run_wedge(
    spec: &WedgeSpec,
    rigid: bool,
    at: &[f64],
    checkpoint: Option<&CheckpointPolicy>,
) -> anyhow::Result<Ended<Vec<WedgeSample>>> {
    let hull = Arc::new(HullSurface::new(&spec.offsets()));
    let x_end = X_TOUCH + at.iter().copied().fold(0.0, f64::max) / spec.slope;
    let cfg = TwoDtConfig {
        fr: spec.fr,
        dx: Some(spec.dx),
        coarse_ratio: 1.0,
        until: Until::X(x_end),
        c0: spec.c0,
        depth_over_draft: spec.depth_over_draft,
        shifting: Some(spec.shifting),
        ..Default::default()
    };
    let fingerprint = fingerprint(spec, rigid, at);
    // A checkpoint of this configuration is resumed (one of another is overwritten by a fresh run); a resumed
    // run's particles come from it, so its scene is built unpacked and not settled.
    let resume = match checkpoint.map(|c| c.path()).filter(|p| p.exists()) {
        Some(path) => {
            let same = checkpoint::peek::<WedgeProgress>(&path, &fingerprint)?.0;
            if !same {
                log::warn!("{}: of another configuration, starting afresh", path.display());
            }
            same.then_some(path)
        }
        None => None,
    };
    let mut scene = build(hull, &if resume.is_some() { cfg.unpacked() } else { cfg })?;
    let v = scene.profile.u * spec.slope;
    // The stem is at x = 0, the section's start (x0).
    let t_touch = scene.profile.t_at(X_TOUCH);
    if rigid {
        scene.sim.boundaries[1] = rigid_wedge(spec, &scene);
    }
    let mut targets: Vec<f64> = at.to_vec();
    targets.sort_by(f64::total_cmp);
    let mut progress = WedgeProgress {
        targets: targets.into_iter().rev().collect(),
        ..Default::default()
    };
    match &resume {
        Some(path) => {
            progress = checkpoint::restore(path, &fingerprint, &mut scene.sim)?
                .ok_or_else(|| anyhow::anyhow!("{}: changed while being read", path.display()))?;
            log::info!("{}: going on from step {}", path.display(), scene.sim.steps);
        }
        None => {
            scene.settle()?;
        }
    }
    let wall_before = progress.wall_before;
    let state = RefCell::new(progress);
    let tb = spec.tan_beta();
    let mut sampler = WedgeSampler {
        v,
        t_touch,
        dx: spec.dx,
        dir: V2::new(1.0, tb).normalize(),
        n: V2::new(tb, -1.0).normalize(),
        state: &state,
    };
    let at_text = |t: f64| format!("Vt/L = {:.4}", v * (t - t_touch));
    // The saver observes first: what it saves is what the sampler has not yet seen, as a resumed run's sampler
    // sees it again.
    let mut saver = Saver::new(checkpoint, &fingerprint, &state, wall_before, &at_text);
    let outcome = drive(&mut scene.sim, &mut [&mut saver, &mut sampler])?;
    match outcome {
        Outcome::BlewUp(b) => anyhow::bail!("wedge run blew up: {b}"),
        Outcome::Halted(h) => Ok(Ended::Halted(h)),
        Outcome::Finished => {
            if let Some(c) = checkpoint {
                // Finished: the checkpoint has served its purpose.
                let _ = std::fs::remove_file(c.path());
            }
            Ok(Ended::Ran(state.into_inner().out))
        }
    }
}

/// The rigid wedge translated at −V as the scene's section wall (boundary 1).
fn rigid_wedge(spec: &WedgeSpec, scene: &super::scene::Scene) -> Box<dyn crate::sph::boundary::Boundary<2>> {
    let v = scene.profile.u * spec.slope;
    let t_start = scene.profile.t_start;
    let t_touch = scene.profile.t_at(X_TOUCH);
    let s = *spec;
    let (z_cut, z_top, tb) = (scene.geom.z_cut, scene.geom.z_top, spec.tan_beta());
    let profile = move |t: f64| {
        let moving = t >= t_start;
        let za = if moving { -v * (t - t_touch) } else { s.apex(0.0) };
        let vz = if moving { -v } else { 0.0 };
        let y_top = (z_top - za) / tb;
        Profile {
            points: vec![V2::new(0.0, z_cut), V2::new(0.0, za), V2::new(y_top, z_top)],
            motion: VertexMotion {
                vel: vec![V2::zeros(), V2::new(0.0, vz), V2::new(0.0, vz)],
                acc: vec![V2::zeros(); 3],
            },
        }
    };
    Box::new(DeformingWall::new(
        "rigid-wedge",
        Box::new(profile),
        FluidSide::Right,
        spec.dx,
        scene.sim.kernel.support,
    ))
}

/// What a wedge run gathers besides the particles: the penetrations still to sample, the force's impulse and
/// the pressure moments of the interval in progress, and the samples taken (a checkpoint saves them).
#[derive(Clone, Debug, Default, serde::Serialize, serde::Deserialize)]
struct WedgeProgress {
    /// Penetrations still to sample, the next one last.
    targets: Vec<f64>,
    stepped: bool,
    impulse: f64,
    last: Option<(f64, f64)>,
    moments: (f64, f64),
    /// Sums and counts of Cp per bin of z/(V t) from −1, over the last quarter of the interval.
    profile: Vec<(f64, u32)>,
    out: Vec<WedgeSample>,
    /// Wall seconds of the run's earlier sessions.
    wall_before: f64,
}

impl RunProgress for WedgeProgress {
    fn set_wall_before(&mut self, seconds: f64) {
        self.wall_before = seconds;
    }
}

/// The wedge's samples at the asked penetrations. The force is integrated in time (trapezoids, every step
/// after the touch) and the coefficient taken from the impulse: ∫F dt = C ρ V³ t²/2 for F = C ρ V³ t, which
/// filters the SPH pressure noise. The pressure moments along the side in the similarity variable s/(V t)
/// are summed over the last quarter of each interval: a single instant is too noisy for the centre of
/// pressure.
struct WedgeSampler<'a> {
    v: f64,
    t_touch: f64,
    dx: f64,
    dir: V2,
    n: V2,
    state: &'a RefCell<WedgeProgress>,
}

impl Observer<Simulation<2>> for WedgeSampler<'_> {
    fn observe(&mut self, sim: &mut Simulation<2>) -> anyhow::Result<Flow> {
        let v = self.v;
        let mut st = self.state.borrow_mut();
        let st = &mut *st;
        if let Some(&pen) = st.targets.last() {
            if std::mem::replace(&mut st.stepped, true) && sim.time > self.t_touch {
                sim.refresh();
                let f = sim.boundary_forces()[1].y;
                let t = sim.time - self.t_touch;
                let (t0, f0) = st.last.unwrap_or((0.0, 0.0));
                st.impulse += 0.5 * (f + f0) * (t - t0);
                st.last = Some((t, f));
                if t > 0.75 * pen / v {
                    let (a, b) = pressure_moments(sim, self.dx, v * t, &self.dir, &self.n, v, &mut st.profile);
                    st.moments.0 += a;
                    st.moments.1 += b;
                }
            }
        }
        while let Some(&pen) = st.targets.last() {
            if sim.time < self.t_touch + pen / v {
                break;
            }
            st.targets.pop();
            let t = sim.time - self.t_touch;
            let (m0, m1) = std::mem::take(&mut st.moments);
            // The centre of pressure s_cp gives the Wagner-equivalent wetted length c = (π/2) s_cp (for
            // p ∝ 1/√(c² − s²)), and the pile-up height c sinβ above the apex.
            let c_over_vt = std::f64::consts::FRAC_PI_2 * m1 / m0.max(1e-300);
            let cp_profile: Vec<(f64, f64)> = std::mem::take(&mut st.profile)
                .into_iter()
                .enumerate()
                .filter(|(_, (_, n))| *n > 0)
                .map(|(k, (sum, n))| (-1.0 + (k as f64 + 0.5) * PROFILE_BIN, sum / n as f64))
                .collect();
            let (z_cpmax_over_vt, cp_max) = cp_profile.iter().copied().fold(
                (f64::NAN, f64::NEG_INFINITY),
                |best, b| if b.1 > best.1 { b } else { best },
            );
            st.out.push(WedgeSample {
                penetration: v * t,
                pileup_over_vt: c_over_vt * self.dir.y,
                force_coefficient: 2.0 * st.impulse / (v * v * v * t * t),
                cp_profile,
                cp_max,
                z_cpmax_over_vt,
            });
        }
        Ok(if st.targets.is_empty() { Flow::Stop } else { Flow::Step })
    }
}

/// Zeroth and first moments (∫p dσ, ∫p σ dσ with σ = s/(V t)) of the pressure along the wedge side, one
/// spacing into the fluid, from the apex up to s = 3 V t / sinβ; `vt` is the penetration. Each sample's Cp
/// (the dynamic part, see [`WedgeSample::cp_profile`]) is added to its bin of z/(V t) in `profile`.
fn pressure_moments(
    sim: &Simulation<2>,
    dx: f64,
    vt: f64,
    dir: &V2,
    n: &V2,
    v: f64,
    profile: &mut Vec<(f64, u32)>,
) -> (f64, f64) {
    let ds = 0.25 * dx;
    let (mut m0, mut m1) = (0.0, 0.0);
    let steps = (3.0 * vt / (dir.y * ds)) as usize + 1;
    for k in 0..steps {
        let s = (k as f64 + 0.5) * ds;
        let p = V2::new(0.0, -vt) + dir * s + n * dx;
        let raw = sim.sensor_pressure_at(&p);
        let pr = raw.max(0.0);
        m0 += pr * ds / vt;
        m1 += pr * (s / vt) * ds / vt;
        // Scene units: ρ0 = 1, g = 1, the calm level at z = 0; binned by the face point's z/(V t).
        let zeta = (s * dir.y - vt) / vt;
        let bin = ((zeta + 1.0) / PROFILE_BIN).floor();
        if raw.is_finite() && bin >= 0.0 {
            let bin = bin as usize;
            if profile.len() <= bin {
                profile.resize(bin + 1, (0.0, 0));
            }
            profile[bin].0 += 2.0 * (raw - (-p.y).max(0.0)) / (v * v);
            profile[bin].1 += 1;
        }
    }
    (m0, m1)
}

/// What identifies a wedge run: a checkpoint or a finished run's samples of another configuration are not used.
fn fingerprint(spec: &WedgeSpec, rigid: bool, at: &[f64]) -> String {
    format!("wedge {spec:?} | rigid {rigid} | at {at:?}")
}

/// Where the wedge runs of one command save themselves: each run in its own folder under `dir`
/// (`beta30-dx5e-4-2dt/`, `…-rigid/`), its checkpoint every `every`, its samples (`samples.json`) once it has
/// finished, so that the same command run again skips finished runs and goes on with the one in progress.
#[derive(Clone, Debug)]
pub struct WedgeCheckpoints {
    pub dir: PathBuf,
    pub every: Duration,
    /// Halt, saved, at this instant (a session's wall-time limit shared by all the command's runs).
    pub deadline: Option<Instant>,
    /// Halt, saved, once a run has taken this many steps (tests).
    pub halt_at_step: Option<u64>,
    /// Start every run from the beginning: earlier samples and checkpoints in `dir` are removed first.
    pub fresh: bool,
}

/// A finished run's samples, as `samples.json` keeps them.
#[derive(serde::Serialize, serde::Deserialize)]
struct Finished {
    fingerprint: String,
    samples: Vec<WedgeSample>,
}

/// One run, or its samples from an earlier session of the same command.
fn run_or_recall(
    spec: &WedgeSpec,
    rigid: bool,
    at: &[f64],
    saving: Option<&WedgeCheckpoints>,
) -> anyhow::Result<Ended<Vec<WedgeSample>>> {
    let Some(w) = saving else {
        return run_wedge(spec, rigid, at, None);
    };
    let run = if rigid { "rigid" } else { "2dt" };
    let dir = w.dir.join(format!("beta{}-dx{:e}-{run}", spec.deadrise_deg, spec.dx));
    let done = dir.join("samples.json");
    let fp = fingerprint(spec, rigid, at);
    if w.fresh {
        for f in [done.clone(), dir.join(checkpoint::FILE)] {
            if f.exists() {
                std::fs::remove_file(&f).map_err(|e| anyhow::anyhow!("cannot remove {}: {e}", f.display()))?;
            }
        }
    }
    if done.exists() {
        let text = std::fs::read_to_string(&done).map_err(|e| anyhow::anyhow!("{}: {e}", done.display()))?;
        let f: Finished = serde_json::from_str(&text).map_err(|e| anyhow::anyhow!("{}: {e}", done.display()))?;
        if f.fingerprint == fp {
            log::info!("{}: finished in an earlier session", done.display());
            return Ok(Ended::Ran(f.samples));
        }
    }
    std::fs::create_dir_all(&dir).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", dir.display()))?;
    let policy = CheckpointPolicy {
        dir,
        every: w.every,
        deadline: w.deadline,
        halt_at_step: w.halt_at_step,
    };
    let ended = run_wedge(spec, rigid, at, Some(&policy))?;
    if let Ended::Ran(samples) = &ended {
        let f = Finished {
            fingerprint: fp,
            samples: samples.clone(),
        };
        crate::io::atomic::write_atomic(&done, serde_json::to_string(&f)?.as_bytes())?;
    }
    Ok(ended)
}

/// Runs both (with `saving`, each resumable) and returns the comparison, or where a run halted.
pub fn compare(
    spec: &WedgeSpec,
    at: &[f64],
    saving: Option<&WedgeCheckpoints>,
) -> anyhow::Result<Ended<WedgeComparison>> {
    let cot = 1.0 / spec.tan_beta();
    let twodt = match run_or_recall(spec, false, at, saving)? {
        Ended::Ran(s) => s,
        Ended::Halted(h) => return Ok(Ended::Halted(h)),
    };
    let rigid = match run_or_recall(spec, true, at, saving)? {
        Ended::Ran(s) => s,
        Ended::Halted(h) => return Ok(Ended::Halted(h)),
    };
    Ok(Ended::Ran(WedgeComparison {
        spec_deadrise_deg: spec.deadrise_deg,
        dx: spec.dx,
        twodt,
        rigid,
        wagner_pileup_over_vt: std::f64::consts::FRAC_PI_2,
        wagner_force_coefficient: std::f64::consts::PI.powi(3) / 8.0 * cot * cot,
        wagner_cp_max: std::f64::consts::PI.powi(2) / 4.0 * cot * cot,
        similarity: Similarity::at(spec.deadrise_deg),
    }))
}

/// Prints the comparison as a table with the differences.
pub fn print(c: &WedgeComparison) {
    print_wagner(c);
    print_similarity(c);
}

/// The comparison with the similarity solution: force, Cp_max and its height, for both runs.
pub fn print_similarity(c: &WedgeComparison) {
    let Some(sim) = c.similarity else {
        println!("  (no similarity solution on record at β = {}°)", c.spec_deadrise_deg);
        return;
    };
    let force = sim.force_coefficient.map_or("–".to_string(), |f| format!("{f:.3}"));
    println!(
        "  similarity solution (Zhao & Faltinsen 1993): half-wedge force {force}, Cp_max {:.3} at z/(Vt) {:.3}; Wagner Cp_max {:.3}",
        sim.cp_max, sim.z_cpmax_over_vt, c.wagner_cp_max
    );
    println!("  Vt/L    run    force   vs sim    Cp_max  vs sim    z(Cp_max)/(Vt)  vs sim");
    for (name, runs) in [("2D+t", &c.twodt), ("rigid", &c.rigid)] {
        for a in runs.iter() {
            let f = sim.force_coefficient.map_or("–".to_string(), |f| {
                format!("{:+.1}%", 100.0 * (a.force_coefficient / f - 1.0))
            });
            println!(
                "  {:.4}  {name:<5}  {:.3}   {f:>7}   {:.3}  {:+.1}%   {:.3}           {:+.3}",
                a.penetration,
                a.force_coefficient,
                a.cp_max,
                100.0 * (a.cp_max / sim.cp_max - 1.0),
                a.z_cpmax_over_vt,
                a.z_cpmax_over_vt - sim.z_cpmax_over_vt,
            );
        }
    }
}

/// The 2D+t run against the rigid wedge, and both against Wagner.
pub fn print_wagner(c: &WedgeComparison) {
    println!(
        "wedge β = {}°, dx/L = {:.2e}; Wagner: pile-up z/(Vt) = {:.3}, half-wedge force F/(ρV³t) = {:.3}",
        c.spec_deadrise_deg, c.dx, c.wagner_pileup_over_vt, c.wagner_force_coefficient
    );
    println!("  Vt/L    pile-up 2D+t  rigid   diff     force 2D+t  rigid   diff    vs Wagner (2D+t)");
    for (a, b) in c.twodt.iter().zip(&c.rigid) {
        println!(
            "  {:.4}  {:.3}        {:.3}   {:+.1}%   {:.3}      {:.3}  {:+.1}%   pile-up {:+.1}%, force {:+.1}%",
            a.penetration,
            a.pileup_over_vt,
            b.pileup_over_vt,
            100.0 * (a.pileup_over_vt / b.pileup_over_vt - 1.0),
            a.force_coefficient,
            b.force_coefficient,
            100.0 * (a.force_coefficient / b.force_coefficient - 1.0),
            100.0 * (a.pileup_over_vt / c.wagner_pileup_over_vt - 1.0),
            100.0 * (a.force_coefficient / c.wagner_force_coefficient - 1.0),
        );
    }
}

/// One row of `wedge.csv`.
#[derive(serde::Serialize)]
struct CsvRow<'a> {
    deadrise_deg: f64,
    dx_over_l: f64,
    run: &'a str,
    penetration_over_l: f64,
    pileup_over_vt: f64,
    force_coefficient: f64,
    cp_max: f64,
    z_cpmax_over_vt: f64,
    sim_force_coefficient: Option<f64>,
    sim_cp_max: Option<f64>,
    sim_z_cpmax_over_vt: Option<f64>,
    wagner_force_coefficient: f64,
    wagner_cp_max: f64,
    wagner_pileup_over_vt: f64,
}

/// The comparisons' rows as CSV: deadrise, dx, run (2dt or rigid), penetration, pile-up, force, Cp_max and
/// its height, then the similarity solution's and Wagner's values (empty where there is none).
pub fn csv(comparisons: &[WedgeComparison]) -> anyhow::Result<String> {
    let mut w = csv::Writer::from_writer(vec![]);
    for c in comparisons {
        let sim = c.similarity;
        for (run, samples) in [("2dt", &c.twodt), ("rigid", &c.rigid)] {
            for a in samples {
                w.serialize(CsvRow {
                    deadrise_deg: c.spec_deadrise_deg,
                    dx_over_l: c.dx,
                    run,
                    penetration_over_l: a.penetration,
                    pileup_over_vt: a.pileup_over_vt,
                    force_coefficient: a.force_coefficient,
                    cp_max: a.cp_max,
                    z_cpmax_over_vt: a.z_cpmax_over_vt,
                    sim_force_coefficient: sim.and_then(|s| s.force_coefficient),
                    sim_cp_max: sim.map(|s| s.cp_max),
                    sim_z_cpmax_over_vt: sim.map(|s| s.z_cpmax_over_vt),
                    wagner_force_coefficient: c.wagner_force_coefficient,
                    wagner_cp_max: c.wagner_cp_max,
                    wagner_pileup_over_vt: c.wagner_pileup_over_vt,
                })?;
            }
        }
    }
    Ok(String::from_utf8(w.into_inner()?)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn similarity_reference_reads_as_transcribed() {
        let s30 = Similarity::at(30.0).unwrap();
        assert_eq!((s30.cp_max, s30.z_cpmax_over_vt), (6.927, 0.4243));
        assert_eq!(s30.force_coefficient, Some(0.5 * 14.17));
        assert_eq!(Similarity::at(20.0).unwrap().force_coefficient, Some(0.5 * 42.94));
        assert_eq!(
            Similarity::at(10.0).unwrap().force_coefficient,
            None,
            "no force on record at 10°"
        );
        assert!(Similarity::at(45.0).is_none());
    }

    /// The spray root's speed rule: 10 × V π/(2 tanβ); at 30°, V = 0.5: 27.2.
    #[test]
    fn mach_safe_sound_speed_follows_the_spray_root() {
        let w = WedgeSpec::default();
        let expected = 10.0 * 0.5 * std::f64::consts::FRAC_PI_2 / 30f64.to_radians().tan();
        assert!((w.mach_safe_c0() - expected).abs() < 1e-12);
    }
}
