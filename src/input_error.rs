//! Errors in the files a user writes (case files, study files): every one names the file and, for a bad value,
//! the field and what was expected there.

use serde::de::DeserializeOwned;
use std::path::Path;

/// An error in a user's input file.
#[derive(Debug, thiserror::Error)]
pub enum InputError {
    #[error("{file}: cannot read: {source}")]
    Io { file: String, source: std::io::Error },
    #[error("{file}: {message}")]
    Syntax { file: String, message: String },
    #[error("{file}: field `{field}`: expected {expected}")]
    Field {
        file: String,
        field: String,
        expected: String,
    },
}

impl InputError {
    /// A bad or missing value: `field` of `file` should have been `expected`.
    pub fn field(file: &str, field: &str, expected: impl Into<String>) -> Self {
        InputError::Field {
            file: file.into(),
            field: field.into(),
            expected: expected.into(),
        }
    }
}

/// The text of `path`, or an error naming it.
pub fn read_text(path: &Path) -> Result<String, InputError> {
    std::fs::read_to_string(path).map_err(|source| InputError::Io {
        file: path.display().to_string(),
        source,
    })
}

/// `text` parsed as TOML into `T` (unknown fields and wrong types are refused by `T`'s serde attributes); `file`
/// names it in the error.
pub fn parse_toml<T: DeserializeOwned>(text: &str, file: &str) -> Result<T, InputError> {
    toml::from_str(text).map_err(|e| InputError::Syntax {
        file: file.to_string(),
        message: e.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A study file that could not be read used to say only "cannot read", without the reason.
    #[test]
    fn a_file_that_cannot_be_read_is_named_with_the_reason() {
        let e = read_text(Path::new("no/such/study.toml")).unwrap_err().to_string();
        assert!(e.starts_with("no/such/study.toml: cannot read: "), "{e}");
        assert!(e.len() > "no/such/study.toml: cannot read: ".len(), "{e}");
    }

    #[test]
    fn a_toml_syntax_error_names_the_file() {
        #[derive(serde::Deserialize, Debug)]
        #[allow(dead_code)]
        struct T {
            a: f64,
        }
        let e = parse_toml::<T>("a = [", "case.toml").unwrap_err().to_string();
        assert!(e.starts_with("case.toml: "), "{e}");
    }
}
