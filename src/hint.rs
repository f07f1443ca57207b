//! What a refusal suggests when a name is not declared: the declared name the user most likely
//! meant (`thta` → `theta`, `o2` → `O2`), or, when nothing is close and few names exist, the
//! names that are. A leaf: every layer that refuses a name calls it with the names it knows.
//!
//! The distance is the optimal string alignment distance of [`strsim`] (an insertion, a
//! deletion, a substitution or a swap of two neighbours each count one), on names compared
//! without case and with the letter O read as the digit 0; a name is suggested when it is at
//! most one edit away (two for names of five characters or more, none for a one-letter name:
//! `Q` is no more `G` than `O`), and no other declared name is as close.

/// How many declared names a refusal lists when none is close.
const LISTED: usize = 6;

/// The declared name closest to `typed`, when exactly one is close enough (see the module).
pub fn closest<'a>(typed: &str, declared: &[&'a str]) -> Option<&'a str> {
    // Compared without case, and the letter O as the digit 0 (`1/O` for the ground `0`).
    let fold = |s: &str| s.to_lowercase().replace('o', "0");
    let t = fold(typed);
    let limit = match t.chars().count() {
        0 | 1 => 0,
        2..=4 => 1,
        _ => 2,
    };
    let mut best: Option<(usize, &str)> = None;
    let mut tie = false;
    for &d in declared {
        if d == typed {
            continue;
        }
        let dist = strsim::osa_distance(&t, &fold(d));
        if dist > limit {
            continue;
        }
        match best {
            Some((b, _)) if dist > b => {}
            Some((b, prev)) if dist == b => tie |= prev != d,
            _ => {
                best = Some((dist, d));
                tie = false;
            }
        }
    }
    match best {
        Some((_, d)) if !tie => Some(d),
        _ => None,
    }
}

/// ` (did you mean `x`?)` after a refusal of `typed`, or ` (declared: `a`, `b`)` when no
/// name is close and at most six are declared; empty otherwise.
pub fn suggestion(typed: &str, declared: &[&str]) -> String {
    if let Some(d) = closest(typed, declared) {
        return format!(" (did you mean `{d}`?)");
    }
    if declared.is_empty() || declared.len() > LISTED {
        return String::new();
    }
    let names: Vec<String> = declared.iter().map(|d| format!("`{d}`")).collect();
    format!(" (declared: {})", names.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_suggestion_names_the_close_name_or_lists_a_few() {
        let declared = ["theta1", "theta2", "psi"];
        assert_eq!(suggestion("thta1", &declared), " (did you mean `theta1`?)");
        assert_eq!(suggestion("Psi", &declared), " (did you mean `psi`?)");
        // Two names are as close: no guess, and more than a few names: no list.
        assert_eq!(
            suggestion("theta", &declared),
            " (declared: `theta1`, `theta2`, `psi`)"
        );
        assert_eq!(suggestion("m", &["A", "B", "C", "D", "E", "F", "G"]), "");
    }

    #[test]
    fn a_close_name_is_suggested_and_a_far_one_is_not() {
        let d = ["O0", "O2", "G2", "theta1", "omega"];
        assert_eq!(closest("o2", &d), Some("O2"));
        assert_eq!(closest("O", &["0", "1"]), Some("0"));
        assert_eq!(closest("thteta1", &d), Some("theta1"));
        assert_eq!(closest("omgea", &d), Some("omega"));
        assert_eq!(closest("x", &d), None);
        assert_eq!(
            closest("O2", &d),
            None,
            "the name itself is not a suggestion"
        );
        // O1 is one edit from O0 and from O2: no guess.
        assert_eq!(closest("O1", &d), None);
        assert_eq!(suggestion("Q", &["O0", "G"]), " (declared: `O0`, `G`)");
        assert_eq!(suggestion("Q", &[]), "");
    }
}
