//! The layers of ARCHITECTURE.md, checked against the code: every `crate::` edge between the
//! top-level modules of `src/` is in the table and points up it, and every edge of the table
//! exists; the same for the files of the float backend (`src/numeric/`) and their `super::`
//! edges, against the table of docs/design-notes.md. And the map itself: every path ARCHITECTURE.md,
//! docs/design-notes.md, the README and the pages it links to in `docs/` name exists, and
//! every folder of `src/` and every top-level module file is named in ARCHITECTURE.md.

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

/// The rows of the table under the heading `heading` of the document `file`: module, uses
/// (rows above).
fn table(file: &str, heading: &str) -> Vec<(String, BTreeSet<String>)> {
    let doc = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(file)).unwrap();
    let section = doc
        .split(&format!("\n{heading}\n"))
        .nth(1)
        .unwrap_or_else(|| panic!("a « {heading} » section in {file}"));
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
            "{what}: {m} uses {new:?}, which its layers table does not list \
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
    check(
        "src/",
        &edges_in_code(),
        &table("ARCHITECTURE.md", "## Layers"),
    );
}

#[test]
fn the_float_backend_files_form_layers_too() {
    check(
        "src/numeric/",
        &numeric_edges_in_code(),
        &table("docs/design-notes.md", "### Layers of the float backend"),
    );
}

/// The crate's root directory.
fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Where a path the documents name may start: the crate's folders and top-level files.
const ROOTS: &[&str] = &[
    "src/",
    "tests/",
    "docs/",
    "derivations/",
    "latex/",
    "benches/",
    "examples/",
    "fuzz/",
    "scripts/",
    "assets/",
    ".ci/",
    ".cargo/",
    "README.md",
    "ARCHITECTURE.md",
    "Cargo.toml",
    "Cargo.lock",
    "spec.schema.json",
    "rustfmt.toml",
];

/// The paths a text names: each run of path characters (letters, digits, `_ - . / *`) that
/// starts at one of [`ROOTS`] or ends in `.rs` (so that a bare `mod.rs` is caught too), a
/// sentence's final period left out. Backticks, brackets and a link's parentheses all end a
/// run, so `` `src/pfd.rs` ``, `[x](docs/history.md)` and a path in a sketch are all found.
fn paths_named(text: &str) -> Vec<String> {
    let is_path_char = |c: char| c.is_ascii_alphanumeric() || "_-./*".contains(c);
    text.split(|c: char| !is_path_char(c))
        .map(|t| t.trim_end_matches('.'))
        .filter(|t| ROOTS.iter().any(|r| t.starts_with(r)) || t.ends_with(".rs"))
        .map(str::to_string)
        .collect()
}

/// Whether `path` (relative to the crate) exists; a `*` in its last part matches any run of
/// characters of a name in its folder, and at least one name must match.
fn exists(path: &str) -> bool {
    let (dir, name) = path.rsplit_once('/').unwrap_or(("", path));
    if dir.contains('*') {
        return false;
    }
    match name.split_once('*') {
        None => root().join(path).exists(),
        Some((head, tail)) => std::fs::read_dir(root().join(dir)).is_ok_and(|entries| {
            entries.filter_map(|e| e.ok()).any(|e| {
                let n = e.file_name().to_string_lossy().into_owned();
                n.len() >= head.len() + tail.len() && n.starts_with(head) && n.ends_with(tail)
            })
        }),
    }
}

/// The folders under `src/` (at every depth, `src/expr/present/` included) and the top-level
/// module files (`src/pfd.rs`), as the map writes them: `src/expr/`, `src/pfd.rs`.
fn source_tree() -> (Vec<String>, Vec<String>) {
    fn folders(dir: &Path, rel: &str, out: &mut Vec<String>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                let name = p.file_name().unwrap().to_str().unwrap();
                let rel = format!("{rel}{name}/");
                folders(&p, &rel, out);
                out.push(rel);
            }
        }
    }
    let src = root().join("src");
    let mut dirs = Vec::new();
    folders(&src, "src/", &mut dirs);
    let mut files: Vec<String> = std::fs::read_dir(&src)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "rs"))
        .map(|p| format!("src/{}", p.file_name().unwrap().to_str().unwrap()))
        .collect();
    dirs.sort();
    files.sort();
    (dirs, files)
}

/// The paths of the map and of the design notes that do not exist, each with its document.
fn missing_paths(docs: &[&str]) -> (usize, Vec<String>) {
    let mut count = 0;
    let mut missing = Vec::new();
    for doc in docs {
        let text = std::fs::read_to_string(root().join(doc))
            .unwrap_or_else(|e| panic!("{doc} cannot be read: {e}"));
        for p in paths_named(&text) {
            count += 1;
            if !exists(&p) {
                missing.push(format!("{doc} names `{p}`, which does not exist"));
            }
        }
    }
    missing.sort();
    missing.dedup();
    (count, missing)
}

#[test]
fn the_path_reader_finds_what_a_map_names() {
    // Written by hand: what a reader of this paragraph sees as paths.
    let text = "The parser (`src/spec/mod.rs`) feeds [the notes](docs/design-notes.md); \
                see src/expr/ and `mod.rs`. The specs are derivations/*.json, the CI .ci/run. \
                Ω(i/j) and V(P, 2/0) are not paths, nor is `crate::expr` or 1/2.";
    assert_eq!(
        paths_named(text),
        [
            "src/spec/mod.rs",
            "docs/design-notes.md",
            "src/expr/",
            "mod.rs",
            "derivations/*.json",
            ".ci/run",
        ]
    );
    assert!(exists("src/spec/mod.rs") && exists("src/expr/") && exists("derivations/*.json"));
    assert!(!exists("mod.rs") && !exists("src/verify.rs") && !exists("derivations/*.tex"));
}

#[test]
fn every_path_the_map_and_the_design_notes_name_exists() {
    let (count, missing) = missing_paths(&[
        "ARCHITECTURE.md",
        "docs/design-notes.md",
        "README.md",
        "docs/guide.md",
        "docs/guarantees.md",
        "docs/performance.md",
    ]);
    // The map names every folder and top-level file of src/ and the files a change touches:
    // far more than this, so an extractor that finds nothing cannot pass.
    assert!(
        count >= 100,
        "only {count} paths found in ARCHITECTURE.md, docs/ and the README"
    );
    assert!(
        missing.is_empty(),
        "paths named in the documents do not exist (write a path from the crate's root, \
         e.g. `src/latex/text.rs`; fix or remove it):\n{}",
        missing.join("\n")
    );
}

#[test]
fn every_folder_and_top_level_module_of_src_is_named_in_the_map() {
    let map = std::fs::read_to_string(root().join("ARCHITECTURE.md")).unwrap();
    let named: BTreeSet<String> = paths_named(&map)
        .into_iter()
        .map(|p| p.trim_end_matches('/').to_string())
        .collect();
    let (dirs, files) = source_tree();
    assert!(
        dirs.len() >= 15 && files.len() >= 10,
        "src/ read wrong: {} folders, {} top-level files",
        dirs.len(),
        files.len()
    );
    let unnamed: Vec<&String> = (dirs.iter().chain(&files))
        .filter(|p| !named.contains(p.trim_end_matches('/')))
        .collect();
    assert!(
        unnamed.is_empty(),
        "ARCHITECTURE.md does not name {unnamed:?}: give each a short paragraph (what it owns, \
         what it must not do) and, for a module, its row in the layers table"
    );
}
