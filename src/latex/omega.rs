//! Ω by the composition of rotations along the frames, as the corrigé states it.

use super::quantity_tex;
use crate::frame::FrameId;
use crate::mechanism::{DeterminedBy, Mechanism};
use crate::quantity::{Motion, QuantityKind};

/// `\overrightarrow{\Omega(2/1)}` from frame names.
pub(super) fn omega_of(a: &str, b: &str) -> String {
    quantity_tex(&QuantityKind::Omega(Motion {
        moving: a.to_string(),
        reference: b.to_string(),
    }))
}

/// The frames from `f` up to `r` (both included), when `r` is an ancestor of `f`.
pub(super) fn chain(m: &Mechanism, f: FrameId, r: FrameId) -> Option<Vec<FrameId>> {
    let mut out = vec![f];
    let mut cur = f;
    while cur != r {
        cur = m.frames.get(cur).parent?;
        out.push(cur);
    }
    Some(out)
}

/// What gives the rate of a coordinate that a loop closure, a rolling condition or a screw
/// determines, in the course's words (« la loi entrée-sortie »); `None` for another.
pub(super) fn rate_source(m: &Mechanism, q: crate::expr::CoordId) -> Option<&'static str> {
    match m.determined_by(q)? {
        DeterminedBy::Closure => Some("la loi entrée-sortie"),
        DeterminedBy::Helical(_) => Some("la liaison hélicoïdale"),
        by => by.rolling_name(),
    }
}

/// « Composition des vitesses de rotation : Ω(2/0) = Ω(2/1) + Ω(1/0) » along the frames that
/// turn, through their common ancestor when neither frame holds the other (Ω(2/1) =
/// Ω(2/0) + Ω(0/1)), or « D'après le paramétrage » for one rotation.
pub(super) fn omega_sentence(m: &Mechanism, mo: &Motion) -> String {
    let (Some(f), Some(r)) = (m.frames.find(&mo.moving), m.frames.find(&mo.reference)) else {
        return "Composition des vitesses de rotation :".to_string();
    };
    // Up from f to the first frame that is also an ancestor of r (the root at worst), then
    // down to r: Ω(f/r) = Σ Ω(k/parent k) on f's side + Σ Ω(parent k/k) on r's side.
    let up_r = chain(m, r, m.frames.ground()).unwrap_or_default();
    let Some(up_f) = chain(m, f, m.frames.ground()) else {
        return "Composition des vitesses de rotation :".to_string();
    };
    let Some(c) = up_f.iter().position(|x| up_r.contains(x)) else {
        return "Composition des vitesses de rotation :".to_string();
    };
    let c_in_r = up_r.iter().position(|x| *x == up_f[c]).unwrap_or(0);
    let turns = |a: FrameId, b: FrameId| {
        m.frames.get(a).rotation.is_some() && !crate::kinematics::omega(m, a, b).is_zero(&m.frames)
    };
    let mut turning: Vec<(FrameId, FrameId)> = up_f[..=c]
        .windows(2)
        .filter(|w| turns(w[0], w[1]))
        .map(|w| (w[0], w[1]))
        .collect();
    turning.extend(
        up_r[..=c_in_r]
            .windows(2)
            .rev()
            .filter(|w| turns(w[0], w[1]))
            .map(|w| (w[1], w[0])),
    );
    // A rotation by a coordinate a loop closure (or a rolling condition) determines takes its
    // rate from the loop law (or that condition).
    let source = turning.iter().find_map(|&(a, b)| {
        // The pair's child frame carries the rotation.
        let frame = if m.frames.get(a).parent == Some(b) {
            a
        } else {
            b
        };
        let r = m.frames.get(frame).rotation.as_ref()?;
        rate_source(m, r.angle.coord)
    });
    if turning.len() <= 1 {
        return match source {
            Some(s) => format!("D'après {s} :"),
            None => "D'après le paramétrage :".to_string(),
        };
    }
    let parts: Vec<String> = turning
        .iter()
        .map(|&(a, b)| omega_of(m.frame_name(a), m.frame_name(b)))
        .collect();
    format!(
        "Composition des vitesses de rotation, ${} = {}${} :",
        omega_of(&mo.moving, &mo.reference),
        parts.join(" + "),
        match source {
            Some(s) => format!(", et {s}"),
            None => String::new(),
        }
    )
}
