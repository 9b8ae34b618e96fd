//! The FMU carries two builds of this library: the portable one (baseline x86-64), which hosts load
//! as `PistonSlap.so`, and one for x86-64-v3 CPUs (AVX2, BMI2, FMA: Intel since 2013, AMD since
//! 2015), [`FILE_NAME`] beside it, ≈ 1.15× as fast. Their results are bit-identical: the wider
//! instructions do the same arithmetic, as Rust never fuses a multiply and an add on its own.
//!
//! At its first call the portable build checks the CPU and, where the sibling can run, loads it and
//! hands it every call for the life of the process (instances and FMU states belong to the build that
//! made them, so the choice is never revisited). `PISTONSLAP_BUILD=x86-64` in the environment keeps
//! the portable build. Each instance says which build runs it in the log category `logBuild`.

use super::exports::{symbol, Functions};
use std::ffi::{c_char, c_void, CStr, CString, OsStr};
use std::os::unix::ffi::OsStrExt;
use std::path::Path;
use std::sync::OnceLock;

/// The sibling's file name, in the FMU's `binaries/linux64/`.
pub const FILE_NAME: &str = "PistonSlap.x86-64-v3.so";

/// The environment variable that keeps the portable build when set to `x86-64`.
pub const CHOICE_VARIABLE: &str = "PISTONSLAP_BUILD";

const PORTABLE: &CStr = c"x86-64";
const WIDE: &CStr = c"x86-64-v3";

/// Which build this library is.
const THIS_BUILD: &CStr = if cfg!(target_feature = "avx2") { WIDE } else { PORTABLE };

/// This build's name, for the portable build to check that the file it opened is the sibling (and
/// not, say, a renamed copy of itself, which would forward every call to itself).
#[no_mangle]
pub extern "C" fn pistonslap_build() -> *const c_char {
    THIS_BUILD.as_ptr()
}

/// The sibling's functions when it runs this process's calls; `None` when this build does.
pub fn functions() -> Option<&'static Functions> {
    choice().as_ref().ok()
}

/// The `logBuild` message of an instance made by this build.
pub fn description() -> String {
    match choice() {
        _ if THIS_BUILD == WIDE => "x86-64-v3 build (AVX2, FMA), chosen for this CPU".into(),
        Err(reason) => format!("portable x86-64 build: {reason}"),
        Ok(_) => "portable x86-64 build, called directly while the x86-64-v3 build runs the exported functions".into(),
    }
}

fn choice() -> &'static Result<Functions, String> {
    static CHOICE: OnceLock<Result<Functions, String>> = OnceLock::new();
    // SAFETY: `load` only reads what dladdr/dlopen/dlsym return, each checked for null.
    CHOICE.get_or_init(|| unsafe { load() })
}

unsafe fn load() -> Result<Functions, String> {
    if THIS_BUILD == WIDE {
        return Err("this is the x86-64-v3 build".into());
    }
    if std::env::var_os(CHOICE_VARIABLE).is_some_and(|v| v.as_bytes() == PORTABLE.to_bytes()) {
        return Err(format!("{CHOICE_VARIABLE}=x86-64 is set"));
    }
    if let Some(missing) = missing_cpu_feature() {
        return Err(format!("this CPU lacks {missing}, which the x86-64-v3 build needs"));
    }
    let mut own: libc::Dl_info = std::mem::zeroed();
    if libc::dladdr(load as *const c_void, &mut own) == 0 || own.dli_fname.is_null() {
        return Err("the path of this library is unknown (dladdr)".into());
    }
    open(&Path::new(OsStr::from_bytes(CStr::from_ptr(own.dli_fname).to_bytes())).with_file_name(FILE_NAME))
}

/// The functions of the x86-64-v3 build at `path`, loaded for good. Also for a host that measures that
/// build directly (the benchmark).
///
/// # Safety
/// Only on a CPU with the x86-64-v3 features ([`missing_cpu_feature`] is `None`).
pub unsafe fn open(path: &Path) -> Result<Functions, String> {
    let c_path = CString::new(path.as_os_str().as_bytes()).map_err(|e| e.to_string())?;
    let library = libc::dlopen(c_path.as_ptr(), libc::RTLD_NOW | libc::RTLD_LOCAL);
    if library.is_null() {
        let reason = libc::dlerror();
        let reason = if reason.is_null() { "".into() } else { CStr::from_ptr(reason).to_string_lossy() };
        return Err(format!("{} could not be loaded ({reason})", path.display()));
    }
    let build = symbol(library, "pistonslap_build\0")
        .map(|f| CStr::from_ptr(std::mem::transmute::<*mut c_void, extern "C" fn() -> *const c_char>(f)()));
    match build {
        Some(name) if name == WIDE => Functions::load(library).ok_or_else(|| format!("{} lacks an fmi2 function", path.display())),
        _ => {
            libc::dlclose(library);
            Err(format!("{} is not the x86-64-v3 build", path.display()))
        }
    }
}

/// The first x86-64-v3 feature this CPU lacks (the list is rustc's for `-C target-cpu=x86-64-v3`
/// beyond the baseline).
pub fn missing_cpu_feature() -> Option<&'static str> {
    #[cfg(target_arch = "x86_64")]
    {
        macro_rules! first_missing {
            ($($feature:tt),*) => {
                [$(($feature, std::arch::is_x86_feature_detected!($feature))),*]
                    .into_iter()
                    .find_map(|(name, present)| (!present).then_some(name))
            };
        }
        first_missing!(
            "avx", "avx2", "bmi1", "bmi2", "cmpxchg16b", "f16c", "fma", "lzcnt", "movbe", "popcnt",
            "sse3", "sse4.1", "sse4.2", "ssse3", "xsave"
        )
    }
    #[cfg(not(target_arch = "x86_64"))]
    Some("the x86-64 architecture")
}
