//! Time step, eq. (4.22): Δt = CFL min_i h / (c_i + |u_i| + h max_j |π_ij|), and Monaghan's body-force
//! limit Δt ≤ 0.25 √(h/|a_i|) (rarely active; guards against a violent acceleration at coarse c0).

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
