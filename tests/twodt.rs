//! The 2D+t scene at coarse resolution: the wedge check against a rigid wedge (and Wagner, printed), and a
//! short Athena run for conservation, settling and the calm far field; the bent-wall channel's 2D+t analogue.

use bowwave::driver::Ended;
use bowwave::geometry::{hull_file::HullOffsets, surface::HullSurface};
use bowwave::twodt::{
    run::{TwoDtOptions, TwoDtResult},
    scene::{TwoDtConfig, Until},
    wedge::{compare, print, WedgeCheckpoints, WedgeSpec},
};
use std::sync::Arc;

/// A 2D+t run that is not expected to halt: its result.
fn run(hull: Arc<HullSurface>, cfg: &TwoDtConfig, opts: &TwoDtOptions) -> anyhow::Result<TwoDtResult> {
    bowwave::twodt::run::run(hull, cfg, opts)?.ran()
}

/// A hull of 30° wedge sections whose apex sinks linearly in x is, in 2D+t, a rigid wedge entering at
/// constant speed: at the last sample (penetration 0.03 L = 20 dx) the pile-up height and the force of the
/// two runs agree to 3 %. Wagner's values are printed beside them (not asserted: Wagner over-predicts the
/// force and the runs include gravity, Fr* = V/√(g h tanβ) ≈ 3.8 at the end).
#[test]
fn wedge_sections_in_2dt_match_the_rigid_wedge() {
    let spec = WedgeSpec {
        dx: 1.5e-3,
        ..Default::default()
    };
    let c = compare(&spec, &[0.02, 0.03], None)
        .and_then(Ended::ran)
        .expect("wedge runs");
    print(&c);
    let (a, b) = (c.twodt.last().unwrap(), c.rigid.last().unwrap());
    let pile = (a.pileup_over_vt / b.pileup_over_vt - 1.0).abs();
    let force = (a.force_coefficient / b.force_coefficient - 1.0).abs();
    assert!(
        pile < 0.03,
        "pile-up 2D+t {} vs rigid {}",
        a.pileup_over_vt,
        b.pileup_over_vt
    );
    assert!(
        force < 0.03,
        "force 2D+t {} vs rigid {}",
        a.force_coefficient,
        b.force_coefficient
    );
}

/// The wedge check is resumable (a run at the third spacing outlasts a session): halted part-way through its
/// first run, saved, and run again, it gives the same samples, bit for bit, as the same command uninterrupted;
/// run once more, it recalls both finished runs from their folders instead of running them. A checkpoint or
/// finished samples of another configuration are not used: that run starts afresh.
#[test]
fn wedge_halted_and_resumed_gives_the_same_samples_as_uninterrupted() {
    let spec = WedgeSpec {
        dx: 3e-3,
        ..Default::default()
    };
    let at = [0.01, 0.02];
    let root = std::env::temp_dir().join(format!("bowwave-wedge-resume-{}", std::process::id()));
    let saving = |name: &str, halt_at_step: Option<u64>| WedgeCheckpoints {
        dir: root.join(name),
        every: std::time::Duration::MAX,
        deadline: None,
        halt_at_step,
        fresh: false,
    };
    let straight = compare(&spec, &at, Some(&saving("straight", None)))
        .and_then(Ended::ran)
        .expect("uninterrupted");
    // Step 76 is in the last quarter of the second interval, where the pressure moments are being summed: the
    // most state a halt can cut through.
    let halted = compare(&spec, &at, Some(&saving("resumed", Some(76)))).expect("first session");
    let Ended::Halted(h) = halted else {
        panic!("expected a halt at step 76")
    };
    assert_eq!(h.steps, 76);
    let vt: f64 = h.at.trim_start_matches("Vt/L = ").parse().expect("Vt/L");
    assert!(vt > 0.75 * 0.02 && vt < 0.02, "halted at {}", h.at);
    assert!(h.checkpoint.exists());
    // Another configuration in a folder holding this one's checkpoint starts afresh, and ends as its own
    // uninterrupted run does.
    let other_at = [0.01];
    let other_dir = saving("other", None)
        .dir
        .join(h.checkpoint.parent().unwrap().file_name().unwrap());
    std::fs::create_dir_all(&other_dir).unwrap();
    std::fs::copy(&h.checkpoint, other_dir.join("checkpoint.bin")).unwrap();
    let other = compare(&spec, &other_at, Some(&saving("other", None)))
        .and_then(Ended::ran)
        .expect("other configuration");
    let other_straight = compare(&spec, &other_at, None)
        .and_then(Ended::ran)
        .expect("other, uninterrupted");
    assert_eq!(other.twodt, other_straight.twodt);
    assert_eq!(other.rigid, other_straight.rigid);
    let resumed = compare(&spec, &at, Some(&saving("resumed", None)))
        .and_then(Ended::ran)
        .expect("second session");
    assert_eq!(resumed.twodt, straight.twodt);
    assert_eq!(resumed.rigid, straight.rigid);
    assert_eq!(resumed.twodt.len(), 2);
    assert!(!h.checkpoint.exists(), "a finished run leaves no checkpoint");
    // Finished runs are recalled: even a halt at step 0 does not stop them.
    let recalled = compare(&spec, &at, Some(&saving("resumed", Some(0))))
        .and_then(Ended::ran)
        .expect("recalled");
    assert_eq!(recalled.rigid, straight.rigid);
    // Fresh: run again (a halt at step 0 stops it), nothing recalled.
    let fresh = WedgeCheckpoints {
        fresh: true,
        ..saving("resumed", Some(0))
    };
    assert!(matches!(compare(&spec, &at, Some(&fresh)), Ok(Ended::Halted(_))));
    // A finished run of another configuration in the folder is run again, not recalled.
    let rerun = compare(&spec, &other_at, Some(&saving("resumed", None)))
        .and_then(Ended::ran)
        .expect("rerun");
    assert_eq!(rerun.twodt, other_straight.twodt);
    let _ = std::fs::remove_dir_all(&root);
}

/// Athena at Fr = 0.64, dx/L = 2e-3, from the stem to x/L = 0.12: mass is conserved to round-off, the
/// mean level of the far field (y > 3W/4) stays within 0.5 % of D of the calm level, and the outputs are
/// written.
#[test]
fn athena_coarse_run_conserves_mass_and_keeps_the_far_field_calm() {
    let cfg = TwoDtConfig {
        vtk: true,
        ..athena_cfg(None, Until::X(0.12))
    };
    let dir = std::env::temp_dir().join(format!("bowwave-twodt-test-{}", std::process::id()));
    let r = run(athena(), &cfg, &quiet_options(&dir, true)).expect("2D+t run");
    assert!(r.blowup.is_none(), "{:?}", r.blowup);
    assert!(r.mass_change.abs() < 1e-12, "mass change {}", r.mass_change);
    assert!(r.ke_after_settle < 1e-6, "E_K after settling {}", r.ke_after_settle);
    assert!(
        r.far_field_eta_over_d < 0.005,
        "far field |η|/D = {}",
        r.far_field_eta_over_d
    );
    assert!(r.x_end_over_l >= 0.12);
    for f in ["metrics.csv", "metrics.json", "series.csv", "eta.csv", "series.pvd"] {
        assert!(dir.join(f).exists(), "{f} missing");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Athena at Fr 0.64, dx/L = 2e-3, outputs every 0.02 L.
fn athena_cfg(x0: Option<f64>, until: Until) -> TwoDtConfig {
    TwoDtConfig {
        fr: 0.64,
        dx: Some(2e-3),
        x0,
        until,
        output_dx: 0.02,
        ..Default::default()
    }
}

/// Outputs into `dir`, no progress bar; with `all`, plots too.
fn quiet_options(dir: &std::path::Path, all: bool) -> TwoDtOptions {
    TwoDtOptions {
        plots: all,
        ..TwoDtOptions::quiet(dir.to_path_buf())
    }
}

fn athena() -> Arc<HullSurface> {
    let hull = HullOffsets::read(std::path::Path::new("hulls/athena.csv")).expect("athena hull");
    Arc::new(HullSurface::new(&hull))
}

/// Regression (found while fuzzing the input files, tests/fuzzed_input.rs): a spacing typed a few orders
/// too fine (`--dx 1e-7`, 4e12 particles) went on to allocate; the scene now refuses it first, naming dx/L.
#[test]
fn spacing_too_fine_for_memory_is_refused_before_allocating() {
    let cfg = TwoDtConfig {
        dx: Some(1e-7),
        ..athena_cfg(None, Until::Plunge)
    };
    let e = format!(
        "{:#}",
        bowwave::twodt::scene::build(athena(), &cfg)
            .err()
            .expect("must be refused")
    );
    assert!(e.contains("dx/L = 1e-7") && e.contains("at most"), "{e}");
    assert!(bowwave::twodt::scene::build(athena(), &athena_cfg(None, Until::Plunge)).is_ok());
}

/// Regression (found by feeding `bowwave twodt` bad numbers): a negative c0, settling or output spacing, a
/// zero output spacing (a frame at every step) or detection interval ran on; each is now refused with the
/// option and what was expected.
#[test]
fn bad_twodt_options_are_refused_with_what_was_expected() {
    let base = athena_cfg(None, Until::Plunge);
    let cases: Vec<(TwoDtConfig, &str)> = vec![
        (
            TwoDtConfig {
                c0: Some(-1.0),
                ..base.clone()
            },
            "c0",
        ),
        (
            TwoDtConfig {
                settle_crossings: -1.0,
                ..base.clone()
            },
            "settling",
        ),
        (
            TwoDtConfig {
                output_dx: 0.0,
                ..base.clone()
            },
            "output spacing",
        ),
        (
            TwoDtConfig {
                output_dx: f64::NAN,
                ..base.clone()
            },
            "output spacing",
        ),
        (
            TwoDtConfig {
                detect_every: 0,
                ..base.clone()
            },
            "detection interval",
        ),
        (
            TwoDtConfig {
                after_plunge: -0.1,
                ..base.clone()
            },
            "after the plunge",
        ),
        (
            TwoDtConfig {
                cfl: Some(0.0),
                ..base.clone()
            },
            "CFL",
        ),
        (
            TwoDtConfig {
                alpha: Some(-0.01),
                ..base.clone()
            },
            "artificial viscosity",
        ),
        (
            TwoDtConfig {
                fr: f64::NAN,
                ..base.clone()
            },
            "Froude",
        ),
        (
            TwoDtConfig {
                air: Some(0.0),
                ..base.clone()
            },
            "air layer height",
        ),
        (
            TwoDtConfig {
                air: Some(1.0),
                air_density: 2.0,
                ..base.clone()
            },
            "air density",
        ),
        (
            // Above the tank's walls (the hull's top plus D).
            TwoDtConfig {
                air: Some(9.0),
                ..base.clone()
            },
            "--air",
        ),
    ];
    for (cfg, needle) in cases {
        let e = format!(
            "{:#}",
            bowwave::twodt::scene::build(athena(), &cfg)
                .err()
                .expect("must be refused")
        );
        assert!(e.contains(needle) && e.contains("expected"), "{needle}: {e}");
    }
}

/// The tank before the stem arrives (x0 = −0.4, run to x/L = −0.2, about 4 √(Z/g)): after the damped
/// settling the water stays at rest: E_K below 1e-6 M g D at every output, the far-field level within
/// 0.5 % of D.
#[test]
fn still_tank_before_the_stem_stays_at_rest() {
    let uniform = TwoDtConfig {
        coarse_ratio: 1.0,
        ..athena_cfg(Some(-0.4), Until::X(-0.2))
    };
    let (ke_max, far) = still_tank(&uniform, "uniform");
    assert!(ke_max < 1e-6, "E_K/(M g D) = {ke_max}");
    assert!(far < 0.005);
}

/// With an air layer (`--air 1`: 1 D of air at a density ratio of 1000 under the lid) the tank before the
/// stem stays at rest too: after the settling (three acoustic crossings with air) E_K/(M g D) falls below
/// 1e-6 within 0.15 L of travel and stays there (measured 5e-7 at dx/L 4e-3), the water's far-field level
/// stays within 0.5 % of D (0.39 %), and the interface keeps no gap: in every column the lowest air particle
/// is within two spacings of the highest water particle (the rows of the two phases stand about 1.5 dx
/// apart, as in the closed two-layer tank, `validate two-layer`).
#[test]
fn still_tank_with_air_stays_at_rest_without_a_gap_at_the_interface() {
    let dx = 4e-3;
    let cfg = TwoDtConfig {
        coarse_ratio: 1.0,
        dx: Some(dx),
        air: Some(1.0),
        vtk: true,
        ..athena_cfg(Some(-0.4), Until::X(-0.2))
    };
    let dir = std::env::temp_dir().join(format!("bowwave-still-air-{}", std::process::id()));
    let r = run(athena(), &cfg, &quiet_options(&dir, false)).expect("still tank with air");
    let series = std::fs::read_to_string(dir.join("series.csv")).expect("series");
    let mut lines = series.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let (kx, kk) = (
        header.iter().position(|c| *c == "x_over_l").unwrap(),
        header.iter().position(|c| *c == "ke_over_mgd").unwrap(),
    );
    let rows: Vec<(f64, f64)> = lines
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            (v[kx], v[kk])
        })
        .collect();
    println!(
        "still tank with air: E_K/(M g D) along x/L {rows:?}; far field {:.2e} D",
        r.far_field_eta_over_d
    );
    let late = rows.iter().filter(|(x, _)| *x > -0.25);
    assert!(late.clone().count() >= 2);
    for (x, ke) in late {
        assert!(*ke < 1e-6, "E_K/(M g D) = {ke} at x/L {x}");
    }
    assert!(
        r.far_field_eta_over_d < 0.005,
        "far-field level {} D",
        r.far_field_eta_over_d
    );
    assert_eq!(r.air_over_d, Some(1.0));
    // The last frame: phases and positions.
    let last = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "vtp"))
        .max()
        .expect("a VTK frame");
    let text = std::fs::read_to_string(&last).unwrap();
    let array = |name: &str| -> Vec<f64> {
        let start = text
            .find(&format!("Name=\"{name}\""))
            .unwrap_or_else(|| panic!("no {name}"));
        let body = &text[start..];
        let (a, b) = (body.find('>').unwrap() + 1, body.find("</DataArray>").unwrap());
        body[a..b].split_whitespace().map(|x| x.parse().unwrap()).collect()
    };
    let points = {
        let start = text.find("<Points>").unwrap();
        let body = &text[start..];
        let body = &body[body.find("<DataArray").unwrap()..];
        let (a, b) = (body.find('>').unwrap() + 1, body.find("</DataArray>").unwrap());
        body[a..b]
            .split_whitespace()
            .map(|x| x.parse::<f64>().unwrap())
            .collect::<Vec<_>>()
    };
    let phase = array("phase");
    assert_eq!(points.len(), 3 * phase.len());
    let width = (0..phase.len()).map(|i| points[3 * i]).fold(0.0, f64::max);
    let columns = (width / dx).ceil() as usize;
    let (mut top_water, mut low_air) = (vec![f64::NEG_INFINITY; columns + 1], vec![f64::INFINITY; columns + 1]);
    for (i, &k) in phase.iter().enumerate() {
        let (y, z) = (points[3 * i], points[3 * i + 1]);
        let c = (y / dx) as usize;
        if k == 0.0 {
            top_water[c] = top_water[c].max(z);
        } else {
            low_air[c] = low_air[c].min(z);
        }
    }
    let gap = top_water
        .iter()
        .zip(&low_air)
        .filter(|(w, a)| w.is_finite() && a.is_finite())
        .map(|(w, a)| a - w)
        .fold(0.0, f64::max);
    println!("largest water-to-air distance over the columns: {:.2} dx", gap / dx);
    assert!(gap < 2.0 * dx, "a gap of {} dx opened at the interface", gap / dx);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Regression: where the section meets the lid, the corner vertex took the section's whole velocity, and the lid's
/// ghosts, which interpolate their vertices' motion, pushed the air down across the whole lid with the raked
/// stem's vertical speed (up to 1.7 √(gL) at Athena's): E_K/(M g D) 9.8e-3 after 0.01 L, the air sloshing at
/// 0.5 √(gL), a blow-up at x/L 0.10. With the corner moving with the lid along the lid: 3.7e-5, before the
/// stem reaches the water (x/L 0.024).
#[test]
fn air_is_not_pumped_by_the_lid_where_the_stem_crosses_it() {
    let cfg = TwoDtConfig {
        dx: Some(4e-3),
        air: Some(1.5),
        until: Until::X(0.01),
        output_dx: 0.005,
        ..athena_cfg(None, Until::Plunge)
    };
    let dir = std::env::temp_dir().join(format!("bowwave-air-stem-{}", std::process::id()));
    let r = run(athena(), &cfg, &quiet_options(&dir, false)).expect("air at the stem");
    let (ke_max, _) = series_max(&dir, "ke_over_mgd");
    println!("air at the stem: largest E_K/(M g D) to x/L 0.01: {ke_max:.2e}");
    assert!(r.blowup.is_none());
    assert!(ke_max < 1e-3, "E_K/(M g D) = {ke_max}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The largest value of `column` in a run folder's series.csv, with its x/L.
fn series_max(dir: &std::path::Path, column: &str) -> (f64, f64) {
    let series = std::fs::read_to_string(dir.join("series.csv")).expect("series");
    let mut lines = series.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let (k, kx) = (
        header.iter().position(|c| *c == column).unwrap(),
        header.iter().position(|c| *c == "x_over_l").unwrap(),
    );
    lines
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            (v[k], v[kx])
        })
        .fold((f64::NEG_INFINITY, f64::NAN), |a, b| if b.0 > a.0 { b } else { a })
}

/// Largest E_K/(M g D) over the series and the far-field level / D of a still-tank run (section before the
/// stem from x/L = −0.4 to −0.2).
fn still_tank(cfg: &TwoDtConfig, label: &str) -> (f64, f64) {
    let dir = std::env::temp_dir().join(format!("bowwave-still-tank-{label}-{}", std::process::id()));
    let r = run(athena(), cfg, &quiet_options(&dir, false)).expect("still tank");
    let (ke_max, _) = series_max(&dir, "ke_over_mgd");
    println!(
        "still tank ({label}): max E_K/(M g D) = {ke_max:.2e}, far-field level {:.2e} D",
        r.far_field_eta_over_d
    );
    let _ = std::fs::remove_dir_all(&dir);
    (ke_max, r.far_field_eta_over_d)
}

/// Graded rows (r = 1.5, the default) relax with a spurious flow above the 1e-6 M g D the issue allows when
/// they start from the lattice; packed first (thesis chapter 6, the default) they stay below it (measured
/// 1.33e-5 and 8.3e-7). Both sides are asserted. E_K sampled every 0.005 L (the default output spacing): every
/// 0.02 L missed the peaks (7.0e-7 read for the packed tank; with particle shifting 1.0e-6 read where 1.9e-6
/// was reached, session 44).
#[test]
fn graded_rows_stay_at_rest_only_after_packing() {
    let graded = TwoDtConfig {
        coarse_ratio: 1.5,
        packing: bowwave::twodt::config::Packing::Off,
        output_dx: 0.005,
        ..athena_cfg(Some(-0.4), Until::X(-0.2))
    };
    let (ke_lattice, _) = still_tank(&graded, "graded-lattice");
    let packed = TwoDtConfig {
        packing: bowwave::twodt::config::Packing::Auto,
        ..graded
    };
    let (ke_packed, far) = still_tank(&packed, "graded-packed");
    assert!(ke_lattice > 1e-6, "lattice start: E_K/(M g D) = {ke_lattice}");
    assert!(ke_packed < 1e-6, "packed start: E_K/(M g D) = {ke_packed}");
    assert!(far < 0.005, "far-field level {far} D");
}

/// Regression: the packing's fixed layers sat on one global lattice, so when W or Z was not a whole number
/// of spacings a gap of up to 1.5 dx opened at the far wall and the bottom; particles were pushed into it
/// against the clamp and never came to rest (specific kinetic energy 1e-2 after 3 000 iterations).
#[test]
fn packing_converges_when_the_tank_is_not_a_whole_number_of_spacings() {
    let cfg = TwoDtConfig {
        packing: bowwave::twodt::config::Packing::On,
        coarse_ratio: 1.5,
        dx: Some(4e-3),
        ..athena_cfg(Some(-0.4), Until::X(-0.2))
    };
    let scene = bowwave::twodt::scene::build(athena(), &cfg).expect("scene");
    let frac = |v: f64| (v / cfg.dx.unwrap()).fract();
    println!(
        "W/dx fraction {:.3}, Z/dx fraction {:.3}",
        frac(scene.geom.width),
        frac(scene.geom.depth)
    );
    assert!(
        frac(scene.geom.width) > 0.05 && frac(scene.geom.depth) > 0.05,
        "the case must exercise the gap"
    );
    let r = scene.packing.expect("packing report");
    println!("{r:?}");
    assert!(r.specific_ke < 1e-6, "{r:?}");
    assert!(r.grad_gamma_after < 0.2 * r.grad_gamma_before, "{r:?}");
}

/// Regression: particles within half a spacing of the section at t = 0 were removed, and before the stem
/// the section is the symmetry plane, so whenever the row spacing W/round(W/dx) fell just below dx the whole
/// first column went, and the water collapsed into the gap as a jet of 0.08 √(gL) up the plane.
#[test]
fn first_column_along_the_symmetry_plane_is_kept() {
    for dx in [4e-3, 2e-3] {
        let cfg = TwoDtConfig {
            fr: 0.64,
            dx: Some(dx),
            x0: Some(-0.4),
            until: Until::X(-0.2),
            ..Default::default()
        };
        let scene = bowwave::twodt::scene::build(athena(), &cfg).expect("scene");
        let ymin = scene.sim.fluid.pos.iter().map(|p| p.x).fold(f64::INFINITY, f64::min);
        assert!(ymin < 0.51 * dx, "first particle at y = {ymin} (dx = {dx})");
        let top = scene.sim.fluid.pos.iter().filter(|p| p.y > -dx).count();
        assert_eq!(top, (scene.geom.width / dx).round() as usize);
    }
}

/// Regression: the settling's kinetic energy was read after the step that crosses the start time, whose
/// later RK stages already move the section; with Wigley's full-depth stem that one step gave 1.24e-4 M g D,
/// reported as what the settling left.
#[test]
fn settling_energy_is_measured_before_the_ship_starts() {
    let hull = Arc::new(HullSurface::new(
        &HullOffsets::read(std::path::Path::new("hulls/wigley.csv")).expect("wigley hull"),
    ));
    let cfg = TwoDtConfig {
        fr: 0.5,
        dx: Some(4e-3),
        until: Until::X(0.005),
        output_dx: 0.005,
        ..Default::default()
    };
    let dir = std::env::temp_dir().join(format!("bowwave-settle-wigley-{}", std::process::id()));
    let r = run(hull, &cfg, &quiet_options(&dir, false)).expect("wigley start");
    let _ = std::fs::remove_dir_all(&dir);
    println!(
        "Wigley at the stem: settling left E_K/(M g D) = {:.2e}",
        r.ke_after_settle
    );
    assert!(r.ke_after_settle < 1e-6, "{:.3e}", r.ke_after_settle);
}

/// A run stopped part-way (its state saved in `checkpoint.bin`) and started again gives the same bits as one
/// that ran through: metrics, series, η table and bow snapshot. The graded rows are packed, so the packing
/// report and the packed particles come from the checkpoint, not from a second packing.
#[test]
fn resumed_run_gives_the_same_bits_as_an_uninterrupted_one() {
    use bowwave::twodt::checkpoint::{CheckpointPolicy, FILE};
    let cfg = TwoDtConfig {
        dx: Some(4e-3),
        detect_every: 3,
        output_dx: 0.01,
        ..athena_cfg(None, Until::X(0.06))
    };
    let base = std::env::temp_dir().join(format!("bowwave-resume-{}", std::process::id()));
    let (dir_a, dir_b) = (base.join("through"), base.join("resumed"));
    let a = run(athena(), &cfg, &quiet_options(&dir_a, false)).unwrap();
    let halt = 2 * a.steps / 3;
    let stop = TwoDtOptions {
        checkpoint: CheckpointPolicy {
            halt_at_step: Some(halt),
            resume: true,
            ..Default::default()
        },
        ..quiet_options(&dir_b, false)
    };
    let h = match bowwave::twodt::run::run(athena(), &cfg, &stop).unwrap() {
        Ended::Halted(h) => h,
        Ended::Ran(_) => panic!("the run stops at the asked step"),
    };
    // It stops at the first plunge check (every `detect_every` steps) at or after the asked step.
    assert!(
        h.steps >= halt && h.steps < halt + cfg.detect_every as u64,
        "stopped at {}",
        h.steps
    );
    assert!(dir_b.join(FILE).exists());
    let go_on = TwoDtOptions {
        checkpoint: CheckpointPolicy {
            resume: true,
            ..Default::default()
        },
        ..quiet_options(&dir_b, false)
    };
    let b = run(athena(), &cfg, &go_on).unwrap();
    assert!(!dir_b.join(FILE).exists(), "a finished run removes its checkpoint");
    let strip = |r: &bowwave::twodt::run::TwoDtResult| {
        let mut v = serde_json::to_value(r).unwrap();
        v["wall_seconds"] = 0.into();
        v["cpu_seconds"] = 0.into();
        v
    };
    assert_eq!(strip(&a), strip(&b));
    assert!(a.ke_after_settle > 0.0 && a.steps > halt);
    for f in ["series.csv", "eta.csv", "snapshot.csv", "snapshot_wall.csv"] {
        let (x, y) = (
            std::fs::read(dir_a.join(f)).unwrap(),
            std::fs::read(dir_b.join(f)).unwrap(),
        );
        assert!(x == y, "{f} differs after the restart");
    }
    let _ = std::fs::remove_dir_all(&base);
}

/// `converge twodt` keeps each spacing's run in its folder: a second call reuses the finished runs instead of
/// running them again, and `--runs` gathers the same folders into the same table (coarse to fine only).
#[test]
fn convergence_ladder_reuses_finished_runs_and_gathers_run_folders() {
    use bowwave::methods::twodt_convergence::{converge_finished, converge_twodt, run_dir};
    use bowwave::twodt::checkpoint::CheckpointPolicy;
    let base = TwoDtConfig {
        output_dx: 0.01,
        ..athena_cfg(None, Until::X(0.03))
    };
    let out = std::env::temp_dir().join(format!("bowwave-ladder-{}", std::process::id()));
    let dxs = [5e-3, 4e-3];
    let policy = CheckpointPolicy::default();
    let first = converge_twodt(athena(), &base, &dxs, &out, &policy, false)
        .unwrap()
        .ran()
        .unwrap();
    let again = converge_twodt(athena(), &base, &dxs, &out, &policy, false)
        .unwrap()
        .ran()
        .unwrap();
    assert_eq!(
        first.wall_seconds, again.wall_seconds,
        "the second call reuses the recorded runs"
    );
    let crest = |c: &bowwave::methods::convergence::Convergence| {
        let q = c.quantities.iter().find(|q| q.name.starts_with("crest")).unwrap();
        q.values.iter().map(|v| v.0).collect::<Vec<_>>()
    };
    assert!(crest(&first).iter().all(|c| c.is_finite() && *c > 0.0));
    let dirs: Vec<_> = dxs.iter().map(|&d| run_dir(&out, d)).collect();
    let gathered = converge_finished(&dirs).unwrap();
    assert_eq!(crest(&gathered), crest(&first));
    let reversed: Vec<_> = dirs.iter().rev().cloned().collect();
    let e = format!("{:#}", converge_finished(&reversed).unwrap_err());
    assert!(e.contains("coarse to fine"), "{e}");
    let e = format!(
        "{:#}",
        converge_finished(&[dirs[0].clone(), out.join("nowhere")]).unwrap_err()
    );
    assert!(e.contains("nowhere") && e.contains("metrics.json"), "{e}");
    let _ = std::fs::remove_dir_all(&out);
}

/// The plunge instant searched step by step from the last regular check (the fast path: a check every
/// `detect_every` = 10 steps, then back to the check before a plunge and every step from there) against the
/// slow oracle of a check at every step: the same step, the same plunge. Athena Fr 0.55 at dx/L = 7e-4 with
/// criterion 5 off, whose first closed cavity (the false plunge of docs/reference/jet-metrics.md, criterion 5) closes
/// near x/L 0.227: two runs of about 1 100 steps of 49 000 particles, 331 s on 2 cores, so not run in CI:
/// `cargo test --release --test twodt -- --ignored plunge_instant`.
#[test]
#[ignore]
fn plunge_instant_found_between_checks_is_the_one_a_check_every_step_finds() {
    let cfg = |detect_every| TwoDtConfig {
        fr: 0.55,
        dx: Some(7e-4),
        until: Until::Plunge,
        give_up_at: Some(0.25),
        plunge_circulation: bowwave::twodt::config::PlungeCirculation::Off,
        detect_every,
        ..Default::default()
    };
    let dir = std::env::temp_dir().join(format!("bowwave-refine-test-{}", std::process::id()));
    let fast = run(athena(), &cfg(10), &quiet_options(&dir.join("fast"), false)).expect("run, check every 10");
    let slow = run(athena(), &cfg(1), &quiet_options(&dir.join("slow"), false)).expect("run, check every step");
    let (pf, ps) = (fast.plunge.expect("a plunge"), slow.plunge.expect("a plunge"));
    assert_eq!(pf.x_plunge_over_l.to_bits(), ps.x_plunge_over_l.to_bits());
    assert_eq!(pf.gamma_over_ud.to_bits(), ps.gamma_over_ud.to_bits());
    assert_eq!(fast.steps, slow.steps);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The CLI as a batch job sees it (stderr a file, not a terminal): progress as plain lines, a run halted at
/// its wall-time limit exits with status 3 and a checkpoint, and the same command then goes on to the end
/// (status 0). Before, the progress bars hid themselves in a log, so a job's log said nothing until the end.
#[test]
fn batch_run_logs_plain_progress_and_halts_with_status_3() {
    let dir = std::env::temp_dir().join(format!("bowwave-batch-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let run = |extra: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_bowwave"))
            .args([
                "--threads",
                "1",
                "twodt",
                "--fr",
                "0.64",
                "--dx",
                "4e-3",
                "--until",
                "0.02",
            ])
            .args(["--output-dx", "0.01", "--out"])
            .arg(&dir)
            .args(extra)
            .output()
            .unwrap()
    };
    let halted = run(&["--wall-limit", "0.0001"]);
    let log = String::from_utf8_lossy(&halted.stderr);
    assert_eq!(halted.status.code(), Some(3), "{log}");
    assert!(
        log.contains(": started") && log.contains("halted (stopped at x/L"),
        "{log}"
    );
    assert!(dir.join(bowwave::twodt::checkpoint::FILE).exists());
    let resumed = run(&[]);
    let log = String::from_utf8_lossy(&resumed.stderr);
    assert_eq!(resumed.status.code(), Some(0), "{log}");
    assert!(log.contains(": finished at x/L = 0.02"), "{log}");
    assert!(!dir.join(bowwave::twodt::checkpoint::FILE).exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Water entry against the exact similarity solution (Zhao & Faltinsen 1993, no gravity): a 30° wedge in a
/// tank 4 draughts deep, sampled at Vt = 0.015 L = 7.5 dx. The half-wedge force is within 10 % of the
/// similarity solution's 7.085 ρV³t in both runs: at this spacing it is 6.8–7.4 % high, at dx/L 1e-3 (15 dx)
/// 2.0–2.1 % (`studies/results/wedge-similarity/`), so 10 % is this spacing's error with a margin, not a
/// tolerance that hides a trend. The peak pressure is reported, not asserted (it does not converge yet:
/// +11 % here, +37 % at 15 dx, with the face over-pressured near the apex; see that log).
#[test]
fn wedge_entry_force_approaches_the_similarity_solution() {
    let mut spec = WedgeSpec {
        dx: 2e-3,
        depth_over_draft: 4.0,
        ..Default::default()
    };
    spec.c0 = Some(spec.mach_safe_c0());
    let c = compare(&spec, &[0.015], None).and_then(Ended::ran).expect("wedge runs");
    bowwave::twodt::wedge::print_similarity(&c);
    let exact = c
        .similarity
        .and_then(|s| s.force_coefficient)
        .expect("30° is on record");
    for a in [c.twodt.last().unwrap(), c.rigid.last().unwrap()] {
        let err = a.force_coefficient / exact - 1.0;
        assert!(
            err.abs() < 0.10,
            "force {} against {exact}: {:+.1} %",
            a.force_coefficient,
            100.0 * err
        );
    }
}

/// The bent-wall channel's 2D+t analogue (thesis §10.2.1, `bowwave bent-wall`) at a coarse spacing: the plate
/// that slides and turns keeps every particle on the water's side of it and above the floor, the water rises
/// against it, and the run gives the same bits on 1 and 2 threads.
#[test]
fn bent_wall_keeps_the_water_on_its_side_and_runs_to_the_same_bits_on_any_thread_count() {
    use bowwave::compare3d::bent_wall::{build, profile, run, BentWallOptions};
    use bowwave::geometry::bent_wall::BentWall;
    let opts = BentWallOptions {
        res: 8.0,
        s_end: 0.3,
        frames: 0,
        ..Default::default()
    };
    let (mut sim, width) = build(&opts).unwrap();
    let wall = BentWall { length: opts.length };
    let t_end = opts.s_end * opts.length / opts.fr_h;
    let mut worst: f64 = f64::INFINITY;
    while sim.time < t_end {
        sim.step().unwrap();
        let p = wall.plate(opts.fr_h * sim.time / opts.length, opts.fr_h);
        for x in &sim.fluid.pos {
            worst = worst.min((x - p.foot).dot(&p.normal())).min(x.y);
        }
    }
    assert!(worst > 0.0, "a particle crossed the plate or the floor by {}", -worst);
    assert_eq!(profile(&wall, opts.fr_h, width, 0.0).points.len(), 4);

    let with_threads = |n: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(n).build().unwrap();
        pool.install(|| run(&opts, None, false).unwrap())
    };
    let (a, b) = (with_threads(1), with_threads(2));
    assert!(a.stopped.is_none(), "{:?}", a.stopped);
    let bits = |r: &bowwave::compare3d::bent_wall::BentWallResult| -> Vec<u64> {
        r.samples
            .iter()
            .flat_map(|s| [s.t, s.run_up, s.crest, s.crest_y, s.kinetic].map(f64::to_bits))
            .collect()
    };
    assert_eq!(bits(&a), bits(&b));
    assert!(
        a.samples.last().unwrap().s >= opts.s_end,
        "stopped at s = {}",
        a.samples.last().unwrap().s
    );
    // The plate pushes the water up against it: by s = 0.3 the run-up is above the calm level by more than a
    // spacing.
    let last = a.samples.last().unwrap();
    assert!(
        last.run_up > 1.0 / opts.res,
        "run-up {} H at s = {}",
        last.run_up,
        last.s
    );
}
