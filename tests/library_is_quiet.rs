//! The library never prints: only the CLI (and examples and tests) write to
//! stdout or stderr. A scan of the library sources for print macros.

mod common;

#[test]
fn no_library_crate_prints() {
    let mut offenders = Vec::new();
    let mut dirs = vec![
        common::root().join("crates"),
        common::root().join("plugin-api/src"),
    ];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            let rel = path
                .strip_prefix(common::root())
                .unwrap()
                .to_string_lossy()
                .to_string();
            if path.is_dir() {
                // The CLI prints by design; examples and tests may.
                if !(rel.contains("thinwall-cli")
                    || rel.ends_with("examples")
                    || rel.ends_with("tests"))
                {
                    dirs.push(path);
                }
                continue;
            }
            if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).unwrap();
                // Unit tests at the end of a file may print.
                // Doc comments (examples for callers) are not code that runs.
                let code: String = text
                    .split("#[cfg(test)]")
                    .next()
                    .unwrap_or("")
                    .lines()
                    .filter(|l| !l.trim_start().starts_with("//"))
                    .collect::<Vec<_>>()
                    .join("\n");
                for mac in ["println!", "eprintln!", "print!(", "eprint!(", "dbg!("] {
                    if code.contains(mac) {
                        offenders.push(format!("{rel}: {mac}"));
                    }
                }
            }
        }
    }
    assert!(offenders.is_empty(), "{offenders:?}");
}
