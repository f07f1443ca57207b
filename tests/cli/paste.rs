//! A fragment of the answer key pasted into a teacher's own document (issue 34, item 6): a
//! host of another class, another size and other margins, which defines its own `\vect`, its
//! own notation for a long vector and macros a corrigé could clash with, compiles with the
//! fragments of several keys `\input` into it, and no line of it is overfull by more than 1 pt.

use super::*;

/// A teacher's document: KOMA's article class in 12 pt, 2.5 cm margins, bold vectors, their
/// own `\vect` (used for the long vectors of the corrigé, defined before the fragments, so
/// that it wins) and macros named as a corrigé might name its own.
const HOST: &str = r"\documentclass[12pt,a4paper]{scrartcl}
\usepackage[T1]{fontenc}
\usepackage[french]{babel}
\usepackage{amsmath,graphicx}
\usepackage[margin=2.5cm]{geometry}
\renewcommand{\vec}[1]{\boldsymbol{#1}}
\newcommand{\vect}[1]{\overrightarrow{#1}}
\newcommand{\TVecLong}[1]{\vect{#1}}
\newcommand{\torseur}[1]{\left\{#1\right\}}
\newcommand{\R}{\mathcal{R}}
\begin{document}
\section{Mon cours}
Un paragraphe du cours, puis les corrigés.
";

/// The overfull lines of a pdflatex log wider than 1 pt: (how much, the log's line).
fn overfull(log: &str) -> Vec<(f64, String)> {
    log.lines()
        .filter_map(|l| {
            let rest = l.strip_prefix("Overfull \\hbox (")?;
            let pt: f64 = rest.split("pt too wide").next()?.parse().ok()?;
            (pt > 1.0).then(|| (pt, l.to_string()))
        })
        .collect()
}

#[test]
fn fragments_compile_in_a_teachers_document_and_fit_its_lines() {
    if Command::new("pdflatex").arg("--version").output().is_err() {
        eprintln!("SKIPPED: pdflatex is not installed (scripts/setup installs it; CI has it)");
        return;
    }
    let d = tmp();
    let keys = [
        ("regulateur_centrifuge", "3,4,6"),
        ("treuil", ""),
        ("double_pendule", ""),
        ("bielle_manivelle", "1,2"),
    ];
    let mut host = HOST.to_string();
    for (k, qs) in keys {
        let spec = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("derivations/{k}.json"));
        let out = d.path().join(format!("{k}.tex"));
        let mut args = vec!["answer-key", spec.to_str().unwrap(), "--fragment"];
        if !qs.is_empty() {
            args.extend(["--questions", qs]);
        }
        args.extend(["-o", out.to_str().unwrap()]);
        let o = run(&args);
        assert!(o.status.success(), "{k}: {}", stderr(&o));
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(!text.contains("\\documentclass") && !text.contains("\\begin{document}"));
        assert!(!text.contains("\\usepackage") && !text.contains("\\renewcommand"));
        // The headings are the block's macros, run in whatever the class.
        assert!(!text.contains("\\subsubsection") && !text.contains("\\paragraph"));
        assert!(
            text.starts_with("% Corrigé de"),
            "{k}: the packages are said first"
        );
        let title = k.replace('_', " ");
        host.push_str(&format!("\\subsection*{{{title}}}\n\\input{{{k}.tex}}\n"));
    }
    host.push_str("\\end{document}\n");
    let tex = d.path().join("cours.tex");
    std::fs::write(&tex, host).unwrap();
    let c = pdflatex(&tex);
    let log = std::fs::read_to_string(d.path().join("cours.log")).unwrap_or_default();
    assert!(c.status.success(), "{}", String::from_utf8_lossy(&c.stdout));
    let wide = overfull(&log);
    assert!(wide.is_empty(), "overfull lines: {wide:#?}");
}

#[test]
fn a_fragment_asks_for_questions_the_spec_has() {
    let o = run(&[
        "answer-key",
        spec().to_str().unwrap(),
        "--fragment",
        "--questions",
        "2,99",
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("question 99"), "{}", stderr(&o));
    let o = run(&["answer-key", spec().to_str().unwrap(), "--questions", "2"]);
    assert_eq!(o.status.code(), Some(2), "--questions without --fragment");
}

/// A fragment's head names the questions it holds, and says so when the spec poses none.
#[test]
fn a_fragment_names_its_questions_or_says_there_are_none() {
    let (d, p) = edited_regulator(|j| {
        j.as_object_mut().unwrap().remove("questions");
    });
    let out = d.path().join("body.tex");
    let o = run(&[
        "answer-key",
        p.to_str().unwrap(),
        "--fragment",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let head = std::fs::read_to_string(&out).unwrap();
    let first = head.lines().next().unwrap();
    assert!(first.contains("aucune question"), "{first}");
    let out = d.path().join("two.tex");
    let spec = spec();
    let o = run(&[
        "answer-key",
        spec.to_str().unwrap(),
        "--fragment",
        "--questions",
        "2,4",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let head = std::fs::read_to_string(&out).unwrap();
    assert!(
        head.lines().next().unwrap().contains("question(s) 2, 4"),
        "{head:.200}"
    );
}
