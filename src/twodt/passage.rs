//! The ship's passage as observers of the one run driver (`crate::driver`): at every iteration, in this
//! order, [`Begin`] reads where the section is, [`Checkpoints`] saves (or halts), [`Detector`] surveys the
//! free surface and looks for the plunge (going back to the check before when it finds one, so that the
//! plunge instant is known to one step), [`Outputs`] writes the series row, the η(y) profile and the frames,
//! and [`End`] keeps the point to come back to and stops at the end point. The progress is the driver's.

use super::checkpoint;
use super::pictures::{bow_tables, depth_plot, plunge_plots, write_frame};
use super::result::PlungeMetrics;
use super::scene::{Scene, TwoDtConfig, Until};
use crate::analysis::{cavity, jet, level_set, Snapshot};
use crate::driver::{Flow, Halted, Observer, Stepper};
use crate::sph::polyline_wall::nearest_point;
use crate::sph::solver::BlowUp;
use nalgebra::Vector2;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

type V2 = Vector2<f64>;

/// The state a 2D+t run steps: the scene, the passage loop's state (what a checkpoint saves), and what the
/// observers of one iteration tell each other.
pub(crate) struct TwoDtRun {
    pub scene: Scene,
    pub p: checkpoint::Passage,
    /// The state at the last check ([`Rewind`]).
    rewind: Option<Rewind>,
    /// While a plunge found at a check is searched again step by step from the check before, the step where
    /// it was found.
    replay_until: Option<u64>,
    /// This iteration, as [`Begin`] found it.
    now: Now,
    /// This iteration's survey of the free surface, when one was taken.
    survey: Option<Survey>,
}

#[derive(Clone, Copy, Default)]
struct Now {
    x: f64,
    searching: bool,
    regular: bool,
    /// An output is due (x reached the next output point).
    output: bool,
    /// The plunge check ran at this iteration.
    checked: bool,
}

/// The free surface at one iteration: the snapshot, max|u|/c0 and η(y).
struct Survey {
    s: Snapshot,
    mach: f64,
    eta: Vec<f64>,
}

impl TwoDtRun {
    pub fn new(scene: Scene, p: checkpoint::Passage) -> Self {
        TwoDtRun {
            scene,
            p,
            rewind: None,
            replay_until: None,
            now: Now::default(),
            survey: None,
        }
    }

    /// x/L of the section now.
    pub fn x(&self) -> f64 {
        self.scene.profile.x_at(self.scene.sim.time)
    }
}

impl Stepper for TwoDtRun {
    fn step(&mut self) -> Result<(), BlowUp> {
        self.scene.sim.step().map(|_| ())
    }
}

/// Reads where the section is and what this iteration does: a regular check (every `detect_every` steps
/// from the start of the passage), a step of the search for the plunge instant, an output.
pub(crate) struct Begin<'a> {
    pub cfg: &'a TwoDtConfig,
}

impl Observer<TwoDtRun> for Begin<'_> {
    fn observe(&mut self, run: &mut TwoDtRun) -> anyhow::Result<Flow> {
        let x = run.x();
        if let Some(m) = run.replay_until.filter(|&m| run.scene.sim.steps > m) {
            // Cannot happen while stepping is deterministic; should it, the run goes on with its regular
            // checks, which find the plunge again, to within `detect_every` steps, rather than stop.
            log::warn!("the plunge found at step {m} was not found again stepping from the check before it");
            run.replay_until = None;
        }
        run.now = Now {
            x,
            searching: run.replay_until.is_some(),
            regular: (run.scene.sim.steps - run.p.steps0).is_multiple_of(self.cfg.detect_every.max(1) as u64),
            output: x >= run.p.next_output,
            checked: false,
        };
        run.survey = None;
        Ok(Flow::Step)
    }
}

/// Saves a checkpoint every `policy.every` of wall time and halts with one at the wall-time limit (or at a
/// step, in tests). Checkpoints are taken only before a regular check, where a resumed run re-enters the
/// loop with its first point to come back to ([`Rewind`], not in the checkpoint) at the same check as the
/// uninterrupted run would; never while a plunge instant is searched step by step.
pub(crate) struct Checkpoints<'a> {
    pub path: PathBuf,
    pub fingerprint: String,
    pub policy: &'a checkpoint::CheckpointPolicy,
    /// When this session of the run started, and the process CPU seconds then.
    pub clock: Instant,
    pub cpu0: f64,
    pub last_save: Instant,
}

impl Observer<TwoDtRun> for Checkpoints<'_> {
    fn observe(&mut self, run: &mut TwoDtRun) -> anyhow::Result<Flow> {
        let may_save = run.now.regular && !run.now.searching;
        let policy = self.policy;
        let halt = may_save
            && (policy.halt_at_step.is_some_and(|h| run.scene.sim.steps >= h)
                || policy.deadline.is_some_and(|d| Instant::now() >= d));
        let due = |e: Duration| self.last_save.elapsed() >= e;
        if halt || (may_save && policy.every.is_some_and(due)) {
            let wall = run.p.wall_before + self.clock.elapsed().as_secs_f64();
            let cpu = run.p.cpu_before + crate::process_usage::cpu_seconds() - self.cpu0;
            checkpoint::save(&self.path, &self.fingerprint, &run.scene, &run.p, wall, cpu)?;
            self.last_save = Instant::now();
            if halt {
                return Ok(Flow::Halt(Halted {
                    at: format!("x/L = {:.4}", run.now.x),
                    steps: run.scene.sim.steps,
                    checkpoint: self.path.clone(),
                }));
            }
        }
        Ok(Flow::Step)
    }
}

/// Surveys the free surface at a check, an output or the end point (max|u|/c0, η(y), the far field's
/// level), and until the plunge looks for it ([`plunge_check`]). A plunge found at a regular check lies
/// between the previous check and this one: the run goes back to the previous check and checks every step.
pub(crate) struct Detector<'a> {
    pub cfg: &'a TwoDtConfig,
    pub out_dir: &'a Path,
    pub plots: bool,
}

impl Observer<TwoDtRun> for Detector<'_> {
    fn observe(&mut self, run: &mut TwoDtRun) -> anyhow::Result<Flow> {
        let now = run.now;
        let detect = now.regular || now.searching;
        if !(detect || now.output || now.x >= run.p.x_stop) {
            return Ok(Flow::Step);
        }
        let g = run.scene.geom.clone();
        let s = snapshot(&mut run.scene);
        let umax = s.vel.iter().map(|v| v.norm()).fold(0.0, f64::max);
        let mach = umax / g.c0;
        let p = &mut run.p;
        if mach > 0.1 && p.max_mach <= 0.1 {
            log::warn!("Mach number {mach:.3} above 0.1 at x/L = {:.4}: raise c0 (--c0)", now.x);
        }
        p.max_mach = p.max_mach.max(mach);
        let (bin, far_from) = eta_bins(&g);
        let eta = eta_profile(&s.pos, g.width, bin, g.dx_f);
        if p.plunge.is_none() {
            run.now.checked = true;
            // The mean level of the far field (the top particles jitter by a tenth of a spacing).
            let far = (mean_finite(&eta[far_from..]) - p.far_ref).abs();
            p.far_eta = p.far_eta.max(far / g.draft);
            let found = plunge_check(
                &PlungeScene::of(&run.scene),
                &s,
                (self.cfg.plunge_depth, self.cfg.plunge_circulation.threshold()),
                &mut run.p.closure_watch,
                now.searching,
            );
            if found.is_some() && !now.searching {
                if let Some(r) = run.rewind.take() {
                    // t_p lies between the previous check and this one: go back and check every step.
                    run.replay_until = Some(run.scene.sim.steps);
                    r.restore(&mut run.scene, &mut run.p);
                    return Ok(Flow::Again);
                }
            }
            if let Some((pm, c)) = found {
                run.replay_until = None;
                log::info!("plunge at x/L = {:.4}", pm.x_plunge_over_l);
                if self.plots {
                    plunge_plots(&run.scene, &s, &c, self.out_dir)?;
                }
                run.p.bow = Some(bow_tables(&run.scene, &s));
                if self.cfg.until == Until::Plunge {
                    run.p.x_stop = run.p.x_stop.min(pm.x_plunge_over_l + self.cfg.after_plunge);
                }
                run.p.plunge = Some(pm);
            }
        }
        run.survey = Some(Survey { s, mach, eta });
        Ok(Flow::Step)
    }
}

/// At each output point (every `output_dx`, and at the end point): a row of the series, the η(y) profile
/// outside the waterline (and the crest height, its highest point), a PNG frame and a VTK frame on request.
pub(crate) struct Outputs<'a> {
    pub cfg: &'a TwoDtConfig,
    pub out_dir: &'a Path,
}

impl Observer<TwoDtRun> for Outputs<'_> {
    fn observe(&mut self, run: &mut TwoDtRun) -> anyhow::Result<Flow> {
        let x = run.now.x;
        let (Some(sv), true) = (&run.survey, run.now.output || x >= run.p.x_stop) else {
            return Ok(Flow::Step);
        };
        let (scene, p) = (&run.scene, &mut run.p);
        let g = &scene.geom;
        p.next_output += self.cfg.output_dx;
        let ke = scene.sim.energies().kinetic;
        p.series.push(vec![
            x,
            scene.sim.time - scene.profile.t_start,
            scene.sim.steps as f64,
            ke / (p.total_mass * g.draft),
            sv.mach,
            p.far_eta,
            sv.s.on_surface.iter().filter(|b| **b).count() as f64,
            scene.sim.wall_corrections as f64,
        ]);
        let y_wl = waterline_half_breadth(&scene.profile.at(scene.sim.time).points);
        let (bin, _) = eta_bins(g);
        p.crest = f64::NEG_INFINITY;
        for (y, z) in eta_outside_waterline(&sv.eta, bin, y_wl) {
            p.eta_table.push(vec![x, y, z / g.draft]);
            p.crest = p.crest.max(z / g.draft);
        }
        if self.cfg.frames {
            let path = self.out_dir.join(format!("frame_{:04}.png", p.series.rows.len()));
            depth_plot(
                scene,
                &sv.s,
                &path,
                (0.0, 2.0 * g.beam, -g.draft, 2.5 * g.draft),
                &format!("x/L = {x:.4}"),
            )?;
        }
        if self.cfg.vtk {
            let name = format!("frame_{:05}.vtp", p.vtk_frames.len());
            write_frame(scene, &sv.s, &self.out_dir.join(&name))?;
            p.vtk_frames.push((x, name));
        }
        Ok(Flow::Step)
    }
}

/// Keeps the point to come back to and stops at the end point. Every check that moved the closure watch
/// (regular or at an output) is a point to come back to: the step-by-step search compares with the same
/// earlier check as the check that found the plunge.
pub(crate) struct End<'a> {
    pub cfg: &'a TwoDtConfig,
}

impl Observer<TwoDtRun> for End<'_> {
    fn observe(&mut self, run: &mut TwoDtRun) -> anyhow::Result<Flow> {
        let now = run.now;
        if now.checked && !now.searching && run.p.plunge.is_none() && self.cfg.detect_every > 1 {
            run.rewind = Some(Rewind::keep(&run.scene, &run.p));
        }
        Ok(if now.x >= run.p.x_stop { Flow::Stop } else { Flow::Step })
    }
}

pub(crate) fn snapshot(scene: &mut Scene) -> Snapshot {
    Snapshot::from_simulation(&mut scene.sim, scene.geom.dx_f)
}

/// What the plunge criteria read of a 2D+t scene at one instant (units of L, speeds in √(gL)): the tank and the
/// section, whatever code moved the water ([`super::external_frames`] fills it from another code's frames).
pub(crate) struct PlungeScene {
    pub draft: f64,
    pub beam: f64,
    /// The tank's half width W and depth Z.
    pub width: f64,
    pub depth: f64,
    /// The finest particle spacing (the level set's grid).
    pub dx: f64,
    /// The wall at this instant (symmetry plane and section, [`super::profile::SectionProfile::at`]).
    pub walls: Vec<V2>,
    /// Ship speed U.
    pub u: f64,
    /// x/L of the section, and of the bow (the hull's first section).
    pub x: f64,
    pub x_bow: f64,
}

impl PlungeScene {
    pub fn of(scene: &Scene) -> Self {
        let (g, t) = (&scene.geom, scene.sim.time);
        PlungeScene {
            draft: g.draft,
            beam: g.beam,
            width: g.width,
            depth: g.depth,
            dx: g.dx_f,
            walls: scene.profile.at(t).points,
            u: scene.profile.u,
            x: scene.profile.x_at(t),
            x_bow: scene.profile.hull.x_range.0,
        }
    }
}

/// Looks for a closed air cavity at the bow wave; returns the metrics and the cavity if the wave has plunged
/// (`docs/reference/jet-metrics.md`, the plunge criteria).
pub(crate) fn plunge_check(
    g: &PlungeScene,
    s: &Snapshot,
    (plunge_depth, plunge_circulation): (Option<f64>, Option<f64>),
    watch: &mut cavity::ClosureWatch,
    between_checks: bool,
) -> Option<(PlungeMetrics, cavity::Cavity)> {
    let h = s.h;
    let zmax = s.pos.iter().map(|p| p.y).fold(f64::NEG_INFINITY, f64::max);
    let lo = V2::new(0.0, -0.5 * g.draft);
    let hi = V2::new(g.width, zmax + 3.0 * h);
    let ls = level_set::level_set(s, lo, hi, g.dx);
    let walls = &g.walls;
    let margin = 3.0 * h;
    let keep = |nodes: &[V2]| {
        nodes
            .iter()
            .all(|p| (nearest_point(walls, p) - p).norm() > margin && p.x < g.width - margin && p.y > -g.depth + margin)
    };
    let closed = if between_checks {
        watch.closed_since_previous(&ls, (2.0 * h).powi(2), keep)?
    } else {
        watch.newly_closed(&ls, (2.0 * h).powi(2), keep)?
    };
    // Crest: the highest free-surface particle over the cavity or up to one cavity width before it.
    let crest_of = |c: &cavity::Cavity| {
        let y_from = c.lo.x - (c.hi.x - c.lo.x);
        (0..s.len())
            .filter(|&k| s.on_surface[k] && s.pos[k].x >= y_from && s.pos[k].x <= c.hi.x)
            .map(|k| s.pos[k].y)
            .fold(f64::NEG_INFINITY, f64::max)
            + 0.5 * g.dx
    };
    let u = g.u;
    // Criterion 3 (optional): a plunge closes the cavity against the free surface in front of the wave, so
    // the cavity reaches down into the lower part of the wave. Criterion 5: the jet closing it turns
    // clockwise around it; a sliver of air between particle rows of a sheet has no such circulation.
    let (c, crest, gamma) = closed.into_iter().find_map(|c| {
        let crest = crest_of(&c);
        if !plunge_depth.is_none_or(|f| c.lo.y < f * crest) {
            return None;
        }
        let gamma = cavity::circulation(s, &ls, &c);
        plunge_circulation
            .is_none_or(|min| gamma / (u * g.draft) >= min)
            .then_some((c, crest, gamma))
    })?;
    let idx = jet::jet_particles(s, &ls, &c);
    let m = jet::metrics(s, &ls, &idx)?;
    let x = g.x;
    let pm = PlungeMetrics {
        x_plunge_over_l: x,
        y_plunge_over_l: c.rightmost.x,
        fr_x: u / (x - g.x_bow).max(1e-12).sqrt(),
        h_pj_over_d: crest / g.draft,
        fall_over_d: (crest - c.rightmost.y) / g.draft,
        gamma_over_ud: gamma / (u * g.draft),
        cavity_area_over_d2: c.area / (g.draft * g.draft),
        l_jet_over_d: m.length / g.draft,
        s_jet_over_db: m.area / (g.draft * g.beam),
        i_og_over_s2: m.i_og / (m.area * m.area),
        y_g_over_d: m.y_g / g.draft,
        z_g_over_d: m.z_g / g.draft,
        v_g_over_u: m.v_g / u,
        w_g_over_u: m.w_g / u,
        alpha_g_deg: m.alpha_g_deg,
        alpha_vg_deg: m.alpha_vg_deg,
        jet_particles: m.particles,
    };
    Some((pm, c))
}

/// The state of a run at a plunge check (regular or at an output), kept until the next one: when that one
/// finds a plunge, the run goes back here and checks every step to the plunge, so that t_p is known to one
/// step without checking every step all along. Stepping is deterministic, so the steps run again are the
/// same bits.
struct Rewind {
    sim: crate::sph::solver::SimState<2>,
    passage: checkpoint::Passage,
}

impl Rewind {
    fn keep(scene: &Scene, p: &checkpoint::Passage) -> Self {
        Rewind {
            sim: scene.sim.state(),
            passage: p.clone(),
        }
    }

    fn restore(self, scene: &mut Scene, p: &mut checkpoint::Passage) {
        scene.sim.set_state(self.sim);
        *p = self.passage;
    }
}

/// The bins of η(y): their width (4 dx_f) and the first bin of the far field (y > 3W/4), where the calm level is
/// watched.
pub(crate) fn eta_bins(g: &super::scene::SceneGeometry) -> (f64, usize) {
    let bin = 4.0 * g.dx_f;
    (bin, (0.75 * g.width / bin) as usize)
}

/// Free-surface elevation η(y) as the top of the fluid in bins of `bin` across [0, width] (NaN where empty).
pub(crate) fn eta_profile(pos: &[V2], width: f64, bin: f64, dx: f64) -> Vec<f64> {
    let n = (width / bin).ceil() as usize;
    let mut top = vec![f64::NAN; n];
    for p in pos {
        let k = ((p.x / bin) as usize).min(n - 1);
        if top[k].is_nan() || p.y > top[k] {
            top[k] = p.y;
        }
    }
    top.iter().map(|z| z + 0.5 * dx).collect()
}

/// The (y, η) of the bins of an [`eta_profile`] (width `bin`) that hold water outside the section's waterline
/// half-breadth `y_wl`: bins inside it would show the water under the hull, not a free surface.
pub(crate) fn eta_outside_waterline(eta: &[f64], bin: f64, y_wl: f64) -> impl Iterator<Item = (f64, f64)> + '_ {
    eta.iter()
        .enumerate()
        .map(move |(k, &z)| ((k as f64 + 0.5) * bin, z))
        .filter(move |&(y, z)| z.is_finite() && y > y_wl)
}

/// The half-breadth of a section polyline at the calm level z = 0: the largest y where it crosses z = 0
/// (0 if it does not reach the water).
pub(crate) fn waterline_half_breadth(points: &[V2]) -> f64 {
    points
        .windows(2)
        .filter(|w| (w[0].y <= 0.0) != (w[1].y <= 0.0))
        .map(|w| w[0].x + (w[1].x - w[0].x) * (0.0 - w[0].y) / (w[1].y - w[0].y))
        .fold(0.0, f64::max)
}

/// Mean of the finite values (bins of η with fluid in them); 0 if there are none.
pub(crate) fn mean_finite(v: &[f64]) -> f64 {
    let (sum, n) = v
        .iter()
        .filter(|z| z.is_finite())
        .fold((0.0, 0usize), |(s, n), z| (s + z, n + 1));
    sum / n.max(1) as f64
}
