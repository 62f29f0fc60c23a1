//! Issue 37, item 4: no module cycles at any level. Cargo forbids a circle
//! between crates (`regression_32_architecture_names_each_crates_dependencies`
//! checks the crates' table); this checks the modules inside each crate.
//!
//! A module *uses* another when its non-test code names it by path:
//! `crate::a::b`, `super::x`, `self::y`, or a `use` tree (braces expanded)
//! that starts with one of those or with a child module's name. Each use is
//! lifted to the siblings it joins: `models::circular::system` using
//! `models::contact` is `circular → contact` among the children of
//! `models`. Among the children of any module (the crate root included),
//! those edges must form no circle. Only the path written is followed, not
//! a re-export it may go through. Test code (from the first `#[cfg(test)]`
//! of a file on) and comments are left out, as they import freely.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// A module's path inside its crate (`["models", "circular"]`; the root is
/// empty).
type ModPath = Vec<String>;

/// The module of a source file `rel` (relative to its crate's `src/`), or
/// `None` for a file of `src/bin/`.
fn module_of(rel: &Path) -> Option<ModPath> {
    let mut parts: Vec<String> = rel
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    let last = parts.pop()?;
    let stem = last.strip_suffix(".rs")?.to_string();
    if parts.first().map(String::as_str) == Some("bin") {
        return None;
    }
    if stem != "mod" && !(parts.is_empty() && (stem == "lib" || stem == "main")) {
        parts.push(stem);
    }
    Some(parts)
}

/// The non-test code of a file, without comments.
fn code(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap_or("");
    text.lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// The top-level items of a brace group's inside, split at its own commas.
fn split_top(inner: &str) -> Vec<&str> {
    let (mut depth, mut start, mut out) = (0, 0, Vec::new());
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                out.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(&inner[start..]);
    out.into_iter()
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .collect()
}

/// The paths of a `use` tree (spaces only around `as`), braces expanded:
/// `a::{b, c::{d as e, f}}` gives `a::b`, `a::c::d`, `a::c::f`.
fn expand(tree: &str) -> Vec<Vec<String>> {
    let Some(open) = tree.find('{') else {
        let path = tree.split(" as ").next().unwrap_or(tree);
        return vec![path.split("::").map(str::to_string).collect()];
    };
    let prefix: Vec<String> = tree[..open]
        .trim_end_matches("::")
        .split("::")
        .filter(|s| !s.is_empty())
        .map(str::to_string)
        .collect();
    let close = tree.rfind('}').filter(|&c| c > open).unwrap_or(tree.len());
    let inner = &tree[open + 1..close];
    let mut out = Vec::new();
    for item in split_top(inner) {
        for tail in expand(item) {
            let mut p = prefix.clone();
            p.extend(tail.into_iter().filter(|s| s != "self"));
            out.push(p);
        }
    }
    out
}

/// Every path a file's code names: its `use` trees, and each
/// `crate::`/`super::`/`self::` path written elsewhere.
fn paths(code: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let text = code;
    // `use` trees.
    let mut at = 0;
    while let Some(i) = text[at..].find("use ") {
        let start = at + i;
        at = start + 4;
        let before = text[..start].chars().next_back();
        if before.is_some_and(is_ident) {
            continue;
        }
        let Some(end) = text[at..].find(';') else {
            break;
        };
        // Words joined by one space; none beside `::`, braces and commas.
        let mut tree = text[at..at + end]
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        for tight in ["::", "{", "}", ","] {
            tree = tree
                .replace(&format!(" {tight}"), tight)
                .replace(&format!("{tight} "), tight);
        }
        out.extend(expand(&tree));
    }
    // Paths in expressions and types.
    for root in ["crate::", "super::", "self::"] {
        let mut at = 0;
        while let Some(i) = text[at..].find(root) {
            let start = at + i;
            at = start + root.len();
            if text[..start].chars().next_back().is_some_and(is_ident) {
                continue;
            }
            let len = text[start..]
                .find(|c: char| !(is_ident(c) || c == ':'))
                .unwrap_or(text.len() - start);
            out.push(
                text[start..start + len]
                    .split("::")
                    .filter(|s| !s.is_empty())
                    .map(str::to_string)
                    .collect(),
            );
        }
    }
    out
}

/// The module a path `p`, written in module `me`, names: the longest of
/// its leading module names that is a module of the crate (`modules`).
fn target(me: &ModPath, p: &[String], modules: &BTreeSet<ModPath>) -> Option<ModPath> {
    let first = p.first()?;
    let (mut base, rest): (ModPath, &[String]) = match first.as_str() {
        "crate" => (Vec::new(), &p[1..]),
        "super" | "self" => {
            let mut base = me.clone();
            let mut k = 0;
            while let Some(s) = p.get(k).filter(|s| *s == "super" || *s == "self") {
                if s == "super" {
                    base.pop();
                }
                k += 1;
            }
            (base, &p[k..])
        }
        name => {
            // A child module named without `self::` (2018 paths).
            let mut child = me.clone();
            child.push(name.to_string());
            if !modules.contains(&child) {
                return None;
            }
            (me.clone(), p)
        }
    };
    for seg in rest {
        let mut next = base.clone();
        next.push(seg.clone());
        if !modules.contains(&next) {
            break;
        }
        base = next;
    }
    Some(base)
}

/// The circles among sibling modules of one crate whose files are `files`
/// (module path, source text), each as `parent: a → b → … → a`.
fn circles(files: &[(ModPath, String)]) -> Vec<String> {
    let modules: BTreeSet<ModPath> = files.iter().map(|(m, _)| m.clone()).collect();
    // Edges among the children of each parent.
    let mut graphs: BTreeMap<ModPath, BTreeMap<String, BTreeSet<String>>> = BTreeMap::new();
    for (me, text) in files {
        for p in paths(&code(text)) {
            let Some(t) = target(me, &p, &modules) else {
                continue;
            };
            let k = me.iter().zip(&t).take_while(|(a, b)| a == b).count();
            if k < me.len() && k < t.len() {
                graphs
                    .entry(me[..k].to_vec())
                    .or_default()
                    .entry(me[k].clone())
                    .or_default()
                    .insert(t[k].clone());
            }
        }
    }
    let mut found = Vec::new();
    for (parent, g) in &graphs {
        // Reachability (the graphs have a few dozen nodes at most).
        let nodes: Vec<&String> = g
            .keys()
            .chain(g.values().flatten())
            .collect::<BTreeSet<_>>()
            .into_iter()
            .collect();
        let index = |n: &String| nodes.iter().position(|m| *m == n).unwrap();
        let n = nodes.len();
        let mut reach = vec![vec![false; n]; n];
        for (a, bs) in g {
            for b in bs {
                reach[index(a)][index(b)] = true;
            }
        }
        for k in 0..n {
            let via = reach[k].clone();
            for row in reach.iter_mut().filter(|row| row[k]) {
                for (r, v) in row.iter_mut().zip(&via) {
                    *r |= *v;
                }
            }
        }
        let mut seen = BTreeSet::new();
        for (i, row) in reach.iter().enumerate() {
            if !row[i] || seen.contains(&i) {
                continue;
            }
            let circle: Vec<usize> = (0..n).filter(|&j| row[j] && reach[j][i]).collect();
            seen.extend(circle.iter().copied());
            let names: Vec<&str> = circle.iter().map(|&j| nodes[j].as_str()).collect();
            let parent = if parent.is_empty() {
                "the crate root".to_string()
            } else {
                parent.join("::")
            };
            found.push(format!("{parent}: {}", names.join(" ↔ ")));
        }
    }
    found
}

/// Every `.rs` file under `dir`.
fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

#[test]
fn issue37_no_module_cycle_in_any_crate() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut crates: Vec<PathBuf> = std::fs::read_dir(root.join("crates"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.join("src").is_dir())
        .collect();
    crates.sort();
    assert!(crates.len() >= 6, "{crates:?}");
    let mut found = Vec::new();
    let mut modules = 0;
    for krate in crates {
        let src = krate.join("src");
        let mut files = Vec::new();
        sources(&src, &mut files);
        let files: Vec<(ModPath, String)> = files
            .iter()
            .filter_map(|f| {
                let m = module_of(f.strip_prefix(&src).unwrap())?;
                Some((m, std::fs::read_to_string(f).unwrap()))
            })
            .collect();
        modules += files.len();
        let name = krate.file_name().unwrap().to_string_lossy().into_owned();
        found.extend(circles(&files).into_iter().map(|c| format!("{name}: {c}")));
    }
    assert!(modules > 150, "only {modules} modules read");
    assert!(
        found.is_empty(),
        "modules in a circle:\n{}",
        found.join("\n")
    );
}

/// The check itself, on made-up crates: it sees a circle through `super::`,
/// `crate::` and a `use` group, a deeper one, and passes a tree without one.
#[test]
fn issue37_the_cycle_check_finds_a_circle_written_each_way() {
    let file =
        |m: &[&str], text: &str| (m.iter().map(|s| s.to_string()).collect(), text.to_string());
    let circular = [
        file(&[], "mod a;\nmod b;\nmod c;\n"),
        file(&["a"], "use super::b::Thing;\n"),
        file(
            &["b"],
            "use crate::{\n    c::{self, Other as Another},\n    d,\n};\n",
        ),
        file(&["c"], "fn f() { crate::a::g(); }\n"),
    ];
    assert_eq!(circles(&circular), vec!["the crate root: a ↔ b ↔ c"]);
    let deep = [
        file(&["m"], "mod x;\nmod y;\n"),
        file(&["m", "x"], "use super::y::Y;\n"),
        file(&["m", "y", "z"], "fn f() { super::super::x::g(); }\n"),
        file(&["m", "y"], "mod z;\n"),
    ];
    assert_eq!(circles(&deep), vec!["m: x ↔ y"]);
    let tree = [
        file(&[], "mod a;\nmod b;\n"),
        file(&["a"], "use super::b::Thing; // crate::a in a comment\n"),
        file(
            &["b"],
            "pub struct Thing;\n#[cfg(test)]\nmod tests { use crate::a::*; }\n",
        ),
    ];
    assert!(circles(&tree).is_empty(), "{:?}", circles(&tree));
}
