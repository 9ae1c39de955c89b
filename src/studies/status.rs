//! Where each case of a study stands, without running anything (`bowwave study --status`): finished (its
//! record), stopped part-way (its checkpoint: the x/L reached, steps, time spent, and whether running the case
//! again goes on from there), or not started. For sweeps whose cases run for hours, case by case, under a
//! batch scheduler or over several sessions.

use super::runner::{case_dir, case_surface, finished, CaseRecord};
use super::study_file::{CaseSpec, Study};
use crate::twodt::run::CheckpointProgress;
use std::path::Path;

/// The state of one case in an output folder.
#[derive(Clone, Debug)]
pub enum CaseState {
    /// Finished with the study's current configuration.
    Finished(Box<CaseRecord>),
    /// Stopped part-way with a checkpoint (of this configuration or, if `same_configuration` is false, of an
    /// earlier one that a run would overwrite).
    InProgress(CheckpointProgress),
    /// A `[ship3d]` case whose 2D+t partner has run and whose 3D run stopped part-way with a checkpoint.
    Ship3dInProgress(crate::compare3d::towed_checkpoint::Peek),
    /// A finished record exists but of another configuration: the case runs again.
    OtherConfiguration,
    NotStarted,
}

/// A case and its state.
#[derive(Clone, Debug)]
pub struct CaseStatus {
    pub spec: CaseSpec,
    pub state: CaseState,
}

/// The state of every case of `study` in `out`, in study order. Only cases with a checkpoint build their
/// scene (unpacked), to read where the checkpoint's section is.
pub fn status(study: &Study, out: &Path) -> anyhow::Result<Vec<CaseStatus>> {
    study
        .cases
        .iter()
        .map(|spec| {
            let dir = case_dir(out, spec);
            let ship_checkpoint = dir
                .join(super::ship3d::DIR)
                .join(crate::compare3d::towed_checkpoint::FILE);
            let state = if let Some(rec) = finished(out, spec) {
                CaseState::Finished(Box::new(rec))
            } else if let Some(ship) = spec.ship3d.as_ref().filter(|_| ship_checkpoint.exists()) {
                let hull = case_surface(study, spec, None)?;
                let fingerprint =
                    crate::compare3d::towed_ship::TowedShip::with_options((*hull).clone(), spec.fr(), ship)
                        .fingerprint();
                CaseState::Ship3dInProgress(crate::compare3d::towed_checkpoint::peek(
                    &ship_checkpoint,
                    &fingerprint,
                )?)
            } else if dir.join(crate::twodt::checkpoint::FILE).exists() {
                let hull_surface = case_surface(study, spec, None)?;
                match crate::twodt::run::progress(&hull_surface, &spec.config, &dir)? {
                    Some(p) => CaseState::InProgress(p),
                    None => CaseState::NotStarted,
                }
            } else if dir.join("case.json").exists() {
                CaseState::OtherConfiguration
            } else {
                CaseState::NotStarted
            };
            Ok(CaseStatus {
                spec: spec.clone(),
                state,
            })
        })
        .collect()
}

/// Wall seconds still needed to reach the run's stop point at the pace the passage has kept so far, the
/// packing and settling before it left out when the checkpoint records them (early in a run of 665 000
/// particles the packing counted as progress made the estimate about 3 times too long); `None` before the
/// section has moved.
pub fn remaining_seconds(p: &CheckpointProgress) -> Option<f64> {
    let done = p.x_over_l - p.x_start;
    let s = &p.saved;
    let passage = (s.wall_seconds - s.setup_seconds).max(0.0);
    (done > 0.0).then(|| (s.x_stop - p.x_over_l).max(0.0) / done * passage)
}
