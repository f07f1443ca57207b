//! The answer key is pinned by a committed golden file, and so are `derive`'s text and JSON;
//! re-approve a reviewed change with `TORSEUR_BLESS=1 cargo test --release --test engine latex`.

use super::golden::golden_in;
use super::*;

fn golden(name: &str, actual: &str) {
    golden_in("latex", name, actual)
}

/// Every spec's answer key is pinned (its layout; its signs are proven in `printed`).
#[test]
fn every_answer_key_matches_its_golden_file() {
    let specs = specs_in(&["derivations"]);
    assert!(specs.len() >= 10);
    for p in specs {
        let m = torseur::spec::load(&p).unwrap();
        let tex = torseur::latex::answer_key(&m, &torseur::simulate::question_runs(&m)).unwrap();
        let stem = p.file_stem().unwrap().to_str().unwrap();
        golden(&format!("{stem}.tex"), &tex);
    }
}

/// The key depends on the problem alone: not on what was written before it on the same
/// thread (the statement's names of basis vectors are in force while a key is written, in a
/// thread-local), nor on how its JSON is laid out, nor on a run's hash seeds. Right after the
/// key of a pendulum that names the basis of its frame 2 (u, v, w), the regulator's spec with
/// the keys of every object in reverse order (every map filled in another order) gives the
/// committed key, written by another process, byte for byte.
#[test]
fn the_answer_key_depends_on_the_problem_alone() {
    fn reversed(v: serde_json::Value) -> serde_json::Value {
        use serde_json::Value;
        match v {
            Value::Object(o) => {
                Value::Object(o.into_iter().rev().map(|(k, x)| (k, reversed(x))).collect())
            }
            Value::Array(a) => Value::Array(a.into_iter().map(reversed).collect()),
            x => x,
        }
    }
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let named =
        torseur::spec::load(root.join("tests/specs/pendule_support_oscillant.json")).unwrap();
    let before = super::printed::course(
        &torseur::latex::answer_key(&named, &torseur::simulate::question_runs(&named)).unwrap(),
    );
    assert!(before.contains("\\vec{u}"), "the pendulum's key names x2 u");
    let path = "derivations/regulateur_centrifuge.json";
    let text = std::fs::read_to_string(root.join(path)).unwrap();
    let spec: serde_json::Value = serde_json::from_str(&text).unwrap();
    let first = |v: &serde_json::Value| v.as_object().unwrap().keys().next().cloned();
    let turned = reversed(spec.clone());
    assert_ne!(first(&turned), first(&spec), "the keys are turned round");
    let m = torseur::spec::from_str(&serde_json::to_string_pretty(&turned).unwrap()).unwrap();
    let key = torseur::latex::answer_key(&m, &torseur::simulate::question_runs(&m)).unwrap();
    let golden = std::fs::read_to_string(root.join("latex/regulateur_centrifuge.tex")).unwrap();
    super::golden::assert_same_text("latex/regulateur_centrifuge.tex", &golden, &key);
}

#[test]
fn the_key_shows_the_course_notation() {
    let m = regulator();
    let tex = super::printed::course(
        &torseur::latex::answer_key(&m, &torseur::simulate::question_runs(&m)).unwrap(),
    );
    for needle in [
        "\\overrightarrow{\\delta(O_{2},2/0)}",
        "\\left\\{\\mathcal{D}(2/0)\\right\\}_{O_{2}}",
        "\\dot{\\theta}_{1}",
        "\\ddot{\\theta}_{2}",
        "\\vec{x}_{2}",
        "\\mathcal{B}_{2}",
        "\\mathcal{R}_{0}",
        "\\cos\\theta_{2}",
        "L_{1}",
        "A_{2}",
        "Théorème de Huygens",
        // The method, applied to the objects, and the structure of a corrigé.
        "$O_{1}$ est un point de $S_{1}$ fixe dans $\\mathcal{R}_{0}$",
        "Composition des vitesses de rotation",
        "Bilan des actions mécaniques extérieures à $E$",
        "(question 3)",
        "\\TResultat{\n",
        "Hypothèses du modèle.} Le référentiel $\\mathcal{R}_{0}$ est galiléen",
        "On se place sous l'hypothèse H2.",
    ] {
        assert!(tex.contains(needle), "missing {needle}");
    }
}

#[test]
fn spec_text_cannot_inject_latex() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/regulateur_centrifuge.json"
    ))
    .unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    // Outside `$…$`, every special character is printed as text.
    v["title"] = "\\input{/etc/passwd} \\write18{rm -rf /} }{".into();
    v["hypotheses"][0]["text"] = "\\immediate\\write18{id} % \\$".into();
    // Inside, anything off the whitelist refuses the spec when it is loaded.
    let mut bad = v.clone();
    bad["hypotheses"][0]["text"] = "$\\immediate\\write18{id}$ %".into();
    let e = torseur::spec::from_str(&bad.to_string()).unwrap_err();
    assert!(e.to_string().contains("hypotheses[0].text"), "{e}");
    let mut bad = v.clone();
    bad["title"] = "$\\input{/etc/passwd}$".into();
    let e = torseur::spec::from_str(&bad.to_string()).unwrap_err();
    assert!(e.to_string().contains("at title"), "{e}");
    assert!(e.to_string().contains("`\\input` is not allowed"), "{e}");
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    let tex = torseur::latex::answer_key(&m, &torseur::simulate::question_runs(&m)).unwrap();
    assert!(!tex.contains("\\input{"));
    assert!(!tex.contains("\\write18"));
    assert!(!tex.contains("\\immediate"));
    assert!(tex.contains("\\textbackslash{}input\\{/etc/passwd\\}"));
    // Braces stay balanced.
    let depth = tex.chars().fold(0i64, |d, c| match c {
        '{' => d + 1,
        '}' => d - 1,
        _ => d,
    });
    let escaped = tex.matches("\\{").count() as i64 - tex.matches("\\}").count() as i64;
    assert_eq!(depth, escaped);
}

/// The top's equations in ψ and φ are first integrals in disguise; the key says so, and the
/// conserved quantities are the textbook's, derived by hand: the momentum about the spin axis
/// C (ψ̇ cos θ + φ̇) (Euler's third equation with no torque about z2), and the momentum about
/// the vertical σ(O)·z0 = (A + m h²) ψ̇ sin²θ + C cos θ (ψ̇ cos θ + φ̇). The pendulum on a cart,
/// whose equations hold gravity and a push, has none.
#[test]
fn first_integrals_are_stated_with_the_textbook_quantities() {
    let m = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/toupie.json"
    ))
    .unwrap();
    let key = torseur::latex::answer_key_document(
        &m,
        torseur::latex::VectorStyle::Sum,
        &torseur::simulate::question_runs(&m),
    )
    .unwrap();
    let found = |id: &str| {
        key.inline
            .iter()
            .find(|i| i.what == format!("first integral of {id}"))
            .map(|i| match &i.value {
                torseur::derivation::Value::Scalar(e) => e.clone(),
                _ => panic!("a scalar"),
            })
    };
    let spin = m.reg().parse("C*(dot(psi)*cos(theta) + dot(phi))").unwrap();
    assert_eq!(found("eom(phi)"), Some(spin));
    let vertical = m
        .reg()
        .parse("(A + m*h^2)*dot(psi)*sin(theta)^2 + C*cos(theta)*(dot(psi)*cos(theta) + dot(phi))")
        .unwrap();
    assert_eq!(found("eom(psi)"), Some(vertical));
    assert!(key.tex.contains("Intégrale première :"));
    let cart = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/pendule_sur_chariot.json"
    ))
    .unwrap();
    let key = torseur::latex::answer_key_document(
        &cart,
        torseur::latex::VectorStyle::Sum,
        &torseur::simulate::question_runs(&cart),
    )
    .unwrap();
    assert!(!key.tex.contains("Intégrale première"));
}

/// A kinetic energy is written as a sum of squares when one completes: the top's
/// ½ (A + m h²)(θ̇² + ψ̇² sin²θ) + ½ C (ψ̇ cos θ + φ̇)², the textbook form (its value is the
/// engine's, as every printed form; here the shape is what is checked).
#[test]
fn the_tops_kinetic_energy_is_written_as_squares() {
    let m = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/toupie.json"
    ))
    .unwrap();
    let q = torseur::quantity::Quantity::parse("Ec(3/0)").unwrap();
    let d = torseur::derivation::derive_values(&m, &[q]).unwrap();
    let e = d[0].value.exprs()[0].clone();
    assert_eq!(
        e.presentation().to_string(),
        "1/2*(A + m*h^2)*(dot(psi)^2*sin(theta)^2 + dot(theta)^2) + 1/2*C*(dot(psi)*cos(theta) + dot(phi))^2"
    );
}

/// `derive`'s outputs are pinned for every spec of the library: the text (the values by the
/// fast route, as the CLI prints them without `--json`) and the JSON (the derivations with
/// their steps, as `--json` writes them). Both routes give the same values, exactly.
#[test]
fn every_derive_output_matches_its_golden_files() {
    let specs = specs_in(&["derivations"]);
    assert!(specs.len() >= 12);
    for p in specs {
        let m = torseur::spec::load(&p).unwrap();
        let stem = p.file_stem().unwrap().to_str().unwrap();
        let fast = torseur::derivation::derive_values(&m, m.quantities()).unwrap();
        let full: Vec<_> = m
            .quantities()
            .iter()
            .map(|q| torseur::derivation::derive(&m, q).unwrap())
            .collect();
        for (a, b) in fast.iter().zip(&full) {
            assert_eq!(
                a.value.exprs(),
                b.value.exprs(),
                "{stem}: {} by the fast route and with steps",
                a.quantity
            );
        }
        let text = torseur::output::derive_text(&m, &fast);
        assert_eq!(
            text,
            torseur::output::derive_text(&m, &full),
            "{stem}: the fast route and the derivation with steps print the same"
        );
        golden_in("tests/golden/derive", &format!("{stem}.txt"), &text);
        let json =
            serde_json::to_string_pretty(&torseur::output::derive_json(&m, &full)).unwrap() + "\n";
        golden_in("tests/golden/derive", &format!("{stem}.json"), &json);
    }
}

/// A value cited for a later step is cited alone, without what it was derived from: the top's
/// δ(O,3/0) is d/dt σ(O,3/0) in R0 (Bour with Ω(2/0)), so its derivation cites σ(O,3/0) of
/// question 2 and not I_O(3), which σ already holds; each projection of δ cites δ alone.
#[test]
fn a_citation_names_the_latest_value_of_each_solid_only() {
    let m = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/toupie.json"
    ))
    .unwrap();
    let tex = super::printed::course(
        &torseur::latex::answer_key(&m, &torseur::simulate::question_runs(&m)).unwrap(),
    );
    let citations: Vec<&str> = tex
        .lines()
        .filter(|l| l.starts_with("On reprend "))
        .collect();
    assert!(
        citations.contains(&"On reprend $\\overrightarrow{\\sigma(O,3/0)}$ (question 2)."),
        "{citations:#?}"
    );
    assert_eq!(
        citations
            .iter()
            .filter(|l| **l == "On reprend $\\overrightarrow{\\delta(O,3/0)}$ (ci-dessus).")
            .count(),
        2,
        "{citations:#?}"
    );
    assert!(
        !citations
            .iter()
            .any(|l| l.contains("\\sigma(O,3/0)") && l.contains("I_{O}(3)")),
        "{citations:#?}"
    );
}

/// The composition of rotation vectors a key states (« Ω(2/1) = Ω(2/0) + Ω(0/1) ») is an
/// identity: read back from the LaTeX, the sum of the named terms, each derived on its own, is
/// the left side, exactly. A wrong chain of frames (a missing or reversed term) fails.
#[test]
fn every_stated_composition_of_rotations_holds() {
    use torseur::derivation::{Value, derive_values};
    use torseur::quantity::Quantity;
    let omegas = |s: &str| -> Vec<String> {
        s.split("\\overrightarrow{\\Omega(")
            .skip(1)
            .map(|t| t[..t.find(")}").unwrap()].to_string())
            .collect()
    };
    let mut checked = 0;
    for p in specs_in(&["derivations"]) {
        let m = torseur::spec::load(&p).unwrap();
        let tex = super::printed::course(
            &torseur::latex::answer_key(&m, &torseur::simulate::question_runs(&m)).unwrap(),
        );
        for line in tex
            .lines()
            .filter(|l| l.starts_with("Composition des vitesses de rotation, $"))
        {
            let names = omegas(line);
            assert!(names.len() >= 3, "{line}");
            let qs: Vec<Quantity> = names
                .iter()
                .map(|n| Quantity::parse(&format!("Omega({n}) in B0")).unwrap())
                .collect();
            let vs: Vec<[Expr; 3]> = derive_values(&m, &qs)
                .unwrap()
                .into_iter()
                .map(|d| match d.value {
                    Value::Vector { components, .. } => components,
                    other => panic!("{other:?}"),
                })
                .collect();
            for k in 0..3 {
                let sum = vs[1..].iter().fold(m.reg().zero(), |acc, v| &acc + &v[k]);
                assert_eq!(sum, vs[0][k], "{}: {line}", p.display());
            }
            checked += 1;
        }
    }
    assert!(checked >= 4, "{checked} compositions");
}

/// The public writer of a value names the basis vectors as the statement does, like the key:
/// the support-pendulum's B2 is (u, v, w) and its ground's (x, y, z), so V(G,2/1) in B2 is
/// written along \vec{u}, \vec{v}, never \vec{x}_{2}; the graph of links says its axis z.
#[test]
fn a_value_written_alone_uses_the_statements_vector_names() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let m = torseur::spec::load(root.join("tests/specs/pendule_support_oscillant.json")).unwrap();
    let q = torseur::quantity::Quantity::parse("V(G,2/1) in B2").unwrap();
    let d = torseur::derivation::derive(&m, &q).unwrap();
    let tex = torseur::latex::value(&m, "V", &d.value);
    assert!(
        tex.contains("\\vec{v}") || tex.contains("\\vec{u}"),
        "{tex}"
    );
    assert!(
        !tex.contains("\\vec{x}_{2}") && !tex.contains("\\vec{y}_{2}"),
        "{tex}"
    );
    let graph = torseur::latex::link_graph(&m);
    assert!(
        graph.contains("\\vec{z})") && !graph.contains("\\vec{z}_{0}"),
        "{graph}"
    );
}

/// The answer key draws the runs it is handed and runs nothing itself: a failed run given to
/// it is the key's error (naming its scenario), and no run at all for a question that shows
/// a simulation is refused.
#[test]
fn the_key_draws_the_runs_it_is_given_and_runs_none() {
    use torseur::simulate::{QuestionRuns, SimulateError, Simulated};
    let m = regulator();
    let shown = (m.statement().questions.iter())
        .position(|q| q.simulation.is_some())
        .expect("the regulator shows a simulation");
    let scenario = m.statement().questions[shown]
        .simulation
        .as_ref()
        .unwrap()
        .scenarios[0]
        .clone();
    let none = || Simulated {
        runs: Vec::new(),
        figure: torseur::simulate::question_figure(&[], &[]),
    };
    let mut runs: Vec<QuestionRuns> = (m.statement().questions.iter())
        .map(|_| Ok(none()))
        .collect();
    runs[shown] = Err((
        scenario.clone(),
        SimulateError::Scenario("given failure".into()),
    ));
    let e = torseur::latex::answer_key(&m, &runs)
        .unwrap_err()
        .to_string();
    assert!(e.contains(&scenario) && e.contains("given failure"), "{e}");
    let e = torseur::latex::answer_key(&m, &runs[..shown])
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("the runs of its simulation were not given"),
        "{e}"
    );
}
