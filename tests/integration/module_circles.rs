//! No module circle inside a crate (ARCHITECTURE.md): of a crate's top-level modules, none uses
//! another that, through others, uses it back. A circle is a misplaced helper, and it makes the
//! modules one knot that can be read and changed only together.
//!
//! A module's uses are read from its source as written: `crate::NAME` anywhere in it, and
//! `super::NAME` in its top file (where `super` is the crate's root); doc comments and the test
//! module at a file's end are left out.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The `.rs` files under `dir`, each with its path relative to `dir`.
fn sources(dir: &Path, under: &Path, found: &mut Vec<(String, String)>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, under, found);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let relative = path
                .strip_prefix(under)
                .unwrap()
                .to_string_lossy()
                .into_owned();
            found.push((relative, std::fs::read_to_string(&path).unwrap()));
        }
    }
}

/// The first path segment of each name `prefix` is followed by in `code`: `crate::a::b` and
/// `crate::{a, b::c}` give `a` (and `b`).
fn used_after(code: &str, prefix: &str) -> BTreeSet<String> {
    let mut used = BTreeSet::new();
    for (at, _) in code.match_indices(prefix) {
        let before = code[..at].chars().next_back();
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
            continue;
        }
        let rest = &code[at + prefix.len()..];
        let names = match rest.strip_prefix('{') {
            Some(group) => group.split('}').next().unwrap_or_default(),
            None => rest,
        };
        for name in names.split(',') {
            let name: String = name
                .trim()
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() {
                used.insert(name);
            }
        }
    }
    used
}

/// Each top-level module of the crate whose source `files` are given (each with its path from
/// the crate's `src`) and the top-level modules it uses.
fn module_uses(files: &[(String, String)]) -> BTreeMap<String, BTreeSet<String>> {
    let mut uses: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (path, text) in files {
        let parts: Vec<&str> = path.trim_end_matches(".rs").split('/').collect();
        if matches!(parts.as_slice(), ["lib" | "main"]) {
            continue;
        }
        let top_file = parts.len() == 1 || (parts.len() == 2 && parts[1] == "mod");
        let code: String = text
            .split("#[cfg(test)]\nmod tests")
            .next()
            .unwrap_or_default()
            .lines()
            .filter(|line| !line.trim_start().starts_with("//"))
            .collect::<Vec<_>>()
            .join("\n");
        let mut used = used_after(&code, "crate::");
        if top_file {
            used.extend(used_after(&code, "super::"));
        }
        uses.entry(parts[0].to_owned()).or_default().extend(used);
    }
    let modules: BTreeSet<String> = uses.keys().cloned().collect();
    for (module, used) in &mut uses {
        used.retain(|u| modules.contains(u) && u != module);
    }
    uses
}

/// The modules `from` reaches through `uses`, itself included only through a circle.
fn reached(uses: &BTreeMap<String, BTreeSet<String>>, from: &str) -> BTreeSet<String> {
    let mut seen = BTreeSet::new();
    let mut next: Vec<&String> = uses[from].iter().collect();
    while let Some(module) = next.pop() {
        if seen.insert(module.clone()) {
            next.extend(uses.get(module).into_iter().flatten());
        }
    }
    seen
}

/// Every module of the crate of `files` (as [`module_uses`] takes them) that reaches itself,
/// with the modules of its circle.
fn circles(files: &[(String, String)]) -> Vec<String> {
    let uses = module_uses(files);
    let reach: BTreeMap<&String, BTreeSet<String>> =
        uses.keys().map(|m| (m, reached(&uses, m))).collect();
    reach
        .iter()
        .filter(|(module, reached)| reached.contains(module.as_str()))
        .map(|(module, reached)| {
            let circle: Vec<&String> = reached
                .iter()
                .filter(|other| reach[other].contains(module.as_str()))
                .collect();
            format!("{module} ↔ {circle:?}")
        })
        .collect()
}

#[test]
fn no_crate_has_a_module_circle() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut crates = vec![root.join("src")];
    for entry in std::fs::read_dir(root.join("crates")).unwrap() {
        crates.push(entry.unwrap().path().join("src"));
    }
    assert!(crates.len() > 8, "read {crates:?}");
    let found: Vec<String> = crates
        .iter()
        .flat_map(|src| {
            let mut files = Vec::new();
            sources(src, src, &mut files);
            circles(&files)
                .into_iter()
                .map(move |c| format!("{}: {c}", src.display()))
        })
        .collect();
    assert!(found.is_empty(), "module circles:\n{}", found.join("\n"));
}

#[test]
fn a_circle_is_found_where_two_modules_use_each_other() {
    let files = [
        ("lib.rs", "mod a;\nmod b;\nmod c;\n"),
        (
            "a.rs",
            "use super::b::Thing;\n/// [`crate::c`]\npub struct Other;\n",
        ),
        (
            "b/mod.rs",
            "mod d;\nuse crate::{c::More, a::Other};\npub struct Thing;\n",
        ),
        ("b/d.rs", "use super::Thing;\n"),
        (
            "c.rs",
            "pub struct More;\n#[cfg(test)]\nmod tests {\n    use crate::a::Other;\n}\n",
        ),
    ]
    .map(|(path, text)| (path.to_owned(), text.to_owned()));
    let uses = module_uses(&files);
    assert_eq!(uses["a"], BTreeSet::from(["b".to_owned()]));
    assert_eq!(uses["b"], BTreeSet::from(["a".to_owned(), "c".to_owned()]));
    assert!(
        uses["c"].is_empty(),
        "its test module and a doc link are no use"
    );
    let found = circles(&files);
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(found[0].starts_with("a ↔"), "{found:?}");
}
