//! The `torseur` command line: parse arguments, call the library, print.
//!
//! Exit codes: 0 success, 1 a mathematical mismatch, 2 bad input or usage.

use anyhow::{Context, Result, anyhow};
use clap::Parser;
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::atomic::Ordering;
use torseur::output::Target;

// The chains' long polynomials are allocated and freed by the million; glibc's allocator
// spent a third of a chain 10 run in page faults and `free`.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;
use torseur::derivation::{Derivation, derive};
use torseur::mechanism::Mechanism;
use torseur::output;
use torseur::quantity::Quantity;

mod args;
mod process;
use args::{
    AnswerKeyArgs, CheckArgs, Cli, Command, DeriveArgs, EvalArgs, Form, SimulateArgs, Vectors,
    VerifyArgs,
};
use process::{
    CHILD, STARTED, STOPPING, WRITTEN, catch_abort, redirect_stdout, watch_signals, watchdog,
};

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
    catch_abort();
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

/// The inputs of a run, read (bounded) before it queues for symbolica, and its outputs,
/// resolved and checked apart from each other and from the inputs before any work.
struct Io {
    /// The spec's text.
    spec: String,
    /// What was read, for the « same file » check: (what it is, path).
    inputs: Vec<(String, PathBuf)>,
    /// Resolved outputs: (what it is, target).
    outputs: Vec<(String, Target)>,
}

impl Io {
    /// Reads the spec (`-`: standard input).
    fn read(spec: &Path) -> Result<Io, Failure> {
        let text = torseur::spec::read(spec).map_err(bad_input)?;
        Ok(Io {
            spec: text,
            inputs: vec![("the spec".to_string(), spec.to_path_buf())],
            outputs: Vec::new(),
        })
    }

    /// Reads another input, bounded; `-` is standard input, which only one input may use.
    fn also_read(&mut self, what: &str, path: &Path, limit: u64) -> Result<String, Failure> {
        if path.as_os_str() == "-" && self.inputs.iter().any(|(_, p)| p.as_os_str() == "-") {
            return Err(bad_input(anyhow!(
                "{what}: standard input already gives another input; give a file"
            )));
        }
        let text = torseur::input::read_text(path, limit)
            .map_err(|e| bad_input(anyhow!("{what}: {e}")))?;
        self.inputs.push((what.to_string(), path.to_path_buf()));
        Ok(text)
    }

    /// Resolves an output (`what` names it in messages: `-o key.tex`) and checks it apart
    /// from every input and earlier output. Returns its index.
    fn output(&mut self, what: String, path: &Path) -> Result<usize, Failure> {
        let t = output::target(path).map_err(|e| bad_input(anyhow!("{what}: {e}")))?;
        self.outputs.push((what, t));
        self.distinct()?;
        Ok(self.outputs.len() - 1)
    }

    fn distinct(&self) -> Result<(), Failure> {
        let outs: Vec<(String, &Target)> =
            self.outputs.iter().map(|(w, t)| (w.clone(), t)).collect();
        let ins: Vec<(String, &Path)> = self
            .inputs
            .iter()
            .map(|(w, p)| (w.clone(), p.as_path()))
            .collect();
        output::distinct(&outs, &ins).map_err(bad_input)
    }

    fn target(&self, k: usize) -> &Target {
        &self.outputs[k].1
    }
}

/// Parses and validates the spec's text (the first symbolica work of a run).
fn load(io: &Io) -> Result<Mechanism, Failure> {
    let m = torseur::spec::from_str(&io.spec);
    STARTED.store(true, Ordering::SeqCst);
    m.map_err(bad_input)
}

/// Writes the outputs, all of them once everything has succeeded.
fn write(items: &[(&Target, &[u8])], out: &mut File) -> Result<(), Failure> {
    let mut written = WRITTEN.lock().unwrap_or_else(|p| p.into_inner());
    output::write_outputs(items, out).map_err(bad_input)?;
    *written = true;
    Ok(())
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

/// The answer key's figures as PNG, all rendered before anything is written.
fn render_figures(key: &torseur::latex::AnswerKey) -> Result<Vec<(String, Vec<u8>)>, Failure> {
    key.figures
        .iter()
        .map(|(name, fig)| Ok((name.clone(), fig.to_png(2).map_err(bad_input)?)))
        .collect()
}

/// The prefix of an answer key's figure files, from the .tex file's name (`key.tex` →
/// `key-`): letters, digits, `-` and `_` only, so that `\includegraphics` reads it as is.
fn figure_prefix(tex: &Target) -> String {
    let Some(stem) = tex.given.file_stem() else {
        return String::new();
    };
    let stem: String = stem
        .to_string_lossy()
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '-'
            }
        })
        .collect();
    format!("{stem}-")
}

/// Output files, each the index of its resolved target in [`Io`] and its bytes.
type Files = Vec<(usize, Vec<u8>)>;

/// Writes every file of a command to its output, all or none ([`write`]).
fn write_files(io: &Io, files: &Files, out: &mut File) -> Result<(), Failure> {
    let items: Vec<(&Target, &[u8])> = files
        .iter()
        .map(|(k, b)| (io.target(*k), b.as_slice()))
        .collect();
    write(&items, out)
}

/// The answer key of `m` (or, with `fragment`, the bodies of those questions: all when it is
/// empty), its figures named after `tex` when it is a file (they are written beside it, where
/// `\includegraphics` finds them), else not written (said on stderr).
fn key_with_figures(
    m: &Mechanism,
    style: torseur::latex::VectorStyle,
    io: &mut Io,
    tex: usize,
    fragment: Option<&[usize]>,
) -> Result<(torseur::latex::AnswerKey, Files), Failure> {
    let dir = io
        .target(tex)
        .file()
        .and_then(Path::parent)
        .map(Path::to_path_buf);
    let prefix = match dir {
        Some(_) => figure_prefix(io.target(tex)),
        None => String::new(),
    };
    // The simulations the questions show are run here: the key only draws their runs.
    let runs = torseur::simulate::question_runs(m);
    let key = match fragment {
        Some(chosen) => torseur::latex::answer_key_fragment(m, style, &prefix, chosen, &runs),
        None => torseur::latex::answer_key_named(m, style, &prefix, &runs),
    }
    .map_err(bad_input)?;
    let pngs = render_figures(&key)?;
    let mut figures = Vec::new();
    match dir {
        Some(dir) => {
            for (name, bytes) in pngs {
                let k = io.output(format!("the figure {name}"), &dir.join(&name))?;
                figures.push((k, bytes));
            }
        }
        None if !pngs.is_empty() => eprintln!(
            "torseur: the key includes {} figure(s): give -o FILE.tex to write them",
            pngs.len()
        ),
        None => {}
    }
    Ok((key, figures))
}

/// Compiles LaTeX with pdflatex in a temporary directory (no shell escape) and returns the
/// PDF, byte-reproducible (fixed dates and trailer identifier, `SOURCE_DATE_EPOCH`). A key
/// pdflatex rejects is bad input (exit 2), named by the spec's text at fault when there is one.
fn compile_pdf(m: &Mechanism, tex: &str, figures: &[(String, &[u8])]) -> Result<Vec<u8>, Failure> {
    let dir = tempfile::tempdir().map_err(bad_input)?;
    output::register_pending(dir.path());
    let result = run_pdflatex(m, dir.path(), tex, figures);
    output::forget_pending(dir.path());
    result
}

fn run_pdflatex(
    m: &Mechanism,
    dir: &Path,
    tex: &str,
    figures: &[(String, &[u8])],
) -> Result<Vec<u8>, Failure> {
    std::fs::write(dir.join("key.tex"), tex).map_err(bad_input)?;
    for (name, bytes) in figures {
        std::fs::write(dir.join(name), bytes).map_err(bad_input)?;
    }
    let epoch = std::env::var("SOURCE_DATE_EPOCH")
        .ok()
        .filter(|v| !v.is_empty() && v.bytes().all(|b| b.is_ascii_digit()))
        .unwrap_or_else(|| "0".to_string());
    let child = std::process::Command::new("pdflatex")
        .args([
            "-no-shell-escape",
            "-interaction=nonstopmode",
            "-halt-on-error",
            "key.tex",
        ])
        .current_dir(dir)
        .env("SOURCE_DATE_EPOCH", epoch)
        .env("FORCE_SOURCE_DATE", "1")
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn();
    let child = match child {
        Ok(c) => c,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Err(bad_input(anyhow!(
                "pdflatex is not installed (run scripts/setup, or install Debian's texlive)"
            )));
        }
        Err(e) => return Err(bad_input(anyhow!("cannot run pdflatex: {e}"))),
    };
    CHILD.store(child.id() as i32, Ordering::SeqCst);
    let o = child.wait_with_output();
    CHILD.store(0, Ordering::SeqCst);
    while STOPPING.load(Ordering::SeqCst) {
        // The process is being stopped (and pdflatex was killed for it): `stop` exits.
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    let o = o.map_err(|e| bad_input(anyhow!("cannot run pdflatex: {e}")))?;
    if !o.status.success() {
        let log = String::from_utf8_lossy(&o.stdout);
        let tail: Vec<&str> = log
            .lines()
            .filter(|l| l.starts_with('!') || l.starts_with("l."))
            .collect();
        let line = tail.iter().find_map(|l| {
            l.strip_prefix("l.")
                .and_then(|r| r.split(|c: char| !c.is_ascii_digit()).next())
                .and_then(|n| n.parse::<usize>().ok())
        });
        let place = line
            .and_then(|l| torseur::latex::text_at_fault(m, tex, l))
            .map(|p| format!("at {p}: "))
            .unwrap_or_default();
        return Err(bad_input(anyhow!(
            "{place}pdflatex rejected the answer key: {}",
            tail.join(" | ")
        )));
    }
    // Report lines that overflow the page by more than 20pt (the key must fit the page).
    let log = std::fs::read_to_string(dir.join("key.log")).unwrap_or_default();
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
    std::fs::read(dir.join("key.pdf")).map_err(bad_input)
}

/// A command, its inputs read and its outputs resolved, ready to run once the lock is held.
type Job = Box<dyn FnOnce(&mut File) -> Result<(), Failure>>;

fn run(cli: Cli, mut out: File) -> Result<(), Failure> {
    watch_signals();
    torseur::expr::budget::set_max_terms(usize::try_from(cli.max_terms).unwrap_or(usize::MAX));
    if let Some(limit) = cli.timeout {
        watchdog(limit)?;
    }
    // Every input is read and every output resolved before the run queues for symbolica: a
    // FIFO without a writer, or a bad output path, holds or fails this run only.
    let job: Job = match cli.command {
        Command::Derive(a) => prepare_derive(a)?,
        Command::Eval(a) => prepare_eval(a)?,
        Command::AnswerKey(a) => prepare_answer_key(a)?,
        Command::Check(a) => prepare_check(a)?,
        Command::Simulate(a) => prepare_simulate(a)?,
        Command::Verify(a) => prepare_verify(a)?,
    };
    let _lock = torseur::lock::ProcessLock::acquire(|| {
        eprintln!(
            "torseur: waiting for another torseur run to finish (symbolica allows one at a time)"
        )
    })
    .context("cannot take the torseur lock")
    .map_err(bad_input)?;
    job(&mut out)
}

/// The standard output of a command, as an output (so that `--json -` and the text do not
/// both claim it).
fn stdout_target(io: &mut Io, what: &str) -> Result<usize, Failure> {
    io.output(what.to_string(), Path::new("-"))
}

/// `torseur derive`: closed forms, as text, JSON and LaTeX.
fn prepare_derive(a: DeriveArgs) -> Result<Job, Failure> {
    let DeriveArgs {
        spec,
        quantities: qs,
        json,
        latex,
        stats,
        form,
    } = a;
    let start = std::time::Instant::now();
    let mut io = Io::read(&spec)?;
    let text_out = stdout_target(&mut io, "the results on standard output")?;
    let latex_out = match &latex {
        Some(p) => Some(io.output(format!("--latex {}", p.display()), p)?),
        None => None,
    };
    let json_out = match &json {
        Some(p) => Some(io.output(format!("--json {}", p.display()), p)?),
        None => None,
    };
    Ok(Box::new(move |out| {
        let m = load(&io)?;
        let qs = quantities(&m, &qs)?;
        if let Form::Structured = form {
            return derive_structured(
                &m, &qs, &io, text_out, latex_out, json_out, out, stats, start,
            );
        }
        let ds = if json_out.is_some() {
            derive_all(&m, &qs)?
        } else {
            values_only(&m, &qs)?
        };
        let mut files: Files = Vec::new();
        if let Some(k) = latex_out {
            let mq = m.asking(qs.clone());
            let (key, figures) =
                key_with_figures(&mq, torseur::latex::VectorStyle::Sum, &mut io, k, None)?;
            files.extend(figures);
            files.push((k, key.tex.into_bytes()));
        }
        if let Some(k) = json_out {
            let j = output::derive_json(&m, &ds);
            let text = serde_json::to_string_pretty(&j).map_err(bad_input)? + "\n";
            files.push((k, text.into_bytes()));
        }
        let form = match form {
            Form::Canonical => output::TextForm::Canonical,
            _ => output::TextForm::Presentation,
        };
        files.push((text_out, output::derive_text_in(&m, &ds, form).into_bytes()));
        write_files(&io, &files, out)?;
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
            let p = torseur::expr::budget::peaks();
            eprintln!(
                "budget: at most {} terms held at once, {} in one expression, {} formed by one product (--max-terms {})",
                p.held,
                p.expression,
                p.product,
                torseur::expr::budget::max_terms()
            );
        }
        Ok(())
    }))
}

/// `derive --form structured`: the named form of the quantities that have one (each nested
/// set's dynamic torsor once, the equations of motion over the names), the engine's values of
/// the others; `--latex` is refused (the answer key writes each result in full).
#[allow(clippy::too_many_arguments)]
fn derive_structured(
    m: &Mechanism,
    qs: &[Quantity],
    io: &Io,
    text_out: usize,
    latex_out: Option<usize>,
    json_out: Option<usize>,
    out: &mut File,
    stats: bool,
    start: std::time::Instant,
) -> Result<(), Failure> {
    if latex_out.is_some() {
        return Err(bad_input(anyhow!(
            "--latex writes each result in full: it does not go with --form structured"
        )));
    }
    let s = torseur::pfd::structured::Structured::of(m, qs).map_err(|e| bad_input(anyhow!(e)))?;
    let rest: Vec<Quantity> = qs
        .iter()
        .filter(|q| s.value(q).is_none())
        .cloned()
        .collect();
    let others = values_only(m, &rest)?;
    let mut files: Files = Vec::new();
    if let Some(k) = json_out {
        let j = output::structured_json(m, &s, qs, &others);
        let text = serde_json::to_string_pretty(&j).map_err(bad_input)? + "\n";
        files.push((k, text.into_bytes()));
    }
    files.push((
        text_out,
        output::structured_text(m, &s, qs, &others).into_bytes(),
    ));
    write_files(io, &files, out)?;
    if stats {
        let named: usize = s
            .program
            .definitions()
            .iter()
            .map(|d| d.value.nterms())
            .sum();
        let values: usize = s.values.iter().map(|(_, v)| v.nterms()).sum();
        eprintln!(
            "structured: {} names of {named} terms, {values} terms in the values; {:.3} s",
            s.program.definitions().len(),
            start.elapsed().as_secs_f64()
        );
    }
    Ok(())
}

/// `torseur eval`: numbers at the values of a JSON file.
fn prepare_eval(a: EvalArgs) -> Result<Job, Failure> {
    let EvalArgs {
        spec,
        at,
        quantities: qs,
    } = a;
    let mut io = Io::read(&spec)?;
    let text = io.also_read("--at", &at, torseur::input::MAX_VALUES_BYTES)?;
    let text_out = stdout_target(&mut io, "the numbers on standard output")?;
    Ok(Box::new(move |out| {
        let m = load(&io)?;
        let mut values = output::Values::parse(&text).map_err(bad_input)?;
        let qs = quantities(&m, &qs)?;
        let ds = values_only(&m, &qs)?;
        let j = output::eval_json(&m, &mut values, &ds).map_err(bad_input)?;
        let text = serde_json::to_string_pretty(&j).map_err(bad_input)? + "\n";
        write(&[(io.target(text_out), text.as_bytes())], out)
    }))
}

/// `torseur answer-key`: the corrigé as LaTeX, with its figures, a PDF and a manifest.
fn prepare_answer_key(a: AnswerKeyArgs) -> Result<Job, Failure> {
    let AnswerKeyArgs {
        spec,
        output,
        pdf,
        vectors,
        manifest,
        fragment,
        questions,
    } = a;
    let mut io = Io::read(&spec)?;
    let given = output.unwrap_or_else(|| PathBuf::from("-"));
    let tex_out = io.output(format!("-o {}", given.display()), &given)?;
    let pdf_out = if pdf {
        if fragment {
            return Err(bad_input(anyhow!(
                "--pdf compiles a whole document: a --fragment has none (paste it into yours)"
            )));
        }
        if io.target(tex_out).file().is_none() {
            return Err(bad_input(anyhow!(
                "--pdf writes FILE.pdf beside -o FILE.tex: give -o the name of a file"
            )));
        }
        let p = given.with_extension("pdf");
        Some(io.output(format!("the PDF {}", p.display()), &p)?)
    } else {
        None
    };
    let manifest_out = match &manifest {
        Some(p) => Some(io.output(format!("--manifest {}", p.display()), p)?),
        None => None,
    };
    Ok(Box::new(move |out| {
        let m = load(&io)?;
        let style = match vectors {
            Vectors::Sum => torseur::latex::VectorStyle::Sum,
            Vectors::Column => torseur::latex::VectorStyle::Column,
        };
        let chosen = fragment.then_some(questions.as_slice());
        let (key, figures) = key_with_figures(&m, style, &mut io, tex_out, chosen)?;
        let mut files: Files = Vec::new();
        if let Some(k) = manifest_out {
            let text = serde_json::to_string_pretty(&output::manifest_json(&m, &key))
                .map_err(bad_input)?
                + "\n";
            files.push((k, text.into_bytes()));
        }
        if let Some(k) = pdf_out {
            let named: Vec<(String, &[u8])> = key
                .figures
                .iter()
                .map(|(n, _)| n.clone())
                .zip(figures.iter().map(|(_, b)| b.as_slice()))
                .collect();
            files.push((k, compile_pdf(&m, &key.tex, &named)?));
        }
        files.extend(figures);
        files.push((tex_out, key.tex.into_bytes()));
        write_files(&io, &files, out)
    }))
}

/// `torseur check`: the exact results against the float backend, and their dimensions.
fn prepare_check(a: CheckArgs) -> Result<Job, Failure> {
    let CheckArgs {
        spec,
        samples,
        seed,
        json,
    } = a;
    let io = Io::read(&spec)?;
    Ok(Box::new(move |out| {
        let m = load(&io)?;
        let r = torseur::check::check(&m, samples.clamp(1, 100_000), seed).map_err(bad_input)?;
        let text = if json {
            serde_json::to_string_pretty(&r.to_json()).map_err(bad_input)? + "\n"
        } else {
            format!("{r}\n")
        };
        out.write_all(text.as_bytes())
            .and_then(|_| out.flush())
            .map_err(|e| bad_input(anyhow!("cannot write to stdout: {e}")))?;
        if r.passed() {
            Ok(())
        } else {
            Err(check_failure(&r))
        }
    }))
}

/// The exit-1 message of a failed check.
fn check_failure(r: &torseur::check::CheckReport) -> Failure {
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
    Failure {
        code: 1,
        error: anyhow!("{}", problems.join("\n")),
    }
}

/// `torseur simulate`: a scenario integrated in time, as CSV and plots.
fn prepare_simulate(a: SimulateArgs) -> Result<Job, Failure> {
    let SimulateArgs {
        spec,
        scenario,
        output,
        plot,
        png,
    } = a;
    let mut io = Io::read(&spec)?;
    let given = output.unwrap_or_else(|| PathBuf::from("-"));
    let csv_out = io.output(format!("-o {}", given.display()), &given)?;
    let svg_out = match &plot {
        Some(p) => Some(io.output(format!("--plot {}", p.display()), p)?),
        None => None,
    };
    let png_out = match &png {
        Some(p) => Some(io.output(format!("--png {}", p.display()), p)?),
        None => None,
    };
    Ok(Box::new(move |out| {
        let m = load(&io)?;
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
        let mut files: Files = Vec::new();
        if let Some(k) = svg_out {
            files.push((k, fig.to_svg().map_err(bad_input)?.into_bytes()));
        }
        if let Some(k) = png_out {
            files.push((k, fig.to_png(2).map_err(bad_input)?));
        }
        files.push((csv_out, table.to_csv().into_bytes()));
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
        write_files(&io, &files, out)
    }))
}

/// `torseur verify`: is a hand-written value or equation the engine's?
fn prepare_verify(a: VerifyArgs) -> Result<Job, Failure> {
    let VerifyArgs {
        spec,
        quantity,
        expr,
        hypothesis,
    } = a;
    let mut io = Io::read(&spec)?;
    // `@FILE`: a text too long for a command line (a chain's equation of motion).
    let expr = match expr.strip_prefix('@') {
        Some(file) => io.also_read(
            &format!("--expr @{file}"),
            Path::new(file),
            torseur::input::MAX_EXPR_BYTES,
        )?,
        None => expr,
    };
    Ok(Box::new(move |out| {
        let m = load(&io)?;
        let v = match &quantity {
            Some(q) => torseur::verify::verify(&m, q, &expr, hypothesis.as_deref()),
            None => torseur::verify::verify_equation(&m, &expr, hypothesis.as_deref()),
        }
        .map_err(bad_input)?;
        let mut text = format!("{v}\n");
        for (k, d) in v
            .difference
            .iter()
            .enumerate()
            .filter(|(_, d)| !d.is_zero())
        {
            text.push_str(&format!(
                "  {} (LaTeX): {}\n",
                v.difference_label(k),
                torseur::latex::expr(d)
            ));
        }
        out.write_all(text.as_bytes())
            .and_then(|_| out.flush())
            .map_err(|e| bad_input(anyhow!("cannot write to stdout: {e}")))?;
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
    }))
}
