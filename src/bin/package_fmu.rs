//! Packs the FMUs: `cargo run --release --bin package_fmu [-- [--linux64 <.so>] [--win64 <.dll>] [--out <directory>]]`.
//!
//! Defaults: the linux64 cdylib next to this executable (the same cargo profile directory), no win64 binary,
//! and `<target>/fmu/`. The one binary of each platform serves every FMU of the registry
//! (`pistonslap::fmus::PACKAGES`) in both FMI versions, each FMU's copy stamped with its name
//! (`pistonslap::fmi::identity`) so that it refuses the other FMUs' GUIDs. Each FMU is written twice: `<name>.fmu`
//! (FMI 2.0) and `<name>3.fmu` (FMI 3.0), each with its `modelDescription.xml` and its documentation's variable
//! table, all generated from `modelDescription/<fmu>.xml`, the files its room lists (PistonSlap's geometry sketch
//! and `resources/`), and the binaries as `binaries/<platform>/<name>.{so,dll}` in the version's platform folders.
use pistonslap::fmi::identity::stamp;
use pistonslap::fmi::{Causality, Kind, Package, Variable};
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

/// A platform: its option, its folders under `binaries/` in FMI 2.0 (§2.4) and FMI 3.0 (§2.5.1.4), and its
/// shared-library extension.
struct Platform {
    option: &'static str,
    fmi2: &'static str,
    fmi3: &'static str,
    extension: &'static str,
}

const PLATFORMS: [Platform; 2] = [
    Platform { option: "--linux64", fmi2: "linux64", fmi3: "x86_64-linux", extension: "so" },
    Platform { option: "--win64", fmi2: "win64", fmi3: "x86_64-windows", extension: "dll" },
];

/// What differs between an FMU's two archives: the file name's suffix, the model description, the platform
/// folder, and a note the FMI 3.0 documentation opens with.
struct Version {
    suffix: &'static str,
    model_description: fn(&Package) -> &'static str,
    folder: fn(&Platform) -> &'static str,
    note: &'static str,
}

const VERSIONS: [Version; 2] = [
    Version { suffix: "", model_description: |p| p.model_description_xml, folder: |p| p.fmi2, note: "" },
    Version {
        suffix: "3",
        model_description: |p| p.fmi3_model_description_xml,
        folder: |p| p.fmi3,
        note: "<p><em>This archive is the FMI 3.0 Co-Simulation FMU of the model: the same binary, variables and \
               results as the FMI 2.0 FMU this page describes. Each fmi2 function named below is the fmi3 function \
               of the same role (fmi2GetReal: fmi3GetFloat64, fmi2GetInteger: fmi3GetInt32); the experiment is \
               given at fmi3EnterInitializationMode; inputs are held over a step (FMI 3.0 has no input \
               derivatives); doStep never returns early and the FMU has no Event Mode.</em></p>\n",
    },
];

fn run() -> Result<(), String> {
    let here = std::env::current_exe().map_err(|e| e.to_string())?;
    let profile_dir = here.parent().ok_or("no executable directory")?.to_path_buf();
    let target_dir = profile_dir.parent().unwrap_or(&profile_dir);
    let mut libraries: Vec<(usize, PathBuf)> = vec![(0, profile_dir.join("libpistonslap.so"))];
    let mut out_dir = target_dir.join("fmu");
    let mut args = std::env::args_os().skip(1);
    while let Some(flag) = args.next() {
        let value = args.next().map(PathBuf::from).ok_or_else(|| format!("{} needs a path", flag.to_string_lossy()))?;
        match PLATFORMS.iter().position(|p| flag == p.option) {
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
                .map(|bytes| (&PLATFORMS[*platform], bytes))
                .map_err(|e| format!("cannot read {} ({e}); run `make fmu`", path.display()))
        })
        .collect::<Result<Vec<_>, _>>()?;
    std::fs::create_dir_all(&out_dir).map_err(|e| format!("cannot create {}: {e}", out_dir.display()))?;
    for package in PACKAGES {
        // The FMU's copies of the binaries, stamped with its name.
        let stamped = binaries
            .iter()
            .map(|(platform, bytes)| {
                let mut copy = bytes.clone();
                stamp(&mut copy, package.name).map_err(|e| format!("the {} binary: {e}", platform.fmi2))?;
                Ok((*platform, copy))
            })
            .collect::<Result<Vec<_>, String>>()?;
        for version in &VERSIONS {
            let documentation = documentation(package.documentation, package.variables, version.note);
            let mut entries: Vec<(String, Vec<u8>, bool)> = vec![
                ("modelDescription.xml".into(), (version.model_description)(package).as_bytes().to_vec(), false),
                ("documentation/index.html".into(), documentation.into_bytes(), false),
            ];
            entries.extend(package.files.iter().map(|&(path, bytes)| (path.to_string(), bytes.to_vec(), false)));
            for (platform, copy) in &stamped {
                entries.push((
                    format!("binaries/{}/{}.{}", (version.folder)(platform), package.name, platform.extension),
                    copy.clone(),
                    true,
                ));
            }
            let out = out_dir.join(format!("{}{}.fmu", package.name, version.suffix));
            write_fmu(&out, &entries).map_err(|e| format!("cannot write {}: {e}", out.display()))?;
            let folders: Vec<&str> = stamped.iter().map(|(platform, _)| (version.folder)(platform)).collect();
            println!("wrote {} ({} variables, binaries {})", out.display(), package.variables.len(), folders.join(" and "));
        }
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
/// table as the XML), its assumptions and references; `note` opens it, after the title.
fn documentation(template: &str, variables: &[Variable], note: &str) -> String {
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
    let page = template.replace("{{version}}", env!("CARGO_PKG_VERSION")).replace("{{variables}}", &rows);
    match page.split_once("</h1>\n") {
        Some((title, rest)) => format!("{title}</h1>\n{note}{rest}"),
        None => format!("{note}{page}"),
    }
}
