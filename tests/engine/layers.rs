//! The layers of ARCHITECTURE.md, checked against the code: every `crate::` edge between the
//! top-level modules of `src/` is in the table and points up it, and every edge of the table
//! exists; the same for the files of the float backend (`src/numeric/`) and their `super::`
//! edges, against the second table.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The top-level module a source file belongs to (`src/latex/document.rs` → `latex`).
fn module_of(src: &Path, file: &Path) -> String {
    let rel = file.strip_prefix(src).unwrap();
    let first = rel
        .components()
        .next()
        .unwrap()
        .as_os_str()
        .to_str()
        .unwrap();
    first.trim_end_matches(".rs").to_string()
}

fn rust_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// Module → the modules its code names as `crate::name` (comment lines left out).
fn edges_in_code() -> BTreeMap<String, BTreeSet<String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for f in files {
        let m = module_of(&src, &f);
        if m == "lib" || m == "bin" {
            continue;
        }
        let uses = edges.entry(m.clone()).or_default();
        for line in std::fs::read_to_string(&f).unwrap().lines() {
            if line.trim_start().starts_with("//") {
                continue;
            }
            for (at, _) in line.match_indices("crate::") {
                let name: String = line[at + 7..]
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                if !name.is_empty() && name != m {
                    uses.insert(name);
                }
            }
        }
    }
    edges
}

/// Text with the comment lines left out.
fn code_of(f: &Path) -> String {
    std::fs::read_to_string(f)
        .unwrap()
        .lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The files of the float backend → the sibling modules they name as `super::name` or in a
/// `super::{…}` group (its hub `mod.rs`, which declares the shared types, and its test files
/// left out).
fn numeric_edges_in_code() -> BTreeMap<String, BTreeSet<String>> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/numeric");
    let mut files: Vec<(String, std::path::PathBuf)> = Vec::new();
    for e in std::fs::read_dir(&dir).unwrap() {
        let p = e.unwrap().path();
        let stem = p.file_stem().unwrap().to_str().unwrap().to_string();
        if p.is_dir() {
            files.push((stem, p.join("mod.rs")));
        } else if stem != "mod" && !stem.starts_with("tests") {
            files.push((stem, p));
        }
    }
    let names: BTreeSet<String> = files.iter().map(|f| f.0.clone()).collect();
    let word = |t: &str| -> String {
        t.trim()
            .chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
            .collect()
    };
    let mut edges = BTreeMap::new();
    for (m, f) in &files {
        let text = code_of(f);
        let mut uses = BTreeSet::new();
        for (at, _) in text.match_indices("super::") {
            let rest = &text[at + 7..];
            let named: Vec<String> = match rest.strip_prefix('{') {
                Some(group) => group[..group.find('}').unwrap()]
                    .split(',')
                    .map(word)
                    .collect(),
                None => vec![word(rest)],
            };
            uses.extend(named.into_iter().filter(|n| names.contains(n) && n != m));
        }
        edges.insert(m.clone(), uses);
    }
    edges
}

/// The rows of the table under the heading `heading`: module, uses (rows above).
fn table(heading: &str) -> Vec<(String, BTreeSet<String>)> {
    let doc =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("ARCHITECTURE.md"))
            .unwrap();
    let section = doc
        .split(&format!("\n{heading}\n"))
        .nth(1)
        .unwrap_or_else(|| panic!("a « {heading} » section"));
    let section = section.split("\n## ").next().unwrap();
    let names = |cell: &str| -> BTreeSet<String> {
        cell.split(',')
            .map(|x| x.trim().trim_matches('`').to_string())
            .filter(|x| !x.is_empty() && x != "—")
            .collect()
    };
    section
        .lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| {
            let cells: Vec<&str> = l.trim_matches('|').split('|').collect();
            assert_eq!(cells.len(), 2, "a row has two cells: {l}");
            (
                cells[0].trim().trim_matches('`').to_string(),
                names(cells[1]),
            )
        })
        .collect()
}

/// Every module of the code is a row, uses only rows above it, and each row lists exactly
/// what its module uses.
fn check(
    what: &str,
    code: &BTreeMap<String, BTreeSet<String>>,
    rows: &[(String, BTreeSet<String>)],
) {
    let order: Vec<&str> = rows.iter().map(|r| r.0.as_str()).collect();
    let at = |m: &str| order.iter().position(|x| *x == m);
    let in_code: BTreeSet<&String> = code.keys().collect();
    let in_table: BTreeSet<&String> = rows.iter().map(|r| &r.0).collect();
    assert_eq!(
        in_code, in_table,
        "every module of {what} is a row of its table"
    );
    for (m, above) in rows {
        let i = at(m).unwrap();
        for b in above {
            assert!(
                at(b).is_some_and(|j| j < i),
                "{what}: {m} → {b} is listed, but {b} is not a row above {m}"
            );
        }
        let actual = &code[m];
        let new: Vec<_> = actual.difference(above).collect();
        assert!(
            new.is_empty(),
            "{what}: {m} uses {new:?}, which its layers table in ARCHITECTURE.md does not list \
             (a module may only use the rows above it)"
        );
        let gone: Vec<_> = above.difference(actual).collect();
        assert!(
            gone.is_empty(),
            "{what}: {m} no longer uses {gone:?}: remove it from the layers table"
        );
    }
}

#[test]
fn every_module_uses_only_the_layers_the_architecture_table_allows() {
    check("src/", &edges_in_code(), &table("## Layers"));
}

#[test]
fn the_float_backend_files_form_layers_too() {
    check(
        "src/numeric/",
        &numeric_edges_in_code(),
        &table("## Layers of the float backend"),
    );
}
