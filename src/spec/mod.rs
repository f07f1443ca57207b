//! Problem specs: JSON wire types and their validation into a [`crate::mechanism::Mechanism`].

mod builder;
mod closures;
mod coulomb;
mod dynamics;
mod hypotheses;
mod locate;
mod pipeline;
mod refusal;
mod scenarios;
mod sides;
mod solids;
mod solved;
mod statement;
mod texts;
mod trial;
mod validate;
/// The wire types, also at [`crate::wire`] (the spec's data, used by every layer).
pub use crate::wire;

pub use builder::Builder;
pub use locate::locate;
pub use pipeline::build;

use crate::excerpt::{bounded, excerpt};
use crate::mechanism::Mechanism;
use crate::wire::SpecFile;
use std::path::Path;

/// Why a spec was refused. Every variant names the place in the file; its message quotes at
/// most an excerpt of each piece of input, and is at most [`crate::excerpt::MAX_MESSAGE`]
/// bytes long, the place first.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SpecError {
    /// The file could not be read.
    #[error("{}", shown(&excerpt(file), None, message))]
    Io {
        /// The file.
        file: String,
        /// What went wrong.
        message: String,
    },
    /// Not JSON, or not the spec's shape.
    #[error("{}", shown(&json_place(path), Some((*line, *column)), message))]
    Json {
        /// JSON path of the value (`solids[1].mass`); empty for a JSON syntax error, which
        /// only has a line and column.
        path: String,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What is wrong.
        message: String,
    },
    /// Valid JSON whose content is wrong (an unknown frame, a cycle, a bad expression...).
    #[error("{}", shown(&format!("at {}", excerpt(path)), *location, message))]
    Invalid {
        /// JSON path of the value.
        path: String,
        /// What is wrong.
        message: String,
        /// 1-based line and column of the value, when the text is known.
        location: Option<(usize, usize)>,
    },
}

/// `place (line l, column c): message`, bounded.
/// « at solids[1].mass », or « in the JSON text » where there is no path.
fn json_place(path: &str) -> String {
    if path.is_empty() {
        "in the JSON text".to_string()
    } else {
        format!("at {}", excerpt(path))
    }
}

fn shown(place: &str, location: Option<(usize, usize)>, message: &str) -> String {
    let at = location
        .map(|(l, c)| format!(" (line {l}, column {c})"))
        .unwrap_or_default();
    bounded(&format!("{place}{at}: {message}")).into_owned()
}

/// Largest spec file accepted (a hand-written spec is a few kilobytes).
pub const MAX_SPEC_BYTES: u64 = crate::input::MAX_SPEC_BYTES;

/// The JSON Schema (draft 2020-12) of a spec file, generated from the wire types: their doc
/// comments are its descriptions. The repository commits it as `spec.schema.json`, and every
/// spec names it in its `$schema` key so that an editor validates and completes it.
///
/// ```
/// let schema = torseur::spec::json_schema();
/// assert_eq!(schema["title"], "SpecFile");
/// assert_eq!(schema["additionalProperties"], false);
/// assert!(schema["properties"]["links"].is_object());
/// ```
pub fn json_schema() -> serde_json::Value {
    schemars::schema_for!(wire::SpecFile).to_value()
}

/// Reads, parses and validates a spec file (`-`: standard input).
///
/// ```
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// assert_eq!(m.bodies().len(), 2);
/// ```
pub fn load(path: impl AsRef<Path>) -> Result<Mechanism, SpecError> {
    from_str(&read(path)?)
}

/// Reads a spec's text, bounded by [`MAX_SPEC_BYTES`] while it is read (`-`: standard
/// input), without parsing it: no symbolica work, so the CLI reads every input before it
/// queues for symbolica.
///
/// ```
/// let dir = tempfile::tempdir().unwrap();
/// let p = dir.path().join("big.json");
/// std::fs::write(&p, vec![b' '; 5 << 20]).unwrap();
/// let e = torseur::spec::read(&p).unwrap_err().to_string();
/// assert!(e.ends_with("larger than 4194304 bytes"), "{e}");
/// ```
pub fn read(path: impl AsRef<Path>) -> Result<String, SpecError> {
    let p = path.as_ref();
    crate::input::read_text(p, MAX_SPEC_BYTES).map_err(|e| SpecError::Io {
        file: if p.as_os_str() == "-" {
            "standard input".to_string()
        } else {
            p.display().to_string()
        },
        message: match e {
            crate::input::InputError::Io { source, .. } => source.to_string(),
            crate::input::InputError::TooLarge { limit, .. } => {
                format!("larger than {limit} bytes")
            }
            crate::input::InputError::NotText { offset, .. } => {
                format!("not UTF-8 text (invalid byte at offset {offset})")
            }
        },
    })
}

/// Parses and validates spec text; errors carry the line and column of the value.
pub fn from_str(text: &str) -> Result<Mechanism, SpecError> {
    build(&parse_spec(text)?).map_err(|e| match e {
        SpecError::Invalid { path, message, .. } => SpecError::Invalid {
            location: located(text, &path),
            path,
            message,
        },
        other => other,
    })
}

/// Where the value at `path` is in `text`; for a value left out (a solid's `mass`), where the
/// object that should hold it is.
fn located(text: &str, path: &str) -> Option<(usize, usize)> {
    locate(text, path).or_else(|| {
        let parent = path.rsplit_once('.')?.0;
        locate(text, parent)
    })
}

/// Reads a spec from JSON text, with the JSON path and line/column of a structural error.
/// serde_json's recursion limit turns absurdly deep nesting into an error, not a stack overflow.
pub fn parse_spec(text: &str) -> Result<SpecFile, SpecError> {
    let mut de = serde_json::Deserializer::from_str(text);
    let spec: SpecFile = serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner();
        // An array longer than its fixed length (a 3-vector given 4 names) is a syntax error
        // of serde_json's, « trailing characters », inside the document: its path says where.
        if inner.is_syntax()
            && inner.to_string().starts_with("trailing characters")
            && let Some(n) = locate::fixed_length(&path)
        {
            return SpecError::Json {
                path,
                line: inner.line(),
                column: inner.column(),
                message: format!("more elements than the {n} this array holds"),
            };
        }
        // A syntax error has no path (`?`); the line and column say where.
        let path = if inner.is_syntax() || inner.is_eof() || path == "?" {
            String::new()
        } else {
            path
        };
        json_error(path, &inner)
    })?;
    de.end().map_err(|e| json_error(String::new(), &e))?;
    Ok(spec)
}

/// A JSON error at `path`, its message without serde_json's « at line L column C » (the
/// error prints the line and column once, after the path).
fn json_error(path: String, e: &serde_json::Error) -> SpecError {
    let text = e.to_string();
    let suffix = format!(" at line {} column {}", e.line(), e.column());
    SpecError::Json {
        path,
        line: e.line(),
        column: e.column(),
        message: text.strip_suffix(&suffix).unwrap_or(&text).to_string(),
    }
}
