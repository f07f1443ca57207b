//! A mechanism written in Rust instead of JSON: [`Builder`].

use super::{SpecError, build, parse_spec};
use crate::mechanism::Mechanism;
use serde_json::{Map, Value, json};

/// Builds a mechanism in code, entry by entry, with the spec file's words: what it builds is a
/// spec, validated by [`super::build`] like a file, so a mistake gets the same message and
/// names the same place (`links[1].axis`). Each method adds one entry; the methods that refine
/// an entry ([`Builder::inertia`], [`Builder::massless`], [`Builder::eom`]) apply to the last one
/// added of their kind; [`Builder::entry`] adds any entry the spec format has.
///
/// ```
/// use torseur::spec::Builder;
/// // The README's first spec: a point mass m at G, O0G = −l y1, turning about (O0, z0).
/// let m = Builder::new("Pendule simple")
///     .parameters("kg", &["m"])
///     .parameter("l", "m")
///     .parameter("g", "m/s^2")
///     .angle("theta")
///     .rotating_frame("1", "0", "z", "theta", "O0")
///     .point("G", "O0", "-l*y1")
///     .solid("1", "m", "G")
///     .gravity("-g*y0")
///     .pivot("01", ["0", "1"], "O0", "z0")
///     .moment("1", "O0", "z0").eom("theta")
///     .build()
///     .unwrap();
/// torseur::assert_equivalent!(m, "eom(theta)", "m*l^2*ddot(theta) + m*g*l*sin(theta)");
///
/// // A mistake is named where a spec file would name it.
/// let e = Builder::new("x").angle("theta").rotating_frame("1", "0", "w", "theta", "O0")
///     .build().unwrap_err();
/// assert!(e.to_string().contains("frames[0].rotation.axis: axis `w` is not x, y, z"), "{e}");
/// ```
#[derive(Debug, Clone)]
pub struct Builder {
    spec: Map<String, Value>,
}

impl Builder {
    /// A spec with this title: the ground frame `0`, its origin `O0`, and nothing else.
    pub fn new(title: &str) -> Builder {
        let mut spec = Map::new();
        spec.insert("title".into(), title.into());
        Builder { spec }
    }

    fn push(mut self, list: &str, entry: Value) -> Builder {
        let slot = self
            .spec
            .entry(list)
            .or_insert_with(|| Value::Array(Vec::new()));
        if let Value::Array(a) = slot {
            a.push(entry);
        }
        self
    }

    /// Sets `key` on the last entry of `list` (nothing if the list is empty: the validation
    /// then reports what is missing).
    fn refine(mut self, list: &str, key: &str, value: Value) -> Builder {
        if let Some(Value::Object(o)) = self
            .spec
            .get_mut(list)
            .and_then(Value::as_array_mut)
            .and_then(|a| a.last_mut())
        {
            o.insert(key.into(), value);
        }
        self
    }

    /// Sets a top-level field of the spec (`"description"`, `"ground_origin"`,
    /// `"default_basis"`, `"gravity"`…), replacing what it held.
    pub fn set(mut self, key: &str, value: Value) -> Builder {
        self.spec.insert(key.into(), value);
        self
    }

    /// Adds any entry to one of the spec's lists (`"links"`, `"actions"`, `"hypotheses"`,
    /// `"closures"`, `"scenarios"`…), written as in a spec file.
    pub fn entry(self, list: &str, entry: Value) -> Builder {
        self.push(list, entry)
    }

    /// The statement of the problem.
    pub fn description(self, text: &str) -> Builder {
        self.set("description", text.into())
    }

    /// A parameter and its unit (`"kg"`, `"m/s^2"`; `""` for none).
    pub fn parameter(self, name: &str, unit: &str) -> Builder {
        let mut p = json!({ "name": name });
        if !unit.is_empty() {
            p["unit"] = unit.into();
        }
        self.push("parameters", p)
    }

    /// Parameters of one unit (`"kg"`, &["m1", "m2"]).
    pub fn parameters(self, unit: &str, names: &[&str]) -> Builder {
        names.iter().fold(self, |b, n| b.parameter(n, unit))
    }

    /// An angle coordinate θ(t).
    pub fn angle(self, name: &str) -> Builder {
        self.push("coordinates", json!({ "name": name, "kind": "angle" }))
    }

    /// A length coordinate x(t).
    pub fn length(self, name: &str) -> Builder {
        self.push("coordinates", json!({ "name": name, "kind": "length" }))
    }

    /// A frame translated from `parent`, its origin at `origin`.
    pub fn frame(self, name: &str, parent: &str, origin: &str) -> Builder {
        self.push(
            "frames",
            json!({ "name": name, "parent": parent, "origin": origin }),
        )
    }

    /// A frame turned from `parent` by `angle` about the axis `axis` (`"x"`, `"y"`, `"z"`)
    /// the two share, its origin at `origin`.
    pub fn rotating_frame(
        self,
        name: &str,
        parent: &str,
        axis: &str,
        angle: &str,
        origin: &str,
    ) -> Builder {
        self.push(
            "frames",
            json!({ "name": name, "parent": parent, "origin": origin,
                    "rotation": { "axis": axis, "angle": angle } }),
        )
    }

    /// A point at `position` from the point `from` (`"q*x0"`, `"-l*y1"`).
    pub fn point(self, name: &str, from: &str, position: &str) -> Builder {
        self.push(
            "points",
            json!({ "name": name, "from": from, "position": position }),
        )
    }

    /// A solid fixed to the frame of the same name, of mass `mass` and centre of inertia
    /// `centre` (a point mass until [`Builder::inertia`] gives its operator).
    pub fn solid(self, name: &str, mass: &str, centre: &str) -> Builder {
        self.push(
            "solids",
            json!({ "name": name, "frame": name, "mass": mass, "centre": centre }),
        )
    }

    /// The last solid's inertia operator at `point`, in the basis of frame `basis`, by rows.
    pub fn inertia(self, point: &str, basis: &str, rows: [[&str; 3]; 3]) -> Builder {
        self.refine(
            "solids",
            "inertia",
            json!({ "point": point, "basis": basis, "matrix": rows }),
        )
    }

    /// The last solid's principal moments of inertia at `point`, on the axes of the basis of
    /// frame `basis` (a diagonal operator).
    pub fn principal_inertia(self, point: &str, basis: &str, moments: [&str; 3]) -> Builder {
        let [a, b, c] = moments;
        self.inertia(point, basis, [[a, "0", "0"], ["0", b, "0"], ["0", "0", c]])
    }

    /// The last solid has no mass (a support, a carrier): no mass, no centre.
    pub fn massless(self) -> Builder {
        let b = self.refine("solids", "massless", true.into());
        b.refine("solids", "mass", Value::Null)
            .refine("solids", "centre", Value::Null)
    }

    /// A set of solids, to isolate.
    pub fn set_of(mut self, name: &str, solids: &[&str]) -> Builder {
        let sets = self
            .spec
            .entry("sets")
            .or_insert_with(|| Value::Object(Map::new()));
        if let Value::Object(o) = sets {
            o.insert(name.into(), json!(solids));
        }
        self
    }

    /// Gravity, as a vector (`"-g*y0"`).
    pub fn gravity(self, vector: &str) -> Builder {
        self.set("gravity", vector.into())
    }

    /// A perfect link of `kind` (`"pivot"`, `"slider"`, `"ball"`, …) between two solids, at
    /// `point`, of axis (or normal) `axis`.
    pub fn link(
        self,
        name: &str,
        kind: &str,
        between: [&str; 2],
        point: &str,
        axis: &str,
    ) -> Builder {
        self.push(
            "links",
            json!({ "name": name, "kind": kind, "between": between, "point": point,
                    "axis": axis }),
        )
    }

    /// A pivot of axis `axis` at `point`.
    pub fn pivot(self, name: &str, between: [&str; 2], point: &str, axis: &str) -> Builder {
        self.link(name, "pivot", between, point, axis)
    }

    /// A slider along `axis`.
    pub fn slider(self, name: &str, between: [&str; 2], point: &str, axis: &str) -> Builder {
        self.link(name, "slider", between, point, axis)
    }

    /// A given force of `from` on `on`, applied at `point` (`"F*x0"`).
    pub fn force(self, name: &str, from: &str, on: &str, point: &str, resultant: &str) -> Builder {
        self.push(
            "actions",
            json!({ "name": name, "from": from, "on": on, "point": point,
                    "resultant": resultant }),
        )
    }

    /// A given couple of `from` on `on` (`"C*z0"`), written at `point`.
    pub fn couple(self, name: &str, from: &str, on: &str, point: &str, moment: &str) -> Builder {
        self.push(
            "actions",
            json!({ "name": name, "from": from, "on": on, "point": point, "moment": moment }),
        )
    }

    /// The resultant theorem on the set (or solid) `isolate`, projected on `on`.
    pub fn resultant(self, isolate: &str, on: &str) -> Builder {
        self.push(
            "pfd",
            json!({ "isolate": isolate, "theorem": "resultant", "on": on }),
        )
    }

    /// The moment theorem on `isolate` at `point`, projected on `on`.
    pub fn moment(self, isolate: &str, point: &str, on: &str) -> Builder {
        self.push(
            "pfd",
            json!({ "isolate": isolate, "theorem": "moment", "point": point, "on": on }),
        )
    }

    /// The last theorem is the equation of motion of the coordinate `q`.
    pub fn eom(self, q: &str) -> Builder {
        self.refine("pfd", "eom", q.into())
    }

    /// Quantities to derive (`"eom(theta)"`, `"V(G,1/0).x1"`), which `check` and the answer
    /// key take.
    pub fn quantities(self, notations: &[&str]) -> Builder {
        notations
            .iter()
            .fold(self, |b, q| b.push("quantities", (*q).into()))
    }

    /// The spec built so far, as the JSON a file would hold.
    pub fn to_json(&self) -> Value {
        Value::Object(self.spec.clone())
    }

    /// Validates the spec and builds the mechanism, as [`super::from_str`] does a file's.
    pub fn build(&self) -> Result<Mechanism, SpecError> {
        build(&parse_spec(&self.to_json().to_string())?)
    }
}
