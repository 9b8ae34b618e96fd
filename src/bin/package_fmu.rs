//! Packs the FMUs: `cargo run --release --bin package_fmu [-- [--linux64 <.so>] [--win64 <.dll>] [--out <directory>]]`.
//!
//! Defaults: the linux64 cdylib next to this executable (the same cargo profile directory), no win64 binary,
//! and `<target>/fmu/`. The one binary of each platform serves both FMUs, each FMU's copy stamped with its model
//! (`pistonslap::fmi::identity`) so that it refuses the other FMU's GUID:
//! - `PistonSlap.fmu`: `modelDescription.xml` and the documentation's variable table, both generated from
//!   `modelDescription/variables.xml`, the binaries as `binaries/<platform>/PistonSlap.{so,dll}`, and
//!   `resources/`;
//! - `EngineCycle.fmu`: its `modelDescription.xml` (from `modelDescription/variables_engine_cycle.xml`), its
//!   documentation (`documentation/engine_cycle.html` with the variable table) and the binaries as
//!   `binaries/<platform>/EngineCycle.{so,dll}`.

use pistonslap::fmi::description::{engine_cycle, Causality, Kind, Variable, MODEL_DESCRIPTION_XML, VARIABLES};
use pistonslap::fmi::identity::{stamp, Identity};
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
    let slap_documentation = documentation(DOCUMENTATION, &VARIABLES);
    let engine_documentation = documentation(ENGINE_DOCUMENTATION, &engine_cycle::VARIABLES);
    // Each model's copies of the binaries, stamped with its identity.
    let binaries_of = |model: &str, identity: Identity| -> Result<Vec<(String, Vec<u8>, bool)>, String> {
        binaries
            .iter()
            .map(|((_, folder, ext), bytes)| {
                let mut copy = bytes.clone();
                stamp(&mut copy, identity).map_err(|e| format!("the {folder} binary: {e}"))?;
                Ok((format!("binaries/{folder}/{model}.{ext}"), copy, true))
            })
            .collect()
    };
    let piston_slap_files: [(&str, &[u8]); 6] = [
        ("modelDescription.xml", MODEL_DESCRIPTION_XML.as_bytes()),
        ("documentation/index.html", slap_documentation.as_bytes()),
        ("documentation/geometry.svg", GEOMETRY_SVG.as_bytes()),
        ("resources/README.txt", RESOURCES_README.as_bytes()),
        ("resources/full_load.csv", FULL_LOAD_TRACE.as_bytes()),
        ("resources/motored.csv", MOTORED_TRACE.as_bytes()),
    ];
    let engine_cycle_files: [(&str, &[u8]); 2] = [
        ("modelDescription.xml", engine_cycle::MODEL_DESCRIPTION_XML.as_bytes()),
        ("documentation/index.html", engine_documentation.as_bytes()),
    ];
    let platforms: Vec<&str> = binaries.iter().map(|((_, folder, _), _)| *folder).collect();
    for (name, identity, files, variables) in [
        ("PistonSlap", Identity::PistonSlap, &piston_slap_files[..], VARIABLES.len()),
        ("EngineCycle", Identity::EngineCycle, &engine_cycle_files[..], engine_cycle::VARIABLES.len()),
    ] {
        let stamped = binaries_of(name, identity)?;
        let mut entries: Vec<(String, &[u8], bool)> = files.iter().map(|&(path, bytes)| (path.to_string(), bytes, false)).collect();
        entries.extend(stamped.iter().map(|(path, bytes, executable)| (path.clone(), &bytes[..], *executable)));
        let out = out_dir.join(format!("{name}.fmu"));
        write_fmu(&out, &entries).map_err(|e| format!("cannot write {}: {e}", out.display()))?;
        println!("wrote {} ({variables} variables, binaries {})", out.display(), platforms.join(" and "));
    }
    Ok(())
}

/// The archive of `files`: (name in the archive, bytes, executable).
fn write_fmu(out: &Path, files: &[(String, &[u8], bool)]) -> zip::result::ZipResult<()> {
    let mut zip = zip::ZipWriter::new(File::create(out)?);
    let text = SimpleFileOptions::default().compression_method(CompressionMethod::Deflated);
    for &(ref name, bytes, executable) in files {
        zip.start_file(name, if executable { text.unix_permissions(0o755) } else { text })?;
        zip.write_all(bytes)?;
    }
    zip.finish()?;
    Ok(())
}

/// The example pressure traces (`pressure_source = 3`, `pressure_trace = "full_load.csv"`) and what they are.
const RESOURCES_README: &str = include_str!("../../resources/README.txt");
const FULL_LOAD_TRACE: &str = include_str!("../../resources/full_load.csv");
const MOTORED_TRACE: &str = include_str!("../../resources/motored.csv");

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// The FMUs' documentation pages (`documentation/index.html` and `documentation/engine_cycle.html` of the sources,
/// placeholders `{{…}}`) and the geometry sketch PistonSlap's shows.
const DOCUMENTATION: &str = include_str!("../../documentation/index.html");
const ENGINE_DOCUMENTATION: &str = include_str!("../../documentation/engine_cycle.html");
const GEOMETRY_SVG: &str = include_str!("../../documentation/geometry.svg");

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
