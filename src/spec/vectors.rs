//! Basis vectors and their names: the course's x1, y1, z1, and the names a statement gives
//! them ((u, v, w), (i, j, k)).

use super::SpecError;
use super::validate::at;
use crate::frame::Frames;
use crate::wire::SpecFile;
use std::collections::HashSet;

/// The message refusing a scalar named like a basis vector (`x0` when frame `0` exists), if
/// `n` is one: in a vector expression the name could only be read as the basis vector.
pub(super) fn basis_vector_clash(spec: &SpecFile, what: &str, n: &str) -> Option<String> {
    let mut c = n.chars();
    let axis = c.next().filter(|a| matches!(a, 'x' | 'y' | 'z'))?;
    let frame = c.as_str();
    let exists = frame == spec.ground || spec.frames.iter().any(|f| f.name == frame);
    exists.then(|| {
        format!(
            "the {what} `{n}` has the name of the basis vector {axis} of frame {frame}: rename it \
             (a position such as `{n}*{n}` could not tell them apart)"
        )
    })
}

/// Names the basis vectors of the frames whose spec gives them (`ground_basis`, a frame's
/// `basis`): identifiers, not reserved, taken by no parameter, coordinate, alias or other
/// basis vector (`x1` while frame 1 exists).
pub(super) fn name_vectors(
    spec: &SpecFile,
    frames: &mut Frames,
    names: &HashSet<String>,
) -> Result<(), SpecError> {
    let declared = std::iter::once(("ground_basis".to_string(), &spec.ground, &spec.ground_basis))
        .chain(
            spec.frames
                .iter()
                .enumerate()
                .map(|(i, f)| (format!("frames[{i}].basis"), &f.name, &f.basis)),
        );
    let mut vector_names: HashSet<String> = HashSet::new();
    for (path, frame, given) in declared {
        let Some(given) = given else { continue };
        for (k, n) in given.iter().enumerate() {
            let path = format!("{path}[{k}]");
            crate::expr::check_identifier(n).map_err(|m| at(&path, m))?;
            if crate::expr::RESERVED.contains(&n.as_str()) {
                return Err(at(
                    path,
                    format!("`{n}` is reserved by the expression syntax"),
                ));
            }
            if names.contains(n) || !vector_names.insert(n.clone()) {
                return Err(at(
                    path,
                    format!(
                        "`{n}` is already the name of a parameter, a coordinate, an alias or \
                         another basis vector: rename one of them"
                    ),
                ));
            }
            if let Some((f, a)) = frames.basis_vector(n) {
                return Err(at(
                    path,
                    format!(
                        "`{n}` is already the basis vector {} of frame {}",
                        a.letter(),
                        frames.get(f).name
                    ),
                ));
            }
        }
        let f = frames.find(frame).expect("placed");
        frames.name_vectors(f, given.clone());
    }
    Ok(())
}
