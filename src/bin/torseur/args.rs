//! The command line's arguments (clap), and their checks that need no work: kept apart from
//! the commands so that a fuzz target reaches them (`fuzz/fuzz_targets/args.rs`).

use clap::{Parser, Subcommand};
use std::path::PathBuf;

#[derive(Parser)]
#[command(
    name = "torseur",
    version,
    about = "Exact derivations of rigid-body dynamics in the course's torsor notation"
)]
pub struct Cli {
    /// Stop with a clear message (exit 2) if the work takes longer than this many seconds;
    /// nothing is written then.
    #[arg(long, global = true, value_name = "SECONDS")]
    pub timeout: Option<f64>,
    /// The derivation's budget of terms: the most its expressions may hold at once, and the
    /// most a product may form before like terms combine; past it the run stops (exit 2)
    /// naming what grew. A derivation that fits gives the same result under any budget.
    #[arg(long, global = true, value_name = "N", default_value_t = torseur::expr::budget::DEFAULT_MAX_TERMS as u64,
          value_parser = clap::value_parser!(u64).range(1..))]
    pub max_terms: u64,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand)]
pub enum Command {
    /// Closed forms of the spec's quantities (or of those given with --quantity).
    Derive(DeriveArgs),
    /// The whole answer key (« corrigé ») as LaTeX, on stdout or in a file, optionally as PDF.
    AnswerKey(AnswerKeyArgs),
    /// Numbers: evaluates quantities at the values of a JSON file.
    Eval(EvalArgs),
    /// Symbolic results against the independent float backend, and every result of its
    /// quantity's dimension (exit 1 on a mismatch or a wrong dimension).
    Check(CheckArgs),
    /// Integrates the equations of motion for a scenario of the spec: CSV on stdout or in a
    /// file, plots as SVG and PNG.
    Simulate(SimulateArgs),
    /// Exact equivalence of a hand-written result or equation with the engine's (exit 1 if
    /// not): a value, an equation of motion up to a nonzero factor of parameters (reported),
    /// or a relation between quantities, unknowns and expressions.
    Verify(VerifyArgs),
}

// The arguments of `torseur derive`.
#[derive(clap::Args)]
pub struct DeriveArgs {
    /// Problem spec (JSON; `-` reads standard input).
    pub spec: PathBuf,
    /// A quantity in course notation, e.g. `delta(O2,2/0).x2`; repeatable.
    #[arg(long = "quantity", short = 'q')]
    pub quantities: Vec<String>,
    /// Also write the full results (canonical and presentation forms, steps) as JSON.
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Also write the answer key (LaTeX) of the spec's quantities.
    #[arg(long)]
    pub latex: Option<PathBuf>,
    /// Print the number of terms of each canonical form, and the time taken, on stderr.
    #[arg(long)]
    pub stats: bool,
    /// The written form on stdout: `presentation` (as a teacher writes it) or `canonical`
    /// (the expanded polynomial, for tools; the JSON has both).
    #[arg(long, value_enum, default_value_t = Form::Presentation)]
    pub form: Form,
}

// The arguments of `torseur answerkey`.
#[derive(clap::Args)]
pub struct AnswerKeyArgs {
    /// Problem spec (JSON; `-` reads standard input).
    pub spec: PathBuf,
    /// Output .tex file (stdout if absent or `-`); its figures are written beside it, named
    /// after it.
    #[arg(short = 'o', long = "output")]
    pub output: Option<PathBuf>,
    /// Also compile the PDF with pdflatex (next to the .tex file).
    #[arg(long, requires = "output")]
    pub pdf: bool,
    /// How vectors are written: `sum` over the basis vectors, or `column` with the basis
    /// as subscript (long vectors stay sums).
    #[arg(long, value_enum, default_value_t = Vectors::Sum)]
    pub vectors: Vectors,
    /// Also write every displayed formula as JSON: what it shows, under which hypothesis,
    /// its LaTeX exactly as printed, and the engine's value (canonical text).
    #[arg(long)]
    pub manifest: Option<PathBuf>,
    /// Write only the bodies of the questions, to paste into your own document: no
    /// \documentclass, no \begin{document}; the packages they need in a comment, then the
    /// notation's macros as \providecommand (your own definitions win); lines broken for a
    /// 12 pt page with 2.5 cm margins.
    #[arg(long)]
    pub fragment: bool,
    /// With --fragment: the questions to write, numbered from 1 (`2,4`); all by default.
    #[arg(long, value_delimiter = ',', requires = "fragment")]
    pub questions: Vec<usize>,
}

// The arguments of `torseur eval`.
#[derive(clap::Args)]
pub struct EvalArgs {
    /// Problem spec (JSON; `-` reads standard input).
    pub spec: PathBuf,
    /// Values file: {"parameters":{..},"coordinates":{"q":[q,qdot,qddot]}}.
    #[arg(long)]
    pub at: PathBuf,
    /// A quantity in course notation; repeatable.
    #[arg(long = "quantity", short = 'q')]
    pub quantities: Vec<String>,
}

// The arguments of `torseur check`.
#[derive(clap::Args)]
pub struct CheckArgs {
    /// Problem spec (JSON; `-` reads standard input).
    pub spec: PathBuf,
    /// Random samples per quantity.
    #[arg(long, default_value_t = 20)]
    pub samples: usize,
    /// Seed of the random generator (reproducible runs).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Print the report as JSON.
    #[arg(long)]
    pub json: bool,
}

// The arguments of `torseur simulate`.
#[derive(clap::Args)]
pub struct SimulateArgs {
    /// Problem spec (JSON; `-` reads standard input).
    pub spec: PathBuf,
    /// Scenario name (the spec's `scenarios`).
    #[arg(long)]
    pub scenario: String,
    /// Output CSV file (stdout if absent or `-`).
    #[arg(short = 'o', long = "output")]
    pub output: Option<PathBuf>,
    /// Plot as SVG (every coordinate and recorded quantity against time).
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Plot as PNG.
    #[arg(long)]
    pub png: Option<PathBuf>,
}

// The arguments of `torseur verify`.
#[derive(clap::Args)]
pub struct VerifyArgs {
    /// Problem spec (JSON; `-` reads standard input).
    pub spec: PathBuf,
    /// The quantity, in course notation; without it, --expr is an equation `lhs = rhs`.
    #[arg(long = "quantity", short = 'q')]
    pub quantity: Option<String>,
    /// The hand-written value: a scalar; a vector over any bases (`a*x1 + b*y2`) or
    /// `[x, y, z]` in the quantity's basis; a torsor `[R, M]`, each element either way; or
    /// an equation `lhs = rhs`; `@FILE` reads it from FILE (a long text). Quantities
    /// (`delta(O2,2/0).x2`, `eom(theta)`) and unknowns (`X01`, `C_m`) may be written in it.
    #[arg(long = "expr", short = 'e', allow_hyphen_values = true)]
    pub expr: String,
    /// Compare with the derived value under this hypothesis of the spec.
    #[arg(long)]
    pub hypothesis: Option<String>,
}

/// The written form of `derive`'s text.
#[derive(Clone, Copy, clap::ValueEnum)]
pub enum Form {
    /// As a teacher writes it: sin² θ, cos(θ2 − θ1), m2 (L1 + L2 cos θ2)²
    Presentation,
    /// The canonical polynomial, expanded
    Canonical,
    /// Named subexpressions (each nested set's dynamic resultant and moment, once), each
    /// quantity over them, and the equations of motion M(q) q'' + h = Q over them: the form
    /// that stays small for a long chain
    Structured,
}

/// How vectors are written in the answer key.
#[derive(Clone, Copy, clap::ValueEnum)]
pub enum Vectors {
    /// a x2 + b y2 + c z2
    Sum,
    /// (a, b, c) in a column, with the basis as subscript
    Column,
}

/// The longest time limit accepted (about 31 years): a longer one is a typing error.
pub const MAX_TIMEOUT: f64 = 1e9;

/// `--timeout`'s seconds as a duration: positive, finite, at most [`MAX_TIMEOUT`].
pub fn time_limit(seconds: f64) -> Result<std::time::Duration, String> {
    if !(seconds.is_finite() && seconds > 0.0 && seconds <= MAX_TIMEOUT) {
        return Err(format!(
            "--timeout takes a positive number of seconds, at most {MAX_TIMEOUT:e}"
        ));
    }
    std::time::Duration::try_from_secs_f64(seconds).map_err(|e| format!("--timeout: {e}"))
}
