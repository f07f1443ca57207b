//! The answer key is pinned by a committed golden file; re-approve a reviewed change with
//! `TORSEUR_BLESS=1 cargo test --test engine latex`.

use super::*;

fn golden(name: &str, actual: &str) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("latex")
        .join(name);
    if std::env::var_os("TORSEUR_BLESS").is_some() {
        std::fs::write(&path, actual).unwrap();
        return;
    }
    let expected = std::fs::read_to_string(&path)
        .unwrap_or_else(|_| panic!("{} missing: run with TORSEUR_BLESS=1", path.display()));
    if expected != actual {
        let (e, a): (Vec<&str>, Vec<&str>) = (expected.lines().collect(), actual.lines().collect());
        let first = e
            .iter()
            .zip(&a)
            .position(|(x, y)| x != y)
            .unwrap_or(e.len().min(a.len()));
        panic!(
            "{name} differs from the golden file at line {}:\n- {}\n+ {}\n(re-approve a reviewed change with TORSEUR_BLESS=1)",
            first + 1,
            e.get(first).unwrap_or(&"<end>"),
            a.get(first).unwrap_or(&"<end>")
        );
    }
}

/// Every spec's answer key is pinned (its layout; its signs are proven in `printed`).
#[test]
fn every_answer_key_matches_its_golden_file() {
    let specs = specs_in(&["derivations"]);
    assert!(specs.len() >= 10);
    for p in specs {
        let m = torseur::spec::load(&p).unwrap();
        let tex = torseur::latex::answer_key(&m).unwrap();
        let stem = p.file_stem().unwrap().to_str().unwrap();
        golden(&format!("{stem}.tex"), &tex);
    }
}

#[test]
fn the_answer_key_is_deterministic() {
    let a = torseur::latex::answer_key(&regulator()).unwrap();
    let b = torseur::latex::answer_key(&regulator()).unwrap();
    assert_eq!(a, b);
}

#[test]
fn the_key_shows_the_course_notation() {
    let tex = torseur::latex::answer_key(&regulator()).unwrap();
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
        "D'après la question 3",
        "\\begin{empheq}[box=\\fbox]{align*}",
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
    let tex = torseur::latex::answer_key(&m).unwrap();
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
