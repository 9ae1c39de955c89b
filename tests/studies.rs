//! Study files and the study runner: errors name the file and the field; finished cases are recognised and
//! skipped (resumable), one case can be run alone, and the collected tables hold every case with the
//! published comparison beside the hull's status.

use bowwave::studies::{collect_all, runner, study_file::Study};
use std::path::{Path, PathBuf};

fn write_study(dir: &Path, name: &str, body: &str) -> PathBuf {
    std::fs::create_dir_all(dir).unwrap();
    let hull = std::fs::canonicalize("hulls/athena.csv").unwrap();
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(
        &path,
        format!("name = \"{name}\"\nhull = \"{}\"\n{body}", hull.display()),
    )
    .unwrap();
    path
}

/// A study file written afresh in an emptied temporary folder `bowwave-study-TAG`, read back; with that folder.
fn fresh_study(tag: &str, body: &str) -> (Study, PathBuf) {
    let dir = std::env::temp_dir().join(format!("bowwave-study-{tag}"));
    let _ = std::fs::remove_dir_all(&dir);
    let study = Study::read(&write_study(&dir, tag, body)).unwrap();
    (study, dir)
}

/// Options of a test run: every case, one job on one thread, no progress bars, the default checkpoints.
fn serial_options(out: &Path) -> runner::StudyOptions {
    runner::StudyOptions {
        out_dir: out.to_path_buf(),
        force: false,
        case: None,
        jobs: 1,
        threads: 1,
        progress: false,
        checkpoint: Default::default(),
    }
}

/// The same study with every spacing 10 % finer: another configuration in the same case folders.
fn finer(study: &Study) -> Study {
    Study {
        cases: study
            .cases
            .iter()
            .map(|c| {
                let mut c = c.clone();
                c.config.dx = Some(c.dx() * 0.9);
                c
            })
            .collect(),
        ..study.clone()
    }
}

fn error_of(dir: &Path, body: &str) -> String {
    let path = write_study(dir, "bad", body);
    format!(
        "{:#}",
        Study::read(&path).expect_err("a bad study file must be refused")
    )
}

#[test]
fn bad_study_files_name_the_file_and_the_field() {
    let dir = std::env::temp_dir().join("bowwave-study-errors");
    let e = error_of(&dir, "froude = [0.5, 0.6]\n[resolution]\ndx = [1e-3]\n");
    assert!(
        e.contains("bad.toml") && e.contains("resolution.dx") && e.contains("2 values"),
        "{e}"
    );
    let e = error_of(&dir, "froude = [0.5]\n[resolution]\nlevel = \"huge\"\n");
    assert!(e.contains("bad.toml") && e.contains("coarse"), "{e}");
    let e = error_of(&dir, "froude = []\n[resolution]\nlevel = \"coarse\"\n");
    assert!(e.contains("`froude`"), "{e}");
    let e = error_of(
        &dir,
        "froude = [0.5]\n[resolution]\nlevel = \"coarse\"\nrule = \"auto\"\n",
    );
    assert!(e.contains("`resolution`") && e.contains("exactly one"), "{e}");
    let e = error_of(
        &dir,
        "froude = [0.5]\n[resolution]\nlevel = \"coarse\"\n[config]\nuntil = \"stern\"\n",
    );
    assert!(e.contains("`config`") && e.contains("stern"), "{e}");
    let e = error_of(
        &dir,
        "froude = [0.5]\n[resolution]\nlevel = \"coarse\"\n[config]\nratoi = 1.5\n",
    );
    assert!(e.contains("ratoi"), "{e}");
    let e = error_of(
        &dir,
        "froude = [0.5]\n[resolution]\nlevel = \"coarse\"\n[config]\nratio = 0.5\n",
    );
    assert!(e.contains("config.ratio"), "{e}");
    // The values are checked by the 2D+t configuration's own rules, told with the study's field names:
    // (the part of the file after `froude = [0.5]` and a coarse level, what the error must hold).
    let coarse = "[resolution]\nlevel = \"coarse\"\n";
    let cases: [(&str, &[&str]); 8] = [
        ("froude = [0.5, 5.0]\n", &["`froude`", "(0, 3)", "got 5"]),
        ("[config]\nuntil = -0.2\n", &["config.until", "> 0"]),
        (
            "[config]\nuntil = \"transom\"\ngive_up_at = -1.0\n",
            &["config.give_up_at"],
        ),
        ("[config]\noutput_dx = 0.0\n", &["config.output_dx", "> 0"]),
        // A case's own options are checked, and told with the case's table.
        ("[case.1]\nc0 = -3\n", &["case.1.c0", "> 0"]),
        ("[case.2]\nc0 = 3\n", &["case.2", "from 1 to 1"]),
        ("[case.1]\nratoi = 2\n", &["case.1", "ratoi"]),
        // fr and dx come from `froude` and `[resolution]` only.
        ("[config]\ndx = 1e-3\n", &["config.dx", "`resolution`"]),
    ];
    for (tail, wanted) in cases {
        let body = if tail.starts_with("froude") {
            format!("{tail}{coarse}")
        } else {
            format!("froude = [0.5]\n{coarse}{tail}")
        };
        let e = error_of(&dir, &body);
        assert!(wanted.iter().all(|w| e.contains(w)), "{body}: {e}");
    }
}

/// Two short, very coarse cases (to x/L = 0.04) run, are found finished on a re-run (nothing runs again),
/// and are collected with their published rows. Regression: `finished` compared a case read back from JSON
/// with the resolved one, and the automatic dx did not survive serde_json's default float parsing, so a
/// finished case was run again and left out of the tables (`float_roundtrip` feature).
#[test]
fn finished_cases_are_skipped_on_rerun_and_collected() {
    let (study, dir) = fresh_study(
        "resume",
        "froude = [0.55, 0.64]\n[resolution]\nlevel = \"coarse\"\n[config]\nuntil = 0.04\n",
    );
    let out = dir.join("out");
    let opts = runner::StudyOptions {
        case: Some(2),
        ..serial_options(&out)
    };
    assert_eq!(
        runner::run_cases(&study, &opts).unwrap().finished,
        1,
        "--case 2 runs case 2 only"
    );
    assert_eq!(runner::collect_finished(&study, &out).len(), 1);
    let all = runner::StudyOptions {
        case: None,
        ..opts.clone()
    };
    assert_eq!(
        runner::run_cases(&study, &all).unwrap().finished,
        1,
        "only the unfinished case 1 runs"
    );
    assert_eq!(
        runner::run_cases(&study, &all).unwrap().finished,
        0,
        "nothing left to run"
    );
    assert_eq!(collect_all(&study, &out).unwrap(), 2);
    let jets = std::fs::read_to_string(out.join("jets.csv")).unwrap();
    assert_eq!(jets.lines().count(), 3, "header and one row per Froude number:\n{jets}");
    let comparison = std::fs::read_to_string(out.join("comparison.csv")).unwrap();
    // Three published quantities per Froude number (Table 10.1), each with the hull's status.
    assert_eq!(comparison.lines().count(), 1 + 6, "{comparison}");
    assert!(comparison
        .lines()
        .skip(1)
        .all(|l| l.starts_with("athena,approximation,")));
    let manifest = std::fs::read_to_string(out.join("manifest.json")).unwrap();
    assert!(manifest.contains("\"git_commit\"") && manifest.contains("\"bowwave_version\""));
    // Each case records the build that ran it, and the manifest lists it per case.
    let m: serde_json::Value = serde_json::from_str(&manifest).unwrap();
    for (rec, listed) in runner::collect_finished(&study, &out)
        .iter()
        .zip(m["cases"].as_array().unwrap())
    {
        let commit = rec.git_commit.as_deref().expect("the case's build is recorded");
        assert!(!commit.is_empty());
        assert_eq!(listed["git_commit"].as_str(), Some(commit));
    }
    // A record written before that field existed still counts as finished, with no build.
    let record = runner::case_dir(&out, &study.cases[0]).join("case.json");
    let mut old: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&record).unwrap()).unwrap();
    old.as_object_mut().unwrap().remove("git_commit");
    std::fs::write(&record, serde_json::to_string(&old).unwrap()).unwrap();
    let rec = runner::finished(&out, &study.cases[0]).expect("an older record still reads");
    assert_eq!(rec.git_commit, None);
    for f in ["report.md", "plunge_x.png", "snapshots.png", "wave_pattern_fr0.640.png"] {
        assert!(out.join(f).is_file(), "{f} missing");
    }
    // A changed configuration is not mistaken for the finished one.
    let changed = finer(&study);
    assert!(runner::collect_finished(&changed, &out).is_empty());
}

/// The published trends of the jet's own metrics (I_OG/S², α_G) are judged only on jets of at least
/// `RESOLVED_JET_PARTICLES` particles: at dx/L 7e-4 (15–32 jet particles) a round-off change of the initial
/// packing flipped the α_G verdict (docs/reference/twodt.md, session 16). Metrics put in by hand on two short runs.
#[test]
fn jet_metric_trends_are_not_judged_on_jets_of_a_few_particles() {
    use bowwave::studies::collect::{report, trends, RESOLVED_JET_PARTICLES};
    let (study, dir) = fresh_study(
        "jet-guard",
        "froude = [0.55, 0.64]\n[resolution]\nlevel = \"coarse\"\n[config]\nuntil = 0.01\n",
    );
    let out = dir.join("out");
    runner::run_cases(&study, &serial_options(&out)).unwrap();
    let mut records = runner::collect_finished(&study, &out);
    assert_eq!(records.len(), 2);
    let with_jets = |records: &mut Vec<bowwave::studies::runner::CaseRecord>, particles: usize| {
        for (k, r) in records.iter_mut().enumerate() {
            r.result.plunge = Some(bowwave::twodt::run::PlungeMetrics {
                x_plunge_over_l: 0.3 + 0.1 * k as f64,
                y_plunge_over_l: 0.1 + 0.02 * k as f64,
                i_og_over_s2: 0.6 - 0.2 * k as f64,
                alpha_g_deg: 40.0 + 10.0 * k as f64,
                jet_particles: particles,
                ..Default::default()
            });
        }
    };
    let line = |t: &[String], start: &str| t.iter().find(|l| l.starts_with(start)).cloned().unwrap();
    with_jets(&mut records, 20);
    let few = trends(&records);
    for metric in ["I_OG/S² falls", "α_G rises"] {
        assert!(line(&few, metric).contains("not assessed"), "{few:?}");
    }
    assert!(line(&few, "x_plunge/L grows").contains(": holds"), "{few:?}");
    let text = report("jet-guard", "athena", "approximation", "", &records, &[], 2);
    assert!(text.contains("read x_p, y_p and H_pj only"), "{text}");
    // Issue #32: a single-phase report says that what follows the cavity's closure is without the trapped air.
    assert!(text.contains("without the trapped air"), "{text}");
    with_jets(&mut records, RESOLVED_JET_PARTICLES);
    let enough = trends(&records);
    for metric in ["I_OG/S² falls", "α_G rises"] {
        assert!(line(&enough, metric).contains(": holds"), "{enough:?}");
    }
    let text = report("jet-guard", "athena", "approximation", "", &records, &[], 2);
    assert!(!text.contains("read x_p, y_p and H_pj only"), "{text}");
    // Regression: a case with a layer of air (`air`) was reported as single phase too; its row and the note
    // now say it has air.
    records[1].result.air_over_d = Some(1.5);
    let text = report("jet-guard", "athena", "approximation", "", &records, &[], 2);
    assert!(
        text.contains("with 1.5 D of air") && text.contains("except those with a layer of air"),
        "{text}"
    );
}

/// Regression: the trends were read over every plunging case in the study file's order, so a finer case at a
/// Froude number already present (athena-shifting's case 5) made "x_plunge grows with Fr" fail on cases that
/// hold it. They are read per series of one configuration and spacing, in increasing Fr. Metrics put in by
/// hand on three short runs.
#[test]
fn trends_are_read_per_spacing_in_increasing_froude_number() {
    use bowwave::studies::collect::trends;
    let (study, dir) = fresh_study(
        "trend-series",
        "froude = [0.64, 0.5, 0.5]\n[resolution]\ndx = [3e-3, 3e-3, 2.5e-3]\n[config]\nuntil = 0.01\n",
    );
    let out = dir.join("out");
    runner::run_cases(&study, &serial_options(&out)).unwrap();
    let mut records = runner::collect_finished(&study, &out);
    assert_eq!(records.len(), 3);
    for (r, x) in records.iter_mut().zip([0.47, 0.33, 0.30]) {
        r.result.plunge = Some(bowwave::twodt::run::PlungeMetrics {
            x_plunge_over_l: x,
            y_plunge_over_l: x / 3.0,
            ..Default::default()
        });
    }
    let t = trends(&records);
    assert!(t.iter().any(|l| l == "Fr = 0.500, 0.640"), "{t:?}");
    assert!(
        t.iter().any(|l| l == "x_plunge/L grows with Fr: holds (0.330, 0.470)"),
        "{t:?}"
    );
    assert!(
        !t.iter().any(|l| l.contains("0.300")),
        "the finer case has no series of its own: {t:?}"
    );
}

/// A convergence study: one Froude number at two spacings. Regression: the comparison paired each published
/// row with the first case at its Froude number, so the finer case had no comparison rows, and the report
/// tested the published trends over Fr on cases that all have the same Fr.
#[test]
fn one_froude_number_at_two_spacings_compares_both_and_claims_no_trend() {
    let (study, dir) = fresh_study(
        "convergence",
        "froude = [0.55, 0.55]\n[resolution]\ndx = [3e-3, 2.5e-3]\n[config]\nuntil = 0.04\n",
    );
    let out = dir.join("out");
    let opts = serial_options(&out);
    assert_eq!(
        runner::run_cases(&study, &opts).unwrap().finished,
        2,
        "two cases, two folders"
    );
    assert_eq!(collect_all(&study, &out).unwrap(), 2);
    let comparison = std::fs::read_to_string(out.join("comparison.csv")).unwrap();
    assert_eq!(
        comparison.lines().count(),
        1 + 6,
        "three quantities for each case:\n{comparison}"
    );
    for dx in ["3.000e-3", "2.500e-3"] {
        assert_eq!(
            comparison.lines().filter(|l| l.split(',').any(|c| c == dx)).count(),
            3,
            "rows of the case at dx/L {dx}:\n{comparison}"
        );
    }
    // The published trends run over Froude numbers: even with both cases plunging (metrics put in by hand,
    // these short runs stop before the plunge) there is nothing to check at one Froude number.
    let mut records = runner::collect_finished(&study, &out);
    for r in &mut records {
        r.result.plunge = Some(Default::default());
    }
    let trends = bowwave::studies::collect::trends(&records);
    assert_eq!(trends.len(), 1, "{trends:?}");
    assert!(trends[0].contains("2 plunging case(s) at 1 Froude number(s)") && trends[0].contains("cannot be checked"));
}

/// Regression: after the packing became the default (r = 1.5), `study --dry-run` built and packed every scene,
/// which at the published Athena resolutions ran for over 20 minutes before printing anything. The dry run now
/// builds unpacked scenes; the packing never changes the particle count, so the estimate is the same.
#[test]
fn dry_run_does_not_pack_the_scenes() {
    let dir = std::env::temp_dir().join("bowwave-study-dry-run");
    let path = write_study(
        &dir,
        "dry",
        "froude = [0.5]\n[resolution]\ndx = [4e-3]\n[config]\nratio = 1.5\n",
    );
    let study = Study::read(&path).unwrap();
    let spec = &study.cases[0];
    assert_eq!(
        runner::dry_run_config(spec).packing,
        bowwave::twodt::config::Packing::Off
    );
    let est = runner::dry_run(&study).unwrap();
    let hull = bowwave::geometry::hull_file::HullOffsets::read(&study.hull_path).unwrap();
    let surface = std::sync::Arc::new(bowwave::geometry::surface::HullSurface::new(&hull));
    let packed = bowwave::twodt::scene::build(surface, &spec.config).unwrap();
    assert!(packed.packing.is_some(), "the case itself packs (r = 1.5)");
    assert_eq!(est[0].particles, packed.sim.n_fluid());
}

/// Regression: the dry run priced every case at the water's sound speed, so a case with `air` (whose step the
/// air's 14 times larger sound speed sets) was estimated at a fourteenth of its steps (964 against the 12 411 a
/// run took, Athena Fr 0.64, dx/L 2e-3). The estimate now takes the fastest phase's.
#[test]
fn dry_run_prices_a_case_with_air_at_the_airs_sound_speed() {
    let dir = std::env::temp_dir().join("bowwave-study-dry-run-air");
    let path = write_study(
        &dir,
        "dry-air",
        "froude = [0.5, 0.5]\n[resolution]\ndx = [4e-3, 4e-3]\n[config]\nuntil = 0.1\n[case.2]\nair = 1.0\n",
    );
    let study = Study::read(&path).unwrap();
    let est = runner::dry_run(&study).unwrap();
    let ratio = est[1].steps / est[0].steps;
    // The step is c_a/c_w = √(1.4 / (7 × 0.001)) = 14.1 times shorter (docs/reference/twodt.md, "Air"), and the
    // settling three times as long: 15.1 here, where the settling is a tenth of the run.
    let c_ratio = 200f64.sqrt();
    assert!(
        ratio > 0.99 * c_ratio && ratio < 1.15 * c_ratio,
        "steps with air / without: {ratio}"
    );
    assert!(est[1].particles > est[0].particles);
}

/// `study --wall-limit` is the command's limit, counted once from its start, not each case's from the case's
/// own start (session 47's review: with a per-case limit a study of N cases could run N limits): a case whose
/// turn comes after the limit is not started, and the command says so.
#[test]
fn a_study_wall_limit_is_the_commands_not_each_cases() {
    let (study, dir) = fresh_study(
        &format!("deadline-{}", std::process::id()),
        "froude = [0.64, 0.6]\n[resolution]\ndx = [4e-3, 4e-3]\n[config]\nuntil = 0.05\n",
    );
    let out = dir.join("out");
    let passed = runner::StudyOptions {
        checkpoint: bowwave::twodt::checkpoint::CheckpointPolicy {
            deadline: Some(std::time::Instant::now()),
            ..Default::default()
        },
        ..serial_options(&out)
    };
    let ran = runner::run_cases(&study, &passed).unwrap();
    assert_eq!((ran.finished, ran.halted.len(), ran.not_started), (0, 0, 2));
    assert!(runner::collect_finished(&study, &out).is_empty());
    let _ = std::fs::remove_dir_all(&dir);
}

/// A study whose case is stopped part-way (as by a kill or a batch time limit, after a checkpoint) and run
/// again ends with the same tables as one that ran through: jets.csv (timing columns aside) and
/// comparison.csv are identical.
#[test]
fn stopped_study_resumes_to_the_same_tables_as_an_uninterrupted_one() {
    let (study, dir) = fresh_study(
        &format!("killed-{}", std::process::id()),
        "froude = [0.64]\n[resolution]\ndx = [4e-3]\n[config]\nuntil = 0.05\n",
    );
    let options = |out: &Path, halt: Option<u64>| runner::StudyOptions {
        checkpoint: bowwave::twodt::checkpoint::CheckpointPolicy {
            halt_at_step: halt,
            ..Default::default()
        },
        ..serial_options(out)
    };
    let (through, stopped) = (dir.join("through"), dir.join("stopped"));
    assert_eq!(runner::run_cases(&study, &options(&through, None)).unwrap().finished, 1);
    collect_all(&study, &through).unwrap();
    let steps = runner::collect_finished(&study, &through)[0].result.steps;
    let ran = runner::run_cases(&study, &options(&stopped, Some(steps / 2))).unwrap();
    assert_eq!((ran.finished, ran.halted.len()), (0, 1), "stopped part-way");
    assert!(
        ran.halted[0].to_string().contains("stopped at x/L"),
        "{}",
        ran.halted[0]
    );
    assert!(
        runner::collect_finished(&study, &stopped).is_empty(),
        "a stopped case is not finished"
    );
    assert_eq!(runner::run_cases(&study, &options(&stopped, None)).unwrap().finished, 1);
    collect_all(&study, &stopped).unwrap();
    let without_timings = |out: &Path| {
        let text = std::fs::read_to_string(out.join("jets.csv")).unwrap();
        let mut rows = text
            .lines()
            .map(|l| l.split(',').map(str::to_string).collect::<Vec<_>>());
        let header = rows.next().unwrap();
        let keep: Vec<bool> = header.iter().map(|c| !c.contains("seconds")).collect();
        assert!(keep.iter().any(|k| !k), "jets.csv has timing columns: {header:?}");
        std::iter::once(header)
            .chain(rows)
            .map(|r| {
                r.into_iter()
                    .zip(&keep)
                    .filter(|(_, k)| **k)
                    .map(|(c, _)| c)
                    .collect::<Vec<_>>()
            })
            .collect::<Vec<_>>()
    };
    assert_eq!(without_timings(&through), without_timings(&stopped));
    let comparison = |out: &Path| std::fs::read_to_string(out.join("comparison.csv")).unwrap();
    assert_eq!(comparison(&through), comparison(&stopped));
    let _ = std::fs::remove_dir_all(&dir);
}

/// `study --status` tells each case's state from the output folder alone: finished, stopped part-way with
/// the x/L and steps of its checkpoint (and whether a run would go on from it), or not started; a changed
/// configuration is reported as such, not as the finished or resumable case.
#[test]
fn status_tells_finished_stopped_and_unstarted_cases_apart() {
    use bowwave::studies::status::{remaining_seconds, status, CaseState};
    let (study, dir) = fresh_study(
        &format!("status-{}", std::process::id()),
        "froude = [0.64, 0.6, 0.55]\n[resolution]\ndx = [4e-3, 4e-3, 4e-3]\n[config]\nuntil = 0.05\n",
    );
    let out = dir.join("out");
    let only = |case: usize, halt: Option<u64>| runner::StudyOptions {
        case: Some(case),
        checkpoint: bowwave::twodt::checkpoint::CheckpointPolicy {
            halt_at_step: halt,
            ..Default::default()
        },
        ..serial_options(&out)
    };
    assert_eq!(runner::run_cases(&study, &only(1, None)).unwrap().finished, 1);
    let steps = runner::collect_finished(&study, &out)[0].result.steps;
    let ran = runner::run_cases(&study, &only(2, Some(steps / 2))).unwrap();
    assert_eq!(ran.halted.len(), 1, "case 2 stopped part-way");
    let states = status(&study, &out).unwrap();
    assert_eq!(states.len(), 3);
    match &states[0].state {
        CaseState::Finished(rec) => assert_eq!(rec.result.steps, steps),
        s => panic!("case 1 finished, got {s:?}"),
    }
    let p = match &states[1].state {
        CaseState::InProgress(p) => p.clone(),
        s => panic!("case 2 stopped part-way, got {s:?}"),
    };
    assert!(p.same_configuration, "{p:?}");
    let saved = &p.saved;
    assert!(saved.steps >= steps / 2 && saved.steps < steps, "{p:?}");
    assert!(p.x_over_l > p.x_start && p.x_over_l < 0.05, "{p:?}");
    assert!((saved.x_stop - 0.05).abs() < 1e-12, "{p:?}");
    // The packing and settling before the passage are recorded apart, and left out of the pace.
    assert!(
        saved.setup_seconds > 0.0 && saved.setup_seconds < saved.wall_seconds,
        "{p:?}"
    );
    let left = remaining_seconds(&p).expect("the section has moved");
    let with_setup = (saved.x_stop - p.x_over_l) / (p.x_over_l - p.x_start) * saved.wall_seconds;
    assert!(
        left > 0.0 && left < with_setup,
        "{left} s against {with_setup} s with the setup: {p:?}"
    );
    assert!(
        matches!(states[2].state, CaseState::NotStarted),
        "{:?}",
        states[2].state
    );
    let m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("manifest.json")).unwrap()).unwrap();
    let listed: Vec<_> = m["cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["status"].clone())
        .collect();
    assert_eq!(listed, ["no plunge", "stopped part-way (checkpoint)", "not run"]);
    // The same folders read with another spacing: nothing there is this configuration's.
    let changed = finer(&study);
    let states = status(&changed, &out).unwrap();
    assert!(
        matches!(states[0].state, CaseState::OtherConfiguration),
        "{:?}",
        states[0].state
    );
    match &states[1].state {
        CaseState::InProgress(p) => assert!(!p.same_configuration, "{p:?}"),
        s => panic!("case 2's checkpoint is still there, got {s:?}"),
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Every shipped study file, the README's main job among them, reads and resolves to cases.
#[test]
fn shipped_study_files_read() {
    let mut names = vec![];
    for entry in std::fs::read_dir("studies").unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let study = Study::read(&path).unwrap_or_else(|e| panic!("{}: {e:#}", path.display()));
            assert!(!study.cases.is_empty(), "{}", path.display());
            names.push(path.file_name().unwrap().to_string_lossy().into_owned());
        }
    }
    assert!(names.iter().any(|n| n == "quick.toml"), "{names:?}");
}

/// `path`'s text with the columns named `wall_seconds` and `cpu_seconds` emptied: the cost of a run differs
/// from run to run; every other byte must not.
fn without_timings(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or_default().split(',').collect();
    let timing: Vec<bool> = header.iter().map(|h| h.ends_with("_seconds")).collect();
    let mut out = header.join(",") + "\n";
    for line in lines {
        let cells: Vec<&str> = line
            .split(',')
            .enumerate()
            .map(|(k, c)| if timing.get(k) == Some(&true) { "" } else { c })
            .collect();
        out += &(cells.join(",") + "\n");
    }
    out
}

/// `path`'s Markdown with the cells of the column headed `CPU s` emptied: a case's CPU time differs from run
/// to run (and rounds to a different whole second when the jobs share cores); every other byte must not.
/// Regression: the concurrent-jobs test compared `report.md` whole and failed when two jobs' CPU seconds
/// rounded apart.
fn report_without_cpu_seconds(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut column = None;
    let mut out = String::new();
    for line in text.lines() {
        if !line.starts_with('|') {
            column = None;
            out += line;
        } else {
            let mut cells: Vec<&str> = line.split('|').collect();
            if column.is_none() {
                column = cells.iter().position(|c| c.trim() == "CPU s");
            } else if let Some(k) = column.filter(|&k| k < cells.len() && !line.starts_with("|-")) {
                cells[k] = "";
            }
            out += &cells.join("|");
        }
        out.push('\n');
    }
    out
}

/// The README's job-array recipe, tested for real: three `bowwave study FILE --case N` processes started
/// together into one folder write the same tables (`jets.csv` less its timing columns, `comparison.csv`,
/// `report.md` less its CPU seconds) as one serial run, byte for byte, and leave no temporary file. Regression: every write went
/// through the same `NAME.tmp`, and each job gathered the tables from what had finished when it ended, so the
/// last job to rename could leave out a case (`studies::lock`).
#[test]
fn concurrent_case_jobs_write_the_serial_tables() {
    let (study, dir) = fresh_study(
        "jobs",
        "froude = [0.55, 0.6, 0.64]\n[resolution]\ndx = [4e-3, 4e-3, 4e-3]\n[config]\nuntil = 0.02\n",
    );
    let exe = env!("CARGO_BIN_EXE_bowwave");
    let run = |out: &Path, case: Option<usize>| {
        let mut c = std::process::Command::new(exe);
        c.args(["--threads", "1", "study"])
            .arg(&study.file)
            .arg("--out")
            .arg(out)
            .arg("-q");
        if let Some(k) = case {
            c.args(["--case", &k.to_string()]);
        }
        c.stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::piped());
        c.spawn().unwrap()
    };
    let serial = dir.join("serial");
    let together = dir.join("together");
    let jobs: Vec<_> = (1..=3).map(|k| run(&together, Some(k))).collect();
    for job in jobs {
        let o = job.wait_with_output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let o = run(&serial, None).wait_with_output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(runner::collect_finished(&study, &together).len(), 3);
    assert_eq!(
        without_timings(&together.join("jets.csv")),
        without_timings(&serial.join("jets.csv"))
    );
    let a = std::fs::read(together.join("comparison.csv")).unwrap();
    let b = std::fs::read(serial.join("comparison.csv")).unwrap();
    assert!(a == b, "comparison.csv differs from the serial run's");
    let (a, b) = (
        report_without_cpu_seconds(&together.join("report.md")),
        report_without_cpu_seconds(&serial.join("report.md")),
    );
    assert!(a.contains("| plunge |") || a.contains("| no plunge"), "{a}");
    assert_eq!(a, b, "report.md differs from the serial run's beyond its CPU seconds");
    let temporaries: Vec<_> = walk(&together)
        .into_iter()
        .filter(|p| p.to_string_lossy().ends_with(".tmp"))
        .collect();
    assert!(temporaries.is_empty(), "{temporaries:?}");
}

/// Every file under `dir`.
fn walk(dir: &Path) -> Vec<PathBuf> {
    let mut files = vec![];
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        let p = e.path();
        if p.is_dir() {
            files.extend(walk(&p));
        } else {
            files.push(p);
        }
    }
    files
}

/// Every case may have its own hull: a file, or a generated variant of a family (the hull sensitivity
/// studies). The variant is generated when the case runs, written into its folder as `hull.csv`, and recorded
/// in the case's configuration; a misspelt generator parameter is refused with the case's field.
#[test]
fn a_case_runs_its_own_hull_or_a_generated_variant() {
    let wigley = std::fs::canonicalize("hulls/wigley.csv").unwrap();
    let (study, dir) = fresh_study(
        &format!("variants-{}", std::process::id()),
        &format!(
            "froude = [0.64, 0.64, 0.64]\n[resolution]\ndx = [4e-3, 4e-3, 4e-3]\n[config]\nuntil = 0.01\n\
             [case.2.hull_variant]\ngenerator = \"athena\"\nflare_angle = 0\n[case.3]\nhull = \"{}\"\n",
            wigley.display()
        ),
    );
    let out = dir.join("out");
    assert_eq!(runner::run_cases(&study, &serial_options(&out)).unwrap().finished, 3);
    let recs = runner::collect_finished(&study, &out);
    let names: Vec<&str> = recs.iter().map(|r| r.result.hull.as_str()).collect();
    assert_eq!(names, ["athena", "athena-variant", "wigley"]);
    let written = std::fs::read_to_string(runner::case_dir(&out, &study.cases[1]).join("hull.csv")).unwrap();
    assert!(
        written.contains("VARIANT of the athena approximation (flare_angle=0)"),
        "{written}"
    );
    let manifest = std::fs::read_to_string(out.join("manifest.json")).unwrap();
    assert!(manifest.contains("\"generator\": \"athena\""), "{manifest}");
    let e = error_of(
        &dir,
        "froude = [0.5]\n[resolution]\nlevel = \"coarse\"\n[case.1.hull_variant]\ngenerator = \"athena\"\nflair = 3\n",
    );
    assert!(e.contains("case.1.hull_variant") && e.contains("flair"), "{e}");
    let e = error_of(
        &dir,
        "froude = [0.5]\n[resolution]\nlevel = \"coarse\"\n[case.1]\nhull = \"nowhere.csv\"\n",
    );
    assert!(e.contains("case.1.hull") && e.contains("not found"), "{e}");
}

/// A `[ship3d]` study (issue #31): each case runs the 2D+t partner and the towed 3D hull at one spacing (D/res),
/// in one tank and at one sound speed, records both, writes `ship3d.csv`, the 3D files and the report's section,
/// and is skipped when run again. Wigley at D/dx 4 in a narrow, shallow tank, towed 0.1 L: the plumbing, not a
/// steady bow (the comparison at a useful travel is `studies/results/ship3d-*`).
#[test]
fn a_3d_study_tows_the_hull_beside_its_2dt_partner_at_one_spacing() {
    let dir = std::env::temp_dir().join("bowwave-study-ship3d");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let hull = std::fs::canonicalize("hulls/wigley.csv").unwrap();
    let path = dir.join("s3.toml");
    std::fs::write(
        &path,
        format!(
            "name = \"s3\"\nhull = \"{}\"\nfroude = [0.5]\n[ship3d]\nres = 4\nramp = 0.05\nmin_travel = 0.1\n\
             travel = 0.1\nhalf_width = 1.5\ndepth = 1.5\n",
            hull.display()
        ),
    )
    .unwrap();
    let study = Study::read(&path).unwrap();
    let out = dir.join("out");
    let ran = runner::run_cases(&study, &serial_options(&out)).unwrap();
    assert_eq!(ran.finished, 1);
    collect_all(&study, &out).unwrap();
    let rec = &runner::collect_finished(&study, &out)[0];
    let three = rec.ship3d.as_ref().expect("the 3D run is recorded");
    let two = &rec.result;
    // One spacing (Wigley's D/L is 0.1), one sound speed.
    assert!((two.dx_over_l - 0.025).abs() < 1e-12, "2D+t dx/L {}", two.dx_over_l);
    assert!(
        (three.dx_over_l - two.dx_over_l).abs() < 1e-12,
        "3D dx/L {}",
        three.dx_over_l
    );
    assert!(
        (three.c0_over_sqrt_gl - two.c0_over_sqrt_gl).abs() < 1e-9,
        "c0 {} against {}",
        three.c0_over_sqrt_gl,
        two.c0_over_sqrt_gl
    );
    assert!(three.particles > 1000 && three.steps > 0 && three.travel_over_l >= 0.1 - 1e-9);
    assert!(three.blow_up.is_none() && !three.steady);
    let case = out.join("cases").join("01-fr0.500");
    for f in [
        "eta.csv",
        "ship3d/summary.txt",
        "ship3d/agreement.csv",
        "ship3d/wave_pattern_difference.png",
    ] {
        assert!(case.join(f).is_file(), "{f} missing");
    }
    let csv = std::fs::read_to_string(out.join("ship3d.csv")).unwrap();
    assert_eq!(csv.lines().count(), 2, "{csv}");
    assert!(csv.lines().nth(1).unwrap().starts_with("0.5,2.5"), "{csv}");
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("## 3D against 2D+t"), "{report}");
    // Run again: finished, skipped.
    assert_eq!(runner::run_cases(&study, &serial_options(&out)).unwrap().finished, 0);
    // A 3D run stopped part-way is told apart by `--status`: its record gone, its checkpoint after 3 steps.
    let spec = &study.cases[0];
    let surface =
        bowwave::geometry::surface::HullSurface::new(&bowwave::geometry::hull_file::HullOffsets::read(&hull).unwrap());
    let mut towed =
        bowwave::compare3d::towed_ship::TowedShip::with_options(surface, spec.fr(), spec.ship3d.as_ref().unwrap());
    towed.checkpoint = Some(bowwave::compare3d::towed_ship::CheckpointPolicy {
        dir: case.join("ship3d"),
        every: std::time::Duration::MAX,
        deadline: None,
        halt_at_step: Some(3),
    });
    assert!(matches!(
        bowwave::compare3d::towed_ship::run(&towed, false).unwrap(),
        bowwave::driver::Ended::Halted(_)
    ));
    std::fs::remove_file(case.join("case.json")).unwrap();
    match &bowwave::studies::status::status(&study, &out).unwrap()[0].state {
        bowwave::studies::status::CaseState::Ship3dInProgress(p) => {
            assert!(p.same_configuration && p.steps >= 3, "{p:?}")
        }
        other => panic!("expected a 3D run in progress, got {other:?}"),
    }
}

/// What a `[ship3d]` study refuses, by field: a `[resolution]` (its spacing is D/res), fewer than 4 particles
/// over the draft, a 2D+t option that would give the two models different tanks, a case's own hull.
#[test]
fn a_3d_study_refuses_a_second_spacing_tank_or_hull() {
    let dir = std::env::temp_dir().join("bowwave-study-ship3d-errors");
    let cases: [(&str, &[&str]); 5] = [
        (
            "[resolution]\nlevel = \"coarse\"\n[ship3d]\nres = 5\n",
            &["`resolution`", "D/res"],
        ),
        ("[ship3d]\nres = 3\n", &["ship3d.res", "≥ 4"]),
        ("[ship3d]\nres = 5\nmin_travel = 0.1\n", &["ship3d.min_travel"]),
        ("[ship3d]\nres = 5\n[config]\nwidth = 2\n", &["config.width", "one"]),
        (
            "[ship3d]\nres = 5\n[case.1]\nhull = \"other.csv\"\n",
            &["case.1", "one hull"],
        ),
    ];
    for (tail, wanted) in cases {
        let body = format!("froude = [0.5]\n{tail}");
        let e = error_of(&dir, &body);
        assert!(wanted.iter().all(|w| e.contains(w)), "{body}: {e}");
    }
}

/// Issue #30, item 4: a report that compares an approximated Athena or Alliance with the published jets says what
/// the hull-or-method campaign measured about the difference; an exact hull's report, or one without published
/// jets, does not.
#[test]
fn report_on_an_approximated_hull_says_what_the_difference_was_measured_to_mean() {
    use bowwave::studies::collect::{report, Comparison};
    let comp = Comparison {
        fr: 0.5,
        quantity: "x_plunge/L",
        ours: Some(0.31),
        published: 0.191,
        our_dx: 3.5e-4,
        published_dx: 1.9e-4,
        note: String::new(),
    };
    let heading = "What the difference was measured to mean";
    let athena = report("s", "athena", "approximation", "", &[], std::slice::from_ref(&comp), 1);
    assert!(
        athena.contains(heading) && athena.contains("a fit, not a prediction"),
        "{athena}"
    );
    let alliance = report(
        "s",
        "alliance",
        "approximation",
        "",
        &[],
        std::slice::from_ref(&comp),
        1,
    );
    assert!(
        alliance.contains(heading) && alliance.contains("Table 10.2"),
        "{alliance}"
    );
    assert!(!report("s", "athena", "exact", "", &[], std::slice::from_ref(&comp), 1).contains(heading));
    assert!(!report("s", "wigley", "approximation", "", &[], std::slice::from_ref(&comp), 1).contains(heading));
    assert!(!report("s", "athena", "approximation", "", &[], &[], 1).contains(heading));
}
