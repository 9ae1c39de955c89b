//! Cases: the TOML description of a run, the built-in cases, their set-up as a simulation, and the driver
//! that runs one and writes its outputs.

pub mod box_tank;
pub mod builtin;
pub mod case_file;
pub mod cavity_probe;
pub mod overrides;
pub mod reference_file;
pub mod run;
pub mod sensor_placement;
pub mod setup;
pub mod variant;
pub mod wall_motion;

use crate::input_error::InputError;
pub use case_file::CaseFile;

/// Loads a case by built-in name or from a TOML file path.
pub fn load(name_or_path: &str) -> Result<CaseFile, InputError> {
    if let Some(text) = builtin::builtin_text(name_or_path) {
        return CaseFile::parse(text, &format!("built-in case `{name_or_path}`"));
    }
    let path = std::path::Path::new(name_or_path);
    if !path.exists() {
        return Err(InputError::field(
            name_or_path,
            "CASE",
            format!(
                "a built-in case ({}) or an existing .toml file",
                builtin::builtin_names().join(", ")
            ),
        ));
    }
    CaseFile::read(path)
}
