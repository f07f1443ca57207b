//! Which components of its torsor a perfect link transmits, in the basis of its axis.

use crate::frame::Axis;
use crate::wire::LinkKind;

/// Which of the six components (X, Y, Z, L, M, N in the link's basis) a perfect link
/// transmits, given its axis (or normal) `a` and, for a line contact, its direction `d`; with
/// Coulomb's law on its unknowns, also the tangential force along its sliding direction
/// `sliding`.
pub fn transmitted(k: LinkKind, a: Axis, d: Option<Axis>, sliding: Option<Axis>) -> [bool; 6] {
    let mut t = perfect(k, a, d);
    if let Some(s) = sliding {
        t[s.index()] = true;
    }
    t
}

/// What a perfect link transmits (see [`transmitted`]).
fn perfect(k: LinkKind, a: Axis, d: Option<Axis>) -> [bool; 6] {
    let i = a.index();
    let mut t = [true; 6];
    match k {
        LinkKind::Fixed => {}
        // A helical link's axial moment is no unknown of its own: −p/(2π) times the axial
        // resultant (added with the torsor, `spec::dynamics`).
        LinkKind::Pivot | LinkKind::Helical => t[3 + i] = false,
        LinkKind::Slider => t[i] = false,
        LinkKind::PivotSlider => {
            t[i] = false;
            t[3 + i] = false;
        }
        LinkKind::Ball => t[3..].iter_mut().for_each(|x| *x = false),
        LinkKind::Plane => {
            for k in 0..3 {
                t[k] = k == i;
            }
            t[3 + i] = false;
        }
        LinkKind::Annular => {
            t[i] = false;
            t[3..].iter_mut().for_each(|x| *x = false);
        }
        LinkKind::Line => {
            let d = d.map(|d| d.index()).unwrap_or((i + 1) % 3);
            let third = 3 - i - d;
            for k in 0..3 {
                t[k] = k == i;
                t[3 + k] = k == third;
            }
        }
        LinkKind::Point => {
            for k in 0..6 {
                t[k] = k == i;
            }
        }
    }
    t
}
