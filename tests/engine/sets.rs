//! The inertia operator of a set of solids, I(P,E) = Σ I(P,Si) (issue 37): derived by hand
//! (Huygens for each solid, the operator of S2 turned into B1), compared exactly with the
//! engine's, and checked by the float backend, which sums its own point clouds.

use torseur::derivation::{Value, derive};
use torseur::quantity::Quantity;

/// I(O1,E) of the regulator, E = {1, 2}, in B1. By hand: O1G1 = h1 z1 gives m1 h1² on the
/// x and y diagonal; O1G2 = (L1 + L2 cos θ2) y1 + (d1 + L2 sin θ2) z1 gives
/// m2 [(O1G2·O1G2) Id − O1G2 ⊗ O1G2]; I_G2(2), given in B2, is R I R^T in B1 with
/// y2 = cos θ2 y1 + sin θ2 z1, z2 = −sin θ2 y1 + cos θ2 z1 (expanded with sympy, typed here).
#[test]
fn the_inertia_of_the_regulators_set_by_hand() {
    let m = super::regulator();
    let xx = "A1 + A2 + L1^2*m2 + 2*L1*L2*m2*cos(theta2) + L2^2*m2 + 2*L2*d1*m2*sin(theta2) \
              + d1^2*m2 + h1^2*m1";
    let xy = "E2*sin(theta2) - F1 - F2*cos(theta2)";
    let xz = "-E1 - E2*cos(theta2) - F2*sin(theta2)";
    let yy = "B1 + B2*cos(theta2)^2 + C2*sin(theta2)^2 + 2*D2*sin(theta2)*cos(theta2) \
              + L2^2*m2*sin(theta2)^2 + 2*L2*d1*m2*sin(theta2) + d1^2*m2 + h1^2*m1";
    let yz = "B2*sin(theta2)*cos(theta2) - C2*sin(theta2)*cos(theta2) - D1 \
              + D2*sin(theta2)^2 - D2*cos(theta2)^2 - L1*L2*m2*sin(theta2) - L1*d1*m2 \
              - L2^2*m2*sin(theta2)*cos(theta2) - L2*d1*m2*cos(theta2)";
    let zz = "B2*sin(theta2)^2 + C1 + C2*cos(theta2)^2 - 2*D2*sin(theta2)*cos(theta2) \
              + L1^2*m2 + 2*L1*L2*m2*cos(theta2) + L2^2*m2*cos(theta2)^2";
    let rows = [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]];
    let q = Quantity::parse("I(O1,E)").unwrap();
    let d = derive(&m, &q).unwrap();
    let Value::Matrix(i) = &d.value else {
        panic!("I(O1,E) is a matrix: {:?}", d.value)
    };
    assert_eq!(m.frame_name(i.basis), "1", "in the basis of S1's operator");
    for (r, row) in rows.iter().enumerate() {
        for (c, hand) in row.iter().enumerate() {
            assert_eq!(
                i.matrix[r][c],
                m.reg().parse(hand).unwrap(),
                "I(O1,E)[{r}][{c}]"
            );
        }
    }
    // The float backend, on its own point clouds, at 10 samples.
    let model = torseur::numeric::NumericModel::new(m.spec()).unwrap();
    let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(5);
    let report = torseur::check::compare(&m, &model, &q, &d.value, None, 10, &mut rng).unwrap();
    assert!(
        report.worst <= torseur::check::TOLERANCE,
        "{}",
        report.worst
    );
    // The steps name each solid's operator at O1 before the sum.
    let labels: Vec<&str> = d.steps.iter().map(|s| s.label.as_str()).collect();
    assert!(
        labels.contains(&"I(O1,1)") && labels.contains(&"I(O1,2)"),
        "{labels:?}"
    );
}

/// A name that is neither a solid nor a set is refused, with the names that are.
#[test]
fn the_inertia_of_an_unknown_set_is_refused_by_name() {
    let m = super::regulator();
    let e = derive(&m, &Quantity::parse("I(O1,F)").unwrap()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "I(O1,F): unknown solid or set `F` (declared: `1`, `2`, `E`)"
    );
}

/// In the answer key, the operator of a set is derived solid by solid, each by Huygens from
/// its own centre, and said to be their sum before it is boxed.
#[test]
fn the_key_derives_the_inertia_of_a_set_solid_by_solid() {
    let mut spec: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/derivations/regulateur_centrifuge.json"
        ))
        .unwrap(),
    )
    .unwrap();
    spec["questions"] = serde_json::json!([
        {"title": "Inertie", "statement": "Opérateur d'inertie de E en O1.", "quantities": ["I(O1,E)"]}
    ]);
    let m = torseur::spec::from_str(&spec.to_string()).unwrap();
    let tex = torseur::latex::answer_key(&m, &torseur::simulate::question_runs(&m)).unwrap();
    let at = |s: &str| {
        tex.find(s)
            .unwrap_or_else(|| panic!("`{s}` not in the key"))
    };
    let g1 = at("Théorème de Huygens, de $G_{1}$ en $O_{1}$");
    let g2 = at("Théorème de Huygens, de $G_{2}$ en $O_{1}$");
    let sum = at(
        "L'opérateur d'inertie de $E$ en $O_{1}$ est la somme de ceux de $S_{1}$ et \
                  $S_{2}$ en $O_{1}$ :",
    );
    assert!(g1 < g2 && g2 < sum);
}
