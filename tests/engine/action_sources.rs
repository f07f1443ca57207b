//! The spec's names on the page (issue 34, item 7): a given action's torsor prints what
//! exerts it in the course's words ({T(poussée → 1)}, not {T(poussee → 1)}), two links
//! between the same solids print apart ({T_A(0 → 1)} and {T_B(0 → 1)}), and a link is named
//! in prose by its label, not its identifier.

use std::collections::{BTreeMap, BTreeSet};
use torseur::mechanism::{Mark, Mechanism};

fn load(rel: &str) -> Mechanism {
    torseur::spec::load(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(rel))
        .unwrap_or_else(|e| panic!("{rel}: {e}"))
}

fn key(m: &Mechanism) -> torseur::latex::AnswerKey {
    torseur::latex::answer_key_document(
        m,
        torseur::latex::VectorStyle::Sum,
        &torseur::simulate::question_runs(m),
    )
    .unwrap()
}

fn json(rel: &str) -> serde_json::Value {
    let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(rel);
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

/// The printed name of each action display of the bilan (`\mathcal{T}_{A}(0 \rightarrow 1)`)
/// and the points it is shown at.
fn bilan_torsors(k: &torseur::latex::AnswerKey) -> BTreeMap<String, BTreeSet<String>> {
    let mut out: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for d in &k.displays {
        // An action of a bilan is its step `T(from->on)`; a quantity asked is `{T(…)}_P`.
        if !d.what.starts_with("T(") {
            continue;
        }
        // A wide torsor is written by its elements (R, M(P)), named in the line before.
        let Some(rest) = d.latex.strip_prefix("\\TTorseur{") else {
            continue;
        };
        let (name, after) = rest.split_once("}{").unwrap();
        let point = after.split_once('}').unwrap().0;
        out.entry(name.to_string())
            .or_default()
            .insert(point.to_string());
    }
    out
}

/// The library's actions, by the words their specs give: an accented word of the label
/// (« la poussée », « le couple résistant »), a source given (« moteur 1 »).
#[test]
fn the_library_prints_each_action_in_the_course_s_words() {
    for (spec, printed) in [
        (
            "derivations/pendule_sur_chariot.json",
            "\\mathcal{T}(\\textnormal{poussée} \\rightarrow 1)",
        ),
        (
            "derivations/train_engrenages.json",
            "\\mathcal{T}(\\textnormal{résistant} \\rightarrow 2)",
        ),
        (
            "derivations/masse_ressort_forcee.json",
            "\\mathcal{T}(\\mathrm{excitateur} \\rightarrow 1)",
        ),
        (
            "derivations/bras_robot_deux_axes.json",
            "\\mathcal{T}(\\textnormal{moteur 1} \\rightarrow 1)",
        ),
    ] {
        let k = key(&load(spec));
        assert!(k.tex.contains(printed), "{spec}: no {printed}");
    }
}

/// For every spec of the library and of the tests: no action whose source differs from its
/// identifier prints the identifier, each bilan torsor's printed name is shown at one point
/// only (two links between the same solids never read the same), and a link with friction or
/// a spring is named in the model's hypotheses by its label.
#[test]
fn no_identifier_reaches_the_page_in_place_of_a_source() {
    for path in super::specs_in(&["derivations", "tests/specs"]) {
        let m = torseur::spec::load(&path).unwrap();
        let k = key(&m);
        let sources = torseur::wire::action_sources(m.spec());
        for (a, s) in m.spec().actions.iter().zip(&sources) {
            if *s != a.name {
                let raw = format!("\\mathrm{{{}}} \\rightarrow", a.name);
                assert!(!k.tex.contains(&raw), "{}: {raw}", path.display());
            }
        }
        for (name, points) in bilan_torsors(&k) {
            assert_eq!(
                points.len(),
                1,
                "{}: {name} printed for actions at {points:?}",
                path.display()
            );
        }
        for l in m.links() {
            let raw = format!("la liaison {} (", l.name);
            assert!(!k.tex.contains(&raw), "{}: {raw}", path.display());
        }
    }
}

/// Two bearings between the rotor and the frame: each torsor carries its bearing's centre, in
/// the bilan and wherever it is cited.
#[test]
fn two_bearings_print_apart() {
    let m = load("derivations/rotor_deux_paliers.json");
    let k = key(&m);
    for needle in [
        "\\TTorseur{\\mathcal{T}_{A}(0 \\rightarrow 1)}{A}",
        "\\TTorseur{\\mathcal{T}_{B}(0 \\rightarrow 1)}{B}",
    ] {
        assert!(k.tex.contains(needle), "no {needle}");
    }
    assert!(!k.tex.contains("\\mathcal{T}(0 \\rightarrow 1)}{A}"));
    // The motor, between the same solids but a given action, keeps its own name.
    assert!(
        k.tex
            .contains("\\TTorseur{\\mathcal{T}(\\mathrm{moteur} \\rightarrow 1)}{A}")
    );
}

/// Two links between the same solids at one point are told apart by their names; a link
/// alone between its solids has no mark.
#[test]
fn links_at_one_point_are_marked_by_their_names() {
    let marks = |v: &serde_json::Value| -> Vec<Option<Mark>> {
        let m = torseur::spec::from_str(&v.to_string()).unwrap();
        let n = m.links().len();
        (m.dynamics().actions[..n].iter())
            .map(|a| a.mark.clone())
            .collect()
    };
    let mut v = json("derivations/rotor_deux_paliers.json");
    assert_eq!(
        marks(&v),
        [Some(Mark::Point("A".into())), Some(Mark::Point("B".into()))]
    );
    v["links"][1]["point"] = "A".into();
    assert_eq!(
        marks(&v),
        [Some(Mark::Link("A".into())), Some(Mark::Link("B".into()))]
    );
    let v = json("derivations/train_engrenages.json");
    assert_eq!(marks(&v), [None, None]);
}

/// The default source: read from the label, else the name; two actions whose labels would
/// print the same source, or one that a solid or gravity prints, keep their names.
#[test]
fn sources_read_from_labels_never_print_the_same() {
    let mut v = json("derivations/train_engrenages.json");
    let spec = |v: &serde_json::Value| -> torseur::wire::SpecFile {
        serde_json::from_value(v.clone()).unwrap()
    };
    assert_eq!(
        torseur::wire::action_sources(&spec(&v)),
        ["moteur", "résistant", "denture"]
    );
    v["actions"][1]["label"] = "le moteur".into();
    v["actions"][2]["label"] = "la pes".into();
    assert_eq!(
        torseur::wire::action_sources(&spec(&v)),
        ["moteur", "resistant", "denture"]
    );
    // A source given is kept as given.
    v["actions"][1]["source"] = "$C_r$".into();
    assert_eq!(
        torseur::wire::action_sources(&spec(&v)),
        ["moteur", "$C_r$", "denture"]
    );
    let k = key(&torseur::spec::from_str(&v.to_string()).unwrap());
    assert!(k.tex.contains("\\mathcal{T}(C_r \\rightarrow 2)"));
}

/// A source that would print like another torsor's, or could not be printed, is refused
/// with its JSON path.
#[test]
fn a_source_that_would_mislead_is_refused_at_its_path() {
    let refused = |edit: &dyn Fn(&mut serde_json::Value)| {
        let mut v = json("derivations/train_engrenages.json");
        edit(&mut v);
        torseur::spec::from_str(&v.to_string())
            .unwrap_err()
            .to_string()
    };
    for (edit, words) in [
        (
            &(|v: &mut serde_json::Value| v["actions"][1]["source"] = "moteur".into())
                as &dyn Fn(&mut serde_json::Value),
            "also the source of actions[0] (`moteur`)",
        ),
        (
            &|v: &mut serde_json::Value| v["actions"][1]["source"] = "2".into(),
            "already prints as the source of another torsor",
        ),
        (
            &|v: &mut serde_json::Value| v["actions"][1]["source"] = "pes".into(),
            "already prints as the source of another torsor",
        ),
        (
            &|v: &mut serde_json::Value| v["actions"][1]["source"] = " ".into(),
            "may not be blank",
        ),
        (
            &|v: &mut serde_json::Value| v["actions"][1]["source"] = "r".repeat(41).into(),
            "41 characters",
        ),
        (
            &|v: &mut serde_json::Value| v["actions"][1]["source"] = "$\\input{x}$".into(),
            "\\input",
        ),
    ] {
        let e = refused(edit);
        assert!(
            e.contains("actions[1].source") && e.contains(words),
            "{words}: {e}"
        );
    }
}
