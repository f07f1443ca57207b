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

/// Names live where the notation puts them (issue 15, item 8): a point B and the inertia
/// moment B of the same problem, as a corrigé writes them.
#[test]
fn a_point_may_be_named_like_a_parameter() {
    let text = std::fs::read_to_string("derivations/rotor_vitesse_imposee.json").unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["parameters"]
        .as_array_mut()
        .unwrap()
        .push(serde_json::json!({"name": "b", "unit": "m"}));
    v["points"] = serde_json::json!([{"name": "B", "position": "b*y2"}]);
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    // Ω(2/0) ∧ OB with Ω = ω (sin α y2 + cos α z2) and OB = b y2; Huygens at B keeps the
    // parameter B on y2.
    torseur::assert_equivalent!(m, "V(B,2/0) in B2", "-b*omega*cos(alpha)*x2");
    torseur::assert_equivalent!(
        m,
        "I(B,2)",
        "[[A + m*b^2, -F, -E], [-F, B, -D], [-E, -D, C + m*b^2]]"
    );
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

fn message_of(e: &SpecError) -> String {
    match e {
        SpecError::Invalid { message, .. } | SpecError::Json { message, .. } => message.clone(),
        SpecError::Io { message, .. } => message.clone(),
    }
}

#[test]
fn a_coordinate_named_like_a_basis_vector_is_refused_at_its_name() {
    // sympy's mass–spring–damper names its coordinate x0: accepted, `x0*x0` then failed with
    // « a basis vector cannot be raised to a power ». Refused at the name instead.
    let spec = serde_json::json!({"title": "t",
        "parameters": [{"name": "m"}],
        "coordinates": [{"name": "x0", "kind": "length"}],
        "frames": [{"name": "1", "parent": "0", "origin": "P"}],
        "points": [{"name": "P", "from": "O0", "position": "x0*x0"}],
        "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "P"}]});
    let e = refused(spec.clone());
    assert_eq!(path_of(&e), "coordinates[0].name", "{e}");
    assert!(message_of(&e).contains("basis vector x of frame 0"), "{e}");
    // The same for a parameter (frame 1 exists) and an action's unknown (frame 2 exists).
    let mut v = base();
    v["parameters"][0]["name"] = "y1".into();
    let e = refused(v);
    assert_eq!(path_of(&e), "parameters[0].name", "{e}");
    assert!(message_of(&e).contains("basis vector y of frame 1"), "{e}");
    let mut v = base();
    v["actions"][0]["unknowns"][0] = "z2".into();
    v["actions"][0]["moment"] = "z2*z0".into();
    let e = refused(v);
    assert_eq!(path_of(&e), "actions[0].unknowns[0]", "{e}");
    // x3 names no basis vector here (no frame 3): still a valid coordinate name.
    let mut ok = spec;
    ok["coordinates"][0]["name"] = "x3".into();
    ok["points"][0]["position"] = "x3*x0".into();
    from_str(&ok.to_string()).expect("x3 is a fine name");
}

/// A four-bar linkage: crank 1 (pivot O), coupler 2 (pivot A), rocker 3 (pivot B), and the
/// pivot C between 3 and the ground closes the loop.
fn four_bar() -> serde_json::Value {
    serde_json::json!({"title": "quadrilatère articulé",
        "parameters": [{"name": "a"}, {"name": "b"}, {"name": "c"}, {"name": "d"},
                       {"name": "m"}, {"name": "J"}],
        "coordinates": [{"name": "theta1", "kind": "angle"}, {"name": "theta2", "kind": "angle"},
                        {"name": "theta3", "kind": "angle"}],
        "frames": [
            {"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "theta1"}},
            {"name": "2", "parent": "1", "rotation": {"axis": "z", "angle": "theta2"}, "origin": "A"},
            {"name": "3", "parent": "2", "rotation": {"axis": "z", "angle": "theta3"}, "origin": "B"}],
        "points": [{"name": "A", "from": "O0", "position": "a*x1"},
                   {"name": "B", "from": "A", "position": "b*x2"},
                   {"name": "C", "from": "B", "position": "c*x3"}],
        "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "O0"},
                   {"name": "2", "frame": "2", "mass": "m", "centre": "A"},
                   {"name": "3", "frame": "3", "mass": "m", "centre": "B"}],
        "links": [
            {"name": "01", "kind": "pivot", "between": ["0", "1"], "point": "O0", "axis": "z0"},
            {"name": "12", "kind": "pivot", "between": ["1", "2"], "point": "A", "axis": "z1"},
            {"name": "23", "kind": "pivot", "between": ["2", "3"], "point": "B", "axis": "z2"},
            {"name": "03", "kind": "pivot", "between": ["0", "3"], "point": "C", "axis": "z0"}],
        "actions": [{"name": "moteur", "from": "0", "on": "1", "point": "O0",
                     "moment": "C_m*z0", "unknowns": ["C_m"]}],
        "pfd": [{"isolate": "1", "theorem": "moment", "point": "O0", "on": "z0"}]})
}

#[test]
fn a_four_bar_linkage_is_refused_as_a_closed_kinematic_loop() {
    // Was refused only indirectly (« the equation of motion still contains the unknown X30 »).
    let e = refused(four_bar());
    assert_eq!(path_of(&e), "links[3].between", "{e}");
    let msg = message_of(&e);
    assert!(msg.contains("closes a kinematic loop"), "{msg}");
    assert!(msg.contains("links 01, 12, 23"), "{msg}");
    assert!(msg.contains("not supported yet"), "{msg}");
    // Without the closing link, the open chain is accepted.
    let mut open = four_bar();
    open["links"].as_array_mut().unwrap().pop();
    from_str(&open.to_string()).expect("an open chain is a tree of links");
    // Two links in parallel between the same solids (two bearings of a shaft) are one
    // connection, not a loop.
    let mut v = base();
    v["links"].as_array_mut().unwrap().push(serde_json::json!(
        {"name": "01b", "kind": "annular", "between": ["0", "1"], "point": "O1", "axis": "z0"}));
    from_str(&v.to_string()).expect("two bearings between 0 and 1");
}

#[test]
fn the_inertia_basis_message_has_no_run_of_spaces() {
    // A string literal broken without `\` kept its indentation: « relative to the solid's
    // frame ␣␣␣␣␣…2 ».
    let mut v = base();
    v["solids"][1]["inertia"]["basis"] = "1".into();
    let e = refused(v);
    assert_eq!(path_of(&e), "solids[1].inertia.basis", "{e}");
    let msg = message_of(&e);
    assert_eq!(
        msg,
        "the inertia matrix is given in basis 1 which turns relative to the solid's frame 2: \
         give it in the solid's basis (or in a basis where it is of revolution about the \
         relative rotation axis)"
    );
    assert!(!msg.contains("  "), "{msg}");
}

#[test]
fn a_rotation_angle_that_is_not_plus_or_minus_one_coordinate_plus_a_constant_is_refused() {
    let angle_of = |a: &str| {
        let mut v = base();
        v["frames"][1]["rotation"]["angle"] = a.into();
        refused(v)
    };
    // A constant whose cos and sin are not exact rationals: declare it as a parameter.
    let e = angle_of("theta2 + pi/6");
    assert_eq!(path_of(&e), "frames[1].rotation.angle", "{e}");
    assert!(message_of(&e).contains("multiple of pi/2"), "{e}");
    assert!(message_of(&e).contains("\"kind\": \"angle\""), "{e}");
    let e = angle_of("theta1 + theta2");
    assert!(message_of(&e).contains("several coordinates"), "{e}");
    let e = angle_of("2*theta2");
    assert!(message_of(&e).contains("coefficient 1 or -1"), "{e}");
    let e = angle_of("pi/2");
    assert!(message_of(&e).contains("constant multiple of pi/2"), "{e}");
    // A plain parameter is not an angle; a length coordinate neither.
    let e = angle_of("theta2 + L1");
    assert!(message_of(&e).contains("`L1` is not an angle"), "{e}");
    let e = angle_of("beta");
    assert!(message_of(&e).contains("unknown name `beta`"), "{e}");
}

/// Free texts accept `$…$` formulas with the whitelisted macros (issue 12, item 3).
#[test]
fn free_texts_accept_whitelisted_formulas() {
    let mut v = base();
    v["title"] = "Régulateur : $\\mathcal{R}_0$ galiléen".into();
    v["description"] = "Le rotor $S_1$ tourne de $\\theta_1$ autour de $(O_1, \\vec{z}_0)$ ; \
                        $\\overrightarrow{O_1G_2} \\wedge m_2 \\vec{\\Gamma}$, 100 % & \\$"
        .into();
    v["questions"][2]["statement"] =
        "Calculer $\\left\\{ \\mathcal{D}(2/0) \\right\\}_{O_2}$ et $\\dot{\\theta}_1 \\leq \
         \\frac{\\pi}{2}$, $\\sin\\theta_2 \\cdot \\cos\\theta_2 \\approx \\ell^{2}$."
            .into();
    v["hypotheses"][0]["text"] = "$D_2 \\neq 0$, $\\ddot{\\theta}_1 = 0$".into();
    v["actions"][0]["label"] = "le moteur $M$".into();
    v["scenarios"][0]["label"] = "$f = 0$".into();
    let m = from_str(&v.to_string()).unwrap();
    assert_eq!(m.action_label("moteur").as_deref(), Some("le moteur $M$"));
}

/// Anything outside the whitelist in a formula refuses the spec, naming the text's path.
#[test]
fn forbidden_latex_in_free_texts_is_refused_with_its_path() {
    let cases: [(&str, &str, &str); 14] = [
        ("/title", "$\\input{/etc/passwd}$", "`\\input`"),
        ("/description", "$\\write18{id}$", "`\\write`"),
        ("/questions/2/statement", "$\\def\\x{1}$", "`\\def`"),
        ("/questions/1/answer", "$\\catcode 36=11$", "`\\catcode`"),
        ("/questions/0/title", "$\\immediate$", "`\\immediate`"),
        (
            "/hypotheses/0/text",
            "$\\csname relax\\endcsname$",
            "`\\csname`",
        ),
        ("/parameters/0/description", "$\\textbf{G}_1$", "`\\textbf`"),
        ("/coordinates/0/description", "$\\theta_{1$", "not closed"),
        (
            "/scenarios/0/description",
            "de 0 à $2000 tr/min",
            "never closed",
        ),
        ("/scenarios/0/label", "$x}$", "closes no"),
        ("/actions/0/label", "$a % b$", "`%`"),
        ("/links/0/label", "$$x$$", "empty formula"),
        (
            "/questions/0/equations/0/reason",
            "$\\unknown$",
            "`\\unknown`",
        ),
        ("/questions/3/statement", "$x^2^3$", "double superscript"),
    ];
    for (pointer, text, what) in cases {
        let mut v = base();
        v["questions"][0]["equations"] = serde_json::json!([
            {"lhs": "Cm", "quantity": "delta(O1,E/0).z0", "reason": "ok"}
        ]);
        let (parent, key) = pointer.rsplit_once('/').unwrap();
        let target = if parent.is_empty() {
            &mut v
        } else {
            v.pointer_mut(parent).unwrap_or_else(|| panic!("{pointer}"))
        };
        target[key] = text.into();
        let e = refused(v);
        let path =
            pointer
                .trim_start_matches('/')
                .split('/')
                .fold(String::new(), |mut acc, part| {
                    if part.chars().all(|c| c.is_ascii_digit()) {
                        acc.push_str(&format!("[{part}]"));
                    } else {
                        if !acc.is_empty() {
                            acc.push('.');
                        }
                        acc.push_str(part);
                    }
                    acc
                });
        assert_eq!(path_of(&e), path, "{text}: {e}");
        assert!(e.to_string().contains(what), "{text}: {e}");
    }
}

/// The JSON path (as errors write it, `solids[1].mass`) and the pointer of every string of a
/// spec.
fn string_leaves(
    v: &serde_json::Value,
    path: &str,
    pointer: &str,
    out: &mut Vec<(String, String)>,
) {
    match v {
        serde_json::Value::String(_) => out.push((path.to_string(), pointer.to_string())),
        serde_json::Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                string_leaves(x, &format!("{path}[{i}]"), &format!("{pointer}/{i}"), out);
            }
        }
        serde_json::Value::Object(o) => {
            for (k, x) in o {
                let p = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                string_leaves(x, &p, &format!("{pointer}/{k}"), out);
            }
        }
        _ => {}
    }
}

/// Asserts a refusal's message is short and starts with the JSON path of the value it refuses
/// (issue 14: 5000 nested parentheses got a 10 kB message quoting all of them). `what` is the
/// change made, for the failure's message.
fn assert_bounded(e: &SpecError, what: &str, limit: usize) {
    let text = e.to_string();
    assert!(
        text.len() <= limit,
        "{what}: a message of {} bytes: {}",
        text.len(),
        torseur::excerpt::excerpt(&text)
    );
    let path = path_of(e);
    assert!(!path.is_empty(), "{what}: {text}");
    let named = torseur::excerpt::excerpt(&path);
    assert!(text.starts_with(&format!("at {named}")), "{what}: {text}");
}

/// `m1` in 5000 nested parentheses.
fn nested() -> String {
    format!("{}m1{}", "(".repeat(5000), ")".repeat(5000))
}

#[test]
fn five_thousand_nested_parentheses_get_a_short_message_naming_the_path() {
    let mut v = base();
    v["solids"][0]["mass"] = nested().into();
    let e = refused(v);
    assert_eq!(path_of(&e), "solids[0].mass");
    assert_bounded(&e, "5000 parentheses", 400);
    assert!(e.to_string().contains("nested deeper than 64"), "{e}");
    // The same through the expression parser alone, and the quantity notation.
    let m = super::regulator();
    let long = nested();
    assert!(m.reg().parse(&long).unwrap_err().to_string().len() < 200);
    let q = format!("delta({},2/0)", "O".repeat(10_000));
    let e = torseur::quantity::Quantity::parse(&q).unwrap_err();
    assert!(e.to_string().len() < 200, "{e}");
}

/// Whatever a string of the regulator's spec holds (10 000 characters: nested parentheses, one
/// letter, accented letters, many short quotes), and whatever key is added, the message of a
/// refusal stays within [`torseur::excerpt::MAX_MESSAGE`] bytes and starts with the path of
/// the value refused (that string, or a reference to what it named).
#[test]
fn every_error_message_is_bounded_and_names_its_path() {
    let base = base();
    let mut leaves = Vec::new();
    string_leaves(&base, "", "", &mut leaves);
    assert!(leaves.len() > 200, "{} strings", leaves.len());
    let huge = [
        nested(),
        "x".repeat(10_000),
        "é".repeat(5000),
        "`a` \"b\" ".repeat(1250),
    ];
    let limit = torseur::excerpt::MAX_MESSAGE;
    let mut refusals = 0;
    for (path, pointer) in &leaves {
        for h in &huge {
            let mut v = base.clone();
            *v.pointer_mut(pointer).unwrap() = h.as_str().into();
            if let Err(e) = from_str(&v.to_string()) {
                assert_bounded(&e, path, limit);
                refusals += 1;
            }
        }
    }
    assert!(refusals > 500, "only {refusals} refusals");
    // Keys: an unknown field and a set named by 10 000 characters; a number given as text.
    for h in &huge {
        let mut v = base.clone();
        v[h.as_str()] = 1.into();
        assert_bounded(&refused(v), "", limit);
        let mut v = base.clone();
        v["sets"][h.as_str()] = serde_json::json!(["1"]);
        assert_bounded(&refused(v), "sets", limit);
        let mut v = base.clone();
        v["scenarios"][0]["duration"] = h.as_str().into();
        assert_bounded(&refused(v), "scenarios[0].duration", limit);
    }
}

/// Found by a new user's try (session 6): the line and column were printed twice, a JSON
/// syntax error was placed « at ? », and a bad operator quoted symbolica's caret drawing over
/// three lines. Each message is now one line, with the place once.
#[test]
fn a_json_or_syntax_error_says_its_place_once_on_one_line() {
    let mut v = base();
    v["solids"][1].as_object_mut().unwrap().remove("name");
    let missing = refused(v).to_string();
    assert_eq!(missing.matches("line").count(), 1, "{missing}");
    assert!(missing.contains("missing field `name`"), "{missing}");
    // A frame left out (a carried solid takes its carrier's) is placed at its solid.
    let mut v = base();
    v["solids"][1].as_object_mut().unwrap().remove("frame");
    let missing = refused(v).to_string();
    assert_eq!(missing.matches("line").count(), 1, "{missing}");
    assert!(missing.starts_with("at solids[1].frame (line"), "{missing}");
    assert!(missing.contains("\"carried_by\": \"1\""), "{missing}");
    // A mass left out (it may be, for a body of negligible mass) is placed at its solid.
    let mut v = base();
    v["solids"][1].as_object_mut().unwrap().remove("mass");
    let missing = refused(v).to_string();
    assert_eq!(missing.matches("line").count(), 1, "{missing}");
    assert!(missing.starts_with("at solids[1].mass (line"), "{missing}");
    assert!(missing.contains("\"massless\": true"), "{missing}");

    let text = base().to_string();
    let broken = text.replacen("\"ground\"", "\"ground\" \"", 1);
    let syntax = from_str(&broken).unwrap_err().to_string();
    assert!(
        syntax.starts_with("in the JSON text (line 1, column"),
        "{syntax}"
    );
    assert_eq!(syntax.matches("line").count(), 1, "{syntax}");

    let mut v = base();
    v["points"][0]["position"] = serde_json::json!("-L1**x1");
    let op = refused(v).to_string();
    assert!(
        !op.contains('\n') && op.contains("missing left-hand side"),
        "{op}"
    );
}

/// The forced oscillator, whose exciter writes the time: `F0*cos(Omega*t)*x0`.
fn forced() -> serde_json::Value {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/masse_ressort_forcee.json"
    ))
    .unwrap();
    serde_json::from_str(&text).unwrap()
}

#[test]
fn the_time_enters_only_as_a_phase_of_a_parameter() {
    for (force, why) in [
        ("F0*t*x0", "only as a phase"),
        ("F0*cos(t)*x0", "only as a phase"),
        ("F0*cos(x*t)*x0", "only as a phase"),
        ("F0*cos(Omega*t/2)*x0", "integer multiples"),
        ("F0*cos(Omega*t^2)*x0", "only as a phase"),
        ("F0*cos(Omega*k*t)*x0", "only as a phase"),
    ] {
        let mut v = forced();
        v["actions"][0]["resultant"] = force.into();
        let e = refused(v);
        assert_eq!(path_of(&e), "actions[0].resultant", "{force}: {e}");
        assert!(e.to_string().contains(why), "{force}: {e}");
    }
    // An imposed rate is a constant: the time is refused there.
    let mut v = forced();
    v["coordinates"][0]["rate"] = "Omega*cos(Omega*t)".into();
    let e = refused(v);
    assert!(e.to_string().contains("constant"), "{e}");
    // Twice the phase, and a phase with an angle, are angles.
    let mut v = forced();
    v["actions"][0]["resultant"] = "F0*sin(2*Omega*t)*x0".into();
    assert!(from_str(&v.to_string()).is_ok());
}

#[test]
fn the_energy_theorem_takes_no_point_and_no_vector() {
    // pfd[1] of the regulator, the moment at O2 on x2, made an energy theorem.
    let mut v = base();
    v["pfd"][1]["theorem"] = "energy".into();
    let e = refused(v.clone());
    assert_eq!(path_of(&e), "pfd[1].point", "{e}");
    assert!(e.to_string().contains("written at no point"), "{e}");
    v["pfd"][1].as_object_mut().unwrap().remove("point");
    let e = refused(v.clone());
    assert_eq!(path_of(&e), "pfd[1].on", "{e}");
    assert!(e.to_string().contains("projected on no vector"), "{e}");
    v["pfd"][1].as_object_mut().unwrap().remove("on");
    assert!(from_str(&v.to_string()).is_ok());
    // A moment theorem without its vector.
    let mut v = base();
    v["pfd"][0].as_object_mut().unwrap().remove("on");
    let e = refused(v);
    assert_eq!(path_of(&e), "pfd[0].on", "{e}");
}

/// The gyroscope in a massless Cardan suspension, as JSON to edit.
fn gyroscope() -> serde_json::Value {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/gyroscope_cardan.json"
    ))
    .unwrap();
    serde_json::from_str(&text).unwrap()
}

/// A body of negligible mass is `"massless": true` (or a mass of 0); what contradicts it, and
/// a solid that gives neither its mass nor `massless`, is refused at its place, saying how
/// to write it.
#[test]
fn a_massless_body_is_declared_without_mass_inertia_or_symmetries() {
    type Edit<'a> = &'a dyn Fn(&mut serde_json::Value);
    let cases: [(Edit, &str, &str); 7] = [
        (
            &|v| v["solids"][1]["massless"] = false.into(),
            "solids[1].mass",
            "\"massless\": true",
        ),
        (
            &|v| v["solids"][1]["mass"] = "m".into(),
            "solids[1].mass",
            "remove `mass`",
        ),
        (
            &|v| v["solids"][1]["inertia"] = v["solids"][2]["inertia"].clone(),
            "solids[1].inertia",
            "no inertia operator",
        ),
        (
            &|v| {
                v["solids"][1]["symmetries"] =
                    serde_json::json!([{"kind": "revolution", "axis": "z2"}])
            },
            "solids[1].symmetries[0]",
            "no symmetry",
        ),
        (
            &|v| {
                v["solids"][2]["mass"] = "0".into();
            },
            "solids[2].inertia",
            "a mass of 0",
        ),
        (
            &|v| {
                v["solids"][2].as_object_mut().unwrap().remove("centre");
            },
            "solids[2].centre",
            "centre of inertia",
        ),
        (
            &|v| {
                v["solids"].as_array_mut().unwrap().remove(1);
                v["sets"] = serde_json::json!({"E": ["3"], "T": ["1", "3"]});
            },
            "links[1].between[1]",
            "{\"name\": \"2\", \"frame\": \"2\", \"massless\": true}",
        ),
    ];
    for (edit, path, says) in cases {
        let mut v = gyroscope();
        edit(&mut v);
        let e = refused(v);
        assert_eq!(path_of(&e), path, "{e}");
        assert!(e.to_string().contains(says), "{e}");
    }
    // A mass of 0 (with or without `massless`) is a body of negligible mass, like `massless`.
    for mass in ["0", "0*m"] {
        let mut v = gyroscope();
        v["solids"][0]["mass"] = mass.into();
        v["solids"][1]["massless"] = false.into();
        v["solids"][1]["mass"] = mass.into();
        let m = from_str(&v.to_string()).unwrap();
        assert!(m.bodies()[0].massless && m.bodies()[1].massless);
        assert!(m.bodies()[0].mass.is_zero());
    }
    // Isolating a frame that is not a solid says how to declare it.
    let mut v = gyroscope();
    v["pfd"][0]["isolate"] = "2".into();
    v["solids"].as_array_mut().unwrap().remove(1);
    v["sets"] = serde_json::json!({"E": ["3"], "T": ["1", "3"]});
    v["links"].as_array_mut().unwrap().truncate(1);
    v["actions"] = serde_json::json!([]);
    let e = refused(v);
    assert_eq!(path_of(&e), "pfd[0].isolate", "{e}");
    assert!(e.to_string().contains("\"massless\": true"), "{e}");
}
