//! Line and column of the value at a JSON path (`solids[1].inertia.matrix[0][1]`) in a spec's
//! text, so that errors found after parsing (an unknown frame, a cycle) point at the place.

enum Seg {
    Key(String),
    Index(usize),
}

fn segments(path: &str) -> Option<Vec<Seg>> {
    let mut out = Vec::new();
    for part in path.split('.') {
        let (key, mut rest) = match part.find('[') {
            Some(i) => (&part[..i], &part[i..]),
            None => (part, ""),
        };
        if !key.is_empty() {
            out.push(Seg::Key(key.to_string()));
        }
        while let Some(r) = rest.strip_prefix('[') {
            let close = r.find(']')?;
            out.push(Seg::Index(r[..close].parse().ok()?));
            rest = &r[close + 1..];
        }
    }
    Some(out)
}

struct Scanner<'a> {
    b: &'a [u8],
    i: usize,
}

impl Scanner<'_> {
    fn ws(&mut self) {
        while self.i < self.b.len() && self.b[self.i].is_ascii_whitespace() {
            self.i += 1;
        }
    }

    fn string(&mut self) -> Option<String> {
        if self.b.get(self.i) != Some(&b'"') {
            return None;
        }
        let start = self.i;
        self.i += 1;
        while self.i < self.b.len() {
            match self.b[self.i] {
                b'\\' => self.i += 2,
                b'"' => {
                    self.i += 1;
                    let raw = std::str::from_utf8(&self.b[start..self.i]).ok()?;
                    return serde_json::from_str(raw).ok();
                }
                _ => self.i += 1,
            }
        }
        None
    }

    /// Skips one value (bounded nesting: the spec was parsed by serde_json already).
    fn skip(&mut self, depth: usize) -> Option<()> {
        if depth > 256 {
            return None;
        }
        self.ws();
        match *self.b.get(self.i)? {
            b'"' => self.string().map(|_| ()),
            b'{' | b'[' => {
                let close = if self.b[self.i] == b'{' { b'}' } else { b']' };
                self.i += 1;
                loop {
                    self.ws();
                    if *self.b.get(self.i)? == close {
                        self.i += 1;
                        return Some(());
                    }
                    if close == b'}' {
                        self.string()?;
                        self.ws();
                        self.i += 1; // ':'
                    }
                    self.skip(depth + 1)?;
                    self.ws();
                    if *self.b.get(self.i)? == b',' {
                        self.i += 1;
                    }
                }
            }
            _ => {
                while self.i < self.b.len() && !b",}] \t\r\n".contains(&self.b[self.i]) {
                    self.i += 1;
                }
                Some(())
            }
        }
    }

    /// Moves to the start of the value at `seg` inside the current object or array.
    fn enter(&mut self, seg: &Seg) -> Option<()> {
        self.ws();
        match (seg, *self.b.get(self.i)?) {
            (Seg::Key(k), b'{') => {
                self.i += 1;
                loop {
                    self.ws();
                    let key = self.string()?;
                    self.ws();
                    self.i += 1; // ':'
                    self.ws();
                    if &key == k {
                        return Some(());
                    }
                    self.skip(0)?;
                    self.ws();
                    if *self.b.get(self.i)? != b',' {
                        return None;
                    }
                    self.i += 1;
                }
            }
            (Seg::Index(n), b'[') => {
                self.i += 1;
                for _ in 0..*n {
                    self.skip(0)?;
                    self.ws();
                    if *self.b.get(self.i)? != b',' {
                        return None;
                    }
                    self.i += 1;
                }
                self.ws();
                Some(())
            }
            _ => None,
        }
    }
}

/// 1-based (line, column) of the value at `path` in `text`, if it can be found.
///
/// ```
/// let text = "{\n  \"frames\": [\n    {\"name\": \"1\"},\n    {\"name\": \"2\", \"parent\": \"9\"}\n  ]\n}";
/// assert_eq!(torseur::spec::locate(text, "frames[1].parent"), Some((4, 29)));
/// ```
pub fn locate(text: &str, path: &str) -> Option<(usize, usize)> {
    let segs = segments(path)?;
    let mut s = Scanner {
        b: text.as_bytes(),
        i: 0,
    };
    for seg in &segs {
        s.enter(seg)?;
    }
    s.ws();
    let before = &text[..s.i.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    Some((line, column))
}

/// The fixed number of elements of the array at a JSON path of a spec (`solids[1].inertia.matrix`
/// holds 3 rows, `ground_basis` 3 names), read from the spec's JSON Schema; none where the
/// path is not a fixed-length array.
///
/// ```
/// // Through an internal function: the message of an array given too many elements.
/// let spec = r#"{"title": "t", "ground_basis": ["x", "y", "z", "w"]}"#;
/// let e = torseur::spec::parse_spec(spec).unwrap_err().to_string();
/// assert!(e.starts_with("at ground_basis (line 1, column "), "{e}");
/// assert!(e.ends_with("more elements than the 3 this array holds"), "{e}");
/// ```
pub(super) fn fixed_length(path: &str) -> Option<usize> {
    let schema = super::json_schema();
    let defs = schema.get("$defs");
    // The node and its alternatives (an optional value is `anyOf` a type and null), each with
    // its `$ref` followed.
    let choices = |n: &serde_json::Value| -> Vec<serde_json::Value> {
        let mut out = Vec::new();
        let mut todo = vec![n.clone()];
        while let Some(n) = todo.pop() {
            if out.len() + todo.len() > 64 {
                break;
            }
            match n.get("$ref").and_then(|r| r.as_str()) {
                Some(r) => todo.extend(
                    (r.strip_prefix("#/$defs/"))
                        .and_then(|name| defs?.get(name))
                        .cloned(),
                ),
                None => {
                    for key in ["anyOf", "oneOf", "allOf"] {
                        if let Some(alts) = n.get(key).and_then(|a| a.as_array()) {
                            todo.extend(alts.iter().cloned());
                        }
                    }
                    out.push(n);
                }
            }
        }
        out
    };
    let mut nodes = choices(&schema);
    for seg in segments(path)? {
        nodes = nodes
            .iter()
            .filter_map(|n| match &seg {
                Seg::Key(k) => n
                    .get("properties")
                    .and_then(|p| p.get(k))
                    .or_else(|| n.get("additionalProperties").filter(|a| a.is_object())),
                Seg::Index(_) => n.get("items").filter(|i| i.is_object()),
            })
            .flat_map(choices)
            .collect();
    }
    nodes.iter().find_map(|n| {
        let max = n.get("maxItems")?.as_u64()?;
        (n.get("minItems")?.as_u64()? == max).then_some(max as usize)
    })
}
