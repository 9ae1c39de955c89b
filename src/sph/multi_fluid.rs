//! The multi-fluid δ-SPH of Hammani, Oger, Le Touzé, Colagrossi & Marrone ("How to derive the multi-fluid
//! δ-SPH model", their eq. 21): several immiscible phases (water and air), each particle carrying its phase.
//!
//! What changes against the single-phase δ-SPH of the thesis (eq. 5.1), and how this solver does it:
//! - **Density.** The particle's volume V_i is integrated with the volumetric strain rate,
//!   dV_i/dt = V_i Σ_j (u_j − u_i)·∇W_ij V_j; the solver integrates ρ̃_i = m_i/V_i instead (the same equation,
//!   dρ̃/dt = −(ρ̃/V) dV/dt), so that the particle arrays, checkpoints and the time integrator are those of the
//!   single phase. The state equation reads ρ̃_i (the default, [`StateDensity::Integrated`]) or, as eq. 21 has
//!   it, a same-phase Shepard density (their eq. 13, restricted to the particle's own phase as Grenier et al.
//!   2009 do in their eqs. 12 and 19): ρ_i = Σ_{j∈χ} m_j W_ij / Σ_{j∈χ} W_ij V_j, ghosts of the phase included
//!   ([`StateDensity::Shepard`]; measured unstable at coarse resolution, see there).
//! - **Pressure.** Each phase has its own state equation p = B_χ[(ρ/ρ0χ)^γχ − 1] (their eq. 10) plus a
//!   background pressure p_b constant over the domain ([`MultiFluid::background_pressure`]): without it the
//!   negative pressures of the light phase open a void at the interface (their Fig. 1). A p_b > 0 needs a
//!   closed domain: at a free surface it pulls the particles inwards. The solver's pressures (sensors,
//!   outputs, the ghosts' Neumann condition) are the state equation's, p_b apart; p_b enters the forces only,
//!   as p_i + p_j + 2 p_b, where a constant does not change the continuous pressure gradient.
//! - **Diffusion and artificial viscosity** act within a phase only (the sums of eq. 21 over j ∈ χ), with the
//!   phase's c0χ and ρ0χ, so the density jump at the interface is not smeared. A physical viscosity acts across
//!   the interface too, with the harmonic mean of the two μ (Grenier et al. eq. 22,
//!   [`viscosity::pair_coefficient`]). The renormalised density gradient
//!   (their eq. 18) is taken over the same phase too.
//! - **Momentum**: −(1/ρ̃_i) Σ_j (p_i + p_j) ∇W_ij V_j over all phases (their eq. 14), with ρ̃_i = m_i/V_i in
//!   front so that the pairwise forces V_i V_j (p_i + p_j)∇W_ij stay equal and opposite (exact conservation of
//!   momentum); eq. 21 writes the Shepard ρ_i there, which differs from ρ̃_i by the smoothing only.
//! - **Walls**: each ghost takes the phase of the fluid particle nearest to its mirror point and is valued
//!   (MLS, §7.1.1) from the particles of that phase only, with that phase's state equation.
//! - Optional, from Grenier et al. (2009) eq. 23: a small repulsion between particles of different phases,
//!   ε_I Σ_{j∉χ} (|p_i| + |p_j|) ∇W_ij V_j ([`MultiFluid::interface_repulsion`], default 0).
//!
//! One phase is the default and takes none of this path ([`super::solver::SolverConfig::multi_fluid`] is
//! `None`): the single-phase solver costs nothing extra.

use super::eos::Eos;
use super::equations::{
    continuity,
    density_diffusion::{self, DensityDiffusion},
    interface_repulsion::interface_repulsion,
    pressure_force, timestep, viscosity,
};
use super::kernel_table::GradientFactor;
use super::solver::{GhostState, SolverConfig};
use nalgebra::SVector;
use rayon::prelude::*;

/// One fluid phase: its name and state equation.
#[derive(Clone, Debug, PartialEq)]
pub struct Phase {
    /// A name for outputs and errors ("water", "air").
    pub name: String,
    /// Its state equation (ρ0, c0, γ); the background pressure is added on top.
    pub eos: Eos,
}

/// The form of the volume-diffusion term, Hammani et al. eq. (20).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum VolumeDiffusion {
    /// ψ_ji = 2(ρ_j − ρ_i) r_ji/|r_ij|² − (⟨∇ρ⟩_i + ⟨∇ρ⟩_j): the thesis's δ-SPH term (eq. 5.2) mapped
    /// through dV/V = −dρ/ρ. The factor 2 makes the two parts cancel for a linear (hydrostatic) density even
    /// in a kernel truncated by the free surface. The default (`../shared/papers/notes_multiphase_seeds.md`:
    /// the printed eq. 20 lacks it, probably a slip; the two-layer hydrostatic test measures both).
    #[default]
    FactorTwo,
    /// ψ_ji = (ρ_j − ρ_i) r_ji/|r_ij|² − (⟨∇ρ⟩_i + ⟨∇ρ⟩_j), eq. (20) as printed.
    AsPrinted,
}

impl VolumeDiffusion {
    /// The factor in front of (ρ_j − ρ_i) r_ji/|r_ij|².
    pub fn factor(self) -> f64 {
        match self {
            VolumeDiffusion::FactorTwo => 2.0,
            VolumeDiffusion::AsPrinted => 1.0,
        }
    }
}

/// Which density a particle's state equation reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum StateDensity {
    /// The same-phase Shepard density Σ_{j∈χ} m_j W_ij / Σ_{j∈χ} W_ij V_j (Hammani et al. eq. 13, Grenier et
    /// al. eq. 19). In gravity it reads a surface or interface particle's density from the deeper particles
    /// of its truncated support (an over-pressure of order ρ g h there): measured unstable at coarse
    /// resolution (`docs/decisions/multi-fluid-density.md`).
    Shepard,
    /// The particle's own integrated density m_i/V_i (Hammani et al. eq. 9, their first route). With one phase
    /// the multi-fluid path then gives the single-phase solver's bits. The default, by measurement
    /// (`docs/decisions/multi-fluid-density.md`).
    #[default]
    Integrated,
}

/// The phases of a scene and the constants of the multi-fluid model.
#[derive(Clone, Debug, PartialEq)]
pub struct MultiFluid {
    /// The phases; a particle's `phase` indexes this list. At most 255.
    pub phases: Vec<Phase>,
    /// Background pressure p_b (Pa), added to every phase's state equation (Hammani et al. eq. 10; they use
    /// 0.1 of the largest hydrostatic pressure in their two-layer tank, §III.A).
    pub background_pressure: f64,
    /// ε_I of Grenier et al. (2009) eq. (23), dimensionless; 0 switches it off (the default: Hammani et al.
    /// need none; Grenier used 0.02 for Rayleigh–Taylor, and O(0.01–0.1) in general).
    pub interface_repulsion: f64,
    /// The diffusive term's form, eq. (20).
    pub diffusion: VolumeDiffusion,
    /// The density the state equation reads.
    pub density: StateDensity,
}

impl MultiFluid {
    /// The state equations, in the phases' order.
    pub fn eoses(&self) -> Vec<Eos> {
        self.phases.iter().map(|p| p.eos).collect()
    }

    /// The state equation of phase `k`.
    #[inline]
    pub fn eos(&self, k: u8) -> &Eos {
        &self.phases[k as usize].eos
    }

    /// The largest sound speed of the phases (m/s): the one that sets the time step.
    pub fn max_sound_speed(&self) -> f64 {
        self.phases.iter().map(|p| p.eos.c0).fold(0.0, f64::max)
    }

    /// p = p_χ(ρ) (Pa), without the background pressure.
    #[inline]
    pub fn pressure(&self, k: u8, rho: f64) -> f64 {
        self.eos(k).pressure(rho)
    }
}

/// The sound speed of a light phase that gives it the stiffness B = ρ0 c0²/γ of a heavy one (Hammani et al.
/// eq. 23, after Colagrossi & Landrini 2003): c_l = c_h √(γ_l ρ0h / (γ_h ρ0l)) (m/s). Water (γ 7) and air
/// (γ 1.4) at a density ratio of 1000: c_air = 14.14 c_water.
/// The light phase's law is given by its kind, ρ0 and γ; a linear law counts as γ = 1 (p = ρ0c0²(ρ/ρ0 − 1)).
pub fn equal_stiffness_sound_speed(heavy: &Eos, light: &Eos) -> f64 {
    heavy.c0 * (light.exponent() * heavy.rho0 / (heavy.exponent() * light.rho0)).sqrt()
}

/// Accumulates the same-phase Shepard density of one particle (Hammani et al. eq. 13 restricted to the
/// phase, Grenier et al. eq. 19): ρ_i = Σ_{j∈χ} m_j W_ij / Σ_{j∈χ} W_ij V_j, the particle itself included.
#[derive(Clone, Copy, Debug, Default)]
pub struct ShepardDensity {
    mass: f64,
    volume: f64,
}

impl ShepardDensity {
    /// Adds neighbour j of the same phase with kernel value `w`, mass m_j and volume V_j.
    #[inline]
    pub fn add(&mut self, w: f64, m_j: f64, v_j: f64) {
        self.mass += w * m_j;
        self.volume += w * v_j;
    }

    /// ρ_i; `fallback` (the particle's own m/V) if no weight was gathered.
    #[inline]
    pub fn density(&self, fallback: f64) -> f64 {
        if self.volume > 0.0 {
            self.mass / self.volume
        } else {
            fallback
        }
    }
}

/// The prepared state of one right-hand-side evaluation, as the multi-fluid gather reads it.
pub(super) struct Stage<'a, const D: usize> {
    pub pos: &'a [SVector<f64, D>],
    pub vel: &'a [SVector<f64, D>],
    /// The integrated density ρ̃ = m/V.
    pub rho_tilde: &'a [f64],
    /// The density the state equation read (ρ̃, or the same-phase Shepard density).
    pub rho: &'a [f64],
    pub pressure: &'a [f64],
    /// V = m/ρ̃.
    pub volume: &'a [f64],
    /// The renormalised gradient of `rho` over the same phase.
    pub grad_rho: &'a [SVector<f64, D>],
    pub phase: &'a [u8],
    /// Each fluid particle's neighbours (fluid below the fluid count, ghosts after).
    pub neighbours: &'a [Vec<u32>],
    pub all_pos: &'a [SVector<f64, D>],
    pub ghosts: &'a GhostState<D>,
    pub gradient: GradientFactor<'a, D>,
    pub h: f64,
}

/// Eq. (21) of Hammani et al. for every fluid particle: (dρ̃/dt, du/dt, signal speed of eq. 4.22). A gather in
/// the neighbour lists' order: the same bits for any thread count.
pub(super) fn rates<const D: usize>(
    mf: &MultiFluid,
    cfg: &SolverConfig<D>,
    st: &Stage<'_, D>,
) -> super::solver::Gathered<D> {
    let nf = st.pos.len();
    let gs = st.ghosts;
    let h = st.h;
    let factor = mf.diffusion.factor();
    (0..nf)
        .into_par_iter()
        .map(|i| {
            let k = st.phase[i];
            let eos = mf.eos(k);
            // The phase's own coefficients: δ h c0χ and α h c0χ ρ0χ (eq. 21).
            let diff = if cfg.diffusion == DensityDiffusion::None {
                0.0
            } else {
                cfg.delta * eos.c0 * h
            };
            let p_b = mf.background_pressure;
            let (rt_i, rho_i, u_i, p_i) = (st.rho_tilde[i], st.rho[i], st.vel[i], st.pressure[i] + p_b);
            let mut drho = 0.0;
            let mut dvel = SVector::<f64, D>::zeros();
            let mut max_pi = 0.0f64;
            for &j in &st.neighbours[i] {
                let j = j as usize;
                let rij = st.pos[i] - st.all_pos[j];
                let r2 = rij.norm_squared();
                let gw = rij * st.gradient.at(r2);
                let (u_j, rho_j, p_j, v_j, grad_j, k_j, u_visc_j) = if j < nf {
                    (
                        st.vel[j],
                        st.rho[j],
                        st.pressure[j] + p_b,
                        st.volume[j],
                        st.grad_rho[j],
                        st.phase[j],
                        st.vel[j],
                    )
                } else {
                    let g = j - nf;
                    (
                        gs.vel[g],
                        gs.rho[g],
                        gs.p[g] + p_b,
                        gs.volume[g],
                        gs.grad_rho[g],
                        gs.phase[g],
                        // Under no slip the viscous term reads the ghost's reversed velocity (§7.1.3).
                        gs.viscous_velocity(g),
                    )
                };
                let u_ji = u_j - u_i;
                drho += continuity::velocity_divergence(rt_i, &u_ji, &gw, v_j);
                dvel += pressure_force::pressure_acceleration(p_i, p_j, rt_i, &gw, v_j);
                if k_j == k && diff > 0.0 {
                    // dV_i/dt ⊃ −δhc0 V_i ψ·∇W V_j / ρ_i (eq. 20) is dρ̃_i/dt ⊃ δhc0 (ρ̃_i/ρ_i) ψ·∇W V_j.
                    let psi = density_diffusion::psi_with_factor(
                        cfg.diffusion,
                        factor,
                        rho_i,
                        rho_j,
                        &rij,
                        r2,
                        &st.grad_rho[i],
                        &grad_j,
                    );
                    drho += diff * (rt_i / rho_i) * psi.dot(&gw) * v_j;
                }
                let rho0_j = mf.eos(k_j).rho0;
                if let Some(visc) =
                    viscosity::pair_coefficient(&cfg.viscosity, D, h, (eos.rho0, eos.c0), rho0_j, k_j == k)
                {
                    let pi = viscosity::pi_ij(&(u_visc_j - u_i), &rij, r2, h);
                    dvel += viscosity::viscous_acceleration(visc, rt_i, pi, &gw, v_j);
                    max_pi = max_pi.max(pi.abs());
                }
                if k_j != k && mf.interface_repulsion > 0.0 {
                    dvel += interface_repulsion(mf.interface_repulsion, p_i, p_j, rt_i, &gw, v_j);
                }
            }
            dvel += cfg.body_force.acceleration(&st.pos[i]);
            let signal = timestep::signal_speed(eos.sound_speed(rho_i), u_i.norm(), h, max_pi);
            (drho, (dvel, signal))
        })
        .unzip()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::eos::{EosKind, TAIT_GAMMA_WATER};

    #[test]
    fn equal_stiffness_rule_gives_air_the_stiffness_of_water() {
        let water = Eos {
            kind: EosKind::Tait,
            rho0: 1000.0,
            c0: 20.0,
            gamma: TAIT_GAMMA_WATER,
        };
        let mut air = Eos {
            kind: EosKind::Tait,
            rho0: 1.0,
            c0: 0.0,
            gamma: 1.4,
        };
        let c_air = equal_stiffness_sound_speed(&water, &air);
        // Grenier et al. §4.2: 282.84 m/s for water at 20 m/s.
        assert!((c_air - 282.84).abs() < 0.01, "{c_air}");
        air.c0 = c_air;
        assert!((air.stiffness() - water.stiffness()).abs() < 1e-9 * water.stiffness());
    }

    #[test]
    fn shepard_density_is_the_volume_weighted_mean_of_the_particle_densities() {
        let mut s = ShepardDensity::default();
        // Two neighbours with ρ̃ = m/V of 1000 and 1010, weights 0.3 and 0.1.
        s.add(0.3, 1000.0 * 2.0, 2.0);
        s.add(0.1, 1010.0 * 1.0, 1.0);
        let expect = (0.3 * 2.0 * 1000.0 + 0.1 * 1.0 * 1010.0) / (0.3 * 2.0 + 0.1 * 1.0);
        assert!((s.density(0.0) - expect).abs() < 1e-9);
        assert_eq!(ShepardDensity::default().density(7.0), 7.0);
    }
}
