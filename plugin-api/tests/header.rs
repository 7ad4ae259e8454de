//! The committed header `include/thinwall.h` is what cbindgen generates
//! from the sources now, with version macros from Cargo.toml; the pkg-config
//! file carries the same version. Regenerate with
//! `UPDATE_HEADER=1 cargo test -p thinwall-capi --test header`.

use std::path::PathBuf;

fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn version_macros() -> String {
    format!(
        "\n#define THINWALL_VERSION_MAJOR {}\n#define THINWALL_VERSION_MINOR {}\n#define THINWALL_VERSION_PATCH {}\n#define THINWALL_VERSION \"{}\"\n",
        env!("CARGO_PKG_VERSION_MAJOR"),
        env!("CARGO_PKG_VERSION_MINOR"),
        env!("CARGO_PKG_VERSION_PATCH"),
        env!("CARGO_PKG_VERSION")
    )
}

fn generate() -> String {
    let mut config =
        cbindgen::Config::from_file(crate_dir().join("cbindgen.toml")).expect("cbindgen.toml");
    config.after_includes = Some(version_macros());
    let bindings = cbindgen::Builder::new()
        .with_crate(crate_dir())
        .with_config(config)
        .generate()
        .expect("cbindgen");
    let mut out = Vec::new();
    bindings.write(&mut out);
    String::from_utf8(out).expect("utf-8")
}

#[test]
fn committed_header_is_current() {
    let path = crate_dir().join("include/thinwall.h");
    let generated = generate();
    if std::env::var_os("UPDATE_HEADER").is_some() {
        std::fs::write(&path, &generated).unwrap();
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "include/thinwall.h is stale: run `UPDATE_HEADER=1 cargo test -p thinwall-capi --test header`"
    );
    for name in [
        "tw_version",
        "tw_last_error_message",
        "tw_part_load_file",
        "tw_part_load_memory",
        "tw_part_free",
        "tw_options_new",
        "tw_options_set_up",
        "tw_options_free",
        "tw_recognize",
        "tw_result_free",
        "tw_result_to_json",
        "tw_string_free",
        "tw_result_feature_count",
        "tw_result_feature_kind",
        "TW_OK",
    ] {
        assert!(committed.contains(name), "{name} missing from the header");
    }
}

#[test]
fn version_macros_and_pkg_config_match_cargo() {
    let header = std::fs::read_to_string(crate_dir().join("include/thinwall.h")).unwrap();
    assert!(header.contains(&format!(
        "#define THINWALL_VERSION \"{}\"",
        env!("CARGO_PKG_VERSION")
    )));
    assert!(header.contains(&format!(
        "#define THINWALL_VERSION_MAJOR {}",
        env!("CARGO_PKG_VERSION_MAJOR")
    )));
    let pc = std::fs::read_to_string(crate_dir().join("thinwall.pc")).unwrap();
    assert!(
        pc.lines()
            .any(|l| l == format!("Version: {}", env!("CARGO_PKG_VERSION"))),
        "{pc}"
    );
    assert!(pc.contains("-lthinwall"));
}
