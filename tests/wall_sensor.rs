//! The wall pressure sensors: the face sensor of the case files (`sph::wall_sensor`: the wall pressure
//! integrated over a face of the size it declares) against the exact hydrostatic pressure, and the kernel
//! reading (`Simulation::sensor_pressure_at`) against the Shepard average it replaced.
//!
//! Regression: at the dam break's first impact (H/dx 40, t√(g/H) = 2.44) the P1 sensor read 2.3 ρgH, and point
//! sensors 0.1H and 0.2H above the floor 10 and 12 ρgH, while the water there was a tongue 0.03H thin: the Shepard average Σ p W V / Σ W V divides by the weight of whatever few
//! particles reach the sensor's kernel, so a sensor that no water touches reads the pressure of a distant
//! splash. The sensor scales that average by how much of the fluid side of its support water fills, up to
//! a quarter (`SENSOR_WET_FRACTION`): dry, it reads about 0; under water, the Shepard average unchanged.

use bowwave::cases::{self, case_file::CaseFile, run, setup};
use bowwave::sph::{
    body_force::BodyForce,
    boundary::{Boundary, RigidMotion},
    particles::Fluid,
    polyline_wall::{FluidSide, PolylineWall},
    solver::{Simulation, SolverConfig},
};
use nalgebra::Vector2;

type V2 = Vector2<f64>;

/// Spacing (m), ρ0 (kg/m³) and c0 (m/s) of the splash scene.
const SPLASH: (f64, f64, f64) = (0.01, 1000.0, 20.0);

/// A 2 × 2 splash compressed to 0.1 % above ρ0 (p = 400 Pa), its lowest row 3 dx above a floor, and its density.
fn splash_over_a_floor() -> (Simulation<2>, f64) {
    let (dx, rho0, c0) = SPLASH;
    let mut cfg = SolverConfig::new(dx, rho0, c0, BodyForce::Uniform(V2::new(0.0, -9.81)));
    cfg.h = 1.33 * dx;
    let support = 3.0 * cfg.h;
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
    (
        Simulation::new(cfg, fluid, vec![Box::new(floor) as Box<dyn Boundary<2>>]),
        rho,
    )
}

#[test]
fn sensor_no_water_touches_reads_air_not_a_distant_splash() {
    let (_, rho0, c0) = SPLASH;
    let (mut sim, rho) = splash_over_a_floor();
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

/// Sensor widths of the hydrostatic test, in particle spacings: the range, 0.5 dx to 20 dx.
const WIDTHS: [f64; 6] = [0.5, 1.0, 2.0, 5.0, 10.0, 20.0];

/// Height of the side sensors' centre (m), in the built-in tank 1 m deep.
const SIDE_Y: f64 = 0.3;

/// The built-in hydrostatic tank (H = 1 m, 2H wide, c0 = 10 √(gH), linear state equation) with face sensors of
/// the given widths (in spacings `dx`): on the right wall centred [`SIDE_Y`] above the floor (`sideW`), and on
/// the floor at x = 0.7 (`floorW`); run to t√(g/H) = 10.
fn tank_with_faces(dx: f64, widths: &[f64]) -> CaseFile {
    let text = cases::builtin::builtin_text("hydrostatic").unwrap();
    let mut text = text[..text.find("[[probes.pressure]]").unwrap()].to_string();
    for w in widths {
        for (name, pos) in [("side", format!("[2.0, {SIDE_Y}]")), ("floor", "[0.7, 0.0]".into())] {
            text += &format!(
                "[[probes.pressure]]\nname = \"{name}{w}\"\nposition = {pos}\nsize = {}\n\n",
                w * dx
            );
        }
    }
    text += "[output]\nend_time = 3.2\nseries_every = 0.32\nvtk_every = 0.0\n";
    CaseFile::parse(&text, "test tank").unwrap()
}

/// The exact static pressure of the tank's water, averaged over the wall face [y0, y1] (Pa): with the linear
/// state equation p = c0² (ρ − ρ0) and dp/dy = −ρ g, p(y) = ρ0 c0² ((1 + μ g/(ρ0 c0²)) e^{−g y/c0²} − 1), μ the
/// mass per unit width. The hydrostatic start ρ = ρ0 (1 + g (H − y)/c0²) holds μ = ρ0 H (1 + g H/(2 c0²)).
fn static_pressure(y0: f64, y1: f64) -> f64 {
    let (rho0, g, h) = (1000.0, 9.81, 1.0);
    let c2 = 100.0 * g * h;
    let mu = rho0 * h * (1.0 + g * h / (2.0 * c2));
    let a = rho0 * c2 * (1.0 + mu * g / (rho0 * c2));
    let k = g / c2;
    if y1 - y0 < 1e-12 {
        return a * (-k * y0).exp() - rho0 * c2;
    }
    a * ((-k * y0).exp() - (-k * y1).exp()) / (k * (y1 - y0)) - rho0 * c2
}

/// Largest relative error of the face sensors of a run at its first row (the hydrostatic start, against
/// ρ0 g (H − y)), the largest settled error per width (the mean pressure over the run's second half,
/// t√(g/H) 5–10, from the impulse every step gathers, against the static solution), and the run. Settled, not
/// the last row: the tank keeps an acoustic oscillation of about ±0.6 % (period 4H/c0 = 0.4 √(H/g), which the
/// rows 1.0 √(H/g) apart alias), and a single row reads its phase, not the sensor's error.
fn face_errors(res: f64, widths: &[f64]) -> (f64, Vec<f64>, run::RunResult) {
    let dx = 1.0 / res;
    let case = tank_with_faces(dx, widths);
    let opts = run::RunOptions {
        res: Some(res),
        ..Default::default()
    };
    let r = run::run(&case, &opts).unwrap();
    assert!(r.blowup.is_none(), "{:?}", r.blowup);
    let t = r.series.column("t").unwrap();
    let (n, half) = (t.len(), t.len() / 2);
    let (mut start, mut settled) = (0.0f64, vec![0.0f64; widths.len()]);
    for (k, w) in widths.iter().enumerate() {
        let size = w * dx;
        for (name, y0, y1) in [("side", SIDE_Y - 0.5 * size, SIDE_Y + 0.5 * size), ("floor", 0.0, 0.0)] {
            let col = r.series.column(&format!("p_{name}{w}")).unwrap();
            let initial = 1000.0 * 9.81 * (1.0 - 0.5 * (y0 + y1));
            start = start.max((col[0] / initial - 1.0).abs());
            let impulse = r.series.column(&format!("pimpulse_{name}{w}")).unwrap();
            let mean = impulse[half + 1..].iter().sum::<f64>() / (t[n - 1] - t[half]);
            settled[k] = settled[k].max((mean / static_pressure(y0, y1) - 1.0).abs());
        }
    }
    (start, settled, r)
}

/// Issue #36: a face sensor of 0.5 to 20 spacings reads the integrated hydrostatic pressure (at H/dx 40 a face
/// of 20 spacings is half the depth; at 20, up to 10 fit). At the hydrostatic start, where the field is exactly
/// ρ0 g (H − y), within 0.05 % (measured: 0.024 % and 0.012 %); settled (the mean over t√(g/H) 5–10) within
/// 0.25 % of the static solution (measured 0.18 % and 0.10 %; with particle shifting 0.12 % and 0.15 %), and closer
/// at H/dx 40 than at 20 on the same widths. Regression: the settled reading was the last row's, within 0.5 %,
/// which read the phase of the tank's acoustic oscillation (±0.6 %): with shifting 0.55 % and 0.57 %, not
/// closer at 40 than at 20 (session 44).
#[test]
fn face_sensors_half_to_twenty_spacings_wide_read_the_integrated_hydrostatic_pressure() {
    let largest = |e: &[f64]| e.iter().cloned().fold(0.0, f64::max);
    let (start20, settled20, _) = face_errors(20.0, &WIDTHS[..5]);
    let (start40, settled40, r) = face_errors(40.0, &WIDTHS);
    let (settled20, settled40_same, settled40) = (largest(&settled20), largest(&settled40[..5]), largest(&settled40));
    eprintln!("face sensors, largest error: start {start20:.2e} (H/dx 20), {start40:.2e} (40); settled {settled20:.2e}, {settled40:.2e} ({settled40_same:.2e} on H/dx 20's widths)");
    assert!(
        start20 < 5e-4 && start40 < 5e-4,
        "at the start: {start20:.2e}, {start40:.2e}"
    );
    assert!(
        settled20 < 2.5e-3 && settled40 < 2.5e-3,
        "settled: {settled20:.2e}, {settled40:.2e}"
    );
    assert!(
        settled40_same < settled20,
        "converges: {settled20:.2e} then {settled40_same:.2e}"
    );
    // Peak and impulse between outputs, from every step: the peak is at least the readings at both ends of its
    // interval and the interval's mean pressure (impulse / length); over the whole run the mean pressure is the
    // static one, within the 0.5 % the readings oscillate by while the tank settles.
    let t = r.series.column("t").unwrap();
    let p = r.series.column("p_side5").unwrap();
    let peak = r.series.column("ppeak_side5").unwrap();
    let impulse = r.series.column("pimpulse_side5").unwrap();
    assert_eq!(impulse[0], 0.0);
    for k in 1..t.len() {
        let mean = impulse[k] / (t[k] - t[k - 1]);
        assert!(
            peak[k] >= p[k].max(p[k - 1]).max(mean),
            "row {k}: peak {} below a reading or the mean {mean}",
            peak[k]
        );
    }
    let mean = impulse.iter().sum::<f64>() / t[t.len() - 1];
    let exact = static_pressure(SIDE_Y - 2.5 / 40.0, SIDE_Y + 2.5 / 40.0);
    assert!(
        (mean / exact - 1.0).abs() < 5e-3,
        "mean over the run {mean} Pa, static {exact} Pa"
    );
}

/// A face sensor under a splash that does not touch the wall reads about nothing (as the kernel sensor above).
#[test]
fn face_sensor_no_water_touches_reads_air() {
    let (dx, rho0, c0) = SPLASH;
    let (mut sim, rho) = splash_over_a_floor();
    let face = bowwave::sph::wall_sensor::WallSensor::face(
        V2::zeros(),
        V2::new(1.0, 0.0),
        2.0 * dx,
        V2::new(0.0, 1.0),
        None,
        dx,
    );
    sim.set_sensors(vec![face]);
    sim.refresh();
    let p_splash = c0 * c0 * (rho - rho0);
    let reading = sim.read_sensors()[0];
    assert!(
        reading.abs() < 0.1 * p_splash,
        "reading {reading} Pa, splash {p_splash} Pa"
    );
}
