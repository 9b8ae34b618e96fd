//! How the FMU's x86-64-v3 build (see `fmi::sibling`) is made: this crate again, release profile,
//! `-C target-cpu=x86-64-v3`, in a target directory of its own. `package_fmu`, the C-host test and
//! the benchmark all build it here, so they build it alike.

use std::path::{Path, PathBuf};
use std::process::Command;

/// Builds the x86-64-v3 library under `<target_dir>/x86-64-v3` (a no-op when it is fresh) and
/// returns its path.
pub fn build_sibling(target_dir: &Path) -> Result<PathBuf, String> {
    if !cfg!(target_arch = "x86_64") {
        return Err("the x86-64-v3 build is made on x86-64 machines only".into());
    }
    let triple = env!("PISTONSLAP_TARGET");
    let dir = target_dir.join("x86-64-v3");
    // With an explicit --target the flag reaches the library only, not build.rs, which runs here.
    let status = Command::new(env!("CARGO"))
        .args(["build", "--release", "--lib", "--target", triple, "--target-dir"])
        .arg(&dir)
        .env("CARGO_ENCODED_RUSTFLAGS", "-Ctarget-cpu=x86-64-v3")
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .status()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    let library = dir.join(triple).join("release").join("libpistonslap.so");
    if status.success() && library.is_file() {
        Ok(library)
    } else {
        Err(format!("cargo did not build {}", library.display()))
    }
}
