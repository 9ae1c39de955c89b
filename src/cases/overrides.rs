//! What the command line may change in every case it runs (`bowwave run` and `bowwave validate`).

use super::CaseFile;
use crate::sph::equations::{ghost_conditions::WallSlip, viscosity::Viscosity};
use crate::sph::particle_shifting::ParticleShifting;
use crate::sph::polyline_wall::GhostKind;

/// Settings that replace a case file's own, when given.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CaseOverrides {
    /// The ghost kind of every wall's straight sides (`--ghosts`).
    pub ghosts: Option<GhostKind>,
    /// The particle shifting (`--shifting`).
    pub shifting: Option<ParticleShifting>,
    /// A physical kinematic viscosity ν (m²/s) in place of the case's viscosity (`--nu`).
    pub nu: Option<f64>,
    /// The walls' condition on the tangential velocity (`--wall-slip`).
    pub wall_slip: Option<WallSlip>,
}

impl CaseOverrides {
    /// Writes the given settings into `case`; refuses particle shifting for a case with several phases.
    pub fn apply(&self, case: &mut CaseFile) -> anyhow::Result<()> {
        if let Some(kind) = self.ghosts {
            case.set_ghosts(kind);
        }
        if let Some(s) = self.shifting {
            if s != ParticleShifting::None && !case.phases.is_empty() {
                anyhow::bail!(
                    "--shifting {s}: case `{}` has `[[phases]]`; expected {}",
                    case.name,
                    crate::sph::particle_shifting::WITH_PHASES
                );
            }
            case.numerics.shifting = s;
        }
        if let Some(nu) = self.nu {
            case.numerics.viscosity = Viscosity::Physical { nu };
        }
        if let Some(w) = self.wall_slip {
            case.numerics.wall_slip = w;
        }
        Ok(())
    }
}
