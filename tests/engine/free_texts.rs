//! Free texts (titles, labels, statements…): the escaper and the formula whitelist never
//! panic, what they print is safe by an independent reader ([`super::latex_safe`]), the
//! validation refuses with the JSON path what TeX could not typeset (control characters,
//! nesting, length), and an answer key made of hostile but accepted texts compiles with
//! pdflatex.

use super::latex_safe::{MATH_CHARS, MATH_MACROS, MATH_OTHERS, MATH_SYMBOLS, check};
use proptest::prelude::*;
use std::path::Path;
use std::process::Command;
use torseur::latex::{escape_text, rich_text, rich_text_or_escaped};

/// Every route from a free text to LaTeX is safe for `s`, and none panics.
fn all_safe(s: &str) {
    let e = escape_text(s);
    assert_eq!(check(&e), Ok(()), "escape_text({s:?}) = {e:?}");
    if let Ok(r) = rich_text(s) {
        assert_eq!(check(&r), Ok(()), "rich_text({s:?}) = {r:?}");
    }
    let r = rich_text_or_escaped(s);
    assert_eq!(check(&r), Ok(()), "rich_text_or_escaped({s:?}) = {r:?}");
}

/// What exerts an action prints safely for any `s`, in a torsor and under the arrow of a
/// resultant (as the key writes {T(s → 1)} and R(s → 1)).
fn source_safe(s: &str) {
    let src = torseur::latex::action_source(s);
    for f in [
        format!("$\\mathcal{{T}}_{{A}}({src} \\rightarrow 1)$"),
        format!("$\\overrightarrow{{R({src} \\rightarrow 1)}}$"),
    ] {
        assert_eq!(check(&f), Ok(()), "action_source({s:?}) in {f:?}");
    }
}

/// The input: an escaped dollar, then a combining dot.
#[test]
fn a_combining_dot_after_an_escape_does_not_panic() {
    let title = "\\$\u{307}";
    assert_eq!(escape_text(title), "\\textbackslash{}\\$");
    assert_eq!(rich_text(title).unwrap(), "\\$");
    all_safe(title);
}

#[test]
fn a_combining_dot_goes_only_over_a_letter() {
    for (text, latex) in [
        ("x\u{307}", "$\\dot{\\mathrm{x}}$"),
        ("θ\u{308}", "$\\ddot{\\theta}$"),
        ("a θ\u{307} b", "a $\\dot{\\theta}$ b"),
        ("1\u{307}", "$\\dot{\\mathrm{1}}$"),
        // Over an escape, a space, an accented letter, nothing, or a dot: dropped.
        ("%\u{307}", "\\%"),
        ("#\u{308}", "\\#"),
        ("{\u{307}}", "\\{\\}"),
        ("\\\u{307}", "\\textbackslash{}"),
        ("_\u{307}", "\\_"),
        ("^\u{307}", "\\textasciicircum{}"),
        (" \u{307}", " "),
        ("é\u{307}", "é"),
        ("\u{307}", ""),
        ("θ\u{307}\u{307}", "$\\dot{\\theta}$"),
        ("∧\u{307}", "$\\wedge$"),
    ] {
        assert_eq!(escape_text(text), latex, "{text:?}");
    }
    // In a free text with formulas, after a formula: nothing to put it over.
    assert_eq!(rich_text("$x$\u{307}").unwrap(), "$x$");
}

#[test]
fn control_characters_never_reach_the_latex() {
    assert_eq!(escape_text("a\u{85}b\u{7f}c\u{9f}d\u{1}e"), "abcde");
    assert_eq!(escape_text("a\nb\tc"), "a b c");
    // The validation refuses them, at their position (in characters, from 1).
    let e = rich_text("Ques\u{85}tion").unwrap_err();
    assert_eq!(
        e.to_string(),
        "a control character (U+0085) is not allowed (character 5)"
    );
    let e = rich_text("$x$ \u{202e}").unwrap_err();
    assert_eq!(
        e.to_string(),
        "an invisible formatting character (U+202E) is not allowed (character 5)"
    );
    assert!(rich_text("ligne\nsuivante\ttab").is_ok());
}

#[test]
fn formulas_that_tex_would_not_take_are_refused() {
    for (bad, what) in [
        ("$x^'$", "a prime as argument"),
        ("$x_'$", "a prime as argument"),
        ("$x^\\sin$", "`\\sin` as argument"),
        ("$x_\\quad$", "`\\quad` as argument"),
        ("$x^\\ldots$", "`\\ldots` as argument"),
        ("$x'_1^2$", "double superscript"),
        ("$x' _1 ^2$", "double superscript"),
        (
            "$\\overrightarrow{\\overrightarrow{\\overrightarrow{\\overrightarrow{x}}}}$",
            "at most 3 `\\overrightarrow`",
        ),
    ] {
        let e = rich_text(bad).expect_err(bad);
        assert!(e.message.contains(what), "{bad}: {e}");
    }
    // What TeX joins is written so that it does: a letter after a control word, a `^` after
    // primes.
    assert_eq!(rich_text("$θx$").unwrap(), "$\\theta x$");
    assert_eq!(rich_text("$a×b·c$").unwrap(), "$a\\times b\\cdot c$");
    assert_eq!(rich_text("$x' ^2$").unwrap(), "$x'^2$");
    assert_eq!(rich_text("$f' '$").unwrap(), "$f''$");
    assert_eq!(rich_text("$x'_1$").unwrap(), "$x'_1$");
    assert_eq!(rich_text("$x^{\\sin}$").unwrap(), "$x^{\\sin}$");
}

#[test]
fn formulas_nest_at_most_32_groups() {
    let nest = |n: usize| format!("${}x{}$", "{".repeat(n), "}".repeat(n));
    assert!(rich_text(&nest(32)).is_ok());
    let e = rich_text(&nest(33)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "a formula may nest at most 32 groups (braces and `\\left … \\right`) (character 34)"
    );
    let lefts = |n: usize| format!("${}x{}$", "\\left(".repeat(n), "\\right)".repeat(n));
    assert!(rich_text(&lefts(32)).is_ok());
    assert!(rich_text(&lefts(33)).is_err());
    // Braces and \left count together.
    assert!(
        rich_text(&format!(
            "${}{}$",
            "{\\left(".repeat(17),
            "\\right)}".repeat(17)
        ))
        .is_err()
    );
    // 100,000 braces: a refusal, not a stack overflow.
    assert!(rich_text(&nest(100_000)).is_err());
    let deep = format!("${}", "\\vec{".repeat(100_000));
    assert!(rich_text(&deep).is_err());
}

/// Every string of up to 5 characters over the characters that matter to the escaper and the
/// whitelist (escapes, braces, scripts, primes, dollars, a combining dot, a C1 control).
#[test]
fn every_short_string_is_safe() {
    let alphabet = [
        '\\', '$', '{', '}', '^', '_', '\'', ' ', 'x', 'θ', '\u{307}', '%', '(', '\u{85}',
    ];
    let mut s = String::new();
    let mut count = 0usize;
    fn walk(s: &mut String, left: usize, alphabet: &[char], count: &mut usize) {
        all_safe(s);
        *count += 1;
        if left == 0 {
            return;
        }
        for &c in alphabet {
            s.push(c);
            walk(s, left - 1, alphabet, count);
            s.pop();
        }
    }
    walk(&mut s, 5, &alphabet, &mut count);
    assert_eq!(count, (0..=5).map(|k| 14usize.pow(k)).sum::<usize>());
}

/// Pieces of free text: the characters and macros that matter, whole.
fn fragment() -> impl Strategy<Value = String> {
    prop::sample::select(vec![
        "\\",
        "$",
        "{",
        "}",
        "%",
        "#",
        "&",
        "~",
        "^",
        "_",
        "'",
        " ",
        "\n",
        "a",
        "x",
        "Z",
        "1",
        "θ",
        "ω",
        "Ω",
        "ς",
        "\u{307}",
        "\u{308}",
        "\u{85}",
        "\u{7f}",
        "\u{202e}",
        "é",
        "·",
        "×",
        "(",
        ")",
        "[",
        "]",
        "+",
        "=",
        "|",
        ".",
        "<",
        "€",
        "\\vec",
        "\\overrightarrow",
        "\\frac",
        "\\left",
        "\\right",
        "\\alpha",
        "\\sin",
        "\\quad",
        "\\ldots",
        "\\mathrm",
        "\\dot",
        "\\,",
        "\\{",
        "\\}",
        "\\$",
        "\\input",
        "\\def",
        "\\\\",
    ])
    .prop_map(String::from)
}

/// Formulas built from the whitelist, nested, for the accepted side.
fn formula() -> impl Strategy<Value = String> {
    let leaf = prop::sample::select(vec![
        "x", "A", "2", "\\alpha", "\\Omega", "\\sin", "\\quad", "\\ldots", "\\infty", "θ", "ω",
        "·", "×", "→", "+", "=", "(", ")", "|", "'", ",", "\\,", "\\{", "\\}", " ", "!", "<",
    ])
    .prop_map(String::from);
    leaf.prop_recursive(6, 48, 4, |inner| {
        let word = prop::sample::select(vec![
            "vec",
            "overrightarrow",
            "mathcal",
            "mathrm",
            "dot",
            "ddot",
        ]);
        let script = prop::sample::select(vec!["^", "_", "'", " ", "''"]);
        prop_oneof![
            prop::collection::vec(inner.clone(), 1..4).prop_map(|v| v.concat()),
            inner.clone().prop_map(|a| format!("{{{a}}}")),
            (word, inner.clone()).prop_map(|(w, a)| format!("\\{w}{{{a}}}")),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("\\frac{{{a}}}{{{b}}}")),
            (inner.clone(), script, inner.clone()).prop_map(|(a, s, b)| format!("{a}{s}{b}")),
            inner.clone().prop_map(|a| format!("\\left({a}\\right)")),
            inner.prop_map(|a| format!("\\left\\{{{a}\\right.")),
        ]
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    #[test]
    fn fragments_are_safe(v in prop::collection::vec(fragment(), 0..40)) {
        all_safe(&v.concat());
    }

    #[test]
    fn any_string_is_safe(s in any::<String>()) {
        all_safe(&s);
    }

    #[test]
    fn sources_print_safely(v in prop::collection::vec(fragment(), 0..12)) {
        source_safe(&v.concat());
    }

    #[test]
    fn any_source_prints_safely(s in any::<String>()) {
        source_safe(&s);
    }

    #[test]
    fn built_formulas_are_safe(a in "[a-zé %#&]{0,8}", f in formula(), b in "[a-z ]{0,8}") {
        all_safe(&format!("{a}${f}${b}"));
    }
}

/// A spec to take apart: `bloc_frottement_sec`, as JSON.
fn bloc() -> serde_json::Value {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("derivations/bloc_frottement_sec.json");
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

fn load(v: &serde_json::Value) -> Result<torseur::mechanism::Mechanism, String> {
    torseur::spec::from_str(&serde_json::to_string_pretty(v).unwrap()).map_err(|e| e.to_string())
}

#[test]
fn the_validation_names_the_text_and_the_limit() {
    let refused = |edit: &dyn Fn(&mut serde_json::Value)| {
        let mut v = bloc();
        edit(&mut v);
        load(&v).map(|_| ()).unwrap_err()
    };
    let e = refused(&|v| v["title"] = "Bloc\u{85}".into());
    assert!(
        e.contains("title")
            && e.contains("a control character (U+0085) is not allowed (character 5)"),
        "{e}"
    );
    let e = refused(&|v| v["links"][0]["label"] = "l".repeat(201).into());
    assert!(
        e.contains("links[0].label")
            && e.contains("201 characters: a title or a label may hold at most 200"),
        "{e}"
    );
    let e = refused(&|v| v["questions"][1]["statement"] = "a ".repeat(10_001).into());
    assert!(
        e.contains("questions[1].statement")
            && e.contains("20002 characters: a text may hold at most 20000"),
        "{e}"
    );
    let e = refused(&|v| {
        v["questions"][0]["answer"] = format!("${}x{}$", "{".repeat(40), "}".repeat(40)).into()
    });
    assert!(
        e.contains("questions[0].answer") && e.contains("at most 32 groups"),
        "{e}"
    );
    // At the limits, accepted.
    let mut v = bloc();
    v["questions"][0]["title"] = "q".repeat(200).into();
    v["description"] = "a".repeat(20_000).into();
    load(&v).unwrap();
}

/// The title may hold formulas, as validation says: they are printed as formulas, in the
/// title and where a sentence cites a question by its title.
#[test]
fn a_title_prints_its_formulas() {
    let mut v = bloc();
    v["title"] = "Bloc $S_2$ sur un plan, 5 \\$".into();
    v["questions"][0]["title"] = "Question 1 : $\\Omega$ et $S_2$".into();
    let m = load(&v).unwrap();
    let tex = torseur::latex::answer_key(&m, &torseur::simulate::question_runs(&m)).unwrap();
    assert!(
        tex.contains("{\\Large\\bfseries Corrigé -- Bloc $S_2$ sur un plan, 5 \\$\\par}"),
        "{}",
        &tex[..2000.min(tex.len())]
    );
    assert!(tex.contains("\\TQuestion{Question 1 : $\\Omega$ et $S_2$}"));
    assert!(!tex.contains("\\$S\\_2\\$"));
    assert_eq!(check_document_texts(&tex), Ok(()));
}

/// The key's own lines that hold a free text are safe too (no `\$S\_2\$` left): the lines
/// between `\begin{document}` and the first section.
fn check_document_texts(tex: &str) -> Result<(), String> {
    let start = tex.find("Corrigé -- ").ok_or("no title")? + "Corrigé -- ".len();
    let end = tex[start..].find("\\par}").ok_or("no end of title")? + start;
    check(&tex[start..end])
}

#[test]
fn the_text_at_fault_is_found_by_its_line() {
    let mut v = bloc();
    v["questions"][1]["statement"] = "Déterminer la puissance (100 % utile) de $S_2$.".into();
    let m = load(&v).unwrap();
    let tex = torseur::latex::answer_key(&m, &torseur::simulate::question_runs(&m)).unwrap();
    let line_of = |needle: &str| 1 + tex.lines().position(|l| l.contains(needle)).unwrap();
    let at = |line| torseur::latex::text_at_fault(&m, &tex, line);
    let statement = line_of("Déterminer la puissance (100 \\% utile)");
    assert_eq!(at(statement).as_deref(), Some("questions[1].statement"));
    // The line after (TeX may report an error there): the nearest text above.
    assert_eq!(at(statement + 1).as_deref(), Some("questions[1].statement"));
    assert_eq!(
        at(line_of("Un bloc $S_2$ de masse")).as_deref(),
        Some("description")
    );
    assert_eq!(
        at(line_of("\\item $x(t)$")).as_deref(),
        Some("coordinates[0].description")
    );
    assert_eq!(at(1), None);
    assert_eq!(at(0), None);
    assert_eq!(at(tex.lines().count() + 1), None);
}

/// Every macro of the whitelist, alone, as the argument of each macro that takes one, and
/// under scripts where TeX takes it.
fn every_macro() -> Vec<String> {
    // The reader's own lists: every word it knows, symbols and words without argument.
    let plain: Vec<&str> = MATH_SYMBOLS.iter().chain(MATH_OTHERS).copied().collect();
    let takers: Vec<&str> = MATH_MACROS
        .iter()
        .filter(|(_, n)| *n == 1)
        .map(|(w, _)| *w)
        .collect();
    let mut out = Vec::new();
    for w in plain {
        let mut f = format!("$\\{w} a\\{w}");
        for t in &takers {
            f.push_str(&format!(" \\{t}\\{w} \\{t}{{\\{w}}}"));
        }
        f.push_str(&format!(" \\frac\\{w}\\{w} x^{{\\{w}}}_{{\\{w}}}"));
        if !MATH_OTHERS.contains(&w) {
            f.push_str(&format!(" y^\\{w}_\\{w}"));
        }
        f.push('$');
        out.push(f);
    }
    let mut chars = String::from("$");
    for c in MATH_CHARS.chars().chain(['\'']) {
        chars.push_str(&format!(" , {c} \\vec{c} \\frac{c}{c} \\mathrm{c}"));
        if c != '\'' {
            chars.push_str(&format!(" z^{c}_{c}"));
        }
    }
    chars.push_str(
        " \\left( \\left[ \\left| \\left. \\left/ \\left\\{ x \\right\\} \\right/ \\right. \
         \\right| \\right] \\right) \\, \\; \\! \\{ \\} θ·ω×Ω ≤ ≥ ≠ ≈ → ∞ … ∧ x'^2_1 f'' g' ^3 \
         h' _1$",
    );
    out.push(chars);
    out
}

/// A piece of `n` characters of accepted text, built by repeating `unit` and padding.
fn filled(unit: &str, n: usize) -> String {
    let k = unit.chars().count();
    let mut s = unit.repeat(n / k);
    s.push_str(&"a".repeat(n - (n / k) * k));
    assert_eq!(s.chars().count(), n);
    s
}

/// An answer key whose every free text is hostile but accepted compiles: every whitelisted
/// macro, combining dots after escapes, Greek, the deepest nesting, the longest texts,
/// Latin-1 and other Unicode, TeX's special characters as text.
#[test]
fn an_answer_key_of_hostile_accepted_texts_compiles() {
    let latin1: String = (0xA0u32..=0xFF).filter_map(char::from_u32).collect();
    let specials = "\\$\u{307} 50 % # & ~ ^ _ { } \\ < > \\input{x} \\write18{ls} \\$ \\\\ `` ''";
    let dots = "θ\u{307} ω\u{308} x\u{307} 1\u{308} é\u{307} %\u{307} #\u{308} {\u{307} }\u{307} \
                \\$\u{307} \u{307}\u{308}";
    let unicode = "€ — – “ ” ’ « » ° ² µ ½ × ÷ ∧ · − ς Ω 中 😀 \u{2028} \u{FFFD}";
    let depth = format!(
        "${}x{}$ ${}{}y{}{}$ $\\overrightarrow{{\\overrightarrow{{\\overrightarrow{{AB}}}}}}$",
        "{".repeat(32),
        "}".repeat(32),
        "\\left(".repeat(16),
        "{".repeat(16),
        "}".repeat(16),
        "\\right)".repeat(16),
    );
    let macros = every_macro();
    // Short pieces, for every text; the whole list of macros, for a few.
    let mix = [
        specials,
        dots,
        unicode,
        latin1.as_str(),
        depth.as_str(),
        "$\\vec{\\Omega}(2/0) \\wedge \\overrightarrow{O_1G_2}$ θ·ω $x'^2_1$ $θx ·y ×z$",
    ]
    .join(" ");
    let all = format!("{mix} {}", macros.join(" "));
    assert!(all.chars().count() <= torseur::latex::MAX_PROSE_CHARS);
    // The longest texts: a title or a label of 200 characters, prose of 20,000 with one word
    // of 5,000 characters in it.
    let label = |s: &str| {
        assert!(s.chars().count() < 200, "{s}");
        filled(&format!("{s} "), torseur::latex::MAX_LABEL_CHARS)
    };
    let long_prose = format!(
        "{} {}",
        "9".repeat(5_000),
        filled(&format!("{mix} "), torseur::latex::MAX_PROSE_CHARS - 5_001)
    );
    let titles = [
        "Question 1 : $\\vec{\\Omega}(2/0) \\wedge \\overrightarrow{O_1G_2}$ 100 % #",
        "Question 2 : θ\u{307} $x'^2_1 \\frac{1}{2}$ \\$\u{307} & ~ ^ _",
    ];

    let mut v = bloc();
    v["title"] = label(specials).into();
    v["description"] = long_prose.clone().into();
    for p in v["parameters"].as_array_mut().unwrap() {
        p["description"] = mix.clone().into();
    }
    v["parameters"][0]["description"] = all.clone().into();
    v["coordinates"][0]["description"] = format!("[{dots}").into();
    v["aliases"] = serde_json::json!([{"name": "K", "value": "f*m*g", "description": unicode}]);
    v["hypotheses"] = serde_json::json!([{"name": "H1", "text": all}]);
    v["links"][0]["label"] = label(dots).into();
    v["actions"] = serde_json::json!([{
        "name": "pousse", "from": "0", "on": "2", "point": "G", "resultant": "K*x1",
        "label": label(&format!("[{unicode}")),
        "source": "é % # & ~ ^ _ {} \\ $x'^2_1$ θ\u{307} 😀 «»"
    }]);
    v["scenarios"][0]["label"] = label(&format!("*{specials}")).into();
    v["scenarios"][0]["description"] = mix.clone().into();
    for (k, q) in v["questions"]
        .as_array_mut()
        .unwrap()
        .iter_mut()
        .enumerate()
    {
        q["title"] = label(titles[k]).into();
        q["statement"] = if k == 0 { all.clone() } else { mix.clone() }.into();
        q["answer"] = format!("[{mix}").into();
        q["hypotheses"] = serde_json::json!(["H1"]);
    }
    v["questions"][0]["equations"] =
        serde_json::json!([{"lhs": "N", "quantity": "Y02", "reason": format!("*{mix}")}]);
    let m = load(&v).unwrap_or_else(|e| panic!("the hostile texts are accepted: {e}"));
    // Each text alone reads as safe.
    let pieces: [&str; 8] = [
        specials,
        dots,
        unicode,
        &latin1,
        &depth,
        &mix,
        &all,
        &long_prose,
    ];
    for t in pieces
        .iter()
        .copied()
        .chain(macros.iter().map(String::as_str))
    {
        assert_eq!(check(&rich_text(t).unwrap()), Ok(()), "{t}");
    }

    let key = torseur::latex::answer_key_document(
        &m,
        torseur::latex::VectorStyle::Sum,
        &torseur::simulate::question_runs(&m),
    )
    .unwrap();
    for needle in [
        "\\textbackslash{}input\\{x\\}",
        "\\textbackslash{}write18",
        "$\\dot{\\theta}$",
        "\\overrightarrow{\\overrightarrow",
        "\\mathcal{T}(\\textnormal{é \\% \\# \\& \\textasciitilde{}",
    ] {
        assert!(key.tex.contains(needle), "{needle}");
    }
    if Command::new("pdflatex").arg("--version").output().is_err() {
        eprintln!("pdflatex is not installed (scripts/setup installs it): the key is not compiled");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("key.tex"), &key.tex).unwrap();
    for (name, figure) in &key.figures {
        std::fs::write(dir.path().join(name), figure.to_png(1).unwrap()).unwrap();
    }
    let o = Command::new("pdflatex")
        .args([
            "-no-shell-escape",
            "-interaction=nonstopmode",
            "-halt-on-error",
            "key.tex",
        ])
        .current_dir(dir.path())
        .stdin(std::process::Stdio::null())
        .output()
        .unwrap();
    if !o.status.success() {
        let log = String::from_utf8_lossy(&o.stdout);
        let line = log.lines().find_map(|l| {
            l.strip_prefix("l.")?
                .split(' ')
                .next()?
                .parse::<usize>()
                .ok()
        });
        let at = line.and_then(|l| torseur::latex::text_at_fault(&m, &key.tex, l));
        let tail: Vec<&str> = log.lines().rev().take(30).collect();
        panic!(
            "pdflatex refused the key at line {line:?} (text {at:?}):\n{}",
            tail.into_iter().rev().collect::<Vec<_>>().join("\n")
        );
    }
    assert!(dir.path().join("key.pdf").exists());
}
