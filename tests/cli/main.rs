//! The `torseur` binary, run as a user would. This test binary never uses symbolica itself:
//! a process that has used it cannot start another symbolica process.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

mod budget;
mod corpus;
mod hostile;
mod messages;
mod readme;

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
fn eval_follows_the_json_contract() {
    let d = tmp();
    let at = d.path().join("values.json");
    // theta2 = 0, rates 1 and 0, accelerations 0: delta(O2,2/0).x2 = 0 by the formula
    // (sin 0 = 0, no ddot), V(G2,2/0) = [-(L1+L2)*1, 0, 0].
    std::fs::write(
        &at,
        r#"{"parameters":{"h1":0.1,"d1":0.2,"L1":0.3,"L2":0.5,"m1":1,"m2":2,
            "A1":1,"B1":1,"C1":1,"D1":0,"E1":0,"F1":0,"A2":1,"B2":1,"C2":1,"D2":0,"E2":0,"F2":0,
            "g":9.81,"f":0},
            "coordinates":{"theta1":[0.4,1,0],"theta2":[0,0,0]}}"#,
    )
    .unwrap();
    let o = run(&[
        "eval",
        spec().to_str().unwrap(),
        "--at",
        at.to_str().unwrap(),
        "-q",
        "V(G2,2/0) in B2",
        "-q",
        "delta(O2,2/0).x2",
        "-q",
        "{D(2/0)}_O2 in B2",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let q = v["quantities"].as_array().unwrap();
    assert_eq!(q[0]["id"], "V(G2,2/0) in B2");
    assert_eq!(q[0]["kind"], "vector");
    assert_eq!(q[0]["basis"], "B2");
    let vx = q[0]["value"][0].as_f64().unwrap();
    assert!((vx + 0.8).abs() < 1e-12, "{vx}");
    assert_eq!(q[1]["kind"], "scalar");
    assert!(q[1]["value"].as_f64().unwrap().abs() < 1e-12);
    assert_eq!(q[2]["kind"], "torsor");
    assert_eq!(q[2]["point"], "O2");
    assert_eq!(q[2]["resultant"].as_array().unwrap().len(), 3);
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
fn verify_answers_equivalent_or_shows_the_difference() {
    let s = spec();
    let ok = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "delta(O2,2/0).x2",
        "--hypothesis",
        "H1",
        "-e",
        "(A2 + m2*L2^2)*ddot(theta2) + (m2*L1*L2*sin(theta2) + 1/2*(C2 - B2 + m2*L2^2)*sin(2*theta2) + D2*cos(2*theta2))*dot(theta1)^2",
    ]);
    assert_eq!(ok.status.code(), Some(0), "{}", stderr(&ok));
    assert!(stdout(&ok).contains("equivalent"));
    let bad = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "delta(O2,2/0).x2",
        "--hypothesis",
        "H1",
        "-e",
        "(A2 + m2*L2^2)*ddot(theta2)",
    ]);
    assert_eq!(bad.status.code(), Some(1));
    assert!(stdout(&bad).contains("NOT equivalent"));
    assert!(stdout(&bad).contains("dot(theta1)^2"), "{}", stdout(&bad));
    let vector = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "V(G2,2/0) in B2",
        "-e",
        "[-(L1 + L2*cos(theta2))*dot(theta1), 0, L2*dot(theta2)]",
    ]);
    assert_eq!(vector.status.code(), Some(0), "{}", stderr(&vector));
    let malformed = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "V(G2,2/0) in B2",
        "-e",
        "[1, 2",
    ]);
    assert_eq!(malformed.status.code(), Some(2));
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
        "\\overrightarrow{\\Omega(2/0)} &= \\begin{pmatrix} \\dot{\\theta}_{2} \\\\ \\dot{\\theta}_{1}\\,\\sin\\theta_{2} \\\\ \\dot{\\theta}_{1}\\,\\cos\\theta_{2} \\end{pmatrix}_{\\mathcal{B}_{2}}"
    ));
    // Long vectors stay sums over the basis vectors, so nothing overflows the page.
    assert!(t.contains("\\right]\\,\\dot{\\theta}_{1}^{2}\\,\\vec{x}_{1} \\\\"));
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
fn verify_accepts_an_equation_of_motion_up_to_a_factor() {
    let eq = "A2*ddot(theta2) + m2*L2^2*ddot(theta2) \
              + (C2 - B2)*sin(theta2)*cos(theta2)*dot(theta1)^2 + D2*cos(2*theta2)*dot(theta1)^2 \
              + m2*L1*L2*sin(theta2)*dot(theta1)^2 + m2*L2^2*sin(theta2)*cos(theta2)*dot(theta1)^2 \
              = -m2*g*L2*cos(theta2) - f*dot(theta2)";
    let o = run(&[
        "verify",
        spec().to_str().unwrap(),
        "-q",
        "eom(theta2)",
        "--hypothesis",
        "H1",
        "-e",
        eq,
    ]);
    assert!(o.status.success(), "{}{}", stdout(&o), stderr(&o));
    // Twice the equation, sides swapped: the same equation.
    let (lhs, rhs) = eq.split_once('=').unwrap();
    let doubled = format!("2*({rhs}) = 2*({lhs})");
    let o = run(&[
        "verify",
        spec().to_str().unwrap(),
        "-q",
        "eom(theta2)",
        "--hypothesis",
        "H1",
        "-e",
        &doubled,
    ]);
    assert!(
        o.status.success(),
        "{doubled}: {}{}",
        stdout(&o),
        stderr(&o)
    );
    // Without friction it is another equation.
    let o = run(&[
        "verify",
        spec().to_str().unwrap(),
        "-q",
        "eom(theta2)",
        "--hypothesis",
        "H1",
        "-e",
        &eq.replace(" - f*dot(theta2)", ""),
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
}

#[test]
fn verify_takes_an_expression_that_starts_with_a_minus() {
    // Found while writing the library: `-e "-m..."` was read as an option.
    let o = run(&[
        "verify",
        spec().to_str().unwrap(),
        "-q",
        "Omega(2/1) in B1",
        "-e",
        "[-(-dot(theta2)), 0, 0]",
    ]);
    assert!(o.status.success(), "{}{}", stdout(&o), stderr(&o));
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
    let boxed = "\\begin{empheq}[box=\\fbox]{align*}";
    assert_eq!(
        ds.len(),
        text.matches("\\begin{align*}").count() + text.matches(boxed).count()
    );
    for disp in ds {
        let latex = disp["latex"].as_str().unwrap();
        assert!(
            text.contains(&format!("\\begin{{align*}}\n{latex}\n\\end{{align*}}"))
                || text.contains(&format!("{boxed}\n{latex}\n\\end{{empheq}}"))
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

/// A corrigé writes the pendulum's equation divided by m l (hand derivation in
/// tests/engine/verify.rs: eom(θ) = m l (ẍ cos θ + l θ̈ + g sin θ) for a point mass).
#[test]
fn verify_accepts_an_equation_up_to_a_factor_of_parameters_and_reports_it() {
    let s = fixture("pendule_simple_sur_chariot.json");
    let divided = "ddot(x)*cos(theta) + l*ddot(theta) + g*sin(theta) = 0";
    let o = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "eom(theta)",
        "-e",
        divided,
    ]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert!(
        stdout(&o).contains("equivalent, up to the factor m*l"),
        "{}",
        stdout(&o)
    );
    // Without -q: found to be the equation of motion of theta, with the same factor.
    let o = run(&["verify", s.to_str().unwrap(), "-e", divided]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("up to the factor m*l"), "{out}");
    assert!(out.contains("equation of motion eom(theta)"), "{out}");
    // Multiplied by dot(theta): another equation (exit 1).
    let o = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "eom(theta)",
        "-e",
        "dot(theta)*(ddot(x)*cos(theta) + l*ddot(theta) + g*sin(theta)) = 0",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert!(stdout(&o).contains("NOT equivalent"), "{}", stdout(&o));
    // The weight's sign wrong (exit 1): the difference is that term alone, −2 m g l sin θ.
    let o = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "eom(theta)",
        "-e",
        "ddot(x)*cos(theta) + l*ddot(theta) - g*sin(theta) = 0",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert!(
        stdout(&o).contains("difference: -2*m*g*l*sin(theta)\n"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn verify_decides_relations_between_unknowns_quantities_and_expressions() {
    let s = fixture("pendule_simple_sur_chariot.json");
    // Resultant theorem on the pendulum along y0: Y12 − m g = m Γ(G,2/0)·y0 (hand form in
    // tests/engine/verify.rs), written with the unknown and the quantity Rd(2/0).y0.
    let o = run(&[
        "verify",
        s.to_str().unwrap(),
        "-e",
        "Y12 - m*g = Rd(2/0).y0",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("relation: lhs − rhs = 0"), "{out}");
    assert!(
        out.contains("Rd(2/0).y0 replaced by its derived value and Y12 by its solved value"),
        "{out}"
    );
    // A wrong relation (exit 1), with --quantity naming the unknown it is about.
    let o = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "Y12",
        "-e",
        "Y12 = m*g",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert!(stdout(&o).contains("NOT equivalent"), "{}", stdout(&o));
    // The regulator's Q6: C_m = δ(O1,E/0)·z0, under H2.
    let o = run(&[
        "verify",
        spec().to_str().unwrap(),
        "-e",
        "C_m = delta(O1,E/0).z0",
        "--hypothesis",
        "H2",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    // Undeclared names: exit 2, all of them named; an unknown no equation determines: exit 2.
    let o = run(&[
        "verify",
        spec().to_str().unwrap(),
        "-e",
        "C_m = foo + bar*sin(baz)",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("unknown names `foo`, `bar`, `baz` in `foo + bar*sin(baz)`"),
        "{}",
        stderr(&o)
    );
    assert!(stdout(&o).is_empty());
    let o = run(&["verify", spec().to_str().unwrap(), "-e", "X01 = 0"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("`X01`"), "{}", stderr(&o));
    // Without -q, the text must be an equation.
    let o = run(&["verify", spec().to_str().unwrap(), "-e", "C_m"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn eval_demands_only_the_parameters_the_quantities_hold() {
    let d = tmp();
    // δ(O2,2/0) holds L1, L2, m2, A2…F2 and both angles; not g, f, nor solid 1's data.
    let needed = r#""L1":0.3,"L2":0.5,"m2":2,"A2":1,"B2":0.7,"C2":0.4,"D2":0.1,"E2":0.2,"F2":0.05"#;
    let coordinates = r#""coordinates":{"theta1":[0.4,1.5,2],"theta2":[0.3,-0.7,3]}"#;
    let few = d.path().join("few.json");
    std::fs::write(
        &few,
        format!("{{\"parameters\":{{{needed}}},{coordinates}}}"),
    )
    .unwrap();
    let all = d.path().join("all.json");
    std::fs::write(
        &all,
        format!(
            "{{\"parameters\":{{{needed},\"h1\":0.1,\"d1\":0.2,\"m1\":1,\"A1\":1,\"B1\":1,\
             \"C1\":1,\"D1\":0,\"E1\":0,\"F1\":0,\"g\":9.81,\"f\":0.3}},{coordinates}}}"
        ),
    )
    .unwrap();
    let eval = |at: &Path| {
        run(&[
            "eval",
            spec().to_str().unwrap(),
            "--at",
            at.to_str().unwrap(),
            "-q",
            "delta(O2,2/0) in B2",
        ])
    };
    let (o_few, o_all) = (eval(&few), eval(&all));
    assert_eq!(o_few.status.code(), Some(0), "{}", stderr(&o_few));
    assert_eq!(o_all.status.code(), Some(0), "{}", stderr(&o_all));
    // The value does not depend on what else is given.
    assert_eq!(stdout(&o_few), stdout(&o_all));
    // Missing m2 and theta1: exactly those are named (exit 2), nothing on stdout.
    let missing = d.path().join("missing.json");
    std::fs::write(
        &missing,
        format!(
            "{{\"parameters\":{{{}}},\"coordinates\":{{\"theta2\":[0.3,-0.7,3]}}}}",
            needed.replace("\"m2\":2,", "")
        ),
    )
    .unwrap();
    let o = eval(&missing);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("missing parameter `m2` and coordinate `theta1`"),
        "{}",
        stderr(&o)
    );
    assert!(stdout(&o).is_empty());
    // The equation of motion of theta2 does hold g and f.
    let o = run(&[
        "eval",
        spec().to_str().unwrap(),
        "--at",
        few.to_str().unwrap(),
        "-q",
        "eom(theta2)",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("missing parameters `g`, `f` (the requested quantities hold them)"),
        "{}",
        stderr(&o)
    );
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

/// Issue 12's length: the regulator's corrigé in at most 5 pages with its seven questions,
/// every other key of the library in at most 3, counted by pdflatex itself.
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
        let most = if stem == "regulateur_centrifuge" {
            5
        } else {
            3
        };
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

#[test]
fn eval_solves_the_unknowns_an_action_holds_or_takes_them_given() {
    let d = tmp();
    let at = d.path().join("values.json");
    let values = |unknowns: &str| {
        format!(
            r#"{{"parameters":{{"h1":0.1,"d1":0.2,"L1":0.3,"L2":0.5,"m1":1,"m2":2,
            "A1":1,"B1":1.5,"C1":2,"A2":1,"B2":1.2,"C2":0.7,"D2":0.1,"E2":0.05,"F2":-0.02,
            "g":9.81,"f":0.05}},
            "coordinates":{{"theta1":[0.4,1.3,0.2],"theta2":[0.6,-0.4,0.9]}}{unknowns}}}"#
        )
    };
    std::fs::write(&at, values("")).unwrap();
    let spec = spec();
    let eval = |qs: &[&str]| {
        let mut args = vec!["eval", spec.to_str().unwrap(), "--at", at.to_str().unwrap()];
        for q in qs {
            args.extend(["-q", q]);
        }
        run(&args)
    };
    // The moment theorem on E at O1 on z0: the exterior actions' moment is the motor torque,
    // which the PFD solves for.
    let o = eval(&["M(O1,ext->E).z0", "C_m"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let (a, b) = (
        v["quantities"][0]["value"].as_f64().unwrap(),
        v["quantities"][1]["value"].as_f64().unwrap(),
    );
    assert!(
        (a - b).abs() <= 1e-12 * b.abs().max(1.0) && b != 0.0,
        "{a} {b}"
    );
    // X01 is determined by no equation: exit 2, named, nothing on stdout.
    let o = eval(&["R(0->1)"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stdout(&o).is_empty());
    assert!(stderr(&o).contains("no value for `X01`"), "{}", stderr(&o));
    // Given, it is used as is.
    std::fs::write(&at, values(r#","unknowns":{"X01":1,"Y01":2,"Z01":3}"#)).unwrap();
    let o = eval(&["R(0->1) in B0"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(
        v["quantities"][0]["value"],
        serde_json::json!([1.0, 2.0, 3.0])
    );
    // A name that is not an unknown of the PFD.
    std::fs::write(&at, values(r#","unknowns":{"m1":1}"#)).unwrap();
    let o = eval(&["C_m"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("`m1` is not an unknown of the PFD"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn eval_and_derive_give_an_unknown_solved_as_a_quotient() {
    // Two bearings L apart: the moment at A on x1 gives L Y_B = −D ω² (hand derivation in
    // tests/engine/library.rs), so Y_B = −D ω²/L; the resultant on y1, Y_A = −Y_B.
    let d = tmp();
    let at = d.path().join("values.json");
    std::fs::write(
        &at,
        r#"{"parameters":{"m":2,"a":0.01,"c":0.2,"L":0.5,"A1":1,"B1":1,"C1":1,"D1":0.003,
        "E1":0.004,"F1":0,"omega":100,"g":9.81},"coordinates":{"theta":[0.3,100,0]}}"#,
    )
    .unwrap();
    let spec = "derivations/rotor_deux_paliers.json";
    let o = run(&[
        "eval",
        spec,
        "--at",
        at.to_str().unwrap(),
        "-q",
        "Y_B",
        "-q",
        "R(0->1).y1",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let y_b = v["quantities"][0]["value"].as_f64().unwrap();
    assert!((y_b - (-0.003 * 100.0 * 100.0 / 0.5)).abs() < 1e-9, "{y_b}");
    // R(0→1)·y1 = Y_A + Y_B = 0 (the bearings' y1 actions cancel).
    let r = v["quantities"][1]["value"].as_f64().unwrap();
    assert!(r.abs() < 1e-9, "{r}");
    // derive prints the quotient as it reads back; the JSON splits it.
    let o = run(&["derive", spec, "-q", "Y_B"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o).trim(), "Y_B = -D1*omega^2/L\n  under H: 0");
}

#[test]
fn eval_takes_values_written_as_expressions_of_the_others() {
    // The pendulum on a shaft turning at ω (hand derivation in tests/engine/library.rs):
    // A' θ̈ + (C − A') ω² sin θ cos θ + m g a sin θ = 0, A' = A + m a². Its relative
    // equilibrium off the axis is cos β = m g a / ((A' − C) ω²): given by an arccosine, the
    // equation of motion there is zero.
    let d = tmp();
    let at = d.path().join("values.json");
    std::fs::write(
        &at,
        r#"{"parameters": {"m": 0.5, "a": 0.2, "A": 0.01, "C": 0.002, "g": 9.81,
        "omega": 12, "beta": "acos(m*g*a/((A + m*a^2 - C)*omega^2))"},
        "coordinates": {"theta": ["beta", 0, 0]}}"#,
    )
    .unwrap();
    let spec = "derivations/pendule_arbre_tournant.json";
    let eval = |q: &str| run(&["eval", spec, "--at", at.to_str().unwrap(), "-q", q]);
    let o = eval("eom(theta)");
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let r = v["quantities"][0]["value"].as_f64().unwrap();
    assert!(r.abs() < 1e-12, "{r}");
    // The weight's moment there is m g a sin β, β from the same arccosine.
    let o = eval("M(O,pes->2).x1");
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let beta = (0.5f64 * 9.81 * 0.2 / ((0.01 + 0.5 * 0.04 - 0.002) * 144.0)).acos();
    let w = v["quantities"][0]["value"].as_f64().unwrap();
    assert!((w + 0.5 * 9.81 * 0.2 * beta.sin()).abs() < 1e-12, "{w}");
    // Values that refer to each other: exit 2, the entry named, nothing written.
    std::fs::write(&at, r#"{"parameters": {"m": "g*2", "g": "m/2"}}"#).unwrap();
    let o = eval("eom(theta)");
    assert_eq!(o.status.code(), Some(2));
    assert!(stdout(&o).is_empty());
    assert!(stderr(&o).contains("at parameters.g"), "{}", stderr(&o));
    // A function that is not a number's.
    std::fs::write(&at, r#"{"parameters": {"m": "dot(g)"}}"#).unwrap();
    let o = eval("eom(theta)");
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("the functions are sin, cos, tan"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn eval_and_verify_take_the_time_of_a_forced_oscillator() {
    // M ẍ + c ẋ + k x = F0 cos(Ω t) (hand derivation in tests/engine/library.rs): at t the
    // residual is computed here by hand.
    let d = tmp();
    let at = d.path().join("values.json");
    let spec = "derivations/masse_ressort_forcee.json";
    let eval = |q: &str| run(&["eval", spec, "--at", at.to_str().unwrap(), "-q", q]);
    std::fs::write(
        &at,
        r#"{"parameters": {"M": 2, "k": 50, "c": 0.3, "F0": 4, "Omega": 3, "g": 9.81, "X": 0},
        "coordinates": {"x": [0.1, 0.2, 0.3]}, "time": 0.7}"#,
    )
    .unwrap();
    let o = eval("eom(x)");
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let r = v["quantities"][0]["value"].as_f64().unwrap();
    let hand = 2.0 * 0.3 + 0.3 * 0.2 + 50.0 * 0.1 - 4.0 * (3.0f64 * 0.7).cos();
    assert!((r - hand).abs() < 1e-12 * hand.abs(), "{r} {hand}");
    // Without the time: exit 2, the time named.
    std::fs::write(
        &at,
        r#"{"parameters": {"M": 2, "k": 50, "c": 0.3, "F0": 4, "Omega": 3, "g": 9.81},
        "coordinates": {"x": [0.1, 0.2, 0.3]}}"#,
    )
    .unwrap();
    let o = eval("eom(x)");
    assert_eq!(o.status.code(), Some(2));
    assert!(stdout(&o).is_empty());
    assert!(stderr(&o).contains("the time `t`"), "{}", stderr(&o));
    // The weight does not need it.
    assert!(eval("Y01").status.success());
    // A corrigé's equation divided by M, with the time in it.
    let o = run(&[
        "verify",
        spec,
        "-q",
        "eom(x)",
        "-e",
        "ddot(x) + c/M*dot(x) + k/M*x = F0/M*cos(Omega*t)",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("up to the factor M"), "{}", stdout(&o));
    let o = run(&[
        "verify",
        spec,
        "-q",
        "eom(x)",
        "-e",
        "M*ddot(x) + c*dot(x) + k*x = F0*sin(Omega*t)",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
}
