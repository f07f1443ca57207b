//! The time in expressions: it enters only as a phase Ω t inside sin and cos (a forcing
//! F0 cos(Ω t)), each pulsation Ω a parameter whose phase the registry declares
//! ([`super::RegistryBuilder::phases`]).

use symbolica::atom::AtomView;

/// The name of the time.
pub(super) const TIME: &str = "t";

/// Why the time is refused where it stands.
pub(super) const TIME_IN_PHASES: &str = "the time t enters only as a phase inside sin and cos, \
     Omega*t with Omega a parameter (a pulsation in rad/s), possibly times a number";

/// Whether `v` is the time `t`.
pub(super) fn is_time(v: AtomView) -> bool {
    matches!(v, AtomView::Var(x) if x.get_symbol().get_stripped_name() == TIME)
}

/// Whether `v` holds the time anywhere (`t^2`, `(t + 1)`).
pub(super) fn mentions_time(v: AtomView) -> bool {
    match v {
        AtomView::Var(_) => is_time(v),
        AtomView::Mul(m) => m.iter().any(mentions_time),
        AtomView::Add(a) => a.iter().any(mentions_time),
        AtomView::Pow(p) => {
            let (b, e) = p.get_base_exp();
            mentions_time(b) || mentions_time(e)
        }
        AtomView::Fun(f) => f.iter().any(mentions_time),
        _ => false,
    }
}

/// The pulsations Ω of the phases Ω t written in `s` (`F0*cos(Omega*t)` gives `Omega`), in
/// order of appearance: the names a registry's [`super::RegistryBuilder::phases`] declares. A text
/// that does not parse has none (its error comes when it is read).
///
/// ```
/// assert_eq!(torseur::expr::pulsations_in("a*cos(Omega*t)*y0 + b*sin(2*w*t - theta)*x1"),
///            ["Omega", "w"]);
/// ```
pub fn pulsations_in(s: &str) -> Vec<String> {
    fn walk(v: AtomView, out: &mut Vec<String>) {
        match v {
            AtomView::Mul(m) if m.iter().any(|f| is_time(f)) => {
                for f in m.iter() {
                    if let AtomView::Var(x) = f {
                        let n = super::words::typed_name(x.get_symbol());
                        if n != TIME && !out.contains(&n) {
                            out.push(n);
                        }
                    }
                }
            }
            AtomView::Mul(m) => m.iter().for_each(|f| walk(f, out)),
            AtomView::Add(a) => a.iter().for_each(|f| walk(f, out)),
            AtomView::Pow(p) => walk(p.get_base_exp().0, out),
            AtomView::Fun(f) => f.iter().for_each(|a| walk(a, out)),
            _ => {}
        }
    }
    let mut out = Vec::new();
    if super::lexical::names_in(s)
        .iter()
        .any(|&(a, b, _)| &s[a..b] == TIME)
        && let Ok(a) = super::lexical::parse_checked(s)
    {
        walk(a.as_view(), &mut out);
    }
    out
}
