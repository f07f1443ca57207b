//! Units and homogeneity: the dimension of every variable of a mechanism, read from the spec's
//! parameter units, and the check that every term of a result has its quantity's dimension.
//!
//! A [`Dimension`] is a product Mᵃ Lᵇ Tᶜ of mass, length and time. **The radian is
//! dimensionless**, as in SI and in the course: Ω(2/0) = θ̇1 z0 is in rad/s, and a velocity
//! Ω ∧ r must add to a slider's ẋ, so an angle cannot carry a base dimension of its own. A
//! friction coefficient f in N·m·s/rad times θ̇ in rad/s is then a moment in N·m, and a torsion
//! stiffness in N·m/rad times an angle is N·m. The angle comes back only when a dimension is
//! printed: [`UnitStyle::Angle`] writes a pure number as rad.
//!
//! Where dimensions come from ([`Dimensions::of`]):
//! - a parameter: its `unit` in the spec ([`Dimension::parse`]); a constant angle (`"kind":
//!   "angle"`) is dimensionless. **A parameter without a unit has an unknown dimension**: the
//!   terms that contain it are skipped by [`dimension`], so they never make a check fail (nor
//!   can they make it pass: they are not checked at all);
//! - a coordinate q: an angle is dimensionless, a length is L; cos q and sin q are
//!   dimensionless; q̇ is q/T, q̈ q/T², the third derivative q/T³;
//! - an unknown of the PFD: each action it appears in gives it one; a component of a
//!   resultant is a force (M L T⁻²), of a moment a moment (M L² T⁻²), so X01 is in N, L01 in
//!   N·m, and `C_m` in `C_m*z0` given as a moment is in N·m (the unknown's coefficient there
//!   divides the action's dimension).
//!
//! ```
//! use torseur::units::{dimension, Dimension, Dimensions, UnitStyle};
//! let m = torseur::spec::load("derivations/regulateur_centrifuge.json")?;
//! let dims = Dimensions::of(&m);
//! // m2 L2² θ̈2 is a moment.
//! let e = m.reg.parse("m2*L2^2*ddot(theta2) + A2*ddot(theta2)")?;
//! let d = dimension(&e, &dims)?.unwrap();
//! assert_eq!(d, Dimension::MOMENT);
//! assert_eq!(d.si_text(UnitStyle::Mechanics), "N·m");
//! // A mass plus a length is refused, naming both terms.
//! let wrong = m.reg.parse("m2 + L2")?;
//! let err = dimension(&wrong, &dims).unwrap_err();
//! assert!(err.to_string().contains("`m2`") && err.to_string().contains("`L2`"), "{err}");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::derivation::{Derivation, StepKind, Value};
use crate::expr::{CoordId, Expr, Registry, VarRole};
use crate::mechanism::Mechanism;
use crate::quantity::{Quantity, QuantityKind};
use crate::spec::wire::{CoordinateKind, ParameterKind, TheoremKind};
use std::fmt;
use std::ops::{Div, Mul};
use std::rc::Rc;
use std::str::FromStr;

/// A physical dimension Mᵃ Lᵇ Tᶜ: the exponents of mass, length and time (the radian is
/// dimensionless, see the [module documentation](self)).
///
/// ```
/// use torseur::units::Dimension;
/// let f = Dimension::parse("N m s/rad").unwrap();
/// let rate = Dimension::parse("rad/s").unwrap();
/// assert_eq!(f * rate, Dimension::MOMENT);
/// assert_eq!(Dimension::FORCE.to_string(), "M·L·T⁻²");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Dimension {
    /// Exponent of M (mass, kg).
    pub mass: i32,
    /// Exponent of L (length, m).
    pub length: i32,
    /// Exponent of T (time, s).
    pub time: i32,
}

impl Dimension {
    /// A pure number (an angle, a cosine).
    pub const NONE: Dimension = Dimension::new(0, 0, 0);
    /// M: a mass (kg).
    pub const MASS: Dimension = Dimension::new(1, 0, 0);
    /// L: a length (m).
    pub const LENGTH: Dimension = Dimension::new(0, 1, 0);
    /// T: a time (s).
    pub const TIME: Dimension = Dimension::new(0, 0, 1);
    /// T⁻¹: a rate of rotation, Ω (rad/s).
    pub const ANGULAR_VELOCITY: Dimension = Dimension::new(0, 0, -1);
    /// L T⁻¹: a velocity V (m/s).
    pub const VELOCITY: Dimension = Dimension::new(0, 1, -1);
    /// L T⁻²: an acceleration Γ (m/s²).
    pub const ACCELERATION: Dimension = Dimension::new(0, 1, -2);
    /// M L²: a moment of inertia (kg·m²).
    pub const INERTIA: Dimension = Dimension::new(1, 2, 0);
    /// M L T⁻¹: a kinetic resultant m V(G) (kg·m/s).
    pub const MOMENTUM: Dimension = Dimension::new(1, 1, -1);
    /// M L² T⁻¹: a kinetic moment σ (kg·m²/s).
    pub const ANGULAR_MOMENTUM: Dimension = Dimension::new(1, 2, -1);
    /// M L T⁻²: a force, a dynamic resultant m Γ(G) (N).
    pub const FORCE: Dimension = Dimension::new(1, 1, -2);
    /// M L² T⁻²: a moment, a dynamic moment δ (N·m).
    pub const MOMENT: Dimension = Dimension::new(1, 2, -2);
    /// M L² T⁻²: an energy (J), the same dimension as [`Dimension::MOMENT`].
    pub const ENERGY: Dimension = Dimension::MOMENT;
    /// M L² T⁻³: a power (W).
    pub const POWER: Dimension = Dimension::new(1, 2, -3);

    /// Mᵃ Lᵇ Tᶜ.
    pub const fn new(mass: i32, length: i32, time: i32) -> Dimension {
        Dimension { mass, length, time }
    }

    /// Whether this is a pure number.
    pub fn is_dimensionless(self) -> bool {
        self == Dimension::NONE
    }

    /// selfⁿ.
    pub fn pow(self, n: i32) -> Dimension {
        Dimension::new(self.mass * n, self.length * n, self.time * n)
    }

    /// Reads a unit as a spec writes it: SI symbols `kg`, `m`, `s`, `rad`, `N`, `J`, `W`,
    /// `Hz`, `Pa` (and `1` for a pure number), multiplied with spaces, `*` or `·`, each with an
    /// optional integer power `^n` (negative too: `s^-1`; `m²` is accepted), and at most one
    /// `/`, everything after which divides (`N m s/rad` is N·m·s/rad). Units that are not
    /// coherent SI (`g`, `mm`, `tr/min`, `deg`, `kN`) are refused with the SI unit to use: the
    /// scenarios' values are read in SI.
    ///
    /// ```
    /// use torseur::units::Dimension;
    /// assert_eq!(Dimension::parse("kg m^2").unwrap(), Dimension::INERTIA);
    /// assert_eq!(Dimension::parse("kg·m²/s").unwrap(), Dimension::ANGULAR_MOMENTUM);
    /// assert_eq!(Dimension::parse("N*m").unwrap(), Dimension::MOMENT);
    /// assert_eq!(Dimension::parse("m s^-2").unwrap(), Dimension::ACCELERATION);
    /// let e = Dimension::parse("tr/min").unwrap_err();
    /// assert!(e.to_string().contains("rad/s"), "{e}");
    /// ```
    pub fn parse(unit: &str) -> Result<Dimension, UnitError> {
        parse_unit(unit).map_err(|reason| UnitError {
            unit: unit.to_string(),
            reason,
        })
    }

    /// The unit as the course writes it, in plain text: `N`, `N·m`, `kg·m²`, `m/s`, `rad/s`,
    /// `kg·m/s`, `kg·m²/s`, `m/s²`, `N/m`, `N·s/m`; empty for a pure number (unless
    /// [`UnitStyle::Angle`]). Other dimensions are written in kg, m and s.
    ///
    /// ```
    /// use torseur::units::{Dimension, UnitStyle};
    /// assert_eq!(Dimension::MOMENT.si_text(UnitStyle::Mechanics), "N·m");
    /// assert_eq!(Dimension::ENERGY.si_text(UnitStyle::Energy), "J");
    /// assert_eq!(Dimension::INERTIA.si_text(UnitStyle::Mechanics), "kg·m²");
    /// assert_eq!(Dimension::ANGULAR_VELOCITY.si_text(UnitStyle::Mechanics), "rad/s");
    /// assert_eq!(Dimension::NONE.si_text(UnitStyle::Mechanics), "");
    /// assert_eq!(Dimension::NONE.si_text(UnitStyle::Angle), "rad");
    /// ```
    pub fn si_text(&self, style: UnitStyle) -> String {
        render(&self.si_factors(style), false)
    }

    /// [`Dimension::si_text`] in LaTeX, upright: `\mathrm{N\cdot m}`, `\mathrm{kg\cdot m^{2}}`,
    /// `\mathrm{m/s^{2}}`; empty for a pure number (unless [`UnitStyle::Angle`]).
    ///
    /// ```
    /// use torseur::units::{Dimension, UnitStyle};
    /// assert_eq!(Dimension::MOMENT.si_latex(UnitStyle::Mechanics), r"\mathrm{N\cdot m}");
    /// assert_eq!(Dimension::INERTIA.si_latex(UnitStyle::Mechanics), r"\mathrm{kg\cdot m^{2}}");
    /// assert_eq!(Dimension::ACCELERATION.si_latex(UnitStyle::Mechanics), r"\mathrm{m/s^{2}}");
    /// ```
    pub fn si_latex(&self, style: UnitStyle) -> String {
        let body = render(&self.si_factors(style), true);
        if body.is_empty() {
            body
        } else {
            format!("\\mathrm{{{body}}}")
        }
    }

    /// The unit symbols with their powers, in writing order.
    fn si_factors(&self, style: UnitStyle) -> Vec<(&'static str, i32)> {
        let Dimension { mass, length, time } = *self;
        let nonzero = |v: Vec<(&'static str, i32)>| v.into_iter().filter(|f| f.1 != 0).collect();
        match (mass, length, time) {
            (0, 0, 0) if style == UnitStyle::Angle => vec![("rad", 1)],
            (1, 2, -2) if style == UnitStyle::Energy => vec![("J", 1)],
            (1, 2, -3) if style == UnitStyle::Energy => vec![("W", 1)],
            // A force times a length to a power: N, N·m, N/m (a stiffness), N/m².
            (1, l, -2) => nonzero(vec![("N", 1), ("m", l - 1)]),
            // A linear viscous coefficient.
            (1, 0, -1) => vec![("N", 1), ("s", 1), ("m", -1)],
            // A rate of rotation and its derivatives.
            (0, 0, t) if t < 0 => vec![("rad", 1), ("s", t)],
            _ => nonzero(vec![("kg", mass), ("m", length), ("s", time)]),
        }
    }
}

/// How to print a dimension that several units share ([`Dimension::si_text`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum UnitStyle {
    /// Mechanics: M L² T⁻² is a moment, N·m; a pure number prints empty.
    #[default]
    Mechanics,
    /// Energy and power: M L² T⁻² is J, M L² T⁻³ is W (a kinetic energy, Ec).
    Energy,
    /// An angle: a pure number is rad (otherwise as [`UnitStyle::Mechanics`]).
    Angle,
}

/// The style a quantity's unit is written in: an energy in J, every other quantity in the
/// units of mechanics.
///
/// ```
/// use torseur::units::{unit_style, UnitStyle};
/// use torseur::quantity::Quantity;
/// assert_eq!(unit_style(&Quantity::parse("Ec(E/0)").unwrap().kind), UnitStyle::Energy);
/// assert_eq!(unit_style(&Quantity::parse("delta(O,1/0).z0").unwrap().kind), UnitStyle::Mechanics);
/// ```
pub fn unit_style(kind: &QuantityKind) -> UnitStyle {
    match kind {
        QuantityKind::KineticEnergy(_) => UnitStyle::Energy,
        _ => UnitStyle::Mechanics,
    }
}

/// Writes factors as `num/den`, plain (Unicode powers, `·`) or LaTeX (`\cdot`, `^{n}`).
fn render(factors: &[(&str, i32)], latex: bool) -> String {
    let dot = if latex { "\\cdot " } else { "·" };
    let power = |s: &str, k: i32| -> String {
        match (k, latex) {
            (1, _) => s.to_string(),
            (_, true) => format!("{s}^{{{k}}}"),
            (_, false) => format!("{s}{}", superscript(k)),
        }
    };
    let join = |fs: Vec<String>| fs.join(dot);
    let num: Vec<String> = factors
        .iter()
        .filter(|f| f.1 > 0)
        .map(|&(s, k)| power(s, k))
        .collect();
    let den: Vec<String> = factors
        .iter()
        .filter(|f| f.1 < 0)
        .map(|&(s, k)| power(s, -k))
        .collect();
    match (num.is_empty(), den.len()) {
        (true, 0) => String::new(),
        (_, 0) => join(num),
        (num_empty, n) => {
            let top = if num_empty {
                "1".to_string()
            } else {
                join(num)
            };
            if n == 1 {
                format!("{top}/{}", den[0])
            } else {
                format!("{top}/({})", join(den))
            }
        }
    }
}

/// `-2` as `⁻²`.
fn superscript(k: i32) -> String {
    k.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            d => "⁰¹²³⁴⁵⁶⁷⁸⁹"
                .chars()
                .nth(d.to_digit(10).unwrap_or(0) as usize)
                .unwrap_or('?'),
        })
        .collect()
}

impl Mul for Dimension {
    type Output = Dimension;
    fn mul(self, o: Dimension) -> Dimension {
        Dimension::new(
            self.mass + o.mass,
            self.length + o.length,
            self.time + o.time,
        )
    }
}

impl Div for Dimension {
    type Output = Dimension;
    fn div(self, o: Dimension) -> Dimension {
        self * o.pow(-1)
    }
}

impl fmt::Display for Dimension {
    /// The dimension formula, `M·L²·T⁻²`; `1` for a pure number.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let parts: Vec<String> = [("M", self.mass), ("L", self.length), ("T", self.time)]
            .iter()
            .filter(|p| p.1 != 0)
            .map(|&(s, k)| {
                if k == 1 {
                    s.to_string()
                } else {
                    format!("{s}{}", superscript(k))
                }
            })
            .collect();
        if parts.is_empty() {
            f.write_str("1")
        } else {
            f.write_str(&parts.join("·"))
        }
    }
}

impl FromStr for Dimension {
    type Err = UnitError;
    fn from_str(s: &str) -> Result<Dimension, UnitError> {
        Dimension::parse(s)
    }
}

/// A unit text that [`Dimension::parse`] refuses.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("cannot read the unit `{unit}`: {reason}")]
pub struct UnitError {
    /// The text given.
    pub unit: String,
    /// Why, and what to write instead.
    pub reason: String,
}

/// Largest power accepted in a unit (`m^12`).
const MAX_POWER: i32 = 12;

fn parse_unit(unit: &str) -> Result<Dimension, String> {
    let s = unit.trim();
    if s.is_empty() {
        return Err(
            "it is empty: leave `unit` out when it is unknown, or write `1` for a pure \
                    number"
                .to_string(),
        );
    }
    if s.chars().count() > 64 {
        return Err("longer than 64 characters".to_string());
    }
    let compact: String = s.chars().filter(|c| !c.is_whitespace()).collect();
    if matches!(
        compact.as_str(),
        "tr/min" | "tr/s" | "rpm" | "rps" | "t/min" | "rev/min"
    ) {
        return Err(
            "not an SI unit: a rate of rotation is written in rad/s (2000 tr/min is \
                    2000*2*pi/60 rad/s), the unit the scenarios' values are read in"
                .to_string(),
        );
    }
    if s.contains(['(', ')']) {
        return Err(
            "no parentheses: everything after the `/` divides (`N s/m` is N·s/m, \
                    `kg/m s^2` is kg/(m·s²))"
                .to_string(),
        );
    }
    let mut sides = s.split('/');
    let num = sides.next().unwrap_or_default().trim();
    let den = sides.next().map(str::trim);
    if sides.next().is_some() {
        return Err(
            "one `/` at most: everything after it divides (`N m s/rad`), or write \
                    negative powers (`kg m^-1 s^-2`)"
                .to_string(),
        );
    }
    let top = product(num, "before")?;
    match den {
        None => Ok(top),
        Some(d) => Ok(top / product(d, "after")?),
    }
}

/// A product of unit symbols with optional powers.
fn product(text: &str, side: &str) -> Result<Dimension, String> {
    if text.is_empty() {
        return Err(format!(
            "nothing {side} the `/` (write `1/s` for an inverse)"
        ));
    }
    if text == "1" {
        return Ok(Dimension::NONE);
    }
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    let mut acc = Dimension::NONE;
    let is_symbol = |c: char| c.is_alphabetic() || matches!(c, '°' | 'µ' | 'Ω');
    loop {
        let start = i;
        while i < chars.len() && is_symbol(chars[i]) {
            i += 1;
        }
        if start == i {
            let rest: String = chars[i..].iter().collect();
            return Err(format!("expected a unit symbol at `{rest}`"));
        }
        let sym: String = chars[start..i].iter().collect();
        let base = symbol(&sym)?;
        let mut power: i32 = 1;
        if i < chars.len() && chars[i] == '^' {
            i += 1;
            let from = i;
            if i < chars.len() && matches!(chars[i], '-' | '+') {
                i += 1;
            }
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
            }
            let digits: String = chars[from..i].iter().collect();
            power = digits.parse().map_err(|_| {
                format!("`{sym}^` must be followed by an integer power (`{sym}^2`, `{sym}^-1`)")
            })?;
        } else if i < chars.len() && "⁻¹²³⁴⁵⁶⁷⁸⁹⁰".contains(chars[i]) {
            let from = i;
            while i < chars.len() && "⁻¹²³⁴⁵⁶⁷⁸⁹⁰".contains(chars[i]) {
                i += 1;
            }
            let digits: String = chars[from..i]
                .iter()
                .map(|&c| match c {
                    '⁻' => '-',
                    c => char::from_digit(
                        "⁰¹²³⁴⁵⁶⁷⁸⁹".chars().position(|d| d == c).unwrap_or(0) as u32,
                        10,
                    )
                    .unwrap_or('0'),
                })
                .collect();
            power = digits
                .parse()
                .map_err(|_| format!("`{sym}` has an unreadable power"))?;
        } else if i < chars.len() && chars[i].is_ascii_digit() {
            return Err(format!("a power is written with `^`: `{sym}^{}`", chars[i]));
        }
        if power == 0 || power.abs() > MAX_POWER {
            return Err(format!(
                "the power of `{sym}` must be a nonzero integer between -{MAX_POWER} and \
                 {MAX_POWER}"
            ));
        }
        acc = acc * base.pow(power);
        // A separator: spaces, with at most one `*` or `·` among them.
        let sep_start = i;
        let mut explicit = false;
        while i < chars.len() && (chars[i].is_whitespace() || matches!(chars[i], '*' | '·' | '⋅'))
        {
            if !chars[i].is_whitespace() {
                if explicit {
                    return Err("two multiplication signs in a row".to_string());
                }
                explicit = true;
            }
            i += 1;
        }
        if i == chars.len() {
            if explicit {
                return Err("a multiplication sign with nothing after it".to_string());
            }
            return Ok(acc);
        }
        if sep_start == i {
            return Err(format!("unexpected `{}` after `{sym}`", chars[i]));
        }
    }
}

/// The dimension of one SI symbol, or why it is refused.
fn symbol(s: &str) -> Result<Dimension, String> {
    Ok(match s {
        "kg" => Dimension::MASS,
        "m" => Dimension::LENGTH,
        "s" => Dimension::TIME,
        "rad" => Dimension::NONE,
        "N" => Dimension::FORCE,
        "J" => Dimension::ENERGY,
        "W" => Dimension::POWER,
        "Hz" => Dimension::ANGULAR_VELOCITY,
        "Pa" => Dimension::new(1, -1, -2),
        _ => return Err(refusal(s)),
    })
}

fn refusal(s: &str) -> String {
    let si = match s {
        "g" | "mg" | "t" => Some("kg"),
        "mm" | "cm" | "dm" | "km" | "µm" | "um" => Some("m"),
        "min" | "h" | "ms" => Some("s"),
        "tr" | "rev" | "deg" | "°" | "rd" | "grad" => Some("rad"),
        "kN" | "daN" | "mN" => Some("N"),
        "kJ" | "Wh" | "kWh" => Some("J"),
        "kW" | "ch" => Some("W"),
        "bar" | "kPa" | "MPa" => Some("Pa"),
        _ => None,
    };
    if let Some(si) = si {
        return format!(
            "`{s}` is not a coherent SI unit: write the value in {si} (the scenarios' values are \
             read in SI units)"
        );
    }
    if matches!(s, "A" | "K" | "mol" | "cd" | "V" | "C" | "Ω") {
        return format!("`{s}` is outside mechanics: units are built from kg, m and s");
    }
    let known = ["kg", "m", "s", "rad", "N", "J", "W", "Hz", "Pa"];
    for k in 1..s.len() {
        if let (Some(a), Some(b)) = (s.get(..k), s.get(k..))
            && known.contains(&a)
            && known.contains(&b)
        {
            return format!("`{s}`: separate the units with a space, `*` or `·` (`{a} {b}`)");
        }
    }
    format!(
        "unknown unit `{s}` (SI units: kg, m, s, rad, N, J, W, Hz, Pa; products with spaces, \
         `*` or `·`, one `/`, integer powers such as `m^2` or `s^-1`)"
    )
}

/// Terms of two dimensions in one expression.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "the terms `{first}` ({first_dimension}, {}) and `{second}` ({second_dimension}, {}) have \
     different dimensions",
    unit_or_one(first_dimension),
    unit_or_one(second_dimension)
)]
pub struct Inhomogeneous {
    /// A term, in the plain-text syntax.
    pub first: String,
    /// Its dimension.
    pub first_dimension: Dimension,
    /// A term of another dimension.
    pub second: String,
    /// Its dimension.
    pub second_dimension: Dimension,
}

/// The SI unit for messages, `1` for a pure number.
fn unit_or_one(d: &Dimension) -> String {
    match d.si_text(UnitStyle::Mechanics) {
        s if s.is_empty() => "1".to_string(),
        s => s,
    }
}

/// The dimension of every variable of a registry: parameters and unknowns (when known),
/// coordinates and their rates, cos and sin.
///
/// ```
/// use torseur::units::{Dimension, Dimensions};
/// let m = torseur::spec::load("derivations/pendule_sur_chariot.json")?;
/// let d = Dimensions::of(&m);
/// assert_eq!(d.scalar("F"), Some(Dimension::FORCE));
/// assert_eq!(d.scalar("X12"), Some(Dimension::FORCE));
/// assert_eq!(d.coordinate(m.reg.coord("x").unwrap()), Dimension::LENGTH);
/// assert_eq!(d.coordinate(m.reg.coord("theta").unwrap()), Dimension::NONE);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Dimensions {
    reg: Rc<Registry>,
    vars: Vec<Option<Dimension>>,
}

impl Dimensions {
    /// The dimensions a registry fixes by itself: coordinates (an angle is a pure number, a
    /// length L), their rates (q/Tⁿ), cos and sin (pure numbers) and the constant angle
    /// parameters; every other parameter and unknown is unknown until [`Dimensions::set`].
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// use torseur::units::{dimension, Dimension, Dimensions};
    /// let reg = Registry::new(&["k".into(), "m".into()], &[("x".into(), CoordinateKind::Length)]).unwrap();
    /// let mut d = Dimensions::new(&reg);
    /// let e = reg.parse("m*ddot(x) + k*x").unwrap();
    /// // k and m are unknown: no term is checked.
    /// assert_eq!(dimension(&e, &d).unwrap(), None);
    /// d.set("m", Some(Dimension::MASS));
    /// // m ẍ is a force; k x is still skipped.
    /// assert_eq!(dimension(&e, &d).unwrap(), Some(Dimension::FORCE));
    /// d.set("k", Some(Dimension::parse("N/m").unwrap()));
    /// assert_eq!(dimension(&e, &d).unwrap(), Some(Dimension::FORCE));
    /// d.set("k", Some(Dimension::parse("N").unwrap()));
    /// assert!(dimension(&e, &d).is_err());
    /// ```
    pub fn new(reg: &Rc<Registry>) -> Dimensions {
        let coordinate = |q: CoordId| match reg.coord_info(q).kind {
            CoordinateKind::Angle => Dimension::NONE,
            CoordinateKind::Length => Dimension::LENGTH,
        };
        let vars = (0..reg.nvars())
            .map(|i| match reg.role(i) {
                VarRole::Parameter(k) => {
                    let is_angle = !reg.is_unknown(k)
                        && reg
                            .angle(reg.scalar_name(k))
                            .is_some_and(|q| reg.coord_info(q).is_constant());
                    is_angle.then_some(Dimension::NONE)
                }
                VarRole::Cos(_) | VarRole::Sin(_) => Some(Dimension::NONE),
                VarRole::Value(q) => Some(coordinate(q)),
                VarRole::Rate(q, order) => {
                    Some(coordinate(q) / Dimension::TIME.pow(i32::from(order)))
                }
            })
            .collect();
        Dimensions {
            reg: reg.clone(),
            vars,
        }
    }

    /// The dimensions of a mechanism: [`Dimensions::new`], each parameter's from its `unit`
    /// (a constant angle is a pure number whatever its unit says; a unit that does not parse,
    /// which loading refuses, is unknown), and each unknown of the PFD's from the actions it
    /// appears in (a resultant component is a force, a moment component a moment, divided by
    /// the dimension of the unknown's coefficient there). An unknown whose coefficient has
    /// an unknown dimension stays unknown.
    pub fn of(m: &Mechanism) -> Dimensions {
        let mut d = Dimensions::new(&m.reg);
        for p in &m.spec.parameters {
            let dim = match (p.kind, &p.unit) {
                (ParameterKind::Angle, _) => Some(Dimension::NONE),
                (ParameterKind::Scalar, Some(u)) => Dimension::parse(u).ok(),
                (ParameterKind::Scalar, None) => None,
            };
            d.set(&p.name, dim);
        }
        let reg = &m.reg;
        let np = reg.parameters().len();
        let unknowns: Vec<(usize, String)> = reg
            .unknowns()
            .iter()
            .enumerate()
            .filter_map(|(k, n)| {
                reg.index_of(VarRole::Parameter(np + k))
                    .map(|v| (v, n.clone()))
            })
            .collect();
        let mut found: Vec<Option<Dimension>> = vec![None; unknowns.len()];
        for a in &m.dynamics.actions {
            for (vector, dim) in [
                (&a.resultant, Dimension::FORCE),
                (&a.moment, Dimension::MOMENT),
            ] {
                for c in vector.express_in(&m.frames, a.basis) {
                    for (k, (v, _)) in unknowns.iter().enumerate() {
                        if found[k].is_some() {
                            continue;
                        }
                        let coefficient = c.derivative(*v);
                        if coefficient.is_zero() {
                            continue;
                        }
                        if let Ok(Some(dc)) = dimension(&coefficient, &d) {
                            found[k] = Some(dim / dc);
                        }
                    }
                }
            }
        }
        for ((_, n), dim) in unknowns.iter().zip(found) {
            d.set(n, dim);
        }
        d
    }

    /// Sets the dimension of a parameter or unknown by name (`None`: unknown). Returns false
    /// when the registry has no such scalar.
    pub fn set(&mut self, name: &str, dimension: Option<Dimension>) -> bool {
        match self.scalar_var(name) {
            Some(i) => {
                self.vars[i] = dimension;
                true
            }
            None => false,
        }
    }

    /// The dimension of the polynomial variable `i` (see [`Registry::role`]), if known.
    pub fn variable(&self, i: usize) -> Option<Dimension> {
        self.vars.get(i).copied().flatten()
    }

    /// The dimension of a parameter or unknown by name, if known.
    pub fn scalar(&self, name: &str) -> Option<Dimension> {
        self.scalar_var(name).and_then(|i| self.variable(i))
    }

    /// The dimension of a coordinate's value: a pure number for an angle, L for a length.
    pub fn coordinate(&self, q: CoordId) -> Dimension {
        match self.reg.coord_info(q).kind {
            CoordinateKind::Angle => Dimension::NONE,
            CoordinateKind::Length => Dimension::LENGTH,
        }
    }

    fn scalar_var(&self, name: &str) -> Option<usize> {
        let reg = &self.reg;
        let np = reg.parameters().len();
        let k = reg
            .parameters()
            .iter()
            .position(|p| p == name)
            .or_else(|| {
                reg.unknowns()
                    .iter()
                    .position(|u| u == name)
                    .map(|k| np + k)
            })?;
        reg.index_of(VarRole::Parameter(k))
    }
}

/// The dimension of one term (its exponents), none if a factor's is unknown.
fn term_dimension(exponents: &[u8], dims: &Dimensions) -> Option<Dimension> {
    let mut acc = Dimension::NONE;
    for (i, &k) in exponents.iter().enumerate() {
        if k != 0 {
            acc = acc * dims.variable(i)?.pow(i32::from(k));
        }
    }
    Some(acc)
}

/// The text of one term of `e`.
fn term_text(e: &Expr, term: usize) -> String {
    e.terms()
        .nth(term)
        .map(|(c, x)| Expr::from_terms(e.registry(), vec![(c.clone(), x.to_vec())]).to_string())
        .unwrap_or_default()
}

/// The common dimension of the terms of `e` whose dimension is known, with the index of the
/// first of them.
fn scan(e: &Expr, dims: &Dimensions) -> Result<Option<(Dimension, usize)>, Inhomogeneous> {
    let mut first: Option<(Dimension, usize)> = None;
    for (t, (_, x)) in e.terms().enumerate() {
        let Some(d) = term_dimension(x, dims) else {
            continue;
        };
        match first {
            None => first = Some((d, t)),
            Some((d0, _)) if d0 == d => {}
            Some((d0, t0)) => {
                return Err(Inhomogeneous {
                    first: term_text(e, t0),
                    first_dimension: d0,
                    second: term_text(e, t),
                    second_dimension: d,
                });
            }
        }
    }
    Ok(first)
}

/// The dimension of an expression: the common dimension of its terms (`None` for zero, or
/// when every term holds a variable of unknown dimension: those terms are skipped), or the
/// two terms that differ.
///
/// ```
/// use torseur::units::{dimension, Dimension, Dimensions};
/// let m = torseur::spec::load("derivations/systeme_masse_ressort.json")?;
/// let d = Dimensions::of(&m);
/// // k in N/m, c in N s/m, x a length: k (x - l0) + c ẋ is a force.
/// let e = m.reg.parse("k*(x - l0) + c*dot(x) + m*ddot(x)")?;
/// assert_eq!(dimension(&e, &d)?, Some(Dimension::FORCE));
/// assert_eq!(dimension(&m.reg.zero(), &d)?, None);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn dimension(e: &Expr, dims: &Dimensions) -> Result<Option<Dimension>, Inhomogeneous> {
    debug_assert!(
        Rc::ptr_eq(e.registry(), &dims.reg),
        "dimensions of another registry"
    );
    Ok(scan(e, dims)?.map(|(d, _)| d))
}

/// The dimension a quantity has whatever its value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExpectedDimension {
    /// A scalar, a vector or an inertia operator: every component has this dimension (`None`
    /// when it is unknown: an unknown of the PFD whose dimension nothing gives).
    Components(Option<Dimension>),
    /// A torsor: the dimensions of its resultant and of its moment.
    Torsor {
        /// Of the resultant's components.
        resultant: Dimension,
        /// Of the moment's components.
        moment: Dimension,
    },
}

impl ExpectedDimension {
    /// The dimension of the k-th expression of a value, in the order of [`Value::exprs`].
    pub fn component(&self, k: usize) -> Option<Dimension> {
        match *self {
            ExpectedDimension::Components(d) => d,
            ExpectedDimension::Torsor { resultant, moment } => {
                Some(if k < 3 { resultant } else { moment })
            }
        }
    }

    fn map(self, f: impl Fn(Dimension) -> Dimension) -> ExpectedDimension {
        match self {
            ExpectedDimension::Components(d) => ExpectedDimension::Components(d.map(f)),
            ExpectedDimension::Torsor { resultant, moment } => ExpectedDimension::Torsor {
                resultant: f(resultant),
                moment: f(moment),
            },
        }
    }
}

/// The dimension of a quantity from its kind alone: Ω T⁻¹, V L T⁻¹, Γ L T⁻², I M L²,
/// Rc M L T⁻¹, σ M L² T⁻¹, Rd M L T⁻² (N), δ M L² T⁻² (N·m), Ec M L² T⁻² (J); a torsor its
/// resultant's and moment's; an unknown of the PFD its own ([`Dimensions::of`]); eom(q) that
/// of the theorem it comes from (a force for a resultant theorem, a moment for a moment
/// theorem). A projection or `lin(...)` keeps the dimension.
///
/// ```
/// use torseur::quantity::Quantity;
/// use torseur::units::{expected_dimension, Dimension, Dimensions, ExpectedDimension};
/// let m = torseur::spec::load("derivations/pendule_sur_chariot.json")?;
/// let d = Dimensions::of(&m);
/// let e = |q: &str| expected_dimension(&m, &d, &Quantity::parse(q).unwrap());
/// assert_eq!(e("V(G,2/0) in B0"), ExpectedDimension::Components(Some(Dimension::VELOCITY)));
/// assert_eq!(e("eom(x)"), ExpectedDimension::Components(Some(Dimension::FORCE)));
/// assert_eq!(e("eom(theta)"), ExpectedDimension::Components(Some(Dimension::MOMENT)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn expected_dimension(m: &Mechanism, dims: &Dimensions, q: &Quantity) -> ExpectedDimension {
    use ExpectedDimension::{Components, Torsor};
    use QuantityKind::*;
    let one = |d: Dimension| Components(Some(d));
    match &q.kind {
        Omega(_) => one(Dimension::ANGULAR_VELOCITY),
        Velocity { .. } => one(Dimension::VELOCITY),
        Acceleration { .. } => one(Dimension::ACCELERATION),
        Inertia { .. } => one(Dimension::INERTIA),
        KineticResultant(_) => one(Dimension::MOMENTUM),
        KineticMoment { .. } => one(Dimension::ANGULAR_MOMENTUM),
        DynamicResultant(_) => one(Dimension::FORCE),
        DynamicMoment { .. } => one(Dimension::MOMENT),
        KineticEnergy(_) => one(Dimension::ENERGY),
        KinematicTorsor { .. } => Torsor {
            resultant: Dimension::ANGULAR_VELOCITY,
            moment: Dimension::VELOCITY,
        },
        KineticTorsor { .. } => Torsor {
            resultant: Dimension::MOMENTUM,
            moment: Dimension::ANGULAR_MOMENTUM,
        },
        DynamicTorsor { .. } => Torsor {
            resultant: Dimension::FORCE,
            moment: Dimension::MOMENT,
        },
        Unknown(name) => Components(dims.scalar(name)),
        Eom(c) => Components(m.reg.coord(c).and_then(|q| {
            m.dynamics
                .theorems
                .iter()
                .find(|t| t.eom == Some(q))
                .map(|t| match t.kind {
                    TheoremKind::Resultant => Dimension::FORCE,
                    TheoremKind::Moment => Dimension::MOMENT,
                })
        })),
    }
}

/// Why a value fails the homogeneity check.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{at}: {problem}")]
pub struct DimensionError {
    /// What was checked: the quantity or step, and the component (`V(G,2/0) in B0, y0`).
    pub at: String,
    /// What is wrong.
    pub problem: DimensionProblem,
}

/// What is wrong with a component's dimension.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum DimensionProblem {
    /// Two terms of different dimensions.
    #[error("inhomogeneous: {0}")]
    Inhomogeneous(Inhomogeneous),
    /// Homogeneous, but not of the quantity's dimension.
    #[error(
        "dimension {found} ({}) where the quantity is {expected} ({}), e.g. the term `{term}`",
        unit_or_one(found),
        unit_or_one(expected)
    )]
    Unexpected {
        /// A term of the component, in the plain-text syntax.
        term: String,
        /// Its dimension (every known term has it).
        found: Dimension,
        /// The quantity's.
        expected: Dimension,
    },
}

/// Names of the expressions of a value, in the order of [`Value::exprs`]: the basis vector of
/// each component (`y2`), `R.x1` and `M.x1` for a torsor, `[0][1]` for an inertia entry.
fn component_names(m: &Mechanism, v: &Value) -> Vec<String> {
    let axes = |b: crate::frame::FrameId| {
        let f = m.frame_name(b);
        ["x", "y", "z"].map(|a| format!("{a}{f}"))
    };
    match v {
        Value::Scalar(_) => vec![String::new()],
        Value::Vector { basis, .. } => axes(*basis).to_vec(),
        Value::Matrix(_) => (0..9).map(|k| format!("[{}][{}]", k / 3, k % 3)).collect(),
        Value::Torsor { basis, .. } => {
            let a = axes(*basis);
            a.iter()
                .map(|c| format!("R.{c}"))
                .chain(a.iter().map(|c| format!("M.{c}")))
                .collect()
        }
    }
}

/// Checks that every component of a value is homogeneous and, where the dimension expected
/// is known, of that dimension. `what` names the value in the error (a quantity, a step).
pub fn check_expected(
    m: &Mechanism,
    dims: &Dimensions,
    what: &str,
    expected: ExpectedDimension,
    v: &Value,
) -> Result<(), DimensionError> {
    let names = component_names(m, v);
    for (k, e) in v.exprs().into_iter().enumerate() {
        let at = match names.get(k).map(String::as_str) {
            None | Some("") => what.to_string(),
            Some(c) => format!("{what}, {c}"),
        };
        let found = scan(e, dims).map_err(|h| DimensionError {
            at: at.clone(),
            problem: DimensionProblem::Inhomogeneous(h),
        })?;
        if let (Some((found, t)), Some(want)) = (found, expected.component(k))
            && found != want
        {
            return Err(DimensionError {
                at,
                problem: DimensionProblem::Unexpected {
                    term: term_text(e, t),
                    found,
                    expected: want,
                },
            });
        }
    }
    Ok(())
}

/// Checks a quantity's value (in general or under a hypothesis): every component homogeneous
/// and of the quantity's dimension ([`expected_dimension`]).
///
/// ```
/// use torseur::derivation::derive;
/// use torseur::quantity::Quantity;
/// use torseur::units::{check_value, Dimensions};
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json")?;
/// let dims = Dimensions::of(&m);
/// let q = Quantity::parse("delta(O2,2/0).x2")?;
/// let d = derive(&m, &q)?;
/// check_value(&m, &dims, &q, &d.value)?;
/// // The same value taken for a velocity is refused.
/// let v = Quantity::parse("V(G2,2/0).x2")?;
/// let err = check_value(&m, &dims, &v, &d.value).unwrap_err();
/// assert!(err.to_string().contains("where the quantity is L·T⁻¹ (m/s)"), "{err}");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn check_value(
    m: &Mechanism,
    dims: &Dimensions,
    q: &Quantity,
    v: &Value,
) -> Result<(), DimensionError> {
    check_expected(m, dims, &q.to_string(), expected_dimension(m, dims, q), v)
}

/// Checks every step of a derivation (what the answer key displays) and its result: each step
/// of the dimension of what it computes (a derivative of σ is a moment, a complementary
/// term a moment, an action torsor a force and a moment, a sum of actions a force or a
/// moment).
///
/// ```
/// use torseur::derivation::derive;
/// use torseur::quantity::Quantity;
/// use torseur::units::{check_derivation, Dimensions};
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json")?;
/// let d = derive(&m, &Quantity::parse("C_m")?)?;
/// check_derivation(&m, &Dimensions::of(&m), &d)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn check_derivation(
    m: &Mechanism,
    dims: &Dimensions,
    d: &Derivation,
) -> Result<(), DimensionError> {
    let of_kind = |kind: &QuantityKind| {
        let q = Quantity {
            kind: kind.clone(),
            basis: None,
            projection: None,
            linear: false,
        };
        expected_dimension(m, dims, &q)
    };
    let torsor = |resultant, moment| ExpectedDimension::Torsor { resultant, moment };
    for s in &d.steps {
        let expected = match &s.kind {
            StepKind::Quantity(k) | StepKind::Projected(k, _) => of_kind(k),
            StepKind::Derivative(k, _) => of_kind(k).map(|x| x / Dimension::TIME),
            StepKind::Complementary(..) => ExpectedDimension::Components(Some(Dimension::MOMENT)),
            StepKind::Action { .. } => torsor(Dimension::FORCE, Dimension::MOMENT),
            StepKind::External { point, .. } => {
                ExpectedDimension::Components(Some(if point.is_some() {
                    Dimension::MOMENT
                } else {
                    Dimension::FORCE
                }))
            }
        };
        check_expected(
            m,
            dims,
            &format!("{} (step {})", d.quantity, s.label),
            expected,
            &s.value,
        )?;
    }
    check_value(m, dims, &d.quantity, &d.value)
}
