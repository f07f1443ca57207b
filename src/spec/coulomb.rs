//! Coulomb's law on a contact's unknowns (`contact_friction`), validated into the equation
//! the PFD adds: T = −f N ε while the contact slides, f a pure number, ε the sign of the
//! sliding velocity V(P ∈ second/first)·t, which must slide along t and along t only.

use super::SpecError;
use super::refusal::at;
use super::sides::{constant, frame_of_side, source};
use crate::expr::{Expr, VarRole};
use crate::frame::{Axis, FrameId};
use crate::kinematics::velocity;
use crate::mechanism::{BodyId, CoulombLaw, Mechanism};
use crate::point::PointId;
use crate::resolve::{Contact, LinkNode, Unknowns};
use crate::units::Dimension;
use crate::vector::Vector;
use crate::wire::{ParameterKind, SpecFile};

/// The law of the link `i` (`links[i]`), whose transmitted components `comps` hold its T and
/// N: its coefficient checked (constant, no unknown, dimensionless), its sliding velocity
/// along t not zero whatever the motion, and zero across (along n ∧ t).
pub(super) fn law(
    m: &Mechanism,
    (spec, i): (&SpecFile, usize),
    node: &LinkNode,
    c: Contact,
    comps: &[(usize, usize)],
    unknowns: &Unknowns,
) -> Result<CoulombLaw, SpecError> {
    let reg = &m.reg;
    let l = &spec.links[i];
    let friction = l
        .contact_friction
        .as_ref()
        .expect("a link with Coulomb's law");
    let path = format!("links[{i}].contact_friction");
    let field = format!("{path}.coefficient");
    let f = coefficient(m, spec, &field, &friction.coefficient)?;
    let name = |axis: usize| {
        let (_, u) = comps.iter().find(|(k, _)| *k == axis).expect("transmitted");
        unknowns.names[*u].clone()
    };
    let [t, n] = [name(c.tangent), name(c.normal)];
    let value = |u: &str| reg.param(u).expect("unknown registered");
    let sign = l.sign_parameter().expect("a link with friction");
    let eps = reg.parse(&sign).map_err(|e| at(&path, e.to_string()))?;
    let basis = FrameId(node.axis.0);
    let along = |k: usize| Vector::along(basis, Axis::ALL[k], reg.one());
    let (fa, fb) = (
        frame_of_side(m, &source(node.from)),
        m.body(BodyId(node.on)).frame,
    );
    let v = velocity(m, PointId(node.point), fb, fa);
    let rate = v.dot(&m.frames, &along(c.tangent));
    let names = (&l.between[1], &l.between[0], &l.point);
    if rate.is_zero() {
        let why = format!(
            "the sliding velocity V({},{}/{}) along the tangent is zero whatever the motion: \
             nothing slides",
            names.2, names.0, names.1
        );
        return Err(at(path, why));
    }
    let across = 3 - c.tangent - c.normal;
    if !v.dot(&m.frames, &along(across)).is_zero() {
        let why = format!(
            "V({},{}/{}) also has a component across the tangent, along {}{}: Coulomb's law \
             along the tangent alone would not oppose the sliding",
            names.2,
            names.0,
            names.1,
            ['x', 'y', 'z'][across],
            m.frame_name(basis)
        );
        return Err(at(path, why));
    }
    Ok(CoulombLaw {
        link: i,
        values: [value(&t), value(&n)],
        unknowns: [t, n],
        coefficient: f,
        sign: eps,
        directions: [(basis, Axis::ALL[c.tangent]), (basis, Axis::ALL[c.normal])],
        rate,
    })
}

/// The friction coefficient: a constant expression with no unknown of the PFD, whose
/// parameters are pure numbers (unit `1`, or angles), and not a negative number.
fn coefficient(m: &Mechanism, spec: &SpecFile, path: &str, text: &str) -> Result<Expr, SpecError> {
    let reg = &m.reg;
    let f = constant(reg, path, text)?;
    let occurs = f.occurring();
    for v in reg.var_ids().filter(|v| occurs[v.index()]) {
        let VarRole::Parameter(p) = reg.role(v) else {
            continue;
        };
        let n = reg.scalar_name(p);
        if reg.is_unknown(p) {
            let why = format!("the coefficient holds the unknown `{n}`: f is a given number");
            return Err(at(path, why));
        }
        let Some(spec_p) = spec.parameters.iter().find(|q| q.name == n) else {
            continue;
        };
        let unit = spec_p.unit.as_deref().map(Dimension::parse);
        if spec_p.kind == ParameterKind::Scalar
            && let Some(Ok(d)) = unit
            && d != Dimension::NONE
        {
            let why = format!(
                "a friction coefficient is a pure number: `{n}` is in {}",
                spec_p.unit.as_deref().unwrap_or_default()
            );
            return Err(at(path, why));
        }
    }
    if f.as_rational().is_some() && f.reads_negative() {
        return Err(at(path, "a friction coefficient is not negative"));
    }
    Ok(f)
}

/// A hypothesis that sets the sign ε of a link's dry friction (the limit of sliding, the
/// impending motion's sign given) sets it to 1 or −1.
pub(super) fn signs(
    spec: &SpecFile,
    reg: &std::rc::Rc<crate::expr::Registry>,
    h: &crate::wire::HypothesisSpec,
    path: &str,
) -> Result<(), SpecError> {
    for (p, text) in &h.relations {
        if !(spec.links.iter()).any(|l| l.sign_parameter().as_deref() == Some(p.as_str())) {
            continue;
        }
        let field = format!("{path}.relations.{p}");
        let e = reg.parse(text).map_err(|e| at(&field, e.to_string()))?;
        if e != reg.one() && e != -&reg.one() {
            let why = format!("`{p}` is the sign of a sliding velocity: it is set to 1 or -1");
            return Err(at(field, why));
        }
    }
    Ok(())
}
