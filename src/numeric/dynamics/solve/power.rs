//! Powers from the definition, P(from→on/R) = Σ R·V(P∈S/R) + M(P)·Ω(S/R), affine in the
//! unknowns, and the power of the interior actions.

use super::*;

/// A power affine in the unknowns, c + Σ aₖ uₖ, summed action by action: the unknowns of a
/// perfect link cancel between an action and its reaction, so a coefficient is read once the
/// sum is complete.
pub(super) struct PowerSum {
    /// The part without unknowns.
    pub(super) c: f64,
    /// The coefficient of each unknown.
    pub(super) a: Vec<f64>,
    /// The largest term summed, for the rounding noise of a cancelled coefficient.
    pub(super) size: f64,
}

impl PowerSum {
    pub(super) fn new(n: usize) -> Self {
        PowerSum {
            c: 0.0,
            a: vec![0.0; n],
            size: 0.0,
        }
    }

    /// Adds T ⊗ {Ω, V}: R·V + M·Ω, affine in the unknowns.
    pub(super) fn add(
        &mut self,
        r: &Lin<Vector3<f64>>,
        mo: &Lin<Vector3<f64>>,
        v: &Vector3<f64>,
        w: &Vector3<f64>,
    ) {
        let c = r.c.dot(v) + mo.c.dot(w);
        self.size = self.size.max(c.abs());
        self.c += c;
        for k in 0..self.a.len() {
            let x = r.a[k].dot(v) + mo.a[k].dot(w);
            self.size = self.size.max(x.abs());
            self.a[k] += x;
        }
    }

    /// The value at the unknowns `unknowns`: an error naming an unknown that appears (above
    /// the rounding noise) without a value.
    pub(super) fn value(
        &self,
        m: &NumericModel,
        unknowns: &BTreeMap<String, f64>,
        what: &str,
    ) -> Result<f64, NumericError> {
        let mut p = self.c;
        for (k, a) in self.a.iter().enumerate() {
            if a.abs() <= APPEARS * self.size.max(1.0) {
                continue;
            }
            let name = &m.dynamics.unknowns[k];
            let u = unknowns.get(name).ok_or_else(|| NumericError::Quantity {
                quantity: what.to_string(),
                message: format!("no value for the unknown `{name}`"),
            })?;
            p += a * u;
        }
        Ok(p)
    }
}

/// P(from→on/R), from the definition: every action `from` exerts on a member of `on` from
/// outside it, R·V(P∈S/R) + M(P)·Ω(S/R) at its point P, and for `pes` or `ext` the weight of
/// every point mass, mₖ g⃗·V(Pₖ∈S/R).
#[allow(clippy::too_many_arguments)]
pub(in crate::numeric) fn power(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    from: &str,
    on: &[usize],
    on_name: &str,
    reference: usize,
    unknowns: &BTreeMap<String, f64>,
) -> Result<f64, NumericError> {
    let member = |b: Body| matches!(b, Body::Solid(s) if on.contains(&s));
    let what = format!("P({from}->{on_name})");
    let mut sum = PowerSum::new(m.dynamics.unknowns.len());
    let mut found = false;
    for t in terms(m, st, vals)? {
        if !member(t.on) || member(t.from) || (from != "ext" && t.names[0] != from) {
            continue;
        }
        let f = body_frame(m, t.on);
        let v = kin::velocity_at(st, f, &t.point, reference);
        let w = kin::omega(st, f, reference);
        sum.add(&t.resultant, &t.moment, &v, &w);
        found = true;
    }
    if (from == "pes" || from == "ext") && m.dynamics.gravity.is_some() {
        let g = gravity(m, st, vals)?;
        for s in on {
            let f = m.solids[*s].frame;
            let (rf, of) = (st.rot0(f), st.origin(f).map(|x| x.re));
            for (mk, local) in cloud::solid_cloud(m, st, vals, *s)? {
                let v = kin::velocity_at(st, f, &(of + rf * local), reference);
                sum.c += (g * mk).dot(&v);
            }
        }
        found = true;
    }
    // `ext` on a solid that receives nothing is the zero torsor, as the exact side has it.
    if !found && from != "ext" {
        return Err(NumericError::Quantity {
            quantity: what,
            message: format!("no action of `{from}` on `{on_name}`"),
        });
    }
    sum.value(m, unknowns, &what)
}

/// P_int(E), from the definition: every action between two members, and its reaction, at
/// their common point P, each R·V(P∈receiver/R0) + M(P)·Ω(receiver/R0); an action and its
/// reaction sum to {T(i→j)} ⊗ {V(j/i)}.
pub(in crate::numeric) fn internal_power(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    on: &[usize],
    unknowns: &BTreeMap<String, f64>,
) -> Result<f64, NumericError> {
    let member = |b: Body| matches!(b, Body::Solid(s) if on.contains(&s));
    let mut sum = PowerSum::new(m.dynamics.unknowns.len());
    for t in terms(m, st, vals)? {
        if !(member(t.on) && member(t.from)) {
            continue;
        }
        let f = body_frame(m, t.on);
        let v = kin::velocity_at(st, f, &t.point, 0);
        let w = kin::omega(st, f, 0);
        sum.add(&t.resultant, &t.moment, &v, &w);
    }
    sum.value(m, unknowns, "Pint")
}
