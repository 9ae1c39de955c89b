//! Time step, eq. (4.22): Δt = CFL min_i h / (c_i + |u_i| + h max_j |π_ij|), and Monaghan's body-force
//! limit Δt ≤ 0.25 √(h/|a_i|) (rarely active; guards against a violent acceleration at coarse c0). With a
//! physical viscosity, the explicit diffusion limit Δt ≤ 0.125 h²/ν as well (Morris, Fox & Zhu 1997): eq. (4.22)
//! bounds the artificial viscosity through π_ij, not a ν given in m²/s.

/// Per-particle denominator of eq. (4.22) (m/s).
#[inline]
pub fn signal_speed(c_i: f64, speed_i: f64, h: f64, max_pi: f64) -> f64 {
    c_i + speed_i + h * max_pi
}

/// Δt from the largest signal speed and the largest acceleration.
pub fn time_step(cfl: f64, h: f64, max_signal: f64, max_accel: f64) -> f64 {
    let acoustic = cfl * h / max_signal;
    let force = if max_accel > 0.0 {
        0.25 * (h / max_accel).sqrt()
    } else {
        f64::INFINITY
    };
    acoustic.min(force)
}

/// The diffusion limit of a physical kinematic viscosity ν (m²/s): 0.125 h²/ν (s), Morris, Fox & Zhu (1997).
/// Binding only at low cell Reynolds numbers c0 h/ν (below about 16 at CFL 2): the `stokes-wall` case at
/// depth/dx 40, not the dam break at Re 1e4 nor Rayleigh–Taylor.
pub fn viscous_limit(h: f64, nu: f64) -> f64 {
    if nu > 0.0 {
        0.125 * h * h / nu
    } else {
        f64::INFINITY
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The diffusion limit takes over from the acoustic one of eq. (4.22) at CFL 2 exactly when the cell
    /// Reynolds number c0 h/ν falls below CFL/0.125 = 16; an inviscid or artificially viscous run has none.
    #[test]
    fn viscous_limit_binds_below_a_cell_reynolds_number_of_sixteen() {
        let (h, c0, cfl) = (0.02, 10.0, 2.0);
        let acoustic = time_step(cfl, h, c0, 0.0);
        let nu_at = |re: f64| c0 * h / re;
        assert!(viscous_limit(h, nu_at(15.9)) < acoustic);
        assert!(viscous_limit(h, nu_at(16.1)) > acoustic);
        assert_eq!(viscous_limit(h, 0.0), f64::INFINITY);
    }
}
