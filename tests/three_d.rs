//! The solver in three dimensions (the engine is generic over D): a still tank holds its water at rest, its
//! walls carrying the weight (with image faces, at the hydrostatic pressure), and a 3D dam break gives the
//! same bits on 1 and 2 threads. Walls are
//! [`bowwave::sph::box_wall::BoxWall`], whose edges use the 3D-only mirror through two faces.

use bowwave::cases::box_tank::BoxTank;
use bowwave::sph::polyline_wall::GhostKind;
use bowwave::validation::tank_3d;
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

/// The still tank of `bowwave validate tank-3d` at the CI level, H/dx = 10 (1 × 0.5 H, to t√(g/H) = 20; the 2D
/// check runs H/dx = 20 to 50; in 3D each particle has about 5 times the neighbours and the walls 6 times the
/// fluid in ghosts, so the coarse level is coarser), its faces made of `ghosts`; prints every check.
fn tank_checks(ghosts: GhostKind) -> Vec<bowwave::validation::Check> {
    let r = tank_3d::tank_at_rest(10.0, ghosts, false)
        .unwrap()
        .unwrap_or_else(|b| panic!("the still tank blew up: {b}"));
    let checks = r.checks();
    bowwave::validation::print_checks(&checks);
    checks
}

/// Asserts the named checks (the quantity starts with one of `names`) and that every one of them was found.
fn assert_checks(checks: &[bowwave::validation::Check], names: &[&str]) {
    for name in names {
        let c = checks
            .iter()
            .find(|c| c.quantity.starts_with(name))
            .unwrap_or_else(|| panic!("no check `{name}`"));
        assert!(
            c.pass(),
            "{}: {} {} against {} ± {:?}",
            c.case,
            c.quantity,
            c.value,
            c.reference,
            c.tolerance
        );
    }
}

/// The thesis's fixed ghosts: the water stays at rest, E_K/(MgH) < 1e-5 at the end (the 2D check's bound), and
/// its walls carry its weight within 1 % (a fluid at rest is held by its walls alone). The pressure is printed,
/// not asserted: with fixed ghosts in 3D it creeps up while the water stays at rest (bottom sensor 1.014 ρgH at
/// t* = 5, 1.040 at 20, the interior gradient 3 % above ρ0 g; 2D at the same spacing holds 1.01–1.016), an open
/// defect of this coarse spacing written up in docs/reference/method.md ("Three dimensions": at H/dx 20 it reads
/// 1.001–1.012 of M g / A over t* 5–20, no trend); the next test shows that image ghosts on the faces remove it.
#[test]
fn three_dimensional_tank_is_held_at_rest_by_its_walls() {
    assert_checks(
        &tank_checks(GhostKind::Fixed),
        &["kinetic energy", "vertical wall force"],
    );
}

/// Image ghosts on the faces (the edges and vertices fixed): the same two bounds, and the hydrostatic pressure
/// itself: the bottom sensor and the interior gradient within 1 % (the 2D check's bound) of their exact values
/// at rest, M g / A and ρ̄ g.
#[test]
fn three_dimensional_tank_with_image_faces_keeps_the_hydrostatic_pressure() {
    assert_checks(
        &tank_checks(GhostKind::Images),
        &[
            "kinetic energy",
            "vertical wall force",
            "bottom pressure",
            "interior dp/dz",
        ],
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

/// The dam break as a 3D slab between free-slip side walls is the 2D dam break: before the impact its front
/// stays within the 2D front's own resolution error of the 2D front, with either kind of ghosts. H/dx = 10, a
/// slab 4 spacings wide. The bound at each sampled time from t√(g/H) = 0.3 to 2.1 is |x_2D(H/dx 20) −
/// x_2D(H/dx 10)|, the change of the 2D front when the spacing is halved (0.08–0.25 H; the 3D–2D gap is
/// 0.03–0.08 H, docs/reference/method.md).
#[test]
fn three_dimensional_slab_front_follows_the_two_dimensional_one_within_its_resolution_error() {
    use bowwave::compare3d::slab::{compare, SlabOptions};
    for ghosts in [GhostKind::Fixed, GhostKind::Images] {
        let opts = |res: f64, width_cells: usize| SlabOptions {
            res,
            width_cells,
            end: 2.1,
            ghosts,
            every: 0.1,
            cfl: None,
        };
        let coarse = compare(&opts(10.0, 4), false).unwrap();
        let fine = compare(&opts(20.0, 1), false).unwrap();
        let (two, three, two_fine) = (&coarse.two, &coarse.three, &fine.two);
        assert_eq!(two.t_star.len(), two_fine.t_star.len());
        for k in 3..two.t_star.len() {
            let gap = (three.front[k] - two.front[k]).abs();
            let resolution = (two_fine.front[k] - two.front[k]).abs();
            println!(
                "{ghosts:?}, t* {:.2}: 3D − 2D {gap:.4} H, 2D H/dx 20 − 10 {resolution:.4} H",
                two.t_star[k]
            );
            assert!(
                gap < resolution,
                "{ghosts:?}, t* {}: the 3D front is {gap} H from the 2D one",
                two.t_star[k]
            );
        }
    }
}

#[test]
fn slab_comparison_refuses_bad_options_with_what_it_expected() {
    use bowwave::compare3d::slab::{compare, SlabOptions};
    let good = SlabOptions {
        res: 10.0,
        width_cells: 4,
        end: 1.0,
        ghosts: GhostKind::Fixed,
        every: 0.1,
        cfl: None,
    };
    for bad in [
        SlabOptions {
            res: 2.0,
            ..good.clone()
        },
        SlabOptions {
            width_cells: 0,
            ..good.clone()
        },
        SlabOptions {
            end: f64::NAN,
            ..good.clone()
        },
        SlabOptions {
            every: 0.0,
            ..good.clone()
        },
    ] {
        let e = compare(&bad, false).unwrap_err().to_string();
        assert!(e.contains("expected H/dx ≥ 4"), "{e}");
    }
}

/// A comparison whose 3D run stopped early keeps every 2D sample in its table, the 3D columns NaN past the
/// stop (the blow-up path itself cannot be reached cheaply: no small case blows up).
#[test]
fn slab_table_keeps_the_two_dimensional_samples_past_a_stopped_three_dimensional_run() {
    use bowwave::compare3d::slab::{RunHistory, SlabComparison, SlabOptions};
    let run = |n: usize| RunHistory {
        t_star: (0..n).map(|k| k as f64 * 0.1).collect(),
        front: vec![2.0; n],
        p1: vec![0.0; n],
        p2: vec![0.0; n],
        ..Default::default()
    };
    let c = SlabComparison {
        options: SlabOptions {
            res: 10.0,
            width_cells: 4,
            end: 0.5,
            ghosts: GhostKind::Fixed,
            every: 0.1,
            cfl: None,
        },
        two: run(6),
        three: RunHistory {
            stopped: Some("the 3D run blew up".into()),
            ..run(3)
        },
    };
    let t = c.table();
    let front_3d = t.column("front_3d").unwrap();
    assert_eq!(front_3d.len(), 6);
    assert!(front_3d[..3].iter().all(|x| *x == 2.0) && front_3d[3..].iter().all(|x| x.is_nan()));
    assert_eq!(c.stopped(), Some("the 3D run blew up"));
}

/// The 3D mode's towed ship at the CI level (Wigley, Fr 0.5, D/dx 3, to 0.5 L travelled; `bowwave ship` runs D/dx
/// 5 and more against the 2D+t map): the hull raises a bow crest, and the water ahead of the stem stays calm.
/// The latter is exact for this tank: its depth 2 D = 0.2 L gives a depth Froude number U/√(g 2D) = 1.12 > 1, so no
/// wave travels as fast as the ship, and the ramp's start cannot run ahead of it either. The crest's height is
/// bounded loosely (0.05–0.6 D within 0.4 L of the stem): at this spacing the bow wave is two particles high, a
/// smoke test of the moving 3D wall, not a validation.
#[test]
fn towed_wigley_raises_a_bow_crest_and_leaves_the_water_ahead_calm() {
    use bowwave::compare3d::towed_ship::{run, TowedShip};
    let hull = bowwave::validation::hull_at_rest::wigley();
    let mut opts = TowedShip::new(hull, 0.5, 3.0);
    opts.min_travel_over_l = 0.5;
    opts.max_travel_over_l = 0.5;
    let r = run(&opts, false).unwrap().ran().unwrap();
    assert!(r.blow_up.is_none(), "blew up: {:?}", r.blow_up);
    assert!(r.travel_over_l >= 0.5);
    let (_, crest, x) = *r.bow.last().unwrap();
    println!(
        "bow crest {crest:.3} D at x/L {x:.3}; {} particles, {} steps",
        r.particles, r.steps
    );
    assert!(
        (0.05..0.6).contains(&crest) && (0.0..=0.4).contains(&x),
        "crest {crest} D at x/L {x}"
    );
    let mut ahead = 0usize;
    for (i, col) in r.eta.values.iter().enumerate() {
        let x = r.eta.x0 + i as f64 * r.eta.dx;
        if x < -0.1 {
            for v in col.iter().filter(|v| v.is_finite()) {
                assert!(v.abs() < 0.03, "η/D {v} at x/L {x} ahead of the stem");
                ahead += 1;
            }
        }
    }
    assert!(ahead > 10, "only {ahead} bins ahead of the stem");
}

/// A towed run stopped with its state saved and run again goes on to the same bits as an uninterrupted one
/// (D/dx 2, to 0.3 L travelled, stopped at step 30 of about 50).
#[test]
fn resumed_towed_ship_gives_the_same_bits_as_an_uninterrupted_one() {
    use bowwave::compare3d::towed_ship::{run, CheckpointPolicy, TowedShip};
    use bowwave::driver::Ended;
    let hull = bowwave::validation::hull_at_rest::wigley();
    let mut opts = TowedShip::new(hull, 0.5, 2.0);
    opts.min_travel_over_l = 0.3;
    opts.max_travel_over_l = 0.3;
    let whole = run(&opts, false).unwrap().ran().unwrap();
    let dir = std::env::temp_dir().join(format!("bowwave-towed-resume-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    opts.checkpoint = Some(CheckpointPolicy {
        dir: dir.clone(),
        every: std::time::Duration::MAX,
        wall_limit: None,
        halt_at_step: Some(30),
    });
    match run(&opts, false).unwrap() {
        Ended::Halted(h) => assert_eq!(h.steps, 30),
        Ended::Ran(_) => panic!("the run did not stop at step 30"),
    }
    opts.checkpoint.as_mut().unwrap().halt_at_step = None;
    let resumed = run(&opts, false).unwrap().ran().unwrap();
    assert_eq!(resumed.steps, whole.steps);
    assert_eq!(resumed.bow, whole.bow);
    let bits = |f: &bowwave::io::plot::Field| -> Vec<u64> { f.values.iter().flatten().map(|v| v.to_bits()).collect() };
    assert_eq!(bits(&resumed.eta), bits(&whole.eta));
    assert!(
        !dir.join("checkpoint.bin").exists(),
        "a finished run leaves no checkpoint"
    );
    std::fs::remove_dir_all(&dir).ok();
}
