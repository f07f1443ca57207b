//! The `torseur` command line: parse arguments, call the library, print.
//!
//! Exit codes: 0 success, 1 a mathematical mismatch, 2 bad input or usage.

use anyhow::{Context, Result, anyhow};
use clap::{Parser, Subcommand};
use std::fs::File;
use std::io::Write;
use std::os::fd::FromRawFd;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

// The chains' long polynomials are allocated and freed by the million; glibc's allocator
// spent a third of a chain 10 run in page faults and `free`.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;
use torseur::derivation::{Derivation, derive};
use torseur::mechanism::Mechanism;
use torseur::output;
use torseur::quantity::Quantity;

#[derive(Parser)]
#[command(
    name = "torseur",
    version,
    about = "Exact derivations of rigid-body dynamics in the course's torsor notation"
)]
struct Cli {
    /// Stop with a clear message (exit 2) if the work takes longer than this many seconds.
    #[arg(long, global = true, value_name = "SECONDS")]
    timeout: Option<f64>,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
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
struct DeriveArgs {
    /// Problem spec (JSON).
    spec: PathBuf,
    /// A quantity in course notation, e.g. `delta(O2,2/0).x2`; repeatable.
    #[arg(long = "quantity", short = 'q')]
    quantities: Vec<String>,
    /// Also write the full results (canonical and presentation forms, steps) as JSON.
    #[arg(long)]
    json: Option<PathBuf>,
    /// Also write the answer key (LaTeX) of the spec's quantities.
    #[arg(long)]
    latex: Option<PathBuf>,
    /// Print the number of terms of each canonical form, and the time taken, on stderr.
    #[arg(long)]
    stats: bool,
    /// The written form on stdout: `presentation` (as a teacher writes it) or `canonical`
    /// (the expanded polynomial, for tools; the JSON has both).
    #[arg(long, value_enum, default_value_t = Form::Presentation)]
    form: Form,
}

// The arguments of `torseur answerkey`.
#[derive(clap::Args)]
struct AnswerKeyArgs {
    /// Problem spec (JSON).
    spec: PathBuf,
    /// Output .tex file (stdout if absent).
    #[arg(short = 'o', long = "output")]
    output: Option<PathBuf>,
    /// Also compile the PDF with pdflatex (next to the .tex file).
    #[arg(long, requires = "output")]
    pdf: bool,
    /// How vectors are written: `sum` over the basis vectors, or `column` with the basis
    /// as subscript (long vectors stay sums).
    #[arg(long, value_enum, default_value_t = Vectors::Sum)]
    vectors: Vectors,
    /// Also write every displayed formula as JSON: what it shows, under which hypothesis,
    /// its LaTeX exactly as printed, and the engine's value (canonical text).
    #[arg(long)]
    manifest: Option<PathBuf>,
}

// The arguments of `torseur eval`.
#[derive(clap::Args)]
struct EvalArgs {
    /// Problem spec (JSON).
    spec: PathBuf,
    /// Values file: {"parameters":{..},"coordinates":{"q":[q,qdot,qddot]}}.
    #[arg(long)]
    at: PathBuf,
    /// A quantity in course notation; repeatable.
    #[arg(long = "quantity", short = 'q')]
    quantities: Vec<String>,
}

// The arguments of `torseur check`.
#[derive(clap::Args)]
struct CheckArgs {
    /// Problem spec (JSON).
    spec: PathBuf,
    /// Random samples per quantity.
    #[arg(long, default_value_t = 20)]
    samples: usize,
    /// Seed of the random generator (reproducible runs).
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Print the report as JSON.
    #[arg(long)]
    json: bool,
}

// The arguments of `torseur simulate`.
#[derive(clap::Args)]
struct SimulateArgs {
    /// Problem spec (JSON).
    spec: PathBuf,
    /// Scenario name (the spec's `scenarios`).
    #[arg(long)]
    scenario: String,
    /// Output CSV file (stdout if absent).
    #[arg(short = 'o', long = "output")]
    output: Option<PathBuf>,
    /// Plot as SVG (every coordinate and recorded quantity against time).
    #[arg(long)]
    plot: Option<PathBuf>,
    /// Plot as PNG.
    #[arg(long)]
    png: Option<PathBuf>,
}

// The arguments of `torseur verify`.
#[derive(clap::Args)]
struct VerifyArgs {
    /// Problem spec (JSON).
    spec: PathBuf,
    /// The quantity, in course notation; without it, --expr is an equation `lhs = rhs`.
    #[arg(long = "quantity", short = 'q')]
    quantity: Option<String>,
    /// The hand-written value: a scalar; a vector over any bases (`a*x1 + b*y2`) or
    /// `[x, y, z]` in the quantity's basis; a torsor `[R, M]`, each element either way; or
    /// an equation `lhs = rhs`; `@FILE` reads it from FILE (a long text). Quantities
    /// (`delta(O2,2/0).x2`, `eom(theta)`) and unknowns (`X01`, `C_m`) may be written in it.
    #[arg(long = "expr", short = 'e', allow_hyphen_values = true)]
    expr: String,
    /// Compare with the derived value under this hypothesis of the spec.
    #[arg(long)]
    hypothesis: Option<String>,
}

/// The written form of `derive`'s text.
#[derive(Clone, Copy, clap::ValueEnum)]
enum Form {
    /// As a teacher writes it: sin² θ, cos(θ2 − θ1), m2 (L1 + L2 cos θ2)²
    Presentation,
    /// The canonical polynomial, expanded
    Canonical,
}

/// How vectors are written in the answer key.
#[derive(Clone, Copy, clap::ValueEnum)]
enum Vectors {
    /// a x2 + b y2 + c z2
    Sum,
    /// (a, b, c) in a column, with the basis as subscript
    Column,
}

/// A failure with its exit code.
struct Failure {
    code: u8,
    error: anyhow::Error,
}

fn bad_input(e: impl Into<anyhow::Error>) -> Failure {
    Failure {
        code: 2,
        error: e.into(),
    }
}

fn main() -> ExitCode {
    // symbolica prints its licence notice on stdout: stdout is kept for our own output, and
    // file descriptor 1 is pointed at stderr so the notice stays visible there.
    let out = match redirect_stdout() {
        Ok(f) => f,
        Err(e) => {
            eprintln!("torseur: error: {e:#}");
            return ExitCode::from(2);
        }
    };
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    match run(cli, out) {
        Ok(()) => ExitCode::SUCCESS,
        // Bad input is named by an excerpt of it; a mismatch report (exit 1) is kept whole.
        Err(f) if f.code == 2 => {
            let message = error_text(&f.error);
            eprintln!("torseur: error: {}", torseur::excerpt::bounded(&message));
            ExitCode::from(2)
        }
        Err(f) => {
            eprintln!("torseur: error: {}", error_text(&f.error));
            ExitCode::from(f.code)
        }
    }
}

/// An error and its causes, each said once: a cause whose text the message already holds
/// (an error that prints its source, « float backend: X », with X as its source) is not
/// repeated.
fn error_text(e: &anyhow::Error) -> String {
    let mut out = String::new();
    for cause in e.chain() {
        let text = cause.to_string();
        if out.contains(&text) {
            continue;
        }
        if !out.is_empty() {
            out.push_str(": ");
        }
        out.push_str(&text);
    }
    out
}

fn redirect_stdout() -> Result<File> {
    // SAFETY: dup and dup2 on the standard descriptors; the duplicate is owned by the File.
    unsafe {
        let saved = libc::dup(1);
        if saved < 0 {
            return Err(anyhow!("cannot duplicate stdout"));
        }
        if libc::dup2(2, 1) < 0 {
            return Err(anyhow!("cannot redirect stdout"));
        }
        Ok(File::from_raw_fd(saved))
    }
}

fn load(spec: &Path) -> Result<Mechanism, Failure> {
    torseur::spec::load(spec).map_err(bad_input)
}

fn quantities(m: &Mechanism, given: &[String]) -> Result<Vec<Quantity>, Failure> {
    if given.is_empty() {
        return Ok(m.quantities().to_vec());
    }
    given
        .iter()
        .map(|q| Quantity::parse(q).map_err(bad_input))
        .collect()
}

/// With the steps of the course's methodology (for JSON and LaTeX).
fn derive_all(m: &Mechanism, qs: &[Quantity]) -> Result<Vec<Derivation>, Failure> {
    qs.iter().map(|q| derive(m, q).map_err(bad_input)).collect()
}

/// Values only, by the fastest exact route; progress on stderr once the work passes a second.
fn values_only(m: &Mechanism, qs: &[Quantity]) -> Result<Vec<Derivation>, Failure> {
    let start = std::time::Instant::now();
    torseur::derivation::derive_values_with(m, qs, |k, q| {
        let t = start.elapsed().as_secs_f64();
        if t > 1.0 {
            eprintln!("torseur: derived {k}/{} ({q}) after {t:.1} s", qs.len());
        }
    })
    .map_err(bad_input)
}

/// Ends the process with a clear message if `limit` seconds pass. Outputs are written
/// atomically at the very end, so nothing half-written is left.
fn watchdog(limit: f64) -> Result<(), Failure> {
    if !(limit.is_finite() && limit > 0.0) {
        return Err(bad_input(anyhow!(
            "--timeout takes a positive number of seconds"
        )));
    }
    std::thread::spawn(move || {
        std::thread::sleep(std::time::Duration::from_secs_f64(limit));
        eprintln!("torseur: error: stopped after the time limit of {limit} s (--timeout)");
        std::process::exit(2);
    });
    Ok(())
}

/// The answer key's figures as PNG, all rendered before anything is written.
fn render_figures(key: &torseur::latex::AnswerKey) -> Result<Vec<(String, Vec<u8>)>, Failure> {
    key.figures
        .iter()
        .map(|(name, fig)| Ok((name.clone(), fig.to_png(2).map_err(bad_input)?)))
        .collect()
}

/// Writes the figures next to the .tex file, where `\includegraphics` finds them.
fn write_figures(tex: &Path, figures: &[(String, Vec<u8>)]) -> Result<(), Failure> {
    let dir = tex.parent().unwrap_or(Path::new(""));
    for (name, bytes) in figures {
        write_atomic(&dir.join(name), bytes)?;
    }
    Ok(())
}

/// Writes a file atomically ([`torseur::output::write_atomic`]).
fn write_atomic(path: &Path, content: &[u8]) -> Result<(), Failure> {
    torseur::output::write_atomic(path, content).map_err(bad_input)
}

/// Compiles LaTeX with pdflatex in a temporary directory (no shell escape) and returns the PDF.
fn compile_pdf(tex: &str, figures: &[(String, Vec<u8>)]) -> Result<Vec<u8>, Failure> {
    let dir = tempfile::tempdir().map_err(bad_input)?;
    std::fs::write(dir.path().join("key.tex"), tex).map_err(bad_input)?;
    for (name, bytes) in figures {
        std::fs::write(dir.path().join(name), bytes).map_err(bad_input)?;
    }
    let run = || {
        std::process::Command::new("pdflatex")
            .args([
                "-no-shell-escape",
                "-interaction=nonstopmode",
                "-halt-on-error",
                "key.tex",
            ])
            .current_dir(dir.path())
            .stdin(std::process::Stdio::null())
            .output()
    };
    let o = match run() {
        Ok(o) => o,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Err(bad_input(anyhow!(
                "pdflatex is not installed (run scripts/setup, or install Debian's texlive)"
            )));
        }
        Err(e) => return Err(bad_input(anyhow!("cannot run pdflatex: {e}"))),
    };
    if !o.status.success() {
        let log = String::from_utf8_lossy(&o.stdout);
        let tail: Vec<&str> = log
            .lines()
            .filter(|l| l.starts_with('!') || l.starts_with("l."))
            .collect();
        return Err(Failure {
            code: 1,
            error: anyhow!("pdflatex failed: {}", tail.join(" | ")),
        });
    }
    // Report lines that overflow the page by more than 20pt (the key must fit the page).
    let log = std::fs::read_to_string(dir.path().join("key.log")).unwrap_or_default();
    for l in log.lines().filter(|l| l.starts_with("Overfull \\hbox (")) {
        let pt: f64 = l["Overfull \\hbox (".len()..]
            .split("pt")
            .next()
            .and_then(|x| x.parse().ok())
            .unwrap_or(0.0);
        if pt > 20.0 {
            eprintln!("torseur: warning: {l}");
        }
    }
    std::fs::read(dir.path().join("key.pdf")).map_err(bad_input)
}

/// Writes a command's text to stdout.
type Emit<'a> = dyn FnMut(&str) -> Result<(), Failure> + 'a;

fn run(cli: Cli, mut out: File) -> Result<(), Failure> {
    if let Some(limit) = cli.timeout {
        watchdog(limit)?;
    }
    let _lock = torseur::lock::ProcessLock::acquire(|| {
        eprintln!(
            "torseur: waiting for another torseur run to finish (symbolica allows one at a time)"
        )
    })
    .context("cannot take the torseur lock")
    .map_err(bad_input)?;
    let mut emit = |s: &str| -> Result<(), Failure> {
        out.write_all(s.as_bytes())
            .and_then(|_| out.flush())
            .map_err(|e| bad_input(anyhow!("cannot write to stdout: {e}")))
    };
    match cli.command {
        Command::Derive(a) => run_derive(a, &mut emit),
        Command::Eval(a) => run_eval(a, &mut emit),
        Command::AnswerKey(a) => run_answer_key(a, &mut emit),
        Command::Check(a) => run_check(a, &mut emit),
        Command::Simulate(a) => run_simulate(a, &mut emit),
        Command::Verify(a) => run_verify(a, &mut emit),
    }
}

/// `torseur derive`: closed forms, as text, JSON and LaTeX.
fn run_derive(a: DeriveArgs, emit: &mut Emit) -> Result<(), Failure> {
    let DeriveArgs {
        spec,
        quantities: qs,
        json,
        latex,
        stats,
        form,
    } = a;
    let start = std::time::Instant::now();
    let m = load(&spec)?;
    let qs = quantities(&m, &qs)?;
    let ds = if json.is_some() {
        derive_all(&m, &qs)?
    } else {
        values_only(&m, &qs)?
    };
    if let Some(path) = latex {
        let mq = m.asking(qs.clone());
        let key = torseur::latex::answer_key_document(&mq, torseur::latex::VectorStyle::Sum)
            .map_err(bad_input)?;
        let figures = render_figures(&key)?;
        write_figures(&path, &figures)?;
        write_atomic(&path, key.tex.as_bytes())?;
    }
    if let Some(path) = json {
        let j = output::derive_json(&m, &ds);
        let text = serde_json::to_string_pretty(&j).map_err(bad_input)? + "\n";
        write_atomic(&path, text.as_bytes())?;
    }
    let form = match form {
        Form::Presentation => output::TextForm::Presentation,
        Form::Canonical => output::TextForm::Canonical,
    };
    emit(&output::derive_text_in(&m, &ds, form))?;
    if stats {
        let mut total = 0;
        for d in &ds {
            total += d.value.nterms();
            eprintln!("terms {:>9}  {}", d.value.nterms(), d.quantity);
        }
        eprintln!(
            "terms {total:>9}  total; {:.3} s",
            start.elapsed().as_secs_f64()
        );
    }
    Ok(())
}

/// `torseur eval`: numbers at the values of a JSON file.
fn run_eval(a: EvalArgs, emit: &mut Emit) -> Result<(), Failure> {
    let EvalArgs {
        spec,
        at,
        quantities: qs,
    } = a;
    let m = load(&spec)?;
    let text = std::fs::read_to_string(&at)
        .with_context(|| format!("cannot read {}", at.display()))
        .map_err(bad_input)?;
    let mut values = output::Values::parse(&text).map_err(bad_input)?;
    let qs = quantities(&m, &qs)?;
    let ds = values_only(&m, &qs)?;
    // An action holds its links' unknowns: those without a value are solved for.
    let solved = ds
        .iter()
        .map(|d| output::solve_unknowns(&m, &d.value, &mut values))
        .collect::<Result<Vec<_>, _>>()
        .map_err(bad_input)?;
    // Only the parameters and coordinates the results hold are demanded.
    let exprs: Vec<&torseur::expr::Expr> = solved.iter().flat_map(|v| v.exprs()).collect();
    let point = output::numeric_point_for(&m, &values, &exprs).map_err(bad_input)?;
    let items: Vec<serde_json::Value> = ds
        .iter()
        .zip(&solved)
        .map(|(d, v)| output::eval_value(&m, &d.quantity.to_string(), v, &point))
        .collect();
    let j = serde_json::json!({ "quantities": items });
    emit(&(serde_json::to_string_pretty(&j).map_err(bad_input)? + "\n"))
}

/// `torseur answer-key`: the corrigé as LaTeX, with its figures, a PDF and a manifest.
fn run_answer_key(a: AnswerKeyArgs, emit: &mut Emit) -> Result<(), Failure> {
    let AnswerKeyArgs {
        spec,
        output,
        pdf,
        vectors,
        manifest,
    } = a;
    let m = load(&spec)?;
    let style = match vectors {
        Vectors::Sum => torseur::latex::VectorStyle::Sum,
        Vectors::Column => torseur::latex::VectorStyle::Column,
    };
    let key = torseur::latex::answer_key_document(&m, style).map_err(bad_input)?;
    let figures = render_figures(&key)?;
    let manifest_bytes =
        serde_json::to_string_pretty(&output::manifest_json(&m, &key)).map_err(bad_input)? + "\n";
    if let Some(path) = &manifest {
        write_atomic(path, manifest_bytes.as_bytes())?;
    }
    let tex = key.tex;
    match output {
        None => {
            if !figures.is_empty() {
                eprintln!(
                    "torseur: the key includes {} figure(s): give -o to write them",
                    figures.len()
                );
            }
            emit(&tex)
        }
        Some(path) => {
            let pdf_bytes = if pdf {
                Some(compile_pdf(&tex, &figures)?)
            } else {
                None
            };
            write_figures(&path, &figures)?;
            write_atomic(&path, tex.as_bytes())?;
            if let Some(bytes) = pdf_bytes {
                write_atomic(&path.with_extension("pdf"), &bytes)?;
            }
            Ok(())
        }
    }
}

/// `torseur check`: the exact results against the float backend, and their dimensions.
fn run_check(a: CheckArgs, emit: &mut Emit) -> Result<(), Failure> {
    let CheckArgs {
        spec,
        samples,
        seed,
        json,
    } = a;
    let m = load(&spec)?;
    let r = torseur::check::check(&m, samples.clamp(1, 100_000), seed).map_err(bad_input)?;
    if json {
        let rows: Vec<serde_json::Value> = r
            .rows
            .iter()
            .map(|x| {
                serde_json::json!({"id": x.quantity, "hypothesis": x.hypothesis,
                        "worst_relative_error": x.worst, "sample": x.sample,
                        "ok": x.worst <= torseur::check::TOLERANCE})
            })
            .collect();
        let dims: Vec<serde_json::Value> = r
            .dimensions
            .iter()
            .map(|x| {
                serde_json::json!({"id": x.quantity, "hypothesis": x.hypothesis,
                        "ok": x.error.is_none(),
                        "error": x.error.as_ref().map(|e| e.to_string())})
            })
            .collect();
        let j = serde_json::json!({"samples": r.samples, "seed": r.seed,
                "tolerance": torseur::check::TOLERANCE, "passed": r.passed(), "quantities": rows,
                "dimensions": dims});
        emit(&(serde_json::to_string_pretty(&j).map_err(bad_input)? + "\n"))?;
    } else {
        emit(&format!("{r}\n"))?;
    }
    if r.passed() {
        Ok(())
    } else {
        let mut problems = Vec::new();
        let names: Vec<String> = r.failures().iter().map(|x| x.quantity.clone()).collect();
        if !names.is_empty() {
            problems.push(format!(
                "symbolic and float results disagree: {}",
                names.join(", ")
            ));
        }
        let wrong = r.dimension_failures();
        if let Some(x) = wrong.first()
            && let Some(e) = &x.error
        {
            let under = x
                .hypothesis
                .as_ref()
                .map(|h| format!(" under {h}"))
                .unwrap_or_default();
            let more = match wrong.len() {
                1 => String::new(),
                n => format!(" ({} more in the report)", n - 1),
            };
            problems.push(format!("wrong dimension{under}: {e}{more}"));
        }
        Err(Failure {
            code: 1,
            error: anyhow!("{}", problems.join("\n")),
        })
    }
}

/// `torseur simulate`: a scenario integrated in time, as CSV and plots.
fn run_simulate(a: SimulateArgs, emit: &mut Emit) -> Result<(), Failure> {
    let SimulateArgs {
        spec,
        scenario,
        output,
        plot,
        png,
    } = a;
    let m = load(&spec)?;
    let run = torseur::simulate::simulate(&m, &scenario).map_err(bad_input)?;
    let table = run.table().map_err(bad_input)?;
    let ids: Vec<&str> = run
        .columns
        .iter()
        .map(|c| c.id.as_str())
        .filter(|id| !id.starts_with("int("))
        .collect();
    let fig = torseur::simulate::figure(
        &format!("{} ({})", m.title(), run.label),
        &[(run.label.as_str(), &run)],
        &ids,
        true,
    );
    // Everything is computed before anything is written.
    let svg = match &plot {
        Some(_) => Some(fig.to_svg().map_err(bad_input)?),
        None => None,
    };
    let png_bytes = match &png {
        Some(_) => Some(fig.to_png(2).map_err(bad_input)?),
        None => None,
    };
    let csv = table.to_csv();
    if let (Some(p), Some(s)) = (&plot, &svg) {
        write_atomic(p, s.as_bytes())?;
    }
    if let (Some(p), Some(b)) = (&png, &png_bytes) {
        write_atomic(p, b)?;
    }
    eprintln!(
        "simulate: {} points, {} evaluations, {} steps{}",
        run.times.len(),
        run.stats.evaluations,
        run.stats.accepted_steps,
        match run.drift {
            Some(d) => format!(", loop closure drift at most {d:.1e} (SI)"),
            None => String::new(),
        }
    );
    match output {
        None => emit(&csv),
        Some(p) => write_atomic(&p, csv.as_bytes()),
    }
}

/// `torseur verify`: is a hand-written value or equation the engine's?
fn run_verify(a: VerifyArgs, emit: &mut Emit) -> Result<(), Failure> {
    let VerifyArgs {
        spec,
        quantity,
        expr,
        hypothesis,
    } = a;
    let m = load(&spec)?;
    // `@FILE`: a text too long for a command line (a chain's equation of motion).
    let expr = match expr.strip_prefix('@') {
        Some(file) => std::fs::read_to_string(file)
            .map_err(|e| bad_input(anyhow::anyhow!("--expr @{file}: cannot read the file: {e}")))?,
        None => expr,
    };
    let v = match &quantity {
        Some(q) => torseur::verify::verify(&m, q, &expr, hypothesis.as_deref()),
        None => torseur::verify::verify_equation(&m, &expr, hypothesis.as_deref()),
    }
    .map_err(bad_input)?;
    emit(&format!("{v}\n"))?;
    for (k, d) in v
        .difference
        .iter()
        .enumerate()
        .filter(|(_, d)| !d.is_zero())
    {
        emit(&format!(
            "  {} (LaTeX): {}\n",
            v.difference_label(k),
            torseur::latex::expr(d)
        ))?;
    }
    if v.is_equivalent() {
        Ok(())
    } else {
        Err(Failure {
            code: 1,
            error: match &v.equation {
                None => anyhow!("{} differs from the derived result", v.quantity),
                Some(eq) => anyhow!("`{eq}` is not equivalent to the engine's relation"),
            },
        })
    }
}
