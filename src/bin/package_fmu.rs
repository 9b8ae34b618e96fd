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
    let files: [(&str, &[u8], SimpleFileOptions); 4] = [
        ("modelDescription.xml", MODEL_DESCRIPTION_XML.as_bytes(), text),
        ("binaries/linux64/PistonSlap.so", binary, executable),
        ("documentation/index.html", documentation.as_bytes(), text),
        ("resources/README.txt", RESOURCES_README.as_bytes(), text),
    ];
    for (name, bytes, options) in files {
        zip.start_file(name, options)?;
        zip.write_all(bytes)?;
    }
    zip.finish()?;
    Ok(())
}

const RESOURCES_README: &str = "\
PistonSlap needs no resource files. The built-in four-stroke pressure curve (pressure_source = 2) is
computed in the binary (src/models/pressure.rs in the sources): a closed-cylinder polytropic
compression and expansion with a Wiebe burn fraction, zero gauge pressure during exhaust and intake,
scaled so that its maximum is peak_pressure. See documentation/index.html.
";

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// documentation/index.html: what the model is, its variables (from the same table as the XML), its
/// assumptions and references.
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
    format!(
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>PistonSlap FMU</title>
<style>body{{font-family:sans-serif;max-width:64em;margin:auto}}table{{border-collapse:collapse}}
td,th{{border:1px solid #ccc;padding:0.2em 0.5em;text-align:left;vertical-align:top}}</style></head>
<body>
<h1>PistonSlap</h1>
<p>An FMI 2.0 Co-Simulation FMU of piston secondary motion ("piston slap"): a crank, a connecting rod
and a piston with clearance in the cylinder. The piston corners hit the liner (rigid impacts with a
generalized Newton restitution law) and slide along it (persistent contact with non-negative normal
forces). Inside every <code>fmi2DoStep</code> an event-driven RK4 integrator locates each impact,
sliding start and release, so results do not depend on the communication step size beyond the
integrator's accuracy.</p>
<ul>
<li><b>model_variant = 1</b>: the crank train of Awrejcewicz and Kudra, a triple physical pendulum with
four corner constraints; crank at prescribed speed (<code>crank_mode = 1</code>) or free under
<code>load_torque</code> (<code>crank_mode = 2</code>).</li>
<li><b>model_variant = 2</b>: Farahanchi's single-degree-of-freedom, linearized slider crank with
slider clearance (<code>roller_forcing</code> 1 = the thesis's equation as printed, 2 = corrected).</li>
</ul>
<h2>Variables</h2>
<p>All values in SI units (display units rpm, bar, mm and µm in the model description). Value
references as listed; outputs are computed at the end of each step (no direct feedthrough).</p>
<table><tr><th>name</th><th>value reference</th><th>causality</th><th>type</th><th>unit</th><th>start</th>
<th>description</th></tr>
{rows}</table>
<h2>Assumptions</h2>
<ul>
<li>Rigid bodies, frictionless liner contact, impacts with one restitution coefficient for all corners.</li>
<li>Inputs are held constant over a communication step (no input interpolation).</li>
<li><code>gas_pressure</code> is the pressure difference across the piston (cylinder minus crankcase),
acting on the crown area π d²/4; the built-in curve (<code>pressure_source = 2</code>) is gauge as well.</li>
<li>At the start time the crank is at <code>crank_angle_start</code>, the piston centred in the bore
without tilt, moving with the zero-clearance slider-crank kinematics.</li>
<li>Parameters are fixed after initialization; out-of-range values are refused at
<code>fmi2ExitInitializationMode</code> with a message naming the parameter.</li>
<li>FMU states can be saved, restored and serialized; a restored state continues bit-identically.</li>
<li>A communication step may span many engine cycles (up to 10<sup>7</sup> internal RK4 steps, about
2500 s of the default case).</li>
<li>A logger callback that calls back into the instance that is logging gets <code>fmi2Error</code>, and
<code>fmi2FreeInstance</code> from there does nothing; calls into other instances are fine.</li>
</ul>
<h2>References</h2>
<ul>
<li>J. Awrejcewicz, G. Kudra, "The piston–connecting rod–crankshaft system as a triple physical pendulum
with impacts", International Journal of Bifurcation and Chaos 15(7), 2005.</li>
<li>F. Farahanchi, "Chaotic and periodic dynamics of a slider crank mechanism with slider clearance",
Ph.D. thesis, Michigan State University, 1991.</li>
</ul>
</body></html>
"#
    )
}
