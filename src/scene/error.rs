//! What can be wrong with a scene file: every problem names the file, the TOML key path, the
//! offending value and what was expected.

use std::fmt;
use std::path::PathBuf;
use thiserror::Error;

/// One problem found while validating a scene: `key = value: expected …`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Problem {
    /// The TOML key path (`mechanism.group[1].la`, `mechanism.crank.length`).
    pub key: String,
    /// The offending value as written (`-140`, `"X"`); `None` when the key is missing or the
    /// problem is about the whole table.
    pub value: Option<String>,
    /// What was expected instead (`expected a length > 0 mm`).
    pub expected: String,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.value {
            Some(value) => write!(f, "{} = {}: {}", self.key, value, self.expected),
            None => write!(f, "{}: {}", self.key, self.expected),
        }
    }
}

/// A scene file that cannot be used. Every variant is bad input (the CLI exits with code 2).
#[derive(Debug, Error)]
pub enum SceneError {
    /// The file could not be read.
    #[error("{}: cannot read the file: {source}", path.display())]
    Read {
        /// The scene file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The file is not UTF-8 text.
    #[error("{}:{line}: not UTF-8 text (byte {byte} of the file): expected a text file saved as UTF-8", path.display())]
    NotUtf8 {
        /// The file.
        path: PathBuf,
        /// The 1-based line of the first byte that is not UTF-8.
        line: usize,
        /// Its offset in the file.
        byte: usize,
    },
    /// The file is larger than a scene can be.
    #[error("{}: the file is larger than {limit} bytes: expected a scene, grid or table of at most {limit} bytes (1 MiB)", path.display())]
    TooLarge {
        /// The scene file.
        path: PathBuf,
        /// The largest scene, bytes.
        limit: u64,
    },
    /// The text is not TOML, or a value has the wrong type, or a key is unknown (reported by
    /// the TOML reader, with its line and column).
    #[error("{}:{line}:{column}: {}{message}", path.display(), key_value(key, value))]
    Toml {
        /// The scene file.
        path: PathBuf,
        /// 1-based line of the offending text.
        line: usize,
        /// 1-based column (in characters) of the offending text.
        column: usize,
        /// The key path the offending text belongs to, when it could be told.
        key: Option<String>,
        /// The offending text.
        value: Option<String>,
        /// The TOML reader's message (`invalid type: string "abc", expected f64`).
        message: String,
    },
    /// The file is well-formed TOML but describes an invalid scene: one problem per line.
    #[error("{}", list(path, problems))]
    Invalid {
        /// The scene file.
        path: PathBuf,
        /// All the problems found, in file order as far as possible (never empty).
        problems: Vec<Problem>,
    },
}

impl SceneError {
    /// The problems of an [`SceneError::Invalid`] scene (empty for the other variants).
    pub fn problems(&self) -> &[Problem] {
        match self {
            SceneError::Invalid { problems, .. } => problems,
            _ => &[],
        }
    }
}

/// `key = value: ` (or less when either is unknown) before a TOML reader's message.
fn key_value(key: &Option<String>, value: &Option<String>) -> String {
    match (key, value) {
        (Some(k), Some(v)) => format!("{k} = {v}: "),
        (Some(k), None) => format!("{k}: "),
        (None, Some(v)) => format!("{v}: "),
        (None, None) => String::new(),
    }
}

/// One `path: problem` line per problem.
fn list(path: &std::path::Path, problems: &[Problem]) -> String {
    let lines: Vec<String> = problems
        .iter()
        .map(|p| format!("{}: {p}", path.display()))
        .collect();
    lines.join("\n")
}
