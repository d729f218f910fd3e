//! The programs a user runs, built as `cargo build` builds them: the window (`raytracer`) and the
//! frame command (the example `frame`). They belong to the root package, not to this one, so Cargo
//! does not build them for these tests: the first test that needs them builds them, once a test
//! program, in the profile and target directory the tests were built in.
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// Where the two built programs are.
pub struct Built {
    pub raytracer: PathBuf,
    pub frame: PathBuf,
}

/// Builds the program and the frame command, the first time, and says where they are. A build that
/// fails fails the test with what Cargo said.
pub fn built() -> &'static Built {
    static BUILT: OnceLock<Built> = OnceLock::new();
    BUILT.get_or_init(|| {
        // This test program is <target>/<profile>/deps/NAME-HASH.
        let test = std::env::current_exe().expect("the test program's own path");
        let profile = test
            .parent()
            .and_then(Path::parent)
            .expect("the test program in <target>/<profile>/deps");
        let target = profile.parent().expect("the profile's folder in <target>");
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../.."); // tests/maintainers
        let mut cargo = Command::new(env!("CARGO"));
        cargo
            .args(["build", "--bin", "raytracer", "--example", "frame"])
            .arg("--manifest-path")
            .arg(root.join("Cargo.toml"))
            .arg("--target-dir")
            .arg(target);
        match profile.file_name().and_then(|name| name.to_str()) {
            Some("debug") => {}
            Some("release") => {
                cargo.arg("--release");
            }
            Some(other) => {
                cargo.args(["--profile", other]);
            }
            None => panic!("the test program's profile folder has no name: {test:?}"),
        }
        let output = cargo.output().unwrap_or_else(|error| {
            panic!("the tests could not start Cargo to build the program: {error}")
        });
        assert!(
            output.status.success(),
            "these tests run the program and the frame command, but `cargo build --bin raytracer \
             --example frame` failed ({}); Cargo said:\n{}",
            output.status,
            String::from_utf8_lossy(&output.stderr)
        );
        Built {
            raytracer: profile.join("raytracer"),
            frame: profile.join("examples").join("frame"),
        }
    })
}
