//! The C ABI as a C host sees it: tests/c_host/host.c, compiled with gcc against fmi_headers/ and
//! linked with the built cdylib, runs instantiate / setup / initialize / 50 steps with a state
//! restore / free, compares with a straight run, and tries a few misuses that must be refused. Under valgrind's
//! memcheck it repeats short instantiate / step / FMU-state / free cycles, which must leak nothing
//! and touch no invalid memory.

use crate::common::fmu_host::vr;
use pistonslap::fmus::piston_slap::GUID;
use std::path::PathBuf;
use std::process::{Command, Output};
use std::sync::OnceLock;

/// The compiled C host, built once per test binary.
fn c_host() -> &'static PathBuf {
    static HOST: OnceLock<PathBuf> = OnceLock::new();
    HOST.get_or_init(|| {
        let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        // The test binary lives in <target>/<profile>/deps, the cdylib in <target>/<profile>. `cargo test`
        // does not link the cdylib, so build it (a no-op when fresh) with this test's profile.
        let exe = std::env::current_exe().unwrap();
        let lib_dir = exe.parent().and_then(|deps| deps.parent()).unwrap().to_path_buf();
        let built =
            Command::new(env!("CARGO")).args(["build", "--lib", "--profile", profile()]).current_dir(&root).status().expect("cargo");
        assert!(built.success() && lib_dir.join("libpistonslap.so").is_file(), "no cdylib in {}", lib_dir.display());
        let tmp = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
        let libs = tmp.join("c_host_libs");
        std::fs::create_dir_all(&libs).unwrap();
        std::fs::copy(lib_dir.join("libpistonslap.so"), libs.join("libpistonslap.so")).unwrap();
        let host = tmp.join("c_host");
        let compiled = Command::new("gcc")
            .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-g", "-o"])
            .arg(&host)
            .arg(root.join("tests/c_host/host.c"))
            .arg("-I")
            .arg(root.join("fmi_headers"))
            .arg(format!("-L{}", libs.display()))
            // DT_RPATH, not RUNPATH: cargo's LD_LIBRARY_PATH (with target/<profile>) must not win.
            .arg(format!("-Wl,--disable-new-dtags,-rpath,{}", libs.display()))
            .arg("-lpistonslap")
            .status()
            .expect("gcc");
        assert!(compiled.success(), "gcc failed");
        host
    })
}

fn profile() -> &'static str {
    let exe = std::env::current_exe().unwrap();
    if exe.parent().and_then(|deps| deps.parent()).unwrap().ends_with("release") {
        "release"
    } else {
        "dev"
    }
}

/// The host's arguments for `cycles` cycles.
fn host_args(cycles: usize) -> Vec<String> {
    let names = ["crank_angle", "impact_count", "crank_speed"];
    [GUID.to_string()].into_iter().chain(names.map(|n| vr(n).to_string())).chain([cycles.to_string()]).collect()
}

/// Checks the host's report of its first, checked cycle.
fn check_report(out: &Output) {
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "host exited {:?}\n{stdout}\n{stderr}", out.status);
    let field = |name: &str| -> f64 {
        let item = stdout.split_whitespace().find_map(|w| w.strip_prefix(&format!("{name}="))).expect(name);
        item.parse().unwrap()
    };
    // Prescribed speed 125.66 rad/s from crank angle 0 for 0.05 s.
    assert!((field("crank_angle") - 125.66 * 0.05).abs() < 1e-9, "{stdout}");
    // The run with a restore ends exactly where the straight run does, impacts included.
    assert_eq!(field("crank_angle"), field("straight_crank_angle"), "{stdout}");
    assert_eq!(field("impact_count"), field("straight_impact_count"), "{stdout}");
    assert!(field("impact_count") > 0.0, "the default engine slaps within 50 ms: {stdout}");
    assert_eq!(field("errors"), 3.0, "{stdout}");
    // The wrong GUID and the three refused calls each logged a message; the straight run (logging
    // switched off after instantiation) and the short cycles log nothing.
    assert_eq!(field("logged"), 4.0, "{stdout}");
}

#[test]
fn a_c_host_runs_one_cycle() {
    check_report(&Command::new(c_host()).args(host_args(1)).output().unwrap());
}

/// 10⁴ cycles under memcheck. Only with an optimized build (`make test` runs `cargo test --release`):
/// the debug build under valgrind would take many minutes. Where valgrind was not found when the
/// crate was built, or in a debug build, the test is reported ignored.
#[test]
#[cfg_attr(not(valgrind), ignore = "valgrind not found (build.rs looks for it)")]
#[cfg_attr(debug_assertions, ignore = "memcheck runs with the release build only (cargo test --release)")]
fn ten_thousand_cycles_under_valgrind_leak_nothing() {
    let start = std::time::Instant::now();
    let out = Command::new("valgrind")
        .args(["--tool=memcheck", "--leak-check=full", "--show-leak-kinds=definite,indirect,possible"])
        .args(["--errors-for-leak-kinds=definite,indirect,possible", "--error-exitcode=1"])
        .arg(c_host())
        .args(host_args(10_000))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    let summary: Vec<&str> =
        stderr.lines().filter(|l| l.contains("ERROR SUMMARY") || l.contains("lost:") || l.contains("in use at exit")).collect();
    println!("memcheck of 10000 cycles in {:?}:\n{}", start.elapsed(), summary.join("\n"));
    check_report(&out);
    assert!(stderr.contains("ERROR SUMMARY: 0 errors"), "{stderr}");
}
