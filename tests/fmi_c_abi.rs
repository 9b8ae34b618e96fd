//! The C ABI as a C host sees it: tests/c_host/host.c, compiled with gcc against fmi_headers/ and
//! linked with the built cdylib, runs instantiate / setup / initialize / 50 steps with a state
//! restore / free, compares with a straight run, and tries a few misuses that must be refused.

use pistonslap::fmi::description::{GUID, VARIABLES};
use std::path::PathBuf;
use std::process::Command;

fn vr(name: &str) -> String {
    VARIABLES
        .iter()
        .position(|v| v.name == name)
        .expect(name)
        .to_string()
}

#[test]
fn a_c_host_runs_one_cycle() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    // The test binary lives in <target>/<profile>/deps, the cdylib in <target>/<profile>. `cargo test`
    // does not link the cdylib, so build it (a no-op when fresh) with this test's profile.
    let exe = std::env::current_exe().unwrap();
    let lib_dir = exe
        .parent()
        .and_then(|deps| deps.parent())
        .unwrap()
        .to_path_buf();
    let profile = if lib_dir.ends_with("release") {
        "release"
    } else {
        "dev"
    };
    let built = Command::new(env!("CARGO"))
        .args(["build", "--lib", "--profile", profile])
        .current_dir(&root)
        .status()
        .expect("cargo");
    assert!(
        built.success() && lib_dir.join("libpistonslap.so").is_file(),
        "no cdylib in {}",
        lib_dir.display()
    );
    let host = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("c_host");
    let compiled = Command::new("gcc")
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-o"])
        .arg(&host)
        .arg(root.join("tests/c_host/host.c"))
        .arg("-I")
        .arg(root.join("fmi_headers"))
        .arg(format!("-L{}", lib_dir.display()))
        .arg(format!("-Wl,-rpath,{}", lib_dir.display()))
        .arg("-lpistonslap")
        .status()
        .expect("gcc");
    assert!(compiled.success(), "gcc failed");

    let out = Command::new(&host)
        .args([
            GUID.to_string(),
            vr("crank_angle"),
            vr("impact_count"),
            vr("crank_speed"),
        ])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "host exited {:?}\n{stdout}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    let field = |name: &str| -> f64 {
        let item = stdout
            .split_whitespace()
            .find_map(|w| w.strip_prefix(&format!("{name}=")))
            .expect(name);
        item.parse().unwrap()
    };
    // Prescribed speed 125.66 rad/s from crank angle 0 for 0.05 s.
    assert!(
        (field("crank_angle") - 125.66 * 0.05).abs() < 1e-9,
        "{stdout}"
    );
    // The run with a restore ends exactly where the straight run does, impacts included.
    assert_eq!(field("crank_angle"), field("straight_crank_angle"), "{stdout}");
    assert_eq!(field("impact_count"), field("straight_impact_count"), "{stdout}");
    assert!(field("impact_count") > 0.0, "the default engine slaps within 50 ms: {stdout}");
    assert_eq!(field("errors"), 3.0, "{stdout}");
    // The wrong GUID and the three refused calls each logged a message.
    assert_eq!(field("logged"), 4.0, "{stdout}");
}
