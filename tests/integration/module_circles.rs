//! No module circle inside a crate, at any depth (ARCHITECTURE.md): of the modules that share a
//! parent, none uses another that, through others, uses it back. A circle is a misplaced helper,
//! and it makes the modules one knot that can be read and changed only together.
//!
//! A module's uses are read from its source as written: each path after `crate::`, `super::`
//! (any number of them) and `self::`, groups `{a, b::c}` included, resolved to the deepest
//! module it names. A use from anywhere inside one child of a module to anywhere inside another
//! child of the same module is an arrow between those two children; a module using its own
//! parent or child is no arrow (a parent holds what its children share). Comment lines (doc
//! comments too) and the test module at a file's end are left out.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// A module's path from its crate's root: `["app", "deck"]`; the root is empty.
type ModulePath = Vec<String>;

/// The `.rs` files under `dir`, each with its path relative to `under`.
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

/// The module a file under `src` holds: `app/deck/mod.rs` and `app/deck.rs` are `app::deck`,
/// `lib.rs` and `main.rs` the root.
fn module_of(file: &str) -> ModulePath {
    let mut parts: Vec<String> = file
        .trim_end_matches(".rs")
        .split('/')
        .map(str::to_owned)
        .collect();
    if matches!(
        parts.last().map(String::as_str),
        Some("mod" | "lib" | "main")
    ) {
        parts.pop();
    }
    parts
}

/// The code of a file as the uses are read from it: no comment line, no test module at its end.
fn code_of(text: &str) -> String {
    text.split("#[cfg(test)]\nmod tests {")
        .next()
        .unwrap_or_default()
        .lines()
        .filter(|line| !line.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The paths of the use tree at the start of `code` (what follows `crate::`), and the code after
/// it: `a::b` gives `[a, b]`, `{a, b::{c, d as e}}` gives `[a]`, `[b, c]` and `[b, d]`.
fn use_tree(code: &str) -> (Vec<ModulePath>, &str) {
    let mut path = Vec::new();
    let mut rest = code;
    loop {
        if let Some(mut inner) = rest.strip_prefix('{') {
            let mut paths = Vec::new();
            loop {
                let (found, after) = use_tree(inner.trim_start());
                paths.extend(found.into_iter().map(|p| [path.clone(), p].concat()));
                let mut after = after.trim_start();
                if let Some(alias) = after.strip_prefix("as ") {
                    after = alias
                        .trim_start()
                        .trim_start_matches(is_name_char)
                        .trim_start();
                }
                match after.strip_prefix(',') {
                    Some(next) => inner = next,
                    None => return (paths, after.strip_prefix('}').unwrap_or(after)),
                }
            }
        }
        let name_len = rest.len() - rest.trim_start_matches(is_name_char).len();
        if name_len == 0 {
            break;
        }
        path.push(rest[..name_len].to_owned());
        rest = &rest[name_len..];
        match rest.strip_prefix("::") {
            Some(next) => rest = next,
            None => break,
        }
    }
    let paths = if path.is_empty() { vec![] } else { vec![path] };
    (paths, rest)
}

/// Whether `c` can be part of a name.
fn is_name_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// The paths named in `code` (the code of `module`), each from its crate's root: after
/// `crate::`, `super::` and `self::`.
fn paths_used(code: &str, module: &[String]) -> Vec<ModulePath> {
    let mut used = Vec::new();
    for prefix in ["crate::", "super::", "self::"] {
        for (at, _) in code.match_indices(prefix) {
            let before = code[..at].chars().next_back();
            if before.is_some_and(|c| is_name_char(c) || c == ':') {
                continue;
            }
            let mut base: ModulePath = match prefix {
                "crate::" => vec![],
                _ => module.to_vec(),
            };
            let mut rest = &code[at + prefix.len()..];
            if prefix == "super::" {
                base.pop();
                while let Some(further) = rest.strip_prefix("super::") {
                    base.pop();
                    rest = further;
                }
            }
            let (paths, _) = use_tree(rest);
            used.extend(paths.into_iter().map(|p| [base.clone(), p].concat()));
        }
    }
    used
}

/// The arrows between modules that share a parent, for the crate whose source `files` are
/// given (each with its path from the crate's `src`): for each parent, its children and the
/// children of the same parent each uses.
fn module_uses(files: &[(String, String)]) -> BTreeMap<ModulePath, BTreeSet<ModulePath>> {
    let modules: BTreeSet<ModulePath> = files.iter().map(|(path, _)| module_of(path)).collect();
    let mut uses: BTreeMap<ModulePath, BTreeSet<ModulePath>> = BTreeMap::new();
    for (path, text) in files {
        let from = module_of(path);
        for used in paths_used(&code_of(text), &from) {
            let Some(to) = (0..=used.len())
                .rev()
                .map(|n| used[..n].to_vec())
                .find(|m| modules.contains(m))
            else {
                continue;
            };
            let shared = from.iter().zip(&to).take_while(|(a, b)| a == b).count();
            if shared < from.len() && shared < to.len() {
                uses.entry(from[..=shared].to_vec())
                    .or_default()
                    .insert(to[..=shared].to_vec());
            }
        }
    }
    uses
}

/// The modules `from` reaches through `uses`, itself included only through a circle.
fn reached(
    uses: &BTreeMap<ModulePath, BTreeSet<ModulePath>>,
    from: &ModulePath,
) -> BTreeSet<ModulePath> {
    let mut seen = BTreeSet::new();
    let mut next: Vec<&ModulePath> = uses[from].iter().collect();
    while let Some(module) = next.pop() {
        if seen.insert(module.clone()) {
            next.extend(uses.get(module).into_iter().flatten());
        }
    }
    seen
}

/// Every circle of the crate of `files` (as [`module_uses`] takes them): the modules that reach
/// each other, in order, as `app::deck ↔ app::link ↔ app::tools`.
fn circles(files: &[(String, String)]) -> Vec<String> {
    let uses = module_uses(files);
    let reach: BTreeMap<&ModulePath, BTreeSet<ModulePath>> =
        uses.keys().map(|m| (m, reached(&uses, m))).collect();
    let knots: BTreeSet<Vec<String>> = reach
        .iter()
        .filter(|(module, reached)| reached.contains(**module))
        .map(|(module, reached)| {
            reached
                .iter()
                .filter(|other| reach.get(other).is_some_and(|r| r.contains(*module)))
                .map(|other| other.join("::"))
                .collect()
        })
        .collect();
    knots.into_iter().map(|knot| knot.join(" ↔ ")).collect()
}

#[test]
fn no_crate_has_a_module_circle() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut crates = vec![root.join("src"), root.join("xtask/src")];
    for entry in std::fs::read_dir(root.join("crates")).unwrap() {
        crates.push(entry.unwrap().path().join("src"));
    }
    assert!(crates.len() > 8, "read {crates:?}");
    let mut found = Vec::new();
    for src in &crates {
        let mut files = Vec::new();
        sources(src, src, &mut files);
        let folder = src.strip_prefix(root).unwrap();
        let folder = folder.to_string_lossy().replace('\\', "/");
        found.extend(
            circles(&files)
                .into_iter()
                .map(|c| format!("{folder}: {c}")),
        );
    }
    assert!(found.is_empty(), "module circles:\n{}", found.join("\n"));
}

#[test]
fn a_circle_is_found_where_two_top_modules_use_each_other() {
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
    let path = |p: &str| p.split("::").map(str::to_owned).collect::<ModulePath>();
    assert_eq!(uses[&path("a")], BTreeSet::from([path("b")]));
    assert_eq!(uses[&path("b")], BTreeSet::from([path("a"), path("c")]));
    assert!(
        !uses.contains_key(&path("c")),
        "its test module and a doc link are no use: {uses:?}"
    );
    assert!(
        !uses.contains_key(&path("b::d")),
        "a module using its parent is no arrow: {uses:?}"
    );
    assert_eq!(circles(&files), ["a ↔ b"]);
}

#[test]
fn a_circle_is_found_between_modules_deep_inside_others() {
    let files = [
        ("main.rs", "mod app;\n"),
        (
            "app/mod.rs",
            "mod deck;\nmod link;\nmod tools;\nuse self::deck::Deck;\n",
        ),
        ("app/deck/mod.rs", "mod panel;\npub struct Deck;\n"),
        (
            "app/deck/panel.rs",
            "use super::super::tools::{Tool, frame as tool_frame};\nuse super::Deck;\n",
        ),
        (
            "app/tools.rs",
            "pub struct Tool;\nfn f() { crate::app::link::Row::new(); }\n",
        ),
        ("app/link.rs", "use super::{deck::panel::Panel, tools};\n"),
    ]
    .map(|(path, text)| (path.to_owned(), text.to_owned()));
    let uses = module_uses(&files);
    let path = |p: &str| p.split("::").map(str::to_owned).collect::<ModulePath>();
    assert_eq!(
        uses[&path("app::deck")],
        BTreeSet::from([path("app::tools")]),
        "a use from inside deck is deck's"
    );
    assert_eq!(
        uses[&path("app::link")],
        BTreeSet::from([path("app::deck"), path("app::tools")])
    );
    assert!(
        !uses.contains_key(&path("app")),
        "a parent using its child is no arrow: {uses:?}"
    );
    assert_eq!(circles(&files), ["app::deck ↔ app::link ↔ app::tools"]);
    let untied: Vec<(String, String)> = files
        .iter()
        .filter(|(path, _)| path != "app/tools.rs")
        .cloned()
        .collect();
    assert!(circles(&untied).is_empty(), "{:?}", circles(&untied));
}
