//! The statement's typed data, read once from the spec as written: the links as the course
//! describes them, the loop closures and the dependent coordinates, the paramétrage's
//! descriptions, the questions and the scenarios (see [`crate::mechanism::Statement`]).

use super::SpecError;
use super::refusal::{at, expr_err, name_ok};
use super::solved::Solved;
use crate::expr::Registry;
use crate::frame::Frames;
use crate::mechanism::{
    Closure, Coordinate, Dependent, DeterminedBy, Equation, Hypothesis, Link, LinkSpring, Question,
    Statement,
};
use crate::quantity::Quantity;
use crate::wire::{LinkSpec, SpecFile};
use std::rc::Rc;

/// The statement's words and questions, the questions' hypotheses known and their quantities
/// and equations readable (they are resolved once the mechanism is built).
pub(super) fn statement(
    spec: &SpecFile,
    reg: &Rc<Registry>,
    hypotheses: &[Hypothesis],
) -> Result<Statement, SpecError> {
    let coordinates = (spec.coordinates.iter())
        .map(|c| Coordinate {
            name: c.name.clone(),
            coord: reg.coord(&c.name),
            description: c.description.clone(),
            constant: c.rate.as_deref().is_some_and(|r| r.trim() == "0"),
        })
        .collect();
    let questions = (spec.questions.iter().enumerate())
        .map(|(i, q)| question(q, &format!("questions[{i}]"), hypotheses))
        .collect::<Result<_, _>>()?;
    Ok(Statement {
        coordinates,
        aliases: spec.aliases.iter().map(|a| a.description.clone()).collect(),
        questions,
        scenarios: spec.scenarios.clone(),
        free_texts: (crate::wire::free_texts(spec).into_iter())
            .map(|(path, text)| (path, text.to_string()))
            .collect(),
    })
}

/// The position of the hypothesis `h`, refused at `path` when none has its name.
fn hypothesis(h: &str, path: String, hypotheses: &[Hypothesis]) -> Result<usize, SpecError> {
    hypotheses.iter().position(|x| x.name == h).ok_or_else(|| {
        let declared: Vec<&str> = hypotheses.iter().map(|x| x.name.as_str()).collect();
        let hint = crate::hint::suggestion(h, &declared);
        at(path, format!("unknown hypothesis `{h}`{hint}"))
    })
}

/// A question at `path`: its hypotheses by position, its quantities and equations read.
fn question(
    q: &crate::wire::QuestionSpec,
    path: &str,
    hypotheses: &[Hypothesis],
) -> Result<Question, SpecError> {
    let stated = (q.hypotheses.iter().enumerate())
        .map(|(k, h)| hypothesis(h, format!("{path}.hypotheses[{k}]"), hypotheses))
        .collect::<Result<_, _>>()?;
    let under = (q.under.as_deref())
        .map(|h| hypothesis(h, format!("{path}.under"), hypotheses))
        .transpose()?;
    let quantities = (q.quantities.iter().enumerate())
        .map(|(k, t)| {
            Quantity::parse(t).map_err(|e| at(format!("{path}.quantities[{k}]"), e.to_string()))
        })
        .collect::<Result<_, _>>()?;
    let mut equations = Vec::new();
    for (k, e) in q.equations.iter().enumerate() {
        name_ok(&format!("{path}.equations[{k}].lhs"), &e.lhs)?;
        let quantity = Quantity::parse(&e.quantity)
            .map_err(|er| at(format!("{path}.equations[{k}].quantity"), er.to_string()))?;
        equations.push(Equation {
            lhs: e.lhs.clone(),
            quantity,
            reason: e.reason.clone(),
        });
    }
    Ok(Question {
        title: q.title.clone(),
        statement: q.statement.clone(),
        answer: q.answer.clone(),
        hypotheses: stated,
        under,
        quantities,
        equations,
        simulation: q.simulation.clone(),
    })
}

/// The links as the statement describes them, their expressions read.
pub(super) fn links(spec: &SpecFile, reg: &Rc<Registry>) -> Result<Vec<Link>, SpecError> {
    (spec.links.iter().enumerate())
        .map(|(i, l)| link(l, &format!("links[{i}]"), reg))
        .collect()
}

/// One link at `path`.
fn link(l: &LinkSpec, path: &str, reg: &Rc<Registry>) -> Result<Link, SpecError> {
    let read = |what: &str, t: Option<&str>| {
        t.map(|t| {
            reg.parse(t)
                .map_err(|e| expr_err(&format!("{path}.{what}"), e))
        })
        .transpose()
    };
    let spring = match &l.spring {
        Some(sp) => Some(LinkSpring {
            stiffness: reg
                .parse(&sp.stiffness)
                .map_err(|e| expr_err(&format!("{path}.spring.stiffness"), e))?,
            torsion: reg.angle(&sp.coordinate).is_some(),
        }),
        None => None,
    };
    let pitch = l.pitch.as_deref().map(str::trim);
    Ok(Link {
        name: l.name.clone(),
        kind: l.kind,
        between: l.between.clone(),
        point: l.point.clone(),
        axis: l.axis.clone(),
        direction: l.direction.clone(),
        pitch: pitch.and_then(|t| reg.parse(t).ok()),
        pitch_name: (pitch.filter(|n| crate::expr::validate_identifier(n).is_ok()))
            .map(str::to_string),
        dependent: l.dependent.as_deref().and_then(|n| reg.coord(n)),
        viscous: read("friction", l.friction.as_deref())?,
        dry: read("coulomb", l.coulomb.as_deref())?,
        coefficient: read(
            "contact_friction.coefficient",
            l.contact_friction.as_ref().map(|c| c.coefficient.as_str()),
        )?,
        sign: read("name", l.sign_parameter().as_deref())?,
        spring,
        label: l.label(),
    })
}

/// The loop closures, each vector read with the mechanism's bases.
pub(super) fn closures(
    spec: &SpecFile,
    reg: &Rc<Registry>,
    frames: &Frames,
) -> Result<Vec<Closure>, SpecError> {
    let bv = |s: &str| frames.basis_vector(s).map(|(f, a)| (f, a.index()));
    let mut out = Vec::new();
    for (i, c) in spec.closures.iter().enumerate() {
        let parts = (reg.parse_vector(&c.vector, &bv))
            .map_err(|e| expr_err(&format!("closures[{i}].vector"), e))?;
        let mut vector = crate::vector::Vector::zero();
        for (f, comps) in parts {
            vector.add_part(f, comps);
        }
        out.push(Closure {
            written: c.vector.clone(),
            vector,
            dependent: c.dependent.iter().filter_map(|n| reg.coord(n)).collect(),
        });
    }
    Ok(out)
}

/// The dependent coordinates: the closures', the rolling conditions', then those of the
/// helical links the loop law states (`solved`), each with what determines it.
pub(super) fn dependent(
    spec: &SpecFile,
    reg: &Rc<Registry>,
    solved: Option<&Solved>,
) -> Vec<Dependent> {
    let of = |names: &[String], by: DeterminedBy| -> Vec<Dependent> {
        (names.iter().filter_map(|n| reg.coord(n)))
            .map(|coord| Dependent { coord, by })
            .collect()
    };
    let closures = (spec.closures.iter()).flat_map(|c| of(&c.dependent, DeterminedBy::Closure));
    let rolling = (spec.rolling.iter()).flat_map(|r| {
        let whole = r.on.is_empty();
        of(&r.dependent, DeterminedBy::Rolling { whole })
    });
    let helical = (solved.map_or(&[][..], |s| &s.helical[..]).iter()).filter_map(|h| {
        let n = spec.links.get(h.link)?.dependent.as_deref()?;
        let coord = reg.coord(n)?;
        Some(Dependent {
            coord,
            by: DeterminedBy::Helical(h.link),
        })
    });
    closures.chain(rolling).chain(helical).collect()
}
