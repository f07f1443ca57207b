//! A derived value written for the page: a vector as a sum over its basis vectors or a column,
//! an inertia matrix, a torsor, a scalar within a line's width.

use super::*;

/// Whether most terms of the presentation form are negative (a product counts once).
fn mostly_negative(p: &crate::expr::Presentation) -> bool {
    let t = &p.form().terms;
    t.len() > 1 && 2 * t.iter().filter(|p| p.coef.is_negative()).count() > t.len()
}

/// A vector as a sum over its basis vectors, one line per component when long, inside an
/// `aligned` block: `\left(...\right)\vec{x}_2 + ...`.
pub fn vector_sum(
    m: &Mechanism,
    lhs: &str,
    basis_frame: &str,
    c: &[Expr; 3],
    max: usize,
) -> String {
    let _ = m;
    plain(&vector_sum_with(
        &VectorNames::default(),
        lhs,
        basis_frame,
        c,
        max,
    ))
}

/// [`vector_sum`], the basis vectors by the statement's names.
fn vector_sum_with(
    names: &VectorNames,
    lhs: &str,
    basis_frame: &str,
    c: &[Expr; 3],
    max: usize,
) -> String {
    let lines = sum_lines(names, basis_frame, c, max);
    if lines.is_empty() {
        return format!("{lhs} &= \\TVec{{0}}");
    }
    let total: usize = lines.iter().map(|l| width(l)).sum();
    if total <= max && lines.iter().all(|l| !l.contains("\\Big")) {
        return format!("{lhs} &= {}", lines.join(" "));
    }
    let mut out = format!("{lhs} &= {}", lines[0]);
    for l in &lines[1..] {
        out.push_str(&format!(" \\\\\n&\\phantom{{=}} {l}"));
    }
    out
}

/// The lines of a vector's sum over its basis vectors, none for the zero vector.
fn sum_lines(names: &VectorNames, basis_frame: &str, c: &[Expr; 3], max: usize) -> Vec<String> {
    let axes = ['x', 'y', 'z'];
    let mut lines: Vec<String> = Vec::new();
    for k in 0..3 {
        if c[k].is_zero() {
            continue;
        }
        let bv = names.basis_vector(axes[k], basis_frame);
        lines.extend(component_lines(&c[k], &bv, lines.is_empty(), max));
    }
    lines
}

/// A vector's sum over its basis vectors on one line (`\dot{\theta}\,\vec{z}_{0}`, `\vec{0}`
/// for zero), when it holds in `max` characters.
pub(super) fn vector_line(
    names: &VectorNames,
    basis_frame: &str,
    c: &[Expr; 3],
    max: usize,
) -> Option<String> {
    let lines = sum_lines(names, basis_frame, c, max);
    if lines.is_empty() {
        return Some("\\TVec{0}".to_string());
    }
    let one = lines.join(" ");
    (width(&one) <= max && !one.contains("\\Big")).then_some(one)
}

/// The lines of a vector sum (see [`vector_sum`]) that its nonzero component `e` along the
/// basis vector `bv` adds (`first`: it opens the sum); more than one when long.
pub(super) fn component_lines(e: &Expr, bv: &str, first: bool, max: usize) -> Vec<String> {
    let mut lines = Vec::new();
    // A sum whose terms are mostly negative is written − [...] (− [(L1 + L2 cos θ2) θ̇1²
    // cos θ2 + L2 θ̇2²] y2, not + (−(L1 + L2 cos θ2) θ̇1² cos θ2 − L2 θ̇2²) y2).
    let own = e.presentation();
    let negated = mostly_negative(&own);
    let shown = if negated { (-e).presentation() } else { own };
    let ls = expr::presentation_lines(&shown, max);
    // One product (a group that is not a bare sum) multiplies the basis vector without
    // parentheses; anything else is parenthesised.
    let single_term = shown.form().terms.len() == 1;
    let sign = match (first, negated) {
        (true, false) => "",
        (true, true) => "-",
        (false, false) => "+ ",
        (false, true) => "- ",
    };
    let (open_p, close_p) = if ls.iter().any(|l| l.contains("\\left(")) {
        ("\\left[", "\\right]")
    } else {
        ("\\left(", "\\right)")
    };
    if ls.len() == 1 && single_term {
        // The product's own sign and the sign taken out combine.
        let (inner_neg, body) = match ls[0].strip_prefix('-') {
            Some(b) => (true, b),
            None => (false, ls[0].as_str()),
        };
        let s = match (first, negated != inner_neg) {
            (true, false) => body.to_string(),
            (true, true) => format!("-{body}"),
            (false, false) => format!("+ {body}"),
            (false, true) => format!("- {body}"),
        };
        lines.push(format!("{s}\\,{bv}"));
    } else if ls.len() == 1 {
        lines.push(format!("{sign}{open_p}{}{close_p}{bv}", ls[0]));
    } else {
        let n = ls.len();
        for (i, l) in ls.into_iter().enumerate() {
            let open = if i == 0 {
                format!("{sign}\\Big(")
            } else {
                "\\quad ".to_string()
            };
            let close = if i + 1 == n {
                format!("\\Big)\\,{bv}")
            } else {
                String::new()
            };
            lines.push(format!("{open}{l}{close}"));
        }
    }
    lines
}

/// A short vector as a column with its basis as subscript.
pub fn vector_column(basis_frame: &str, c: &[Expr; 3]) -> String {
    format!(
        "\\begin{{pmatrix}} {} \\\\ {} \\\\ {} \\end{{pmatrix}}_{{{}}}",
        expr(&c[0]),
        expr(&c[1]),
        expr(&c[2]),
        basis(basis_frame)
    )
}

/// An inertia matrix with its point and basis.
pub fn matrix(m: &Mechanism, i: &crate::inertia::Inertia) -> String {
    let rows: Vec<String> = i
        .matrix
        .iter()
        .map(|r| r.iter().map(expr).collect::<Vec<_>>().join(" & "))
        .collect();
    format!(
        "\\begin{{pmatrix}} {} \\end{{pmatrix}}_{{{}}}",
        rows.join(" \\\\ "),
        basis(m.frame_name(i.basis))
    )
}

/// A matrix too wide for a line: named entries I_xx, I_xy... in the matrix, then each
/// non-trivial entry on its own line (lines of an `align*`).
fn matrix_named(m: &Mechanism, lhs: &str, i: &crate::inertia::Inertia) -> String {
    let ax = ['x', 'y', 'z'];
    let mut cells: Vec<Vec<String>> = vec![vec![String::new(); 3]; 3];
    let mut defs = Vec::new();
    for r in 0..3 {
        for c in 0..3 {
            let e = &i.matrix[r][c];
            let short = expr(e);
            cells[r][c] = if e.nterms() <= 1 && width(&short) <= 8 {
                short
            } else {
                let n = format!("I_{{{}{}}}", ax[r.min(c)], ax[r.max(c)]);
                if r <= c {
                    defs.push(format!(
                        "{n} &= {}",
                        expr_lines(e, LINE).join(" \\\\\n&\\phantom{=} ")
                    ));
                }
                n
            };
        }
    }
    let rows: Vec<String> = cells.iter().map(|r| r.join(" & ")).collect();
    let mut out = format!(
        "{lhs} &= \\begin{{pmatrix}} {} \\end{{pmatrix}}_{{{}}}",
        rows.join(" \\\\ "),
        basis(m.frame_name(i.basis))
    );
    for d in defs {
        out.push_str(&format!(" \\\\\n{d}"));
    }
    out
}

/// A value on the right of `lhs`, as lines of an `align*` environment (vectors as sums), the
/// basis vectors named as the mechanism's statement names them (`basis` of a frame), as the
/// answer key writes them.
pub fn value(m: &Mechanism, lhs: &str, v: &Value) -> String {
    value_styled(m, VectorStyle::Sum, lhs, v)
}

/// A value on the right of `lhs`, with vectors in the given style.
pub fn value_styled(m: &Mechanism, style: VectorStyle, lhs: &str, v: &Value) -> String {
    value_named(m, style, lhs, v, None)
}

/// [`value_styled`], naming the resultant and the moment of a long torsor as the course does
/// (`\overrightarrow{R_d(2/0)}` and `\overrightarrow{\delta(O_2,2/0)}` for a dynamic torsor);
/// `\vec{R}` and `\vec{M}(P)` without names.
pub fn value_named(
    m: &Mechanism,
    style: VectorStyle,
    lhs: &str,
    v: &Value,
    torsor_names: Option<(&str, &str)>,
) -> String {
    plain(&value_within(
        m,
        &VectorNames::of(m),
        style,
        lhs,
        v,
        torsor_names,
        LINE,
    ))
}

/// The width left for the right side of `lhs` on a line of `line` characters: a wide left
/// side (a derivative, a long name) takes its share.
fn room(lhs: &str, line: usize) -> usize {
    line.saturating_sub(width(lhs).saturating_sub(14)).max(28)
}

/// [`value_named`] on lines of at most `line` characters (a boxed result has less room), the
/// basis vectors by the statement's `names`.
pub(super) fn value_within(
    m: &Mechanism,
    names: &VectorNames,
    style: VectorStyle,
    lhs: &str,
    v: &Value,
    torsor_names: Option<(&str, &str)>,
    line: usize,
) -> String {
    let max = room(lhs, line);
    if let (
        VectorStyle::Column,
        Value::Vector {
            basis: b,
            components,
        },
    ) = (style, v)
    {
        let col = vector_column(m.frame_name(*b), components);
        if components.iter().all(|c| width(&expr(c)) <= max) {
            return format!("{lhs} &= {col}");
        }
    }
    match v {
        Value::Quotient(q) => format!("{lhs} &= {}", fraction(q)),
        Value::Scalar(e) => {
            let ls = expr_lines(e, max);
            let mut out = format!("{lhs} &= {}", ls[0]);
            for l in &ls[1..] {
                out.push_str(&format!(" \\\\\n&\\phantom{{=}} {l}"));
            }
            out
        }
        Value::Vector {
            basis: b,
            components,
        } => vector_sum_with(names, lhs, m.frame_name(*b), components, max),
        Value::Matrix(i) => {
            let mx = matrix(m, i);
            if width(&mx) > max + 20 {
                matrix_named(m, lhs, i)
            } else {
                format!("{lhs} &= {mx}")
            }
        }
        Value::Torsor {
            point: p,
            basis: b,
            resultant,
            moment,
        } => torsor_value(
            m,
            names,
            lhs,
            (*p, *b),
            [resultant, moment],
            torsor_names,
            line,
        ),
    }
}

/// A torsor's value on the right of `lhs` (see [`value_within`]): the zero torsor, a short
/// torsor as its two columns, a long one as its two elements, each a vector sum.
fn torsor_value(
    m: &Mechanism,
    names: &VectorNames,
    lhs: &str,
    (p, b): (crate::point::PointId, crate::frame::FrameId),
    [resultant, moment]: [&[Expr; 3]; 2],
    torsor_names: Option<(&str, &str)>,
    line: usize,
) -> String {
    let short = resultant
        .iter()
        .chain(moment.iter())
        .all(|e| e.nterms() <= 1);
    let pn = point(m.point_name(p));
    if resultant.iter().chain(moment.iter()).all(|e| e.is_zero()) {
        // The zero torsor, as the course writes it.
        return format!("{lhs} &= \\left\\{{ 0 \\right\\}}");
    }
    if short {
        let rows: Vec<String> = (0..3)
            .map(|k| format!("{} & {}", expr(&resultant[k]), expr(&moment[k])))
            .collect();
        format!(
            "{lhs} &= \\TElements{{{}}}{{{pn}}}{{{}}}",
            rows.join(" \\\\ "),
            basis(m.frame_name(b))
        )
    } else {
        let bn = m.frame_name(b);
        let (rn, mn) = match torsor_names {
            Some((r, mo)) => (r.to_string(), mo.to_string()),
            None => ("\\TVec{R}".to_string(), format!("\\TVec{{M}}({pn})")),
        };
        format!(
            "{}\\\\\n{}",
            vector_sum_with(names, &rn, bn, resultant, room(&rn, line)),
            vector_sum_with(names, &mn, bn, moment, room(&mn, line))
        )
    }
}

/// A vector as written in the spec, over the bases of its parts: `d_{1}\,\vec{z}_{0} +
/// L_{1}\,\vec{y}_{1}`.
pub(super) fn vector_over_bases(
    m: &Mechanism,
    names: &VectorNames,
    v: &crate::vector::Vector,
) -> String {
    let parts: Vec<String> = v
        .parts()
        .flat_map(|(b, c)| {
            let bn = m.frame_name(b).to_string();
            (0..3)
                .filter(|&k| !c[k].is_zero())
                .map(|k| {
                    let e = expr(&c[k]);
                    let bv = names.basis_vector(['x', 'y', 'z'][k], &bn);
                    if c[k].nterms() > 1 {
                        format!("\\left({e}\\right){bv}")
                    } else if e == "1" {
                        bv
                    } else if e == "-1" {
                        format!("-{bv}")
                    } else {
                        format!("{e}\\,{bv}")
                    }
                })
                .collect::<Vec<_>>()
        })
        .collect();
    if parts.is_empty() {
        "\\TVec{0}".to_string()
    } else {
        parts.join(" + ").replace("+ -", "- ")
    }
}
