//! Method variants by name (`delta-sph`, `wendland`, `h=1.4`, `wendland+h=1.4`, …): the vocabulary that
//! `chart speed-accuracy`, `bench --variants` and `run`/`validate --variant` share, each name a change of a
//! case file's numerics or walls.

use super::CaseFile;
use crate::sph::polyline_wall::GhostKind;
use crate::sph::{
    density_diffusion::DensityDiffusion, integrator::Integrator, kernel::KernelKind, viscosity::Viscosity,
};

/// A method variant, by name: `delta-sph` (the default scheme), `molteni` (Molteni–Colagrossi diffusion (5.4),
/// no gradient correction), `wcsph` (no density diffusion), `wendland` (Wendland C2 kernel, h = 2 dx),
/// `pc` (predictor–corrector at its default CFL), `table`/`exact-kernel` (tabulated or exact kernel gradient),
/// `lagged-gradient` (after a step's first stage the δ-term reads the previous stage's density gradient),
/// `images`/`fixed-ghosts` (every wall's straight sides as image ghosts, or the fixed lattice), or `alpha=A`,
/// `delta=D`, `cfl=C`, `h=H` (h/dx) for one parameter. Names joined by `+` apply in turn, left to right
/// (`wendland+h=1.4`: the Wendland kernel at h = 1.4 dx).
pub fn apply_variant(case: &mut CaseFile, name: &str) -> anyhow::Result<()> {
    for part in name.split('+') {
        if part.is_empty() {
            anyhow::bail!("variant `{name}`: an empty name; expected names joined by `+`");
        }
        apply_one_variant(case, part)?;
    }
    Ok(())
}

fn apply_one_variant(case: &mut CaseFile, name: &str) -> anyhow::Result<()> {
    let ghosts = match name {
        "images" => Some(GhostKind::Images),
        "fixed-ghosts" => Some(GhostKind::Fixed),
        "normal-flux" => Some(GhostKind::NormalFlux),
        _ => None,
    };
    if let Some(kind) = ghosts {
        case.set_ghosts(kind);
        return Ok(());
    }
    if name == "normal-flux-thesis" {
        case.set_ghosts(GhostKind::NormalFlux);
        case.numerics.normal_flux = crate::sph::normal_flux::NormalFluxForm::Thesis;
        return Ok(());
    }
    let n = &mut case.numerics;
    match name {
        "delta-sph" => n.density_diffusion = DensityDiffusion::DeltaSph,
        "molteni" => n.density_diffusion = DensityDiffusion::MolteniColagrossi,
        "wcsph" => n.density_diffusion = DensityDiffusion::None,
        "wendland" => {
            n.kernel = KernelKind::WendlandC2;
            n.h_over_dx = None;
        }
        "pc" => {
            n.integrator = Integrator::PredictorCorrector;
            n.cfl = None;
        }
        "rk4" => {
            n.integrator = Integrator::Rk4;
            n.cfl = None;
        }
        "table" => n.kernel_table = true,
        "exact-kernel" => n.kernel_table = false,
        "sun2017" => n.shifting = Some(crate::sph::particle_shifting::ParticleShifting::Sun2017),
        "sun2017-walls" => n.shifting = Some(crate::sph::particle_shifting::ParticleShifting::Sun2017Walls),
        "sun2017-leaving" => n.shifting = Some(crate::sph::particle_shifting::ParticleShifting::Sun2017Leaving),
        "no-shifting" => n.shifting = Some(crate::sph::particle_shifting::ParticleShifting::None),
        "lagged-gradient" => n.gradient_stage = crate::sph::main_loop::GradientStage::Previous,
        other => {
            let (k, v) = other.split_once('=').ok_or_else(|| {
                anyhow::anyhow!(
                    "variant `{other}`: expected delta-sph, molteni, wcsph, wendland, pc, rk4, table, exact-kernel, sun2017, sun2017-walls, sun2017-leaving, no-shifting, lagged-gradient, images, fixed-ghosts, normal-flux, normal-flux-thesis, alpha=A, delta=D, cfl=C or h=H (h/dx)"
                )
            })?;
            let x: f64 = v
                .parse()
                .ok()
                .filter(|x: &f64| x.is_finite() && *x >= 0.0)
                .ok_or_else(|| anyhow::anyhow!("variant `{other}`: expected a number ≥ 0 after `=`"))?;
            match k {
                "alpha" => n.viscosity = Viscosity::Artificial { alpha: x },
                "delta" => n.delta = x,
                "cfl" if x > 0.0 => n.cfl = Some(x),
                // The case file's range for h/dx (a support of 100 spacings would run for days).
                "h" if (0.5..=4.0).contains(&x) => n.h_over_dx = Some(x),
                _ => anyhow::bail!("variant `{other}`: expected alpha=A, delta=D, cfl=C (C > 0) or h=H (0.5 ≤ H ≤ 4)"),
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn variants_set_their_parameter_and_bad_ones_are_refused() {
        let mut c = crate::cases::load("dam-break").unwrap();
        assert!(c.numerics.kernel_table, "the tabulated gradient is the default");
        for v in ["exact-kernel", "h=1.5", "cfl=2.5", "alpha=0.01", "molteni"] {
            apply_variant(&mut c, v).unwrap();
        }
        let n = &c.numerics;
        assert!(!n.kernel_table);
        assert_eq!(n.h_over_dx, Some(1.5));
        assert_eq!(n.cfl, Some(2.5));
        assert_eq!(n.density_diffusion, DensityDiffusion::MolteniColagrossi);
        assert!(
            c.walls.iter().all(|w| w.ghosts == GhostKind::Fixed),
            "fixed ghosts are the default"
        );
        apply_variant(&mut c, "images").unwrap();
        assert!(c.walls.iter().all(|w| w.ghosts == GhostKind::Images));
        apply_variant(&mut c, "fixed-ghosts").unwrap();
        assert!(c.walls.iter().all(|w| w.ghosts == GhostKind::Fixed));
        // h=100 and cfl=0 were accepted (a support of 300 spacings; a zero time step).
        for bad in ["h=0", "h=-1", "h=100", "cfl=0", "cfl=x", "speed=2", "gauss"] {
            let e = apply_variant(&mut c, bad).unwrap_err().to_string();
            assert!(e.contains(bad) && e.contains("expected"), "{e}");
        }
    }

    #[test]
    fn variants_joined_by_plus_apply_left_to_right() {
        let mut c = crate::cases::load("dam-break").unwrap();
        apply_variant(&mut c, "wendland+h=1.4+cfl=1.5").unwrap();
        let n = &c.numerics;
        assert_eq!(n.kernel, KernelKind::WendlandC2);
        assert_eq!(n.h_over_dx, Some(1.4), "h after wendland keeps its value");
        assert_eq!(n.cfl, Some(1.5));
        // In the other order `wendland` resets h to its own default.
        apply_variant(&mut c, "h=1.4+wendland").unwrap();
        assert_eq!(c.numerics.h_over_dx, None);
        for bad in ["wendland+", "+h=1.4", "wendland++h=1.4", "wendland+gauss"] {
            let e = apply_variant(&mut c, bad).unwrap_err().to_string();
            assert!(
                e.contains("variant") && (e.contains("empty") || e.contains("expected")),
                "{bad}: {e}"
            );
        }
    }
}
