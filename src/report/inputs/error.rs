//! What is wrong with an input, typed: the flag at fault ([`Flag`]) and how it is wrong
//! ([`InputError`]). The command line writes the flag as `--s-bar`, the Python package as the
//! keyword `s_bar`; both read it from the error, not from its text.

use crate::physics::case::CaseError;
use crate::physics::lubricant::LubricantError;
use crate::solver::point;
use std::fmt;

/// A flag of the command line (the Python package's keyword of the same name), by its name
/// without dashes, as clap spells it: `s-bar`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Flag(pub &'static str);

impl Flag {
    /// Its name without dashes (`s-bar`).
    pub fn name(self) -> &'static str {
        self.0
    }

    /// The Python package's keyword (`s_bar`).
    pub fn keyword(self) -> String {
        self.0.replace('-', "_")
    }
}

/// As the command line writes it: `--s-bar`.
impl fmt::Display for Flag {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "--{}", self.0)
    }
}

/// An input that cannot be used. Its text is one line that starts with the flag at fault
/// (`--s-bar: required`), other flags it mentions written as the command line writes them.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum InputError {
    /// A flag that is needed was not given; `with` says what needs it, where something does.
    #[error("{flag}: required{}", with.map(|w| format!(" {w}")).unwrap_or_default())]
    Missing {
        /// The flag.
        flag: Flag,
        /// What needs it (`with a datasheet`), if anything in particular.
        with: Option<&'static str>,
    },
    /// A flag's value is out of range, or the flag cannot go with another given.
    #[error("{flag}: {message}")]
    Invalid {
        /// The flag.
        flag: Flag,
        /// What is wrong.
        message: String,
    },
    /// The flags describe no case, or a case in two forms at once: no one flag is at fault.
    #[error("{0}")]
    Form(&'static str),
    /// The case cannot be solved for a reason no one flag stands for (a [`CaseError`]'s
    /// text: the error itself is not `Clone`).
    #[error("{0}")]
    Case(String),
}

impl InputError {
    /// `flag` is missing.
    pub fn missing(flag: &'static str) -> InputError {
        InputError::Missing {
            flag: Flag(flag),
            with: None,
        }
    }

    /// `flag` is missing where `with` needs it.
    pub fn missing_with(flag: &'static str, with: &'static str) -> InputError {
        InputError::Missing {
            flag: Flag(flag),
            with: Some(with),
        }
    }

    /// `flag` is wrong as `message` says.
    pub fn invalid(flag: &'static str, message: impl Into<String>) -> InputError {
        InputError::Invalid {
            flag: Flag(flag),
            message: message.into(),
        }
    }

    /// The flag at fault, where one is.
    pub fn flag(&self) -> Option<Flag> {
        match self {
            InputError::Missing { flag, .. } | InputError::Invalid { flag, .. } => Some(*flag),
            InputError::Form(_) | InputError::Case(_) => None,
        }
    }
}

/// `v`, or the error that `flag` is missing.
pub fn need(v: Option<f64>, flag: &'static str) -> Result<f64, InputError> {
    v.ok_or_else(|| InputError::missing(flag))
}

/// `v`, or the error that `flag` is missing where `with` needs it.
pub fn need_with(
    v: Option<f64>,
    flag: &'static str,
    with: &'static str,
) -> Result<f64, InputError> {
    v.ok_or_else(|| InputError::missing_with(flag, with))
}

/// Checks the grid level given by `flag` (`level`, `levels`).
pub fn check_level(flag: &'static str, level: u32) -> Result<u32, InputError> {
    if (point::MIN_LEVEL..=point::MAX_LEVEL).contains(&level) {
        Ok(level)
    } else {
        Err(InputError::invalid(
            flag,
            format!(
                "level {level} outside the supported range {}..={}",
                point::MIN_LEVEL,
                point::MAX_LEVEL
            ),
        ))
    }
}

/// A case error as the flag it names.
pub fn flag_error(e: CaseError) -> InputError {
    match e {
        CaseError::Field { field, message } => InputError::invalid(field, message),
        CaseError::Lubricant(l @ LubricantError::Unknown { .. }) => {
            InputError::invalid("lubricant", l.to_string())
        }
        CaseError::Lubricant(l @ LubricantError::Temperature { .. }) => {
            InputError::invalid("temperature", l.to_string())
        }
        CaseError::Datasheet(d) => InputError::invalid(datasheet_flag(d.field()), d.to_string()),
        other => InputError::Case(other.to_string()),
    }
}

/// The flag of a datasheet key ([`crate::physics::datasheet::DatasheetError::field`]).
fn datasheet_flag(key: &'static str) -> &'static str {
    match key {
        "nu40_mm2_s" => "nu40",
        "iso_vg" => "iso-vg",
        "nu100_mm2_s" => "nu100",
        "viscosity_index" => "vi",
        "rho15_kg_m3" => "rho15",
        "expansion15_per_k" => "expansion15",
        "base_oil" => "base-oil",
        "alpha_per_gpa" => "alpha",
        "temperature_c" => "temperature",
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_error_knows_its_flag_and_reads_as_one_line() {
        let e = InputError::missing("s-bar");
        assert_eq!(e.flag(), Some(Flag("s-bar")));
        assert_eq!(e.to_string(), "--s-bar: required");
        assert_eq!(Flag("s-bar").keyword(), "s_bar");
        let e = InputError::missing_with("nu40", "with a datasheet (or --iso-vg)");
        assert_eq!(
            e.to_string(),
            "--nu40: required with a datasheet (or --iso-vg)"
        );
        let e = check_level("levels", 30).unwrap_err();
        assert_eq!(e.flag(), Some(Flag("levels")));
        assert!(e.to_string().starts_with("--levels: level 30 outside"));
        assert_eq!(InputError::Form("give a case").flag(), None);
    }
}
