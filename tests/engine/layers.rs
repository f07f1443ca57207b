//! The layers of ARCHITECTURE.md, checked against the code: every `crate::` edge between the
//! top-level modules of `src/` is in the table, in the column its direction says, and every
//! edge of the table exists.

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

/// The rows of the table under « ## Layers »: module, uses above, uses below.
fn table() -> Vec<(String, BTreeSet<String>, BTreeSet<String>)> {
    let doc =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("ARCHITECTURE.md"))
            .unwrap();
    let section = doc
        .split("\n## Layers\n")
        .nth(1)
        .expect("a « ## Layers » section");
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
            assert_eq!(cells.len(), 3, "a row has three cells: {l}");
            (
                cells[0].trim().trim_matches('`').to_string(),
                names(cells[1]),
                names(cells[2]),
            )
        })
        .collect()
}

#[test]
fn every_module_uses_only_the_layers_the_architecture_table_allows() {
    let code = edges_in_code();
    let rows = table();
    let order: Vec<&str> = rows.iter().map(|r| r.0.as_str()).collect();
    let at = |m: &str| order.iter().position(|x| *x == m);
    let in_code: BTreeSet<&String> = code.keys().collect();
    let in_table: BTreeSet<&String> = rows.iter().map(|r| &r.0).collect();
    assert_eq!(
        in_code, in_table,
        "every module of src/ is a row of the table"
    );
    for (m, above, below) in &rows {
        let i = at(m).unwrap();
        for b in above {
            assert!(
                at(b).unwrap() < i,
                "{m} → {b} is listed as above, but {b} is below {m}"
            );
        }
        for b in below {
            assert!(
                at(b).unwrap() > i,
                "{m} → {b} is listed as below, but {b} is above {m}"
            );
        }
        let listed: BTreeSet<String> = above.union(below).cloned().collect();
        let actual = &code[m];
        let new: Vec<_> = actual.difference(&listed).collect();
        assert!(
            new.is_empty(),
            "{m} uses {new:?}, which the layers table of ARCHITECTURE.md does not list \
             (a module may only use the rows above it)"
        );
        let gone: Vec<_> = listed.difference(actual).collect();
        assert!(
            gone.is_empty(),
            "{m} no longer uses {gone:?}: remove it from the layers table"
        );
    }
}
