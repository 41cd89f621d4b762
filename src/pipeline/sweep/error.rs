//! What a bad sweep file is told: the file, the field, what was expected.

/// A sweep that cannot be read: names the file and the field.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SweepError {
    /// The file could not be read.
    #[error("{file}: cannot read: {message}")]
    Io {
        /// File name.
        file: String,
        /// OS message.
        message: String,
    },
    /// The TOML did not parse (the message gives line and column).
    #[error("{file}: {message}")]
    Parse {
        /// File name.
        file: String,
        /// Parser message.
        message: String,
    },
    /// A field is missing or inconsistent.
    #[error("{file}: {field}: {message}")]
    Field {
        /// File name.
        file: String,
        /// The field.
        field: String,
        /// What is expected.
        message: String,
    },
}

/// A field error of `file`.
pub(super) fn field(file: &str, field: &str, message: impl Into<String>) -> SweepError {
    SweepError::Field {
        file: file.into(),
        field: field.into(),
        message: message.into(),
    }
}
