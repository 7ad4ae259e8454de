//! The workspace tests read third-party parts from `../shared/data` (beside
//! the checkout; never copied into the repository). Without them the test
//! command stops here with one message saying so, instead of a panic in
//! every test that opens one.

fn main() {
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/data");
    println!("cargo:rerun-if-changed={}", data.display());
    if !data.join("nist").is_dir() {
        eprintln!(
            "\nThinwall's tests need the shared third-party STEP parts in {}\n\
             (folders nist/, thinwall/, mfcad/, mfcadpp_gen/, mfinstseg/; see README.md,\n\
             \"Prerequisites\"). Put them there, or run one crate's own tests with\n\
             `cargo test -p <crate>`.\n",
            data.display()
        );
        std::process::exit(1);
    }
}
