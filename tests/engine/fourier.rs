//! Issue 17: the linearised trigonometric (Fourier) form against the canonical polynomial
//! form, on every quantity of every spec of `derivations/` (and `tests/specs/`): the two agree
//! exactly by conversion, the Fourier form's own sum, product and d/dt agree with the
//! canonical form's, and its value, computed in f64 from cos(Σ kᵢ qᵢ) and sin(Σ kᵢ qᵢ) of the
//! drawn angles, is the canonical form's.

use rand::SeedableRng;
use torseur::derivation::derive_values;
use torseur::expr::{Expr, Fourier, Trig};
use torseur::numeric::NumericModel;
use torseur::output::{Values, numeric_point};

/// The value of a Fourier form in f64: each coefficient by the canonical evaluator (it holds
/// no cos or sin of a time angle), each harmonic by the standard library's cos and sin.
fn float_value(f: &Fourier, point: &[f64], angle_of: &dyn Fn(usize) -> f64) -> f64 {
    f.terms()
        .map(|(a, g, c)| {
            let x: f64 = a
                .terms()
                .iter()
                .map(|&(q, k)| k as f64 * angle_of(q.index()))
                .sum();
            let h = match g {
                Trig::Cos => x.cos(),
                Trig::Sin => x.sin(),
            };
            c.eval(point) * h
        })
        .sum()
}

#[test]
fn the_fourier_form_agrees_with_the_canonical_form_on_every_quantity() {
    let mut specs = super::specs_in(&["derivations", "tests/specs"]);
    for n in ["chain_3", "planar_4"] {
        specs.push(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join(format!("derivations/chain/{n}.json")),
        );
    }
    let (mut converted, mut refused, mut canonical_terms, mut fourier_terms) = (0, 0, 0, 0);
    for path in &specs {
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let m = torseur::spec::load(path).unwrap();
        let model = NumericModel::new(m.spec()).unwrap();
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let s = model.sample(&mut rng).unwrap();
        let values = Values {
            parameters: s.parameters.clone(),
            coordinates: s.coordinates.clone(),
            time: Some(s.time),
            // A link's transmissible torsor keeps the unknowns the PFD leaves (X_H of a
            // helical link): any value of them serves, each a different one.
            unknowns: (m.reg().unknowns().iter().enumerate())
                .map(|(k, n)| (n.clone(), 0.7 + 0.13 * k as f64))
                .collect(),
        };
        let point = numeric_point(&m, &values).unwrap();
        // A time coordinate's drawn value, or Ω t for a phase.
        let angle_of = |i: usize| {
            let c = &m.reg().coordinates()[i];
            match c.phase() {
                Some(w) => s.parameters[w] * s.time,
                None => s.coordinates[&c.name][0],
            }
        };
        let derived = derive_values(&m, m.quantities()).unwrap();
        let exprs: Vec<&Expr> = derived.iter().flat_map(|d| d.value.exprs()).collect();
        for (i, &e) in exprs.iter().enumerate() {
            let Some(f) = e.to_fourier() else {
                // Only a loop closure's 1/cos φ has no such form.
                assert!(
                    !m.spec().closures.is_empty() || !m.spec().rolling.is_empty(),
                    "{name}: {e}"
                );
                refused += 1;
                continue;
            };
            converted += 1;
            canonical_terms += e.nterms();
            fourier_terms += f.nterms();
            assert_eq!(&f.to_expr(), e, "{name}: {e}");
            let (a, b) = (e.eval(&point), float_value(&f, &point, &angle_of));
            assert!(
                (a - b).abs() <= 1e-9 * (1.0 + a.abs()),
                "{name}: {e}: {a} against {b}"
            );
            // Its own operations, held against the canonical form's.
            assert_eq!(
                e.dt().to_fourier().as_ref(),
                f.dt().as_ref(),
                "{name}: d/dt {e}"
            );
            let other = exprs[(i + 1) % exprs.len()];
            if let Some(g) = other.to_fourier()
                && e.nterms() * other.nterms() <= 40_000
            {
                assert_eq!(
                    (e * other).to_fourier().as_ref(),
                    Some(&f.mul(&g)),
                    "{name}: {e} × {other}"
                );
                assert_eq!(
                    (e + other).to_fourier().as_ref(),
                    Some(&f.add(&g)),
                    "{name}: {e} + {other}"
                );
            }
        }
    }
    eprintln!(
        "{converted} converted ({canonical_terms} canonical terms, {fourier_terms} in the \
         Fourier form), {refused} refused"
    );
    assert!(
        converted > 300 && refused < converted / 10,
        "{converted} converted, {refused} refused"
    );
    assert!(
        fourier_terms <= canonical_terms,
        "{fourier_terms} against {canonical_terms}"
    );
}

#[test]
fn a_planar_chain_is_smaller_in_the_fourier_form() {
    // cos qi cos qj + sin qi sin qj = cos(qj − qi): the planar chain's equations of motion.
    let m = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/chain/planar_6.json"
    ))
    .unwrap();
    let (mut canonical, mut fourier) = (0, 0);
    for d in derive_values(&m, m.quantities()).unwrap() {
        for e in d.value.exprs() {
            canonical += e.nterms();
            fourier += e.to_fourier().unwrap().nterms();
        }
    }
    assert!(
        2 * fourier < canonical + canonical / 4,
        "{fourier} against {canonical}"
    );
    let f = m
        .reg()
        .parse("cos(q2)*cos(q1) + sin(q2)*sin(q1)")
        .unwrap()
        .to_fourier()
        .unwrap();
    assert_eq!(f.to_string(), "cos(q2 - q1)");
}
