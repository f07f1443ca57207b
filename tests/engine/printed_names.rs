//! The left side of a display is proven too where the writer chose its symbols from the
//! mechanism: the complementary term V(A/R) ∧ m V(G/R) of δ(A,S/R) (issue 34, item 0: a
//! writer that took the mass of the first solid whose centre is G printed V(G3/R0) ∧ 0
//! V(G3/R0), or m1 for the term of S3, and the proof of the value alone called it equal).
//!
//! The writer records which solid's term a display is (`Display::solid`). This reader parses
//! the printed left side itself and checks, against the spec's own data (its `solids`, not
//! the mechanism the writer read) and the derivation's label (`V(A/R) ^ m V(G/R)`): the
//! printed mass is that solid's mass, the printed G its centre, the printed A and R those of
//! the derivation; and that these printed symbols give the value the display shows:
//! m (V(A/R) ∧ V(G/R)), with V of the points printed, equals the value proven on the right.

use super::printed::{Ctx, Tok, equations};
use torseur::derivation::Value;
use torseur::latex::Display;

/// A name as printed (`O_{1}`, `\mathcal{R}_{0}`): its letters and digits (`O1`, `R0`).
fn flat(t: &[Tok]) -> String {
    t.iter()
        .filter_map(|x| match x {
            Tok::Letter(c) | Tok::Digit(c) => Some(*c),
            _ => None,
        })
        .collect()
}

/// A spec name as it prints, its letters and digits (`G_3` and `G3` both `G3`).
fn flat_name(n: &str) -> String {
    n.chars().filter(|c| c.is_ascii_alphanumeric()).collect()
}

/// `\overrightarrow{V(P/R)}` from `t[0]`: (P, R) flattened.
fn velocity(t: &[Tok]) -> Result<(String, String), String> {
    let open = t.iter().position(|x| *x == Tok::Sym('('));
    let slash = t.iter().position(|x| *x == Tok::Sym('/'));
    let close = t.iter().position(|x| *x == Tok::Sym(')'));
    match (t.first(), t.get(2), t.get(3), open, slash, close) {
        (
            Some(Tok::Cmd(c)),
            Some(Tok::Letter('V')),
            Some(Tok::Sym('(')),
            Some(o),
            Some(s),
            Some(e),
        ) if c == "overrightarrow" && o < s && s < e => {
            Ok((flat(&t[o + 1..s]), flat(&t[s + 1..e])))
        }
        _ => Err(format!("not a velocity \\overrightarrow{{V(P/R)}}: {t:?}")),
    }
}

/// The parts of a printed complementary term `\overrightarrow{V(A/R)} \wedge m\,
/// \overrightarrow{V(G/R)}`: (A, R of the first velocity, the mass's tokens, G, R of the
/// second).
type Parts = (String, String, Vec<Tok>, String, String);

fn parts(lhs: &[Tok]) -> Result<Parts, String> {
    let wedge = lhs
        .iter()
        .position(|x| *x == Tok::Cmd("wedge".into()))
        .ok_or("no \\wedge in a complementary term")?;
    let second = lhs
        .iter()
        .rposition(|x| *x == Tok::Cmd("overrightarrow".into()))
        .filter(|&k| k > wedge)
        .ok_or("no velocity after \\wedge")?;
    let (a, r) = velocity(&lhs[..wedge])?;
    let (g, r2) = velocity(&lhs[second..])?;
    let mut mass = lhs[wedge + 1..second].to_vec();
    while matches!(mass.last(), Some(Tok::Cmd(c)) if c == ",") {
        mass.pop();
    }
    Ok((a, r, mass, g, r2))
}

/// The label of a complementary step, as the derivation writes it (`V(A/0) ^ m V(G2/0)`):
/// (A, G, R).
fn label(what: &str) -> Result<(String, String, String), String> {
    let bad = || format!("not the label of a complementary term: {what}");
    let (left, right) = what.split_once(" ^ m ").ok_or_else(bad)?;
    let inner = |s: &str| -> Option<(String, String)> {
        let s = s.strip_prefix("V(")?.strip_suffix(')')?;
        let (p, r) = s.split_once('/')?;
        Some((p.to_string(), r.to_string()))
    };
    let (a, r) = inner(left).ok_or_else(bad)?;
    let (g, r2) = inner(right).ok_or_else(bad)?;
    if r != r2 {
        return Err(bad());
    }
    Ok((a, g, r))
}

/// Checks the left side of a display that names a solid's symbols; `Ok` for the others.
pub(super) fn check(ctx: &Ctx, d: &Display) -> Result<(), String> {
    let eqs = equations(&d.latex);
    let Some((lhs, _)) = eqs.first() else {
        return Ok(());
    };
    let Some(solid) = &d.solid else {
        // The reader finds the complementary terms itself: one printed without its solid
        // recorded would escape the proof of its mass.
        if parts(lhs).is_ok() {
            return Err(format!(
                "a complementary term printed without the solid whose term it is: {}",
                d.latex
            ));
        }
        return Ok(());
    };
    let m = ctx.m;
    let (pa, pr, mass_toks, pg, pr2) = parts(lhs)?;
    let (la, lg, lr) = label(&d.what)?;
    // The spec's own data for the solid whose term it is.
    let spec = m
        .spec()
        .solids
        .iter()
        .find(|s| &s.name == solid)
        .ok_or(format!("no solid `{solid}` in the spec"))?;
    let spec_mass = m
        .reg()
        .parse(
            spec.mass
                .as_deref()
                .ok_or(format!("solid {solid} has no mass"))?,
        )
        .map_err(|e| e.to_string())?;
    let printed_mass = ctx.scalar(&mass_toks)?;
    if printed_mass != spec_mass {
        return Err(format!(
            "the term of solid {solid} prints the mass {printed_mass}; its mass is {spec_mass}"
        ));
    }
    let centre = spec
        .centre
        .as_deref()
        .ok_or(format!("solid {solid} has no centre"))?;
    if pg != flat_name(centre) || flat_name(&lg) != pg {
        return Err(format!(
            "the term of solid {solid} prints the point {pg}; its centre is {centre}"
        ));
    }
    let reference = format!("R{}", flat_name(&lr));
    if pa != flat_name(&la) || pr != reference || pr2 != reference {
        return Err(format!(
            "printed V({pa}/{pr}) ∧ … V({pg}/{pr2}) for the term V({la}/{lr}) ∧ m V({lg}/{lr})"
        ));
    }
    // What the printed symbols give: m (V(A/R) ∧ V(G/R)).
    let find = |p: &str| m.point(p).ok_or(format!("no point {p}"));
    let rf = m.frames().find(&lr).ok_or(format!("no frame {lr}"))?;
    let va = torseur::kinematics::point_velocity(m, find(&la)?, rf);
    let vg = torseur::kinematics::point_velocity(m, find(&lg)?, rf);
    let term = va.cross(m.frames(), &vg.scale(&printed_mass));
    let Value::Vector { basis, components } = &d.value else {
        return Err("a complementary term that is not a vector".into());
    };
    let mut want = Value::Vector {
        basis: *basis,
        components: term.express_in(m.frames(), *basis),
    };
    if let Some(h) = &d.hypothesis {
        let h = m
            .hypotheses()
            .iter()
            .find(|x| &x.name == h)
            .ok_or("no such hypothesis")?;
        want = want.under(h);
    }
    match &want {
        Value::Vector { components: c, .. } if c == components => Ok(()),
        _ => Err(format!(
            "the printed symbols give {:?}, the display shows {:?}",
            want.exprs(),
            d.value.exprs()
        )),
    }
}

/// The proof of a left side can fail: on the key of a spec where two solids of mass share
/// their centre G (and a third, of zero mass, shares it too), the term of S3 printed with
/// m1 or with 0 — what the writer printed when it took the mass of the first solid whose
/// centre is G — is refused, and so is a wrong point or frame; the key as written passes.
#[test]
fn a_complementary_term_printed_with_another_solids_mass_is_caught() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let m = torseur::spec::load(root.join("tests/specs/porteur_centre_commun.json")).unwrap();
    let key = torseur::latex::answer_key_document(
        &m,
        torseur::latex::VectorStyle::Sum,
        &torseur::simulate::question_runs(&m),
    )
    .unwrap();
    let ctx = Ctx::new(&m);
    let terms: Vec<&Display> = key.displays.iter().filter(|d| d.solid.is_some()).collect();
    // One term per solid with a mass (1 and 3), none for the body of zero mass (2).
    let solids: Vec<&str> = terms.iter().filter_map(|d| d.solid.as_deref()).collect();
    assert_eq!(solids, ["1", "3"], "{:#?}", terms);
    for d in &terms {
        assert_eq!(check(&ctx, d), Ok(()), "{}", d.latex);
    }
    let s3 = terms[1];
    assert!(s3.latex.contains("\\wedge m_{3}\\,"), "{}", s3.latex);
    let wrong = |from: &str, to: &str| Display {
        latex: s3.latex.replacen(from, to, 1),
        ..s3.clone()
    };
    // The old writer's left sides: the mass of solid 1, or the zero mass of solid 2.
    for bad in [
        wrong("\\wedge m_{3}\\,", "\\wedge m_{1}\\,"),
        wrong("\\wedge m_{3}\\,", "\\wedge 0\\,"),
        wrong("V(G/", "V(A/"),
        wrong("V(A/", "V(G/"),
        wrong("\\mathcal{R}_{0}", "\\mathcal{R}_{1}"),
    ] {
        assert!(check(&ctx, &bad).is_err(), "not caught: {}", bad.latex);
    }
    // Recorded as the term of another solid, the right left side is refused too.
    let other = Display {
        solid: Some("1".into()),
        ..s3.clone()
    };
    assert!(check(&ctx, &other).is_err());
    // And a complementary term recorded without its solid is refused, not skipped.
    let unnamed = Display {
        solid: None,
        ..s3.clone()
    };
    assert!(check(&ctx, &unnamed).is_err());
    // The massless body: said so, never derived, never « masse ponctuelle ».
    assert!(key.tex.contains("est de masse négligeable"));
    assert!(!key.tex.contains("masse ponctuelle"), "{}", key.tex);
    assert!(!key.tex.contains("\\wedge 0\\,"), "{}", key.tex);
}
