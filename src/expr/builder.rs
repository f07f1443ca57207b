//! The declarations a [`Registry`] is built from.

use super::{CoordinateKind, Expr, ExprError, Registry};
use std::rc::Rc;

/// The declarations of a [`Registry`], which [`RegistryBuilder::build`] turns into the
/// registry once: its variables are fixed from then on.
///
/// ```
/// use torseur::expr::Registry;
/// use torseur::spec::wire::CoordinateKind;
/// let reg = Registry::builder()
///     .parameters(&["L".into(), "m".into(), "w".into()])
///     .coordinate("q", CoordinateKind::Angle)
///     .coordinate_with_rate("phi", CoordinateKind::Angle, "w")
///     .unknowns(&["C_m".into()])
///     .display_ranks(vec![2, 0, 1]) // m before L in a product, as the course writes it
///     .build()
///     .unwrap();
/// assert_eq!(reg.parse("L*m*ddot(q)").unwrap().presentation().to_string(), "m*L*ddot(q)");
/// assert_eq!(reg.parse("dot(phi)").unwrap(), reg.parse("w").unwrap());
/// assert!(reg.parse("ddot(phi)").unwrap().is_zero());
/// assert_eq!(reg.unknowns(), ["C_m"]);
/// ```
#[derive(Debug, Clone, Default)]
pub struct RegistryBuilder {
    pub(super) parameters: Vec<String>,
    pub(super) coords: Vec<(String, CoordinateKind, Option<ImposedRate>)>,
    pub(super) unknowns: Vec<String>,
    pub(super) raw_angles: Vec<String>,
    pub(super) angle_parameters: Vec<String>,
    pub(super) phases: Vec<String>,
    pub(super) aliases: Vec<(String, String)>,
    pub(super) inverses: Vec<String>,
    pub(super) secants: Vec<String>,
    pub(super) cosecants: Vec<String>,
    pub(super) holonomic: Vec<String>,
    pub(super) display_ranks: Vec<u32>,
    pub(super) roots: Vec<super::RootText>,
}

impl RegistryBuilder {
    /// The constant parameters, in order.
    pub fn parameters(mut self, names: &[String]) -> Self {
        self.parameters.extend_from_slice(names);
        self
    }

    /// A time coordinate.
    pub fn coordinate(mut self, name: &str, kind: CoordinateKind) -> Self {
        self.coords.push((name.to_string(), kind, None));
        self
    }

    /// A time coordinate whose rate is imposed: q̇ is `rate`, an expression in the parameters
    /// (`omega`), and q̈ = 0.
    pub fn coordinate_with_rate(mut self, name: &str, kind: CoordinateKind, rate: &str) -> Self {
        let rate = ImposedRate::Text(rate.to_string());
        self.coords.push((name.to_string(), kind, Some(rate)));
        self
    }

    /// A time coordinate whose rate a loop closure determines: `numerator / denominator`,
    /// two expressions of another registry (the loop's geometry, where Cramer's rule solved
    /// them; the denominator a monomial this registry can invert), carried onto this one's
    /// variables by name when it is built ([`Expr::carried`]).
    pub(crate) fn coordinate_with_quotient(
        mut self,
        name: &str,
        kind: CoordinateKind,
        (numerator, denominator): (Expr, Expr),
    ) -> Self {
        let rate = ImposedRate::Quotient(numerator, denominator);
        self.coords.push((name.to_string(), kind, Some(rate)));
        self
    }

    /// The phases Ω t of the pulsations `names` (parameters): the time enters a mechanism
    /// only as sin(Ω t) and cos(Ω t), so each phase is an angle coordinate named `Omega*t`
    /// whose rate Ω is imposed, after the declared coordinates.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// let reg = Registry::builder()
    ///     .parameters(&["F0".into(), "Omega".into()])
    ///     .phases(&["Omega".into()])
    ///     .build()
    ///     .unwrap();
    /// let f = reg.parse("F0*cos(Omega*t)").unwrap();
    /// assert_eq!(f.dt(), reg.parse("-F0*Omega*sin(Omega*t)").unwrap());
    /// assert_eq!(f.to_string(), "F0*cos(Omega*t)");
    /// ```
    pub fn phases(mut self, names: &[String]) -> Self {
        self.phases.extend_from_slice(names);
        self
    }

    /// Named expressions of the parameters, (name, text) in order, each text reading the
    /// parameters and the aliases before it: a name then reads as its value everywhere.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// let reg = Registry::builder()
    ///     .parameters(&["C".into(), "omega".into()])
    ///     .aliases(&[("K".into(), "C*omega".into()), ("K2".into(), "K^2".into())])
    ///     .build()
    ///     .unwrap();
    /// assert_eq!(reg.parse("K2 - K*C*omega").unwrap().is_zero(), true);
    /// assert_eq!(reg.aliases().next().unwrap().0, "K");
    /// ```
    pub fn aliases(mut self, aliases: &[(String, String)]) -> Self {
        self.aliases.extend_from_slice(aliases);
        self
    }

    /// The parameters the mechanism divides by (`l0 - m*g*sin(beta)/k`, a rate `V/R`): each
    /// gets a variable 1/p, and p·(1/p) is reduced to 1 after every product, so results stay
    /// canonical Laurent polynomials in these parameters. A text may then divide by any
    /// product of them (`/(2*m*l)`); a sum below the line is refused.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// let reg = Registry::builder()
    ///     .parameters(&["m".into(), "g".into(), "k".into(), "l0".into()])
    ///     .inverses(&["k".into()])
    ///     .build()
    ///     .unwrap();
    /// let xe = reg.parse("l0 - m*g/k").unwrap();
    /// // k (x_e − l0) + m g = 0, exactly.
    /// let k = reg.parse("k").unwrap();
    /// assert!((&k * &(&xe - &reg.parse("l0").unwrap()) + reg.parse("m*g").unwrap()).is_zero());
    /// assert_eq!(xe.to_string(), "l0 - m*g/k");
    /// assert!(reg.parse("m/(k + g)").is_err());
    /// ```
    pub fn inverses(mut self, names: &[String]) -> Self {
        for n in names {
            if !self.inverses.contains(n) {
                self.inverses.push(n.clone());
            }
        }
        self
    }

    /// The angle coordinates whose cosine a loop closure divides by (the crank–slider's rod,
    /// φ̇ = −R θ̇ cos θ / (L cos φ)): each gets a variable 1/cos q, and cos q·(1/cos q) is
    /// reduced to 1 after every product. Its leading monomial is coprime with sin²q's, so the
    /// reduced form stays unique; d(1/cos q)/dt = sin q q̇ / cos²q.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::builder()
    ///     .parameters(&["L".into()])
    ///     .coordinate("phi", CoordinateKind::Angle)
    ///     .secants(&["phi".into()])
    ///     .build()
    ///     .unwrap();
    /// let t = reg.parse("sin(phi)/cos(phi)").unwrap();
    /// assert!((&t * &reg.parse("cos(phi)").unwrap() - reg.parse("sin(phi)").unwrap()).is_zero());
    /// // d(tan φ)/dt = φ̇ / cos²φ.
    /// assert_eq!(t.dt(), reg.parse("dot(phi)/cos(phi)^2").unwrap());
    /// assert_eq!(t.to_string(), "sin(phi)/cos(phi)");
    /// ```
    pub fn secants(mut self, names: &[String]) -> Self {
        for n in names {
            if !self.secants.contains(n) {
                self.secants.push(n.clone());
            }
        }
        self
    }

    /// The angle coordinates whose sine a loop closure divides by (a four-bar's rocker
    /// measured from its coupler, ψ, whose loop determinant is L2 L3 sin ψ): each gets a
    /// variable 1/sin q, reduced sin q·(1/sin q) → 1, and the angle's other rule becomes
    /// cos²q → 1 − sin²q, so that the two leading monomials stay coprime and the reduced
    /// form unique. A coordinate cannot have both.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::builder()
    ///     .coordinate("psi", CoordinateKind::Angle)
    ///     .cosecants(&["psi".into()])
    ///     .build()
    ///     .unwrap();
    /// let c = reg.parse("cos(psi)/sin(psi)").unwrap();
    /// // d(cot ψ)/dt = −ψ̇ / sin²ψ, and cos²ψ + sin²ψ = 1 still.
    /// assert_eq!(c.dt(), reg.parse("-dot(psi)/sin(psi)^2").unwrap());
    /// assert!(reg.parse("cos(psi)^2 + sin(psi)^2 - 1").unwrap().is_zero());
    /// ```
    pub fn cosecants(mut self, names: &[String]) -> Self {
        for n in names {
            if !self.cosecants.contains(n) {
                self.cosecants.push(n.clone());
            }
        }
        self
    }

    /// Square roots of radicands, texts of the spec syntax (read after the aliases): each
    /// gets a variable s, and s² is reduced to its radicand after every product (see the
    /// conditions of exactness in `roots.rs`). A text then reads `sqrt(P)` as s, and
    /// `sqrt(c^2*P)` as c s.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::builder()
    ///     .parameters(&["R".into(), "L".into()])
    ///     .coordinate("theta", CoordinateKind::Angle)
    ///     .roots(&["L^2 - R^2*sin(theta)^2".into()])
    ///     .build()
    ///     .unwrap();
    /// let s = reg.parse("sqrt(L^2 - R^2*sin(theta)^2)").unwrap();
    /// // Squared by hand: L² − R² sin²θ.
    /// assert_eq!(&s * &s, reg.parse("L^2 - R^2 + R^2*cos(theta)^2").unwrap());
    /// // (x − s)(x + s) with x = R cos θ: R² cos²θ − L² + R² sin²θ = R² − L².
    /// let x = reg.parse("R*cos(theta)").unwrap();
    /// assert_eq!(&(&x - &s) * &(&x + &s), reg.parse("R^2 - L^2").unwrap());
    /// assert_eq!(reg.parse("sqrt(4*L^2 - 4*R^2*sin(theta)^2)").unwrap(), &reg.integer(2) * &s);
    /// assert!(reg.parse("sqrt(L^2 + R^2)").is_err());
    /// ```
    pub fn roots(mut self, radicands: &[String]) -> Self {
        for r in radicands {
            self.roots.push(super::RootText::Text(r.clone()));
        }
        self
    }

    /// Square roots of radicands of another registry (the loop law's, solved over the
    /// geometry's), carried by name when the registry is built.
    pub(crate) fn roots_of(mut self, radicands: Vec<Expr>) -> Self {
        self.roots
            .extend(radicands.into_iter().map(super::RootText::Expr));
        self
    }

    /// The coordinates whose imposed rate was solved from a loop closure f(q) = 0: holonomic
    /// even when its coefficients hold coordinates (see [`super::CoordInfo::is_holonomic`]).
    pub fn holonomic(mut self, names: &[String]) -> Self {
        self.holonomic.extend_from_slice(names);
        self
    }

    /// The unknowns of the PFD (link components, a motor torque): scalars that enter
    /// linearly and are solved for.
    pub fn unknowns(mut self, names: &[String]) -> Self {
        self.unknowns.extend_from_slice(names);
        self
    }

    /// The angle coordinates that also enter as themselves (a torsion spring's −k(θ − θ0), a
    /// disc's centre at R θ x1), not only through sin and cos.
    pub fn raw_angles(mut self, names: &[String]) -> Self {
        self.raw_angles.extend_from_slice(names);
        self
    }

    /// The parameters that are constant angles (an incline α): each gets cos α and sin α
    /// variables, with sin²α reduced like a coordinate's, and a zero rate; α itself stays
    /// the parameter's variable.
    pub fn angle_parameters(mut self, names: &[String]) -> Self {
        self.angle_parameters.extend_from_slice(names);
        self
    }

    /// The written order of the parameters in a product: `ranks[p]` for parameter `p`
    /// (lower first; equal ranks keep the declaration order). The spec sets the course's
    /// order from the units: masses, then accelerations (g), lengths, inertia moments, the
    /// rest. Unknowns come after every parameter.
    pub fn display_ranks(mut self, ranks: Vec<u32>) -> Self {
        self.display_ranks = ranks;
        self
    }

    /// The registry: its variables, in a fixed order.
    pub fn build(self) -> Result<Rc<Registry>, ExprError> {
        Registry::build(self)
    }
}

/// An imposed rate as declared: a text of the spec syntax (`omega`, `-r1/r2*dot(theta1)`),
/// or a quotient of two expressions of another registry (see
/// [`RegistryBuilder::coordinate_with_quotient`]).
#[derive(Debug, Clone)]
pub(crate) enum ImposedRate {
    /// A text, parsed against the registry's parameters and free rates.
    Text(String),
    /// Numerator and denominator, over another registry.
    Quotient(Expr, Expr),
}

impl ImposedRate {
    /// The text, for a rate declared as one.
    pub(super) fn text(&self) -> Option<&str> {
        match self {
            ImposedRate::Text(t) => Some(t),
            ImposedRate::Quotient(..) => None,
        }
    }
}
