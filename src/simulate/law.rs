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

impl TimeLaw {
    /// Parses the pieces; `names` and `values` are the parameters.
    pub fn new(pieces: &[RatePiece], names: &[String], values: &[f64]) -> Result<TimeLaw, String> {
        if pieces.is_empty() {
            return Err("a rate law needs at least one piece".to_string());
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
            let node =
                expr::parse(&p.value, &resolve, false, &[]).map_err(|e| format!("[{k}]: {e}"))?;
            match (p.until, k + 1 == pieces.len()) {
                (Some(u), _) if !(u.is_finite() && u > last) => {
                    return Err(format!("[{k}].until: the pieces end at increasing times"));
                }
                (None, false) => {
                    return Err(format!("[{k}].until: only the last piece has no end"));
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

    /// The instants where one piece gives way to the next.
    pub fn breakpoints(&self) -> Vec<f64> {
        self.pieces.iter().filter_map(|(u, _)| *u).collect()
    }

    /// q̇(t) and q̈(t).
    pub fn rate(&self, t: f64) -> Result<(f64, f64), String> {
        let (_, node) = self
            .pieces
            .iter()
            .find(|(u, _)| u.is_none_or(|u| t < u))
            .or(self.pieces.last())
            .ok_or("empty law")?;
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
