//! Basis vectors and their names: the course's x1, y1, z1, and the names a statement gives
//! them ((u, v, w), (i, j, k)).

use crate::frame::Frames;
use crate::wire::SpecFile;

/// Gives the frames the names their spec declares for their basis vectors (`ground_basis`,
/// a frame's `basis`), as checked by [`crate::resolve`].
pub(super) fn name_vectors(spec: &SpecFile, frames: &mut Frames) {
    let declared = std::iter::once((&spec.ground, &spec.ground_basis))
        .chain(spec.frames.iter().map(|f| (&f.name, &f.basis)));
    for (frame, given) in declared {
        let Some(given) = given else { continue };
        let f = frames.find(frame).expect("placed");
        frames.name_vectors(f, given.clone());
    }
}
