//! Validation tier at coarse resolution: the same checks `bowwave validate` runs at full resolution.
//! Tolerances are the (hydrostatic 1 %, elliptic drop 2 %, oscillating drop 3 %, impact time 0.1).

use bowwave::cases::{
    self,
    run::{run, RunOptions},
};
use bowwave::sph::particle_shifting::ParticleShifting;
use bowwave::sph::polyline_wall::GhostKind;
use bowwave::validation::{self, Check};

fn run_case(name: &str, res: f64, end: Option<f64>) -> bowwave::cases::run::RunResult {
    let case = cases::load(name).expect("built-in case parses");
    let r = run(
        &case,
        &RunOptions {
            res: Some(res),
            end_time: end,
            ..Default::default()
        },
    )
    .expect("run");
    assert!(r.blowup.is_none(), "{name} blew up: {:?}", r.blowup);
    r
}

fn assert_checks(checks: &[Check]) {
    validation::print_checks(checks);
    for c in checks {
        assert!(
            c.pass(),
            "{} / {}: error {} above tolerance {:?}",
            c.case,
            c.quantity,
            c.error,
            c.tolerance
        );
    }
}

/// The same tank with image ghosts on its sides and floor (corners fixed): the same checks. Measured
/// 0.52 % (fixed ghosts: 0.57 %).
#[test]
fn hydrostatic_tank_with_image_ghosts_keeps_pressure_and_rest_to_t50() {
    let r = run_with_image_ghosts("hydrostatic", 20.0);
    let c = validation::hydrostatic(&r);
    assert_checks(&c);
    assert!(c[2].error < 0.01, "bottom force / weight off by {}", c[2].error);
}

/// The same tank with normal-flux walls (thesis §7.1.2, divided by the Shepard sum): no ghosts, the same checks.
/// Measured at H/dx 20: bottom pressure 0.50 %, E_K/(M g H) 3.8e-6 (fixed ghosts: 0.57 %, far below 1e-6). The
/// force on the tank, the wall pressure integrated over the nodes, is reported, not asserted: it rings with the
/// tank (1.08 % at the end here, 0.03 % at H/dx 40).
#[test]
fn hydrostatic_tank_with_normal_flux_walls_keeps_pressure_and_rest_to_t50() {
    let r = run_changed("hydrostatic", 20.0, "normal-flux walls", |c| {
        c.set_ghosts(GhostKind::NormalFlux)
    });
    assert!(r.sim.ghosts.geom.is_empty());
    assert_checks(&validation::hydrostatic(&r));
}

#[test]
fn hydrostatic_tank_keeps_pressure_and_rest_to_t50() {
    let r = run_case("hydrostatic", 20.0, None);
    let c = validation::hydrostatic(&r);
    assert_checks(&c);
    // The ghost-particle force on the tank (7.12) carries the weight of the water.
    assert!(c[2].error < 0.01, "bottom force / weight off by {}", c[2].error);
    // Mass is conserved exactly (particles carry fixed masses).
    let m0: f64 = r.sim.fluid.mass.iter().sum();
    assert_eq!(r.sim.fluid.len(), 800);
    assert!(m0 > 0.0);
}

#[test]
fn elliptic_drop_semi_axis_follows_the_ode() {
    let r = run_case("elliptic-drop", 25.0, None);
    assert_checks(&validation::elliptic_drop(&r));
}

#[test]
fn oscillating_drop_follows_the_ode_for_two_periods() {
    let r = run_case("oscillating-drop", 20.0, None);
    let c = validation::oscillating_drop(&r);
    assert_checks(&c);
    // Energy decays (artificial viscosity dissipates), it does not grow.
    assert!(c[1].value < 0.0, "mechanical energy grew: {}", c[1].value);
}

/// The Martin–Moyce column: its residual height at the back wall follows their Table 6 within one marker
/// spacing (1/18 of the column height), and its surge front's speed dZ/dT over Table 2's T in [1.1, 2.5]
/// is within 10 % of theirs (the owner's check, issue #35; the position error, a constant lead from the
/// instantaneous release, is reported beside it). Measured at a/dx 25: height max 0.019; speed 1.200
/// against 1.175 (2.1 %).
#[test]
fn martin_moyce_column_height_and_front_speed_follow_the_experiment() {
    let r = run_case("dam-break-mm", 25.0, None);
    let checks = validation::martin_moyce(&r);
    let checked: Vec<Check> = checks.iter().filter(|c| c.tolerance.is_some()).cloned().collect();
    assert_eq!(checked.len(), 2, "the height and the speed, nothing else checked");
    assert!(checked.iter().any(|c| c.quantity.starts_with("front speed")));
    assert_checks(&checked);
    assert!(checks.iter().all(|c| c.error.is_finite()), "front errors not computed");
}

/// The whole jet on a flat wall (`jet-plate`, no floor): the wall force within 2 % of ρU²h and every sensor's
/// mean Cp within 0.03 of Taylor's free-streamline solution. Measured at b/dx 10 with the default
/// `sun2017-leaving`: force 0.25 %, Cp 0.0165 (the stagnation sensor, 0.983 against 1.000; the band near every
/// wall fails it at b/dx 20, 0.0300, LOG.md session 49). Without the floor the stagnation pressure is right: the
/// excess of `jet-wall` comes from its floor's ghosts (`jet-floor`, studies/results/validation/LOG.md check 11).
#[test]
fn jet_on_a_flat_wall_has_the_free_streamline_pressure() {
    let r = run_case("jet-plate", 10.0, None);
    assert_checks(&validation::jet_plate(&r));
}

/// A built-in case changed by `change` (named `what` in a failure), run at `res` to its end.
fn run_changed(name: &str, res: f64, what: &str, change: impl FnOnce(&mut cases::CaseFile)) -> cases::run::RunResult {
    let mut case = cases::load(name).expect("built-in case parses");
    change(&mut case);
    let r = run(
        &case,
        &RunOptions {
            res: Some(res),
            ..Default::default()
        },
    )
    .expect("run");
    assert!(r.blowup.is_none(), "{name} with {what} blew up: {:?}", r.blowup);
    r
}

fn run_with_image_ghosts(name: &str, res: f64) -> cases::run::RunResult {
    run_changed(name, res, "image ghosts", |c| c.set_ghosts(GhostKind::Images))
}

/// Two half-jets meeting over a floor (`jet-floor`) and a jet into the floor–wall corner (`jet-wall`), with
/// image ghosts on the straight sides (Colagrossi & Landrini 2003): the stagnation sensor, and in the corner
/// every sensor, within [`validation::JET_PLATE_CP_TOLERANCE`] of Taylor's Cp; the corner's force within 2 %.
/// Measured at b/dx 10: jet-floor stagnation 0.983 (fixed ghosts: 2.79); jet-wall corner 0.994 (fixed:
/// 1.70), y/h ≥ 0.3 within 0.012 (fixed: 0.23). At b/dx 20 `bowwave validate jet-floor --ghosts images`
/// passes every sensor (0.014); at b/dx 10 its worst sensor is 0.033 off, so only the stagnation one is held
/// here (studies/results/validation/LOG.md check 12).
#[test]
fn flow_leaving_a_floor_of_image_ghosts_keeps_the_stagnation_pressure() {
    let r = run_with_image_ghosts("jet-floor", 10.0);
    let c = validation::jet_floor(&r);
    let stagnation = &c[1];
    validation::print_checks(&c);
    assert!(stagnation.quantity.contains("stagnation"), "{}", stagnation.quantity);
    assert!(
        stagnation.error <= validation::JET_PLATE_CP_TOLERANCE,
        "stagnation Cp {} against {}",
        stagnation.value,
        stagnation.reference
    );
    let r = run_with_image_ghosts("jet-wall", 10.0);
    let c = validation::jet_wall(&r);
    assert_checks(&c[..1]);
    for k in [1, 2] {
        assert!(
            c[k].error <= validation::JET_PLATE_CP_TOLERANCE,
            "{}: Cp {} against {}",
            c[k].quantity,
            c[k].value,
            c[k].reference
        );
    }
}

/// Regression (issue #35): the fixed ghosts over-read the pressure where the flow leaves a wall (`jet-floor`'s
/// stagnation point: Cp 2.79 against Taylor's 1.00 at b/dx 10) and in the floor–wall corner (`jet-wall`: 1.70),
/// because the particles there drift apart and leave a void over the ghost lattice. With the particle shifting
/// of Sun et al. (2017) both read within 0.05 of 1 at b/dx 10 (jet-floor 1.048, jet-wall 1.048; at b/dx 20
/// 1.034 and 1.004: first order in dx), and the corner's force stays within 2 % (0.19 %). The bound 0.1 is
/// twice the residual at this spacing and a fifteenth of the defect it guards against.
#[test]
fn stagnation_over_pressure_of_fixed_ghosts_is_removed_by_particle_shifting() {
    stagnation_and_corner_read_taylor(ParticleShifting::Sun2017);
}

/// The same with the shift only within two kernel supports of a wall (`sun2017-walls`, the default of a
/// single-phase case in sessions 48–49): the void the defect comes from is at the wall, so the band is enough
/// (measured at b/dx 20: jet-floor 1.000, every sensor within 0.022; jet-wall corner 0.988; the full shift
/// 1.018, 0.019 and 0.994).
#[test]
fn stagnation_over_pressure_of_fixed_ghosts_is_removed_by_shifting_near_the_walls_only() {
    stagnation_and_corner_read_taylor(ParticleShifting::Sun2017Walls);
}

/// The same with that band only where the flow leaves a wall (`sun2017-leaving`, the default of a single-phase
/// case since session 50): both stagnation points in the check are ones the flow leaves the wall from, so the
/// band must still be there (measured at b/dx 10: jet-floor 1.019, every sensor within 0.022; jet-wall force
/// 0.18 %; at b/dx 20 jet-floor 1.006, every sensor within 0.021, jet-wall corner 0.995).
#[test]
fn stagnation_over_pressure_of_fixed_ghosts_is_removed_by_shifting_where_the_flow_leaves_the_walls() {
    for name in ["jet-floor", "jet-wall", "jet-plate"] {
        let case = bowwave::cases::load(name).unwrap();
        assert_eq!(
            case.shifting(),
            ParticleShifting::Sun2017Leaving,
            "{name}: the default walls are tested"
        );
    }
    stagnation_and_corner_read_taylor(ParticleShifting::Sun2017Leaving);
}

fn stagnation_and_corner_read_taylor(shifting: ParticleShifting) {
    let run_with_shifting =
        |name: &str, res: f64| run_changed(name, res, "particle shifting", |c| c.numerics.shifting = Some(shifting));
    let r = run_with_shifting("jet-floor", 10.0);
    let c = validation::jet_floor(&r);
    validation::print_checks(&c);
    let stagnation = &c[1];
    assert!(stagnation.quantity.contains("stagnation"), "{}", stagnation.quantity);
    assert!(
        stagnation.error < 0.1,
        "jet-floor stagnation Cp {} against {}",
        stagnation.value,
        stagnation.reference
    );
    let r = run_with_shifting("jet-wall", 10.0);
    let c = validation::jet_wall(&r);
    assert_checks(&c[..1]);
    validation::print_checks(&c[1..]);
    assert!(c[2].quantity.contains("corner"), "{}", c[2].quantity);
    assert!(
        c[2].error < 0.1,
        "jet-wall corner Cp {} against {}",
        c[2].value,
        c[2].reference
    );
}

/// A plane jet on a wall (the dam break's corner, without gravity): the mean wall force over the steady
/// window equals ρU²b, the momentum theorem, within 2 %. Measured 0.35 % (b/dx 10). The sensors' Cp is
/// reported, not required: it reads above the free-streamline solution and the excess grows with time at
/// the corner (docs/reference/method.md).
#[test]
fn jet_on_a_wall_carries_its_momentum_flux() {
    let r = run_case("jet-wall", 10.0, None);
    let c = validation::jet_wall(&r);
    assert_checks(&c[..1]);
    assert!(c.iter().all(|c| c.error.is_finite()), "a Cp error was not computed");
    // Taylor's curve itself: Cp = 1 at the stagnation point, and ∫Cp dy over one side = h (force ρU²h/2).
    let h = 0.1;
    assert!((validation::taylor_jet_cp(0.0, h) - 1.0).abs() < 1e-12);
    let n = 200_000;
    let dy = 20.0 * h / n as f64;
    let integral: f64 = (0..n)
        .map(|k| validation::taylor_jet_cp((k as f64 + 0.5) * dy, h) * dy)
        .sum();
    assert!((integral / h - 1.0).abs() < 1e-3, "∫Cp dy / h = {}", integral / h);
}

#[test]
fn impact_time_measure_reads_the_published_curves() {
    // The first-impact measure used by `bowwave validate` (first crossing of p/(ρgH) = 0.1 by the signal
    // averaged over 0.05 t√(g/H)), applied to the published data themselves. Our own impact time is not asserted here: at H/dx = 40 it matches Buchner only
    // through a splash spike and at H/dx = 80 it misses both references (docs/reference/method.md), so `validate` reports
    // FAIL for it.
    use bowwave::reference::{col, load, named};
    let m = load("marrone_p1");
    let t = col(&m, 0);
    let rise = |name: &str| validation::impact_time(&t, &named(&m, name));
    assert!((rise("p_over_rho_g_H_deltaSPH_H_over_dx_40") - 2.572).abs() < 0.005);
    assert!((rise("p_over_rho_g_H_deltaSPH_H_over_dx_80") - 2.540).abs() < 0.005);
    assert!((rise("p_over_rho_g_H_deltaSPH_H_over_dx_320") - 2.534).abs() < 0.005);
    let b = load("buchner_p1");
    assert!((validation::impact_time(&col(&b, 0), &col(&b, 1)) - 2.478).abs() < 0.005);
    // The average does not move the raw crossings of these sharp rises by more than 0.005.
    let raw = validation::first_rise(
        &t,
        &named(&m, "p_over_rho_g_H_deltaSPH_H_over_dx_40"),
        validation::IMPACT_LEVEL,
    );
    assert!((raw - rise("p_over_rho_g_H_deltaSPH_H_over_dx_40")).abs() < 0.005);
    // A one-sample spike of 0.3 before the rise is not an impact (one of 2 would still be).
    let ts: Vec<f64> = (0..400).map(|k| 2.0 + 0.01 * k as f64).collect();
    let ps: Vec<f64> = ts
        .iter()
        .map(|&t| {
            if (t - 2.3).abs() < 0.005 {
                0.3
            } else {
                (t - 2.6).clamp(0.0, 1.0) * 3.0
            }
        })
        .collect();
    assert!(validation::first_rise(&ts, &ps, validation::IMPACT_LEVEL) < 2.31);
    let smoothed = validation::impact_time(&ts, &ps);
    assert!((smoothed - 2.633).abs() < 0.02, "{smoothed}");
}

/// The window mean used to sum up P1's rise: exact on a ramp (its midpoint value) whatever the sampling, and
/// NaN when the signal does not cover the window.
#[test]
fn window_mean_of_a_ramp_is_its_midpoint_value() {
    let dense: Vec<f64> = (0..=700).map(|k| 0.01 * k as f64).collect();
    let sparse = vec![0.0, 2.2, 2.71, 3.3, 7.0];
    for t in [dense, sparse] {
        let p: Vec<f64> = t.iter().map(|x| 3.0 * x - 1.0).collect();
        let m = validation::mean_over(&t, &p, 2.5, 3.0);
        assert!((m - (3.0 * 2.75 - 1.0)).abs() < 1e-12, "{m}");
    }
    let short = [2.6, 3.0];
    assert!(validation::mean_over(&short, &[1.0, 1.0], 2.5, 3.0).is_nan());
}

/// OpenFOAM's interFoam run of the dam break (H/dx 80, free slip, tools/foam-dam-break/), as embedded: samples
/// 0.005 t√(g/H) apart from 0, and the three quantities `validate dam-break` reports against it as reduce.py
/// printed them: P1's first impact 2.726, P1's mean over [`validation::P1_RISE_WINDOW`] 0.114 and P0's over
/// [`validation::CORNER_WINDOW`] 1.131 ρgH (studies/results/validation/LOG.md, session 42).
#[test]
fn openfoam_reference_reads_as_reduced() {
    use bowwave::reference::{col, load, named};
    let f = load("openfoam_wall_sensors");
    let t = col(&f, 0);
    assert!(t.len() > 700, "{} samples", t.len());
    for (k, tk) in t.iter().enumerate() {
        assert!((tk - 0.005 * k as f64).abs() < 1e-9, "t*[{k}] = {tk}");
    }
    let p1 = named(&f, "P1");
    let impact = validation::impact_time(&t, &p1);
    assert!((impact - 2.726).abs() < 0.005, "{impact}");
    let (from, to) = validation::P1_RISE_WINDOW;
    let rise = validation::mean_over(&t, &p1, from, to);
    assert!((rise - 0.1139).abs() < 5e-4, "{rise}");
    let (from, to) = validation::CORNER_WINDOW;
    let corner = validation::mean_over(&t, &named(&f, "P0"), from, to);
    assert!((corner - 1.1307).abs() < 5e-4, "{corner}");
}

/// TrixiParticles' reference runs at P1's centre, as embedded (`data/reference/`, transcribed from their JSON
/// files): 701 samples 0.01 t√(g/H) apart from 0 to 7, water at the sensor from t* = 2.46 in both runs (the
/// impact), and their rise converged between H/dx 80 and 400: means over [`validation::P1_RISE_WINDOW`] of
/// 0.0737 and 0.0720 ρgH, where Marrone's P1 curves give 0.455 (H/dx 40), 0.502 (80) and 0.533 (320).
#[test]
fn trixiparticles_p1_centre_reference_reads_as_transcribed() {
    use bowwave::reference::{col, load, named};
    let (from, to) = validation::P1_RISE_WINDOW;
    let mut means = vec![];
    for res in [80.0, 400.0] {
        let (n, t, p) = validation::trixi_p1_centre(res);
        assert_eq!(n as f64, res);
        assert_eq!(t.len(), 701);
        for (k, tk) in t.iter().enumerate() {
            assert!((tk - 0.01 * k as f64).abs() < 1e-9, "t*[{k}] = {tk}");
        }
        let wet = p.iter().position(|&v| v != 0.0).unwrap();
        assert_eq!(wet, 246, "first non-zero sample");
        means.push(validation::mean_over(&t, &p, from, to));
    }
    assert!(
        (means[0] - 0.0737).abs() < 5e-4 && (means[1] - 0.0720).abs() < 5e-4,
        "{means:?}"
    );
    // The nearer run is picked by resolution (in log; they meet at √(80 · 400) ≈ 179): H/dx 40 and 170 read
    // the 80 run, 200 the 400 one.
    assert_eq!(validation::trixi_p1_centre(40.0).0, 80);
    assert_eq!(validation::trixi_p1_centre(170.0).0, 80);
    assert_eq!(validation::trixi_p1_centre(200.0).0, 400);
    let m = load("marrone_p1");
    let marrone = |c: &str| validation::mean_over(&col(&m, 0), &named(&m, c), from, to);
    assert!((marrone("p_over_rho_g_H_deltaSPH_H_over_dx_80") - 0.502).abs() < 5e-3);
}

#[test]
fn dam_break_energy_loss_before_impact_decreases_with_resolution() {
    let end = 2.3 * (0.6f64 / 9.81).sqrt();
    let loss = |res: f64| {
        let r = run_case("dam-break", res, Some(end));
        let de = r.series.column("de_mechanical_rel").unwrap();
        -*de.last().unwrap()
    };
    let (l20, l40) = (loss(20.0), loss(40.0));
    println!(
        "mechanical energy lost by t* = 2.3: H/dx=20: {l20:.3e}, H/dx=40: {l40:.3e}, order {:.2}",
        (l20 / l40).log2()
    );
    assert!(l20 > 0.0 && l40 > 0.0, "energy must be dissipated, not created");
    assert!(l40 < l20, "loss does not decrease with resolution: {l20} -> {l40}");
}

/// The plunge detection on a simulated breaker: the wave that falls back from the dam-break run-up closes an
/// air cavity at t√(g/H) = 6.0 in the thesis (§8.4); the cavity probe (the 2D+t plunge definitions) must
/// find it within 0.2 (the tolerance of `bowwave validate`), overturning towards −x, so with a
/// counter-clockwise (negative) circulation. Measured: t* = 6.067 (H/dx 20), 6.047 (40).
#[test]
fn dam_break_plunging_wave_closes_its_cavity_when_the_thesis_says() {
    let end = 6.5 * (0.6f64 / 9.81).sqrt();
    let r = run_case("dam-break", 20.0, Some(end));
    let c = r.cavity.as_ref().expect("no cavity closed by t* = 6.5");
    let t_star = c.time / (0.6f64 / 9.81).sqrt();
    println!("{}", validation::cavity_summary(&r).unwrap());
    assert!(
        (t_star - validation::CAVITY_CLOSURE_T_STAR).abs() <= 0.2,
        "closure at t* = {t_star}"
    );
    assert!(c.circulation < 0.0, "circulation {}", c.circulation);
    // The same run's reported pressure checks, among them P1's rise against Marrone, P1's centre against
    // TrixiParticles, P1/P2 at Greco's placement and the corner's first impact (P0), are computed (they carry no tolerance: docs/reference/method.md,
    // checks 12–14 and "Two checks for the owner to decide").
    let checks = validation::dam_break(&r);
    validation::print_checks(&checks);
    for key in [
        "(the rise) vs Marrone",
        "P1c (8.4 mm) mean |p-p_ref|",
        "P1c mean p* over t*",
        "P1g (Greco's placement) first impact",
        "P2g (Greco's placement) mean",
        "P0 (90 mm, bottom of the right wall) first impact",
    ] {
        let c = checks
            .iter()
            .find(|c| c.quantity.contains(key))
            .unwrap_or_else(|| panic!("no check `{key}`"));
        assert!(c.error.is_finite(), "{}: {}", c.quantity, c.error);
    }
}

/// Issue #36: a user's experiment as a case file with its own references (`cases/examples/dam-break-buchner.toml`,
/// Buchner's P1 and P2) runs and is compared end to end: a mean-error, a peak, an impulse and a first-crossing
/// row per reference, with finite numbers, the P2 comparison under the case's declared tolerance (0.1 ρgH; measured 0.052 at H/dx 20),
/// and a plot per reference. Not a built-in's name, so no built-in check applies.
#[test]
fn a_case_file_with_references_is_compared_end_to_end() {
    let case = cases::CaseFile::read(std::path::Path::new("cases/examples/dam-break-buchner.toml")).unwrap();
    assert_eq!(validation::builtin_experiment(&case), None);
    let out = std::env::temp_dir().join(format!("bowwave-example-refs-{}", std::process::id()));
    std::fs::create_dir_all(&out).unwrap();
    let r = run(
        &case,
        &RunOptions {
            res: Some(20.0),
            ..Default::default()
        },
    )
    .unwrap();
    let checks = validation::checks(&r).expect("the references give checks");
    assert_eq!(checks.len(), 8, "{checks:?}");
    assert!(checks.iter().all(|c| c.error.is_finite()), "{checks:?}");
    let p2 = checks
        .iter()
        .find(|c| c.quantity.starts_with("pstar_P2") && c.tolerance.is_some())
        .unwrap();
    assert!(p2.pass(), "{p2:?}");
    let plots = validation::plots(&r, &out).unwrap();
    assert!(
        plots
            .iter()
            .any(|p| p.ends_with("dam-break-buchner_reference1_pstar_P2.png")),
        "{plots:?}"
    );
    let _ = std::fs::remove_dir_all(&out);
}

/// The multi-fluid δ-SPH of Hammani et al. (issue #32) with one phase and the integrated density computes the
/// single-phase δ-SPH term by term: the dam break's state after 0.3 s is the same to the bit (issue #32's
/// first check, P1 and P2 within 0.03 ρgH, with a difference of 0).
#[test]
fn one_phase_through_the_multi_fluid_path_gives_the_single_phase_bits() {
    let a = run_case("dam-break", 20.0, Some(0.3));
    let b = run_changed("dam-break", 20.0, "multi-fluid path", |c| {
        c.multi_fluid.with_one_phase = true;
        c.output.end_time = 0.3;
    });
    assert!(b.sim.cfg.multi_fluid.is_some() && a.sim.cfg.multi_fluid.is_none());
    assert_eq!(a.sim.steps, b.sim.steps);
    assert_eq!(a.sim.fluid.pos, b.sim.fluid.pos);
    assert_eq!(a.sim.fluid.vel, b.sim.fluid.vel);
    assert_eq!(a.sim.fluid.rho, b.sim.fluid.rho);
}

/// Water under air (density ratio 1000) at rest in a closed tank, H/dx 10, to t√(g/H) 50 (Hammani et al.
/// §III.A): no void at the interface (a gap below two spacings), E_K/(MgH) below 1e-6, and the wall sensors on
/// the floor and the lid within 1 % of ρ_w g H, the single-phase hydrostatic tank's tolerance for the same
/// sensor (`validation::hydrostatic`). The particles' mean pressure errors are reported: 1.11 % (water) and
/// 0.91 % (air) here, 0.35 % and 0.09 % at `validate`'s H/dx 20, where they are checked at 0.5 %.
#[test]
fn two_layer_tank_stays_at_rest_with_the_hydrostatic_pressure() {
    let r = run_case("two-layer", 10.0, None);
    let checks = validation::two_layer(&r, 0.01, None);
    assert_eq!(checks.iter().filter(|c| c.tolerance.is_some()).count(), 4);
    assert_checks(&checks);
}

/// The two-fluid drop at density ratio 2 (Hammani et al. §III.B.2; R/dx 20, one period): semi-axis within 1 %
/// and centre pressure within 5 % of the exact solution. Measured 0.42 % and 3.1 %. (Ratio 100 meets the 1 % only
/// at R/dx 80, 0.85 %: `bowwave validate two-phase-drop-100`, 38 min on 2 threads, too long for CI.)
#[test]
fn two_phase_drop_at_density_ratio_2_follows_the_exact_solution() {
    let r = run_case("two-phase-drop-2", 20.0, None);
    let checks = validation::two_phase_drop(&r);
    assert_eq!(checks.iter().filter(|c| c.tolerance.is_some()).count(), 2);
    assert_checks(&checks);
}

/// The Rayleigh–Taylor start (`cases/rayleigh-taylor.toml`, issue #32): at H'/dx 20 the two blocks cut by the
/// curve y = 1 − 0.15 sin 2πx fill the 20 × 40 lattice once (no point in both, none left out), the light fluid
/// below the curve and the heavy one above, and each particle starts with the two-layer hydrostatic pressure
/// (heavy: 1.8 g (2 − y); light: the heavy column's weight at its x plus 1.0 g (y_c − y)), so that the pressure
/// is continuous across the interface.
#[test]
fn rayleigh_taylor_starts_with_a_sinusoidal_interface_and_the_two_layer_pressure() {
    let case = bowwave::cases::case_file::CaseFile::read(std::path::Path::new("cases/rayleigh-taylor.toml")).unwrap();
    let sim = bowwave::cases::setup::build(&case, Some(20.0)).unwrap();
    let f = &sim.fluid;
    assert_eq!(f.pos.len(), 800);
    let curve = |x: f64| 1.0 - 0.15 * (2.0 * std::f64::consts::PI * x).sin();
    let p = sim.state_pressures();
    let mut worst = 0.0f64;
    for ((pos, &phase), &p) in f.pos.iter().zip(&f.phase).zip(&p) {
        let (x, y) = (pos.x, pos.y);
        let (heavy, yc) = (phase == 0, curve(x));
        assert_eq!(heavy, y >= yc, "particle at ({x}, {y}) of phase {phase}");
        let exact = if heavy {
            1.8 * (2.0 - y)
        } else {
            1.8 * (2.0 - yc) + (yc - y)
        };
        worst = worst.max((p - exact).abs());
    }
    assert!(
        worst < 1e-9 * 3.6,
        "largest departure from the two-layer pressure {worst} Pa"
    );
}

/// `converge` on a case without references (issue #32's Rayleigh–Taylor, item 5): the interface tips at each
/// whole t√(g/L) are converged on their own values. A tip is one particle's position, known to about a spacing,
/// so the check is that two successive resolutions (H'/dx 10, 20, 40, to t = 3) place each tip within the
/// coarser one's spacing at every sampled time. Measured at 20, 40 and 80 (session 32, `studies/results/
/// rayleigh-taylor/`): the bubble converges with order 1.5–5.7, the spike to t = 2, then within one spacing.
#[test]
fn rayleigh_taylor_tips_agree_within_a_spacing_between_resolutions() {
    let case = bowwave::cases::case_file::CaseFile::read(std::path::Path::new("cases/rayleigh-taylor.toml")).unwrap();
    let res = [10.0, 20.0, 40.0];
    let c = bowwave::methods::convergence::converge(&case, &res, Some(3.0)).unwrap();
    let names: Vec<&str> = c.quantities.iter().map(|q| q.name.as_str()).collect();
    assert_eq!(names.len(), 6, "{names:?}");
    for q in &c.quantities {
        assert!(
            q.values.iter().all(|v| v.1.is_nan()),
            "{}: no reference, no error",
            q.name
        );
        for k in 1..res.len() {
            let (coarse, fine) = (q.values[k - 1].0, q.values[k].0);
            assert!(
                (fine - coarse).abs() < 1.0 / res[k - 1],
                "{}: {coarse} at H'/dx {} against {fine}",
                q.name,
                res[k - 1]
            );
        }
    }
    let spike = c
        .quantities
        .iter()
        .find(|q| q.name == "spike_y (m) at t√(g/L) = 3")
        .unwrap();
    assert!(
        spike.values.iter().all(|v| (0.0..0.85).contains(&v.0)),
        "the spike has fallen"
    );
}

/// Stokes' first problem (`stokes-wall`, depth/dx 20): a layer sliding over a no-slip floor (thesis §7.1.3,
/// physical viscosity) grows the shear layer U erf(y / 2√(νt)) within 0.03 U (measured 0.017); the same layer
/// over a free-slip floor keeps U, so the check tells the two conditions apart.
#[test]
fn a_layer_sliding_over_a_no_slip_floor_grows_stokes_shear_layer() {
    let r = run_case("stokes-wall", 20.0, None);
    let checks = validation::checks(&r).expect("stokes-wall is checked");
    assert_checks(&checks);
    let free = run_changed("stokes-wall", 20.0, "free slip", |c| {
        c.numerics.wall_slip = bowwave::sph::equations::ghost_conditions::WallSlip::FreeSlip;
    });
    let profile = &validation::checks(&free).unwrap()[0];
    assert!(
        profile.error > 0.5,
        "a free-slip floor should leave the layer at U: profile error {}",
        profile.error
    );
}
