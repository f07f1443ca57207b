//! The `torseur` binary, run as a user would. This test binary never uses symbolica itself:
//! a process that has used it cannot start another symbolica process.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

mod budget;
mod corpus;
mod eval;
mod hostile;
mod messages;
mod paste;
mod readme;
mod verify;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_torseur"))
}

fn spec() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("derivations/regulateur_centrifuge.json")
}

fn run(args: &[&str]) -> Output {
    bin().args(args).output().expect("runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn tmp() -> tempfile::TempDir {
    tempfile::tempdir().unwrap()
}

/// The names in a directory, sorted: what a run left there.
fn files_in(d: &std::path::Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(d)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[test]
fn derive_prints_only_results_on_stdout() {
    let o = run(&["derive", spec().to_str().unwrap(), "-q", "delta(O2,2/0).x2"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.starts_with("delta(O2,2/0).x2 = "), "{out}");
    assert!(out.contains("(A2 + m2*L2^2)*ddot(theta2)"), "{out}");
    assert!(
        !out.contains("Symbolica"),
        "the licence notice must not reach stdout"
    );
    assert!(
        stderr(&o).contains("Symbolica"),
        "the licence notice stays visible on stderr"
    );
}

#[test]
fn derive_writes_json_with_canonical_forms_and_steps() {
    let d = tmp();
    let j = d.path().join("out.json");
    let o = run(&[
        "derive",
        spec().to_str().unwrap(),
        "--json",
        j.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&j).unwrap()).unwrap();
    let qs = v["quantities"].as_array().unwrap();
    assert_eq!(qs.len(), 12);
    let d2 = qs.iter().find(|q| q["id"] == "{D(2/0)}_O2 in B2").unwrap();
    assert_eq!(d2["value"]["kind"], "torsor");
    assert_eq!(d2["value"]["point"], "O2");
    assert_eq!(d2["value"]["basis"], "B2");
    assert!(d2["steps"].as_array().unwrap().len() >= 5);
    assert!(d2["hypotheses"]["H2"].is_object());
}

#[test]
fn bad_input_exits_2_with_a_message_and_writes_nothing() {
    let d = tmp();
    let bad = d.path().join("bad.json");
    std::fs::write(&bad, "{ \"title\": 3 }").unwrap();
    let out = d.path().join("out.json");
    let o = run(&[
        "derive",
        bad.to_str().unwrap(),
        "--json",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("title"), "{}", stderr(&o));
    assert!(stdout(&o).is_empty());
    assert!(!out.exists());
    // Unknown quantity notation, unknown file, missing value, usage error.
    let o = run(&["derive", spec().to_str().unwrap(), "-q", "delta(O2;2/0)"]);
    assert_eq!(o.status.code(), Some(2));
    let o = run(&["derive", "/nonexistent/spec.json"]);
    assert_eq!(o.status.code(), Some(2));
    let vals = d.path().join("v.json");
    std::fs::write(&vals, r#"{"parameters":{"m2":1},"coordinates":{}}"#).unwrap();
    let o = run(&[
        "eval",
        spec().to_str().unwrap(),
        "--at",
        vals.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("missing"), "{}", stderr(&o));
    let o = run(&["frobnicate"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn a_failed_run_leaves_an_existing_output_untouched() {
    let d = tmp();
    let out = d.path().join("keep.json");
    std::fs::write(&out, "precious").unwrap();
    let o = run(&[
        "derive",
        spec().to_str().unwrap(),
        "-q",
        "delta(O9,2/0)",
        "--json",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "precious");
}

#[test]
fn concurrent_runs_wait_for_each_other_and_all_succeed() {
    let children: Vec<_> = (0..4)
        .map(|_| {
            bin()
                .args(["derive", spec().to_str().unwrap()])
                .stdout(std::process::Stdio::piped())
                .stderr(std::process::Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    let outs: Vec<Output> = children
        .into_iter()
        .map(|c| c.wait_with_output().unwrap())
        .collect();
    for o in &outs {
        assert!(o.status.success(), "exit {:?}: {}", o.status, stderr(o));
    }
    // Deterministic: byte-identical output across processes.
    for o in &outs[1..] {
        assert_eq!(o.stdout, outs[0].stdout);
    }
}

#[test]
fn answer_key_compiles_to_pdf_without_overfull_lines() {
    // Needs pdflatex: scripts/setup (the README's first command, and CI) installs it.
    let d = tmp();
    let tex = d.path().join("regulateur.tex");
    let o = run(&[
        "answer-key",
        spec().to_str().unwrap(),
        "-o",
        tex.to_str().unwrap(),
        "--pdf",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let pdf = std::fs::read(d.path().join("regulateur.pdf")).unwrap();
    assert!(pdf.starts_with(b"%PDF"));
    assert!(!stderr(&o).contains("Overfull"), "{}", stderr(&o));
    assert!(stdout(&o).is_empty());
}

#[test]
fn answer_key_goes_to_stdout_without_output_file() {
    let o = run(&["answer-key", spec().to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.starts_with("\\documentclass"));
    assert!(out.trim_end().ends_with("\\end{document}"));
}

#[test]
fn check_reports_agreement_with_the_float_backend() {
    let o = run(&[
        "check",
        spec().to_str().unwrap(),
        "--samples",
        "5",
        "--seed",
        "9",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["passed"], true);
    assert_eq!(v["seed"], 9);
    // 12 quantities (C_m, eom(theta2) and Ec(E/0) included), general and under H1 and H2.
    assert_eq!(v["quantities"].as_array().unwrap().len(), 36);
    let dims = v["dimensions"].as_array().unwrap();
    assert_eq!(dims.len(), 36);
    assert!(dims.iter().all(|x| x["ok"] == true && x["error"].is_null()));
}

#[test]
fn vectors_can_be_written_as_columns_with_their_basis() {
    let d = tmp();
    let tex = d.path().join("col.tex");
    let o = run(&[
        "answer-key",
        spec().to_str().unwrap(),
        "--vectors",
        "column",
        "-o",
        tex.to_str().unwrap(),
        "--pdf",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let t = std::fs::read_to_string(&tex).unwrap();
    assert!(t.contains(
        "\\TVecLong{\\Omega(\\TMvt{2}{0})} &= \\begin{pmatrix} \\dot{\\theta}_{2} \\\\ \\dot{\\theta}_{1}\\,\\sin\\theta_{2} \\\\ \\dot{\\theta}_{1}\\,\\cos\\theta_{2} \\end{pmatrix}_{\\mathcal{B}_{2}}"
    ));
    // Long vectors stay sums over the basis vectors, so nothing overflows the page.
    assert!(t.contains("\\right]\\,\\dot{\\theta}_{1}^{2}\\,\\TVec{x}_{1} \\\\"));
    assert!(!stderr(&o).contains("Overfull"), "{}", stderr(&o));
    let o = run(&[
        "answer-key",
        spec().to_str().unwrap(),
        "--vectors",
        "diagonal",
    ]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn a_time_limit_stops_long_work_cleanly() {
    let d = tmp();
    let out = d.path().join("chain.json");
    let chain = Path::new(env!("CARGO_MANIFEST_DIR")).join("derivations/chain/chain_9.json");
    let o = run(&[
        "derive",
        chain.to_str().unwrap(),
        "--timeout",
        "0.3",
        "--json",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("time limit of 0.3 s"), "{}", stderr(&o));
    assert!(stdout(&o).is_empty());
    assert_eq!(
        std::fs::read_dir(d.path()).unwrap().count(),
        0,
        "nothing written"
    );
    let o = run(&["derive", spec().to_str().unwrap(), "--timeout", "-1"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn simulate_writes_csv_and_plots_and_refuses_unknown_scenarios() {
    let d = tmp();
    let (csv, svg, png) = (
        d.path().join("run.csv"),
        d.path().join("run.svg"),
        d.path().join("run.png"),
    );
    let o = run(&[
        "simulate",
        spec().to_str().unwrap(),
        "--scenario",
        "avec_frottement",
        "-o",
        csv.to_str().unwrap(),
        "--plot",
        svg.to_str().unwrap(),
        "--png",
        png.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&csv).unwrap();
    let header = text.lines().next().unwrap();
    assert_eq!(
        header,
        "t (s),theta1 (rad),dot(theta1) (rad/s),theta2 (rad),dot(theta2) (rad/s),C_m (N m)"
    );
    assert_eq!(text.lines().count(), 1 + 1001, "1 ms output over 1 s");
    assert!(std::fs::read_to_string(&svg).unwrap().starts_with("<svg"));
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));

    let bad = d.path().join("bad.csv");
    let o = run(&[
        "simulate",
        spec().to_str().unwrap(),
        "--scenario",
        "nope",
        "-o",
        bad.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("no scenario `nope`"), "{}", stderr(&o));
    assert!(!bad.exists());
}

#[test]
fn a_coordinate_named_like_a_basis_vector_or_a_closed_loop_exits_2_naming_the_path() {
    let d = tmp();
    // sympy's mass–spring–damper names its coordinate x0, the name of a basis vector.
    let clash = d.path().join("clash.json");
    std::fs::write(
        &clash,
        r#"{"title": "t", "parameters": [{"name": "m"}],
  "coordinates": [{"name": "x0", "kind": "length"}],
  "frames": [{"name": "1", "parent": "0", "origin": "P"}],
  "points": [{"name": "P", "from": "O0", "position": "x0*x0"}],
  "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "P"}]}"#,
    )
    .unwrap();
    let o = run(&["derive", clash.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("coordinates[0].name"), "{}", stderr(&o));
    assert!(stderr(&o).contains("basis vector"), "{}", stderr(&o));
    assert!(stdout(&o).is_empty());
    // A link that closes a loop (0–1–2 then 2–0).
    let text = std::fs::read_to_string(spec()).unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["links"].as_array_mut().unwrap().push(serde_json::json!(
        {"name": "02", "kind": "ball", "between": ["0", "2"], "point": "O2"}));
    let loop_spec = d.path().join("loop.json");
    std::fs::write(&loop_spec, v.to_string()).unwrap();
    let o = run(&["check", loop_spec.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("links[2].between"), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("kinematic loops are not supported yet"),
        "{}",
        stderr(&o)
    );
}

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/specs")
        .join(name)
}

fn pdflatex(tex: &Path) -> Output {
    Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-halt-on-error"])
        .arg(tex.file_name().unwrap())
        .current_dir(tex.parent().unwrap())
        .output()
        .expect("pdflatex runs (scripts/setup installs it)")
}

/// Regression: a coordinate named `q1` or `q` printed `\sinq_{1}` and `\sinq`, an undefined
/// control sequence. Latin, Greek, multi-letter and subscripted names in every LaTeX output.
#[test]
fn latin_angle_names_give_latex_that_compiles() {
    let d = tmp();
    let s = fixture("noms_latins_grecs.json");
    let tex = d.path().join("derive.tex");
    let o = run(&[
        "derive",
        s.to_str().unwrap(),
        "--latex",
        tex.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&tex).unwrap();
    assert!(
        text.contains("\\sin q_{1}") && text.contains("\\cos q"),
        "{text}"
    );
    let c = pdflatex(&tex);
    assert!(c.status.success(), "{}", stdout(&c));
    let key = d.path().join("key.tex");
    let o = run(&[
        "answer-key",
        s.to_str().unwrap(),
        "-o",
        key.to_str().unwrap(),
        "--pdf",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(d.path().join("key.pdf").exists());
    // The chain family (Latin q1, q2, l1, multi-letter parameters) compiles too.
    let chain = Path::new(env!("CARGO_MANIFEST_DIR")).join("derivations/chain/chain_2.json");
    let ck = d.path().join("chain.tex");
    let o = run(&[
        "answer-key",
        chain.to_str().unwrap(),
        "-o",
        ck.to_str().unwrap(),
        "--pdf",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(d.path().join("chain.pdf").exists());
    // verify's LaTeX difference uses the same names.
    let o = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "delta(B,3/0).z0",
        "-e",
        "m_b*mu^2*ddot(q1)",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let out = stdout(&o);
    for bad in ["\\sinq", "\\cosq"] {
        assert!(!out.contains(bad), "{out}");
    }
}

/// `answer-key --manifest` lists every displayed formula with its LaTeX exactly as printed
/// (each is found in the .tex) and the engine's value in the plain syntax.
#[test]
fn answer_key_manifest_lists_every_display_as_printed() {
    let d = tmp();
    let tex = d.path().join("key.tex");
    let man = d.path().join("key.json");
    let o = run(&[
        "answer-key",
        spec().to_str().unwrap(),
        "-o",
        tex.to_str().unwrap(),
        "--manifest",
        man.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&tex).unwrap();
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&man).unwrap()).unwrap();
    let ds = v["displays"].as_array().unwrap();
    let boxed = "\\TResultat{";
    assert_eq!(
        ds.len(),
        text.matches("\\begin{align*}").count() + text.matches(boxed).count()
    );
    for disp in ds {
        let latex = disp["latex"].as_str().unwrap();
        assert!(
            text.contains(&format!("\\begin{{align*}}\n{latex}\n\\end{{align*}}"))
                || text.contains(&format!("{boxed}\n{latex}\n}}"))
        );
        assert!(disp["what"].is_string() && disp["role"].is_string());
        assert!(disp["value"]["kind"].is_string());
    }
    assert!(
        ds.iter()
            .any(|d| d["what"] == "delta(O2,2/0).x2" && d["role"] == "result")
    );
}

/// The regulator's spec with an edit.
fn edited_regulator(edit: impl Fn(&mut serde_json::Value)) -> (tempfile::TempDir, PathBuf) {
    let mut j: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(spec()).unwrap()).unwrap();
    edit(&mut j);
    let d = tmp();
    let p = d.path().join("edited.json");
    std::fs::write(&p, serde_json::to_string_pretty(&j).unwrap()).unwrap();
    (d, p)
}

#[test]
fn a_unit_that_is_not_si_exits_2_naming_its_json_path() {
    let (_d, p) = edited_regulator(|j| j["parameters"][3]["unit"] = "tr/min".into());
    let o = run(&["check", p.to_str().unwrap(), "--samples", "2"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(e.contains("parameters[3].unit"), "{e}");
    assert!(e.contains("rad/s"), "{e}");
    assert!(stdout(&o).is_empty());
}

#[test]
fn check_exits_1_on_an_inhomogeneous_position_naming_the_terms() {
    // O2 at d1 z0 + m2 L1 y1: a mass times a length among lengths. The float backend agrees
    // with the symbolic side (same mechanism); the dimensions do not.
    let (_d, p) = edited_regulator(|j| {
        let o2 = j["points"]
            .as_array_mut()
            .unwrap()
            .iter_mut()
            .find(|p| p["name"] == "O2")
            .unwrap();
        o2["position"] = "d1*z0 + m2*L1*y1".into();
    });
    let o = run(&["check", p.to_str().unwrap(), "--samples", "2"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(e.contains("wrong dimension"), "{e}");
    assert!(
        e.contains("V(G2,2/0) in B2, x2: inhomogeneous: the terms `-L1*m2*dot(theta1)`"),
        "{e}"
    );
    assert!(!e.contains("disagree"), "the float backend agrees: {e}");
    let out = stdout(&o);
    assert!(out.contains("DIMENSION: V(G2,2/0) in B2, x2"), "{out}");
    // The JSON report carries each value's dimension verdict.
    let o = run(&["check", p.to_str().unwrap(), "--samples", "2", "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["passed"], false);
    let dims = v["dimensions"].as_array().unwrap();
    assert_eq!(dims.len(), 36);
    let omega = dims.iter().find(|x| x["id"] == "Omega(2/0) in B2").unwrap();
    assert_eq!(omega["ok"], true);
    let vg = dims
        .iter()
        .find(|x| x["id"] == "V(G2,2/0) in B2" && x["hypothesis"].is_null())
        .unwrap();
    assert_eq!(vg["ok"], false);
    assert!(vg["error"].as_str().unwrap().contains("inhomogeneous"));
}

/// A text using every whitelisted macro of free-text formulas (issue 12, item 3).
const RICH_SAMPLE: &str = "Le rotor $S_1$ tourne de $\\theta_1$ autour de $(O_1, \\vec{z}_0)$ \
    dans $\\mathcal{R}_0$ ; $\\overrightarrow{O_1G_2} \\wedge m_2 \\vec{\\Gamma}(G_2/\\mathcal{R}_0)$, \
    $\\left\\{ \\mathcal{D}(2/0) \\right\\}_{O_2}$, $\\dot{\\theta}_1^{2} \\cdot \\ddot\\theta_2$, \
    $\\frac{1}{2} m v^2 \\times \\sin\\alpha \\cos\\beta \\tan\\gamma$, \
    $\\left( \\frac{\\pi}{2} - q_1 \\right) \\quad \\ell \\leq \\infty$, $a \\geq b \\neq c \\approx d$, \
    $x \\rightarrow 0$, $u_1, \\ldots, u_n$, $\\mathrm{C}_{m}\\,\\omega\\;\\Omega\\!$, $f'(x)$, \
    $\\varepsilon \\vartheta \\varphi \\Delta \\Lambda \\Psi$ ; 100 % & # _ ~ \\$ et θ̇.";

/// Whitelisted formulas in free texts typeset with pdflatex; a spec with a forbidden one is
/// refused with exit 2, its path named and nothing written.
#[test]
fn free_text_formulas_compile_and_forbidden_ones_exit_2() {
    let d = tmp();
    // The text as the answer key prints it (pure string code: no symbolica here).
    let body = torseur::latex::rich_text(RICH_SAMPLE).expect("whitelisted");
    let tex = d.path().join("rich.tex");
    std::fs::write(
        &tex,
        format!(
            "\\documentclass[a4paper,11pt]{{article}}\n\\usepackage[utf8]{{inputenc}}\n\
             \\usepackage[T1]{{fontenc}}\n\\usepackage[french]{{babel}}\n\
             \\usepackage{{lmodern}}\n\\usepackage{{amsmath,amssymb}}\n\
             \\begin{{document}}\n{body}\n\\end{{document}}\n"
        ),
    )
    .unwrap();
    let c = pdflatex(&tex);
    assert!(c.status.success(), "{}", stdout(&c));

    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(spec()).unwrap()).unwrap();
    v["description"] = RICH_SAMPLE.into();
    v["actions"][0]["label"] = "le moteur $M$".into();
    let good = d.path().join("good.json");
    std::fs::write(&good, v.to_string()).unwrap();
    let key = d.path().join("good.tex");
    let o = run(&[
        "answer-key",
        good.to_str().unwrap(),
        "-o",
        key.to_str().unwrap(),
        "--pdf",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(d.path().join("good.pdf").exists());

    v["questions"][2]["statement"] = "Calculer $\\input{/etc/passwd}$.".into();
    let bad = d.path().join("bad.json");
    std::fs::write(&bad, v.to_string()).unwrap();
    let out = d.path().join("bad.tex");
    let o = run(&[
        "answer-key",
        bad.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains("questions[2].statement"), "{err}");
    assert!(err.contains("`\\input` is not allowed"), "{err}");
    assert!(!out.exists());
    assert!(stdout(&o).is_empty());
}

/// The `torseur: error:` line of a run's stderr (the rest is symbolica's licence notice).
fn error_line(o: &Output) -> String {
    let e = stderr(o);
    e.lines()
        .find(|l| l.starts_with("torseur: error:"))
        .unwrap_or_else(|| panic!("no error line in {e}"))
        .to_string()
}

#[test]
fn a_huge_input_is_quoted_by_an_excerpt_and_the_message_stays_short() {
    // Issue 14: 5000 nested parentheses in a spec got a 10 kB message quoting all of them.
    let nested = format!("{}m1{}", "(".repeat(5000), ")".repeat(5000));
    let (d, p) = edited_regulator(|j| j["solids"][0]["mass"] = nested.as_str().into());
    let o = run(&["derive", p.to_str().unwrap(), "-q", "Omega(1/0)"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let line = error_line(&o);
    assert!(line.len() < 400, "{} bytes: {line}", line.len());
    assert!(line.contains("at solids[0].mass"), "{line}");
    assert!(line.contains("(10002 characters)"), "{line}");
    // The same expression typed on the command line, and a huge quantity.
    let s = spec();
    let quantity = format!("delta({},2/0)", "O".repeat(10_000));
    let verify = [
        "verify",
        s.to_str().unwrap(),
        "-q",
        "delta(O2,2/0).x2",
        "--expr",
        &nested,
    ];
    let derive = ["derive", s.to_str().unwrap(), "-q", &quantity];
    for args in [&verify[..], &derive[..]] {
        let o = run(args);
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        let line = error_line(&o);
        assert!(line.len() < 400, "{} bytes: {line}", line.len());
    }
    // A values file naming a parameter with 10 000 letters.
    let at = d.path().join("values.json");
    let name = "x".repeat(10_000);
    std::fs::write(
        &at,
        format!(r#"{{"parameters": {{"{name}": 1}}, "coordinates": {{}}}}"#),
    )
    .unwrap();
    let o = run(&["eval", s.to_str().unwrap(), "--at", at.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let line = error_line(&o);
    assert!(line.len() < 400, "{} bytes: {line}", line.len());
}

/// `derive --form canonical` prints the canonical polynomial (the JSON's `canonical` string);
/// the default prints the presentation form (the JSON's `presentation` string), which differs.
#[test]
fn derive_prints_the_form_asked() {
    let d = tmp();
    let json = d.path().join("d.json");
    let spec = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("derivations/double_pendule.json")
        .to_string_lossy()
        .into_owned();
    let q = "V(G2,2/0).x2";
    let o = run(&["derive", &spec, "-q", q, "--json", json.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let j: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let v = &j["quantities"][0]["value"];
    let (canonical, shown) = (
        v["canonical"].as_str().unwrap(),
        v["presentation"].as_str().unwrap(),
    );
    assert_ne!(canonical, shown);
    assert_eq!(stdout(&o), format!("{q} = {shown}\n"));
    let o = run(&["derive", &spec, "-q", q, "--form", "canonical"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o), format!("{q} = {canonical}\n"));
    let o = run(&["derive", &spec, "-q", q, "--form", "expanded"]);
    assert_eq!(o.status.code(), Some(2));
}

/// `derive --form structured`: the names first, each quantity of the spec once, the equations
/// of motion over the names; the text and the JSON agree line for line; `--latex` with it is
/// refused (exit 2) and writes nothing.
#[test]
fn derive_writes_the_structured_form() {
    let d = tmp();
    let json = d.path().join("s.json");
    let tex = d.path().join("s.tex");
    let spec = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("derivations/chain/planar_3.json")
        .to_string_lossy()
        .into_owned();
    let o = run(&[
        "derive",
        &spec,
        "--form",
        "structured",
        "--json",
        json.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let j: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let names = j["names"].as_array().unwrap();
    assert!(names.len() >= 6, "{text}");
    for (k, n) in names.iter().enumerate() {
        let line = format!(
            "N{} = {}  # {}",
            k + 1,
            n["value"].as_str().unwrap(),
            n["meaning"].as_str().unwrap()
        );
        assert!(text.lines().any(|l| l == line), "{line} not in\n{text}");
    }
    for q in j["quantities"].as_array().unwrap() {
        assert!(q["named"].as_bool().unwrap(), "{q}");
        let line = format!(
            "{} = {}",
            q["id"].as_str().unwrap(),
            q["value"].as_str().unwrap()
        );
        assert!(text.lines().any(|l| l == line), "{line}");
    }
    let eq = &j["equations_of_motion"];
    assert_eq!(eq["coordinates"].as_array().unwrap().len(), 4);
    assert_eq!(eq["mass"][3][3].as_str(), Some("m3*l2^2"));
    assert!(text.contains("\nM(q3,q3) = m3*l2^2\n"), "{text}");
    let o = run(&[
        "derive",
        &spec,
        "--form",
        "structured",
        "--latex",
        tex.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        error_line(&o).contains("--form structured"),
        "{}",
        stderr(&o)
    );
    assert!(!tex.exists());
}

/// Issue 12's length, counted by pdflatex itself: 3 pages for a key of up to four questions,
/// one more from five questions and one more from seven (the regulator's seven in 5), one
/// more for a closed loop (its loop law, explicit form, and long equations of motion).
#[test]
fn every_answer_key_is_as_short_as_a_teachers() {
    let d = tmp();
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("derivations");
    let mut specs: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    specs.sort();
    assert!(specs.len() >= 12);
    let mut counts = Vec::new();
    for s in &specs {
        let stem = s.file_stem().unwrap().to_str().unwrap().to_string();
        let tex = d.path().join(format!("{stem}.tex"));
        let o = run(&[
            "answer-key",
            s.to_str().unwrap(),
            "-o",
            tex.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{stem}: {}", stderr(&o));
        let c = pdflatex(&tex);
        assert!(c.status.success(), "{stem}: {}", stdout(&c));
        // « Output written on x.pdf (5 pages, 123456 bytes). »
        let log = stdout(&c);
        // No line runs into the margin (a long inline formula with few breaks).
        assert!(
            !log.contains("Overfull \\hbox"),
            "{stem}: a line runs into the margin:\n{}",
            log.lines()
                .filter(|l| l.contains("Overfull"))
                .collect::<Vec<_>>()
                .join("\n")
        );
        let pages: usize = log
            .split("Output written on")
            .nth(1)
            .and_then(|r| {
                r.split_once('(')?
                    .1
                    .split_once(" page")
                    .map(|x| x.0.trim().to_string())
            })
            .and_then(|n| n.parse().ok())
            .unwrap_or_else(|| panic!("{stem}: no page count in pdflatex's output"));
        let spec: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(s).unwrap()).unwrap();
        let count = |k: &str| spec[k].as_array().map_or(0, Vec::len);
        let questions = count("questions");
        let most = 3
            + usize::from(questions >= 5)
            + usize::from(questions >= 7)
            + usize::from(count("closures") > 0);
        counts.push(format!("{stem} {pages}"));
        assert!(
            pages <= most,
            "{stem}: {pages} pages, at most {most} ({counts:?})"
        );
    }
}

/// A derived result far past the old 20,000-character limit (chain 8's δ(O1,E1/0)·z0, 3.5 MB
/// of canonical text) goes back through `verify -e @FILE` and is found equal; a missing file
/// is bad input (exit 2), and so is a text past the stated bound.
#[test]
fn a_long_derived_result_is_read_back_from_a_file() {
    let d = tmp();
    let chain = Path::new(env!("CARGO_MANIFEST_DIR")).join("derivations/chain/chain_8.json");
    let q = "delta(O1,E1/0).z0";
    let o = run(&[
        "derive",
        chain.to_str().unwrap(),
        "-q",
        q,
        "--form",
        "canonical",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let value = text.trim_end().split_once(" = ").unwrap().1.to_string();
    assert!(value.len() > 1_000_000, "{}", value.len());
    let file = d.path().join("value.txt");
    std::fs::write(&file, &value).unwrap();
    let at = format!("@{}", file.display());
    let v = run(&["verify", chain.to_str().unwrap(), "-q", q, "-e", &at]);
    assert_eq!(v.status.code(), Some(0), "{}", stderr(&v));
    assert!(stdout(&v).contains("equivalent"));
    // One term changed: not equivalent, the difference shown.
    let wrong = value.replacen("C1*ddot(q1)", "C1*ddot(q2)", 1);
    assert_ne!(wrong, value);
    std::fs::write(&file, &wrong).unwrap();
    let v = run(&["verify", chain.to_str().unwrap(), "-q", q, "-e", &at]);
    assert_eq!(v.status.code(), Some(1), "{}", stderr(&v));
    assert!(
        stdout(&v).contains("C1*(ddot(q2) - ddot(q1))"),
        "{}",
        stdout(&v)
    );
    let missing = format!("@{}", d.path().join("none.txt").display());
    let v = run(&["verify", chain.to_str().unwrap(), "-q", q, "-e", &missing]);
    assert_eq!(v.status.code(), Some(2));
    assert!(
        stderr(&v).contains("--expr @") && stderr(&v).contains("cannot read"),
        "{}",
        stderr(&v)
    );
    std::fs::write(&file, "m1 + ".repeat(torseur::expr::MAX_INPUT_LEN / 5 + 1)).unwrap();
    let v = run(&["verify", chain.to_str().unwrap(), "-q", q, "-e", &at]);
    assert_eq!(v.status.code(), Some(2));
    assert!(stderr(&v).contains("16777216"), "{}", stderr(&v));
    assert!(stderr(&v).len() < 2000);
}
