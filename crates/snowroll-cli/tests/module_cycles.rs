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
//! those edges must form no circle. A name a module re-exports (`pub use`)
//! is followed to the module it comes from: `crate::models::Coefficients`
//! is a use of `models::coefficients`. Test code (from the first
//! `#[cfg(test)]` of a file on) and comments are left out, as they import
//! freely.

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
/// `a::{b, c::{d as e, f}}` gives `a::b`, `a::c::d as e`, `a::c::f` (an
/// alias stays on the last segment; [`Use::of`] splits it off).
fn expand(tree: &str) -> Vec<Vec<String>> {
    let Some(open) = tree.find('{') else {
        return vec![tree.split("::").map(str::to_string).collect()];
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

/// A path a file's code names: a `use` (re-exported when `public`, under
/// `alias` when given) or a path written in the code.
struct Use {
    path: Vec<String>,
    alias: Option<String>,
    public: bool,
}

impl Use {
    /// A path whose last segment may carry ` as alias`.
    fn of(mut path: Vec<String>, public: bool) -> Self {
        let mut alias = None;
        if let Some(last) = path.pop() {
            let mut words = last.split(" as ");
            path.push(words.next().unwrap_or("").to_string());
            alias = words.next().map(str::to_string);
        }
        Use {
            path,
            alias,
            public,
        }
    }
}

/// Whether the code before a `use` makes it public: `pub` or `pub(…)`.
fn is_public(before: &str) -> bool {
    let head = before.trim_end();
    if head.ends_with(')') {
        if let Some(open) = head.rfind('(') {
            return head[..open].trim_end().ends_with("pub");
        }
    }
    head.ends_with("pub") && !head[..head.len() - 3].ends_with(|c: char| is_ident(c))
}

/// Every path a file's code names: its `use` trees, and each
/// `crate::`/`super::`/`self::` path written elsewhere.
fn paths(code: &str) -> Vec<Use> {
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
        let public = is_public(&text[..start]);
        out.extend(expand(&tree).into_iter().map(|p| Use::of(p, public)));
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
            let path = text[start..start + len]
                .split("::")
                .filter(|s| !s.is_empty())
                .map(str::to_string)
                .collect();
            out.push(Use::of(path, false));
        }
    }
    out
}

/// The names each module re-exports (`pub use`), to the absolute path of
/// what they name.
type Reexports = BTreeMap<ModPath, BTreeMap<String, Vec<String>>>;

/// The absolute path (from the crate root) of a path `p` written in module
/// `me`; `None` for a path outside the crate.
fn absolute(me: &ModPath, p: &[String], modules: &BTreeSet<ModPath>) -> Option<Vec<String>> {
    let first = p.first()?;
    let (mut base, rest): (Vec<String>, &[String]) = match first.as_str() {
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
    base.extend(rest.iter().cloned());
    Some(base)
}

/// The module an absolute path names: its leading module names, and where
/// a name is re-exported by the module reached so far, the module of what
/// it re-exports (followed at most `depth` times).
fn resolve(path: &[String], modules: &BTreeSet<ModPath>, re: &Reexports, depth: u32) -> ModPath {
    let mut base: ModPath = Vec::new();
    for seg in path {
        let mut next = base.clone();
        next.push(seg.clone());
        if modules.contains(&next) {
            base = next;
            continue;
        }
        if let Some(to) = re.get(&base).and_then(|names| names.get(seg)) {
            if depth > 0 && to.as_slice() != next.as_slice() {
                return resolve(to, modules, re, depth - 1);
            }
        }
        break;
    }
    base
}

/// The circles among sibling modules of one crate whose files are `files`
/// (module path, source text), each as `parent: a → b → … → a`.
fn circles(files: &[(ModPath, String)]) -> Vec<String> {
    let modules: BTreeSet<ModPath> = files.iter().map(|(m, _)| m.clone()).collect();
    let uses: Vec<(&ModPath, Vec<Use>)> = files.iter().map(|(m, t)| (m, paths(&code(t)))).collect();
    let mut re = Reexports::new();
    for (me, list) in &uses {
        for u in list.iter().filter(|u| u.public) {
            let Some(to) = absolute(me, &u.path, &modules) else {
                continue;
            };
            let Some(name) = u.alias.clone().or_else(|| to.last().cloned()) else {
                continue;
            };
            if name != "*" && name != "self" {
                re.entry((*me).clone()).or_default().insert(name, to);
            }
        }
    }
    // Edges among the children of each parent.
    let mut graphs: BTreeMap<ModPath, BTreeMap<String, BTreeSet<String>>> = BTreeMap::new();
    for (me, list) in &uses {
        let me: &ModPath = me;
        for u in list {
            let Some(to) = absolute(me, &u.path, &modules) else {
                continue;
            };
            let t = resolve(&to, &modules, &re, 16);
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
    // Through a re-export of the parent: `crate::Thing` is `b`'s.
    let reexported = [
        file(&[], "mod a;\nmod b;\npub use b::{Thing as Thing, Other};\n"),
        file(&["a"], "fn f(_: crate::Thing) {}\n"),
        file(&["b"], "pub(crate) use super::a::g;\npub struct Thing;\n"),
    ];
    assert_eq!(circles(&reexported), vec!["the crate root: a ↔ b"]);
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
