//! The solver in three dimensions (the engine is generic over D): a still tank holds its water at rest, its
//! walls carrying the weight, and a 3D dam break gives the same bits on 1 and 2 threads. Walls are
//! [`bowwave::sph::box_wall::BoxWall`], whose edges use the 3D-only mirror through two faces.

use bowwave::cases::box_tank::BoxTank;
use bowwave::sph::diagnostics::energies;
use nalgebra::Vector3;

const G: f64 = 9.81;
const RHO0: f64 = 1000.0;

/// A tank `long` H long and `wide` H wide (free-slip side walls), H = 1 m the water's depth, the water
/// `water_long` H long.
fn tank(res: f64, long: f64, wide: f64, water_long: f64, c0_over_sqrt_gh: f64) -> BoxTank<3> {
    BoxTank {
        tank: Vector3::new(long, wide, 1.2),
        water: Vector3::new(water_long, wide, 1.0),
        dx: 1.0 / res,
        rho0: RHO0,
        c0: c0_over_sqrt_gh * G.sqrt(),
        g: G,
    }
}

/// Hydrostatic tank in 3D, H/dx = 10, 1 H long and 0.5 H wide, to t√(g/H) = 20 (the 2D check runs H/dx = 20
/// to 50; in 3D each particle has about 5 times the neighbours and the walls 6 times the fluid in ghosts, so the
/// coarse level is coarser). Asserted: E_K/(MgH) < 1e-5 at the end (the 2D check's bound), and the force of
/// the water on the tank, eqs. (7.12)–(7.13) summed over the ghosts and averaged over t* = 15–20 (past the
/// acoustic oscillations), equal to its weight within 1 % (a fluid at rest is held by its walls alone). The bottom pressure and the interior
/// pressure gradient are printed, not asserted: in 3D the water's pressure creeps up while it stays at rest
/// (bottom sensor 1.008 ρgH at t* = 5, 1.040 at 20, interior gradient 3 % above ρ0 g; 2D at the same spacing
/// holds 1.01–1.016), an open defect written up in docs/method.md ("3D").
#[test]
fn three_dimensional_tank_is_held_at_rest_by_its_walls() {
    let res = 10.0;
    let t = tank(res, 1.0, 0.5, 1.0, 10.0);
    let mut sim = t.build(t.config()).unwrap();
    let ts = (1.0 / G).sqrt();
    let m = sim.fluid.total_mass();
    // The wall force averaged over t* = 15–20, every 5 steps (about 0.13 t*, 40 samples).
    let (mut force, mut samples) = (Vector3::zeros(), 0.0);
    while sim.time < 20.0 * ts {
        sim.step().unwrap();
        if sim.time > 15.0 * ts && sim.steps.is_multiple_of(5) {
            sim.refresh();
            force += sim.boundary_forces()[0];
            samples += 1.0;
        }
    }
    force /= samples;
    sim.refresh();
    let ek = energies(&sim.fluid, &sim.cfg.eos, &sim.cfg.body_force).kinetic / (m * G);
    let weight_ratio = -force.z / (m * G);
    let layer_mean = |z0: f64, z1: f64| {
        let (mut s, mut z, mut n) = (0.0, 0.0, 0.0);
        for (i, x) in sim.fluid.pos.iter().enumerate() {
            if x.z >= z0 && x.z < z1 {
                s += sim.pressure()[i];
                z += x.z;
                n += 1.0;
            }
        }
        (s / n, z / n)
    };
    let (p_low, z_low) = layer_mean(0.2, 0.3);
    let (p_high, z_high) = layer_mean(0.7, 0.8);
    let gradient = (p_low - p_high) / (z_high - z_low) / (RHO0 * G);
    let bottom = sim.sensor_pressure_at(&Vector3::new(0.5, 0.25, 0.0)) / (RHO0 * G);
    println!(
        "3D tank, H/dx 10, t* 20: E_K/(MgH) {ek:.3e}, wall force/(Mg) {weight_ratio:.5} (horizontal {:.2e}, {:.2e}), \
         interior gradient/(ρ0 g) {gradient:.4}, bottom p/(ρgH) {bottom:.4}",
        force.x / (m * G),
        force.y / (m * G)
    );
    assert!(ek < 1e-5, "kinetic energy {ek:e} MgH");
    assert!(
        (weight_ratio - 1.0).abs() < 0.01,
        "wall force {weight_ratio} of the weight"
    );
}

/// The bits of every particle after 30 steps of a 3D dam break (H/dx = 10, a slab 0.3 H wide), on `n` threads.
fn dam_break_bits(n: usize) -> Vec<u64> {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(n).build().unwrap();
    pool.install(|| {
        let t = tank(10.0, 3.0, 0.3, 2.0, 20.0);
        let mut sim = t.build(t.config()).unwrap();
        for _ in 0..30 {
            sim.step().unwrap();
        }
        let f = &sim.fluid;
        let mut order: Vec<usize> = (0..f.len()).collect();
        order.sort_by_key(|&i| f.id[i]);
        order
            .iter()
            .flat_map(|&i| {
                let (x, u) = (f.pos[i], f.vel[i]);
                [x.x, x.y, x.z, u.x, u.y, u.z, f.rho[i]].map(f64::to_bits)
            })
            .collect()
    })
}

#[test]
fn three_dimensional_dam_break_gives_identical_bits_on_one_and_two_threads() {
    let (a, b) = (dam_break_bits(1), dam_break_bits(2));
    assert_eq!(a.len(), 7 * 20 * 3 * 10);
    assert!(a == b, "3D particle state differs between 1 and 2 threads");
}
