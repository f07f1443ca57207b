//! Imposed rate laws q̇(t), piece by piece, with their exact time derivative.
//!
//! Each piece is an expression of `t` and the parameters in the spec's syntax (`pi` allowed),
//! read by the float backend's parser and evaluated over first-order dual numbers, so q̈(t) is
//! exact, not a finite difference.

use crate::numeric::expr::{self, Env, Name, Node};
use crate::wire::RatePiece;
use num_dual::{Dual64, DualNum};

/// A piecewise rate law.
pub struct TimeLaw {
    pieces: Vec<(Option<f64>, Node)>,
    params: Vec<f64>,
}

/// Why a rate law is refused, and where in its list of pieces (`[1].until`; empty for the
/// list itself).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{}{message}", if .at.is_empty() { String::new() } else { format!("{}: ", .at) })]
pub struct LawError {
    /// The place in the list of pieces: `[k].value` or `[k].until`, or empty.
    pub at: String,
    /// What is wrong.
    pub message: String,
}

impl LawError {
    /// The JSON path of the place, below the path `base` of the list of pieces.
    pub fn path_under(&self, base: &str) -> String {
        format!("{base}{}", self.at)
    }
}

impl TimeLaw {
    /// Parses the pieces; `names` and `values` are the parameters.
    pub fn new(
        pieces: &[RatePiece],
        names: &[String],
        values: &[f64],
    ) -> Result<TimeLaw, LawError> {
        let refuse = |at: String, message: String| LawError { at, message };
        if pieces.is_empty() {
            return Err(refuse(
                String::new(),
                "a rate law needs at least one piece".to_string(),
            ));
        }
        let resolve = |n: &str| -> Result<Name, String> {
            if n == "t" {
                return Ok(Name::Coord(0));
            }
            names
                .iter()
                .position(|p| p == n)
                .map(Name::Param)
                .ok_or_else(|| format!("unknown name `{n}` (a law uses t and the parameters)"))
        };
        let mut out = Vec::new();
        let mut last = f64::NEG_INFINITY;
        for (k, p) in pieces.iter().enumerate() {
            let node = expr::parse(&p.value, &resolve, false, &[])
                .map_err(|e| refuse(format!("[{k}].value"), e))?;
            match (p.until, k + 1 == pieces.len()) {
                (Some(u), _) if !(u.is_finite() && u > last) => {
                    return Err(refuse(
                        format!("[{k}].until"),
                        "the pieces end at increasing times".to_string(),
                    ));
                }
                (None, false) => {
                    return Err(refuse(
                        format!("[{k}].until"),
                        "only the last piece has no end".to_string(),
                    ));
                }
                (Some(u), _) => last = u,
                (None, true) => {}
            }
            out.push((p.until, node));
        }
        Ok(TimeLaw {
            pieces: out,
            params: values.to_vec(),
        })
    }

    /// Each piece that starts before `end` evaluated where it starts (0 for the first, the
    /// previous piece's end for the others): a law that divides by zero there (`1/t` at
    /// t = 0), or whose value is not finite, is refused before any integration.
    pub fn validate_starts(&self, end: f64) -> Result<(), LawError> {
        let mut start = 0.0_f64;
        for (k, (until, _)) in self.pieces.iter().enumerate() {
            if start < end && until.is_none_or(|u| u > start) {
                let at = |message: String| LawError {
                    at: format!("[{k}].value"),
                    message: format!(
                        "the rate at t = {start} s, where this piece starts: {message}"
                    ),
                };
                let (v, a) = self
                    .piece_rate(k, start)
                    .map_err(|e| at(e.trim_end_matches(" at these values").to_string()))?;
                if !(v.is_finite() && a.is_finite()) {
                    return Err(at("the rate or its derivative is not finite".to_string()));
                }
            }
            if let Some(u) = until {
                start = start.max(*u);
            }
        }
        Ok(())
    }

    /// The instants where one piece gives way to the next.
    pub fn breakpoints(&self) -> Vec<f64> {
        self.pieces.iter().filter_map(|(u, _)| *u).collect()
    }

    /// q̇(t) and q̈(t).
    pub fn rate(&self, t: f64) -> Result<(f64, f64), String> {
        let k = self
            .pieces
            .iter()
            .position(|(u, _)| u.is_none_or(|u| t < u))
            .unwrap_or(self.pieces.len().saturating_sub(1));
        self.piece_rate(k, t)
    }

    /// q̇(t) and q̈(t) by the piece `k`.
    fn piece_rate(&self, k: usize, t: f64) -> Result<(f64, f64), String> {
        let (_, node) = self.pieces.get(k).ok_or("empty law")?;
        let tt = [Dual64::from(t).derivative()];
        let env = Env {
            params: &self.params,
            coords: &tt,
            rates: &[],
            frames: &[],
            time: Dual64::from(t).derivative(),
        };
        let v = expr::eval_scalar(node, &env)?;
        Ok((v.re(), v.eps))
    }
}
