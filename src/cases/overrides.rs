//! What the command line may change in every case it runs (`bowwave run` and `bowwave validate`).

use super::CaseFile;
use crate::sph::particle_shifting::ParticleShifting;
use crate::sph::polyline_wall::GhostKind;

/// Settings that replace a case file's own, when given.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CaseOverrides {
    /// The ghost kind of every wall's straight sides (`--ghosts`).
    pub ghosts: Option<GhostKind>,
    /// The particle shifting (`--shifting`).
    pub shifting: Option<ParticleShifting>,
}

impl CaseOverrides {
    /// Writes the given settings into `case`.
    pub fn apply(&self, case: &mut CaseFile) {
        if let Some(kind) = self.ghosts {
            case.set_ghosts(kind);
        }
        if let Some(s) = self.shifting {
            case.numerics.shifting = s;
        }
    }
}
