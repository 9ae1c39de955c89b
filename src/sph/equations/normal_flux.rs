//! The boundary terms of the normal-flux wall (thesis §7.1.2, after De Leffe et al. 2009): where the kernel
//! support of particle i is cut by a solid surface, the divergence and gradient operators gain a surface
//! integral over the cut, discretised on the wall's nodes k of area S_k (eq. 7.14):
//!
//! ⟨∇·u⟩_i ⊃ Σ_k (u_k − u_i)·n_k W_ik S_k,   ⟨∇p⟩_i ⊃ Σ_k (p_k + p_i) n_k W_ik S_k,
//!
//! n_k the unit normal out of the fluid (into the solid), u_k the wall's velocity. The wall pressure p_k comes
//! from a Taylor expansion about the particle (7.15–7.16) whose tangential derivatives are hydrostatic (7.17) and
//! whose normal derivative is the momentum equation projected on n_k (7.18), with the particle's normal
//! acceleration that of an acoustic signal reflected by the wall (7.19), giving eq. (7.20). The thesis prints
//! (7.20) per unit density, for a still wall; here ρ_i multiplies it (pressure in Pa) and the particle's velocity
//! is taken relative to the wall's, whose acceleration enters (7.18) as the fixed ghosts' Neumann condition
//! (7.4) does:
//!
//! p_k = p_i + ρ_i c0 (u_i − u_k)·n_k + ρ_i g·(r_k − r_i) − ρ_i (a_k·n_k) (r_k − r_i)·n_k.
//!
//! The δ-term and the viscous term have no boundary part (free slip; the thesis's formulation cannot hold a
//! no-slip wall). Notation as in the module [`super`]: r_ik = r_i − r_k.

use nalgebra::SVector;

/// A wall node's values in the pair (i, k).
#[derive(Clone, Copy, Debug)]
pub struct WallNode<const D: usize> {
    /// Unit normal out of the fluid, into the solid (n_k of eq. 7.14).
    pub outward: SVector<f64, D>,
    /// The wall's velocity at the node (m/s).
    pub vel: SVector<f64, D>,
    /// The wall's acceleration at the node (m/s²).
    pub acc: SVector<f64, D>,
}

/// The wall pressure p_k of eq. (7.20) (Pa), for the particle i of pressure `p_i`, density `rho_i`, velocity
/// `u_i`, at `r_ik` = r_i − r_k from the node; `g` the body force per unit mass at the particle, `c0` the
/// sound speed (m/s).
#[inline]
pub fn wall_pressure<const D: usize>(
    p_i: f64,
    rho_i: f64,
    u_i: &SVector<f64, D>,
    r_ik: &SVector<f64, D>,
    node: &WallNode<D>,
    g: &SVector<f64, D>,
    c0: f64,
) -> f64 {
    let r_ki = -r_ik;
    let n = &node.outward;
    p_i + rho_i * (c0 * (u_i - node.vel).dot(n) + g.dot(&r_ki) - node.acc.dot(n) * r_ki.dot(n))
}

/// Node k's share of particle i's dρ/dt: −ρ_i (u_k − u_i)·n_k W_ik S_k (kg/m³/s), `w_s` = W_ik S_k.
#[inline]
pub fn continuity_term<const D: usize>(rho_i: f64, u_i: &SVector<f64, D>, node: &WallNode<D>, w_s: f64) -> f64 {
    -rho_i * (node.vel - u_i).dot(&node.outward) * w_s
}

/// Node k's share of particle i's du/dt: −(p_k + p_i)/ρ_i n_k W_ik S_k (m/s²), `w_s` = W_ik S_k.
#[inline]
pub fn pressure_term<const D: usize>(p_i: f64, p_k: f64, rho_i: f64, node: &WallNode<D>, w_s: f64) -> SVector<f64, D> {
    node.outward * (-(p_k + p_i) * w_s / rho_i)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    fn floor() -> WallNode<2> {
        WallNode {
            outward: Vector2::new(0.0, -1.0),
            vel: Vector2::zeros(),
            acc: Vector2::zeros(),
        }
    }

    /// In still water over a still floor the node's pressure is the hydrostatic one at the node's depth, and
    /// the pressure term pushes the particle up, away from the wall.
    #[test]
    fn still_water_over_a_floor_reads_the_hydrostatic_pressure_and_is_pushed_up() {
        let (rho, g) = (1000.0, Vector2::new(0.0, -9.81));
        let p_i = 5000.0;
        let r_ik = Vector2::new(0.01, 0.02); // the particle 2 cm above the node
        let p_k = wall_pressure(p_i, rho, &Vector2::zeros(), &r_ik, &floor(), &g, 20.0);
        assert!((p_k - (p_i + rho * 9.81 * 0.02)).abs() < 1e-9);
        let a = pressure_term(p_i, p_k, rho, &floor(), 0.5);
        assert!(a.y > 0.0 && a.x == 0.0);
    }

    /// A particle moving into the wall raises the node's pressure by ρ c0 times its normal speed (the acoustic
    /// impedance of 7.19), and moving away lowers it; a wall moving with the particle changes nothing; the
    /// continuity term compresses a particle that approaches the wall.
    #[test]
    fn approach_to_the_wall_raises_its_pressure_by_the_acoustic_impedance() {
        let (rho, c0, g) = (1000.0, 20.0, Vector2::zeros());
        let r_ik = Vector2::new(0.0, 0.02);
        let down = Vector2::new(0.0, -0.1);
        let p_k = wall_pressure(0.0, rho, &down, &r_ik, &floor(), &g, c0);
        assert!((p_k - rho * c0 * 0.1).abs() < 1e-9);
        let up = wall_pressure(0.0, rho, &-down, &r_ik, &floor(), &g, c0);
        assert!((up + rho * c0 * 0.1).abs() < 1e-9);
        let moving = WallNode { vel: down, ..floor() };
        assert_eq!(wall_pressure(0.0, rho, &down, &r_ik, &moving, &g, c0), 0.0);
        assert!(continuity_term(rho, &down, &floor(), 0.5) > 0.0);
    }

    /// A wall accelerating into the fluid raises the pressure in proportion to the distance along the normal,
    /// as the fixed ghosts' Neumann condition (7.4) does.
    #[test]
    fn accelerating_wall_adds_its_normal_acceleration_times_the_distance() {
        let node = WallNode {
            acc: Vector2::new(0.0, 3.0),
            ..floor()
        };
        let r_ik = Vector2::new(0.0, 0.02);
        let p_k = wall_pressure(0.0, 1000.0, &Vector2::zeros(), &r_ik, &node, &Vector2::zeros(), 20.0);
        assert!((p_k - 1000.0 * 3.0 * 0.02).abs() < 1e-9);
    }
}
