//! Bad specs are refused with a message naming the place.

use torseur::spec::{SpecError, from_str};

fn base() -> serde_json::Value {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/regulateur_centrifuge.json"
    ))
    .unwrap();
    serde_json::from_str(&text).unwrap()
}

fn refused(v: serde_json::Value) -> SpecError {
    match from_str(&v.to_string()) {
        Ok(_) => panic!("accepted a bad spec"),
        Err(e) => e,
    }
}

fn path_of(e: &SpecError) -> String {
    match e {
        SpecError::Invalid { path, .. } | SpecError::Json { path, .. } => path.clone(),
        SpecError::Io { .. } => String::new(),
    }
}

#[test]
fn unknown_frame_is_named_with_its_path() {
    let mut v = base();
    v["frames"][1]["parent"] = "9".into();
    let e = refused(v);
    assert_eq!(path_of(&e), "frames[1].parent");
    assert!(e.to_string().contains("unknown frame `9`"), "{e}");
}

#[test]
fn a_cycle_of_frames_is_refused() {
    let mut v = base();
    v["frames"][0]["parent"] = "2".into();
    let e = refused(v);
    assert!(e.to_string().contains("cycle"), "{e}");
}

#[test]
fn a_non_symmetric_inertia_is_refused() {
    let mut v = base();
    v["solids"][1]["inertia"]["matrix"][0][1] = "-D2".into();
    let e = refused(v);
    assert!(path_of(&e).starts_with("solids[1].inertia.matrix"), "{e}");
    assert!(e.to_string().contains("not symmetric"), "{e}");
}

#[test]
fn unknown_point_axis_parameter_and_quantity() {
    let mut v = base();
    v["points"][3]["from"] = "Q".into();
    assert_eq!(path_of(&refused(v)), "points[3].from");
    let mut v = base();
    v["frames"][0]["rotation"]["axis"] = "w".into();
    assert_eq!(path_of(&refused(v)), "frames[0].rotation.axis");
    let mut v = base();
    v["solids"][0]["mass"] = "m9".into();
    let e = refused(v);
    assert_eq!(path_of(&e), "solids[0].mass");
    assert!(e.to_string().contains("m9"));
    let mut v = base();
    v["quantities"][0] = "delta(O7,2/0)".into();
    assert_eq!(path_of(&refused(v)), "quantities[0]");
    let mut v = base();
    v["quantities"][0] = "nabla(O2)".into();
    assert_eq!(path_of(&refused(v)), "quantities[0]");
}

#[test]
fn structural_errors_carry_line_and_column() {
    match from_str("{\"title\": \"x\",\n \"frames\": 3}") {
        Err(SpecError::Json { path, line, .. }) => {
            assert_eq!(path, "frames");
            assert_eq!(line, 2);
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        from_str("{\"title\": \"x\", \"oops\": 1}"),
        Err(SpecError::Json { .. })
    ));
    assert!(matches!(from_str(""), Err(SpecError::Json { .. })));
    let deep = "[".repeat(100_000);
    assert!(matches!(from_str(&deep), Err(SpecError::Json { .. })));
}

#[test]
fn names_that_could_inject_latex_or_operators_are_refused() {
    for bad in ["\\input{x}", "m2}", "a b", "x^2", "m-1", "_x", "21", "2D1"] {
        let mut v = base();
        v["parameters"][0]["name"] = bad.into();
        let e = refused(v);
        assert_eq!(path_of(&e), "parameters[0].name", "{bad}: {e}");
    }
    let mut v = base();
    v["points"][0]["name"] = "O\\write18".into();
    assert_eq!(path_of(&refused(v)), "points[0].name");
}

#[test]
fn duplicate_names_are_refused() {
    let mut v = base();
    v["parameters"][1]["name"] = "h1".into();
    assert!(refused(v).to_string().contains("duplicate"));
    let mut v = base();
    v["points"][1]["name"] = "O1".into();
    assert!(refused(v).to_string().contains("duplicate"));
}

#[test]
fn a_symmetry_that_contradicts_the_entries_is_refused() {
    let mut v = base();
    // A product of inertia written as an expression cannot be zeroed by a symmetry.
    v["solids"][1]["inertia"]["matrix"][0][1] = "-F2 - D2".into();
    v["solids"][1]["inertia"]["matrix"][1][0] = "-F2 - D2".into();
    let e = refused(v);
    assert!(e.to_string().contains("symmetries"), "{e}");
    assert!(path_of(&e).starts_with("hypotheses"), "{e}");
}

#[test]
fn content_errors_point_at_line_and_column_in_the_file() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/regulateur_centrifuge.json"
    ))
    .unwrap();
    let needle = "\"parent\": \"1\"";
    let at = text.find(needle).expect("frame 2's parent");
    let bad = text.replacen(needle, "\"parent\": \"9\"", 1);
    let line = text[..at].matches('\n').count() + 1;
    let column =
        text[..at].rsplit('\n').next().unwrap().chars().count() + needle.find('"').unwrap() + 11;
    match from_str(&bad) {
        Err(SpecError::Invalid { path, location, .. }) => {
            assert_eq!(path, "frames[1].parent");
            assert_eq!(
                location,
                Some((line, column)),
                "value `\"9\"` is at {line}:{column}"
            );
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn spec_expressions_of_absurd_degree_are_refused() {
    let mut v = base();
    v["points"][3]["position"] = "L2^40*y2".into();
    let e = refused(v);
    assert_eq!(path_of(&e), "points[3].position");
    assert!(e.to_string().contains("degree over 32"), "{e}");
}
