//! The FMU's `resources/` directory, from fmi2Instantiate's `fmuResourceLocation` (a `file:` URI, RFC 8089),
//! and the lookup of bare file names in it.

use std::path::{Path, PathBuf};

/// How the platform spells a local path: Windows has drive letters and UNC shares, POSIX one root.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PathStyle {
    Posix,
    Windows,
}

impl PathStyle {
    /// The style of the platform this binary runs on.
    pub const NATIVE: PathStyle = if cfg!(windows) { PathStyle::Windows } else { PathStyle::Posix };
}

/// The local directory a `file:` URI names on this platform (see [`local_path`]).
pub fn directory(uri: &str) -> Option<PathBuf> {
    local_path(uri, PathStyle::NATIVE).map(PathBuf::from)
}

/// The local path a `file:` URI names, percent-escapes decoded (RFC 8089 and its Appendix E forms):
/// `file:///dir`, `file:/dir`, `file://localhost/dir`; with Windows style also `file:///C:/dir`,
/// `file:/C:/dir`, `file:C:/dir` and the legacy `file:///C|/dir` (→ `C:\dir`), and a share as
/// `file://host/share/dir` or `file:////host/share/dir` (→ `\\host\share\dir`). None for another scheme,
/// a bad escape, or a remote host on POSIX, where no local path reaches it.
pub fn local_path(uri: &str, style: PathStyle) -> Option<String> {
    let rest = uri.get(..5).filter(|scheme| scheme.eq_ignore_ascii_case("file:")).map(|_| &uri[5..])?;
    let (host, path) = match rest.strip_prefix("//") {
        Some(authority_and_path) => {
            let slash = authority_and_path.find('/').unwrap_or(authority_and_path.len());
            let (host, path) = authority_and_path.split_at(slash);
            (decode(host)?, decode(path)?)
        }
        None => (String::new(), decode(rest)?),
    };
    let local_host = host.is_empty() || host.eq_ignore_ascii_case("localhost");
    match style {
        PathStyle::Posix => local_host.then_some(path),
        PathStyle::Windows if !local_host => Some(format!(r"\\{host}{}", path.replace('/', r"\"))),
        PathStyle::Windows => {
            let path = path.replace('/', r"\");
            Some(match drive_path(&path) {
                Some(drive) => drive,
                None => path,
            })
        }
    }
}

/// A Windows path with its drive letter: `\C:\dir`, `C:\dir` or the legacy `\C|\dir` become `C:\dir`;
/// `\\host\share` (a UNC path carried whole in the URI's path) stays as it is, anything else None.
fn drive_path(path: &str) -> Option<String> {
    let bare = path.strip_prefix('\\').unwrap_or(path);
    let bytes = bare.as_bytes();
    let is_drive =
        bytes.len() >= 2 && bytes[0].is_ascii_alphabetic() && matches!(bytes[1], b':' | b'|') && (bytes.len() == 2 || bytes[2] == b'\\');
    is_drive.then(|| format!("{}:{}", &bare[..1], &bare[2..]))
}

/// `text` with its `%XX` escapes decoded; None for a bad escape or bytes that are not UTF-8.
fn decode(text: &str) -> Option<String> {
    let mut bytes = Vec::with_capacity(text.len());
    let mut iter = text.bytes();
    while let Some(b) = iter.next() {
        if b == b'%' {
            let hex = [iter.next()?, iter.next()?];
            bytes.push(u8::from_str_radix(std::str::from_utf8(&hex).ok()?, 16).ok()?);
        } else {
            bytes.push(b);
        }
    }
    String::from_utf8(bytes).ok()
}

/// `name` as a path to open: a bare file name (no directory part) in `resources`, anything else as given.
pub fn resolve(name: &str, resources: Option<&Path>) -> String {
    match resources {
        Some(dir) if !name.is_empty() && !name.contains(['/', '\\']) => dir.join(name).to_string_lossy().into_owned(),
        _ => name.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::PathStyle::{Posix, Windows};
    use super::*;

    #[test]
    fn posix_file_uris_name_local_directories() {
        let posix = |uri| local_path(uri, Posix);
        assert_eq!(posix("file:///tmp/a%20b/resources").as_deref(), Some("/tmp/a b/resources"));
        assert_eq!(posix("file:/tmp/r").as_deref(), Some("/tmp/r"));
        assert_eq!(posix("file://localhost/tmp/r/").as_deref(), Some("/tmp/r/"));
        assert_eq!(posix("FILE:///tmp/%C3%BC").as_deref(), Some("/tmp/ü"));
        assert_eq!(posix("file://server/share"), None);
        assert_eq!(posix("http://x/y"), None);
        assert_eq!(posix("file:///bad%2"), None);
        assert_eq!(posix("file:///bad%zz"), None);
    }

    /// The forms Windows hosts pass: fmpy and FMPy-based tools `file:///C:/...`, older tools `file:/C:/...`,
    /// a share when the FMU is unpacked on a network drive.
    #[test]
    fn windows_file_uris_name_drives_and_shares() {
        let windows = |uri| local_path(uri, Windows);
        assert_eq!(
            windows("file:///C:/Users/a%20b/AppData/Local/Temp/tmpx/resources").as_deref(),
            Some(r"C:\Users\a b\AppData\Local\Temp\tmpx\resources")
        );
        assert_eq!(windows("file:/D:/fmu/resources/").as_deref(), Some(r"D:\fmu\resources\"));
        assert_eq!(windows("file:C:/fmu").as_deref(), Some(r"C:\fmu"));
        assert_eq!(windows("file://localhost/c:/fmu").as_deref(), Some(r"c:\fmu"));
        assert_eq!(windows("file:///C|/fmu").as_deref(), Some(r"C:\fmu"));
        assert_eq!(windows("file:///C%3A/fmu").as_deref(), Some(r"C:\fmu"));
        assert_eq!(windows("file:///C:").as_deref(), Some("C:"));
        assert_eq!(windows("file://server/share/fmu/resources").as_deref(), Some(r"\\server\share\fmu\resources"));
        assert_eq!(windows("file:////server/share/fmu").as_deref(), Some(r"\\server\share\fmu"));
        assert_eq!(windows("file:///bad%2"), None);
        assert_eq!(windows("https://server/share"), None);
    }

    #[test]
    fn bare_names_are_looked_up_in_the_resources() {
        let dir = Path::new("/fmu/resources");
        assert_eq!(resolve("full_load.csv", Some(dir)), "/fmu/resources/full_load.csv");
        assert_eq!(resolve("./mine.csv", Some(dir)), "./mine.csv");
        assert_eq!(resolve(r"C:\data\mine.csv", Some(dir)), r"C:\data\mine.csv");
        assert_eq!(resolve("/data/mine.csv", Some(dir)), "/data/mine.csv");
        assert_eq!(resolve("", Some(dir)), "");
        assert_eq!(resolve("full_load.csv", None), "full_load.csv");
    }
}
