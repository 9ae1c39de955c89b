//! What the command line may change in every case it runs (`bowwave run` and `bowwave validate`).

use super::CaseFile;
use crate::sph::equations::{ghost_conditions::WallSlip, viscosity::Viscosity};
use crate::sph::particle_shifting::ParticleShifting;
use crate::sph::polyline_wall::GhostKind;

/// Settings that replace a case file's own, when given.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CaseOverrides {
    /// A method variant applied first, before the settings below (`--variant`; the names of
    /// [`super::variant::apply_variant`], e.g. `wendland+h=1.4`).
    pub variant: Option<String>,
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
        if let Some(v) = &self.variant {
            super::variant::apply_variant(case, v)?;
        }
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
            case.numerics.shifting = Some(s);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::kernel::KernelKind;

    #[test]
    fn a_variant_applies_first_and_the_named_options_win_over_it() {
        let mut c = crate::cases::load("dam-break").unwrap();
        CaseOverrides {
            variant: Some("wendland+h=1.4+images".into()),
            ghosts: Some(GhostKind::Fixed),
            ..Default::default()
        }
        .apply(&mut c)
        .unwrap();
        assert_eq!(c.numerics.kernel, KernelKind::WendlandC2);
        assert_eq!(c.numerics.h_over_dx, Some(1.4));
        assert!(
            c.walls.iter().all(|w| w.ghosts == GhostKind::Fixed),
            "--ghosts fixed wins over `images`"
        );
        let e = CaseOverrides {
            variant: Some("gauss".into()),
            ..Default::default()
        }
        .apply(&mut c)
        .unwrap_err()
        .to_string();
        assert!(e.contains("variant `gauss`") && e.contains("expected"), "{e}");
    }
}
