//! The derivation's budget of terms, so that a derivation that blows up (a long chain of
//! solids, a position raised to a high power) stops within seconds with an error naming what
//! grew, instead of running for minutes until memory runs out.
//!
//! Memory and time go to the terms of the canonical forms (each a rational coefficient and a
//! byte per variable), so the budget [`max_terms`] bounds two counts:
//! - the terms a thread's expressions hold at once: every expression counts its terms when it
//!   is built (by one of the two constructors of this module's parent, a clone included) and
//!   gives them back when it is dropped. That count, not the size of one expression, is what
//!   runs out: a 12-link chain fills 10 GB with expressions of under a million terms each;
//! - the terms a product may form before like terms combine, weighed *before* it is
//!   multiplied: a terms by b terms form a·b (summed over a sum of products). This is the
//!   check that fires first on a blow-up, and it refuses without doing the work.
//!
//! The budget applies inside [`bounded`] only (the library's derivations run there: see
//! [`crate::derivation::derive`]): arithmetic outside it is never refused. It refuses and never
//! changes a result: a run either gets the same canonical forms as without a budget or the
//! error. The limit is one setting of the process ([`set_max_terms`], the CLI's
//! `--max-terms`); the count is per thread (expressions never leave their thread).
//!
//! ```
//! use torseur::expr::{ExprError, Registry, budget};
//! let reg = Registry::new(&["a".into(), "b".into()], &[]).unwrap();
//! let s = reg.parse("a + b").unwrap();
//! let previous = budget::max_terms();
//! budget::set_max_terms(1000);
//! // (a + b)¹² has 13 terms: within the budget.
//! assert_eq!(budget::bounded(|| s.pow(12).nterms()), Ok(13));
//! // Keeping every power (a + b)ᵏ, k = 1..80, holds Σ (k + 1) = 3,320 terms: refused.
//! let e = budget::bounded(|| (1..=80).map(|k| s.pow(k)).collect::<Vec<_>>()).unwrap_err();
//! assert!(matches!(e, ExprError::Budget { limit: 1000, .. }), "{e}");
//! // Outside `bounded`, nothing is refused.
//! assert_eq!((1..=80).map(|k| s.pow(k).nterms()).sum::<usize>(), 3320);
//! budget::set_max_terms(previous);
//! ```

use super::{ExprError, Poly};
use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Default [`max_terms`]: twice the largest count of the heaviest benchmark `torseur derive`
/// must finish, chain 10 (its products form up to 2.43 million terms, its expressions hold
/// up to 1.83 million at once), and far past every spec of `derivations/` (under 600 and 100).
/// Chains of 11 to 14 solids stop after about 12 s, at their first product past it.
pub const DEFAULT_MAX_TERMS: usize = 5_000_000;

static MAX_TERMS: AtomicUsize = AtomicUsize::new(DEFAULT_MAX_TERMS);

thread_local! {
    /// How many [`bounded`] calls this thread is inside.
    static DEPTH: Cell<usize> = const { Cell::new(0) };
    /// The terms this thread's expressions hold.
    static HELD: Cell<usize> = const { Cell::new(0) };
    /// The figures of [`peaks`].
    static PEAKS: Cell<Peaks> = const { Cell::new(Peaks { held: 0, expression: 0, product: 0 }) };
}

/// Sets the budget for the whole process: inside [`bounded`], the most terms a thread's
/// expressions may hold at once and a product may form (`usize::MAX` lifts it). It only
/// decides which derivations are refused: a derivation that fits gives the same result under
/// any budget.
pub fn set_max_terms(limit: usize) {
    MAX_TERMS.store(limit.max(1), Ordering::Relaxed);
}

/// The budget: inside [`bounded`], the most terms a thread's expressions may hold at once and
/// a product may form ([`DEFAULT_MAX_TERMS`] unless [`set_max_terms`] changed it).
pub fn max_terms() -> usize {
    MAX_TERMS.load(Ordering::Relaxed)
}

/// The terms this thread's expressions hold now.
pub fn held_terms() -> usize {
    HELD.with(Cell::get)
}

/// The largest figures this thread has reached since it started or since [`reset_peaks`],
/// inside [`bounded`] or not: what to compare with [`max_terms`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Peaks {
    /// The most terms held at once (the figure [`max_terms`] bounds).
    pub held: usize,
    /// The most terms of one expression.
    pub expression: usize,
    /// The most terms a product formed before like terms combined (Σ of the products of its
    /// factors' numbers of terms): the other figure [`max_terms`] bounds.
    pub product: u128,
}

/// The largest figures this thread has reached (see [`Peaks`]).
pub fn peaks() -> Peaks {
    PEAKS.with(Cell::get)
}

/// Starts [`peaks`] over, from the terms held now.
pub fn reset_peaks() {
    let held = held_terms();
    PEAKS.with(|p| {
        p.set(Peaks {
            held,
            ..Peaks::default()
        })
    });
}

/// What outgrew the budget: carried by the unwinding that stops the work, turned into
/// [`ExprError::Budget`] by [`bounded`].
struct Exceeded {
    detail: String,
    terms: u128,
    limit: usize,
}

/// Leaves a [`bounded`] call however it ends.
struct Depth;

impl Depth {
    fn enter() -> Depth {
        DEPTH.with(|d| d.set(d.get() + 1));
        Depth
    }
}

impl Drop for Depth {
    fn drop(&mut self) {
        DEPTH.with(|d| d.set(d.get() - 1));
    }
}

/// Runs `f` under the budget: as soon as this thread's expressions would hold more than
/// [`max_terms`] terms, or a product would form more than that many, `f` stops, its expressions are dropped, and the result is [`ExprError::Budget`], naming what
/// grew; otherwise it is `f`'s value. Calls nest: the innermost one gets the error. The stop
/// is an unwinding that no panic hook sees; a panic of `f` goes on as a panic.
pub fn bounded<T>(f: impl FnOnce() -> T) -> Result<T, ExprError> {
    let depth = Depth::enter();
    let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
    drop(depth);
    match r {
        Ok(v) => Ok(v),
        Err(payload) => match payload.downcast::<Exceeded>() {
            Ok(e) => Err(ExprError::Budget {
                what: "an expression".to_string(),
                detail: e.detail,
                terms: e.terms,
                limit: e.limit,
            }),
            Err(other) => std::panic::resume_unwind(other),
        },
    }
}

/// Stops the work of the enclosing [`bounded`] call.
fn exceed(detail: String, terms: u128, limit: usize) -> ! {
    // `resume_unwind` runs no panic hook: nothing is printed, `bounded` turns it into an error.
    std::panic::resume_unwind(Box::new(Exceeded {
        detail,
        terms,
        limit,
    }))
}

/// Whether a budget applies here, and its limit.
fn limit() -> Option<usize> {
    (DEPTH.with(Cell::get) > 0).then(max_terms)
}

/// Counts the terms of an expression being built.
#[inline]
pub(super) fn built(p: &Poly) {
    let n = p.nterms();
    let held = HELD.with(|h| {
        let held = h.get() + n;
        h.set(held);
        held
    });
    PEAKS.with(|peaks| {
        let mut k = peaks.get();
        if held > k.held || n > k.expression {
            k.held = k.held.max(held);
            k.expression = k.expression.max(n);
            peaks.set(k);
        }
    });
    if let Some(limit) = limit()
        && held > limit
    {
        // The expression was not built: its terms are not held.
        HELD.with(|h| h.set(h.get() - n));
        exceed(
            format!(
                "its expressions held {} terms at once, the last one built {}",
                grouped(held),
                grouped(n)
            ),
            held as u128,
            limit,
        );
    }
}

/// Gives back the terms of an expression dropped.
#[inline]
pub(super) fn freed(n: usize) {
    HELD.with(|h| h.set(h.get().saturating_sub(n)));
}

/// Weighs a product of factors of `a` and `b` terms (summed over `pairs`, a sum of products)
/// before it is multiplied: refused when it would form more terms than the budget.
#[inline]
pub(super) fn product(pairs: impl IntoIterator<Item = (usize, usize)>) {
    let (mut bound, mut largest, mut count) = (0u128, (0, 0), 0usize);
    for (a, b) in pairs {
        count += 1;
        let ab = a as u128 * b as u128;
        bound += ab;
        if ab > largest.0 as u128 * largest.1 as u128 {
            largest = (a, b);
        }
    }
    PEAKS.with(|peaks| {
        let mut k = peaks.get();
        if bound > k.product {
            k.product = bound;
            peaks.set(k);
        }
    });
    if let Some(limit) = limit()
        && bound > limit as u128
    {
        let what = if count == 1 {
            "a product".to_string()
        } else {
            format!("a sum of {count} products, the largest")
        };
        exceed(
            format!(
                "{what} of {} by {} terms, would form {} terms before like terms combine",
                grouped(largest.0),
                grouped(largest.1),
                grouped(bound)
            ),
            bound,
            limit,
        );
    }
}

/// `1234567` as `1,234,567`.
pub(crate) fn grouped(n: impl std::fmt::Display) -> String {
    let digits = n.to_string();
    let mut out = String::with_capacity(digits.len() + digits.len() / 3);
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}
