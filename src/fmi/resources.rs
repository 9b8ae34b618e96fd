//! The FMU's `resources/` directory, from fmi2Instantiate's `fmuResourceLocation` (a file URI), and the
//! lookup of bare file names in it.

use std::path::{Path, PathBuf};

/// The local directory a `file:` URI names (`file:///dir`, `file:/dir`, `file://localhost/dir`),
/// percent-escapes decoded; None for another scheme, a remote host or a bad escape.
pub fn directory(uri: &str) -> Option<PathBuf> {
    let rest = uri.strip_prefix("file:")?;
    let path = match rest.strip_prefix("//") {
        Some(authority_and_path) => {
            let slash = authority_and_path.find('/')?;
            let (host, path) = authority_and_path.split_at(slash);
            if !(host.is_empty() || host == "localhost") {
                return None;
            }
            path
        }
        None => rest,
    };
    let mut bytes = Vec::with_capacity(path.len());
    let mut iter = path.bytes();
    while let Some(b) = iter.next() {
        if b == b'%' {
            let hex = [iter.next()?, iter.next()?];
            bytes.push(u8::from_str_radix(std::str::from_utf8(&hex).ok()?, 16).ok()?);
        } else {
            bytes.push(b);
        }
    }
    Some(PathBuf::from(String::from_utf8(bytes).ok()?))
}

/// `name` as a path to open: a bare file name (no directory part) from the working directory when a
/// file there has it, else from `resources`; anything else as given.
pub fn resolve(name: &str, resources: Option<&Path>) -> String {
    match resources {
        Some(dir) if !name.is_empty() && !name.contains('/') && !Path::new(name).is_file() => dir.join(name).to_string_lossy().into_owned(),
        _ => name.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_uris_name_local_directories() {
        assert_eq!(directory("file:///tmp/a%20b/resources"), Some(PathBuf::from("/tmp/a b/resources")));
        assert_eq!(directory("file:/tmp/r"), Some(PathBuf::from("/tmp/r")));
        assert_eq!(directory("file://localhost/tmp/r/"), Some(PathBuf::from("/tmp/r/")));
        assert_eq!(directory("file://server/share"), None);
        assert_eq!(directory("http://x/y"), None);
        assert_eq!(directory("file:///bad%2"), None);
    }

    #[test]
    fn bare_names_are_looked_up_in_the_working_directory_then_the_resources() {
        let dir = Path::new("/fmu/resources");
        // cargo runs the tests in the crate's directory
        assert_eq!(resolve("Cargo.toml", Some(dir)), "Cargo.toml");
        assert_eq!(resolve("full_load.csv", Some(dir)), "/fmu/resources/full_load.csv");
        assert_eq!(resolve("./mine.csv", Some(dir)), "./mine.csv");
        assert_eq!(resolve("/data/mine.csv", Some(dir)), "/data/mine.csv");
        assert_eq!(resolve("", Some(dir)), "");
        assert_eq!(resolve("full_load.csv", None), "full_load.csv");
    }
}
