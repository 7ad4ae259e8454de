//! `docs/ARCHITECTURE.md` stays true, and the code keeps its shape:
//! - its dependency list names, for every crate, exactly the Thinwall
//!   crates its `Cargo.toml` depends on;
//! - its test index names every test file;
//! - no two source files of one crate refer to each other in a circle
//!   (`crate::a` / `super::a` paths, the crate root aside);
//! - no library function is longer than [`MAX_FUNCTION_LINES`] lines.

use petgraph::algo::tarjan_scc;
use petgraph::graph::DiGraph;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

mod common;

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// Every crate's manifest: `crates/*`, `plugin-api`, `python`.
fn manifests() -> Vec<PathBuf> {
    let root = common::root();
    let mut out: Vec<PathBuf> = std::fs::read_dir(root.join("crates"))
        .unwrap()
        .map(|e| e.unwrap().path().join("Cargo.toml"))
        .filter(|p| p.exists())
        .collect();
    out.push(root.join("plugin-api/Cargo.toml"));
    out.push(root.join("plugin-api/clib/Cargo.toml"));
    out.push(root.join("python/Cargo.toml"));
    out.sort();
    out
}

/// The crate's name and the Thinwall crates under its `[dependencies]`.
fn thinwall_dependencies(manifest: &Path) -> (String, BTreeSet<String>) {
    let text = read(manifest);
    let mut name = String::new();
    let mut deps = BTreeSet::new();
    let mut section = String::new();
    for line in text.lines().map(str::trim) {
        if line.starts_with('[') {
            section = line.to_string();
            continue;
        }
        if section == "[package]" && line.starts_with("name") && name.is_empty() {
            name = line.split('"').nth(1).unwrap_or_default().to_string();
        }
        if section == "[dependencies]" && line.starts_with("thinwall-") {
            let dep = line.split(['.', ' ', '=']).next().unwrap_or_default();
            deps.insert(dep.to_string());
        }
    }
    (name, deps)
}

/// `docs/ARCHITECTURE.md`'s dependency list: lines `` - `crate` ← `a`, `b` ``
/// between the markers.
fn documented_dependencies(doc: &str) -> BTreeMap<String, BTreeSet<String>> {
    let start = doc
        .find("<!-- dependencies -->")
        .expect("a dependency list");
    let end = doc.find("<!-- /dependencies -->").expect("its end");
    let mut out = BTreeMap::new();
    for line in doc[start..end].lines().filter(|l| l.starts_with("- `")) {
        let (name, rest) = line[3..].split_once('`').unwrap();
        let deps: BTreeSet<String> = rest
            .split('`')
            .skip(1)
            .step_by(2)
            .map(|s| s.to_string())
            .collect();
        out.insert(name.to_string(), deps);
    }
    out
}

#[test]
fn the_documented_dependencies_are_the_manifests() {
    let doc = read(&common::root().join("docs/ARCHITECTURE.md"));
    let documented = documented_dependencies(&doc);
    let actual: BTreeMap<String, BTreeSet<String>> = manifests()
        .iter()
        .map(|m| thinwall_dependencies(m))
        .collect();
    for (name, deps) in &actual {
        let doc_deps = documented
            .get(name)
            .unwrap_or_else(|| panic!("docs/ARCHITECTURE.md lists no dependencies of {name}"));
        assert_eq!(
            doc_deps, deps,
            "dependencies of {name}: documented vs Cargo.toml"
        );
    }
    for name in documented.keys() {
        assert!(
            actual.contains_key(name),
            "{name} is documented but is no crate"
        );
    }
}

#[test]
fn the_test_index_names_every_test_file() {
    let root = common::root();
    let doc = read(&root.join("docs/ARCHITECTURE.md"));
    let mut dirs = vec![root.join("tests"), root.join("plugin-api/tests")];
    for m in manifests() {
        dirs.push(m.parent().unwrap().join("tests"));
    }
    let mut missing = Vec::new();
    for dir in dirs.iter().filter(|d| d.is_dir()) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_some_and(|x| x == "rs") {
                let rel = p.strip_prefix(&root).unwrap().display().to_string();
                if !doc.contains(&rel) {
                    missing.push(rel);
                }
            }
        }
    }
    missing.sort();
    assert!(missing.is_empty(), "not in the test index: {missing:?}");
}

/// The `.rs` files under `src`.
fn sources(src: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![src.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// The module file a path of module names under `dir` leads to: the
/// longest prefix that is a file (`a/b.rs`, `a/b/mod.rs`).
fn module_file(dir: &Path, names: &[&str]) -> Option<PathBuf> {
    let mut found = None;
    let mut here = dir.to_path_buf();
    for n in names {
        let file = here.join(format!("{n}.rs"));
        let modrs = here.join(n).join("mod.rs");
        if file.exists() {
            found = Some(file);
        } else if modrs.exists() {
            found = Some(modrs);
        } else {
            break;
        }
        here = here.join(n);
    }
    found
}

/// The files a source refers to by `crate::…` and `super::…` paths
/// (inside `{…}` lists too).
fn references(src: &Path, file: &Path) -> BTreeSet<PathBuf> {
    let text = read(file);
    let parent = if file.ends_with("mod.rs") {
        file.parent().unwrap().parent().unwrap().to_path_buf()
    } else {
        file.parent().unwrap().to_path_buf()
    };
    let mut out = BTreeSet::new();
    for (prefix, base) in [("crate::", src.to_path_buf()), ("super::", parent)] {
        for (at, _) in text.match_indices(prefix) {
            let before = text[..at].chars().last();
            if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
                continue;
            }
            let rest = &text[at + prefix.len()..];
            let path: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':')
                .collect();
            let mut names: Vec<&str> = path.split("::").filter(|s| !s.is_empty()).collect();
            let mut heads = vec![];
            if rest[path.len()..].starts_with('{') {
                // crate::a::{b, c::d}: each head after the shared prefix.
                let list: String = rest[path.len() + 1..]
                    .chars()
                    .take_while(|&c| c != '}')
                    .collect();
                for item in list.split(',') {
                    let item = item.trim();
                    let head = item.split("::").next().unwrap_or("").to_string();
                    heads.push(head);
                }
            }
            if heads.is_empty() {
                if let Some(f) = module_file(&base, &names) {
                    out.insert(f);
                }
            } else {
                for h in &heads {
                    names.push(h);
                    if let Some(f) = module_file(&base, &names) {
                        out.insert(f);
                    }
                    names.pop();
                }
            }
        }
    }
    out.remove(file);
    out
}

#[test]
fn no_two_files_of_a_crate_refer_to_each_other_in_a_circle() {
    let mut circles = Vec::new();
    for m in manifests() {
        let src = m.parent().unwrap().join("src");
        let files: Vec<PathBuf> = sources(&src)
            .into_iter()
            .filter(|f| {
                !(f.ends_with("lib.rs") || f.ends_with("main.rs")) || f.parent() != Some(&src)
            })
            .collect();
        let mut g = DiGraph::<PathBuf, ()>::new();
        let nodes: BTreeMap<PathBuf, _> = files
            .iter()
            .map(|f| (f.clone(), g.add_node(f.clone())))
            .collect();
        for f in &files {
            for r in references(&src, f) {
                if let Some(&to) = nodes.get(&r) {
                    // A module's mod.rs declares its children: not a use.
                    if f.ends_with("mod.rs") && r.starts_with(f.parent().unwrap()) {
                        continue;
                    }
                    g.add_edge(nodes[f], to, ());
                }
            }
        }
        for scc in tarjan_scc(&g).into_iter().filter(|c| c.len() > 1) {
            let mut names: Vec<String> = scc
                .iter()
                .map(|&n| g[n].strip_prefix(&src).unwrap().display().to_string())
                .collect();
            names.sort();
            circles.push(format!(
                "{}: {}",
                m.parent().unwrap().file_name().unwrap().to_string_lossy(),
                names.join(" ↔ ")
            ));
        }
    }
    assert!(
        circles.is_empty(),
        "files in a circle:\n{}",
        circles.join("\n")
    );
}

/// The longest a library function may be, lines from its signature to its
/// closing brace (issue 36: a function read at once).
const MAX_FUNCTION_LINES: usize = 100;

/// The functions of a rustfmt-formatted source longer than the limit:
/// (first line, name, lines). A function ends at the first `}` at its own
/// indentation.
fn long_functions(text: &str) -> Vec<(usize, String, usize)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        let indent = line.len() - line.trim_start().len();
        let words: Vec<&str> = line.split_whitespace().collect();
        let at = words.iter().position(|w| *w == "fn");
        let is_fn = at.is_some_and(|k| {
            words[..k].iter().all(|w| {
                w.starts_with("pub") || ["const", "unsafe", "async", "extern", "\"C\""].contains(w)
            }) && words.len() > k + 1
        });
        if !is_fn {
            i += 1;
            continue;
        }
        // The body opens on the signature's last line; a declaration
        // without a body ends in `;`.
        let mut j = i;
        while j < lines.len()
            && !lines[j].trim_end().ends_with('{')
            && !lines[j].trim_end().ends_with(';')
        {
            j += 1;
        }
        if j == lines.len()
            || lines[j].trim_end().ends_with(';')
            || lines[j].trim_end().ends_with("{}")
        {
            i = j + 1;
            continue;
        }
        let close = format!("{}}}", " ".repeat(indent));
        let Some(end) = (j + 1..lines.len()).find(|&k| lines[k].trim_end() == close) else {
            i += 1;
            continue;
        };
        let name = words[at.unwrap() + 1]
            .split(['(', '<'])
            .next()
            .unwrap_or("")
            .to_string();
        if end - i + 1 > MAX_FUNCTION_LINES {
            out.push((i + 1, name, end - i + 1));
        }
        i = end + 1;
    }
    out
}

#[test]
fn the_long_function_check_finds_a_long_function() {
    let body = "    let x = 1;\n".repeat(MAX_FUNCTION_LINES);
    let text =
        format!("/// Doc.\npub fn long(a: u32) -> u32 {{\n{body}    x\n}}\n\nfn short() {{}}\n");
    assert_eq!(
        long_functions(&text),
        vec![(2, "long".to_string(), MAX_FUNCTION_LINES + 3)]
    );
    let text = format!(
        "fn ok() {{\n{}}}\n",
        "    a();\n".repeat(MAX_FUNCTION_LINES - 2)
    );
    assert!(long_functions(&text).is_empty());
}

#[test]
fn no_library_function_is_longer_than_the_limit() {
    let mut long = Vec::new();
    for m in manifests() {
        let src = m.parent().unwrap().join("src");
        for f in sources(&src) {
            for (line, name, n) in long_functions(&read(&f)) {
                let at = f
                    .strip_prefix(common::root())
                    .unwrap_or(&f)
                    .display()
                    .to_string();
                long.push(format!("{at}:{line} {name}: {n} lines"));
            }
        }
    }
    assert!(
        long.is_empty(),
        "functions over {MAX_FUNCTION_LINES} lines (split them into named steps):\n{}",
        long.join("\n")
    );
}
