//! The 3D side of a `[ship3d]` study case (issue #31): after the case's 2D+t run, the same hull towed in 3D at
//! the same spacing, in the same tank and at the same sound speed (`compare3d::towed_ship`), its files in
//! `CASE/ship3d/` (those of `bowwave ship --twodt CASE`), and the few numbers the study's `ship3d.csv` and report
//! keep of it.

use super::study_file::Ship3d;
use crate::compare3d::towed_ship::{self, TowedShip};
use crate::driver::Ended;
use crate::geometry::surface::HullSurface;
use crate::io::atomic::write_atomic;
use serde::{Deserialize, Serialize};
use std::path::Path;
use std::time::Duration;

/// The 3D run's folder inside its case's.
pub const DIR: &str = "ship3d";

/// What a case's `case.json` keeps of its 3D run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Ship3dRecord {
    pub dx_over_l: f64,
    pub c0_over_sqrt_gl: f64,
    pub particles: usize,
    pub hull_ghosts: usize,
    pub steps: u64,
    /// Wall time of the 3D run, s, over every session of a resumed run.
    pub wall_seconds: f64,
    /// Distance travelled at the end, L.
    pub travel_over_l: f64,
    /// Whether the bow crest met the steadiness tolerance before the longest travel.
    pub steady: bool,
    /// The 3D bow crest at the end: η/D and its x/L from the stem.
    pub crest_over_d: Option<f64>,
    pub crest_x_over_l: Option<f64>,
    /// The 2D+t partner's highest η/D over the same bow region (x/L −0.05–0.5), and its x/L.
    pub twodt_crest_over_d: Option<f64>,
    pub twodt_crest_x_over_l: Option<f64>,
    /// The stretches of x/L over which the two agree within 0.1 D across the whole tank
    /// ([`towed_ship::AGREEMENT_OVER_D`]).
    pub agreement: Vec<(f64, f64)>,
    /// The diagnosis, if the 3D run blew up.
    pub blow_up: Option<String>,
}

/// Runs the 3D side of a case whose 2D+t run has written `case_dir/eta.csv`: checkpoints in `case_dir/ship3d/`
/// with the 2D+t run's `shifting`, every `every` (none with `None`), a stop with the state saved once `deadline` has passed, a fresh start with `fresh`
/// (`--force`); then its tables, maps and `summary.txt` there, and its record.
pub fn run(
    hull: &HullSurface,
    fr: f64,
    ship: &Ship3d,
    shifting: crate::sph::particle_shifting::ParticleShifting,
    case_dir: &Path,
    (every, deadline, fresh): (Option<Duration>, Option<std::time::Instant>, bool),
    progress: bool,
) -> anyhow::Result<Ended<Ship3dRecord>> {
    let two = towed_ship::read_twodt_eta(case_dir)?;
    let dir = case_dir.join(DIR);
    std::fs::create_dir_all(&dir).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", dir.display()))?;
    if fresh {
        let _ = std::fs::remove_file(dir.join(crate::compare3d::towed_checkpoint::FILE));
    }
    let mut opts = TowedShip::with_options(hull.clone(), fr, ship);
    opts.shifting = shifting;
    opts.checkpoint = Some(towed_ship::CheckpointPolicy {
        dir: dir.clone(),
        every: every.unwrap_or(Duration::MAX),
        deadline,
        halt_at_step: None,
    });
    let r = match towed_ship::run(&opts, progress)? {
        Ended::Ran(r) => r,
        Ended::Halted(h) => return Ok(Ended::Halted(h)),
    };
    let x_end = hull.x_range.1 - hull.x_range.0;
    let c = towed_ship::compare(&r.eta, &two, fr, x_end);
    for (file, t) in towed_ship::tables(&r, Some((&two, &c))) {
        let path = dir.join(file);
        t.write(&path)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
    }
    towed_ship::plots(&r, Some((&two, &c)), &dir)?;
    write_atomic(&dir.join("summary.txt"), towed_ship::summary(&r, Some(&c)).as_bytes())?;
    let crest = r.bow.last();
    let two_crest = towed_ship::highest_in_bow_region(&two);
    Ok(Ended::Ran(Ship3dRecord {
        dx_over_l: r.dx_over_l,
        c0_over_sqrt_gl: r.c0_over_sqrt_gl,
        particles: r.particles,
        hull_ghosts: r.hull_ghosts,
        steps: r.steps,
        wall_seconds: r.wall_seconds,
        travel_over_l: r.travel_over_l,
        steady: r.steady,
        crest_over_d: crest.map(|b| b.1),
        crest_x_over_l: crest.map(|b| b.2),
        twodt_crest_over_d: two_crest.map(|c| c.0),
        twodt_crest_x_over_l: two_crest.map(|c| c.1),
        agreement: c.bands,
        blow_up: r.blow_up.map(|b| b.to_string()),
    }))
}
