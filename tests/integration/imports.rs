//! No import circle: within each module, its children import one another
//! in one direction only (ARCHITECTURE.md's layers, one level at a time).
//! The paths a file names (`use crate::a::b`, `super::c::D`, groups in
//! braces, paths written inline) are read from its code outside its tests,
//! each taken to the deepest module it reaches, and every pair of siblings
//! that name each other, directly or round a longer loop, is a circle.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// A module's path below the crate (`app::tabs::map`; the crate root is
/// empty).
type Module = Vec<String>;

/// Every module of `src` (from its file's place) with its code, less its
/// `#[cfg(test)]` module and its comment lines.
fn modules(src: &Path) -> BTreeMap<Module, String> {
    let mut found = BTreeMap::new();
    let mut folders = vec![src.to_path_buf()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).expect("a source folder") {
            let path = entry.expect("an entry").path();
            if path.is_dir() {
                folders.push(path);
                continue;
            }
            if path.extension().is_none_or(|e| e != "rs") {
                continue;
            }
            let relative = path.strip_prefix(src).expect("below src");
            let mut module: Module = relative
                .with_extension("")
                .iter()
                .map(|part| part.to_string_lossy().into_owned())
                .collect();
            if matches!(
                module.last().map(String::as_str),
                Some("mod" | "lib" | "main")
            ) {
                module.pop();
            }
            let text = std::fs::read_to_string(&path).expect("a source file");
            let code = text
                .split("#[cfg(test)]\nmod tests")
                .next()
                .unwrap_or_default()
                .lines()
                .filter(|line| !line.trim_start().starts_with("//"))
                .collect::<Vec<_>>()
                .join("\n");
            found.insert(module, code);
        }
    }
    found
}

/// The paths `code` names that start at `crate` or `super`, with the
/// groups of a `use` spelled out (`use crate::a::{b, c::D}`: `crate::a::b`,
/// `crate::a::c::D`).
fn named_paths(code: &str) -> Vec<Vec<String>> {
    let mut paths = Vec::new();
    let bytes: Vec<char> = code.chars().collect();
    let mut i = 0;
    while i < bytes.len() {
        let rest: String = bytes[i..bytes.len().min(i + 6)].iter().collect();
        let starts = (rest.starts_with("crate:") || rest.starts_with("super:"))
            && (i == 0 || !(bytes[i - 1].is_alphanumeric() || bytes[i - 1] == '_'));
        if starts {
            let (found, end) = path_at(&bytes, i, Vec::new());
            paths.extend(found);
            i = end.max(i + 1);
        } else {
            i += 1;
        }
    }
    paths
}

/// The paths beginning at `at` (after `prefix`), and where they end.
fn path_at(chars: &[char], at: usize, prefix: Vec<String>) -> (Vec<Vec<String>>, usize) {
    let mut path = prefix;
    let mut i = at;
    loop {
        let start = i;
        while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
            i += 1;
        }
        if i > start {
            path.push(chars[start..i].iter().collect());
        }
        if chars.get(i) == Some(&':') && chars.get(i + 1) == Some(&':') {
            i += 2;
            if chars.get(i) == Some(&'{') {
                // A group: each item a path of its own.
                let mut all = Vec::new();
                i += 1;
                loop {
                    while chars.get(i).is_some_and(|c| c.is_whitespace() || *c == ',') {
                        i += 1;
                    }
                    match chars.get(i) {
                        None => return (all, i),
                        Some('}') => return (all, i + 1),
                        _ => {
                            let (inner, end) = path_at(chars, i, path.clone());
                            all.extend(inner);
                            // Past an alias (`as x`) to the next item.
                            i = end;
                            while chars.get(i).is_some_and(|c| *c != ',' && *c != '}') {
                                i += 1;
                            }
                        }
                    }
                }
            }
            continue;
        }
        return (vec![path], i);
    }
}

/// The module `path`, named in `from`, reaches: its `crate` or `super`s
/// resolved, cut at the deepest module there is.
fn reached(path: &[String], from: &Module, known: &BTreeSet<Module>) -> Module {
    let mut module: Module = Vec::new();
    let mut rest = path;
    if rest.first().map(String::as_str) == Some("crate") {
        rest = &rest[1..];
    } else {
        module.clone_from(from);
        while rest.first().map(String::as_str) == Some("super") {
            module.pop();
            rest = &rest[1..];
        }
    }
    for part in rest {
        let mut deeper = module.clone();
        deeper.push(part.clone());
        if !known.contains(&deeper) {
            break;
        }
        module = deeper;
    }
    module
}

#[test]
fn no_two_sibling_modules_import_each_other() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let modules = modules(&src);
    let known: BTreeSet<Module> = modules.keys().cloned().collect();
    // Edges between siblings, keyed by their parent.
    let mut edges: BTreeMap<Module, BTreeSet<(String, String)>> = BTreeMap::new();
    let mut named = 0;
    for (from, code) in &modules {
        for path in named_paths(code) {
            let to = reached(&path, from, &known);
            named += 1;
            let common = from.iter().zip(&to).take_while(|(a, b)| a == b).count();
            // A module naming its own ancestor or descendant is no circle
            // between siblings.
            if common == from.len() || common == to.len() {
                continue;
            }
            edges
                .entry(from[..common].to_vec())
                .or_default()
                .insert((from[common].clone(), to[common].clone()));
        }
    }
    assert!(named > 500, "only {named} paths read");
    let mut circles = Vec::new();
    for (parent, pairs) in &edges {
        for (a, b) in pairs {
            // b reaches a again: a circle through a -> b.
            let mut seen = BTreeSet::new();
            let mut stack = vec![b.clone()];
            while let Some(at) = stack.pop() {
                if at == *a {
                    circles.push(format!("{}: {a} -> {b} -> ... -> {a}", parent.join("::")));
                    break;
                }
                if seen.insert(at.clone()) {
                    stack.extend(
                        pairs
                            .iter()
                            .filter(|(x, _)| *x == at)
                            .map(|(_, y)| y.clone()),
                    );
                }
            }
        }
    }
    assert!(
        circles.is_empty(),
        "import circles:\n{}",
        circles.join("\n")
    );
}
