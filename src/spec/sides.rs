//! What the PFD sections and Coulomb's law both read on the validated mechanism: the side of
//! a link or an action, its frame, and a constant.

use super::SpecError;
use super::refusal::{at, expr_err};
use crate::expr::{Expr, Registry};
use crate::frame::FrameId;
use crate::mechanism::{BodyId, Mechanism};
use crate::pfd::Source;
use crate::resolve::Side;
use std::rc::Rc;

/// A constant of the spec (parameters only), refused at `path` otherwise.
pub(super) fn constant(reg: &Rc<Registry>, path: &str, text: &str) -> Result<Expr, SpecError> {
    let e = reg.parse(text).map_err(|e| expr_err(path, e))?;
    if !e.is_time_independent() {
        return Err(at(path, "a constant is expected (parameters only)"));
    }
    Ok(e)
}

pub(super) fn frame_of_side(m: &Mechanism, s: &Source) -> FrameId {
    match s {
        Source::Body(b) => m.body(*b).frame,
        Source::Outside => m.frames.ground(),
    }
}

/// The side of a link or an action, as resolved.
pub(super) fn source(s: Side) -> Source {
    match s {
        Side::Ground => Source::Outside,
        Side::Solid(b) => Source::Body(BodyId(b)),
    }
}
