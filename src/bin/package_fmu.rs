//! Packs the FMUs: `cargo run --release --bin package_fmu [-- [--linux64 <.so>] [--win64 <.dll>] [--out <directory>]]`.
//!
//! Defaults: the linux64 cdylib next to this executable (the same cargo profile directory), no win64 binary,
//! and `<target>/fmu/`. The one binary of each platform serves every FMU of the registry
//! (`pistonslap::fmus::PACKAGES`), each FMU's copy stamped with its name (`pistonslap::fmi::identity`) so that
//! it refuses the other FMUs' GUIDs. Each `<name>.fmu` holds its `modelDescription.xml` and its documentation's
//! variable table, both generated from `modelDescription/<fmu>.xml`, the files its room lists (PistonSlap's
//! geometry sketch and `resources/`), and the binaries as `binaries/<platform>/<name>.{so,dll}`.

use pistonslap::fmi::identity::stamp;
use pistonslap::fmi::{Causality, Kind, Variable};
use pistonslap::fmus::PACKAGES;
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};
use zip::write::SimpleFileOptions;
use zip::CompressionMethod;

fn main() {
    if let Err(e) = run() {
        eprintln!("package_fmu: {e}");
        std::process::exit(1);
    }
}

/// A platform's folder under `binaries/` (FMI 2.0 §2.4) and its shared-library extension.
const PLATFORMS: [(&str, &str, &str); 2] = [("--linux64", "linux64", "so"), ("--win64", "win64", "dll")];

fn run() -> Result<(), String> {
    let here = std::env::current_exe().map_err(|e| e.to_string())?;
    let profile_dir = here.parent().ok_or("no executable directory")?.to_path_buf();
    let target_dir = profile_dir.parent().unwrap_or(&profile_dir);
    let mut libraries: Vec<(usize, PathBuf)> = vec![(0, profile_dir.join("libpistonslap.so"))];
    let mut out_dir = target_dir.join("fmu");
    let mut args = std::env::args_os().skip(1);
    while let Some(flag) = args.next() {
        let value = args.next().map(PathBuf::from).ok_or_else(|| format!("{} needs a path", flag.to_string_lossy()))?;
        match PLATFORMS.iter().position(|p| flag == p.0) {
            Some(platform) => {
                libraries.retain(|(p, _)| *p != platform);
                libraries.push((platform, value));
            }
            None if flag == "--out" => out_dir = value,
            None => return Err(format!("unknown option {}: --linux64, --win64 or --out", flag.to_string_lossy())),
        }
    }
    let binaries = libraries
        .iter()
        .map(|(platform, path)| {
            std::fs::read(path)
                .map(|bytes| (PLATFORMS[*platform], bytes))
                .map_err(|e| format!("cannot read {} ({e}); run `make fmu`", path.display()))
        })
        .collect::<Result<Vec<_>, _>>()?;
    std::fs::create_dir_all(&out_dir).map_err(|e| format!("cannot create {}: {e}", out_dir.display()))?;
    let platforms: Vec<&str> = binaries.iter().map(|((_, folder, _), _)| *folder).collect();
    for package in PACKAGES {
        let documentation = documentation(package.documentation, package.variables);
        let mut entries: Vec<(String, Vec<u8>, bool)> = vec![
            ("modelDescription.xml".into(), package.model_description_xml.as_bytes().to_vec(), false),
            ("documentation/index.html".into(), documentation.into_bytes(), false),
        ];
        entries.extend(package.files.iter().map(|&(path, bytes)| (path.to_string(), bytes.to_vec(), false)));
        // The FMU's copies of the binaries, stamped with its name.
        for ((_, folder, ext), bytes) in &binaries {
            let mut copy = bytes.clone();
            stamp(&mut copy, package.name).map_err(|e| format!("the {folder} binary: {e}"))?;
            entries.push((format!("binaries/{folder}/{}.{ext}", package.name), copy, true));
        }
        let out = out_dir.join(format!("{}.fmu", package.name));
        write_fmu(&out, &entries).map_err(|e| format!("cannot write {}: {e}", out.display()))?;
        println!("wrote {} ({} variables, binaries {})", out.display(), package.variables.len(), platforms.join(" and "));
    }
    Ok(())
}

/// The archive of `files`: (name in the archive, bytes, executable).
fn write_fmu(out: &Path, files: &[(String, Vec<u8>, bool)]) -> zip::result::ZipResult<()> {
    let mut zip = zip::ZipWriter::new(File::create(out)?);
    let text = SimpleFileOptions::default().compression_method(CompressionMethod::Deflated);
    for (name, bytes, executable) in files {
        zip.start_file(name.as_str(), if *executable { text.unix_permissions(0o755) } else { text })?;
        zip.write_all(bytes)?;
    }
    zip.finish()?;
    Ok(())
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// documentation/index.html of `template`: what the model is, its conventions, its variables (from the same
/// table as the XML), its assumptions and references.
fn documentation(template: &str, variables: &[Variable]) -> String {
    let mut rows = String::new();
    for (vr, v) in variables.iter().enumerate() {
        let causality = match v.causality {
            Causality::Input => "input",
            Causality::Output => "output",
            Causality::Parameter => "parameter",
        };
        let kind = match v.kind {
            Kind::Real => "Real",
            Kind::Integer => "Integer",
            Kind::String => "String",
        };
        rows.push_str(&format!(
            "<tr><td><code>{}</code></td><td>{vr}</td><td>{causality}</td><td>{kind}</td><td>{}</td>\
             <td>{}</td><td>{}</td></tr>\n",
            escape(v.name),
            escape(v.unit),
            escape(v.start),
            escape(v.description)
        ));
    }
    template.replace("{{version}}", env!("CARGO_PKG_VERSION")).replace("{{variables}}", &rows)
}
