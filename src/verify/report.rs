//! A verdict as `verify` prints it: equivalent, and by which check (the factor of an equation
//! of motion, the combination along the motions, the loop's relation), or not, with the
//! difference and, on a closed chain, the configuration where it fails.

use super::{Check, Verdict};
use std::fmt;

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let under = self
            .hypothesis
            .as_ref()
            .map(|h| format!(" under {h}"))
            .unwrap_or_default();
        let subject = match &self.equation {
            Some(eq) if self.quantity != *eq => format!("{}: `{eq}`{under}", self.quantity),
            Some(eq) => format!("`{eq}`{under}"),
            None => format!("{}{under}", self.quantity),
        };
        if self.is_equivalent() {
            return match &self.check {
                Check::Value => write!(f, "{subject}: equivalent"),
                Check::Relation => write!(
                    f,
                    "{subject}: equivalent (relation: lhs − rhs = 0{})",
                    self.replaced()
                ),
                Check::EquationOfMotion { coordinate } => {
                    self.write_equivalent_eom(f, &subject, &under, coordinate)
                }
                Check::Closure { relations } => {
                    let sides = match self.equation {
                        Some(_) => "lhs − rhs",
                        None => "given − derived",
                    };
                    let each: Vec<String> = relations
                        .iter()
                        .map(|(r, k)| match k.is_one() {
                            true => r.clone(),
                            false => format!("{k} × ({r})"),
                        })
                        .collect();
                    write!(
                        f,
                        "{subject}: equivalent modulo the loop closure (not identically): \
                         {sides} = {}{}",
                        each.join("; "),
                        self.replaced()
                    )
                }
                Check::AlongMotions { combination } => {
                    let sides = match self.equation {
                        Some(_) => "lhs − rhs",
                        None => "given − derived",
                    };
                    let sum: Vec<String> = combination
                        .iter()
                        .map(|(q, c)| format!("{c} × eom({q})"))
                        .collect();
                    write!(
                        f,
                        "{subject}: equivalent along the motions (not identically): {sides} = \
                         {}{}",
                        sum.join(" + "),
                        self.replaced()
                    )
                }
            };
        }
        self.write_not_equivalent(f, &subject)?;
        for (k, d) in self.difference.iter().enumerate() {
            if !d.is_zero() {
                writeln!(f, "  {}: {}", self.difference_label(k), d.presentation())?;
                if let Some(den) = self.denominators.get(k).filter(|x| !x.is_one()) {
                    writeln!(f, "    (multiplied by the denominator typed, {den})")?;
                }
            }
        }
        if let Some(at) = &self.counterexample {
            writeln!(f, "  not a consequence of the loop closure: {at}")?;
        }
        Ok(())
    }
}

impl Verdict {
    /// An equivalent equation of motion: up to which factor, and where that holds.
    fn write_equivalent_eom(
        &self,
        f: &mut fmt::Formatter<'_>,
        subject: &str,
        under: &str,
        coordinate: &str,
    ) -> fmt::Result {
        // Say which equation it is, unless that was the quantity asked.
        let asked = self.asked_equation_of_motion();
        let eom = asked.clone().unwrap_or(format!("eom({coordinate})"));
        let is = if asked.is_none() {
            format!(" (it is the equation of motion {eom}{})", self.replaced())
        } else {
            String::new()
        };
        match &self.factor {
            Some(k) if !k.is_one() => {
                write!(f, "{subject}: equivalent, up to the factor {k}{is}")?;
                write!(f, "\n  {eom} = {k} × (lhs − rhs)")?;
                // The same equation wherever the factor is defined and nonzero.
                let conditions: Vec<String> = [&k.numerator, &k.denominator]
                    .into_iter()
                    .filter(|e| e.as_rational().is_none())
                    .map(|e| format!("{e} ≠ 0"))
                    .collect();
                if !conditions.is_empty() {
                    write!(f, ", the same equation where {}", conditions.join(" and "))?;
                }
            }
            _ => write!(f, "{subject}: equivalent{is}")?,
        }
        // Identically 0: the hypothesis' motion satisfies it, and so does every
        // equation that holds under the hypothesis; say so.
        if self.derived.exprs().iter().all(|e| e.is_zero()) {
            write!(
                f,
                "\n  note: {eom} is identically 0{under}: any equation true{under} \
                 is equivalent to it"
            )?;
        }
        Ok(())
    }

    /// The first line of a verdict that is not equivalent: what differs, and how.
    fn write_not_equivalent(&self, f: &mut fmt::Formatter<'_>, subject: &str) -> fmt::Result {
        match &self.check {
            Check::Value => writeln!(f, "{subject}: NOT equivalent; given − derived =")?,
            Check::EquationOfMotion { coordinate } => {
                let eom = self
                    .asked_equation_of_motion()
                    .unwrap_or(format!("eom({coordinate})"));
                write!(
                    f,
                    "{subject}: NOT equivalent: {eom} is not (lhs − rhs) times a nonzero \
                     factor made of parameters; "
                )?;
                match &self.factor {
                    Some(k) if k.is_one() => writeln!(f, "(lhs − rhs) − {eom} =")?,
                    Some(k) if k.denominator.is_one() => writeln!(
                        f,
                        "with the factor {k} that matches most terms, {k} × (lhs − rhs) − {eom} ="
                    )?,
                    Some(k) => writeln!(
                        f,
                        "with the factor {k} that matches most terms, {} × (lhs − rhs) − {} × \
                         {eom} =",
                        k.numerator, k.denominator
                    )?,
                    None => writeln!(f, "(lhs − rhs) − {eom} =")?,
                }
            }
            Check::Relation => writeln!(
                f,
                "{subject}: NOT equivalent: lhs − rhs{} is neither zero nor an equation of \
                 motion times a nonzero factor made of parameters; lhs − rhs =",
                self.replaced()
            )?,
            Check::AlongMotions { .. } | Check::Closure { .. } => {
                writeln!(f, "{subject}: NOT equivalent")?
            }
        }
        Ok(())
    }
}
