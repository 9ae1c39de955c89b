//! Particle shifting of the δ⁺-SPH of Sun, Colagrossi, Marrone & Zhang (2017), an option after each step.
//!
//! δr_i = −CFL·Ma·(2h)² Σ_j [1 + R (W_ij / W(Δx))^n] ∇_i W_ij V_j, with CFL·Ma = U_max Δt / h, so that the
//! coefficient is [`A`] h U_max Δt with A = 4; R = 0.2, n = 4 as in the paper (U_max the largest fluid speed).
//!
//! Near the free surface only the part tangent to it is kept, and splashes do not move; both are read from the
//! minimum eigenvalue λ of the renormalisation matrix and the normal of thesis §7.2
//! ([`super::free_surface`]): λ ≤ 0.2 no shift; the tangential part for a surface particle (λ ≤ 0.75: every
//! free-surface particle and the layer under it) and for every particle within a kernel support of one (the
//! surface's vicinity, as in the paper), whose sum the surface truncates: its normal part points out of the
//! water and would lift the layers under the surface (docs/reference/method.md, "Particle shifting"); all of
//! it elsewhere. The density is carried to the new
//! position to first order with the renormalised gradient of eq. (4.19) (ρ_i += ∇ρ_i · δr_i); the velocity is
//! not corrected (the paper's simple form).
//!
//! `sun2017-walls` ([`ParticleShifting::Sun2017Walls`], ours) applies the same shift only to the particles within
//! two kernel supports of a wall ghost (the water the ghosts' MLS values read) that are not within a support of
//! the free surface; everything else stays Lagrangian, as in the thesis's δ-SPH. `sun2017-leaving`
//! ([`ParticleShifting::Sun2017Leaving`], ours) draws that band only where the flow leaves the ghosts.
//!
//! Why it is here (issue #35): at a stagnation point that the flow leaves a wall from, the Lagrangian particles
//! move apart along the outflow and a void opens over the fixed ghosts; the ghosts' MLS values, extrapolated
//! into the void, over-read the pressure by a factor up to 2.8 (`jet-floor`) and the dam break's corner by
//! 20–60 %. Shifting keeps the particles spread evenly and removes most of it
//! (docs/reference/method.md, "Particle shifting").

use super::free_surface::SurfaceSums;
use super::kernel::Kernel;
use super::neighbours::CellList;
use nalgebra::SVector;
use rayon::prelude::*;

/// Whether (and whose) particle shifting runs after each step.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ParticleShifting {
    /// None: the thesis's δ-SPH; the default with several phases, which the shift would mix
    /// ([`default_for`]).
    None,
    /// Sun et al. (2017), δ⁺-SPH.
    Sun2017,
    /// The same shift, applied only to the particles within two kernel supports of a fixed wall ghost (those the
    /// ghosts' MLS values read) and not within a support of the free surface: the remedy where the defect is
    /// (the void that opens over the fixed ghosts under a stagnation point), the rest of the water, the free
    /// surface and a wall's contact line left Lagrangian (ours; issue #35). The default of a single-phase
    /// scene in sessions 48–49 (docs/decisions/wall-band-shifting.md).
    Sun2017Walls,
    /// The band of [`ParticleShifting::Sun2017Walls`] only where the flow leaves a wall: within a kernel support
    /// of the particles that lie within a support of a fixed ghost and move away from the ghosts there
    /// ([`ShiftRegion::WhereTheFlowLeaves`]). The void opens where the water leaves the ghost lattice; where it
    /// arrives (a flat wall's stagnation point) there is none, and a shift there only costs the velocity it does
    /// not carry (ours; issue #35, studies/results/validation/LOG.md, session 49). The default of a single-phase
    /// scene: the one wall variant that reads a flat wall's stagnation point within tolerance (`jet-plate`)
    /// and the others' corners (docs/decisions/wall-leaving-shifting.md).
    #[default]
    Sun2017Leaving,
}

/// The default shifting of a scene: [`ParticleShifting::Sun2017Leaving`] with one phase, none with several
/// (a case's `[[phases]]`, the 2D+t air layer: [`WITH_PHASES`]).
pub fn default_for(several_phases: bool) -> ParticleShifting {
    if several_phases {
        ParticleShifting::None
    } else {
        ParticleShifting::Sun2017Leaving
    }
}

impl std::str::FromStr for ParticleShifting {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "none" => Ok(Self::None),
            "sun2017" => Ok(Self::Sun2017),
            "sun2017-walls" => Ok(Self::Sun2017Walls),
            "sun2017-leaving" => Ok(Self::Sun2017Leaving),
            v => Err(format!(
                "expected `none`, `sun2017`, `sun2017-walls` or `sun2017-leaving`, got `{v}`"
            )),
        }
    }
}

impl std::fmt::Display for ParticleShifting {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::None => "none",
            Self::Sun2017 => "sun2017",
            Self::Sun2017Walls => "sun2017-walls",
            Self::Sun2017Leaving => "sun2017-leaving",
        })
    }
}

/// Why particle shifting and several phases are refused together (a case's `[[phases]]`, the 2D+t air layer):
/// what is expected instead.
pub const WITH_PHASES: &str = "no particle shifting with it (`shifting = none`): the shift of Sun et al. (2017) \
is single-phase and moves particles across the interface between phases";

/// A of δr = −A h U_max Δt Σ…: (2h)²/h² = 4 (Sun et al. 2017), dimensionless.
pub const A: f64 = 4.0;
/// R of the anti-clumping term (Sun et al. 2017: 0.2), dimensionless.
pub const R: f64 = 0.2;
/// Its power n (Sun et al. 2017: 4).
pub const N: i32 = 4;
/// The largest displacement in one step, in Δx: 0.25 (ours; a bound the shift reaches only where the
/// particles are far from even, as at the first impacts).
pub const CAP: f64 = 0.25;
/// λ at or below which a particle does not move (splashes, thesis eq. 7.22's lower threshold).
pub const LAMBDA_SPLASH: f64 = 0.2;
/// λ at or below which only the tangential part is kept (eq. 7.22's upper threshold).
pub const LAMBDA_SURFACE: f64 = 0.75;

/// The shift of one particle from its sum S = Σ_j [1 + R (W_ij/W(Δx))^n] ∇_i W_ij V_j: −coef S, projected
/// on the free surface's tangent (normal `normal`) where the particle is `near_surface` (on it or within a
/// kernel support of it), zero in a splash (λ ≤ [`LAMBDA_SPLASH`]), at most [`CAP`] Δx long.
pub fn shift_from_sum<const D: usize>(
    sum: &SVector<f64, D>,
    coef: f64,
    lambda: f64,
    near_surface: bool,
    normal: &SVector<f64, D>,
    dx: f64,
) -> SVector<f64, D> {
    if lambda <= LAMBDA_SPLASH {
        return SVector::zeros();
    }
    let mut d = -sum * coef;
    if near_surface {
        if normal.norm_squared() == 0.0 {
            return SVector::zeros();
        }
        d -= normal * normal.dot(&d);
    }
    let m = d.norm();
    if m > CAP * dx {
        d *= CAP * dx / m;
    }
    d
}

/// The velocities of all of `pos`, borrowed from where they live: the fluid's, then the ghosts' (the ghosts
/// follow the fluid in `pos`).
#[derive(Clone, Copy, Debug)]
pub struct Velocities<'a, const D: usize> {
    /// The fluid particles' (m/s), the first of `pos`.
    pub fluid: &'a [SVector<f64, D>],
    /// The ghosts' (m/s), in `pos` after the fluid.
    pub ghosts: &'a [SVector<f64, D>],
}

impl<const D: usize> Velocities<'_, D> {
    /// The velocity of particle j of `pos`.
    pub fn of(&self, j: usize) -> SVector<f64, D> {
        match j.checked_sub(self.fluid.len()) {
            None => self.fluid[j],
            Some(g) => self.ghosts[g],
        }
    }
}

/// Where a step's shift applies.
#[derive(Clone, Debug)]
pub enum ShiftRegion<'a, const D: usize> {
    /// Everywhere ([`ParticleShifting::Sun2017`]).
    Everywhere,
    /// [`ParticleShifting::Sun2017Walls`]: within two kernel supports of these ghosts (their indices in `pos`:
    /// the fixed ghosts, whose lattice the void opens over) and away from the free surface. Image ghosts mirror
    /// the fluid and leave no void: a band around them only disturbs the flow they mirror (the `jet-wall`
    /// corner with image ghosts at b/dx 10 reads Cp 1.042 with it, 0.994 without).
    NearWalls { ghosts: std::ops::Range<usize> },
    /// [`ParticleShifting::Sun2017Leaving`]: within a kernel support of a fluid particle i that lies within a
    /// support of these ghosts and moves away from them, Σ_g (u_i − u_g) · (r_i − r_g) W_ig > 0 over the ghosts
    /// g within its support (the ghosts' part of −∇·u at i: they spread its neighbourhood), and away from the
    /// free surface. `vel`: the velocities of all of `pos` (a ghost's that of its wall condition, so that with
    /// free slip the sum reads the normal velocity relative to the wall).
    WhereTheFlowLeaves {
        ghosts: std::ops::Range<usize>,
        vel: Velocities<'a, D>,
    },
}

/// What one step's shift depends on besides the particles.
#[derive(Clone, Debug)]
pub struct ShiftStep<'a, const D: usize> {
    /// The particle spacing Δx (m): W(Δx) of the anti-clumping term, and the cap [`CAP`] Δx.
    pub dx: f64,
    /// U_max Δt (m): the largest fluid speed times the step.
    pub u_max_dt: f64,
    /// Where it applies.
    pub region: ShiftRegion<'a, D>,
}

/// The shift of every fluid particle (the first `n_fluid` of `pos`; `volume` for all of `pos`, 0 for a ghost
/// that takes no part), for a step of U_max Δt = `u_max_dt`. Everywhere ([`ShiftRegion::Everywhere`]):
/// a first pass over the neighbours gathers the shift's sum and the matrix and vector of §7.2 (λ and the normal,
/// as [`super::free_surface::detect`] computes them; its scan-region test is not needed, since every particle it
/// would decide, λ in (0.2, 0.75], is projected on its tangent anyway); a second finds the particles within a
/// kernel support of a surface particle (λ ≤ [`LAMBDA_SURFACE`]). In a band, the same sums and tests, only
/// for the particles the band needs (its rows along the walls).
pub fn displacements<const D: usize>(
    kernel: &Kernel<D>,
    cells: &CellList<D>,
    pos: &[SVector<f64, D>],
    volume: &[f64],
    n_fluid: usize,
    step: ShiftStep<'_, D>,
) -> Vec<SVector<f64, D>> {
    let coef = A * kernel.h * step.u_max_dt;
    let w_dx = kernel.w(step.dx);
    let sums_of = |i: usize| particle_sums(kernel, cells, pos, volume, i, w_dx);
    let near = |from: &[bool]| fluid_within_a_support(cells, pos, n_fluid, kernel.support, from);
    // The fixed ghosts that take part (a fit, volume > 0).
    let fixed = |ghosts: std::ops::Range<usize>| {
        (0..pos.len())
            .map(|j| ghosts.contains(&j) && volume[j] != 0.0)
            .collect::<Vec<_>>()
    };
    // The fluid within a support of the ghosts is the water their MLS fits read.
    let band = match step.region {
        ShiftRegion::Everywhere => None,
        ShiftRegion::NearWalls { ghosts } => Some(near(&near(&fixed(ghosts)))),
        ShiftRegion::WhereTheFlowLeaves { ghosts, vel } => {
            let fixed = fixed(ghosts);
            let read = near(&fixed);
            let leaving: Vec<bool> = (0..n_fluid)
                .into_par_iter()
                .map(|i| read[i] && moves_away(kernel, cells, pos, vel, &fixed, i))
                .collect();
            Some(near(&leaving))
        }
    };
    if let Some(band) = band {
        return band_displacements(kernel, cells, pos, n_fluid, &band, sums_of, |sums| {
            shift_from_sum(&sums.0, coef, sums.1, false, &sums.2, step.dx)
        });
    }
    let sums: Vec<_> = (0..n_fluid).into_par_iter().map(sums_of).collect();
    let on_surface = |j: usize| j < n_fluid && sums[j].1 <= LAMBDA_SURFACE;
    (0..n_fluid)
        .into_par_iter()
        .map(|i| {
            let (sum, lambda, normal) = &sums[i];
            let near_surface = marked_within_a_support(cells, pos, kernel.support, i, on_surface);
            shift_from_sum(sum, coef, *lambda, near_surface, normal, step.dx)
        })
        .collect()
}

/// Whether fluid particle i moves away from the ghosts marked in `fixed` within a support of it:
/// Σ_g (u_i − u_g) · (r_i − r_g) W_ig > 0 ([`ShiftRegion::WhereTheFlowLeaves`]).
fn moves_away<const D: usize>(
    kernel: &Kernel<D>,
    cells: &CellList<D>,
    pos: &[SVector<f64, D>],
    vel: Velocities<'_, D>,
    fixed: &[bool],
    i: usize,
) -> bool {
    let mut separation = 0.0;
    let u_i = vel.of(i);
    cells.for_each_within(pos, &pos[i], kernel.support, |j, rij, r| {
        if fixed[j] {
            separation += (u_i - vel.of(j)).dot(&rij) * kernel.w(r);
        }
    });
    separation > 0.0
}

/// Whether `marked` holds for particle i or for a particle within a kernel support (`support`) of it (the
/// surface's vicinity, with `marked` the surface test).
fn marked_within_a_support<const D: usize>(
    cells: &CellList<D>,
    pos: &[SVector<f64, D>],
    support: f64,
    i: usize,
    marked: impl Fn(usize) -> bool,
) -> bool {
    let mut near = marked(i);
    if !near {
        cells.for_each_within(pos, &pos[i], support, |j, _, _| near |= marked(j));
    }
    near
}

/// One particle's sums: (S, λ, normal).
type Sums<const D: usize> = (SVector<f64, D>, f64, SVector<f64, D>);

/// A band's shifts: the shift `shift` gives a particle from its sums (`sums_of`) where `band` marks it and no
/// free-surface particle (λ ≤ [`LAMBDA_SURFACE`]) lies within a support of it, zero elsewhere. A scatter
/// ([`fluid_within_a_support`]) finds the particles whose λ the surface test reads, and the sums are taken for
/// those alone: a band is a few rows along the walls, and the rest of the water costs nothing.
fn band_displacements<const D: usize>(
    kernel: &Kernel<D>,
    cells: &CellList<D>,
    pos: &[SVector<f64, D>],
    n_fluid: usize,
    band: &[bool],
    sums_of: impl Fn(usize) -> Sums<D> + Sync,
    shift: impl Fn(&Sums<D>) -> SVector<f64, D> + Sync,
) -> Vec<SVector<f64, D>> {
    let read = fluid_within_a_support(cells, pos, n_fluid, kernel.support, band);
    // λ of the particles read (∞ elsewhere: not a surface particle), and the band's shifts before the surface
    // test; 24 bytes a particle, not the sums themselves.
    let (lambda, mut shifts): (Vec<f64>, Vec<SVector<f64, D>>) = (0..n_fluid)
        .into_par_iter()
        .map(|i| {
            if !read[i] {
                return (f64::INFINITY, SVector::zeros());
            }
            let own = sums_of(i);
            (own.1, if band[i] { shift(&own) } else { SVector::zeros() })
        })
        .unzip();
    let on_surface = |j: usize| j < n_fluid && lambda[j] <= LAMBDA_SURFACE;
    shifts.par_iter_mut().enumerate().for_each(|(i, d)| {
        if *d == SVector::<f64, D>::zeros() {
            return;
        }
        // The band leaves the free surface and its vicinity Lagrangian too: a shift there moves a wall's
        // contact line (ours: the sloshing gauges at the walls read −7 % / +5 % with it).
        if marked_within_a_support(cells, pos, kernel.support, i, on_surface) {
            *d = SVector::zeros();
        }
    });
    shifts
}

/// One particle's sums: the shift's S = Σ_j [1 + R (W_ij/W(Δx))^n] ∇_i W_ij V_j, and λ and the normal of
/// §7.2 from the same neighbours (`w_dx` = W(Δx)).
fn particle_sums<const D: usize>(
    kernel: &Kernel<D>,
    cells: &CellList<D>,
    pos: &[SVector<f64, D>],
    volume: &[f64],
    i: usize,
    w_dx: f64,
) -> Sums<D> {
    let mut surface = SurfaceSums::<D>::new();
    let mut sum = SVector::<f64, D>::zeros();
    cells.for_each_within(pos, &pos[i], kernel.support, |j, rij, r| {
        if j == i || volume[j] == 0.0 {
            return;
        }
        let (w, gw) = kernel.w_and_grad(&rij, r);
        surface.add(&gw, &rij, volume[j]);
        let f = 1.0 + R * (w / w_dx).powi(N);
        sum += gw * (f * volume[j]);
    });
    let (lambda, normal) = surface.lambda_and_normal();
    (sum, lambda, normal)
}

/// The fluid particles (the first `n_fluid` of `pos`) within a kernel support (`support`) of a particle marked
/// in `from` (itself included). A scatter from the marked ones, which are few (a band along the walls), into a
/// set of flags that are only ever set: the same set for any thread count and order, one byte per particle.
fn fluid_within_a_support<const D: usize>(
    cells: &CellList<D>,
    pos: &[SVector<f64, D>],
    n_fluid: usize,
    support: f64,
    from: &[bool],
) -> Vec<bool> {
    use std::sync::atomic::{AtomicBool, Ordering::Relaxed};
    let marked: Vec<AtomicBool> = (0..n_fluid).map(|_| AtomicBool::new(false)).collect();
    (0..from.len()).into_par_iter().filter(|&k| from[k]).for_each(|k| {
        cells.for_each_within_r2(pos, &pos[k], support, |j, _, _| {
            if j < n_fluid {
                marked[j].store(true, Relaxed);
            }
        });
    });
    marked.into_iter().map(AtomicBool::into_inner).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::kernel::KernelKind;
    use nalgebra::Vector2;

    #[test]
    fn a_splash_does_not_move_and_the_surface_moves_along_itself() {
        let s = Vector2::new(3.0, -4.0);
        let n = Vector2::new(0.0, 1.0);
        assert_eq!(shift_from_sum(&s, 1e-3, 0.1, true, &n, 1.0), Vector2::zeros());
        let d = shift_from_sum(&s, 1e-3, 0.5, true, &n, 1.0);
        assert_eq!(d.y, 0.0);
        assert!((d.x + 3e-3).abs() < 1e-15);
        // Inside the water (λ near 1) but within a support of the surface: along it too.
        let d = shift_from_sum(&s, 1e-3, 0.9, true, &n, 1.0);
        assert_eq!(d.y, 0.0);
        let d = shift_from_sum(&s, 1e-3, 0.9, false, &n, 1.0);
        assert!((d - Vector2::new(-3e-3, 4e-3)).norm() < 1e-15);
        // The cap: at most CAP dx.
        let d = shift_from_sum(&s, 1.0, 0.9, false, &n, 1.0);
        assert!((d.norm() - CAP).abs() < 1e-12);
    }

    /// A block of water `nx` × `ny` particles over a floor of fixed ghosts (four rows), its lattice perturbed so
    /// that every sum is non-zero: the positions, fluid first, and the number of fluid particles.
    fn block_over_a_floor(nx: usize, ny: usize, dx: f64) -> (Vec<Vector2<f64>>, usize) {
        let mut pos = vec![];
        for j in 0..ny {
            for i in 0..nx {
                let wobble = 0.05 * dx * (((7 * i + 13 * j) % 11) as f64 / 11.0 - 0.5);
                pos.push(Vector2::new(
                    (i as f64 + 0.5) * dx + wobble,
                    (j as f64 + 0.5) * dx - wobble,
                ));
            }
        }
        let n_fluid = pos.len();
        for k in 0..4 {
            for i in 0..nx {
                pos.push(Vector2::new((i as f64 + 0.5) * dx, -(k as f64 + 0.5) * dx));
            }
        }
        (pos, n_fluid)
    }

    /// `sun2017-walls` moves only the particles within two kernel supports of a fixed wall ghost and away from
    /// the free surface, each by exactly the shift `sun2017` gives it; the rest of the water does not move, and
    /// nothing moves over image ghosts.
    #[test]
    fn wall_band_shift_is_the_full_shift_within_two_supports_of_a_wall_and_zero_beyond() {
        let dx = 0.1;
        let kernel = Kernel::<2>::new(KernelKind::RenormalizedGaussian, 1.33 * dx);
        // A block of water 40 dx high over a floor of ghosts; volumes dx².
        let (nx, ny) = (30, 40);
        let (pos, n_fluid) = block_over_a_floor(nx, ny, dx);
        let volume = vec![dx * dx; pos.len()];
        let cells = CellList::build(&pos, kernel.support);
        let step = |region| ShiftStep {
            dx,
            u_max_dt: 0.01 * dx,
            region,
        };
        let full = displacements(&kernel, &cells, &pos, &volume, n_fluid, step(ShiftRegion::Everywhere));
        let near = |ghosts| step(ShiftRegion::NearWalls { ghosts });
        let band = displacements(&kernel, &cells, &pos, &volume, n_fluid, near(n_fluid..pos.len()));
        // The same floor of image ghosts (no fixed ghost): no band, nothing moves.
        let images = displacements(&kernel, &cells, &pos, &volume, n_fluid, near(n_fluid..n_fluid));
        assert!(
            images.iter().all(|d| *d == Vector2::zeros()),
            "a band around image ghosts"
        );
        let (mut moved, mut still, mut surface) = (0, 0, 0);
        let width = nx as f64 * dx;
        for i in 0..n_fluid {
            let (x, y) = (pos[i].x, pos[i].y);
            let interior = x > 2.0 * kernel.support && x < width - 2.0 * kernel.support;
            if y < kernel.support && interior {
                assert_eq!(
                    band[i], full[i],
                    "particle {i} at ({x}, {y}): within a support of the floor"
                );
                moved += (band[i] != Vector2::zeros()) as usize;
            } else if y > 2.0 * kernel.support {
                assert_eq!(
                    band[i],
                    Vector2::zeros(),
                    "particle {i} at ({x}, {y}): beyond two supports"
                );
                still += (full[i] != Vector2::zeros()) as usize;
            } else if x < 0.5 * kernel.support || x > width - 0.5 * kernel.support {
                // On the block's sides, free surfaces: the band leaves them where they are.
                assert_eq!(
                    band[i],
                    Vector2::zeros(),
                    "particle {i} at ({x}, {y}): at the free surface"
                );
                surface += (full[i] != Vector2::zeros()) as usize;
            } else {
                assert!(
                    band[i] == full[i] || band[i] == Vector2::zeros(),
                    "particle {i}: all or nothing"
                );
            }
        }
        assert!(
            moved > 0 && still > 0 && surface > 0,
            "the case must shift near the floor ({moved}), away from it ({still}) and at the surface ({surface})"
        );
    }

    /// The slow oracle of the bands' scatters: every particle's sums, and each particle's own scans: for a fixed
    /// ghost within a support (and, where the flow must leave, its separation from them), then for such a
    /// particle within a support and for a surface particle within one.
    fn band_by_gather(
        kernel: &Kernel<2>,
        cells: &CellList<2>,
        pos: &[Vector2<f64>],
        volume: &[f64],
        n_fluid: usize,
        step: &ShiftStep<'_, 2>,
    ) -> Vec<Vector2<f64>> {
        let (ghosts, vel) = match &step.region {
            ShiftRegion::NearWalls { ghosts } => (ghosts.clone(), None),
            ShiftRegion::WhereTheFlowLeaves { ghosts, vel } => (ghosts.clone(), Some(*vel)),
            ShiftRegion::Everywhere => unreachable!(),
        };
        let (coef, w_dx) = (A * kernel.h * step.u_max_dt, kernel.w(step.dx));
        let sums: Vec<_> = (0..n_fluid)
            .map(|i| particle_sums(kernel, cells, pos, volume, i, w_dx))
            .collect();
        let seed: Vec<bool> = (0..n_fluid)
            .map(|i| {
                let (mut near, mut separation) = (false, 0.0);
                cells.for_each_within(pos, &pos[i], kernel.support, |j, rij, r| {
                    if ghosts.contains(&j) && volume[j] != 0.0 {
                        near = true;
                        if let Some(u) = vel {
                            separation += (u.of(i) - u.of(j)).dot(&rij) * kernel.w(r);
                        }
                    }
                });
                near && (vel.is_none() || separation > 0.0)
            })
            .collect();
        (0..n_fluid)
            .map(|i| {
                let (mut in_band, mut near_surface) = (false, false);
                cells.for_each_within(pos, &pos[i], kernel.support, |j, _, _| {
                    if j < n_fluid {
                        in_band |= seed[j];
                        near_surface |= sums[j].1 <= LAMBDA_SURFACE;
                    }
                });
                if !in_band || near_surface {
                    return Vector2::zeros();
                }
                shift_from_sum(&sums[i].0, coef, sums[i].1, false, &sums[i].2, step.dx)
            })
            .collect()
    }

    /// The bands' fast path (scatters from the ghosts, then from the marked particles, and the sums only where
    /// they are read) gives the oracle's shifts to the bit, in a corner of fixed ghosts with a sloping free
    /// surface, ghosts that take no part, image ghosts beside them and a splash; where the flow must leave the
    /// walls, in a flow that leaves the floor on one side and falls onto it on the other.
    #[test]
    fn band_scatter_gives_the_gather_oracles_shifts_to_the_bit() {
        let dx = 0.1;
        let kernel = Kernel::<2>::new(KernelKind::RenormalizedGaussian, 1.33 * dx);
        let mut pos = vec![];
        for j in 0..30 {
            for i in 0..40 {
                let wobble = 0.08 * dx * (((7 * i + 13 * j) % 11) as f64 / 11.0 - 0.5);
                let (x, y) = ((i as f64 + 0.5) * dx + wobble, (j as f64 + 0.5) * dx - 0.5 * wobble);
                // A free surface sloping down from the wall x = 0.
                if y < 3.0 - 0.04 * x * x {
                    pos.push(Vector2::new(x, y));
                }
            }
        }
        pos.push(Vector2::new(2.0, 3.6)); // a splash
        let n_fluid = pos.len();
        // Fixed ghosts: four rows under the floor and four columns behind the wall x = 0.
        for k in 0..4 {
            for i in -4..40 {
                pos.push(Vector2::new((i as f64 + 0.5) * dx, -(k as f64 + 0.5) * dx));
            }
            for j in 0..32 {
                pos.push(Vector2::new(-(k as f64 + 0.5) * dx, (j as f64 + 0.5) * dx));
            }
        }
        let n_fixed = pos.len() - n_fluid;
        // Image ghosts behind a wall x = 4 (not in the band's range).
        for j in 0..30 {
            pos.push(Vector2::new(4.05, (j as f64 + 0.5) * dx));
        }
        let mut volume = vec![dx * dx; pos.len()];
        // Some fixed ghosts take no part (no fluid for their fit).
        for v in volume[n_fluid..n_fluid + 20].iter_mut() {
            *v = 0.0;
        }
        // Rising for x < 2, falling beyond; the ghosts hold the mirrored vertical velocity.
        let vel: Vec<Vector2<f64>> = pos
            .iter()
            .enumerate()
            .map(|(k, p)| {
                let v = Vector2::new(0.1 * p.y, (2.0 - p.x).tanh());
                if k < n_fluid {
                    v
                } else {
                    Vector2::new(v.x, -v.y)
                }
            })
            .collect();
        let cells = CellList::build(&pos, kernel.support);
        let ghosts = n_fluid..n_fluid + n_fixed;
        let mut moved = vec![];
        for region in [
            ShiftRegion::NearWalls { ghosts: ghosts.clone() },
            ShiftRegion::WhereTheFlowLeaves {
                ghosts,
                vel: Velocities {
                    fluid: &vel[..n_fluid],
                    ghosts: &vel[n_fluid..],
                },
            },
        ] {
            let step = ShiftStep {
                dx,
                u_max_dt: 0.01 * dx,
                region,
            };
            let fast = displacements(&kernel, &cells, &pos, &volume, n_fluid, step.clone());
            let slow = band_by_gather(&kernel, &cells, &pos, &volume, n_fluid, &step);
            assert_eq!(fast, slow, "{:?}", std::mem::discriminant(&step.region));
            moved.push(fast.iter().filter(|d| **d != Vector2::zeros()).count());
        }
        assert!(
            moved[0] > 50 && moved[0] < n_fluid / 2,
            "the band must move some and not most: {} of {n_fluid}",
            moved[0]
        );
        assert!(
            moved[1] > 10 && moved[1] < moved[0] * 3 / 4,
            "where the flow leaves, fewer: {moved:?}"
        );
    }

    /// Where the flow leaves: water rising off a floor (its ghosts holding the mirrored velocity) is shifted as
    /// the band near the walls shifts it; water falling onto the floor is not shifted at all.
    #[test]
    fn where_the_flow_leaves_a_rising_block_is_the_wall_band_and_a_falling_one_does_not_move() {
        let dx = 0.1;
        let kernel = Kernel::<2>::new(KernelKind::RenormalizedGaussian, 1.33 * dx);
        let (pos, n_fluid) = block_over_a_floor(30, 20, dx);
        let volume = vec![dx * dx; pos.len()];
        let cells = CellList::build(&pos, kernel.support);
        let ghosts = n_fluid..pos.len();
        let shift = |region: ShiftRegion<'_, 2>| {
            let step = ShiftStep {
                dx,
                u_max_dt: 0.01 * dx,
                region,
            };
            displacements(&kernel, &cells, &pos, &volume, n_fluid, step)
        };
        let with = |up: f64| {
            let vel: Vec<_> = (0..pos.len())
                .map(|k| Vector2::new(0.0, if k < n_fluid { up } else { -up }))
                .collect();
            shift(ShiftRegion::WhereTheFlowLeaves {
                ghosts: ghosts.clone(),
                vel: Velocities {
                    fluid: &vel[..n_fluid],
                    ghosts: &vel[n_fluid..],
                },
            })
        };
        let band = shift(ShiftRegion::NearWalls { ghosts: ghosts.clone() });
        assert!(band.iter().any(|d| *d != Vector2::zeros()));
        assert_eq!(with(1.0), band, "rising off the floor");
        assert!(with(-1.0).iter().all(|d| *d == Vector2::zeros()), "falling onto it");
    }
}
