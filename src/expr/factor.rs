//! Factors between expressions: division by a number, the constant or parameter factor
//! between two equations (`verify` accepts an equation up to such a factor).

use super::*;

impl Expr {
    /// `self / c` when `c` is a nonzero rational number, none otherwise (the canonical form is
    /// polynomial: it never divides by a variable).
    pub fn div_constant(&self, c: &Expr) -> Option<Expr> {
        let r = c.as_rational()?;
        if r.is_zero() {
            return None;
        }
        Some(self * &self.reg.constant(r.inv()))
    }

    /// The nonzero factor k = numerator / denominator, made of parameters only, with
    /// `self = k · other`; none if there is no such factor (two equations `e = 0` that differ
    /// by such a factor are the same equation wherever it is nonzero).
    ///
    /// « Parameters » are the spec's parameters and the cos and sin of its constant angle
    /// parameters: never a coordinate, a rate or an unknown, so an equation multiplied by q̇
    /// or cos q is another equation. The factor is found exactly: with μ the kinematic part
    /// (coordinates, rates, unknowns) of a term of `other`, n and d the coefficients of μ in
    /// `self` and `other` (polynomials in the parameters, d ≠ 0), `self = (n/d) · other` iff
    /// d · self = n · other, a product of canonical forms compared structurally. n/d is then
    /// reduced by its polynomial gcd, the denominator's first coefficient made 1.
    ///
    /// A relation between parameters only (an equation of motion at a relative equilibrium,
    /// where every coordinate is a parameter) has no kinematic part to pin the factor: any two
    /// such relations are then equal up to their own quotient. There the factor must be a
    /// product of parameters (k, m l, 1/k): k (x_e − l0) + m g sin β = 0 is
    /// x_e = l0 − m g sin β/k, and x_e = l0 + m g sin β/k is another relation.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(&["m".into(), "l".into(), "g".into()],
    ///     &[("q".into(), CoordinateKind::Angle)]).unwrap();
    /// let derived = reg.parse("m*l^2*ddot(q) + m*g*l*sin(q)").unwrap();
    /// let given = reg.parse("l*ddot(q) + g*sin(q)").unwrap();
    /// let (n, d) = derived.parameter_ratio(&given).unwrap();
    /// assert_eq!((n, d), (reg.parse("m*l").unwrap(), reg.one()));
    /// // The other way round, the factor is 1/(m l).
    /// let (n, d) = given.parameter_ratio(&derived).unwrap();
    /// assert_eq!((n, d), (reg.one(), reg.parse("m*l").unwrap()));
    /// // Multiplied by a rate or by cos q, it is another equation.
    /// assert!(derived.parameter_ratio(&(&given * &reg.parse("dot(q)").unwrap())).is_none());
    /// assert!(derived.parameter_ratio(&(&given * &reg.parse("cos(q)").unwrap())).is_none());
    /// ```
    pub fn parameter_ratio(&self, other: &Expr) -> Option<(Expr, Expr)> {
        let theirs = other.by_kinematic_monomial();
        let (mu, d) = theirs.first()?;
        let n = self
            .by_kinematic_monomial()
            .into_iter()
            .find(|(m, _)| m == mu)?
            .1;
        if d * self != &n * other {
            return None;
        }
        let (n, d) = lowest_terms(n, d.clone());
        if !(self.is_kinematic() || other.is_kinematic()) && (n.nterms() > 1 || d.nterms() > 1) {
            return None;
        }
        Some((n, d))
    }

    /// For a report when [`Expr::parameter_ratio`] finds none: the factor k = numerator /
    /// denominator of parameters only for which the most kinematic monomials of `self` and
    /// `k · other` have equal coefficients (a wrong sign in one term leaves the others
    /// agreeing). None when they share no kinematic monomial.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(&["m".into(), "l".into(), "g".into()],
    ///     &[("q".into(), CoordinateKind::Angle)]).unwrap();
    /// let derived = reg.parse("m*l^2*ddot(q) + m*l*dot(q)^2 + m*g*l*sin(q)").unwrap();
    /// let wrong_sign = reg.parse("l*ddot(q) + dot(q)^2 - g*sin(q)").unwrap();
    /// assert!(derived.parameter_ratio(&wrong_sign).is_none());
    /// let (n, d) = derived.closest_parameter_ratio(&wrong_sign).unwrap();
    /// assert_eq!((n, d), (reg.parse("m*l").unwrap(), reg.one()));
    /// ```
    pub fn closest_parameter_ratio(&self, other: &Expr) -> Option<(Expr, Expr)> {
        /// Candidates tried (each is compared with every shared monomial).
        const CANDIDATES: usize = 32;
        let mine = self.by_kinematic_monomial();
        let shared: Vec<(Expr, Expr)> = other
            .by_kinematic_monomial()
            .into_iter()
            .filter_map(|(mu, d)| Some((mine.iter().find(|(m, _)| *m == mu)?.1.clone(), d)))
            .collect();
        // How many monomials n/d makes agree: n · d' = n' · d.
        let agree = |n: &Expr, d: &Expr| shared.iter().filter(|(n2, d2)| n * d2 == n2 * d).count();
        let mut best: Option<(usize, &Expr, &Expr)> = None;
        for (n, d) in shared.iter().take(CANDIDATES) {
            let k = agree(n, d);
            if best.is_none_or(|(b, _, _)| k > b) {
                best = Some((k, n, d));
            }
        }
        let (n, d) = best.map(|(_, n, d)| lowest_terms(n.clone(), d.clone()))?;
        // As in `parameter_ratio`: between relations of parameters only, a factor that is not
        // a product of parameters would make any relation match.
        if !(self.is_kinematic() || other.is_kinematic()) && (n.nterms() > 1 || d.nterms() > 1) {
            return None;
        }
        Some((n, d))
    }

    /// Whether a term holds a coordinate, a rate or an unknown (a kinematic part).
    fn is_kinematic(&self) -> bool {
        self.by_kinematic_monomial()
            .iter()
            .any(|(m, _)| m.iter().any(|&k| k > 0))
    }

    /// The terms grouped by their kinematic part μ (coordinates, rates, unknowns: every
    /// variable but [`Registry::is_factor_variable`]), each with its coefficient, a polynomial
    /// in the parameters; in the order of the canonical form's terms.
    fn by_kinematic_monomial(&self) -> Vec<(Vec<u8>, Expr)> {
        let reg = &self.reg;
        let param: Vec<bool> = reg.var_ids().map(|i| reg.is_factor_variable(i)).collect();
        // (μ, terms of its coefficient: rational and exponents of the parameters).
        type Terms = Vec<(Rational, Vec<u8>)>;
        let mut groups: Vec<(Vec<u8>, Terms)> = Vec::new();
        for (c, e) in self.terms() {
            let (mu, parameters): (Vec<u8>, Vec<u8>) = e
                .iter()
                .zip(&param)
                .map(|(&k, &p)| if p { (0, k) } else { (k, 0) })
                .unzip();
            match groups.iter_mut().find(|(m, _)| *m == mu) {
                Some((_, terms)) => terms.push((c.clone(), parameters)),
                None => groups.push((mu, vec![(c.clone(), parameters)])),
            }
        }
        groups
            .into_iter()
            .map(|(mu, terms)| (mu, Expr::from_terms(reg, terms)))
            .collect()
    }

    /// The polynomial gcd of two expressions when it is not a number, its first coefficient
    /// made positive and its numeric content 1 (cos and sin are independent variables here:
    /// a common factor as written, m l of m l cos θ and m l sin θ).
    pub fn polynomial_gcd(&self, other: &Expr) -> Option<Expr> {
        let g = self.p.gcd(&other.p);
        if g.is_constant() {
            return None;
        }
        let mut content = g.coefficients[0].abs();
        for c in &g.coefficients[1..] {
            content = content.gcd(c);
        }
        let unit = if g.coefficients[0].is_negative() {
            content.neg()
        } else {
            content
        };
        Some(self.with(g) * self.reg.constant(unit.inv()))
    }

    /// `self / d` when d divides it exactly as polynomials.
    pub fn exact_div(&self, d: &Expr) -> Option<Expr> {
        // Reduced: with 1/p variables a polynomial quotient may hold p·(1/p).
        self.p
            .try_div(&d.p)
            .map(|q| self.with(Expr::reduce(q, &self.reg)))
    }

    /// Whether the expression is a nonzero polynomial in the parameters only (no coordinate,
    /// rate or unknown): what may stand below a fraction's line.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(&["L".into(), "m".into()],
    ///     &[("q".into(), CoordinateKind::Angle)]).unwrap();
    /// assert!(reg.parse("L - 2*m").unwrap().is_parameter_polynomial());
    /// assert!(!reg.parse("L*cos(q)").unwrap().is_parameter_polynomial());
    /// assert!(!reg.zero().is_parameter_polynomial());
    /// ```
    pub fn is_parameter_polynomial(&self) -> bool {
        !self.is_zero()
            && self
                .reg
                .var_ids()
                .all(|i| self.reg.is_factor_variable(i) || !self.contains_var(i))
    }

    /// Whether the expression is a nonzero rational number.
    pub fn is_nonzero_constant(&self) -> bool {
        self.as_rational().is_some_and(|r| !r.is_zero())
    }

    /// 1/self, when self is c·Π pᵢ^aᵢ (c a nonzero number, each pᵢ a parameter the
    /// mechanism divides by, or its inverse): the exact inverse in the canonical form.
    /// Otherwise, why not (a sum, a coordinate, a parameter the spec never divides by).
    pub(crate) fn monomial_inverse(&self) -> Result<Expr, String> {
        let reg = &self.reg;
        if self.p.nterms() != 1 {
            return Err(format!(
                "a spec divides by a product of parameters only (…/k, …/(2*m*l)), not by the \
                 sum `{}`: name it as a parameter, or write the quotient in `verify` or `eval`, \
                 which take any denominator",
                crate::excerpt::excerpt(&self.to_string())
            ));
        }
        let c = &self.p.coefficients[0];
        let mut e = vec![0u8; reg.nvars()];
        for (i, &k) in self.p.exponents(0).iter().enumerate() {
            if k == 0 {
                continue;
            }
            let twin = reg.inverse_pairs().find_map(|(v, w)| {
                if v == i {
                    Some(w)
                } else if w == i {
                    Some(v)
                } else {
                    None
                }
            });
            match (twin, reg.roles[i]) {
                (Some(j), _) => e[j] = k,
                (None, VarRole::Parameter(p)) if !reg.is_unknown(p) => {
                    return Err(format!(
                        "division by `{}`, a parameter this registry was not told the spec \
                         divides by (RegistryBuilder::inverses)",
                        reg.scalar_name(p)
                    ));
                }
                (None, VarRole::Parameter(p)) => {
                    return Err(format!(
                        "division by the unknown `{}`: an unknown enters linearly",
                        reg.scalar_name(p)
                    ));
                }
                _ => {
                    return Err(
                        "division by a coordinate, a rate, or a sin or cos: a spec divides by \
                         parameters only (and a loop closure by the cosine of a coordinate)"
                            .to_string(),
                    );
                }
            }
        }
        Ok(Expr::from_terms(reg, vec![(c.inv(), e)]))
    }

    /// The constant value if the expression is a rational number.
    pub(crate) fn as_rational(&self) -> Option<Rational> {
        if self.p.is_constant() {
            Some(self.p.get_constant())
        } else {
            None
        }
    }
}

/// n/d in lowest terms (divided by their polynomial gcd), the denominator's first coefficient
/// made 1.
pub(crate) fn lowest_terms(n: Expr, d: Expr) -> (Expr, Expr) {
    // 1/p below or above the line is cleared first (both sides times p^k), so that the gcd
    // sees polynomials: (x_e − l0 + m g s/k) / 1 and k x_e − k l0 + m g s share their factor.
    let (mut n, mut d) = (n, d);
    // Parameters only: a 1/cos q of a loop closure stays in the numerator (the denominator
    // of a Fraction is made of parameters).
    let pairs: Vec<(usize, usize)> = n.reg.inverses.iter().map(|&(_, v, w)| (v, w)).collect();
    for (v, w) in pairs {
        let k = n.p.degree(w).max(d.p.degree(w));
        if k > 0 {
            let pk = n.reg.var(v).pow(k as u32);
            n = &n * &pk;
            d = &d * &pk;
        }
    }
    let g = n.p.gcd(&d.p);
    let (np, dp) = match (n.p.try_div(&g), d.p.try_div(&g)) {
        (Some(a), Some(b)) => (a, b),
        _ => (n.p.clone(), d.p.clone()),
    };
    let (n, d) = (n.with(np), d.with(dp));
    let unit = n.reg.constant(d.p.coefficients[0].inv());
    (&n * &unit, &d * &unit)
}
