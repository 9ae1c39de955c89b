//! Boundary conditions imposed on a fixed ghost particle G from the values interpolated at its mirror point I
//! (thesis §7.1.1). With n = (r_G − r_I)/|r_G − r_I| (the outward wall normal on a straight side; the
//! central-symmetry direction at a corner):
//! * free slip, eqs. (7.1)–(7.2): the normal velocity relative to the wall is reversed, the tangential kept:
//!   u_G = u_I − 2 [(u_I − u_B)·n] n, so that ½(u_G + u_I)·n = u_B·n;
//! * at a corner (central symmetry, Fig. 7.3) free slip on both sides leaves only the wall's velocity:
//!   u_G = 2 u_B − u_I;
//! * on an edge of an axis-aligned 3D box, free slip on both faces: the velocity relative to the wall reversed
//!   along the two axes the ghost is beyond, kept along the edge;
//! * no slip (§7.1.3, an option, [`WallSlip::NoSlip`]): in the viscous term only, the velocity relative to the
//!   wall reversed whole, u_G = 2 u_B − u_I, so that ½(u_G + u_I) = u_B (the anti-symmetric mirroring of Takeda
//!   et al. 1994 that the thesis uses in §8.2 and §9.3); the continuity equation keeps the free-slip velocity,
//!   since reversing the tangential component there spoils the velocity divergence near the wall (§7.1.3);
//! * pressure, Neumann condition (7.4)–(7.5) for a wall in translation (dn/dt = 0):
//!   p_G = p_I + ρ_I (g − a_B)·(r_G − r_I), which for a still wall is (7.5), p_G = p_I + 2d ρ g·n.

use nalgebra::SVector;
use serde::{Deserialize, Serialize};

/// What the walls impose on the tangential velocity.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum WallSlip {
    /// Free slip (7.2): the thesis's condition for inviscid impact flows (§9: the boundary layer has a limited
    /// influence at these Reynolds numbers). The default.
    #[default]
    FreeSlip,
    /// No slip in the viscous term ([`no_slip_velocity`]), free slip in the continuity equation (§7.1.3). Meant
    /// with a physical viscosity (`Viscosity::Physical`): with the artificial one, whose ν = α h c0 / 8 is
    /// thousands of times water's at laboratory scale, the boundary layer it makes is that thick.
    NoSlip,
}

impl std::str::FromStr for WallSlip {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "free-slip" => Ok(Self::FreeSlip),
            "no-slip" => Ok(Self::NoSlip),
            v => Err(format!("expected `free-slip` or `no-slip`, got `{v}`")),
        }
    }
}

impl std::fmt::Display for WallSlip {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::FreeSlip => "free-slip",
            Self::NoSlip => "no-slip",
        })
    }
}

/// Ghost velocity of the viscous term under no slip (§7.1.3): the velocity relative to the wall reversed,
/// u_G = 2 u_B − u_I, whatever the side or corner the ghost mirrors.
#[inline]
pub fn no_slip_velocity<const D: usize>(u_i: &SVector<f64, D>, u_wall: &SVector<f64, D>) -> SVector<f64, D> {
    u_wall * 2.0 - u_i
}

/// Free-slip ghost velocity.
#[inline]
pub fn free_slip_velocity<const D: usize>(
    u_i: &SVector<f64, D>,
    u_wall: &SVector<f64, D>,
    n: &SVector<f64, D>,
) -> SVector<f64, D> {
    u_i - n * (2.0 * (u_i - u_wall).dot(n))
}

/// Corner ghost velocity (central symmetry through the vertex).
#[inline]
pub fn point_mirror_velocity<const D: usize>(u_i: &SVector<f64, D>, u_wall: &SVector<f64, D>) -> SVector<f64, D> {
    u_wall * 2.0 - u_i
}

/// Edge ghost velocity of an axis-aligned box (3D): free slip on the two faces that meet there reverses the
/// velocity relative to the wall along the axes in `mask` and keeps it along the edge.
#[inline]
pub fn axes_mirror_velocity<const D: usize>(
    u_i: &SVector<f64, D>,
    u_wall: &SVector<f64, D>,
    mask: u8,
) -> SVector<f64, D> {
    SVector::from_fn(|k, _| {
        if mask & (1 << k) != 0 {
            2.0 * u_wall[k] - u_i[k]
        } else {
            u_i[k]
        }
    })
}

/// Ghost pressure by the Neumann condition; `body` is the body-force acceleration at the wall.
#[inline]
pub fn neumann_pressure<const D: usize>(
    p_i: f64,
    rho_i: f64,
    body: &SVector<f64, D>,
    wall_acc: &SVector<f64, D>,
    r_gi: &SVector<f64, D>,
) -> f64 {
    p_i + rho_i * (body - wall_acc).dot(r_gi)
}

/// A ghost's density gradient (the δ-SPH diffusion term reads it): the tangential part of `grad_i`, the gradient
/// at the mirror point, and the normal part `dn` the Neumann condition gives, dρ/dn = (dρ/dp) ρ (g − a_B)·n, the
/// derivative of (7.4) along n.
#[inline]
pub fn neumann_density_gradient<const D: usize>(
    grad_i: &SVector<f64, D>,
    n: &SVector<f64, D>,
    dn: f64,
) -> SVector<f64, D> {
    tangential_part(grad_i, n) + n * dn
}

/// The part of `v` along the wall, normal to the unit `n`: what a ghost keeps of its mirror point's density
/// gradient ([`neumann_density_gradient`]).
#[inline]
pub fn tangential_part<const D: usize>(v: &SVector<f64, D>, n: &SVector<f64, D>) -> SVector<f64, D> {
    v - n * v.dot(n)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    /// Free slip keeps the tangential velocity and makes the pair's mean normal velocity the wall's; no slip makes
    /// the pair's whole mean velocity the wall's (the wall velocity is where the fluid meets it, §7.1.3).
    #[test]
    fn ghost_and_mirror_point_average_to_the_wall_velocity_as_each_condition_says() {
        let (u_i, u_b) = (Vector2::new(0.7, -0.3), Vector2::new(0.2, 0.1));
        let n = Vector2::new(0.6, 0.8);
        let t = Vector2::new(-0.8, 0.6);
        let free = free_slip_velocity(&u_i, &u_b, &n);
        assert!(((free + u_i) * 0.5 - u_b).dot(&n).abs() < 1e-15);
        assert!((free - u_i).dot(&t).abs() < 1e-15);
        let no_slip = no_slip_velocity(&u_i, &u_b);
        assert!(((no_slip + u_i) * 0.5 - u_b).norm() < 1e-15);
        // Both conditions give the same normal velocity: the continuity equation sees no difference.
        assert!((no_slip - free).dot(&n).abs() < 1e-15);
    }
}
