//! Wall pressure sensors as faces of the size they declare, read at every time step.
//!
//! **The wall pressure at a wall point x_w** with unit normal n into the fluid is the value the fixed-ghost
//! method itself implies there (thesis §7.1.1): the first-order MLS fit of the fluid's pressure (eq. 7.6, fluid
//! particles only) at the mirror point x_I = x_w + ½ dx n of a first-layer ghost, carried to the wall by the
//! Neumann condition (7.4): p_w = p_I + ρ_I (g − a_B)·(x_w − x_I). A first-order fit reproduces a linear field
//! exactly, so the reading is a point value to second order in the spacing, not a kernel-wide average; the fit
//! falls back to the Shepard average where it would extrapolate ([`super::mls`]).
//!
//! **A sensor** is a face of width `size` on a wall: its reading is the face-average of p_w, (1/size) ∫ p_w ds,
//! by the midpoint rule over [`SAMPLES_PER_SPACING`] points per spacing (one point for a face of zero size).
//! Each point's value is multiplied by its wetness min(1, f / [`super::solver::SENSOR_WET_FRACTION`]), f the
//! part of the fluid side of the support that water fills (as for [`Simulation::sensor_pressure_at`]), so a
//! dry face reads 0 instead of a distant splash's pressure.
//!
//! **Between outputs** the solver reads every sensor at the start of every time step (the state the step's
//! first stage has just prepared, at no extra neighbour search) and keeps, per sensor, the peak and the
//! impulse ∫ p dt (trapezoidal rule over the steps) since the last call of [`Simulation::take_sensor_record`].

use super::mls::mls_weights;
use super::solver::Simulation;
use nalgebra::{SMatrix, SVector};
use std::sync::Arc;

/// Sample points per particle spacing along a sensor face: 4, so that the midpoint rule's error on the
/// smooth MLS field stays far below the field's own (a face of 0.5 dx gets 2 points, one of 20 dx 80).
pub const SAMPLES_PER_SPACING: f64 = 4.0;

/// A pressure sensor: a face on a wall, read as the mean wall pressure over it.
#[derive(Clone, Debug)]
pub struct WallSensor<const D: usize> {
    /// Sample points on the wall at t = 0 (m): the midpoints of equal parts of the face.
    pub points: Vec<SVector<f64, D>>,
    /// Unit normal of the wall pointing into the fluid.
    pub inward: SVector<f64, D>,
    /// How the wall carries the sensor: at time t a point p is at R p + b and the normal is R n, with
    /// (R, b) = `frame(t)`; `None` for a still wall.
    pub frame: Option<SensorFrame<D>>,
}

/// The rigid map (R, b) of a moving wall at time t: a point p of it is at R p + b.
pub type RigidMap<const D: usize> = dyn Fn(f64) -> (SMatrix<f64, D, D>, SVector<f64, D>) + Send + Sync;

/// The rigid map of a moving wall at each time (see [`WallSensor::frame`]).
#[derive(Clone)]
pub struct SensorFrame<const D: usize>(pub Arc<RigidMap<D>>);

impl<const D: usize> std::fmt::Debug for SensorFrame<D> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "SensorFrame")
    }
}

impl<const D: usize> WallSensor<D> {
    /// The face centred at `centre` along the unit `tangent`, `size` wide (m; 0 for a point sensor), on a
    /// wall of inward normal `inward`, for particle spacing `dx` (m); the wall carries it by `frame`.
    pub fn face(
        centre: SVector<f64, D>,
        tangent: SVector<f64, D>,
        size: f64,
        inward: SVector<f64, D>,
        frame: Option<SensorFrame<D>>,
        dx: f64,
    ) -> Self {
        let n = ((size / dx * SAMPLES_PER_SPACING).ceil() as usize).max(1);
        let points = (0..n)
            .map(|k| centre + tangent * (size * ((k as f64 + 0.5) / n as f64 - 0.5)))
            .collect();
        WallSensor { points, inward, frame }
    }
}

/// Peak and impulse of every sensor since the record was last taken.
#[derive(Clone, Debug, Default)]
pub struct SensorRecord {
    /// Largest reading (Pa).
    pub peak: Vec<f64>,
    /// ∫ p dt (Pa s), trapezoidal over the readings.
    pub impulse: Vec<f64>,
    /// Time and readings of the last reading (s, Pa).
    last: Option<(f64, Vec<f64>)>,
}

impl SensorRecord {
    /// Adds the readings `p` at time `t`.
    pub fn add(&mut self, t: f64, p: &[f64]) {
        match &self.last {
            None => {
                self.peak = p.to_vec();
                self.impulse = vec![0.0; p.len()];
            }
            Some((t0, p0)) => {
                let dt = t - t0;
                for k in 0..p.len() {
                    self.peak[k] = self.peak[k].max(p[k]);
                    self.impulse[k] += 0.5 * (p0[k] + p[k]) * dt;
                }
            }
        }
        self.last = Some((t, p.to_vec()));
    }

    /// (peak, impulse) since the last take, then starts a new interval at the last reading.
    pub fn take(&mut self) -> (Vec<f64>, Vec<f64>) {
        let out = (self.peak.clone(), self.impulse.clone());
        if let Some((_, p)) = &self.last {
            self.peak = p.clone();
            self.impulse = vec![0.0; p.len()];
        }
        out
    }
}

impl<const D: usize> Simulation<D> {
    /// Wall pressure (Pa) at the wall point `x_w` with unit normal `inward` into the fluid (module doc), from
    /// the state the solver last prepared ([`Simulation::refresh`], or a step's first stage). 0 where no fluid
    /// particle is within the kernel support of the mirror point.
    pub fn wall_pressure(&self, x_w: &SVector<f64, D>, inward: &SVector<f64, D>) -> f64 {
        let x_i = x_w + inward * (0.5 * self.cfg.dx);
        let mut nb = Vec::with_capacity(64);
        self.for_each_fluid_within(&x_i, |j, rij, r, volume| nb.push((j, rij, self.kernel.w(r) * volume)));
        if nb.is_empty() {
            return 0.0;
        }
        let fit = mls_weights(self.kernel.h, &nb);
        let p_i = fit.interpolate(|j| self.pressure()[j]);
        let rho_i = fit.interpolate(|j| self.fluid.rho[j]);
        let a = self.cfg.body_force.acceleration(x_w);
        super::equations::ghost_conditions::neumann_pressure(p_i, rho_i, &a, &SVector::zeros(), &(x_w - x_i))
    }

    /// The reading of `sensor` (Pa): the mean of its points' wall pressures times their wetness (module doc).
    pub fn sensor_reading(&self, sensor: &WallSensor<D>) -> f64 {
        let (r, b) = match &sensor.frame {
            Some(f) => (f.0)(self.time),
            None => (SMatrix::identity(), SVector::zeros()),
        };
        let inward = r * sensor.inward;
        let sum: f64 = sensor
            .points
            .iter()
            .map(|p| {
                let x = r * p + b;
                self.wall_pressure(&x, &inward) * self.wetness(&x)
            })
            .sum();
        sum / sensor.points.len() as f64
    }

    /// Readings of every sensor of the run ([`Simulation::set_sensors`]) at the prepared state.
    pub fn sensor_readings(&self) -> Vec<f64> {
        self.sensors.iter().map(|s| self.sensor_reading(s)).collect()
    }

    /// The sensors read at every step and at every [`Simulation::read_sensors`].
    pub fn set_sensors(&mut self, sensors: Vec<WallSensor<D>>) {
        self.sensors = sensors;
        self.sensor_record = SensorRecord::default();
    }

    /// Reads every sensor at the prepared state and adds the readings to the record; returns them.
    pub fn read_sensors(&mut self) -> Vec<f64> {
        let p = self.sensor_readings();
        self.sensor_record.add(self.time, &p);
        p
    }

    /// Peak and impulse of each sensor since the last take (see [`SensorRecord::take`]).
    pub fn take_sensor_record(&mut self) -> (Vec<f64>, Vec<f64>) {
        self.sensor_record.take()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_face_is_sampled_at_midpoints_four_per_spacing() {
        let s = WallSensor::<2>::face(
            SVector::from([1.0, 0.5]),
            SVector::from([0.0, 1.0]),
            0.1,
            SVector::from([-1.0, 0.0]),
            None,
            0.01,
        );
        assert_eq!(s.points.len(), 40);
        assert!((s.points[0][1] - (0.45 + 0.00125)).abs() < 1e-12);
        let mean: f64 = s.points.iter().map(|p| p[1]).sum::<f64>() / 40.0;
        assert!((mean - 0.5).abs() < 1e-12);
        let point = WallSensor::<2>::face(
            SVector::from([1.0, 0.5]),
            SVector::from([0.0, 1.0]),
            0.0,
            SVector::from([-1.0, 0.0]),
            None,
            0.01,
        );
        assert_eq!(point.points, vec![SVector::from([1.0, 0.5])]);
    }

    #[test]
    fn the_record_holds_the_peak_and_the_trapezoidal_impulse_between_takes() {
        let mut r = SensorRecord::default();
        r.add(0.0, &[1.0]);
        r.add(0.1, &[5.0]);
        r.add(0.3, &[2.0]);
        let (peak, imp) = r.take();
        assert_eq!(peak, vec![5.0]);
        assert!((imp[0] - (0.5 * 6.0 * 0.1 + 0.5 * 7.0 * 0.2)).abs() < 1e-12);
        // The next interval starts at the last reading.
        r.add(0.4, &[0.0]);
        let (peak, imp) = r.take();
        assert_eq!(peak, vec![2.0]);
        assert!((imp[0] - 0.1).abs() < 1e-12);
    }
}
