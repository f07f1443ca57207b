//! Quantity notation: the course's way of naming a result (`delta(O2,2/0).x2`) is its id.

use std::fmt;

/// A motion i/j: the solid, set or frame `moving` relative to `reference`.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Motion {
    /// The moving solid, set or frame (`2`, `E`).
    pub moving: String,
    /// The reference solid or frame (`0`).
    pub reference: String,
}

impl fmt::Display for Motion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.moving, self.reference)
    }
}

/// An action {T(from→on)}: what `from` exerts on the solid or set `on`.
///
/// `from` is written as the answer key's « bilan des actions mécaniques extérieures » writes
/// it: a solid or frame (the links between it and `on`), `pes` (gravity), the name of a given
/// action (`moteur`), or `ext` for the sum of every action exterior to `on` (the course's
/// Ē→E).
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct ActionRef {
    /// What exerts it.
    pub from: String,
    /// The solid or set that receives it.
    pub on: String,
}

impl fmt::Display for ActionRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}->{}", self.from, self.on)
    }
}

/// What is asked for, before any basis or projection. Fields are the notation's arguments:
/// `point` a point name, `motion` a motion i/j, `solid` a solid name.
#[allow(missing_docs)]
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum QuantityKind {
    /// Ω(i/j)
    Omega(Motion),
    /// V(P, i/j)
    Velocity { point: String, motion: Motion },
    /// Γ(P, i/j)
    Acceleration { point: String, motion: Motion },
    /// I(P, S): inertia operator of solid S at P.
    Inertia { point: String, solid: String },
    /// Rc(S/R): kinetic resultant m V(G, S/R).
    KineticResultant(Motion),
    /// σ(A, S/R)
    KineticMoment { point: String, motion: Motion },
    /// Rd(S/R): dynamic resultant m Γ(G, S/R).
    DynamicResultant(Motion),
    /// δ(A, S/R)
    DynamicMoment { point: String, motion: Motion },
    /// {V(i/j)}_A: kinematic torsor.
    KinematicTorsor { motion: Motion, point: String },
    /// {C(S/R)}_A: kinetic torsor.
    KineticTorsor { motion: Motion, point: String },
    /// {D(S/R)}_A: dynamic torsor.
    DynamicTorsor { motion: Motion, point: String },
    /// Ec(S/R): kinetic energy.
    KineticEnergy(Motion),
    /// An unknown of the PFD solved in closed form (`C_m`, `X01`): its bare name.
    Unknown(String),
    /// eom(q): the equation of motion of coordinate q, as the expression equal to zero
    /// (dynamic side minus actions, unknowns eliminated).
    Eom(String),
    /// R(from→on): the resultant of an action, the unknowns of links kept as unknowns.
    ActionResultant(ActionRef),
    /// M(A, from→on): the moment at A of an action.
    ActionMoment { point: String, action: ActionRef },
    /// {T(from→on)}_A: the torsor of an action at A.
    ActionTorsor { action: ActionRef, point: String },
    /// P(from→on/R): the power of an action in the motion of what receives it relative to R,
    /// Σ {T(from→S)} ⊗ {V(S/R)} over the solids S of `on` (théorème de l'énergie cinétique).
    Power {
        action: ActionRef,
        reference: String,
    },
    /// P_int(E): the power of the actions between the solids of E (the links' friction and
    /// springs), Σ {T(i→j)} ⊗ {V(j/i)}: independent of any reference frame.
    InternalPower(String),
    /// dot(q), ddot(q): the rate of a coordinate, order 1 or 2. For a coordinate that a loop
    /// closure, a rolling condition or a screw determines (the slider–crank's λ), the rate
    /// the loop law gives in terms of the free rates (λ̇ as a function of θ̇); for a free
    /// coordinate, its own rate; for one whose rate is imposed, the imposed rate.
    Rate {
        /// The coordinate's name.
        coordinate: String,
        /// 1 for q̇, 2 for q̈.
        order: u8,
    },
    /// J_eq(q): the inertia (or mass, for a length) equivalent to the whole mechanism brought
    /// back to coordinate q, Ec(all/0) = ½ J_eq q̇², when every other rate is driven by q̇.
    EquivalentInertia(String),
    /// d/dt(Q): the time derivative of the scalar quantity `of` (`d/dt(Ec(E/0))`), or, with a
    /// `frame`, [d/dt Q]_R of the vector quantity `of` in the frame R
    /// (`d/dt(sigma(A,2/0))|0`). `of` is Ω, V, Rc, σ or Ec (or a projection of a vector among
    /// them, for a scalar): their values hold rates, never accelerations, so their
    /// derivatives hold no third derivative.
    Derivative {
        of: Box<Quantity>,
        frame: Option<String>,
    },
}

/// A requested quantity: a kind, an optional basis to express it in, an optional projection.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Quantity {
    /// What is asked for.
    pub kind: QuantityKind,
    /// `in B2`: the frame whose basis the result is written in.
    pub basis: Option<String>,
    /// `.x2`: scalar projection on a basis vector (frame name, axis letter).
    pub projection: Option<(String, char)>,
    /// `lin(...)`: linearised for small motions around the spec's equilibrium (`small`).
    pub linear: bool,
}

/// Why a quantity string is not in the notation.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("quantity `{}`: {reason}", crate::excerpt::excerpt(.input))]
pub struct NotationError {
    /// The string given.
    pub input: String,
    /// What is wrong with it.
    pub reason: String,
}

impl Quantity {
    /// Parses the course notation.
    ///
    /// ```
    /// use torseur::quantity::{Quantity, QuantityKind};
    /// let q = Quantity::parse("delta(O2,2/0).x2").unwrap();
    /// assert!(matches!(q.kind, QuantityKind::DynamicMoment { .. }));
    /// assert_eq!(q.projection, Some(("2".to_string(), 'x')));
    /// assert_eq!(q.to_string(), "delta(O2,2/0).x2");
    /// assert!(Quantity::parse("delta(O2;2/0)").is_err());
    /// // Actions: as the bilan writes them, `ext` for every action exterior to a set.
    /// for q in ["R(0->1)", "M(A,pes->2).y1", "M(O1,ext->E).z0", "{T(0->1)}_O1 in B1"] {
    ///     assert_eq!(Quantity::parse(q).unwrap().to_string(), q);
    /// }
    /// assert!(Quantity::parse("M(A,0/1)").is_err());
    /// // Found by the fuzzer: a long name of multi-byte characters is an error, not a panic.
    /// assert!(Quantity::parse("Omega(߰߰߰߰߰߰߰߰߰߰߰߰߰߰߰߰߰߰߰߰/0)").is_err());
    /// // Time derivatives: of a scalar, d/dt(Q); of a vector, in a frame, d/dt(Q)|R.
    /// for q in ["d/dt(Ec(E/0))", "d/dt(sigma(A,2/0))|0", "d/dt(V(G,2/0))|1.x1",
    ///           "d/dt(Omega(2/0))|0 in B2", "d/dt(sigma(O,1/0).z0)"] {
    ///     assert_eq!(Quantity::parse(q).unwrap().to_string(), q);
    /// }
    /// assert!(Quantity::parse("d/dt(Ec(E/0))").unwrap().is_scalar());
    /// // Near misses say the spelling.
    /// let e = Quantity::parse("dEc(E/0)/dt").unwrap_err();
    /// assert!(e.reason.contains("d/dt(Ec(E/0))"), "{e}");
    /// let e = Quantity::parse("d/dt(sigma(A,2/0))").unwrap_err();
    /// assert!(e.reason.contains("d/dt(sigma(A,2/0))|0"), "{e}");
    /// assert!(Quantity::parse("d/dt(delta(A,2/0))|0").is_err());
    /// ```
    pub fn parse(input: &str) -> Result<Quantity, NotationError> {
        let err = |reason: &str| NotationError {
            input: input.to_string(),
            reason: reason.to_string(),
        };
        if input.len() > 200 {
            return Err(err("longer than 200 characters"));
        }
        let s: String = input.trim().to_string();
        // lin(Q): the small-motion linearisation of Q.
        if let Some(inner) = s.strip_prefix("lin(").and_then(|r| r.strip_suffix(')')) {
            let mut q = Quantity::parse(inner).map_err(|e| err(&e.reason))?;
            if q.linear {
                return Err(err("lin(...) is not nested"));
            }
            if matches!(q.kind, QuantityKind::Inertia { .. }) || q.kind.is_torsor() {
                return Err(err("lin(...) takes a vector or a scalar quantity"));
            }
            q.linear = true;
            return Ok(q);
        }
        // `d/dt(sigma(A,2/0) in B1)|0`: the basis belongs after the derivative.
        if s.starts_with("d/dt")
            && let Some((_, tail)) = s.rsplit_once(" in ")
            && tail.contains([')', '|'])
        {
            return Err(err(
                "the basis is written after the derivative: d/dt(sigma(A,2/0))|0 in B1",
            ));
        }
        let (body, basis) = split_basis(&s).map_err(|r| err(&r))?;
        let body = body.replace(' ', "");
        if let Some(rest) = body.strip_prefix("d/dt") {
            let (kind, projection) = derivative(rest).map_err(|r| err(&r))?;
            validate_written(&kind, basis.is_some(), projection.is_some()).map_err(err)?;
            return Ok(Quantity {
                kind,
                basis,
                projection,
                linear: false,
            });
        }
        if let Some(hint) = derivative_hint(&body) {
            return Err(err(&hint));
        }
        let (core, projection) = split_projection(&body).map_err(|r| err(&r))?;
        let kind = if !core.contains('(') && crate::expr::validate_identifier(core).is_ok() {
            QuantityKind::Unknown(core.to_string())
        } else if let Some(rest) = core.strip_prefix('{') {
            torsor_kind(rest).map_err(|r| err(&r))?
        } else {
            call_kind(core).map_err(|r| err(&r))?
        };
        validate_written(&kind, basis.is_some(), projection.is_some()).map_err(err)?;
        Ok(Quantity {
            kind,
            basis,
            projection,
            linear: false,
        })
    }

    /// The same quantity expressed in basis `b` (no projection).
    pub fn with_basis(&self, b: &str) -> Quantity {
        Quantity {
            kind: self.kind.clone(),
            basis: Some(b.to_string()),
            projection: None,
            linear: self.linear,
        }
    }

    /// Whether the value is a scalar (a projection, an energy, an unknown, an equation).
    pub fn is_scalar(&self) -> bool {
        self.projection.is_some() || self.kind.is_scalar_kind()
    }
}

impl QuantityKind {
    /// The action involved, if any.
    pub fn action(&self) -> Option<&ActionRef> {
        match self {
            QuantityKind::ActionResultant(a)
            | QuantityKind::ActionMoment { action: a, .. }
            | QuantityKind::ActionTorsor { action: a, .. }
            | QuantityKind::Power { action: a, .. } => Some(a),
            _ => None,
        }
    }

    /// Whether this is a whole torsor.
    pub fn is_torsor(&self) -> bool {
        matches!(
            self,
            QuantityKind::KinematicTorsor { .. }
                | QuantityKind::KineticTorsor { .. }
                | QuantityKind::DynamicTorsor { .. }
                | QuantityKind::ActionTorsor { .. }
        )
    }

    /// Whether the kind is a scalar by itself (no projection needed).
    pub fn is_scalar_kind(&self) -> bool {
        if let QuantityKind::Derivative { frame, .. } = self {
            return frame.is_none();
        }
        matches!(
            self,
            QuantityKind::KineticEnergy(_)
                | QuantityKind::Unknown(_)
                | QuantityKind::Eom(_)
                | QuantityKind::Power { .. }
                | QuantityKind::InternalPower(_)
                | QuantityKind::EquivalentInertia(_)
                | QuantityKind::Rate { .. }
        )
    }

    /// The motion involved, if any.
    pub fn motion(&self) -> Option<&Motion> {
        use QuantityKind::*;
        match self {
            Omega(m) | KineticResultant(m) | DynamicResultant(m) => Some(m),
            Velocity { motion, .. }
            | Acceleration { motion, .. }
            | KineticMoment { motion, .. }
            | DynamicMoment { motion, .. }
            | KinematicTorsor { motion, .. }
            | KineticTorsor { motion, .. }
            | DynamicTorsor { motion, .. } => Some(motion),
            KineticEnergy(m) => Some(m),
            Inertia { .. }
            | Unknown(_)
            | Eom(_)
            | ActionResultant(_)
            | ActionMoment { .. }
            | ActionTorsor { .. }
            | Power { .. }
            | InternalPower(_)
            | EquivalentInertia(_)
            | Rate { .. }
            | Derivative { .. } => None,
        }
    }
}

impl fmt::Display for QuantityKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use QuantityKind::*;
        match self {
            Omega(m) => write!(f, "Omega({m})"),
            Velocity { point, motion } => write!(f, "V({point},{motion})"),
            Acceleration { point, motion } => write!(f, "Gamma({point},{motion})"),
            Inertia { point, solid } => write!(f, "I({point},{solid})"),
            KineticResultant(m) => write!(f, "Rc({m})"),
            KineticMoment { point, motion } => write!(f, "sigma({point},{motion})"),
            DynamicResultant(m) => write!(f, "Rd({m})"),
            DynamicMoment { point, motion } => write!(f, "delta({point},{motion})"),
            KinematicTorsor { motion, point } => write!(f, "{{V({motion})}}_{point}"),
            KineticTorsor { motion, point } => write!(f, "{{C({motion})}}_{point}"),
            DynamicTorsor { motion, point } => write!(f, "{{D({motion})}}_{point}"),
            KineticEnergy(m) => write!(f, "Ec({m})"),
            Unknown(name) => write!(f, "{name}"),
            Eom(q) => write!(f, "eom({q})"),
            ActionResultant(a) => write!(f, "R({a})"),
            ActionMoment { point, action } => write!(f, "M({point},{action})"),
            ActionTorsor { action, point } => write!(f, "{{T({action})}}_{point}"),
            Power { action, reference } => write!(f, "P({action}/{reference})"),
            InternalPower(set) => write!(f, "Pint({set})"),
            EquivalentInertia(q) => write!(f, "J_eq({q})"),
            Rate {
                coordinate,
                order: 1,
            } => write!(f, "dot({coordinate})"),
            Rate { coordinate, .. } => write!(f, "ddot({coordinate})"),
            Derivative { of, frame } => {
                write!(f, "d/dt({of})")?;
                match frame {
                    Some(r) => write!(f, "|{r}"),
                    None => Ok(()),
                }
            }
        }
    }
}

impl fmt::Display for Quantity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.linear {
            let inner = Quantity {
                linear: false,
                ..self.clone()
            };
            return write!(f, "lin({inner})");
        }
        write!(f, "{}", self.kind)?;
        if let Some((frame, axis)) = &self.projection {
            write!(f, ".{axis}{frame}")?;
        }
        if let Some(b) = &self.basis {
            write!(f, " in B{b}")?;
        }
        Ok(())
    }
}

/// Splits `name(args)`.
fn call(s: &str) -> Option<(&str, &str)> {
    let open = s.find('(')?;
    let inner = s[open + 1..].strip_suffix(')')?;
    if inner.contains('(') || inner.contains(')') {
        return None;
    }
    Some((&s[..open], inner))
}

fn motion(s: &str) -> Result<Motion, String> {
    let (a, b) = s
        .split_once('/')
        .ok_or_else(|| format!("expected a motion moving/reference, got `{s}`"))?;
    validate_system(a)?;
    validate_name(b)?;
    Ok(Motion {
        moving: a.to_string(),
        reference: b.to_string(),
    })
}

fn action(s: &str) -> Result<ActionRef, String> {
    let (a, b) = s
        .split_once("->")
        .ok_or_else(|| format!("expected an action from->on, got `{s}`"))?;
    validate_name(a)?;
    validate_system(b)?;
    Ok(ActionRef {
        from: a.to_string(),
        on: b.to_string(),
    })
}

/// A system: a solid or a set, or several joined by `+` (`1+2`, a carrier with the mass it
/// carries), each a name.
fn validate_system(s: &str) -> Result<(), String> {
    s.split('+').try_for_each(validate_name)
}

/// Names in the notation are ASCII letters, digits and `_`, starting with a letter or digit.
pub fn validate_name(s: &str) -> Result<(), String> {
    if s.is_empty() {
        return Err("empty name".to_string());
    }
    if s.len() > 32 {
        let head: String = s.chars().take(32).collect();
        return Err(format!("name `{head}…` longer than 32 characters"));
    }
    if !s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') || s.starts_with('_') {
        return Err(format!(
            "name `{s}`: only ASCII letters, digits and `_` are allowed"
        ));
    }
    Ok(())
}

/// The optional ` in B<frame>` suffix: the text before it, and the frame.
fn split_basis(s: &str) -> Result<(&str, Option<String>), String> {
    match s.rsplit_once(" in ") {
        Some((b, basis)) => {
            let basis = basis.trim();
            let name = basis
                .strip_prefix('B')
                .ok_or("the basis after `in` is written B<frame>, e.g. B2")?;
            validate_name(name)?;
            Ok((b.trim(), Some(name.to_string())))
        }
        None => Ok((s, None)),
    }
}

/// A projection `.x2`: (frame, axis).
type Projection = (String, char);

/// The optional `.x2` projection (only after a closing parenthesis): the text before it, and
/// the projection.
fn split_projection(body: &str) -> Result<(&str, Option<Projection>), String> {
    let Some(pos) = body.rfind(").") else {
        return Ok((body, None));
    };
    let v = &body[pos + 2..];
    let mut chars = v.chars();
    let axis = chars.next().ok_or("empty projection")?;
    if !matches!(axis, 'x' | 'y' | 'z') {
        return Err("a projection is on x<frame>, y<frame> or z<frame>".to_string());
    }
    let frame: String = chars.collect();
    if frame.is_empty() {
        return Err(format!(
            "a projection names its frame after the axis, as the course writes \
             it: .{axis}0 for the ground, .{axis}2 for frame 2, not .{axis}"
        ));
    }
    validate_name(&frame)?;
    Ok((&body[..pos + 1], Some((frame, axis))))
}

/// A torsor after its `{`: `C(2/0)}_O2`, `T(0->1)}_O1`.
fn torsor_kind(rest: &str) -> Result<QuantityKind, String> {
    let (inner, point) = rest
        .split_once("}_")
        .ok_or("a torsor is written {C(S/R)}_A")?;
    validate_name(point)?;
    let (letter, args) = call(inner).ok_or("a torsor is written {C(S/R)}_A")?;
    let point = point.to_string();
    if letter == "T" {
        let action = action(args)?;
        return Ok(QuantityKind::ActionTorsor { action, point });
    }
    let motion = motion(args)?;
    Ok(match letter {
        "V" => QuantityKind::KinematicTorsor { motion, point },
        "C" => QuantityKind::KineticTorsor { motion, point },
        "D" => QuantityKind::DynamicTorsor { motion, point },
        _ => return Err("torsors are {V(..)}, {C(..)}, {D(..)} and {T(..)}".to_string()),
    })
}

/// `(point,moving/reference)`.
fn point_motion(args: &str) -> Result<(String, Motion), String> {
    let (p, m) = args
        .split_once(',')
        .ok_or_else(|| "expected (point,moving/reference)".to_string())?;
    validate_name(p)?;
    Ok((p.to_string(), motion(m)?))
}

/// A quantity written `name(arguments)`.
fn call_kind(core: &str) -> Result<QuantityKind, String> {
    let (name, args) = call(core).ok_or("expected name(arguments)")?;
    Ok(match name {
        "Omega" => QuantityKind::Omega(motion(args)?),
        "Rc" => QuantityKind::KineticResultant(motion(args)?),
        "Rd" => QuantityKind::DynamicResultant(motion(args)?),
        "V" | "Gamma" | "sigma" | "delta" => {
            let (point, motion) = point_motion(args)?;
            match name {
                "V" => QuantityKind::Velocity { point, motion },
                "Gamma" => QuantityKind::Acceleration { point, motion },
                "sigma" => QuantityKind::KineticMoment { point, motion },
                _ => QuantityKind::DynamicMoment { point, motion },
            }
        }
        "Ec" => QuantityKind::KineticEnergy(motion(args)?),
        "P" => {
            let (a, reference) = args
                .rsplit_once('/')
                .ok_or("a power is written P(from->on/reference), e.g. P(ext->E/0)")?;
            validate_name(reference)?;
            QuantityKind::Power {
                action: action(a)?,
                reference: reference.to_string(),
            }
        }
        "Pint" => {
            validate_system(args)?;
            QuantityKind::InternalPower(args.to_string())
        }
        "J_eq" => {
            crate::expr::validate_identifier(args)?;
            QuantityKind::EquivalentInertia(args.to_string())
        }
        "R" => QuantityKind::ActionResultant(action(args)?),
        "M" => {
            let (p, a) = args
                .split_once(',')
                .ok_or("a moment of an action is written M(A,from->on)")?;
            validate_name(p)?;
            QuantityKind::ActionMoment {
                point: p.to_string(),
                action: action(a)?,
            }
        }
        "eom" => {
            crate::expr::validate_identifier(args)?;
            QuantityKind::Eom(args.to_string())
        }
        "dot" | "ddot" => {
            crate::expr::validate_identifier(args)?;
            QuantityKind::Rate {
                coordinate: args.to_string(),
                order: if name == "dot" { 1 } else { 2 },
            }
        }
        "I" => {
            let (p, solid) = args
                .split_once(',')
                .ok_or("an inertia operator is written I(P,S)")?;
            validate_name(p)?;
            validate_name(solid)?;
            QuantityKind::Inertia {
                point: p.to_string(),
                solid: solid.to_string(),
            }
        }
        other => {
            const KINDS: [&str; 15] = [
                "Omega", "V", "Gamma", "I", "Rc", "sigma", "Rd", "delta", "Ec", "eom", "R", "M",
                "P", "Pint", "J_eq",
            ];
            let guess = crate::hint::closest(other, &KINDS)
                .map(|k| format!("did you mean `{k}`? "))
                .unwrap_or_default();
            return Err(format!(
                "unknown quantity `{other}` ({guess}{}known: Omega, V, Gamma, I, Rc, sigma, Rd, \
                 delta, Ec, eom, R, M, P, Pint, J_eq, {{V(..)}}_A, {{C(..)}}_A, \
                 {{D(..)}}_A, {{T(..)}}_A, or the name of an unknown)",
                crate::expr::function_hint(other)
            ));
        }
    })
}

/// Whether a kind takes the basis and projection written after it.
fn validate_written(
    kind: &QuantityKind,
    basis: bool,
    projection: bool,
) -> Result<(), &'static str> {
    if projection && matches!(kind, QuantityKind::Inertia { .. }) {
        return Err("an inertia operator cannot be projected");
    }
    if (projection || basis) && kind.is_scalar_kind() {
        return Err("this quantity is a scalar: it takes no basis or projection");
    }
    if projection && kind.is_torsor() {
        return Err("a torsor cannot be projected");
    }
    if projection && basis {
        return Err("a projection is a scalar: it takes no basis");
    }
    Ok(())
}

/// The kinds whose time derivative may be asked: their values hold rates, never
/// accelerations or unknowns, so their derivatives hold no third derivative.
const DERIVABLE: &str = "Omega, V, Rc, sigma or Ec (or a projection of one of the vectors)";

/// The end of the parenthesis group opening at byte 0 of `s`: the index of its `)`.
fn closing(s: &str) -> Option<usize> {
    let mut depth = 0usize;
    for (i, c) in s.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => {
                depth = depth.checked_sub(1)?;
                if depth == 0 {
                    return Some(i);
                }
            }
            _ => {}
        }
    }
    None
}

/// `d/dt(Q)` or `d/dt(Q)|R`, after its `d/dt`, with an optional projection `.x2` after the
/// frame: the kind and the projection.
fn derivative(rest: &str) -> Result<(QuantityKind, Option<Projection>), String> {
    let form = "the derivative of a quantity is written d/dt(Q): d/dt(Ec(E/0)) for a scalar, \
                d/dt(sigma(A,2/0))|0 for [d/dt σ(A,2/0)]_R0";
    if !rest.starts_with('(') {
        return Err(form.to_string());
    }
    let close = closing(rest).ok_or("unbalanced parentheses in d/dt(...)")?;
    let inner = &rest[1..close];
    let of = Quantity::parse(inner).map_err(|e| format!("in d/dt({inner}): {}", e.reason))?;
    if of.basis.is_some() {
        return Err(format!(
            "the basis is written after the derivative: d/dt({})|0 in B{}",
            of.kind,
            of.basis.as_deref().unwrap_or("")
        ));
    }
    if of.linear {
        return Err("lin(...) is written around the derivative: lin(d/dt(Q))".to_string());
    }
    let third = "its derivative would hold the third derivatives of the coordinates, \
                 which the engine does not have";
    match &of.kind {
        QuantityKind::Omega(_)
        | QuantityKind::Velocity { .. }
        | QuantityKind::KineticResultant(_)
        | QuantityKind::KineticMoment { .. }
        | QuantityKind::KineticEnergy(_) => {}
        QuantityKind::Acceleration { .. }
        | QuantityKind::DynamicResultant(_)
        | QuantityKind::DynamicMoment { .. }
        | QuantityKind::Derivative { .. } => {
            return Err(format!(
                "d/dt takes {DERIVABLE}: `{}` holds accelerations, so {third}",
                of.kind
            ));
        }
        k => {
            return Err(format!(
                "d/dt takes {DERIVABLE}, not `{k}` (its value may hold accelerations or \
                 unknowns of the PFD, whose derivatives the engine does not have)"
            ));
        }
    }
    let after = &rest[close + 1..];
    let scalar = of.is_scalar();
    let Some(framed) = after.strip_prefix('|') else {
        return match after {
            "" if scalar => Ok((
                QuantityKind::Derivative {
                    of: Box::new(of),
                    frame: None,
                },
                None,
            )),
            "" => Err(format!(
                "`{of}` is a vector: its derivative is taken in a frame, d/dt({of})|0 for the \
                 derivative in R0"
            )),
            a if a.starts_with('_') => Err(format!(
                "the frame follows a bar: d/dt({of})|{}",
                a.trim_start_matches(['_', '{', 'R']).trim_end_matches('}')
            )),
            a if scalar => Err(format!(
                "`{of}` is a scalar: d/dt({of}) takes nothing after it (`{a}`)"
            )),
            a => Err(format!(
                "after d/dt({of}) comes its frame, |0, then a projection .x0 if any, not `{a}`"
            )),
        };
    };
    if scalar {
        return Err(format!(
            "`{of}` is a scalar: its derivative takes no frame, write d/dt({of})"
        ));
    }
    let (frame, projected) = match framed.split_once('.') {
        Some((f, p)) => (f, Some(p)),
        None => (framed, None),
    };
    validate_name(frame).map_err(|e| format!("the frame of the derivative: {e}"))?;
    let projection = match projected {
        None => None,
        Some(p) => {
            // The same rule as after a closing parenthesis: `.x2`.
            let (_, proj) = split_projection(&format!(").{p}"))?;
            proj
        }
    };
    Ok((
        QuantityKind::Derivative {
            of: Box::new(of),
            frame: Some(frame.to_string()),
        },
        projection,
    ))
}

/// What a near miss of the derivative's notation should have been, when `body` (spaces
/// removed) is one: `dEc(E/0)/dt`, `[d/dt sigma(A,2/0)]_0`, `dot(Ec(E/0))`, `diff(...)`.
fn derivative_hint(body: &str) -> Option<String> {
    let form = |q: &str| {
        let vector = !q.starts_with("Ec(") && !q.contains(").");
        if vector {
            format!("write d/dt({q})|0 for its derivative in R0 (the frame after the bar)")
        } else {
            format!("write d/dt({q}) for its time derivative")
        }
    };
    if let Some(inner) = body.strip_prefix("[d/dt").or(body.strip_prefix("[d")) {
        let q = inner
            .split(']')
            .next()
            .unwrap_or("")
            .trim_start_matches('(');
        let q = q.strip_suffix("/dt").unwrap_or(q);
        return Some(form(if q.is_empty() { "sigma(A,2/0)" } else { q }));
    }
    for head in ["dot(", "ddot(", "ddt(", "diff(", "derivative(", "d("] {
        if let Some(inner) = body.strip_prefix(head).and_then(|r| r.strip_suffix(')'))
            && inner.contains('(')
        {
            let q = inner.split(",t").next().unwrap_or(inner);
            let why = match head {
                "dot(" => "dot(q) is the rate of a coordinate; ",
                "ddot(" => {
                    "ddot(q) is the second derivative of a coordinate (a quantity has \
                            a first derivative only); "
                }
                _ => "",
            };
            return Some(format!("{why}{}", form(q)));
        }
    }
    // dEc(E/0)/dt, dsigma(A,2/0)/dt: the course's dX/dt.
    let q = body.strip_prefix('d')?.strip_suffix("/dt")?;
    let name = q.split('(').next()?;
    ["Ec", "sigma", "V", "Omega", "Rc"]
        .contains(&name)
        .then(|| form(q))
}
