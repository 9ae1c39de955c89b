//! A blown-up run stops with a diagnosis and keeps its last good state; bad case files get clear errors.

use bowwave::cases::{
    self,
    run::{run, RunOptions},
    CaseFile,
};
use bowwave::sph::solver::BlowUpReason;

#[test]
fn cfl_far_above_the_stable_limit_stops_with_a_diagnosis() {
    // The predictor–corrector at CFL 2.5 (5× its default) creates energy (+0.56 MgH) and, depending on
    // round-off, throws particles out or runs to the end with a pressure noise of 2 ρgH; either way the
    // run must stop with a diagnosis.
    let text = cases::builtin::builtin_text("dam-break").unwrap().replace(
        "integrator = \"rk4\"",
        "integrator = \"predictor-corrector\"\ncfl = 2.5",
    );
    let case = CaseFile::parse(&text, "unstable").unwrap();
    let r = run(
        &case,
        &RunOptions {
            res: Some(20.0),
            ..Default::default()
        },
    )
    .unwrap();
    let b = r.blowup.expect("an unstable CFL must be detected");
    println!("diagnosis: {b}");
    assert!(matches!(
        b.reason,
        BlowUpReason::NotFinite
            | BlowUpReason::LeftDomain
            | BlowUpReason::TimeStepCollapse { .. }
            | BlowUpReason::EnergyGrowth { .. }
    ));
    assert!(b.to_string().contains("t = "));
    // The kept state is the last good one: finite and inside the domain.
    for p in &r.sim.fluid.pos {
        assert!(p.x.is_finite() && p.y.is_finite() && p.x > -0.3 && p.x < 3.52 && p.y > -0.3);
    }
    assert!(r.sim.time < case.output.end_time);
}

/// Regression: RK4 at CFL 4 (twice its default) never produced a NaN or a lost particle, so it ran to the end
/// and its noisy result (pressure noise 0.52 ρgH against 0.11) was reported as a normal run. Its mechanical
/// energy rises by 4.9e-3 MgH at t√(g/H) ≈ 0.18, which the case runner now diagnoses.
#[test]
fn unstable_cfl_that_never_produces_nan_is_still_diagnosed() {
    let dam = cases::builtin::builtin_text("dam-break").unwrap();
    let with_cfl = |cfl: f64| {
        let text = dam.replace("integrator = \"rk4\"", &format!("integrator = \"rk4\"\ncfl = {cfl}"));
        let case = CaseFile::parse(&text, "cfl").unwrap();
        run(
            &case,
            &RunOptions {
                res: Some(20.0),
                end_time: Some(0.5 * (0.6f64 / 9.81).sqrt()),
                ..Default::default()
            },
        )
        .unwrap()
    };
    let unstable = with_cfl(4.0);
    let b = unstable.blowup.expect("RK4 at CFL 4 gains energy and must be stopped");
    let BlowUpReason::EnergyGrowth { gain, limit } = b.reason else {
        panic!("expected an energy-growth diagnosis, got {b}");
    };
    assert!(gain > limit && b.to_string().contains("mechanical energy grew"));
    // The default CFL on the same case and interval is not stopped.
    assert!(with_cfl(2.0).blowup.is_none());
}

fn err_of(text: &str) -> String {
    CaseFile::parse(text, "bad.toml")
        .expect_err("must be rejected")
        .to_string()
}

/// Each (case text, field) is refused with an error naming the file and the field.
fn assert_each_refused_naming(cases: &[(String, &str)]) {
    for (text, needle) in cases {
        let e = err_of(text);
        println!("{e}");
        assert!(e.contains("bad.toml"), "error does not name the file: {e}");
        assert!(e.contains(needle), "error does not name `{needle}`: {e}");
    }
}

/// Issue #32's bad input for phases: each is refused before anything runs, naming the field.
#[test]
fn bad_phases_name_the_field() {
    let good = cases::builtin::builtin_text("two-layer").unwrap();
    CaseFile::parse(good, "two-layer.toml").expect("the built-in parses");
    let cases = [
        (good.replace("phase = \"air\"", "phase = \"steam\""), "blocks[1].phase"),
        (good.replace("name = \"air\"", "name = \"water\""), "phases[0].name"),
        (good.replace("rho0 = 1.0", "rho0 = 1e-3"), "phases[0].rho0"),
        (good.replace("gamma = 1.4", "gamma = 1.4\nc0 = 1.0"), "phases[0].c0"),
        (good.replace("gamma = 1.4", "gamma = 0.5"), "phases[0].gamma"),
        (good.replace("max = [2.0, 1.0]", "max = [2.0, 1.2]"), "blocks[1]"),
        (good.replace("phase = \"air\"", "phase = \"water\""), "phases[0]"),
        (
            good.replace("background_pressure = 982.0", "background_pressure = 0.0"),
            "multi_fluid.background_pressure",
        ),
        (
            good.replace("[1.0, 2.0]]", "[1.2, 2.0]]"),
            "multi_fluid.background_pressure",
        ),
        (
            good.replace("background_pressure = 982.0", "background_pressure = -1.0"),
            "multi_fluid.background_pressure",
        ),
        (
            format!("{good}\n[numerics]\nshifting = \"sun2017\"\n"),
            "numerics.shifting",
        ),
    ];
    assert_each_refused_naming(&cases);
}

/// Regression (session 43): particle shifting with several phases moved particles across the interface (the
/// two-layer tank's floor 0.49 ρ_w g H off, the 2D+t still tank with air stirred to E_K/(MgD) 1.9e-4). It is
/// refused wherever it can be asked for: a case file (above), `--shifting` on a case with phases, and a 2D+t
/// run with an air layer.
/// A normal-flux wall in a case with several phases is refused by name before anything runs (its terms are
/// single phase; the solver would otherwise stop on its own assertion).
#[test]
fn normal_flux_walls_with_several_phases_are_refused() {
    let mut case = cases::load("two-layer").unwrap();
    case.set_ghosts(bowwave::sph::polyline_wall::GhostKind::NormalFlux);
    let e = match run(&case, &RunOptions::default()) {
        Err(e) => e.to_string(),
        Ok(_) => panic!("a two-phase case with normal-flux walls ran"),
    };
    assert!(
        e.contains("walls[0].ghosts") && e.contains("two-layer") && e.contains("phases"),
        "{e}"
    );
}

#[test]
fn particle_shifting_with_several_phases_is_refused() {
    use bowwave::cases::overrides::CaseOverrides;
    use bowwave::sph::particle_shifting::ParticleShifting;
    let mut case = cases::load("two-layer").unwrap();
    let shift = CaseOverrides {
        shifting: Some(ParticleShifting::Sun2017),
        ..Default::default()
    };
    let e = shift.apply(&mut case).expect_err("shifting with phases").to_string();
    assert!(e.contains("--shifting") && e.contains("two-layer"), "{e}");
    assert_eq!(case.numerics.shifting, None, "refused, so unchanged");
    assert_eq!(
        case.shifting(),
        ParticleShifting::None,
        "with phases the default is none"
    );
    let none = CaseOverrides {
        shifting: Some(ParticleShifting::None),
        ..Default::default()
    };
    none.apply(&mut case).expect("`none` is what is expected");
    let cfg = bowwave::twodt::config::TwoDtConfig {
        air: Some(1.5),
        shifting: Some(ParticleShifting::Sun2017Walls),
        ..Default::default()
    };
    let e = cfg.check().expect_err("an air layer with shifting");
    assert_eq!(e.option, bowwave::twodt::config::ConfigOption::Air, "{e}");
    let air = bowwave::twodt::config::TwoDtConfig { shifting: None, ..cfg };
    air.check().expect("an air layer with the default shifting");
    assert_eq!(air.shifting(), ParticleShifting::None, "with air the default is none");
}

#[test]
fn bad_case_files_name_the_file_and_field() {
    let good = cases::builtin::builtin_text("hydrostatic").unwrap();
    let cases = [
        (good.replace("rho0 = 1000.0", "rho0 = -1.0"), "fluid.rho0"),
        (
            good.replace(
                "c0_over_sqrt_g_length = 10.0",
                "c0_over_sqrt_g_length = 10.0\nc0 = 30.0",
            ),
            "fluid.c0",
        ),
        (good.replace("resolution = 20", "resolution = 0"), "scales.resolution"),
        (good.replace("end_time = 15.97", "end_time = -2"), "output.end_time"),
        (
            good.replace(
                "points = [[0.0, 1.5], [0.0, 0.0], [2.0, 0.0], [2.0, 1.5]]",
                "points = [[0.0, 1.5]]",
            ),
            "walls[0].points",
        ),
        (good.replace("max = [2.0, 1.0]", "max = [-2.0, 1.0]"), "blocks[0]"),
        (good.replace("g = [0.0, -9.81]", "g = [0.0]"), "body_force.g"),
        (
            good.replace("name = \"hydrostatic\"", "name = \"hydrostatic\"\ndimension = 3"),
            "dimension",
        ),
        (
            good.replace("integrator = \"rk4\"", "integrator = \"euler\""),
            "unknown variant",
        ),
        (good.replace("[output]", "[output]\nfoo = 1"), "unknown field"),
        (
            good.replace("direction = [1.0, 0.0]", "direction = [2.0, 0.0]"),
            "probes.pressure[0]",
        ),
        (
            good.replace("[output]", "[probes.cavity]\nafter = -1.0\n\n[output]"),
            "probes.cavity.after",
        ),
        // Found by tests/fuzzed_input.rs: what lies outside the domain used to pass, and a block at 1e6 m
        // sized the neighbour search past what memory holds.
        (
            good.replace("max = [2.0, 1.0]", "max = [2.0, 1e6]"),
            "a rectangle inside the domain",
        ),
        (
            good.replace("[2.0, 0.0], [2.0, 1.5]]", "[2.0, 0.0], [2.0, 1e6]]"),
            "walls[0].points",
        ),
        // Issue #36: a gauge outside the tank and a wall sensor outside the domain were accepted silently.
        (
            good.replace("[output]", "[[probes.gauge]]\nname = \"g\"\nx = 7.0\n\n[output]"),
            "probes.gauge[0].x",
        ),
        (
            good.replace(
                "[output]",
                "[[probes.gauge]]\nname = \"g\"\nx = 1.0\nbottom = -9.0\n\n[output]",
            ),
            "probes.gauge[0].bottom",
        ),
        (
            good.replace("position = [1.0, 0.0]", "position = [1.0, 50.0]"),
            "probes.pressure[0].position",
        ),
    ];
    assert_each_refused_naming(&cases);
}

/// Regression (found by tests/fuzzed_input.rs): a case whose spacing leaves a block without a particle
/// (`scales.length = 1e300`) failed to allocate its wall ghosts ("capacity overflow"), and one that asks
/// for more particles than memory holds would abort; both are now errors that name the case and the cause,
/// given before anything is allocated.
#[test]
fn case_too_coarse_or_too_large_for_its_resolution_is_refused_before_allocating() {
    let good = cases::builtin::builtin_text("hydrostatic").unwrap();
    let build_err = |text: &str, res: Option<f64>| {
        let case = CaseFile::parse(text, "size.toml").unwrap();
        format!("{:#}", cases::setup::build(&case, res).err().expect("must be refused"))
    };
    let e = build_err(&good.replace("length = 1.0 ", "length = 1e300 "), None);
    assert!(
        e.contains("`hydrostatic`") && e.contains("blocks[0]") && e.contains("one spacing"),
        "{e}"
    );
    let e = build_err(good, Some(1e5));
    assert!(
        e.contains("`hydrostatic`") && e.contains("particles") && e.contains("at most"),
        "{e}"
    );
    let e = build_err(good, Some(0.0));
    assert!(e.contains("`hydrostatic`") && e.contains("resolution"), "{e}");
    // The case itself builds at its own resolution.
    let case = CaseFile::parse(good, "size.toml").unwrap();
    assert!(cases::setup::build(&case, None).is_ok());
}

/// Regression: `bowwave run --end -1` (or NaN) ran no step and wrote its series and plots as if the run
/// were done.
#[test]
fn end_time_that_is_not_positive_is_refused() {
    let case = CaseFile::parse(cases::builtin::builtin_text("hydrostatic").unwrap(), "end.toml").unwrap();
    for end in [-1.0, 0.0, f64::NAN] {
        let opts = RunOptions {
            res: Some(10.0),
            end_time: Some(end),
            ..Default::default()
        };
        let e = format!("{:#}", run(&case, &opts).err().expect("must be refused"));
        assert!(e.contains("`hydrostatic`") && e.contains("end time"), "{end}: {e}");
    }
}

#[test]
fn unknown_case_name_lists_the_built_ins() {
    let e = cases::load("no-such-case").unwrap_err().to_string();
    assert!(e.contains("dam-break") && e.contains("hydrostatic"), "{e}");
}

/// Regression (issue #36): a user's case that kept `name = "dam-break"` from the printed built-in but had its
/// own sensors ran to the end, then panicked with "series column `pstar_P1` missing" (exit 101): checks and
/// plots were chosen by the name. Now a built-in's checks apply only to a case that declares the built-in's
/// experiment; this one runs, writes its outputs and says it has no checks.
#[test]
fn a_case_named_like_a_built_in_with_other_probes_runs_without_its_checks() {
    let text = cases::builtin::builtin_text("dam-break")
        .unwrap()
        .replace("name = \"P1\"", "name = \"S1\"")
        .replace("name = \"P2\"", "name = \"S2\"");
    let case = CaseFile::parse(&text, "mine.toml").unwrap();
    assert_eq!(case.name, "dam-break");
    assert_eq!(bowwave::validation::builtin_experiment(&case), None);
    assert_eq!(
        bowwave::validation::builtin_experiment(&cases::load("dam-break").unwrap()),
        Some("dam-break")
    );
    let out = std::env::temp_dir().join(format!("bowwave-named-like-builtin-{}", std::process::id()));
    let opts = RunOptions {
        res: Some(8.0),
        end_time: Some(0.05),
        ..Default::default()
    };
    let status = bowwave::validation::run_and_report(&case, &out, opts).expect("runs");
    assert_eq!(status, 0);
    assert!(out.join("dam-break_energy.png").exists());
    let _ = std::fs::remove_dir_all(&out);
}

/// Issue #36: a case's times may be written in its own non-dimensional time t* = t √(g/length); they are the
/// same run as the times in seconds.
#[test]
fn times_in_t_star_are_read_as_seconds() {
    let good = cases::builtin::builtin_text("hydrostatic").unwrap();
    let secs = CaseFile::parse(good, "s.toml").unwrap();
    let f = (secs.scales.length / secs.gravity_magnitude()).sqrt();
    let star = good
        .replace(
            &format!("end_time = {}", secs.output.end_time),
            &format!("end_time = {}\ntime_unit = \"t_star\"", secs.output.end_time / f),
        )
        .replace(
            &format!("series_every = {}", secs.output.series_every),
            &format!("series_every = {}", secs.output.series_every / f),
        );
    assert!(star.contains("t_star"), "the replacement found its line");
    let star = CaseFile::parse(&star, "star.toml").unwrap();
    assert!((star.output.end_time - secs.output.end_time).abs() < 1e-12 * secs.output.end_time);
    assert!((star.output.series_every - secs.output.series_every).abs() < 1e-12 * secs.output.series_every);
    let e = err_of(&good.replace("[output]", "[output]\ntime_unit = \"minutes\""));
    assert!(e.contains("time_unit") || e.contains("unknown variant"), "{e}");
}

/// Issue #36: a case's own references are checked when the case is read: a column no probe writes, and a
/// missing or malformed file, are errors naming the field.
#[test]
fn references_name_a_probe_column_and_a_readable_file() {
    let dir = std::env::temp_dir().join(format!("bowwave-refs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = cases::builtin::builtin_text("hydrostatic").unwrap();
    let with = |column: &str, file: &str| format!("{good}\n[[references]]\ncolumn = \"{column}\"\nfile = \"{file}\"\n");
    let e = err_of(&with("pstar_nowhere", "r.csv"));
    assert!(e.contains("references[0].column") && e.contains("pstar_bottom"), "{e}");
    let case = dir.join("case.toml");
    std::fs::write(&case, with("pstar_bottom", "missing.csv")).unwrap();
    let e = CaseFile::read(&case).unwrap_err().to_string();
    assert!(e.contains("references[0].file") && e.contains("missing.csv"), "{e}");
    std::fs::write(dir.join("bad.csv"), "time,value\nabc,def\n").unwrap();
    std::fs::write(&case, with("pstar_bottom", "bad.csv")).unwrap();
    let e = CaseFile::read(&case).unwrap_err().to_string();
    assert!(
        e.contains("references[0].file") && e.contains("two numeric columns"),
        "{e}"
    );
    std::fs::write(dir.join("ok.csv"), "# t*, p*\n0, 1\n10, 1\n").unwrap();
    std::fs::write(&case, with("pstar_bottom", "ok.csv")).unwrap();
    assert_eq!(CaseFile::read(&case).unwrap().references.len(), 1);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A block's cut curve (the Rayleigh–Taylor interface) needs a positive wavelength, and two blocks of different
/// phases cut by different curves, or on the same side of one, overlap and are refused.
#[test]
fn a_cut_block_needs_a_wavelength_and_blocks_cut_apart_must_be_cut_by_one_curve() {
    let rt = std::fs::read_to_string("cases/rayleigh-taylor.toml").unwrap();
    let e = err_of(&rt.replace("wavelength = 1.0", "wavelength = 0.0"));
    assert!(e.contains("blocks[0].cut") && e.contains("wavelength"), "{e}");
    let e = err_of(&rt.replacen("keep = \"above\"", "keep = \"below\"", 1));
    assert!(e.contains("blocks[1]") && e.contains("overlap"), "{e}");
    let e = err_of(&rt.replacen(
        "amplitude = -0.15, wavelength = 1.0, keep = \"above\"",
        "amplitude = -0.10, wavelength = 1.0, keep = \"above\"",
        1,
    ));
    assert!(e.contains("blocks[1]") && e.contains("overlap"), "{e}");
}

/// Regression: a time-step collapse said neither where nor which particle (the 3D bent-wall channel at H/dx 6
/// stopped with "time step collapsed … at t = 4.813371 s" and nothing to look at). It now names the particle of
/// the largest acceleration, with its position, and keeps the state before the step.
#[test]
fn time_step_collapse_names_the_particle_of_the_largest_acceleration() {
    let case = cases::load("dam-break").unwrap();
    let mut sim = bowwave::cases::setup::build(&case, Some(10.0)).unwrap();
    let before = sim.fluid.pos.clone();
    // A floor above any step this case takes: the first step collapses.
    sim.cfg.dt_floor = 1.0;
    let b = sim.step().expect_err("a floor of 1 s must stop the first step");
    assert!(matches!(b.reason, BlowUpReason::TimeStepCollapse { .. }), "{b}");
    let (id, at) = b.particle.clone().expect("the collapse names a particle");
    let i = sim.fluid.id.iter().position(|&k| k == id).unwrap();
    assert_eq!(at, sim.fluid.pos[i].iter().copied().collect::<Vec<_>>());
    assert!(b.to_string().contains(&format!("particle {id} at")), "{b}");
    let mut kept = sim.fluid.pos.clone();
    let mut start = before;
    let key = |p: &nalgebra::Vector2<f64>| (p.x.to_bits(), p.y.to_bits());
    kept.sort_by_key(key);
    start.sort_by_key(key);
    assert_eq!(kept, start, "the state before the step is kept");
}

/// Regression: `--wall-limit` (and `--checkpoint-every`) of more minutes than a `Duration` holds panicked in
/// `Duration::from_secs_f64`; now an error naming the option. A limit a `Duration` holds but the clock cannot
/// reach (1e15 minutes) means no limit instead of an overflow of the deadline.
#[test]
fn a_wall_limit_too_large_for_a_clock_is_an_error_not_a_panic() {
    let out = std::env::temp_dir().join(format!("bowwave-huge-limit-{}", std::process::id()));
    let run = |limit: &str| {
        std::process::Command::new(env!("CARGO_BIN_EXE_bowwave"))
            .args([
                "wedge",
                "--dx",
                "3e-3",
                "--at",
                "0.005",
                "--checkpoint-every",
                "0",
                "--wall-limit",
                limit,
                "--out",
            ])
            .arg(&out)
            .output()
            .expect("bowwave runs")
    };
    let huge = run("1e300");
    let err = String::from_utf8_lossy(&huge.stderr);
    assert_eq!(huge.status.code(), Some(1), "{err}");
    assert!(err.contains("--wall-limit") && err.contains("expected"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    let far = run("1e15");
    assert!(far.status.success(), "{}", String::from_utf8_lossy(&far.stderr));
    std::fs::remove_dir_all(&out).ok();
}
