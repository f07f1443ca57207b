//! The derivation's budget of terms (issue 32): a derivation that blows up stops at once with
//! an error naming what grew; one that fits gets the same result under any budget.

use std::time::{Duration, Instant};
use torseur::derivation::{NotDerivable, derive, derive_values};
use torseur::expr::{ExprError, Registry, budget};
use torseur::spec::wire::CoordinateKind;

#[path = "../shared/power_spec.rs"]
mod power_spec;
use power_spec::power;

/// Sets the process's budget for one test and restores it when the test ends, passed or not.
struct Budget(usize);

impl Budget {
    fn set(limit: usize) -> Budget {
        let previous = Budget(budget::max_terms());
        budget::set_max_terms(limit);
        previous
    }
}

impl Drop for Budget {
    fn drop(&mut self) {
        budget::set_max_terms(self.0);
    }
}

fn load(path: &str) -> torseur::mechanism::Mechanism {
    torseur::spec::load(format!("{}/{path}", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

/// The budget error's fields, or a failure naming what came instead.
fn budget_error(e: &torseur::derivation::DeriveError) -> (&str, &str, u128, usize) {
    match &e.reason {
        NotDerivable::Budget(ExprError::Budget {
            what,
            detail,
            terms,
            limit,
        }) => (what, detail, *terms, *limit),
        other => panic!("not the budget: {other:?}"),
    }
}

#[test]
fn a_position_to_the_32nd_power_stops_within_seconds_under_the_default_budget() {
    let _b = Budget::set(budget::DEFAULT_MAX_TERMS);
    let held = budget::held_terms();
    for (n, course) in [(32, false), (16, false), (16, true)] {
        let m = torseur::spec::from_str(&power(n)).unwrap();
        let start = Instant::now();
        let e = if course {
            derive(&m, &m.quantities()[0]).unwrap_err()
        } else {
            derive_values(&m, m.quantities()).unwrap_err()
        };
        assert!(
            start.elapsed() < Duration::from_secs(10),
            "{:?}",
            start.elapsed()
        );
        let (what, _, terms, limit) = budget_error(&e);
        assert_eq!(what, "the derivation of delta(O0,4/0).z0");
        assert_eq!(limit, 5_000_000);
        assert!(terms > 5_000_000, "{terms}");
        let msg = e.to_string();
        assert!(
            msg.starts_with("the derivation of delta(O0,4/0).z0 grew past 5,000,000 terms ("),
            "{msg}"
        );
        assert!(
            msg.ends_with("--max-terms raises this budget if memory allows"),
            "{msg}"
        );
        // Every expression of the refused derivation was dropped, and gave its terms back.
        drop(m);
        assert_eq!(budget::held_terms(), held);
    }
    // The commands' routes return it as their own error.
    let m = torseur::spec::from_str(&power(16)).unwrap();
    let e = torseur::check::check(&m, 2, 1).unwrap_err();
    assert!(e.to_string().contains("grew past 5,000,000 terms"), "{e}");
    let e = torseur::verify::verify(&m, "delta(O0,4/0).z0", "0", None).unwrap_err();
    assert!(e.to_string().contains("grew past 5,000,000 terms"), "{e}");
}

#[test]
fn a_derivation_that_fits_is_the_same_under_any_budget() {
    let m = load("derivations/regulateur_centrifuge.json");
    let qs = m.quantities();
    let values = |limit| {
        let _b = Budget::set(limit);
        let fast = derive_values(&m, qs).unwrap();
        let course: Vec<_> = qs.iter().map(|q| derive(&m, q).unwrap()).collect();
        (fast, course)
    };
    let (fast, course) = values(budget::DEFAULT_MAX_TERMS);
    let (fast_unbounded, course_unbounded) = values(usize::MAX);
    for k in 0..qs.len() {
        assert_eq!(
            fast[k].value.exprs(),
            fast_unbounded[k].value.exprs(),
            "{}",
            qs[k]
        );
        assert_eq!(
            course[k].value.exprs(),
            course_unbounded[k].value.exprs(),
            "{}",
            qs[k]
        );
    }
}

#[test]
fn a_small_budget_refuses_the_regulator_naming_the_quantity() {
    let m = load("derivations/regulateur_centrifuge.json");
    let q = torseur::quantity::Quantity::parse("delta(O1,E/0).z0").unwrap();
    let _b = Budget::set(40);
    let e = derive(&m, &q).unwrap_err();
    let (what, _, _, limit) = budget_error(&e);
    assert_eq!((what, limit), ("the derivation of delta(O1,E/0).z0", 40));
    assert!(
        e.to_string()
            .starts_with("the derivation of delta(O1,E/0).z0 grew past 40 terms (")
    );
}

#[test]
fn the_terms_held_at_once_are_bounded() {
    // Chain 6 derives 14,026 terms (sympy's count), held with its intermediate results:
    // a budget of 10,000 stops it on what its expressions hold.
    let m = load("derivations/chain/chain_6.json");
    let _b = Budget::set(10_000);
    let e = derive_values(&m, m.quantities()).unwrap_err();
    let (_, detail, terms, _) = budget_error(&e);
    assert!(detail.starts_with("its expressions held "), "{detail}");
    assert!(terms > 10_000);
    drop(_b);
    let total: usize = derive_values(&m, m.quantities())
        .unwrap()
        .iter()
        .map(|d| d.value.nterms())
        .sum();
    assert_eq!(total, 14_026);
}

#[test]
fn terms_are_counted_when_built_and_given_back_when_dropped() {
    let reg = Registry::new(
        &["a".into(), "b".into(), "c".into()],
        &[("q".into(), CoordinateKind::Angle)],
    )
    .unwrap();
    let base = budget::held_terms();
    let s = reg.parse("a + b + c").unwrap();
    assert_eq!(budget::held_terms(), base + 3);
    let t = s.clone();
    assert_eq!(budget::held_terms(), base + 6);
    // (a + b + c)² has 6 terms; sin²q → 1 − cos²q turns sin²q into two.
    let square = &s * &t;
    assert_eq!(budget::held_terms(), base + 12);
    let sin2 = reg.parse("sin(q)^2").unwrap();
    assert_eq!(sin2.nterms(), 2);
    assert_eq!(budget::held_terms(), base + 14);
    drop((s, t, square, sin2));
    assert_eq!(budget::held_terms(), base);
}

#[test]
fn a_product_is_weighed_before_it_is_formed() {
    // (x1 + … + x100)(y1 + … + y100): 100 by 100 terms form 10,000 distinct monomials.
    let xs: Vec<String> = (1..=100).map(|i| format!("x{i}")).collect();
    let ys: Vec<String> = (1..=100).map(|i| format!("y{i}")).collect();
    let names: Vec<String> = xs.iter().chain(&ys).cloned().collect();
    let reg = Registry::new(&names, &[]).unwrap();
    let x = reg.parse(&xs.join(" + ")).unwrap();
    let y = reg.parse(&ys.join(" + ")).unwrap();
    let _b = Budget::set(9_999);
    let e = budget::bounded(|| &x * &y).unwrap_err();
    assert_eq!(
        e,
        ExprError::Budget {
            what: "an expression".into(),
            detail: "a product of 100 by 100 terms, would form 10,000 terms before like terms \
                     combine"
                .into(),
            terms: 10_000,
            limit: 9_999,
        }
    );
    assert_eq!(
        e.to_string(),
        "an expression grew past 9,999 terms (a product of 100 by 100 terms, would form 10,000 \
         terms before like terms combine); --max-terms raises this budget if memory allows"
    );
    // Outside `bounded` nothing is refused; within a budget that fits, the same product.
    assert_eq!((&x * &y).nterms(), 10_000);
    drop(_b);
    let _b = Budget::set(10_500);
    assert_eq!(budget::bounded(|| (&x * &y).nterms()), Ok(10_000));
}
