//! The figures planes and the graph of links: drawn for every spec of the library and for
//! rotations the library does not hold (negative axis, offsets), and compiled by pdflatex
//! under the answer key's preamble (French babel) plus TikZ.
//!
//! The compiled document stays in `target/tmp/figures/` to be looked at
//! (`pdftoppm -r 100 -png figures.pdf page`).

use std::path::{Path, PathBuf};
use std::process::Command;

/// The answer key's preamble, with TikZ.
const PREAMBLE: &str = "\\documentclass[a4paper,11pt]{article}\n\\usepackage[utf8]{inputenc}\n\
    \\usepackage[T1]{fontenc}\n\\usepackage[french]{babel}\n\\usepackage{lmodern}\n\
    \\usepackage{amsmath,amssymb,graphicx}\n\\usepackage[margin=2cm]{geometry}\n\
    \\usepackage{tikz}\n\\setlength{\\parindent}{0pt}\n";

/// Rotations the library does not hold: a negative axis with a parameter, an offset of π/2,
/// a negative coordinate, a half turn.
const ODD_ROTATIONS: &str = r#"{"title": "rotations",
  "parameters": [{"name": "alpha", "kind": "angle"}, {"name": "m"}],
  "coordinates": [{"name": "q1", "kind": "angle"}, {"name": "q2", "kind": "angle"},
                  {"name": "q3", "kind": "angle"}, {"name": "q4", "kind": "angle"}],
  "frames": [
    {"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "pi/2 - q1"}},
    {"name": "2", "parent": "1", "rotation": {"axis": "-x", "angle": "q2 + alpha"}},
    {"name": "3", "parent": "2", "rotation": {"axis": "y", "angle": "-q3"}},
    {"name": "4", "parent": "3", "rotation": {"axis": "z", "angle": "pi + q4"}},
    {"name": "5", "parent": "4"}],
  "points": [{"name": "A", "position": "0"}],
  "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "A"},
             {"name": "2", "frame": "2", "mass": "m", "centre": "A"},
             {"name": "3", "frame": "3", "mass": "m", "centre": "A"}],
  "links": [
    {"name": "01", "kind": "pivot_slider", "between": ["0", "1"], "point": "A", "axis": "z0"},
    {"name": "12", "kind": "plane", "between": ["1", "2"], "point": "A", "axis": "x1"},
    {"name": "13", "kind": "line", "between": ["1", "3"], "point": "A", "axis": "z1", "direction": "x1"},
    {"name": "13b", "kind": "point", "between": ["1", "3"], "point": "A", "axis": "y1"}]
}"#;

fn out_dir() -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join("figures");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn pdflatex(dir: &Path, file: &str) {
    let o = Command::new("pdflatex")
        .args([
            "-no-shell-escape",
            "-interaction=nonstopmode",
            "-halt-on-error",
            file,
        ])
        .current_dir(dir)
        .stdin(std::process::Stdio::null())
        .output()
        .expect("pdflatex runs (scripts/setup installs it)");
    let log = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "pdflatex failed on {file}:\n{log}");
    assert!(!log.contains("Overfull \\hbox"), "{file}: {log}");
}

#[test]
fn figures_of_every_spec_compile() {
    let specs = super::specs_in(&["derivations"]);
    let mut doc = String::from(PREAMBLE);
    doc.push_str("\\begin{document}\n");
    let mut mechanisms: Vec<(String, torseur::mechanism::Mechanism)> = specs
        .iter()
        .map(|p| {
            let stem = p.file_stem().unwrap().to_str().unwrap().replace('_', " ");
            (stem, torseur::spec::load(p).unwrap())
        })
        .collect();
    mechanisms.push((
        "rotations".into(),
        torseur::spec::from_str(ODD_ROTATIONS).unwrap(),
    ));
    for (stem, m) in &mechanisms {
        let figures = torseur::latex::rotation_figures(m);
        let graph = torseur::latex::link_graph(m);
        let turned = m
            .frames()
            .ids()
            .filter(|&f| m.frames().get(f).rotation.is_some())
            .count();
        assert_eq!(
            figures.matches("\\begin{tikzpicture}").count(),
            turned,
            "{stem}"
        );
        assert_eq!(graph.is_empty(), m.spec().links.is_empty(), "{stem}");
        doc.push_str(&format!(
            "\\section*{{{stem}}}\n{figures}\n{graph}\n\\clearpage\n"
        ));
    }
    doc.push_str("\\end{document}\n");
    let out = out_dir();
    std::fs::write(out.join("figures.tex"), &doc).unwrap();
    pdflatex(&out, "figures.tex");
}

#[test]
fn a_figure_plane_shows_both_bases_the_axis_and_the_angle() {
    let m = super::regulator();
    let tex = torseur::latex::rotation_figures(&m);
    // θ1 about z0: (x0, y0) then (x1, y1) at 25° and 115°, arc from x0 to x1.
    for needle in [
        "(1.4,0) node[anchor=180, inner sep=2pt] {$\\vec{x}_{0}$}",
        "(0,1.4) node[anchor=270, inner sep=2pt] {$\\vec{y}_{0}$}",
        "(1.269,0.592) node[anchor=205, inner sep=2pt] {$\\vec{x}_{1}$}",
        "(-0.592,1.269) node[anchor=295, inner sep=2pt] {$\\vec{y}_{1}$}",
        "{$\\vec{y}_{1}$}",
        "arc[start angle=0, end angle=25, radius=0.8]",
        "{$\\theta_{1}$}",
        "{$\\vec{z}_{0} = \\vec{z}_{1}$}",
        // θ2 about x1: the plane (y1, z1).
        "{$\\vec{y}_{1}$}",
        "{$\\vec{z}_{2}$}",
        "{$\\vec{x}_{1} = \\vec{x}_{2}$}",
        "{$\\theta_{2}$}",
    ] {
        assert!(tex.contains(needle), "missing {needle} in\n{tex}");
    }
}

/// The angle swept by the arc of a figure plane, in degrees.
fn end_angle(picture: &str) -> i64 {
    let rest = picture.split("end angle=").nth(1).expect("an arc");
    rest[..rest.find(',').unwrap()].parse().unwrap()
}

#[test]
fn odd_rotations_are_drawn_positive_with_the_angle_as_written() {
    let m = torseur::spec::from_str(ODD_ROTATIONS).unwrap();
    let tex = torseur::latex::rotation_figures(&m);
    let pictures: Vec<&str> = tex.split("\\begin{tikzpicture}").skip(1).collect();
    assert_eq!(pictures.len(), 4);
    // π/2 − q1 about z: drawn at 65°, labelled as written.
    assert_eq!(end_angle(pictures[0]), 65, "{}", pictures[0]);
    assert!(pictures[0].contains("{$\\frac{\\pi}{2} - q_{1}$}"));
    // About −x by q2 + α: seen from −x, plane (z, y), the spec's angle.
    assert!(
        (25..=45).contains(&end_angle(pictures[1])),
        "{}",
        pictures[1]
    );
    assert!(pictures[1].contains("{$q_{2} + \\alpha$}"));
    assert!(pictures[1].contains("{$-\\vec{x}_{1} = -\\vec{x}_{2}$}"));
    assert!(pictures[1].contains("(1.4,0) node[anchor=180, inner sep=2pt] {$\\vec{z}_{1}$}"));
    // −q3 about y: q3 about −y, plane (x, z).
    assert!(
        (25..=45).contains(&end_angle(pictures[2])),
        "{}",
        pictures[2]
    );
    assert!(pictures[2].contains("{$q_{3}$}"), "{}", pictures[2]);
    assert!(pictures[2].contains("{$-\\vec{y}_{2} = -\\vec{y}_{3}$}"));
    assert!(pictures[2].contains("{$\\vec{x}_{2}$}"));
    // π + q4 about z: drawn at 205°.
    assert_eq!(end_angle(pictures[3]), 205, "{}", pictures[3]);
    assert!(pictures[3].contains("{$q_{4} + \\pi$}"));
}

#[test]
fn the_graph_of_links_names_each_link_as_the_course_does() {
    let g = torseur::latex::link_graph(&super::regulator());
    assert!(g.contains("pivot d'axe $(O_{1}, \\vec{z}_{0})$"), "{g}");
    assert!(g.contains("pivot d'axe $(O_{2}, \\vec{x}_{1})$, avec frottement visqueux"));
    assert_eq!(g.matches("\\node[solide]").count(), 3);
    let m = torseur::spec::from_str(ODD_ROTATIONS).unwrap();
    let g = torseur::latex::link_graph(&m);
    for needle in [
        "pivot glissant d'axe $(A, \\vec{z}_{0})$",
        "appui plan de normale $\\vec{x}_{1}$",
        // Two links in parallel between 1 and 3: one edge, two lines.
        "linéaire rectiligne de normale $\\vec{z}_{1}$ et de ligne $(A, \\vec{x}_{1})$\\\\ \
         ponctuelle de normale $(A, \\vec{y}_{1})$",
    ] {
        assert!(g.contains(needle), "missing {needle} in\n{g}");
    }
    assert_eq!(g.matches("\\draw (n").count(), 3);
    let toupie = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/toupie.json"
    ))
    .unwrap();
    assert!(torseur::latex::link_graph(&toupie).contains("rotule de centre $O$"));
    let m = torseur::spec::from_str(r#"{"title": "sans liaison"}"#).unwrap();
    assert_eq!(torseur::latex::link_graph(&m), "");
}
