//! Boundary conditions imposed on a fixed ghost particle G from the values interpolated at its mirror point I
//! (thesis §7.1.1). With n = (r_G − r_I)/|r_G − r_I| (the outward wall normal on a straight side; the
//! central-symmetry direction at a corner):
//! * free slip, eqs. (7.1)–(7.2): the normal velocity relative to the wall is reversed, the tangential kept:
//!   u_G = u_I − 2 [(u_I − u_B)·n] n, so that ½(u_G + u_I)·n = u_B·n;
//! * at a corner (central symmetry, Fig. 7.3) free slip on both sides leaves only the wall's velocity:
//!   u_G = 2 u_B − u_I;
//! * on an edge of an axis-aligned 3D box, free slip on both faces: the velocity relative to the wall reversed
//!   along the two axes the ghost is beyond, kept along the edge;
//! * pressure, Neumann condition (7.4)–(7.5) for a wall in translation (dn/dt = 0):
//!   p_G = p_I + ρ_I (g − a_B)·(r_G − r_I), which for a still wall is (7.5), p_G = p_I + 2d ρ g·n.

use nalgebra::SVector;

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
