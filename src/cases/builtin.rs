//! The built-in cases: the TOML files of `cases/`, compiled into the binary so they run by name.

/// (name, TOML text) of every built-in case.
pub const BUILTIN: &[(&str, &str)] = &[
    ("hydrostatic", include_str!("../../cases/hydrostatic.toml")),
    ("dam-break", include_str!("../../cases/dam-break.toml")),
    ("dam-break-mm", include_str!("../../cases/dam-break-mm.toml")),
    ("elliptic-drop", include_str!("../../cases/elliptic-drop.toml")),
    ("oscillating-drop", include_str!("../../cases/oscillating-drop.toml")),
    ("jet-wall", include_str!("../../cases/jet-wall.toml")),
    ("jet-plate", include_str!("../../cases/jet-plate.toml")),
    ("jet-floor", include_str!("../../cases/jet-floor.toml")),
    ("sloshing-deep", include_str!("../../cases/sloshing-deep.toml")),
    ("sloshing-shallow", include_str!("../../cases/sloshing-shallow.toml")),
    ("stokes-wall", include_str!("../../cases/stokes-wall.toml")),
    ("two-layer", include_str!("../../cases/two-layer.toml")),
    ("two-phase-drop-2", include_str!("../../cases/two-phase-drop-2.toml")),
    (
        "two-phase-drop-100",
        include_str!("../../cases/two-phase-drop-100.toml"),
    ),
];

/// The TOML text of a built-in case.
pub fn builtin_text(name: &str) -> Option<&'static str> {
    BUILTIN.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
}

/// Names of the built-in cases.
pub fn builtin_names() -> Vec<&'static str> {
    BUILTIN.iter().map(|(n, _)| *n).collect()
}
