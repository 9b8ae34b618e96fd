//! Packs the FMUs: `cargo run --release --bin package_fmu [-- <libpistonslap.so> [<out directory>]]`.
//!
//! Defaults: the cdylib next to this executable (the same cargo profile directory) and `<target>/fmu/`.
//! The one binary serves both FMUs (it makes an instance of the model whose GUID it gets):
//! - `PistonSlap.fmu`: `modelDescription.xml` and the documentation's variable table, both generated from
//!   `modelDescription/variables.xml`, the binary as `binaries/linux64/PistonSlap.so`, and `resources/`;
//! - `EngineCycle.fmu`: its `modelDescription.xml` (from `modelDescription/variables_engine_cycle.xml`), its
//!   documentation (`documentation/engine_cycle.html` with the variable table) and the binary as
//!   `binaries/linux64/EngineCycle.so`.
//!
//! Each FMU's copy of the binary is stamped with its model (`pistonslap::fmi::identity`): it then refuses the
//! other FMU's GUID.

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

fn run() -> Result<(), String> {
    let here = std::env::current_exe().map_err(|e| e.to_string())?;
    let profile_dir = here.parent().ok_or("no executable directory")?.to_path_buf();
    let mut args = std::env::args_os().skip(1);
    let library = args.next().map_or_else(|| profile_dir.join("libpistonslap.so"), PathBuf::from);
    let target_dir = profile_dir.parent().unwrap_or(&profile_dir);
    let out_dir = args.next().map_or_else(|| target_dir.join("fmu"), PathBuf::from);
    let binary =
        std::fs::read(&library).map_err(|e| format!("cannot read {} ({e}); run `cargo build --release` first", library.display()))?;
    std::fs::create_dir_all(&out_dir).map_err(|e| format!("cannot create {}: {e}", out_dir.display()))?;
    let stamped = |identity| {
        let mut copy = binary.clone();
        stamp(&mut copy, identity).map(|()| copy).map_err(|e| format!("{}: {e}", library.display()))
    };
    let (slap_binary, engine_binary) = (stamped(Identity::PistonSlap)?, stamped(Identity::EngineCycle)?);
    let slap_documentation = documentation(DOCUMENTATION, &VARIABLES);
    let engine_documentation = documentation(ENGINE_DOCUMENTATION, &engine_cycle::VARIABLES);
    let piston_slap: [(&str, &[u8], bool); 7] = [
        ("modelDescription.xml", MODEL_DESCRIPTION_XML.as_bytes(), false),
        ("binaries/linux64/PistonSlap.so", &slap_binary, true),
        ("documentation/index.html", slap_documentation.as_bytes(), false),
        ("documentation/geometry.svg", GEOMETRY_SVG.as_bytes(), false),
        ("resources/README.txt", RESOURCES_README.as_bytes(), false),
        ("resources/full_load.csv", FULL_LOAD_TRACE.as_bytes(), false),
        ("resources/motored.csv", MOTORED_TRACE.as_bytes(), false),
    ];
    let engine_cycle: [(&str, &[u8], bool); 3] = [
        ("modelDescription.xml", engine_cycle::MODEL_DESCRIPTION_XML.as_bytes(), false),
        ("binaries/linux64/EngineCycle.so", &engine_binary, true),
        ("documentation/index.html", engine_documentation.as_bytes(), false),
    ];
    for (name, files, variables) in
        [("PistonSlap.fmu", &piston_slap[..], VARIABLES.len()), ("EngineCycle.fmu", &engine_cycle[..], engine_cycle::VARIABLES.len())]
    {
        let out = out_dir.join(name);
        write_fmu(&out, files).map_err(|e| format!("cannot write {}: {e}", out.display()))?;
        println!("wrote {} ({variables} variables, binary {})", out.display(), library.display());
    }
    Ok(())
}

/// The archive of `files`: (name in the archive, bytes, executable).
fn write_fmu(out: &Path, files: &[(&str, &[u8], bool)]) -> zip::result::ZipResult<()> {
    let mut zip = zip::ZipWriter::new(File::create(out)?);
    let text = SimpleFileOptions::default().compression_method(CompressionMethod::Deflated);
    for &(name, bytes, executable) in files {
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
