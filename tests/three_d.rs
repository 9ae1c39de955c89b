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
        state_bits(&sim.fluid)
    })
}

/// The bits of every particle's position, velocity and density, in the order of their ids.
fn state_bits(f: &bowwave::sph::particles::Fluid<3>) -> Vec<u64> {
    let mut order: Vec<usize> = (0..f.len()).collect();
    order.sort_by_key(|&i| f.id[i]);
    order
        .iter()
        .flat_map(|&i| {
            let (x, u) = (f.pos[i], f.vel[i]);
            [x.x, x.y, x.z, u.x, u.y, u.z, f.rho[i]].map(f64::to_bits)
        })
        .collect()
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
/// (D/dx 2, to 0.3 L travelled, stopped at step 30 of about 50). The interrupted run also writes ParaView frames
/// every 0.1 L: they change no bit, and the resumed run goes on numbering and indexing them (frames at 0, 0.1,
/// 0.2 and 0.3 L, each with the hull's surface beside the particles).
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
        deadline: None,
        halt_at_step: Some(30),
    });
    opts.frames = Some(bowwave::compare3d::towed_ship::Frames {
        dir: dir.clone(),
        every_over_l: 0.1,
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
    for kind in ["fluid", "hull"] {
        let pvd = std::fs::read_to_string(dir.join(format!("{kind}.pvd"))).unwrap();
        let files: Vec<&str> = pvd
            .split("file=\"")
            .skip(1)
            .map(|r| &r[..r.find('"').unwrap()])
            .collect();
        let want: Vec<String> = (0..4).map(|k| format!("{kind}_{k:04}.vtp")).collect();
        assert_eq!(files, want, "{kind}.pvd");
        assert!(files.iter().all(|f| dir.join(f).exists()));
    }
    let hull = std::fs::read_to_string(dir.join("hull_0002.vtp")).unwrap();
    assert!(hull.contains("NumberOfPolys=\"") && !hull.contains("NumberOfPolys=\"0\""));
    std::fs::remove_dir_all(&dir).ok();
}

/// What the Wigley hull at rest (U = 0) in the 3D ship's tank leaves after `steps` steps on `n` threads, D/dx 2
/// (1 880 particles), image faces as the towed runs use: every particle's bits (by id), the mechanical energy at
/// the start and at the end, and the run's scene.
struct HullAtRestRun {
    bits: Vec<u64>,
    start: bowwave::sph::diagnostics::Energies,
    end: bowwave::sph::diagnostics::Energies,
    scene_before: bowwave::sph::particles::Fluid<3>,
    after: bowwave::sph::particles::Fluid<3>,
    pressure: Vec<f64>,
    lo: Vector3<f64>,
    hi: Vector3<f64>,
    dx: f64,
    draft: f64,
}

fn hull_at_rest_run(n: usize, steps: usize) -> HullAtRestRun {
    use bowwave::compare3d::ship::ShipTank;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(n).build().unwrap();
    pool.install(|| {
        let hull = bowwave::validation::hull_at_rest::wigley();
        let d_over_l = hull.meta.draft_m / hull.meta.length_m;
        let mut tank = ShipTank::new(hull, d_over_l / 2.0, 0.25, 0.25);
        tank.tank_ghosts = GhostKind::Images;
        let scene = tank.build().unwrap();
        let (lo, hi, draft) = (scene.lo, scene.hi, scene.draft);
        let mut sim = scene.sim;
        let before = sim.fluid.clone();
        let start = sim.energies();
        for _ in 0..steps {
            sim.step().unwrap();
        }
        let f = &sim.fluid;
        HullAtRestRun {
            bits: state_bits(f),
            start,
            end: sim.energies(),
            scene_before: before,
            after: f.clone(),
            pressure: sim.state_pressures(),
            lo,
            hi,
            dx: sim.cfg.dx,
            draft,
        }
    })
}

/// Issue #31's CI test of the 3D hull: the Wigley hull at rest in the ship's tank, D/dx 2, 60 steps on 1 and on
/// 2 threads. Asserted: the same bits on both; no particle gained or lost and the total mass unchanged to the
/// last bit (particles carry fixed masses, so this says none left the domain); the water stays out of the hull
/// (no particle inside a section's polygon); and the state is mirror-symmetric fore and aft about midship, as the
/// hull, the tank (as much water ahead as behind) and the lattice are (measured: 6e-14 dx in position and 2e-14
/// ρgD in pressure, round-off; a bound of 1e-9 catches any asymmetry of the hull's ghosts or of their mirror
/// points, which a surface sampled at 0.25 dx would show at 1e-3 dx or more). Printed, not asserted: the kinetic
/// energy, which at this spacing is 1.2–1.7e-4 M g D after 30–120 steps, and the mechanical energy, which rises
/// by up to 7e-4 M g D over them. The rest bound (E_K/(M g D) < 1e-5 after settling) is not met at any
/// spacing run so far (`validate hull-at-rest`: 1.9–4.2e-5 at D/dx 5, docs/reference/method.md) and is
/// therefore not claimed here.
#[test]
fn wigley_at_rest_keeps_its_mass_its_fore_aft_symmetry_and_its_bits_on_one_and_two_threads() {
    use bowwave::geometry::hull_solid::{polygon_contains, section_polygon};
    let (a, b) = (hull_at_rest_run(1, 60), hull_at_rest_run(2, 60));
    assert!(a.bits == b.bits, "the hull at rest differs between 1 and 2 threads");
    let (f0, f) = (&a.scene_before, &a.after);
    assert_eq!(f.len(), f0.len(), "particles lost or gained");
    assert_eq!(f.total_mass().to_bits(), f0.total_mass().to_bits(), "mass changed");
    let s = G * a.draft * f.total_mass();
    println!(
        "{} particles: E_K/(M g D) {:.3e}, mechanical energy change {:.3e} M g D",
        f.len(),
        a.end.kinetic / s,
        (a.end.mechanical() - a.start.mechanical()) / s
    );
    let hull = bowwave::validation::hull_at_rest::wigley();
    let l = hull.meta.length_m;
    let inside = f
        .pos
        .iter()
        .filter(|r| section_polygon(&hull, r.x / l, 200).is_some_and(|p| polygon_contains(&p, r.y / l, r.z / l)))
        .count();
    assert_eq!(inside, 0, "particles inside the hull");
    // Fore–aft mirror: the particle laid at the mirror node of each one's starting node.
    let (lo, hi, dx) = (a.lo, a.hi, a.dx);
    let node = |x: f64, r: &Vector3<f64>| [x, r.y, r.z].map(|c| (c / dx).round() as i64);
    let start: std::collections::HashMap<_, _> = (0..f0.len())
        .map(|i| (node(f0.pos[i].x, &f0.pos[i]), f0.id[i]))
        .collect();
    let now: std::collections::HashMap<_, _> = (0..f.len()).map(|i| (f.id[i], i)).collect();
    let (mut dpos, mut dp) = (0.0f64, 0.0f64);
    for i0 in 0..f0.len() {
        let r = f0.pos[i0];
        let twin = start[&node(lo.x + hi.x - r.x, &r)];
        let (i, j) = (now[&f0.id[i0]], now[&twin]);
        let (p, q) = (f.pos[i], f.pos[j]);
        dpos = dpos.max(
            (lo.x + hi.x - p.x - q.x)
                .abs()
                .max((p.y - q.y).abs())
                .max((p.z - q.z).abs())
                / dx,
        );
        dp = dp.max((a.pressure[i] - a.pressure[j]).abs() / (RHO0 * G * a.draft));
    }
    println!("fore–aft asymmetry: {dpos:.2e} dx in position, {dp:.2e} ρgD in pressure");
    assert!(dpos < 1e-9 && dp < 1e-9, "asymmetric: {dpos:e} dx, {dp:e} ρgD");
}

/// Issue #31, bad input: a spacing whose particles the machine cannot hold, and a tank that cuts the hull (too
/// narrow, too shallow), are refused with the cause before the scene is allocated (`towed_ship::plan` builds it).
#[test]
fn ship_too_fine_for_memory_or_in_a_tank_that_cuts_the_hull_is_refused() {
    use bowwave::compare3d::towed_ship::{plan, TowedShip};
    let hull = bowwave::validation::hull_at_rest::wigley();
    let err = |opts: &TowedShip| format!("{:#}", plan(opts).expect_err("must be refused"));
    // D/dx 400: about 4.6e10 particles, some 100 TiB.
    let e = err(&TowedShip::new(hull.clone(), 0.5, 400.0));
    assert!(
        e.contains("particles") && e.contains("GiB") && e.contains("coarser"),
        "{e}"
    );
    let mut narrow = TowedShip::new(hull.clone(), 0.5, 3.0);
    narrow.half_width_over_b = 0.55;
    let e = err(&narrow);
    assert!(e.contains("half width 0.55 B") && e.contains("cuts the hull"), "{e}");
    let mut shallow = TowedShip::new(hull.clone(), 0.5, 3.0);
    shallow.depth_over_d = 1.0;
    let e = err(&shallow);
    assert!(e.contains("depth 1 D") && e.contains("under the keel"), "{e}");
    assert!(plan(&TowedShip::new(hull, 0.5, 3.0)).is_ok(), "the default tank");
}

/// The towed ship gives the same bits on 1 and 2 threads (D/dx 2, to 0.3 L travelled): its bow history and its
/// final map.
#[test]
fn towed_ship_gives_the_same_bits_on_one_and_two_threads() {
    use bowwave::compare3d::towed_ship::{run, TowedShip};
    let on = |n: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(n).build().unwrap();
        pool.install(|| {
            let mut opts = TowedShip::new(bowwave::validation::hull_at_rest::wigley(), 0.5, 2.0);
            opts.min_travel_over_l = 0.3;
            opts.max_travel_over_l = 0.3;
            let r = run(&opts, false).unwrap().ran().unwrap();
            let bits: Vec<u64> = r.eta.values.iter().flatten().map(|v| v.to_bits()).collect();
            (r.steps, r.bow, bits)
        })
    };
    let (a, b) = (on(1), on(2));
    assert!(!a.1.is_empty() && a.2.iter().any(|v| f64::from_bits(*v).is_finite()));
    assert!(a == b, "the towed ship differs between 1 and 2 threads");
}

/// The bent-wall channel in 3D (thesis §10.2.1, `bowwave bent-wall-3d`) at a coarse spacing on a short wall: it
/// runs to its end, keeps every particle, raises the water on the bent part in both models (the wall pushes
/// it up itself), leaves the water ahead of the bent part calm, and gives the same bits on 1 and 2 threads.
#[test]
fn bent_wall_3d_raises_a_crest_keeps_its_water_and_gives_the_same_bits_on_any_thread_count() {
    use bowwave::compare3d::bent_wall::BentWallOptions;
    use bowwave::compare3d::bent_wall_3d::{build, run, Tow3dOptions};
    let ch = BentWallOptions {
        length: 4.0,
        width: 3.0,
        res: 4.0,
        ..Default::default()
    };
    let o = Tow3dOptions {
        ramp: 1.0,
        settle: 0.5,
        ahead: 2.0,
        behind: 1.0,
        top: 2.0,
        sample: 0.5,
    };
    let n0 = build(&ch, &o).unwrap().sim.n_fluid();
    let on = |n: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(n).build().unwrap();
        pool.install(|| run(&ch, &o, None, false).unwrap().ran().unwrap())
    };
    let (a, b) = (on(1), on(2));
    assert!(a.stopped.is_none(), "{:?}", a.stopped);
    assert_eq!(a.particles, n0);
    assert!(a.travelled >= 5.5 - 1e-9, "travelled {}", a.travelled);
    // Past a quarter of the wall the water climbs the wall above the calm level, in 3D and in 2D+t.
    let late: Vec<_> = a.cuts.iter().filter(|c| c.s > 0.25).collect();
    assert!(!late.is_empty());
    for c in &late {
        assert!(c.run_up > 0.05 && c.run_up_2dt > 0.05, "{c:?}");
    }
    // Ahead of the bent part (ξ < 5 H less three spacings) the water is calm: the wall moves along itself there.
    let eta = a.eta.as_ref().unwrap();
    let mut seen = 0;
    for (i, col) in eta.values.iter().enumerate() {
        let xi = eta.x0 + i as f64 * eta.dx;
        if xi < 4.25 {
            for v in col.iter().filter(|v| v.is_finite()) {
                assert!(v.abs() < 0.1, "η {v} at ξ {xi}");
                seen += 1;
            }
        }
    }
    assert!(seen > 0, "no water ahead of the bent part in the map");
    let bits = |r: &bowwave::compare3d::bent_wall_3d::BentWall3dResult| -> Vec<u64> {
        r.cuts
            .iter()
            .flat_map(|c| [c.crest, c.run_up, c.crest_y])
            .chain(r.history.iter().map(|h| h.1))
            .map(f64::to_bits)
            .collect()
    };
    assert_eq!((a.steps, bits(&a)), (b.steps, bits(&b)), "1 and 2 threads differ");
}
