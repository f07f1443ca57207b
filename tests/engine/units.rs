//! Units and homogeneity (`src/units.rs`): unit parsing, dimensions of hand-written
//! expressions, every quantity of every spec of `derivations/` of its dimension under every
//! hypothesis, and `check` failing on an inhomogeneous spec.
//!
//! Expected dimensions are written by hand as (M, L, T) exponents from the course's
//! definitions (V = dOP/dt is L T⁻¹, δ = dσ/dt with σ = I Ω is M L² T⁻², a link's X is a force
//! …), never computed by the code under test.

use super::*;
use torseur::derivation::{Value, derive, derive_values};
use torseur::quantity::Quantity;
use torseur::spec::SpecError;
use torseur::units::{
    Dimension, DimensionProblem, Dimensions, UnitStyle, dimension, homogeneous_derivation,
    homogeneous_value,
};

/// M^a L^b T^c, written by hand.
fn d(mass: i32, length: i32, time: i32) -> Dimension {
    Dimension { mass, length, time }
}

fn spec_path(name: &str) -> String {
    format!("{}/derivations/{name}.json", env!("CARGO_MANIFEST_DIR"))
}

fn load(name: &str) -> Mechanism {
    torseur::spec::load(spec_path(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// The spec's JSON, to be edited by a test.
fn spec_json(name: &str) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(spec_path(name)).unwrap()).unwrap()
}

fn build(json: &serde_json::Value) -> Result<Mechanism, SpecError> {
    torseur::spec::from_str(&serde_json::to_string_pretty(json).unwrap())
}

/// Sets the unit of parameter `name`.
fn set_unit(json: &mut serde_json::Value, name: &str, unit: &str) {
    let p = json["parameters"]
        .as_array_mut()
        .unwrap()
        .iter_mut()
        .find(|p| p["name"] == name)
        .unwrap_or_else(|| panic!("no parameter {name}"));
    p["unit"] = serde_json::Value::String(unit.to_string());
}

#[test]
fn every_unit_of_the_library_parses_to_its_dimension() {
    // N = kg m s^-2; rad = 1.
    let cases = [
        ("kg", d(1, 0, 0)),
        ("m", d(0, 1, 0)),
        ("kg m^2", d(1, 2, 0)),
        ("m/s^2", d(0, 1, -2)),
        ("rad/s", d(0, 0, -1)),
        ("rad", d(0, 0, 0)),
        ("N", d(1, 1, -2)),
        ("N/m", d(1, 0, -2)),
        ("N s/m", d(1, 0, -1)),
        ("N m", d(1, 2, -2)),
        ("N m/rad", d(1, 2, -2)),
        ("N m s/rad", d(1, 2, -1)),
        // Beyond the library.
        ("s", d(0, 0, 1)),
        ("J", d(1, 2, -2)),
        ("W", d(1, 2, -3)),
        ("Hz", d(0, 0, -1)),
        ("Pa", d(1, -1, -2)),
        ("1", d(0, 0, 0)),
        ("1/s", d(0, 0, -1)),
        ("N*m", d(1, 2, -2)),
        ("N·m", d(1, 2, -2)),
        ("N * m", d(1, 2, -2)),
        ("kg·m²", d(1, 2, 0)),
        ("kg·m²/s", d(1, 2, -1)),
        ("kg m^-1 s^-2", d(1, -1, -2)),
        ("s⁻¹", d(0, 0, -1)),
        ("kg m/s^2", d(1, 1, -2)),
        ("  m / s  ", d(0, 1, -1)),
        ("J/kg", d(0, 2, -2)),
    ];
    for (text, want) in cases {
        assert_eq!(
            Dimension::parse(text).unwrap_or_else(|e| panic!("{text}: {e}")),
            want,
            "{text}"
        );
        assert_eq!(text.parse::<Dimension>().unwrap(), want, "{text}");
    }
}

#[test]
fn units_that_are_not_si_or_not_readable_are_refused_with_what_to_write() {
    let cases = [
        ("", "empty"),
        ("   ", "empty"),
        ("tr/min", "rad/s"),
        ("rpm", "rad/s"),
        ("mm", "in m"),
        ("g", "in kg"),
        ("deg", "in rad"),
        ("°", "in rad"),
        ("kN", "in N"),
        ("min", "in s"),
        ("Nm", "`N m`"),
        ("N m/s/rad", "one `/`"),
        ("kg/(m s^2)", "parentheses"),
        ("m2", "`m^2`"),
        ("m^", "integer power"),
        ("m^x", "integer power"),
        ("m^0", "nonzero"),
        ("m^99", "nonzero"),
        ("N *", "nothing after"),
        ("N ** m", "two multiplication"),
        ("/s", "nothing before"),
        ("m/", "nothing after"),
        ("A", "outside mechanics"),
        ("furlong", "unknown unit"),
        ("N-m", "unexpected `-`"),
        ("kg m^2.5", "unexpected `.`"),
    ];
    for (text, hint) in cases {
        let e = Dimension::parse(text)
            .err()
            .unwrap_or_else(|| panic!("`{text}` was accepted"));
        let msg = e.to_string();
        assert!(msg.contains(&format!("`{text}`")), "{msg}");
        assert!(msg.contains(hint), "`{text}`: {msg} (wanted {hint})");
    }
}

#[test]
fn a_bad_unit_is_refused_at_load_with_its_json_path() {
    let mut j = spec_json("regulateur_centrifuge");
    // parameters[3] is L2.
    assert_eq!(j["parameters"][3]["name"], "L2");
    set_unit(&mut j, "L2", "mm");
    let e = build(&j).unwrap_err();
    match &e {
        SpecError::Invalid {
            path,
            message,
            location,
        } => {
            assert_eq!(path, "parameters[3].unit");
            assert!(message.contains("`mm`"), "{message}");
            assert!(location.is_some(), "line and column of the value");
        }
        other => panic!("{other:?}"),
    }
    // A constant angle is in rad (or a pure number), nothing else.
    let mut j = spec_json("pendule_plan_incline");
    set_unit(&mut j, "alpha", "m");
    let e = build(&j).unwrap_err().to_string();
    assert!(e.contains("parameters[7].unit"), "{e}");
    assert!(e.contains("angle"), "{e}");
    set_unit(&mut j, "alpha", "1");
    build(&j).unwrap();
}

#[test]
fn dimensions_print_as_the_course_writes_units() {
    let m = UnitStyle::Mechanics;
    let cases = [
        (d(1, 1, -2), m, "N", r"\mathrm{N}"),
        (d(1, 2, -2), m, "N·m", r"\mathrm{N\cdot m}"),
        (d(1, 2, -2), UnitStyle::Energy, "J", r"\mathrm{J}"),
        (d(1, 2, -3), UnitStyle::Energy, "W", r"\mathrm{W}"),
        (d(1, 2, 0), m, "kg·m²", r"\mathrm{kg\cdot m^{2}}"),
        (d(0, 1, -1), m, "m/s", r"\mathrm{m/s}"),
        (d(0, 1, -2), m, "m/s²", r"\mathrm{m/s^{2}}"),
        (d(0, 0, -1), m, "rad/s", r"\mathrm{rad/s}"),
        (d(0, 0, -2), m, "rad/s²", r"\mathrm{rad/s^{2}}"),
        (d(1, 1, -1), m, "kg·m/s", r"\mathrm{kg\cdot m/s}"),
        (d(1, 2, -1), m, "kg·m²/s", r"\mathrm{kg\cdot m^{2}/s}"),
        (d(1, 0, 0), m, "kg", r"\mathrm{kg}"),
        (d(0, 1, 0), m, "m", r"\mathrm{m}"),
        (d(1, 0, -2), m, "N/m", r"\mathrm{N/m}"),
        (d(1, 0, -1), m, "N·s/m", r"\mathrm{N\cdot s/m}"),
        (d(1, -1, -2), m, "N/m²", r"\mathrm{N/m^{2}}"),
        (d(0, 0, 0), m, "", ""),
        (d(0, 0, 0), UnitStyle::Angle, "rad", r"\mathrm{rad}"),
        (d(0, 0, -1), UnitStyle::Angle, "rad/s", r"\mathrm{rad/s}"),
        (d(1, -1, -1), m, "kg/(m·s)", r"\mathrm{kg/(m\cdot s)}"),
        (d(0, -1, 0), m, "1/m", r"\mathrm{1/m}"),
    ];
    for (dim, style, text, latex) in cases {
        assert_eq!(dim.si_text(style), text, "{dim} in {style:?}");
        assert_eq!(dim.si_latex(style), latex, "{dim} in {style:?}");
    }
    assert_eq!(d(1, 2, -2).to_string(), "M·L²·T⁻²");
    assert_eq!(d(0, 0, -1).to_string(), "T⁻¹");
    assert_eq!(d(0, 0, 0).to_string(), "1");
}

#[test]
fn dimension_of_hand_written_expressions() {
    // The torsion pendulum: k in N m/rad, f in N m s/rad, θ a pure number.
    let m = load("pendule_inverse_ressort");
    let dims = Dimensions::of(&m);
    let of = |s: &str| dimension(&ex(&m, s), &dims);
    // f θ̇ (N·m·s/rad × rad/s) and k θ-terms are moments, like C θ̈ and m g l sin θ.
    assert_eq!(of("f*dot(theta)").unwrap(), Some(d(1, 2, -2)));
    assert_eq!(
        of("(C + m*l^2)*ddot(theta) + f*dot(theta) - m*g*l*sin(theta)").unwrap(),
        Some(d(1, 2, -2))
    );
    // cos² + sin² = 1: a pure number; a rate alone is T⁻¹, its square T⁻².
    assert_eq!(of("cos(theta)^2 + 3").unwrap(), Some(d(0, 0, 0)));
    assert_eq!(of("dot(theta)").unwrap(), Some(d(0, 0, -1)));
    assert_eq!(of("l*dot(theta)^2").unwrap(), Some(d(0, 1, -2)));
    assert_eq!(of("0").unwrap(), None);
    // Two dimensions: both terms are named with theirs.
    let e = of("m*l + C").unwrap_err();
    let named = [e.first.as_str(), e.second.as_str()];
    assert!(named.contains(&"m*l") && named.contains(&"C"), "{e}");
    let dims_named = [e.first_dimension, e.second_dimension];
    assert!(dims_named.contains(&d(1, 1, 0)) && dims_named.contains(&d(1, 2, 0)));
    assert!(e.to_string().contains("kg·m²"), "{e}");

    // The winch: the load at R θ, θ written as itself, is a length.
    let w = load("treuil");
    let wd = Dimensions::of(&w);
    assert_eq!(
        dimension(&ex(&w, "R*theta + h"), &wd).unwrap(),
        Some(d(0, 1, 0))
    );
    assert_eq!(
        dimension(&ex(&w, "R*ddot(theta)"), &wd).unwrap(),
        Some(d(0, 1, -2))
    );
    // The mass-spring: x a length, ẍ L T⁻², the third derivative L T⁻³.
    let s = load("systeme_masse_ressort");
    let sd = Dimensions::of(&s);
    assert_eq!(
        dimension(&ex(&s, "c*dot(x) + k*(x - l0)"), &sd).unwrap(),
        Some(d(1, 1, -2))
    );
    assert_eq!(
        dimension(&s.reg().rate(s.reg().coord("x").unwrap(), 3), &sd).unwrap(),
        Some(d(0, 1, -3))
    );
    // sin β of the constant angle β (a coordinate with rate 0): a pure number.
    assert_eq!(
        dimension(&ex(&s, "m*g*sin(beta)"), &sd).unwrap(),
        Some(d(1, 1, -2))
    );
    // An incline α (a parameter of kind angle) is a pure number.
    let p = load("pendule_plan_incline");
    let pd = Dimensions::of(&p);
    assert_eq!(pd.scalar("alpha"), Some(d(0, 0, 0)));
    assert_eq!(
        dimension(&ex(&p, "M*g*sin(alpha) + M*g*alpha"), &pd).unwrap(),
        Some(d(1, 1, -2))
    );
}

#[test]
fn a_parameter_without_unit_is_skipped_never_failed() {
    // g without a unit: the weight terms are not checked, the others still are.
    let mut j = spec_json("pendule_sur_chariot");
    j["parameters"]
        .as_array_mut()
        .unwrap()
        .iter_mut()
        .find(|p| p["name"] == "g")
        .unwrap()
        .as_object_mut()
        .unwrap()
        .remove("unit");
    let m = build(&j).unwrap();
    let dims = Dimensions::of(&m);
    assert_eq!(dims.scalar("g"), None);
    // m g + m l would fail if g were known; it is m l alone that is checked.
    assert_eq!(
        dimension(&ex(&m, "m*g + m*l"), &dims).unwrap(),
        Some(d(1, 1, 0))
    );
    assert_eq!(dimension(&ex(&m, "g + g^2"), &dims).unwrap(), None);
    // Still inhomogeneous where known terms disagree.
    assert!(dimension(&ex(&m, "m*g + m*l + l"), &dims).is_err());
    let r = torseur::check::check(&m, 3, 1).unwrap();
    assert!(r.passed(), "{r}");
}

#[test]
fn unknowns_take_the_dimension_of_their_place_in_the_actions() {
    // A link's X, Y, Z are forces, its L, M, N moments; C_m in C_m*z0 given as a moment is a
    // moment.
    let force = d(1, 1, -2);
    let moment = d(1, 2, -2);
    let cases: [(&str, &[(&str, Dimension)]); 4] = [
        (
            "rotor_balourd",
            &[
                ("X01", force),
                ("Y01", force),
                ("Z01", force),
                ("L01", moment),
                ("M01", moment),
                ("C_m", moment),
            ],
        ),
        (
            "regulateur_centrifuge",
            &[
                ("C_m", moment),
                ("X12", force),
                ("M12", moment),
                ("N12", moment),
            ],
        ),
        (
            "bras_robot_deux_axes",
            &[("C_m1", moment), ("C_m2", moment)],
        ),
        ("pendule_sur_chariot", &[("X12", force), ("Y12", force)]),
    ];
    for (name, unknowns) in cases {
        let m = load(name);
        let dims = Dimensions::of(&m);
        for (u, want) in unknowns {
            assert_eq!(dims.scalar(u), Some(*want), "{name}: {u}");
        }
    }
    // The winch's C_m is a parameter in N m.
    assert_eq!(Dimensions::of(&load("treuil")).scalar("C_m"), Some(moment));
}

/// The dimension of a requested quantity, by hand from its notation (`in B..`, `.x2` and
/// `lin(...)` keep it): a length coordinate's equation of motion is a resultant theorem
/// (a force), an angle's a moment theorem; a link's X, Y, Z are forces, L, M, N and the motor
/// torques C_m moments.
fn by_hand(m: &Mechanism, q: &str) -> (Dimension, Option<Dimension>) {
    let q = q.strip_prefix("lin(").unwrap_or(q);
    let one = |x| (x, None);
    // d/dt(Q): Q's dimension per second.
    if let Some(inner) = q.strip_prefix("d/dt(") {
        let (main, moment) = by_hand(m, inner);
        let per_second = |x: Dimension| d(x.mass, x.length, x.time - 1);
        return (per_second(main), moment.map(per_second));
    }
    let head: String = q
        .chars()
        .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == '{')
        .collect();
    // A trial motion's amplitude (x = X cos(Ω t), x a length): a length.
    if torseur::derivation::trial_of(m, q).is_some() {
        return one(d(0, 1, 0));
    }
    match head.as_str() {
        "Omega" => one(d(0, 0, -1)),
        "V" => one(d(0, 1, -1)),
        "Gamma" => one(d(0, 1, -2)),
        "I" => one(d(1, 2, 0)),
        "Rc" => one(d(1, 1, -1)),
        "sigma" => one(d(1, 2, -1)),
        "Rd" => one(d(1, 1, -2)),
        "delta" => one(d(1, 2, -2)),
        "Ec" => one(d(1, 2, -2)),
        // A power: an energy per second, W.
        "P" | "Pint" => one(d(1, 2, -3)),
        // An inertia brought back to an angle.
        // A mass brought back to a length (x, or the screw jack's λ).
        "J_eq" if q.contains("(x)") || q.contains("(lambda)") => one(d(1, 0, 0)),
        "J_eq" => one(d(1, 2, 0)),
        // A coordinate's rate: its length (or angle, of no dimension) per second, per
        // second squared.
        "dot" | "ddot" => {
            let c = &q[q.find('(').unwrap() + 1..q.find(')').unwrap()];
            let length = m
                .spec()
                .coordinates
                .iter()
                .any(|x| x.name == c && x.kind == torseur::expr::CoordinateKind::Length);
            let per = if head == "dot" { -1 } else { -2 };
            one(d(0, i32::from(length), per))
        }
        "{V" => (d(0, 0, -1), Some(d(0, 1, -1))),
        "{C" => (d(1, 1, -1), Some(d(1, 2, -1))),
        "{D" | "{T" => (d(1, 1, -2), Some(d(1, 2, -2))),
        // An action's resultant is a force, its moment a moment.
        "R" => one(d(1, 1, -2)),
        "M" => one(d(1, 2, -2)),
        "eom" => {
            // A force for the resultant theorem that gives it, a moment for the moment
            // theorem (the disc on the incline takes x's equation from the moment at I); the
            // energy theorem divided by q̇ is a power over a rate: a moment for an angle, a
            // force for a length.
            use torseur::spec::wire::TheoremKind;
            let c = &q[4..q.find(')').unwrap()];
            let angle = m
                .spec()
                .coordinates
                .iter()
                .any(|x| x.name == c && x.kind == torseur::expr::CoordinateKind::Angle);
            let moment = m.spec().pfd.iter().any(|t| {
                t.eom.as_deref() == Some(c)
                    && (t.theorem == TheoremKind::Moment
                        || (t.theorem == TheoremKind::Energy && angle))
            });
            one(if moment { d(1, 2, -2) } else { d(1, 1, -2) })
        }
        // The gear train's tooth force.
        "T" | "N" => one(d(1, 1, -2)),
        // A contact's tangential and normal forces under Coulomb's law, as the spec names them.
        u if m.spec().links.iter().any(|l| {
            (l.contact_friction
                .as_ref()
                .and_then(|c| c.unknowns.as_ref()))
            .is_some_and(|n| n.tangential == u || n.normal == u)
        }) =>
        {
            one(d(1, 1, -2))
        }
        u if u.starts_with('X') || u.starts_with('Y') || u.starts_with('Z') => one(d(1, 1, -2)),
        u if u.starts_with('L') || u.starts_with('M') || u.starts_with('N') => one(d(1, 2, -2)),
        // A motor's torque, the wheel's guide's couple.
        u if u.starts_with("C_m") || u == "C_g" => one(d(1, 2, -2)),
        other => panic!("no hand dimension for `{other}` ({q})"),
    }
}

const LIBRARY: [&str; 27] = [
    "arbre_deux_rotules",
    "bielle_manivelle",
    "bille_tube_tournant",
    "bloc_frottement_sec",
    "bras_robot_deux_axes",
    "cylindre_gouttiere",
    "disque_plan_incline",
    "double_pendule",
    "echelle_frottement",
    "gyroscope_cardan",
    "masse_ressort_forcee",
    "pendule_arbre_tournant",
    "pendule_inverse_ressort",
    "pendule_masse_portee",
    "pendule_plan_incline",
    "pendule_sur_chariot",
    "quadrilatere_articule",
    "regulateur_centrifuge",
    "rotor_balourd",
    "rotor_deux_paliers",
    "rotor_vitesse_imposee",
    "roue_sur_plan",
    "systeme_masse_ressort",
    "toupie",
    "train_engrenages",
    "treuil",
    "verin_a_vis",
];

#[test]
fn the_library_list_is_every_spec() {
    let on_disk: Vec<String> = super::specs_in(&["derivations"])
        .iter()
        .map(|p| p.file_stem().unwrap().to_str().unwrap().to_string())
        .collect();
    assert_eq!(on_disk, LIBRARY.map(String::from).to_vec());
}

#[test]
fn every_quantity_of_every_spec_has_its_dimension_under_every_hypothesis() {
    for name in LIBRARY {
        let m = load(name);
        let dims = Dimensions::of(&m);
        // Every variable has a known dimension: nothing below is skipped.
        for i in m.reg().var_ids() {
            assert!(
                dims.variable(i).is_some(),
                "{name}: variable {} ({:?}) has no dimension",
                i.index(),
                m.reg().role(i)
            );
        }
        let values = derive_values(&m, m.quantities()).unwrap();
        for (q, dv) in m.quantities().iter().zip(&values) {
            let (main, moment) = by_hand(&m, &q.to_string());
            let forms: Vec<(String, Value)> =
                std::iter::once(("general".to_string(), dv.value.clone()))
                    .chain(
                        m.hypotheses()
                            .iter()
                            .map(|h| (format!("under {}", h.name), dv.value.under(h))),
                    )
                    .collect();
            for (label, v) in &forms {
                // A quotient: its numerator over its denominator has the dimension.
                if let Value::Quotient(f) = v {
                    let n = dimension(&f.num, &dims).unwrap().unwrap();
                    let d = dimension(&f.den, &dims).unwrap().unwrap();
                    assert_eq!(Some(n / d), Some(main), "{name}: {q} {label}, quotient");
                    homogeneous_value(&m, &dims, q, v)
                        .unwrap_or_else(|err| panic!("{name}: {q} {label}: {err}"));
                    continue;
                }
                for (k, e) in v.exprs().into_iter().enumerate() {
                    let want = match moment {
                        Some(mo) if k >= 3 => mo,
                        _ => main,
                    };
                    let got = dimension(e, &dims)
                        .unwrap_or_else(|err| panic!("{name}: {q} {label}: {err}"));
                    if e.is_zero() {
                        assert_eq!(got, None);
                    } else {
                        assert_eq!(got, Some(want), "{name}: {q} {label}, component {k}: {e}");
                    }
                }
                homogeneous_value(&m, &dims, q, v)
                    .unwrap_or_else(|err| panic!("{name}: {q} {label}: {err}"));
            }
            // Every step the answer key shows, with its own dimension.
            let full = derive(&m, q).unwrap();
            homogeneous_derivation(&m, &dims, &full).unwrap_or_else(|err| panic!("{name}: {err}"));
        }
        let r = torseur::check::check(&m, 2, 1).unwrap();
        assert!(r.dimension_failures().is_empty(), "{name}: {r}");
        assert_eq!(
            r.dimensions.len(),
            m.quantities().len() * (1 + m.hypotheses().len()),
            "{name}: every quantity, lin(...) included, under every hypothesis"
        );
    }
}

/// The regulator with O2 placed at d1 z0 + m2 L1 y1: a mass times a length added to lengths.
fn regulator_with_a_mass_in_a_position() -> Mechanism {
    let mut j = spec_json("regulateur_centrifuge");
    let points = j["points"].as_array_mut().unwrap();
    let o2 = points.iter_mut().find(|p| p["name"] == "O2").unwrap();
    assert_eq!(o2["position"], "d1*z0 + L1*y1");
    o2["position"] = "d1*z0 + m2*L1*y1".into();
    build(&j).unwrap()
}

#[test]
fn check_fails_on_a_position_that_mixes_a_mass_and_a_length() {
    let m = regulator_with_a_mass_in_a_position();
    let r = torseur::check::check(&m, 3, 1).unwrap();
    // The float backend computes the same (wrong) mechanism: it agrees; only the dimensions
    // catch the mistake.
    assert!(r.failures().is_empty(), "{r}");
    assert!(!r.passed());
    let wrong = r.dimension_failures();
    let v = wrong
        .iter()
        .find(|x| x.quantity == "V(G2,2/0) in B2" && x.hypothesis.is_none())
        .expect("V(G2,2/0) is inhomogeneous");
    let e = v.error.as_ref().unwrap();
    match &e.problem {
        DimensionProblem::Inhomogeneous(h) => {
            // −(m2 L1 + L2 cos θ2) θ̇1 on x2: kg·m/s against m/s.
            let with_mass = [&h.first, &h.second]
                .iter()
                .filter(|t| t.contains("m2"))
                .count();
            assert_eq!(with_mass, 1, "{e}");
            let dims = [h.first_dimension, h.second_dimension];
            assert!(
                dims.contains(&d(1, 1, -1)) && dims.contains(&d(0, 1, -1)),
                "{e}"
            );
        }
        other => panic!("{other:?}"),
    }
    assert!(e.at.starts_with("V(G2,2/0) in B2, "), "{e}");
    let text = r.to_string();
    assert!(
        text.contains("DIMENSION: V(G2,2/0) in B2, x2: inhomogeneous"),
        "{text}"
    );
    // The steps of the answer key are refused too.
    let dims = Dimensions::of(&m);
    let d2 = derive(&m, &Quantity::parse("delta(O2,2/0).x2").unwrap()).unwrap();
    assert!(homogeneous_derivation(&m, &dims, &d2).is_err());
}

#[test]
fn check_fails_on_a_wrong_unit() {
    // The 1-2 pivot's viscous coefficient given in N m/rad (a stiffness) instead of
    // N m s/rad: f θ̇2 is then N·m/s in a sum of moments.
    let mut j = spec_json("regulateur_centrifuge");
    set_unit(&mut j, "f", "N m/rad");
    let m = build(&j).unwrap();
    let r = torseur::check::check(&m, 3, 1).unwrap();
    assert!(!r.passed());
    let wrong: Vec<_> = r.dimension_failures();
    assert!(
        wrong.iter().all(|x| x.quantity == "eom(theta2)"),
        "only the equation of motion holds f: {r}"
    );
    assert_eq!(wrong.len(), 3, "in general and under H1 and H2: {r}");
    let e = wrong[0].error.as_ref().unwrap().to_string();
    assert!(e.contains("`f*dot(theta2)` (M·L²·T⁻³"), "{e}");
}

#[test]
fn check_fails_on_consistent_but_wrong_units() {
    // Every mass in m and every inertia in m^3: each result is homogeneous, but δ is L³ T⁻²
    // where a moment (M L² T⁻²) is expected.
    let mut j = spec_json("pendule_sur_chariot");
    for p in j["parameters"].as_array_mut().unwrap() {
        let unit = p["unit"].as_str().unwrap().to_string();
        let fixed = match unit.as_str() {
            "kg" => "m",
            "kg m^2" => "m^3",
            "N" => "m^2/s^2",
            u => u,
        };
        p["unit"] = fixed.into();
    }
    let m = build(&j).unwrap();
    let r = torseur::check::check(&m, 3, 1).unwrap();
    let wrong = r.dimension_failures();
    let delta = wrong
        .iter()
        .find(|x| x.quantity == "delta(A,2/0).z0")
        .expect("δ is not a moment");
    match &delta.error.as_ref().unwrap().problem {
        DimensionProblem::Unexpected {
            found, expected, ..
        } => {
            assert_eq!(*found, d(0, 3, -2));
            assert_eq!(*expected, d(1, 2, -2));
        }
        other => panic!("{other:?}"),
    }
    // V and Γ hold no mass: they pass.
    assert!(
        !wrong
            .iter()
            .any(|x| x.quantity.starts_with("V(") || x.quantity.starts_with("Gamma("))
    );
}

#[test]
fn a_value_checked_against_another_quantity_is_refused() {
    let m = regulator();
    let dims = Dimensions::of(&m);
    let sigma = derive(&m, &Quantity::parse("sigma(O2,2/0) in B2").unwrap()).unwrap();
    // σ is M L² T⁻¹; taken for δ it is short of a T⁻¹.
    let e = homogeneous_value(
        &m,
        &dims,
        &Quantity::parse("delta(O2,2/0) in B2").unwrap(),
        &sigma.value,
    )
    .unwrap_err();
    match e.problem {
        DimensionProblem::Unexpected {
            found, expected, ..
        } => {
            assert_eq!(found, d(1, 2, -1));
            assert_eq!(expected, d(1, 2, -2));
        }
        other => panic!("{other:?}"),
    }
    assert!(e.at.starts_with("delta(O2,2/0) in B2, "), "{}", e.at);
}
