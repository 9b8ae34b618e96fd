//! Packs the FMU: `cargo run --release --bin package_fmu [-- <libpistonslap.so> [<out.fmu>]]`.
//!
//! Defaults: the cdylib next to this executable (the same cargo profile directory) and
//! `<target>/fmu/PistonSlap.fmu`. The archive holds `modelDescription.xml` and the documentation's
//! variable table, both generated from `modelDescription/variables.xml`, the binary as
//! `binaries/linux64/PistonSlap.so`, and `resources/`.

use pistonslap::fmi::description::{Causality, Kind, MODEL_DESCRIPTION_XML, VARIABLES};
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
    let default_out = target_dir.join("fmu").join("PistonSlap.fmu");
    let out = args.next().map_or(default_out, PathBuf::from);
    let binary =
        std::fs::read(&library).map_err(|e| format!("cannot read {} ({e}); run `cargo build --release` first", library.display()))?;
    if let Some(dir) = out.parent() {
        std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    }
    write_fmu(&out, &binary).map_err(|e| format!("cannot write {}: {e}", out.display()))?;
    println!("wrote {} ({} variables, binary {})", out.display(), VARIABLES.len(), library.display());
    Ok(())
}

fn write_fmu(out: &Path, binary: &[u8]) -> zip::result::ZipResult<()> {
    let mut zip = zip::ZipWriter::new(File::create(out)?);
    let text = SimpleFileOptions::default().compression_method(CompressionMethod::Deflated);
    let executable = text.unix_permissions(0o755);
    let documentation = documentation();
    let files: [(&str, &[u8], SimpleFileOptions); 7] = [
        ("modelDescription.xml", MODEL_DESCRIPTION_XML.as_bytes(), text),
        ("binaries/linux64/PistonSlap.so", binary, executable),
        ("documentation/index.html", documentation.as_bytes(), text),
        ("documentation/geometry.svg", GEOMETRY_SVG.as_bytes(), text),
        ("resources/README.txt", RESOURCES_README.as_bytes(), text),
        ("resources/full_load.csv", FULL_LOAD_TRACE.as_bytes(), text),
        ("resources/motored.csv", MOTORED_TRACE.as_bytes(), text),
    ];
    for (name, bytes, options) in files {
        zip.start_file(name, options)?;
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

/// The FMU's documentation page (`documentation/index.html` of the sources, placeholders `{{…}}`) and the
/// geometry sketch it shows.
const DOCUMENTATION: &str = include_str!("../../documentation/index.html");
const GEOMETRY_SVG: &str = include_str!("../../documentation/geometry.svg");

/// documentation/index.html: what the model is, its conventions, its variables (from the same table as
/// the XML), its assumptions and references.
fn documentation() -> String {
    let mut rows = String::new();
    for (vr, v) in VARIABLES.iter().enumerate() {
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
    DOCUMENTATION.replace("{{version}}", env!("CARGO_PKG_VERSION")).replace("{{variables}}", &rows)
}
