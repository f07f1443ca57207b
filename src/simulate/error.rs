//! The error type of the [`simulate`](super) module.

use std::path::PathBuf;

/// Everything that can go wrong while integrating, tabulating or plotting.
///
/// No function of the module panics on bad input: each failure is one of these variants.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SimError {
    /// An argument or an option is out of its domain (empty state, `t_end <= t0`, a tolerance
    /// that is not positive, a NaN breakpoint, a table row of the wrong length, ...).
    #[error("invalid input: {0}")]
    InvalidInput(String),

    /// The right-hand side `f(t, y)` returned an error; the integration stopped there.
    #[error("right-hand side failed at t = {t} s: {message}")]
    Rhs {
        /// Time of the failing evaluation, in seconds.
        t: f64,
        /// The message returned by the right-hand side.
        message: String,
    },

    /// The right-hand side returned a derivative that is NaN or infinite.
    #[error("right-hand side returned a non-finite derivative dy[{index}] = {value} at t = {t} s")]
    NonFinite {
        /// Time of the evaluation, in seconds.
        t: f64,
        /// Index of the first non-finite component.
        index: usize,
        /// Its value.
        value: f64,
    },

    /// The step budget [`Options::max_steps`](super::Options::max_steps) was exhausted.
    #[error("step budget exhausted at t = {t} s ({steps} steps): raise Options::max_steps")]
    MaxSteps {
        /// Time reached, in seconds.
        t: f64,
        /// Number of steps (accepted and rejected) taken so far.
        steps: u64,
    },

    /// The step size fell below the resolution of `t` (a singularity, or an unreachable
    /// tolerance).
    #[error("step size underflow at t = {t} s")]
    StepSizeUnderflow {
        /// Time reached, in seconds.
        t: f64,
    },

    /// The problem looks stiff: an explicit method would need tiny steps.
    #[error("the problem looks stiff at t = {t} s")]
    Stiff {
        /// Time reached, in seconds.
        t: f64,
    },

    /// The integrator stopped in a state it should not reach (an internal inconsistency).
    #[error("integrator: {0}")]
    Integrator(String),

    /// Reading or writing a file failed.
    #[error("{op} {path}: {source}")]
    Io {
        /// What was being done (`"write"`, `"rename to"`, ...).
        op: &'static str,
        /// The file concerned.
        path: PathBuf,
        /// The underlying error.
        #[source]
        source: std::io::Error,
    },

    /// Drawing a chart failed (layout, font, backend).
    #[error("plot: {0}")]
    Plot(String),

    /// Encoding the PNG image failed.
    #[error("png encoding: {0}")]
    Png(String),
}
