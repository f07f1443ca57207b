//! What is printed is the engine's value. Every displayed formula of every answer key is read
//! back from its LaTeX by a reader written here, which shares no code with the printer
//! (`src/latex`): it tokenises the math, turns it into the engine's plain syntax, and the
//! engine's parser decides exact equality with the value the line claims to show. The values
//! of the results are themselves re-derived by the fast route (`derive_values`), not taken
//! from the document.

use std::collections::HashMap;
use torseur::derivation::Value;
use torseur::mechanism::Mechanism;

mod macros;
mod reader;

use macros::tokenize;
pub(super) use macros::{Tok, course};
pub(super) use reader::{Ctx, equations};
use reader::{align_bodies, prove, prove_equality};

/// Each J_eq form of an equation of motion (three displays: J_eq(q) = …, J_eq′(q) = dJ_eq/dq
/// = …, and J_eq q̈ + ½ J_eq′ q̇² = Q), read back here: its printed left side is read with
/// J_eq(q) and J_eq′(q) replaced by their printed values, and left − right must be the fast
/// route's eom(q) up to its sign; the printed J_eq′ q̇ must be the time derivative of the
/// printed J_eq. Returns how many were proven.
fn prove_jeq_forms(ctx: &Ctx, m: &Mechanism, displays: &[torseur::latex::Display]) -> usize {
    let find = |what: &str| displays.iter().find(|d| d.what == what);
    // A display's `name &= value`, its value as one line.
    let sides = |latex: &str| -> (String, String) {
        let (l, r) = latex.split_once("&=").expect("a display with `&=`");
        let flat = r.replace("\\\n", " ").replace('&', " ");
        (l.trim().to_string(), flat.trim().to_string())
    };
    let read = |tex: &str| {
        ctx.scalar(&tokenize(tex))
            .unwrap_or_else(|e| panic!("{tex}: {e}"))
    };
    let mut n = 0;
    for d in displays {
        let Some(id) = d.what.strip_prefix("J_eq form of ") else {
            continue;
        };
        let (Some(j), Some(jp)) = (
            find(&format!("J_eq of {id}")),
            find(&format!("J_eq' of {id}")),
        ) else {
            panic!("{id}: a J_eq form without its J_eq and J_eq'");
        };
        let (j_name, j_value) = sides(&j.latex);
        let (jp_def, jp_value) = sides(&jp.latex);
        let jp_name = jp_def.split(" = ").next().unwrap().trim().to_string();
        let (form, actions) = sides(&d.latex);
        let within = |v: &str| format!("\\left({v}\\right)");
        let left = form
            .replace(&jp_name, &within(&jp_value))
            .replace(&j_name, &within(&j_value));
        assert!(
            !left.contains("eq}"),
            "{id}: a J_eq name left unread in {left}"
        );
        let coordinate = id
            .strip_prefix("eom(")
            .and_then(|r| r.strip_suffix(')'))
            .expect("the J_eq form of an equation of motion");
        let reg = m.reg();
        let q = reg.coord(coordinate).unwrap();
        let (jv, jpv) = (read(&j_value), read(&jp_value));
        assert_eq!(
            &jpv * &reg.dot(q),
            jv.dt(),
            "{id}: the printed J_eq' is not the derivative of the printed J_eq"
        );
        let written = &read(&left) - &read(&actions);
        let quantity = torseur::quantity::Quantity::parse(id).unwrap();
        let fast = torseur::derivation::derive_values(m, std::slice::from_ref(&quantity))
            .unwrap()
            .remove(0)
            .value;
        let Value::Scalar(eom) = fast else {
            panic!("{id}: an equation of motion is a scalar")
        };
        assert!(
            written == eom || written == -&eom,
            "{id}: the printed J_eq form is not the equation of motion"
        );
        n += 1;
    }
    n
}

fn spec_paths() -> Vec<std::path::PathBuf> {
    // The library, one chain, and the reusable specs (Latin and Greek names, the link kinds
    // no library spec uses).
    let mut v = super::specs_in(&["derivations"]);
    v.push(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("derivations/chain/chain_2.json"));
    v.extend(super::specs_in(&["tests/specs"]));
    v
}

/// Every displayed formula of every answer key in `derivations/`, proven equal to its value;
/// every `align*` of the document is one of them; every result is the fast route's value.
#[test]
fn every_printed_formula_is_the_engines_value() {
    let mut proven = 0;
    let mut jeq = 0;
    for path in spec_paths() {
        let m = torseur::spec::load(&path).unwrap();
        let key = torseur::latex::answer_key_document(
            &m,
            torseur::latex::VectorStyle::Sum,
            &torseur::simulate::question_runs(&m),
        )
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let ctx = Ctx::new(&m);
        let bodies = align_bodies(&key.tex);
        assert_eq!(
            bodies,
            key.displays
                .iter()
                .map(|d| d.latex.as_str())
                .collect::<Vec<_>>(),
            "{}: the document's displays are exactly the recorded ones",
            path.display()
        );
        for f in &key.inline {
            assert!(
                key.tex.contains(&format!("${}$", f.latex)),
                "{}: {} is not in the text as recorded",
                path.display(),
                f.what
            );
            let t = tokenize(&f.latex);
            let ok = match &f.value {
                // A scalar alone, or stated as `lhs = value` (an imposed rate ψ̇ = ω).
                // A condition `value \neq 0`: its left side is the value, its right side 0.
                Value::Scalar(e) if t.contains(&Tok::Cmd("neq".into())) => {
                    let ne = t.iter().position(|x| *x == Tok::Cmd("neq".into())).unwrap();
                    let zero = ctx.scalar(&t[ne + 1..]).map(|z| z.is_zero());
                    ctx.scalar(&t[..ne]).map(|g| &g == e && zero == Ok(true))
                }
                // A condition |a| ≤ |b| (Coulomb's |T| ≤ f |N|), recorded as a² − b² (≤ 0),
                // the same condition: each |…| is read as (…) and both sides squared.
                Value::Scalar(e) if t.contains(&Tok::Cmd("leq".into())) => {
                    let le = t.iter().position(|x| *x == Tok::Cmd("leq".into())).unwrap();
                    let bars = |s: &[Tok]| -> Vec<Tok> {
                        let mut out = s.to_vec();
                        for k in 1..out.len() {
                            if out[k] == Tok::Sym('|') {
                                out[k] = match &out[k - 1] {
                                    Tok::Cmd(c) if c == "left" => Tok::Sym('('),
                                    Tok::Cmd(c) if c == "right" => Tok::Sym(')'),
                                    _ => Tok::Sym('|'),
                                };
                            }
                        }
                        out
                    };
                    let sides = (ctx.scalar(&bars(&t[..le])), ctx.scalar(&bars(&t[le + 1..])));
                    match sides {
                        (Ok(a), Ok(b)) => Ok(&(&(&a * &a) - &(&b * &b)) == e),
                        (Err(x), _) | (_, Err(x)) => Err(x),
                    }
                }
                // A sign `value > 0` or `value < 0` (an explicit loop law's branch): its left
                // side is the value, its right side 0.
                Value::Scalar(e) if t.contains(&Tok::Sym('>')) || t.contains(&Tok::Sym('<')) => {
                    let at = t
                        .iter()
                        .position(|x| *x == Tok::Sym('>') || *x == Tok::Sym('<'))
                        .unwrap();
                    let zero = ctx.scalar(&t[at + 1..]).map(|z| z.is_zero());
                    ctx.scalar(&t[..at]).map(|g| &g == e && zero == Ok(true))
                }
                Value::Scalar(e) => {
                    let rhs = match t.iter().position(|x| *x == Tok::Sym('=')) {
                        Some(eq) => &t[eq + 1..],
                        None => &t[..],
                    };
                    ctx.scalar(rhs).map(|g| &g == e)
                }
                // A quotient alone (a row of the bilan): n / d = N / D, cross-multiplied.
                Value::Quotient(q) => ctx.quotient(&t).map(|(n, d)| &n * &q.den == &q.num * &d),
                // `lhs = sum`, or a sum alone (a row of the bilan).
                Value::Vector { components, .. } => {
                    let rhs = match t.iter().position(|x| *x == Tok::Sym('=')) {
                        Some(eq) => &t[eq + 1..],
                        None => &t[..],
                    };
                    ctx.any_basis(rhs).map(|g| &g == components)
                }
                _ => unreachable!("inline formulas are scalars and positions"),
            };
            assert_eq!(
                ok,
                Ok(true),
                "{}: {} printed {}",
                path.display(),
                f.what,
                f.latex
            );
            proven += 1;
        }
        // Every displayed value is homogeneous: all its terms have one dimension, from the
        // parameters' units (torseur::units).
        let dims = torseur::units::Dimensions::of(&m);
        for d in &key.displays {
            for v in std::iter::once(&d.value).chain(d.rhs.iter()) {
                for e in v.exprs() {
                    if let Err(err) = torseur::units::dimension(e, &dims) {
                        panic!("{}: {} is not homogeneous: {err:?}", path.display(), d.what);
                    }
                }
            }
        }
        jeq += prove_jeq_forms(&ctx, &m, &key.displays);
        let mut fast: HashMap<String, Value> = HashMap::new();
        for d in &key.displays {
            let proof = match &d.rhs {
                Some(r) => prove_equality(&ctx, &d.latex, &d.value, r),
                None => prove(&ctx, &d.latex, &d.value),
            };
            // The left side's own symbols (a solid's mass and centre), read back too.
            let proof = proof.and_then(|()| super::printed_names::check(&ctx, d));
            if let Err(e) = proof {
                panic!(
                    "{}: {} ({:?}, under {:?}) is printed wrong: {e}\n{}",
                    path.display(),
                    d.what,
                    d.role,
                    d.hypothesis,
                    d.latex
                );
            }
            if matches!(
                d.role,
                torseur::latex::DisplayRole::Result | torseur::latex::DisplayRole::Equation
            ) {
                let q = torseur::quantity::Quantity::parse(&d.what).unwrap();
                let v = fast.entry(d.what.clone()).or_insert_with(|| {
                    torseur::derivation::derive_values(&m, std::slice::from_ref(&q))
                        .unwrap()
                        .remove(0)
                        .value
                });
                let want = match &d.hypothesis {
                    Some(h) => as_asked(
                        &m,
                        &q,
                        v,
                        m.hypotheses().iter().find(|x| &x.name == h).unwrap(),
                    ),
                    None => v.clone(),
                };
                // An equation a = b shows the quantity a − b (up to its sign: either side may
                // stand on the left).
                let shown = match (&d.value, &d.rhs) {
                    (Value::Scalar(a), Some(Value::Scalar(b))) => {
                        let diff = a - b;
                        let Value::Scalar(w) = &want else {
                            panic!("an equation of a vector")
                        };
                        if &(-&diff) == w {
                            Value::Scalar(-&diff)
                        } else {
                            Value::Scalar(diff)
                        }
                    }
                    _ => d.value.clone(),
                };
                assert!(
                    want.exprs() == shown.exprs(),
                    "{}: {} under {:?}: the key's value is not the fast route's",
                    path.display(),
                    d.what,
                    d.hypothesis
                );
            }
            proven += 1;
        }
    }
    eprintln!("{proven} displayed formulas proven");
    eprintln!("{jeq} J_eq forms proven");
    // At least tests/specs/coulisse_ecossaise.json's.
    assert!(jeq >= 1, "no J_eq form read back");
    assert!(proven > 300, "only {proven} formulas read back");
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

    /// The LaTeX of the presentation form of random expressions (sums of angles, powers,
    /// products of sums) reads back, with this file's reader, to the same canonical form.
    #[test]
    fn the_latex_of_random_expressions_reads_back(e in super::properties::expression()) {
        let m = super::regulator();
        let ctx = Ctx::new(&m);
        let exact = m.reg().parse(&e).unwrap();
        let latex = format!("x &= {}", torseur::latex::expr(&exact));
        let v = Value::Scalar(exact);
        proptest::prop_assert!(prove(&ctx, &latex, &v).is_ok(), "{}: {:?}", latex, prove(&ctx, &latex, &v));
    }
}

/// The reader can fail: a sign flipped in the printed LaTeX, a dropped parenthesis, a wrong
/// basis are each caught.
#[test]
fn the_reader_catches_a_wrong_sign() {
    let m = super::regulator();
    let ctx = Ctx::new(&m);
    let e = m.reg().parse("-(A2 + L2^2*m2)*ddot(theta2) + g").unwrap();
    let v = Value::Scalar(e);
    assert!(
        prove(
            &ctx,
            "x &= -\\left(A_{2} + m_{2}\\,L_{2}^{2}\\right)\\,\\ddot{\\theta}_{2} + g",
            &v
        )
        .is_ok()
    );
    assert!(
        prove(
            &ctx,
            "x &= -A_{2} + m_{2}\\,L_{2}^{2}\\,\\ddot{\\theta}_{2} + g",
            &v
        )
        .is_err()
    );
    assert!(
        prove(
            &ctx,
            "x &= -A_{2}\\,\\ddot{\\theta}_{2} - m_{2}\\,L_{2}^{2}\\,\\ddot{\\theta}_{2} - g",
            &v
        )
        .is_err()
    );
    let f2 = m.frames().find("2").unwrap();
    let z = m.reg().zero();
    let vec = Value::Vector {
        basis: f2,
        components: [m.reg().parse("L1 + L2").unwrap(), z.clone(), z],
    };
    assert!(prove(&ctx, "v &= \\left(L_{1} + L_{2}\\right)\\vec{x}_{2}", &vec).is_ok());
    assert!(prove(&ctx, "v &= L_{1} + L_{2}\\,\\vec{x}_{2}", &vec).is_err());
    assert!(prove(&ctx, "v &= \\left(L_{1} + L_{2}\\right)\\vec{x}_{1}", &vec).is_err());
    let col = "\\begin{pmatrix} L_{1} + L_{2} \\\\ 0 \\\\ 0 \\end{pmatrix}_{\\mathcal{B}_{2}}";
    assert!(prove(&ctx, &format!("v &= {col}"), &vec).is_ok());
    assert!(
        prove(
            &ctx,
            &format!("v &= {}", col.replace("B}_{2}", "B}_{1}")),
            &vec
        )
        .is_err()
    );
}

/// An equation of motion written on several rows (the dynamic side on rows of its own, then
/// `&= actions`) reads back side by side; a sign flipped on either side is caught.
#[test]
fn the_reader_reads_a_dynamic_side_on_rows_of_its_own() {
    let m = super::regulator();
    let ctx = Ctx::new(&m);
    let e = |s: &str| Value::Scalar(m.reg().parse(s).unwrap());
    let l = e("(A2 + m2*L2^2)*ddot(theta2) + f*dot(theta2)");
    let r = e("-m2*g*L2*cos(theta2)");
    let rows = |a: &str, b: &str| {
        format!(
            "&\\left(A_{{2}} + m_{{2}}\\,L_{{2}}^{{2}}\\right)\\ddot{{\\theta}}_{{2}} \\\\\n\
             &\\quad {a} f\\,\\dot{{\\theta}}_{{2}} \\\\\n&= {b}m_{{2}}\\,g\\,L_{{2}}\\,\\cos\\theta_{{2}}"
        )
    };
    assert_eq!(prove_equality(&ctx, &rows("+", "-"), &l, &r), Ok(()));
    assert!(prove_equality(&ctx, &rows("-", "-"), &l, &r).is_err());
    assert!(prove_equality(&ctx, &rows("+", ""), &l, &r).is_err());
}

/// The strings of a JSON value (`canonical` or `presentation`), in `Value::exprs` order.
fn json_strings(v: &serde_json::Value, form: &str) -> Vec<String> {
    let flat = |x: &serde_json::Value| -> Vec<String> {
        let mut out = Vec::new();
        let mut stack = vec![x];
        while let Some(y) = stack.pop() {
            match y {
                serde_json::Value::String(s) => out.push(s.clone()),
                serde_json::Value::Array(a) => stack.extend(a.iter().rev()),
                _ => panic!("unexpected {y}"),
            }
        }
        out
    };
    match v["kind"].as_str().unwrap() {
        "torsor" => {
            let mut r = flat(&v["resultant"][form]);
            r.extend(flat(&v["moment"][form]));
            r
        }
        _ => flat(&v[form]),
    }
}

/// The text and JSON outputs of `derive` (canonical and presentation strings) read back by
/// the engine's parser equal the fast route's values, for every quantity of every spec,
/// under every hypothesis.
#[test]
fn every_derived_text_and_json_string_is_the_engines_value() {
    let mut n = 0;
    for path in spec_paths() {
        let m = torseur::spec::load(&path).unwrap();
        let ds = torseur::derivation::derive_values(&m, m.quantities()).unwrap();
        let j = torseur::output::derive_json(&m, &ds);
        for (d, jq) in ds.iter().zip(j["quantities"].as_array().unwrap()) {
            let mut cases = vec![(d.value.clone(), &jq["value"])];
            for h in m.hypotheses() {
                cases.push((
                    as_asked(&m, &d.quantity, &d.value, h),
                    &jq["hypotheses"][&h.name],
                ));
            }
            for (v, jv) in cases {
                for form in ["canonical", "presentation"] {
                    // A quotient is one string n/d: read by the fraction parser, compared by
                    // cross-multiplication.
                    if let Value::Quotient(q) = &v {
                        let g = jv[form].as_str().unwrap();
                        let (n1, d1) = m.reg().parse_fraction_with(g, &|_| None).unwrap();
                        assert!(
                            &n1 * &q.den == &q.num * &d1 && !d1.is_one(),
                            "{}: {} ({form}) printed {g}, engine {}/{}",
                            path.display(),
                            d.quantity,
                            q.num,
                            q.den
                        );
                        n += 1;
                        continue;
                    }
                    let got = json_strings(jv, form);
                    let want = v.exprs();
                    assert_eq!(got.len(), want.len(), "{}: {}", path.display(), d.quantity);
                    for (g, w) in got.iter().zip(want) {
                        let e = m.reg().parse(g).unwrap_or_else(|e| panic!("{g}: {e}"));
                        assert!(
                            &e == w,
                            "{}: {} ({form}) printed {g}, engine {w}",
                            path.display(),
                            d.quantity
                        );
                        n += 1;
                    }
                }
            }
        }
    }
    assert!(n > 500, "only {n} strings read back");
}

/// The value `v` of `q` under `h` by this reader's own route: the hypothesis applied, and for
/// a linearisation under small parameters ε, its terms in ε δ dropped, δ the small
/// coordinates and their rates (one combined first order): v − Σ εᵢ xⱼ ∂²v/∂εᵢ∂xⱼ, the
/// value being affine in each of them.
fn as_asked(
    m: &torseur::Mechanism,
    q: &torseur::quantity::Quantity,
    v: &Value,
    h: &torseur::mechanism::Hypothesis,
) -> Value {
    let under = v.under(h);
    if !q.linear || h.first_order.is_empty() {
        return under;
    }
    let reg = m.reg();
    let mut small = Vec::new();
    for s in &m.dynamics().small {
        small.extend(reg.value(s.coord).and_then(|e| e.single_variable()));
        for order in 1..=2 {
            small.extend(reg.rate(s.coord, order).single_variable());
        }
    }
    under.map(&|e| {
        let mut out = e.clone();
        for &p in &h.first_order {
            for &x in &small {
                let mixed = e.derivative(p).derivative(x);
                out = &out - &(&mixed * &(&reg.variable(p) * &reg.variable(x)));
            }
        }
        out
    })
}
