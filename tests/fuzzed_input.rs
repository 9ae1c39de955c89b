//! Bad input gets an error naming the file, never a panic: property tests that take the project's own case,
//! hull and study files, damage them (a number swapped for a bad value, a line dropped or doubled, the text
//! cut short, a stray character), and check that reading them, and building and stepping what still reads,
//! never panics, and that every error names the file.

use bowwave::cases::{setup, CaseFile};
use bowwave::geometry::{hull_file::HullOffsets, surface::HullSurface};
use bowwave::studies::study_file::Study;
use proptest::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

/// A scratch directory for one damaged file, removed when the case is over (pass or fail), so that a run of
/// hundreds of cases leaves nothing behind in the system's temporary directory.
struct Scratch(PathBuf);

impl Scratch {
    /// `<tmp>/bowwave-fuzz-<kind>-<pid>-<n>`, unique per case even with the tests on several threads.
    fn new(kind: &str) -> Scratch {
        static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("bowwave-fuzz-{kind}-{}-{n}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        Scratch(dir)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Values a damaged number may become: wrong sign, zero, overflow, not finite, another type, empty.
const BAD_VALUES: &[&str] = &[
    "0",
    "-1",
    "1e300",
    "-1e300",
    "1e-300",
    "nan",
    "inf",
    "-inf",
    "\"text\"",
    "[]",
    "[1.0]",
    "[1.0, 2.0, 3.0]",
    "",
    "true",
    "{}",
    "2",
    "0.5",
    "1e6",
];

/// Factors a number may be multiplied by: files that still read, with odd but valid values, reach the code
/// behind the parser.
const FACTORS: &[f64] = &[0.5, 0.9, 1.1, 2.0, -1.0, 10.0, 0.01];

/// Stray characters.
const STRAY: &[char] = &['=', ',', '[', ']', '"', '\n', '#', '-', '.', ' ', '{', '0'];

/// One damage to a text; the indices are taken modulo what the text holds.
#[derive(Clone, Debug)]
enum Edit {
    /// The k-th number becomes `BAD_VALUES[v]`.
    Number(usize, usize),
    /// The k-th number is multiplied by `FACTORS[f]`.
    Scale(usize, usize),
    DropLine(usize),
    DoubleLine(usize),
    /// The text ends at character k.
    Cut(usize),
    /// `STRAY[c]` is inserted before character k.
    Insert(usize, usize),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        3 => (any::<usize>(), 0..BAD_VALUES.len()).prop_map(|(k, v)| Edit::Number(k, v)),
        3 => (any::<usize>(), 0..FACTORS.len()).prop_map(|(k, f)| Edit::Scale(k, f)),
        1 => any::<usize>().prop_map(Edit::DropLine),
        1 => any::<usize>().prop_map(Edit::DoubleLine),
        1 => any::<usize>().prop_map(Edit::Cut),
        1 => (any::<usize>(), 0..STRAY.len()).prop_map(|(k, c)| Edit::Insert(k, c)),
    ]
}

/// Byte ranges of the numbers in `text` (a digit, or a sign or point before a digit, and what follows of
/// digits, points, exponents and signs).
fn numbers(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut out = vec![];
    let mut i = 0;
    while i < b.len() {
        let starts = b[i].is_ascii_digit()
            || (matches!(b[i], b'-' | b'+' | b'.') && b.get(i + 1).is_some_and(u8::is_ascii_digit));
        let inside_word = i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_');
        if starts && !inside_word {
            let mut j = i + 1;
            while j < b.len() && (b[j].is_ascii_digit() || matches!(b[j], b'.' | b'e' | b'E' | b'-' | b'+' | b'_')) {
                j += 1;
            }
            out.push((i, j));
            i = j;
        } else {
            i += 1;
        }
    }
    out
}

fn apply(text: &str, edits: &[Edit]) -> String {
    let mut t = text.to_string();
    for e in edits {
        match *e {
            Edit::Number(k, v) => {
                let n = numbers(&t);
                if !n.is_empty() {
                    let (a, b) = n[k % n.len()];
                    t.replace_range(a..b, BAD_VALUES[v]);
                }
            }
            Edit::Scale(k, f) => {
                let n = numbers(&t);
                if !n.is_empty() {
                    let (a, b) = n[k % n.len()];
                    if let Ok(x) = t[a..b].parse::<f64>() {
                        t.replace_range(a..b, &format!("{:?}", x * FACTORS[f]));
                    }
                }
            }
            Edit::DropLine(k) | Edit::DoubleLine(k) => {
                let mut lines: Vec<&str> = t.lines().collect();
                if !lines.is_empty() {
                    let k = k % lines.len();
                    if matches!(e, Edit::DropLine(_)) {
                        lines.remove(k);
                    } else {
                        lines.insert(k, lines[k]);
                    }
                }
                t = lines.join("\n");
            }
            Edit::Cut(k) => {
                let chars: Vec<char> = t.chars().collect();
                t = chars[..k % (chars.len() + 1)].iter().collect();
            }
            Edit::Insert(k, c) => {
                let mut chars: Vec<char> = t.chars().collect();
                let k = k % (chars.len() + 1);
                chars.insert(k, STRAY[c]);
                t = chars.into_iter().collect();
            }
        }
    }
    t
}

/// Runs `f`, failing the property with the damaged text when it panics.
fn no_panic<T>(what: &str, text: &str, f: impl FnOnce() -> T) -> Result<T, TestCaseError> {
    catch_unwind(AssertUnwindSafe(f)).map_err(|p| {
        let msg = p
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default();
        TestCaseError::fail(format!("{what} panicked ({msg}) on:\n{text}"))
    })
}

fn project(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(rel)
}

const FILE: &str = "damaged.toml";
/// A user's case with references (its reference files are read only by `CaseFile::read`, not from text).
const EXAMPLE_WITH_REFERENCES: &str = include_str!("../cases/examples/dam-break-buchner.toml");

/// 192 damaged files per property from a fixed seed, so that CI runs the same files every time;
/// `PROPTEST_CASES=N PROPTEST_RNG_SEED=S` runs other and more of them (how the bugs behind the
/// regression tests below were found).
fn config() -> ProptestConfig {
    let mut c = ProptestConfig::default();
    if std::env::var_os("PROPTEST_CASES").is_none() {
        c.cases = 192;
    }
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        c.rng_seed = proptest::test_runner::RngSeed::Fixed(20261202);
    }
    c.failure_persistence = None;
    c
}

proptest! {
    #![proptest_config(config())]

    /// A damaged built-in case reads as a case or as an error naming the file; what reads builds and takes
    /// a few steps (or stops with a diagnosis) without a panic.
    #[test]
    fn damaged_case_files_give_errors_not_panics(
        which in 0..bowwave::cases::builtin::BUILTIN.len() + 1,
        edits in prop::collection::vec(edit(), 1..4),
    ) {
        // The built-ins, and the example with gauges' and references' sections (issue #36).
        let original = bowwave::cases::builtin::BUILTIN
            .get(which)
            .map_or(EXAMPLE_WITH_REFERENCES, |b| b.1);
        let text = apply(original, &edits);
        match no_panic("CaseFile::parse", &text, || CaseFile::parse(&text, FILE))? {
            Err(e) => prop_assert!(e.to_string().contains(FILE), "error without the file's name: {e}"),
            Ok(case) => {
                let res = case.scales.resolution.min(10.0);
                let dx = setup::spacing(&case, Some(res));
                let cfg = setup::solver_config(&case, dx);
                let support = cfg.kernel.support_over_h() * cfg.h;
                // Only what the test can afford is built (the library's bound is 1e8).
                if setup::estimated_particles(&case, dx, support) < 2e4 {
                    no_panic("build and step", &text, || match setup::build(&case, Some(res)) {
                        Ok(mut sim) => {
                            for _ in 0..3 {
                                if sim.step().is_err() {
                                    break;
                                }
                            }
                        }
                        Err(e) => assert!(e.to_string().contains(&case.name), "error without the case's name: {e}"),
                    })?;
                }
            }
        }
    }

    /// A damaged hull file reads as a hull or as an error naming the file; a hull that reads gives its
    /// sections, and a coarse 2D+t scene that takes a few steps, without a panic.
    #[test]
    fn damaged_hull_files_give_errors_not_panics(
        which in 0..3usize,
        edits in prop::collection::vec(edit(), 1..4),
    ) {
        let name = ["hulls/athena.csv", "hulls/wigley.csv", "hulls/alliance.csv"][which];
        let original = std::fs::read_to_string(project(name)).unwrap();
        let text = apply(&original, &edits);
        match no_panic("HullOffsets::parse", &text, || HullOffsets::parse(&text, "damaged.csv"))? {
            Err(e) => prop_assert!(e.to_string().contains("damaged.csv"), "error without the file's name: {e}"),
            Ok(h) => {
                no_panic("HullSurface sections and a coarse 2D+t scene", &text, || {
                    let s = std::sync::Arc::new(HullSurface::new(&h));
                    let (a, b) = s.x_range;
                    for k in 0..=10 {
                        let _ = s.section(a + (b - a) * k as f64 / 10.0, 1e-3);
                    }
                    // The hull's section in a coarse scene, starting mid-hull, for a few steps: an error
                    // (a section the scene cannot use, a run that stops) is allowed, a panic is not.
                    let draft = h.meta.draft_m / h.meta.length_m;
                    let cfg = bowwave::twodt::scene::TwoDtConfig {
                        dx: Some(draft / 5.0),
                        x0: Some(0.5 * (a + b)),
                        settle_crossings: 0.0,
                        packing: bowwave::twodt::config::Packing::Off,
                        ..Default::default()
                    };
                    if let Ok(mut scene) = bowwave::twodt::scene::build(s, &cfg) {
                        for _ in 0..3 {
                            if scene.sim.step().is_err() {
                                break;
                            }
                        }
                    }
                })?;
            }
        }
    }

    /// A damaged study file reads as a study or as an error naming the file (the hull's own errors name
    /// the hull file); a study that reads gives configurations that the 2D+t scene accepts.
    #[test]
    fn damaged_study_files_give_errors_not_panics(
        which in 0..6usize,
        edits in prop::collection::vec(edit(), 1..4),
    ) {
        let name = ["quick", "athena", "athena-trend", "athena-fr0.5-thesis-spacings", "alliance", "wigley"][which];
        let original = std::fs::read_to_string(project(&format!("studies/{name}.toml"))).unwrap();
        let text = apply(&original, &edits);
        let scratch = Scratch::new("study");
        let dir = &scratch.0;
        std::fs::create_dir_all(dir.join("studies")).unwrap();
        std::fs::create_dir_all(dir.join("hulls")).unwrap();
        for hull in ["athena", "wigley", "alliance"] {
            std::fs::copy(project(&format!("hulls/{hull}.csv")), dir.join(format!("hulls/{hull}.csv"))).unwrap();
        }
        let path = dir.join("studies/damaged.toml");
        std::fs::write(&path, &text).unwrap();
        match no_panic("Study::read", &text, || Study::read(&path))? {
            Err(e) => {
                let e = format!("{e:#}");
                prop_assert!(e.contains("damaged.toml") || e.contains("hulls/"), "error without a file's name: {e}");
            }
            Ok(study) => {
                // A study file checks its own fields, so every configuration it resolves must pass the 2D+t
                // scene's checks too (else the study would read and its cases fail later).
                let checked = no_panic("case configurations", &text, || {
                    study.cases.iter().map(|c| c.config.check()).collect::<Result<Vec<()>, _>>()
                })?;
                prop_assert!(checked.is_ok(), "a study that reads has a case the scene refuses: {:#}", checked.unwrap_err());
            }
        }
    }
}

#[test]
fn numbers_are_found_where_toml_and_csv_put_them() {
    let t = "a = 1.5\nb = [-2, 3e-4]\nname = \"x2\"\nfr_0 = .5\n";
    let found: Vec<&str> = numbers(t).iter().map(|&(a, b)| &t[a..b]).collect();
    assert_eq!(found, ["1.5", "-2", "3e-4", ".5"]);
}

proptest! {
    #![proptest_config(config())]

    /// A checkpoint damaged on disk (bytes changed, the file cut short) reads back or gives an error naming
    /// the file; a length field turned huge must not be allocated.
    #[test]
    fn damaged_checkpoints_give_errors_not_panics(
        changes in prop::collection::vec((any::<usize>(), any::<u8>()), 0..4),
        cut in any::<usize>(),
    ) {
        use bowwave::io::checkpoint::Checkpoint;
        let scratch = Scratch::new("ckpt");
        let path = scratch.0.join("damaged.bin");
        let mut c = Checkpoint { header: serde_json::json!({"time": 0.25, "steps": 12}), ..Default::default() };
        c.arrays.insert("pos_y".into(), vec![0.1, 0.2, 0.3]);
        c.arrays.insert("rho".into(), vec![1000.0; 3]);
        c.write(&path).unwrap();
        let mut bytes = std::fs::read(&path).unwrap();
        for (at, b) in changes {
            let n = bytes.len();
            bytes[at % n] = b;
        }
        bytes.truncate(cut % (bytes.len() + 1));
        std::fs::write(&path, &bytes).unwrap();
        let text = format!("{bytes:?}");
        if let Err(e) = no_panic("Checkpoint::read", &text, || Checkpoint::read(&path))? {
            prop_assert!(format!("{e:#}").contains("damaged.bin"), "{e:#}");
        }
        if let Err(e) = no_panic("Checkpoint::read_header", &text, || Checkpoint::read_header(&path))? {
            prop_assert!(format!("{e:#}").contains("damaged.bin"), "{e:#}");
        }
    }
}

/// Regression: the property tests left one `bowwave-fuzz-*-<pid>` folder per run in the temporary directory
/// (50 of them after a few sessions). A case's scratch folder is now gone once the case is over.
#[test]
fn fuzz_scratch_folders_are_removed_after_each_case() {
    let path = {
        let scratch = Scratch::new("leak-check");
        std::fs::write(scratch.0.join("damaged.toml"), "x = 1").unwrap();
        assert!(scratch.0.join("damaged.toml").exists());
        scratch.0.clone()
    };
    assert!(!path.exists(), "{} was left behind", path.display());
}
