//! The linearised trigonometric (Fourier) form: a second exact representation of an
//! expression, Σ C_(a,f) f(a), where each a = Σ kᵢ qᵢ is an integer combination of the time
//! angles (normalised as the course writes it: the highest coordinate first, with a positive
//! coefficient), f is cos or sin, and each coefficient C is a canonical [`Expr`] free of the
//! time angles' cos and sin (parameters, rates, lengths, constant angles).
//!
//! The functions cos(k·q), sin(k·q) of distinct normalised k (k ≠ 0 for sin) are linearly
//! independent over the coefficients, so the form is unique: equality and the zero test stay
//! structural. Where the canonical form writes cos q1 cos q2 + sin q1 sin q2 (two terms), this
//! form writes cos(q2 − q1) (one), which is what a planar chain's equations are made of.
//!
//! It converts both ways exactly ([`Expr::to_fourier`], [`Fourier::to_expr`]), adds,
//! multiplies (by the product-to-sum formulas) and differentiates in time on its own, so a test
//! can hold each operation against the canonical form's. An expression that divides by
//! cos q or sin q of a time angle (a loop closure's 1/cos φ) has no such form: the product
//! cos φ · (1/cos φ) would not reduce.

use super::present::Angle;
use super::*;
use std::collections::BTreeMap;

/// A harmonic cos a or sin a (a empty: the constant 1, as cos 0).
type Harmonic = (Angle, Trig);

/// An expression in the linearised trigonometric form (see the module documentation).
///
/// ```
/// use torseur::expr::Registry;
/// use torseur::spec::wire::CoordinateKind;
/// let reg = Registry::new(
///     &["m".into(), "L".into()],
///     &[("q1".into(), CoordinateKind::Angle), ("q2".into(), CoordinateKind::Angle)],
/// ).unwrap();
/// let e = reg.parse("m*L*(cos(q1)*cos(q2) + sin(q1)*sin(q2))*ddot(q2) + sin(q1)^2").unwrap();
/// let f = e.to_fourier().unwrap();
/// // m L q̈2 cos(q2 − q1) + 1/2 − 1/2 cos(2 q1): three terms where the canonical form has four.
/// assert_eq!((e.nterms(), f.nterms()), (4, 3));
/// assert_eq!(f.to_expr(), e);
/// assert_eq!(f.to_string(), "1/2 - 1/2*cos(2*q1) + m*L*ddot(q2)*cos(q2 - q1)");
/// ```
#[derive(Clone)]
pub struct Fourier {
    terms: BTreeMap<Harmonic, Expr>,
    reg: Rc<Registry>,
}

/// Terms of a canonical expression, (coefficient, exponents), in any order.
type Terms = Vec<(Rational, Vec<u8>)>;

/// A trigonometric polynomial with rational coefficients: Σ r_h h.
type TrigPoly = BTreeMap<Harmonic, Rational>;

/// The time angles of a registry: (coordinate, cos variable, sin variable).
fn time_angles(reg: &Registry) -> Vec<(CoordId, usize, usize)> {
    (0..reg.n_coords)
        .filter_map(|i| reg.coords[i].trig.map(|(c, s)| (CoordId(i), c, s)))
        .collect()
}

/// Normalises a harmonic of Σ kᵢ qᵢ: cos(−a) = cos a, sin(−a) = −sin a, sin 0 = 0. Returns
/// the harmonic and its sign, or None for sin 0.
fn harmonic(terms: BTreeMap<CoordId, i32>, f: Trig, n_coords: usize) -> Option<(Harmonic, i64)> {
    let (a, flipped) = Angle::normalized(terms.into_iter().collect(), n_coords);
    match f {
        Trig::Sin if a.terms().is_empty() => None,
        Trig::Sin if flipped => Some(((a, f), -1)),
        _ => Some(((a, f), 1)),
    }
}

/// The product of two harmonics by the product-to-sum formulas: ½ [f(a − b) ± g(a + b)].
fn harmonic_product(x: &Harmonic, y: &Harmonic, n_coords: usize) -> Vec<(Harmonic, Rational)> {
    let combine = |sign: i32| {
        let mut m: BTreeMap<CoordId, i32> = x.0.terms().iter().copied().collect();
        for &(q, k) in y.0.terms() {
            *m.entry(q).or_insert(0) += sign * k;
        }
        m
    };
    let (minus, plus) = (combine(-1), combine(1));
    // (f of a − b, its sign, f of a + b, its sign)
    let (f1, s1, f2, s2) = match (x.1, y.1) {
        (Trig::Cos, Trig::Cos) => (Trig::Cos, 1, Trig::Cos, 1),
        (Trig::Sin, Trig::Sin) => (Trig::Cos, 1, Trig::Cos, -1),
        (Trig::Sin, Trig::Cos) => (Trig::Sin, 1, Trig::Sin, 1),
        (Trig::Cos, Trig::Sin) => (Trig::Sin, -1, Trig::Sin, 1),
    };
    let mut out = Vec::with_capacity(2);
    for (m, f, s) in [(minus, f1, s1), (plus, f2, s2)] {
        if let Some((h, sign)) = harmonic(m, f, n_coords) {
            out.push((h, Rational::new(s * sign, 2)));
        }
    }
    out
}

fn trig_product(a: &TrigPoly, b: &TrigPoly, n_coords: usize) -> TrigPoly {
    let mut out = TrigPoly::new();
    for (x, r) in a {
        for (y, s) in b {
            for (h, t) in harmonic_product(x, y, n_coords) {
                let v = out.entry(h).or_insert_with(Rational::zero);
                *v = &*v + &(&(r * s) * &t);
            }
        }
    }
    out.retain(|_, v| !v.is_zero());
    out
}

fn one_harmonic() -> Harmonic {
    (Angle(Vec::new()), Trig::Cos)
}

/// The linearisations of trigonometric monomials, keyed by their powers of the time angles'
/// cos and sin, for one shape of registry (its time angles and its number of coordinates,
/// on which alone a linearisation depends). The presentation converts a long result
/// coefficient by coefficient, and the same monomials recur in each coefficient and in each
/// result of a derivation: each is linearised once per thread.
#[derive(Default)]
struct Linearisations {
    shape: (Vec<CoordId>, usize),
    known: HashMap<Vec<u8>, TrigPoly>,
}

/// Entries past which the table is emptied (a planar chain of 24 links needs about 1,200).
const LINEARISATIONS_KEPT: usize = 1 << 16;

thread_local! {
    static LINEARISATIONS: std::cell::RefCell<Linearisations> = Default::default();
}

impl Linearisations {
    /// Starts over unless the table is for this shape and not too large.
    fn prepare(&mut self, angles: &[(CoordId, usize, usize)], n: usize) {
        let same = self.shape.1 == n
            && self.shape.0.len() == angles.len()
            && self.shape.0.iter().zip(angles).all(|(a, b)| *a == b.0);
        if !same || self.known.len() > LINEARISATIONS_KEPT {
            self.shape = (angles.iter().map(|a| a.0).collect(), n);
            self.known.clear();
        }
    }

    /// The linearisation of the monomial of these powers (cos q1, sin q1, cos q2, … in the
    /// order of `angles`), computed on first use.
    fn of(&mut self, powers: &[u8], angles: &[(CoordId, usize, usize)], n: usize) -> &TrigPoly {
        self.known.entry(powers.to_vec()).or_insert_with(|| {
            let mut p = TrigPoly::from([(one_harmonic(), Rational::one())]);
            for (k, &(q, _, _)) in angles.iter().enumerate() {
                for (j, f) in [Trig::Cos, Trig::Sin].into_iter().enumerate() {
                    let single = TrigPoly::from([((Angle::of(q), f), Rational::one())]);
                    for _ in 0..powers[2 * k + j] {
                        p = trig_product(&p, &single, n);
                    }
                }
            }
            p
        })
    }
}

impl Expr {
    /// The linearised trigonometric form, or None when the expression divides by cos q or
    /// sin q of a time angle (see [`Fourier`]).
    pub fn to_fourier(&self) -> Option<Fourier> {
        let reg = &self.reg;
        let angles = time_angles(reg);
        if reg
            .reciprocals
            .iter()
            .any(|&(_, _, _, w)| self.p.degree(w) > 0)
        {
            return None;
        }
        LINEARISATIONS.with(|known| {
            let mut known = known.borrow_mut();
            known.prepare(&angles, reg.n_coords);
            Some(self.linearised(&angles, &mut known))
        })
    }

    /// [`Expr::to_fourier`] of an expression without reciprocals, each monomial linearised
    /// through `known`.
    fn linearised(
        &self,
        angles: &[(CoordId, usize, usize)],
        known: &mut Linearisations,
    ) -> Fourier {
        let reg = &self.reg;
        let n = reg.n_coords;
        // The harmonics met so far, numbered, and the terms of each one's coefficient.
        let mut index: HashMap<Harmonic, usize> = HashMap::new();
        let mut buckets: Vec<(Harmonic, Terms)> = Vec::new();
        // Each trigonometric monomial met, as (harmonic number, rational factor).
        let mut seen: HashMap<Vec<u8>, Vec<(usize, Rational)>> = HashMap::new();
        let mut powers: Vec<u8> = Vec::with_capacity(2 * angles.len());
        for (c, e) in self.terms() {
            powers.clear();
            powers.extend(angles.iter().flat_map(|&(_, ci, si)| [e[ci], e[si]]));
            if !seen.contains_key(&powers[..]) {
                let lin = known
                    .of(&powers, angles, n)
                    .iter()
                    .map(|(h, r)| {
                        let k = *index.entry(h.clone()).or_insert_with(|| {
                            buckets.push((h.clone(), Vec::new()));
                            buckets.len() - 1
                        });
                        (k, r.clone())
                    })
                    .collect();
                seen.insert(powers.clone(), lin);
            }
            let lin = &seen[&powers[..]];
            let mut rest = e.to_vec();
            for &(_, ci, si) in angles {
                rest[ci] = 0;
                rest[si] = 0;
            }
            for (j, (k, r)) in lin.iter().enumerate() {
                let x = if j + 1 == lin.len() {
                    std::mem::take(&mut rest)
                } else {
                    rest.clone()
                };
                buckets[*k].1.push((c * r, x));
            }
        }
        let coefficients = (buckets.into_iter()).map(|(h, ts)| (h, Expr::from_terms(reg, ts)));
        Fourier::of_coefficients(reg, coefficients)
    }
}

impl Fourier {
    /// The canonical form: Σ C (cos or sin of a), each cos a and sin a expanded by the angle
    /// addition formulas.
    pub fn to_expr(&self) -> Expr {
        let values: Vec<Expr> = self
            .terms
            .keys()
            .map(|(a, f)| {
                let ks: Vec<(CoordId, i64)> =
                    a.terms().iter().map(|&(q, k)| (q, k as i64)).collect();
                let (c, s) = parse::cos_sin(&self.reg, &ks, 0);
                if *f == Trig::Cos { c } else { s }
            })
            .collect();
        let pairs: Vec<(&Expr, &Expr, bool)> = self
            .terms
            .values()
            .zip(&values)
            .map(|(c, v)| (c, v, false))
            .collect();
        if pairs.is_empty() {
            return self.reg.zero();
        }
        Expr::sum_of_products(&self.reg, &pairs)
    }

    /// The harmonics and their coefficients, in a fixed order (the constant first).
    pub fn terms(&self) -> impl Iterator<Item = (&Angle, Trig, &Expr)> {
        self.terms.iter().map(|((a, f), c)| (a, *f, c))
    }

    /// Terms: Σ over the harmonics of their coefficient's terms.
    pub fn nterms(&self) -> usize {
        self.terms.values().map(Expr::nterms).sum()
    }

    /// Whether the form is zero.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The form of these harmonics' coefficients, the zero ones left out.
    fn of_coefficients(
        reg: &Rc<Registry>,
        coefficients: impl Iterator<Item = (Harmonic, Expr)>,
    ) -> Fourier {
        Fourier {
            terms: coefficients.filter(|(_, c)| !c.is_zero()).collect(),
            reg: reg.clone(),
        }
    }

    /// The form whose coefficient of each harmonic is the sum of its parts.
    fn from_parts(reg: &Rc<Registry>, parts: BTreeMap<Harmonic, Vec<Expr>>) -> Fourier {
        let sums = (parts.into_iter()).map(|(h, cs)| (h, Expr::sum(reg, cs)));
        Fourier::of_coefficients(reg, sums)
    }

    /// The sum.
    pub fn add(&self, other: &Fourier) -> Fourier {
        let mut parts: BTreeMap<Harmonic, Vec<Expr>> = BTreeMap::new();
        for (h, c) in self.terms.iter().chain(&other.terms) {
            parts.entry(h.clone()).or_default().push(c.clone());
        }
        Fourier::from_parts(&self.reg, parts)
    }

    /// The product, harmonic by harmonic by the product-to-sum formulas.
    pub fn mul(&self, other: &Fourier) -> Fourier {
        let n = self.reg.n_coords;
        let mut parts: BTreeMap<Harmonic, Vec<Expr>> = BTreeMap::new();
        for (x, cx) in &self.terms {
            for (y, cy) in &other.terms {
                let c = cx * cy;
                for (h, r) in harmonic_product(x, y, n) {
                    let term = &c * &self.reg.constant(r);
                    parts.entry(h).or_default().push(term);
                }
            }
        }
        Fourier::from_parts(&self.reg, parts)
    }

    /// d/dt: Ċ f(a) + C ȧ f′(a), with ȧ = Σ kᵢ q̇ᵢ, d cos a = −ȧ sin a, d sin a = ȧ cos a.
    /// Ċ and ȧ hold cos and sin where a coordinate's rate is driven by others' (ẋ = −R θ̇ sin θ
    /// of a loop): each piece is then put in the form and multiplied out. None when such a
    /// rate has no form (the 1/cos φ of a loop closure).
    pub fn dt(&self) -> Option<Fourier> {
        let reg = &self.reg;
        let mut out = Fourier::of_coefficients(reg, std::iter::empty());
        for ((a, f), c) in &self.terms {
            let mut pieces = vec![(c.dt(), (a.clone(), *f))];
            if !a.terms().is_empty() {
                let rate = Expr::sum(
                    reg,
                    a.terms()
                        .iter()
                        .map(|&(q, k)| &reg.rate(q, 1) * &reg.integer(k as i64)),
                );
                let (g, sign) = match f {
                    Trig::Cos => (Trig::Sin, -1),
                    Trig::Sin => (Trig::Cos, 1),
                };
                pieces.push((&(c * &rate) * &reg.integer(sign), (a.clone(), g)));
            }
            for (coef, h) in pieces {
                let one = Fourier::of_coefficients(reg, std::iter::once((h, reg.one())));
                out = out.add(&coef.to_fourier()?.mul(&one));
            }
        }
        Some(out)
    }
}

impl fmt::Display for Fourier {
    /// Σ C·cos(a) in the spec syntax (parses back to the same canonical form), the constant
    /// first, by the presentation's printer.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&super::present::fourier_form(self).text(&self.reg))
    }
}

impl PartialEq for Fourier {
    /// Structural: the form is unique.
    fn eq(&self, other: &Fourier) -> bool {
        self.terms == other.terms
    }
}

impl Eq for Fourier {}

impl fmt::Debug for Fourier {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Fourier({self})")
    }
}
