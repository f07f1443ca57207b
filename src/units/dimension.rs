//! The dimension Mᵃ Lᵇ Tᶜ of a unit: reading the spec's unit texts, and writing a dimension as
//! the SI unit the course uses, in plain text and LaTeX.

use std::fmt;
use std::ops::{Div, Mul};
use std::str::FromStr;

/// A physical dimension Mᵃ Lᵇ Tᶜ: the exponents of mass, length and time (the radian is
/// dimensionless, see the [module documentation](super)).
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

    /// The dimension whose square is self, when every exponent is even (√(L²) = L); none
    /// otherwise (√L is no dimension of the SI).
    ///
    /// ```
    /// use torseur::units::Dimension;
    /// assert_eq!(Dimension::LENGTH.pow(2).sqrt(), Some(Dimension::LENGTH));
    /// assert_eq!(Dimension::LENGTH.sqrt(), None);
    /// ```
    pub fn sqrt(self) -> Option<Dimension> {
        let half = |k: i32| (k % 2 == 0).then_some(k / 2);
        Some(Dimension::new(
            half(self.mass)?,
            half(self.length)?,
            half(self.time)?,
        ))
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

/// The SI unit for messages, `1` for a pure number.
pub(super) fn unit_or_one(d: &Dimension) -> String {
    match d.si_text(UnitStyle::Mechanics) {
        s if s.is_empty() => "1".to_string(),
        s => s,
    }
}
