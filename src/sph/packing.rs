//! Particle packing (thesis chapter 6, Colagrossi, Bouscasse, Antuono & Marrone): moves the particles of an
//! initial distribution, inside a domain closed by fixed particles (walls and, in place of the free
//! surface, a solid lid), along w = −∇Γ, Γ_i = Σ_j W_ij V_j, until ∇Γ is as small as the distribution
//! allows. Eq. (6.3) with a linear damping:
//!
//!   du_i/dt = −β ∇Γ_i − ζ u_i,   dr_i/dt = u_i,   ζ = α_ζ √β / V0^{1/d}  (6.2),   Δt = CFL V0^{1/d} / √β  (6.4).
//!
//! β = 2 p0/ρ0 only sets the time scale of this fictitious dynamics, so it is 1 here (m²/s²). Each particle
//! keeps its own volume V_j, so a graded distribution (fine rows above, coarse below) is packed as well:
//! its rows settle where the kernel sum is even across the change of spacing. V0 is the smallest volume (the
//! finest spacing sets the time step). The result is deterministic: a gather loop in parallel, then an
//! update in particle order.

use super::kernel::Kernel;
use super::kernel_table::{GradientFactor, GradientTable};
use super::neighbours::CellList;
use nalgebra::SVector;
use rayon::prelude::*;

/// Options of the packing.
#[derive(Clone, Copy, Debug)]
pub struct PackingConfig {
    /// α_ζ of (6.2), dimensionless. The thesis finds 1e-3 to 5e-3 good; a larger value damps faster per
    /// iteration but freezes the particles before they reach the equilibrium.
    pub alpha_zeta: f64,
    /// CFL of (6.4); the thesis uses 1.
    pub cfl: f64,
    /// Most iterations (the thesis's Fig. 6.4: about 2 500 to rest).
    pub max_iterations: usize,
    /// Stop once the specific kinetic energy Σ|u|²/(N β) falls below this, after at least a tenth of
    /// `max_iterations` (the thesis reports 1e-8 at equilibrium).
    pub ke_tolerance: f64,
}

impl Default for PackingConfig {
    fn default() -> Self {
        Self {
            alpha_zeta: 5e-3,
            cfl: 1.0,
            max_iterations: 3_000,
            ke_tolerance: 1e-8,
        }
    }
}

/// What the packing did.
#[derive(Clone, Copy, Debug, serde::Serialize, serde::Deserialize)]
pub struct PackingReport {
    pub iterations: usize,
    /// Specific kinetic energy Σ|u|²/(N β) at the end.
    pub specific_ke: f64,
    /// max_i |∇Γ_i| · V0^{1/d} (dimensionless) before and after.
    pub grad_gamma_before: f64,
    pub grad_gamma_after: f64,
    /// Largest displacement of a particle from its initial position, over V0^{1/d}.
    pub max_displacement: f64,
}

/// Candidate neighbours of every moving particle: the points within `reach` = the kernel support plus a skin
/// (a Verlet list), in the cell list's fixed order. The packing moves particles by a fraction of a spacing in
/// all, so the lists are built a few times instead of a cell list at every iteration.
fn candidate_lists<const D: usize>(all: &[SVector<f64, D>], n_moving: usize, reach: f64) -> Vec<Vec<u32>> {
    let cells = CellList::build(all, reach);
    (0..n_moving)
        .into_par_iter()
        .map(|i| {
            let mut list = Vec::with_capacity(64);
            cells.for_each_within_r2(all, &all[i], reach, |j, _, _| {
                if j != i {
                    list.push(j as u32);
                }
            });
            list.shrink_to_fit();
            list
        })
        .collect()
}

/// ∇Γ_i = Σ_j ∇_i W_ij V_j over moving and fixed particles (`all`: the moving ones first), for every moving
/// particle (gather loop over its candidates; those beyond the support add nothing).
fn grad_gamma<const D: usize>(
    factor: &GradientFactor<D>,
    support: f64,
    all: &[SVector<f64, D>],
    vol: &[f64],
    lists: &[Vec<u32>],
) -> Vec<SVector<f64, D>> {
    let r2_max = support * support;
    lists
        .par_iter()
        .enumerate()
        .map(|(i, list)| {
            let mut g = SVector::<f64, D>::zeros();
            for &j in list {
                let rij = all[i] - all[j as usize];
                let r2 = rij.norm_squared();
                if r2 < r2_max {
                    g += rij * (factor.at(r2) * vol[j as usize]);
                }
            }
            g
        })
        .collect()
}

/// Packs `moving` (volumes `volumes`) against the fixed particles. `keep_inside` is applied to every new
/// position (e.g. a clamp to the domain), a safeguard: the fixed layers are what holds the particles in.
pub fn pack<const D: usize>(
    kernel: &Kernel<D>,
    moving: &mut [SVector<f64, D>],
    volumes: &[f64],
    fixed: &[SVector<f64, D>],
    fixed_volumes: &[f64],
    cfg: &PackingConfig,
    keep_inside: impl Fn(&mut SVector<f64, D>) + Sync,
) -> PackingReport {
    assert_eq!(moving.len(), volumes.len());
    assert_eq!(fixed.len(), fixed_volumes.len());
    let n = moving.len();
    let v0 = volumes
        .iter()
        .chain(fixed_volumes)
        .copied()
        .fold(f64::INFINITY, f64::min);
    let l0 = v0.powf(1.0 / D as f64);
    let beta: f64 = 1.0;
    let zeta = cfg.alpha_zeta * beta.sqrt() / l0;
    let dt = cfg.cfl * l0 / beta.sqrt();
    let start: Vec<SVector<f64, D>> = moving.to_vec();
    let mut vel = vec![SVector::<f64, D>::zeros(); n];
    let norm_max = |g: &[SVector<f64, D>]| g.iter().map(|v| v.norm()).fold(0.0, f64::max) * l0;
    // The Gaussian's gradient factor from its table in r² (as the solver's default): the packing is a
    // fictitious dynamics, and the table's 6e-7 relative error is far below what it resolves.
    let table = GradientTable::new(kernel);
    let factor = match &table {
        Some(t) => GradientFactor::Table(t),
        None => GradientFactor::Exact(*kernel),
    };
    let mut all: Vec<SVector<f64, D>> = moving.iter().chain(fixed).copied().collect();
    let vol: Vec<f64> = volumes.iter().chain(fixed_volumes).copied().collect();
    // Skin of the candidate lists: rebuilt once a particle has moved half of it, so no pair within the
    // support is ever missing from them.
    let skin = 0.5 * l0;
    let reach = kernel.support + skin;
    let mut lists = candidate_lists(&all, n, reach);
    let mut built_at = moving.to_vec();
    let mut grad = grad_gamma(&factor, kernel.support, &all, &vol, &lists);
    let grad_gamma_before = norm_max(&grad);
    let mut iterations = 0;
    let mut specific_ke = 0.0;
    while iterations < cfg.max_iterations {
        // Semi-implicit Euler: velocity first (force and damping), then position with the new velocity.
        moving
            .par_iter_mut()
            .zip(vel.par_iter_mut())
            .zip(grad.par_iter())
            .for_each(|((x, u), g)| {
                *u = (*u - g * (beta * dt)) / (1.0 + zeta * dt);
                *x += *u * dt;
                let free = *x;
                keep_inside(x);
                if *x != free {
                    // Held by the safeguard: the particle stops, so no momentum piles up against it.
                    *u = SVector::zeros();
                }
            });
        iterations += 1;
        specific_ke = vel.iter().map(|u| u.norm_squared()).sum::<f64>() / (n.max(1) as f64 * beta);
        all[..n].copy_from_slice(moving);
        let drift = moving
            .iter()
            .zip(&built_at)
            .map(|(a, b)| (a - b).norm())
            .fold(0.0, f64::max);
        if drift >= 0.5 * skin {
            drop(std::mem::take(&mut lists));
            lists = candidate_lists(&all, n, reach);
            built_at.copy_from_slice(moving);
        }
        grad = grad_gamma(&factor, kernel.support, &all, &vol, &lists);
        if iterations >= cfg.max_iterations / 10 && specific_ke < cfg.ke_tolerance {
            break;
        }
    }
    let max_displacement = moving
        .iter()
        .zip(&start)
        .map(|(a, b)| (a - b).norm())
        .fold(0.0, f64::max)
        / l0;
    PackingReport {
        iterations,
        specific_ke,
        grad_gamma_before,
        grad_gamma_after: norm_max(&grad),
        max_displacement,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::kernel::KernelKind;
    use nalgebra::Vector2;

    /// The fast path (candidate lists with a skin, the tabulated gradient factor) against the slow oracle
    /// (every pair, the exact kernel): ∇Γ agrees to the table's accuracy, also after every particle has moved
    /// by just under half the skin since the lists were built (a pair may close in by a whole skin).
    #[test]
    fn candidate_lists_give_the_brute_force_grad_gamma_until_half_the_skin_is_used() {
        let dx = 0.1;
        let k = Kernel::<2>::new(KernelKind::RenormalizedGaussian, 1.33 * dx);
        let mut seed = 7u64;
        let mut rnd = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let mut all: Vec<Vector2<f64>> = (0..30)
            .flat_map(|i| (0..30).map(move |j| Vector2::new(i as f64 * dx, j as f64 * dx)))
            .collect();
        for p in all.iter_mut() {
            *p += Vector2::new(rnd(), rnd()) * 0.4 * dx;
        }
        let vol: Vec<f64> = (0..all.len()).map(|i| dx * dx * (1.0 + 0.2 * (i % 3) as f64)).collect();
        let n_moving = 600; // the rest are fixed
        let table = GradientTable::new(&k).unwrap();
        let fast = GradientFactor::Table(&table);
        let skin = 0.5 * dx;
        let lists = candidate_lists(&all, n_moving, k.support + skin);
        let oracle = |all: &[Vector2<f64>]| -> Vec<Vector2<f64>> {
            (0..n_moving)
                .map(|i| {
                    let mut g = Vector2::zeros();
                    for j in 0..all.len() {
                        let rij = all[i] - all[j];
                        if j != i && rij.norm() < k.support {
                            g += k.grad(&rij, rij.norm()) * vol[j];
                        }
                    }
                    g
                })
                .collect()
        };
        let peak = oracle(&all).iter().map(|g| g.norm()).fold(0.0, f64::max);
        let check = |all: &[Vector2<f64>], when: &str| {
            let (got, want) = (grad_gamma(&fast, k.support, all, &vol, &lists), oracle(all));
            let worst = got.iter().zip(&want).map(|(a, b)| (a - b).norm()).fold(0.0, f64::max);
            assert!(
                worst < 1e-5 * peak,
                "{when}: worst |Δ∇Γ| {worst:e} against a largest |∇Γ| of {peak:e}"
            );
        };
        check(&all, "as built");
        // Move every moving particle by just under skin/2 in a random direction.
        for p in all.iter_mut().take(n_moving) {
            let a = std::f64::consts::TAU * (rnd() + 0.5);
            *p += Vector2::new(a.cos(), a.sin()) * 0.499 * skin;
        }
        check(&all, "after moving");
    }

    /// A square of jittered particles inside a closed box of fixed lattice particles: packing shrinks
    /// max |∇Γ| and leaves the particles nearly at rest; a perfect lattice is already packed and stays put.
    #[test]
    fn packing_reduces_grad_gamma_and_keeps_a_lattice() {
        let dx = 0.1;
        let k = Kernel::<2>::new(KernelKind::RenormalizedGaussian, 1.33 * dx);
        let n = 12;
        let lattice = |i: i32, j: i32| Vector2::new((i as f64 + 0.5) * dx, (j as f64 + 0.5) * dx);
        let mut fixed = vec![];
        for i in -4..n + 4 {
            for j in -4..n + 4 {
                if !(0..n).contains(&i) || !(0..n).contains(&j) {
                    fixed.push(lattice(i, j));
                }
            }
        }
        let fixed_v = vec![dx * dx; fixed.len()];
        let mut pts = vec![];
        let mut seed = 12345u64;
        let mut rnd = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 0.3 * dx
        };
        for i in 0..n {
            for j in 0..n {
                pts.push(lattice(i, j) + Vector2::new(rnd(), rnd()));
            }
        }
        let vols = vec![dx * dx; pts.len()];
        let cfg = PackingConfig::default();
        let r = pack(&k, &mut pts, &vols, &fixed, &fixed_v, &cfg, |_| {});
        println!("jittered square: {r:?}");
        assert!(
            r.grad_gamma_after < 0.1 * r.grad_gamma_before,
            "max |∇Γ| dx {:.3e} → {:.3e}",
            r.grad_gamma_before,
            r.grad_gamma_after
        );
        assert!(r.specific_ke < 1e-4, "{r:?}");

        let mut lat: Vec<_> = (0..n).flat_map(|i| (0..n).map(move |j| lattice(i, j))).collect();
        let r = pack(&k, &mut lat, &vols, &fixed, &fixed_v, &cfg, |_| {});
        assert!(r.grad_gamma_before < 1e-6 && r.max_displacement < 1e-6, "{r:?}");
    }
}
