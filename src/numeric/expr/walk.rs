//! Walks over a parsed expression's tree: the names it uses, whether it holds the time, the
//! PFD's unknowns taken out or their coefficient and degree.

use super::Node;

/// Calls `f` on every leaf of `node` (numbers, names, basis vectors, the time).
fn leaves(node: &Node, f: &mut impl FnMut(&Node)) {
    match node {
        Node::Neg(a) | Node::Pow(a, _) | Node::Sin(a) | Node::Cos(a) | Node::Sqrt(a) => {
            leaves(a, f)
        }
        Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => {
            leaves(a, f);
            leaves(b, f)
        }
        leaf => f(leaf),
    }
}

/// Every parameter index `node` uses.
pub(crate) fn params_in(node: &Node, out: &mut std::collections::BTreeSet<usize>) {
    leaves(node, &mut |n| {
        if let Node::Param(i) = n {
            out.insert(*i);
        }
    });
}

/// Every unknown index `node` uses.
pub(crate) fn unknowns_in(node: &Node, out: &mut std::collections::BTreeSet<usize>) {
    leaves(node, &mut |n| {
        if let Node::Unknown(i) = n {
            out.insert(*i);
        }
    });
}

/// Every frame index whose basis vectors `node` uses.
pub(crate) fn frames_in(node: &Node, out: &mut std::collections::BTreeSet<usize>) {
    leaves(node, &mut |n| {
        if let Node::Basis(f, _) = n {
            out.insert(*f);
        }
    });
}

/// Whether `node` depends on time (a coordinate or a rate).
pub(crate) fn depends_on_time(node: &Node) -> bool {
    match node {
        Node::Coord(_) | Node::Rate(..) | Node::Time => true,
        Node::Num(_) | Node::Param(_) | Node::Basis(..) | Node::Unknown(_) => false,
        Node::Neg(a) | Node::Pow(a, _) | Node::Sin(a) | Node::Cos(a) | Node::Sqrt(a) => {
            depends_on_time(a)
        }
        Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => {
            depends_on_time(a) || depends_on_time(b)
        }
    }
}

/// `node` with every unknown set to zero: its part free of unknowns.
pub(crate) fn without_unknowns(node: &Node) -> Node {
    let b = |a: &Node| Box::new(without_unknowns(a));
    match node {
        Node::Unknown(_) => Node::Num(0.0),
        Node::Num(_)
        | Node::Param(_)
        | Node::Coord(_)
        | Node::Rate(..)
        | Node::Basis(..)
        | Node::Time => node.clone(),
        Node::Neg(a) => Node::Neg(b(a)),
        Node::Add(x, y) => Node::Add(b(x), b(y)),
        Node::Sub(x, y) => Node::Sub(b(x), b(y)),
        Node::Mul(x, y) => Node::Mul(b(x), b(y)),
        Node::Div(x, y) => Node::Div(b(x), b(y)),
        Node::Pow(a, n) => Node::Pow(b(a), *n),
        Node::Sin(a) => Node::Sin(b(a)),
        Node::Cos(a) => Node::Cos(b(a)),
        Node::Sqrt(a) => Node::Sqrt(b(a)),
    }
}

/// The coefficient of unknown `k` in a node of degree at most 1 in the unknowns
/// ([`unknown_degree`]): its partial derivative, written as a node free of unknowns.
pub(crate) fn unknown_coefficient(node: &Node, k: usize) -> Node {
    let d = |a: &Node| Box::new(unknown_coefficient(a, k));
    let z = |a: &Node| Box::new(without_unknowns(a));
    match node {
        Node::Unknown(j) => Node::Num(if *j == k { 1.0 } else { 0.0 }),
        Node::Num(_)
        | Node::Param(_)
        | Node::Coord(_)
        | Node::Rate(..)
        | Node::Basis(..)
        | Node::Time => Node::Num(0.0),
        Node::Neg(a) => Node::Neg(d(a)),
        Node::Add(x, y) => Node::Add(d(x), d(y)),
        Node::Sub(x, y) => Node::Sub(d(x), d(y)),
        // Degree at most 1: at most one factor holds unknowns, so the other is taken at zero.
        Node::Mul(x, y) => Node::Add(
            Box::new(Node::Mul(d(x), z(y))),
            Box::new(Node::Mul(z(x), d(y))),
        ),
        // The denominator holds no unknown.
        Node::Div(x, y) => Node::Div(d(x), z(y)),
        Node::Pow(a, n) => match n {
            // Degree at most 1: a power other than 0 or 1 of a node with unknowns is refused.
            1 => *d(a),
            _ => Node::Num(0.0),
        },
        // Their argument holds no unknown.
        Node::Sin(_) | Node::Cos(_) | Node::Sqrt(_) => Node::Num(0.0),
    }
}

/// Degree of `node` in the unknowns, read off its structure, or why the unknowns do not enter
/// polynomially (inside sin or cos, in a denominator, under a negative power). The literal
/// zero has degree 0 like any other number.
pub(crate) fn unknown_degree(node: &Node) -> Result<u32, String> {
    Ok(match node {
        Node::Unknown(_) => 1,
        Node::Num(_)
        | Node::Param(_)
        | Node::Coord(_)
        | Node::Rate(..)
        | Node::Basis(..)
        | Node::Time => 0,
        Node::Neg(a) => unknown_degree(a)?,
        Node::Add(a, b) | Node::Sub(a, b) => unknown_degree(a)?.max(unknown_degree(b)?),
        Node::Mul(a, b) => unknown_degree(a)? + unknown_degree(b)?,
        Node::Div(a, b) => {
            if unknown_degree(b)? > 0 {
                return Err("an unknown divides".into());
            }
            unknown_degree(a)?
        }
        Node::Pow(a, n) => {
            let d = unknown_degree(a)?;
            if d > 0 && *n < 0 {
                return Err("an unknown is raised to a negative power".into());
            }
            d.saturating_mul(n.unsigned_abs())
        }
        Node::Sqrt(a) => {
            if unknown_degree(a)? > 0 {
                return Err("an unknown is inside sqrt".into());
            }
            0
        }
        Node::Sin(a) | Node::Cos(a) => {
            if unknown_degree(a)? > 0 {
                return Err("an unknown is inside sin or cos".into());
            }
            0
        }
    })
}
