//! The wall pressure sensor (`Simulation::sensor_pressure_at`) against the Shepard average it replaced.
//!
//! Regression: at the dam break's first impact (H/dx 40, t√(g/H) = 2.44) the P1 sensor read 2.3 ρgH, and point
//! sensors 0.1H and 0.2H above the floor 10 and 12 ρgH, while the water there was a tongue 0.03H thin: the Shepard average Σ p W V / Σ W V divides by the weight of whatever few
//! particles reach the sensor's kernel, so a sensor that no water touches reads the pressure of a distant
//! splash. The sensor scales that average by how much of the fluid side of its support water fills, up to
//! a quarter (`SENSOR_WET_FRACTION`): dry, it reads about 0; under water, the Shepard average unchanged.

use bowwave::cases::{self, setup};
use bowwave::sph::{
    body_force::BodyForce,
    boundary::{Boundary, RigidMotion},
    particles::Fluid,
    polyline_wall::{FluidSide, PolylineWall},
    solver::{Simulation, SolverConfig},
};
use nalgebra::Vector2;

type V2 = Vector2<f64>;

#[test]
fn sensor_no_water_touches_reads_air_not_a_distant_splash() {
    let (dx, rho0, c0, g) = (0.01, 1000.0, 20.0, 9.81);
    let mut cfg = SolverConfig::new(dx, rho0, c0, BodyForce::Uniform(V2::new(0.0, -g)));
    cfg.h = 1.33 * dx;
    let support = 3.0 * cfg.h;
    // A 2 x 2 splash compressed to 0.1 % above ρ0 (p = 400 Pa), its lowest row 3dx above a floor.
    let rho = rho0 * 1.001;
    let mut fluid = Fluid::default();
    for (i, j) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
        let x = V2::new((i as f64 - 0.5) * dx, (3.0 + j as f64) * dx);
        fluid.push(x, V2::zeros(), rho, rho0 * dx * dx, 0.0);
    }
    let floor = PolylineWall::new(
        "floor",
        vec![V2::new(-0.2, 0.0), V2::new(0.2, 0.0)],
        FluidSide::Left,
        RigidMotion::Fixed,
        dx,
        support,
    );
    let mut sim = Simulation::new(cfg, fluid, vec![Box::new(floor) as Box<dyn Boundary<2>>]);
    sim.refresh();
    let p_splash = c0 * c0 * (rho - rho0);
    let probe = V2::zeros();
    let shepard = sim.pressure_at(&probe).expect("the splash is within the support");
    let sensor = sim.sensor_pressure_at(&probe);
    // The old reading: the splash's own pressure (plus the mirrored hydrostatic head of its ghosts).
    assert!(shepard > 0.9 * p_splash, "Shepard {shepard} Pa, splash {p_splash} Pa");
    // The sensor: the splash fills a few per cent of the support.
    assert!(
        sensor.abs() < 0.1 * p_splash,
        "sensor {sensor} Pa, splash {p_splash} Pa"
    );
}

#[test]
fn sensor_under_still_water_reads_the_hydrostatic_pressure() {
    let case = cases::load("hydrostatic").expect("built-in case");
    let mut sim = setup::build(&case, Some(20.0)).unwrap();
    sim.refresh();
    let (h, rho_g) = (1.0, 1000.0 * 9.81);
    // Side wall at x = 0 (depths 0.25H to 0.75H), the floor's middle and the bottom corner: the Shepard
    // average unchanged, within 1.5 % of ρ g (H − y).
    for (x, y) in [(0.0, 0.25), (0.0, 0.5), (0.0, 0.75), (1.0, 0.0), (0.0, 0.0)] {
        let x = V2::new(x, y);
        let exact = rho_g * (h - y);
        let sensor = sim.sensor_pressure_at(&x);
        let shepard = sim.pressure_at(&x).unwrap();
        assert_eq!(
            sensor, shepard,
            "at {x:?} under water the sensor is the Shepard average"
        );
        assert!(
            (sensor - exact).abs() < 0.015 * exact,
            "at {x:?}: sensor {sensor} Pa, hydrostatic {exact} Pa"
        );
    }
}
