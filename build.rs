//! Turns the variable table `modelDescription/variables.xml` (the one source of truth) into, in OUT_DIR:
//! - `modelDescription.xml`: the FMI 2.0 model description shipped in the FMU;
//! - `variables.rs`: the GUID, the variable table and the value-reference dispatch onto the fields of
//!   `Parameters`, `Inputs` and `Outputs` (included by `src/fmi/description.rs`);
//! - `parameter_defaults.rs`: the defaults and range checks of `Parameters` and `Inputs`
//!   (included by `src/models/parameters.rs`).
//!
//! Value references are the positions in the table (0, 1, …); ModelStructure indices are those plus one.

use quick_xml::events::{BytesDecl, BytesText, Event};
use quick_xml::Writer;
use serde::Deserialize;
use std::fmt::Write as _;
use std::io;
use std::path::Path;

const TABLE: &str = "modelDescription/variables.xml";
const MODEL_NAME: &str = "PistonSlap";

#[derive(Deserialize)]
struct Table {
    #[serde(rename = "DefaultExperiment")]
    experiment: Experiment,
    #[serde(rename = "Units")]
    units: Units,
    #[serde(rename = "Types")]
    types: Types,
    #[serde(rename = "Variables")]
    variables: Variables,
}

#[derive(Deserialize)]
struct Experiment {
    #[serde(rename = "@startTime")]
    start: String,
    #[serde(rename = "@stopTime")]
    stop: String,
    #[serde(rename = "@stepSize")]
    step: String,
}

#[derive(Deserialize)]
struct Units {
    #[serde(rename = "Unit")]
    units: Vec<Unit>,
}

/// A unit with its SI base-unit exponents and display units.
#[derive(Deserialize)]
struct Unit {
    #[serde(rename = "@name")]
    name: String,
    #[serde(rename = "@kg")]
    kg: Option<String>,
    #[serde(rename = "@m")]
    m: Option<String>,
    #[serde(rename = "@s")]
    s: Option<String>,
    #[serde(rename = "@rad")]
    rad: Option<String>,
    #[serde(rename = "DisplayUnit", default)]
    display: Vec<DisplayUnit>,
}

#[derive(Deserialize)]
struct DisplayUnit {
    #[serde(rename = "@name")]
    name: String,
    #[serde(rename = "@factor")]
    factor: String,
}

#[derive(Deserialize)]
struct Types {
    #[serde(rename = "Type")]
    types: Vec<TypeDef>,
}

#[derive(Deserialize)]
struct TypeDef {
    #[serde(rename = "@name")]
    name: String,
    #[serde(rename = "@quantity")]
    quantity: String,
    #[serde(rename = "@unit")]
    unit: String,
    #[serde(rename = "@displayUnit")]
    display_unit: Option<String>,
}

#[derive(Deserialize)]
struct Variables {
    #[serde(rename = "$value")]
    variables: Vec<Variable>,
}

#[derive(Deserialize)]
enum Variable {
    Real(Attributes),
    Integer(Attributes),
    String(Attributes),
}

#[derive(Deserialize)]
struct Attributes {
    #[serde(rename = "@name")]
    name: String,
    #[serde(rename = "@causality")]
    causality: String,
    #[serde(rename = "@type")]
    declared_type: Option<String>,
    #[serde(rename = "@start")]
    start: Option<String>,
    #[serde(rename = "@min")]
    min: Option<String>,
    #[serde(rename = "@max")]
    max: Option<String>,
    #[serde(rename = "@positive", default)]
    positive: bool,
    #[serde(rename = "@initialDeps")]
    initial_deps: Option<String>,
    #[serde(rename = "@description")]
    description: String,
}

/// One variable, resolved: its FMI type name, attributes, value reference and Rust home.
struct Resolved<'a> {
    kind: &'static str,
    a: &'a Attributes,
    vr: usize,
    unit: Option<&'a str>,
    display_unit: Option<&'a str>,
}

impl Resolved<'_> {
    fn variability(&self) -> &'static str {
        match (self.a.causality.as_str(), self.kind) {
            ("parameter", _) => "fixed",
            (_, "Real") => "continuous",
            _ => "discrete",
        }
    }
    /// The struct holding the field, as named in `variables.rs`' function arguments.
    fn owner(&self) -> &'static str {
        match self.a.causality.as_str() {
            "input" => "inputs",
            "output" => "outputs",
            _ => "parameters",
        }
    }
    fn rust_type(&self) -> &'static str {
        match self.kind {
            "Real" => "f64",
            "Integer" => "i32",
            _ => "String",
        }
    }
}

fn main() {
    println!("cargo:rerun-if-changed={TABLE}");
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-env-changed=SOURCE_DATE_EPOCH");
    // For `packaging::build_sibling`, which builds this crate again for the same target.
    println!("cargo:rustc-env=PISTONSLAP_TARGET={}", std::env::var("TARGET").expect("TARGET"));
    let source = std::fs::read_to_string(TABLE).expect("read modelDescription/variables.xml");
    let table: Table =
        quick_xml::de::from_str(&source).expect("parse modelDescription/variables.xml");
    let guid = guid_of(&source);
    let variables = resolve(&table);
    check(&variables);

    let out_dir = std::env::var("OUT_DIR").expect("OUT_DIR");
    let out = Path::new(&out_dir);
    let xml = model_description(&table, &variables, &guid).expect("write modelDescription.xml");
    std::fs::write(out.join("modelDescription.xml"), xml).expect("write modelDescription.xml");
    std::fs::write(out.join("variables.rs"), variables_rs(&variables, &guid))
        .expect("write variables.rs");
    std::fs::write(out.join("parameter_defaults.rs"), defaults_rs(&variables))
        .expect("write parameter_defaults.rs");
}

fn resolve(table: &Table) -> Vec<Resolved<'_>> {
    table
        .variables
        .variables
        .iter()
        .enumerate()
        .map(|(vr, v)| {
            let (kind, a) = match v {
                Variable::Real(a) => ("Real", a),
                Variable::Integer(a) => ("Integer", a),
                Variable::String(a) => ("String", a),
            };
            let declared = a.declared_type.as_deref().map(|t| {
                let def = table.types.types.iter().find(|d| d.name == t);
                def.unwrap_or_else(|| panic!("{}: unknown type {t}", a.name))
            });
            let unit = declared.map(|d| d.unit.as_str());
            let display_unit = declared.and_then(|d| d.display_unit.as_deref());
            Resolved {
                kind,
                a,
                vr,
                unit,
                display_unit,
            }
        })
        .collect()
}

/// Build-time guard: a malformed table fails the build instead of shipping a wrong FMU.
fn check(variables: &[Resolved]) {
    for (i, v) in variables.iter().enumerate() {
        let a = v.a;
        assert!(
            variables[..i].iter().all(|w| w.a.name != a.name),
            "duplicate variable {}",
            a.name
        );
        match a.causality.as_str() {
            "input" | "parameter" => assert!(a.start.is_some(), "{} needs a start value", a.name),
            "output" => {
                assert!(
                    a.start.is_none(),
                    "output {} is calculated: no start",
                    a.name
                );
                assert!(
                    matches!(a.initial_deps.as_deref(), Some("none" | "knowns")),
                    "output {} needs initialDeps=\"none\" or \"knowns\"",
                    a.name
                );
            }
            other => panic!("{}: causality {other} is not used by PistonSlap", a.name),
        }
        if v.kind == "String" {
            assert!(
                a.causality == "parameter",
                "String {} must be a parameter",
                a.name
            );
        }
    }
}

/// When the XML is generated, as FMI's xs:dateTime in UTC: `SOURCE_DATE_EPOCH` (seconds) when set,
/// for reproducible builds, else now.
fn generation_date_and_time() -> String {
    let seconds = std::env::var("SOURCE_DATE_EPOCH")
        .ok()
        .and_then(|s| s.parse::<u64>().ok())
        .unwrap_or_else(|| {
            let now = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH);
            now.expect("clock after 1970").as_secs()
        });
    let (days, time) = (seconds / 86_400, seconds % 86_400);
    // Days since 1970-01-01 to the proleptic Gregorian date (eras of 400 years, March-based years).
    let z = days + 719_468;
    let (era, day_of_era) = (z / 146_097, z % 146_097);
    let year_of_era = (day_of_era - day_of_era / 1460 + day_of_era / 36_524 - day_of_era / 146_096) / 365;
    let day_of_year = day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);
    let month_index = (5 * day_of_year + 2) / 153;
    let day = day_of_year - (153 * month_index + 2) / 5 + 1;
    let month = if month_index < 10 { month_index + 3 } else { month_index - 9 };
    let year = year_of_era + era * 400 + u64::from(month <= 2);
    format!("{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}Z", time / 3600, time % 3600 / 60, time % 60)
}

/// A stable GUID derived from the table, so that any change of the variables changes it.
fn guid_of(source: &str) -> String {
    let seed = format!("{}\n{}", env!("CARGO_PKG_VERSION"), source);
    let hash = |basis: u64| {
        seed.bytes().fold(basis, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
        })
    };
    let (a, b) = (hash(0xcbf2_9ce4_8422_2325), hash(0x6c62_272e_07bb_0142));
    format!(
        "{{{:08x}-{:04x}-{:04x}-{:04x}-{:012x}}}",
        a >> 32,
        (a >> 16) & 0xffff,
        a & 0xffff,
        b >> 48,
        b & 0xffff_ffff_ffff
    )
}

fn model_description(table: &Table, variables: &[Resolved], guid: &str) -> io::Result<Vec<u8>> {
    let mut w = Writer::new_with_indent(Vec::new(), b' ', 2);
    w.write_event(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)))?;
    let number_of_variables = variables.len().to_string();
    w.create_element("fmiModelDescription")
        .with_attributes([
            ("fmiVersion", "2.0"),
            ("modelName", MODEL_NAME),
            ("guid", guid),
            (
                "description",
                "Piston secondary motion (piston slap): crank, connecting rod and piston with clearance, \
                 impacts and sliding of the piston corners on the liner",
            ),
            ("version", env!("CARGO_PKG_VERSION")),
            ("license", "MIT"),
            ("generationTool", "PistonSlap build.rs"),
            ("generationDateAndTime", &generation_date_and_time()),
            ("variableNamingConvention", "flat"),
            ("numberOfEventIndicators", "0"),
        ])
        .write_inner_content(|w| {
            w.write_event(Event::Comment(BytesText::new(&format!(
                " generated from modelDescription/variables.xml: {number_of_variables} variables "
            ))))?;
            w.create_element("CoSimulation")
                .with_attributes([
                    ("modelIdentifier", MODEL_NAME),
                    ("needsExecutionTool", "false"),
                    ("canHandleVariableCommunicationStepSize", "true"),
                    ("canInterpolateInputs", "false"),
                    ("maxOutputDerivativeOrder", "0"),
                    ("canRunAsynchronuously", "false"),
                    ("canBeInstantiatedOnlyOncePerProcess", "false"),
                    ("canNotUseMemoryManagementFunctions", "true"),
                    ("canGetAndSetFMUstate", "true"),
                    ("canSerializeFMUstate", "true"),
                    ("providesDirectionalDerivative", "false"),
                ])
                .write_empty()?;
            write_units(w, table)?;
            write_types(w, table)?;
            w.create_element("LogCategories").write_inner_content(|w| {
                for (name, description) in LOG_CATEGORIES {
                    w.create_element("Category")
                        .with_attributes([("name", name), ("description", description)])
                        .write_empty()?;
                }
                Ok(())
            })?;
            let e = &table.experiment;
            w.create_element("DefaultExperiment")
                .with_attributes([
                    ("startTime", e.start.as_str()),
                    ("stopTime", e.stop.as_str()),
                    ("stepSize", e.step.as_str()),
                ])
                .write_empty()?;
            write_variables(w, variables)?;
            write_structure(w, variables)
        })?;
    let mut xml = w.into_inner();
    xml.push(b'\n');
    Ok(xml)
}

/// Log categories: (name, description). The FMI layer accepts exactly these in fmi2SetDebugLogging.
const LOG_CATEGORIES: [(&str, &str); 4] = [
    (
        "logStatusError",
        "Errors: refused calls, bad parameters, failed steps",
    ),
    (
        "logStatusFatal",
        "Fatal errors: a caught panic; the instance must be freed",
    ),
    (
        "logEvents",
        "Debug: impacts and sliding starts/releases during doStep",
    ),
    (
        "logBuild",
        "Debug: at fmi2Instantiate, which build of the binary runs the instance (x86-64 or x86-64-v3) and why",
    ),
];

fn write_units(w: &mut Writer<Vec<u8>>, table: &Table) -> io::Result<()> {
    w.create_element("UnitDefinitions")
        .write_inner_content(|w| {
            for u in &table.units.units {
                w.create_element("Unit")
                    .with_attribute(("name", u.name.as_str()))
                    .write_inner_content(|w| {
                        let exponents = [("kg", &u.kg), ("m", &u.m), ("s", &u.s), ("rad", &u.rad)];
                        let present = present(&exponents);
                        w.create_element("BaseUnit")
                            .with_attributes(present)
                            .write_empty()?;
                        for d in &u.display {
                            w.create_element("DisplayUnit")
                                .with_attributes([
                                    ("name", d.name.as_str()),
                                    ("factor", d.factor.as_str()),
                                ])
                                .write_empty()?;
                        }
                        Ok(())
                    })?;
            }
            Ok(())
        })?;
    Ok(())
}

fn write_types(w: &mut Writer<Vec<u8>>, table: &Table) -> io::Result<()> {
    w.create_element("TypeDefinitions")
        .write_inner_content(|w| {
            for t in &table.types.types {
                w.create_element("SimpleType")
                    .with_attribute(("name", t.name.as_str()))
                    .write_inner_content(|w| {
                        let mut real = w.create_element("Real").with_attributes([
                            ("quantity", t.quantity.as_str()),
                            ("unit", t.unit.as_str()),
                        ]);
                        if let Some(d) = &t.display_unit {
                            real = real.with_attribute(("displayUnit", d.as_str()));
                        }
                        real.write_empty()?;
                        Ok(())
                    })?;
            }
            Ok(())
        })?;
    Ok(())
}

fn write_variables(w: &mut Writer<Vec<u8>>, variables: &[Resolved]) -> io::Result<()> {
    w.create_element("ModelVariables")
        .write_inner_content(|w| {
            for v in variables {
                let a = v.a;
                let vr = v.vr.to_string();
                let mut sv = w.create_element("ScalarVariable").with_attributes([
                    ("name", a.name.as_str()),
                    ("valueReference", vr.as_str()),
                    ("description", a.description.as_str()),
                    ("causality", a.causality.as_str()),
                    ("variability", v.variability()),
                ]);
                if a.causality == "parameter" {
                    sv = sv.with_attribute(("initial", "exact"));
                }
                sv.write_inner_content(|w| {
                    // unit and displayUnit repeat the declared type's: hosts that do not resolve
                    // declaredType (fmpy's ModelVariable.unit) still see them.
                    let unit = v.unit.map(str::to_string);
                    let display_unit = v.display_unit.map(str::to_string);
                    let optional = [
                        ("declaredType", &a.declared_type),
                        ("unit", &unit),
                        ("displayUnit", &display_unit),
                        ("start", &a.start),
                        ("min", &a.min),
                        ("max", &a.max),
                    ];
                    let present = present(&optional);
                    w.create_element(v.kind)
                        .with_attributes(present)
                        .write_empty()?;
                    Ok(())
                })?;
            }
            Ok(())
        })?;
    Ok(())
}

/// Outputs are computed at the end of each doStep from the state: no direct feedthrough from the inputs
/// (dependencies=""). Initially the impact statistics are constants, the kinematics and forces depend on
/// the inputs and the parameters (except the log file name).
fn write_structure(w: &mut Writer<Vec<u8>>, variables: &[Resolved]) -> io::Result<()> {
    let outputs: Vec<&Resolved> = variables
        .iter()
        .filter(|v| v.a.causality == "output")
        .collect();
    let knowns: Vec<String> = variables
        .iter()
        .filter(|v| matches!(v.a.causality.as_str(), "input" | "parameter") && v.kind != "String")
        .map(|v| (v.vr + 1).to_string())
        .collect();
    let knowns = knowns.join(" ");
    w.create_element("ModelStructure")
        .write_inner_content(|w| {
            w.create_element("Outputs").write_inner_content(|w| {
                for v in &outputs {
                    let index = (v.vr + 1).to_string();
                    w.create_element("Unknown")
                        .with_attributes([("index", index.as_str()), ("dependencies", "")])
                        .write_empty()?;
                }
                Ok(())
            })?;
            w.create_element("InitialUnknowns")
                .write_inner_content(|w| {
                    for v in &outputs {
                        let index = (v.vr + 1).to_string();
                        let deps = if v.a.initial_deps.as_deref() == Some("knowns") {
                            knowns.as_str()
                        } else {
                            ""
                        };
                        w.create_element("Unknown")
                            .with_attributes([("index", index.as_str()), ("dependencies", deps)])
                            .write_empty()?;
                    }
                    Ok(())
                })?;
            Ok(())
        })?;
    Ok(())
}

/// The dispatch functions and the table, as Rust source.
fn variables_rs(variables: &[Resolved], guid: &str) -> String {
    let mut s = String::new();
    writeln!(
        s,
        "/// Fingerprint of the variable table, also in modelDescription.xml."
    )
    .unwrap();
    writeln!(s, "pub const GUID: &str = {guid:?};").unwrap();
    writeln!(s, "/// Log categories accepted by fmi2SetDebugLogging.").unwrap();
    let names: Vec<&str> = LOG_CATEGORIES.iter().map(|(n, _)| *n).collect();
    writeln!(
        s,
        "pub const LOG_CATEGORIES: [&str; {}] = {names:?};",
        names.len()
    )
    .unwrap();
    writeln!(s, "/// Every variable, indexed by value reference.").unwrap();
    writeln!(
        s,
        "pub static VARIABLES: [Variable; {}] = [",
        variables.len()
    )
    .unwrap();
    for v in variables {
        let a = v.a;
        writeln!(
            s,
            "    Variable {{ name: {:?}, kind: Kind::{}, causality: Causality::{}, unit: {:?}, start: {:?}, \
             description: {:?} }},",
            a.name,
            v.kind,
            capitalize(&a.causality),
            v.unit.unwrap_or(""),
            a.start.as_deref().unwrap_or(""),
            a.description
        )
        .unwrap();
    }
    writeln!(s, "];").unwrap();

    for (kind, rust, get_ty, get_expr) in [
        ("Real", "real", "f64", ""),
        ("Integer", "integer", "i32", ""),
        ("String", "string", "&'a str", ".as_str()"),
    ] {
        let of_kind: Vec<&Resolved> = variables.iter().filter(|v| v.kind == kind).collect();
        let used = |owner: &str| of_kind.iter().any(|v| v.owner() == owner);
        let arg = |owner: &str| {
            if used(owner) {
                owner.to_string()
            } else {
                format!("_{owner}")
            }
        };
        let field_ty = of_kind.first().map(|v| v.rust_type()).unwrap_or("f64");
        writeln!(
            s,
            "/// The {kind} variable `vr`, or None if `vr` is not one."
        )
        .unwrap();
        writeln!(
            s,
            "pub(crate) fn get_{rust}<'a>(vr: u32, {}: &'a Parameters, {}: &'a Inputs, {}: &'a Outputs) -> \
             Option<{get_ty}> {{\n    match vr {{",
            arg("parameters"),
            arg("inputs"),
            arg("outputs")
        )
        .unwrap();
        for v in &of_kind {
            writeln!(
                s,
                "        {} => Some({}.{}{get_expr}),",
                v.vr,
                v.owner(),
                v.a.name
            )
            .unwrap();
        }
        writeln!(s, "        _ => None,\n    }}\n}}").unwrap();
        writeln!(
            s,
            "/// The settable (input or parameter) {kind} variable `vr`, or None."
        )
        .unwrap();
        writeln!(
            s,
            "pub(crate) fn {rust}_mut<'a>(vr: u32, {}: &'a mut Parameters, {}: &'a mut Inputs) -> \
             Option<&'a mut {field_ty}> {{\n    match vr {{",
            arg("parameters"),
            arg("inputs")
        )
        .unwrap();
        for v in of_kind.iter().filter(|v| v.owner() != "outputs") {
            writeln!(
                s,
                "        {} => Some(&mut {}.{}),",
                v.vr,
                v.owner(),
                v.a.name
            )
            .unwrap();
        }
        writeln!(s, "        _ => None,\n    }}\n}}").unwrap();
    }
    s
}

/// `Default` for `Parameters` and `Inputs` from the start values, and the range checks of `Parameters`.
fn defaults_rs(variables: &[Resolved]) -> String {
    let mut s = String::new();
    for (owner, ty) in [("parameters", "Parameters"), ("inputs", "Inputs")] {
        writeln!(
            s,
            "impl Default for {ty} {{\n    fn default() -> Self {{\n        Self {{"
        )
        .unwrap();
        for v in variables.iter().filter(|v| v.owner() == owner) {
            let start = v.a.start.as_deref().unwrap_or_default();
            let value = match v.kind {
                "Real" => format!("{:?}_f64", start.parse::<f64>().expect("Real start")),
                "Integer" => format!("{}_i32", start.parse::<i32>().expect("Integer start")),
                _ => format!("String::from({start:?})"),
            };
            writeln!(s, "            {}: {value},", v.a.name).unwrap();
        }
        writeln!(s, "        }}\n    }}\n}}").unwrap();
    }
    writeln!(s, "impl Parameters {{").unwrap();
    writeln!(s, "    /// Every Real parameter finite and within the table's min/max (and > 0 where marked positive);").unwrap();
    writeln!(s, "    /// every Integer parameter within its min/max.").unwrap();
    writeln!(s, "    fn check_ranges(&self) -> Result<(), ModelError> {{").unwrap();
    for v in variables.iter().filter(|v| v.owner() == "parameters") {
        let a = v.a;
        let bound = |b: &Option<String>, parse: &dyn Fn(&str) -> String| {
            b.as_deref()
                .map_or("None".to_string(), |b| format!("Some({})", parse(b)))
        };
        match v.kind {
            "Real" => {
                let f = |b: &str| format!("{:?}", b.parse::<f64>().expect("Real bound"));
                writeln!(
                    s,
                    "        check_real({:?}, self.{}, {}, {}, {}, {:?})?;",
                    a.name,
                    a.name,
                    bound(&a.min, &f),
                    bound(&a.max, &f),
                    a.positive,
                    v.unit.unwrap_or("")
                )
                .unwrap();
            }
            "Integer" => {
                let i = |b: &str| b.parse::<i32>().expect("Integer bound").to_string();
                writeln!(
                    s,
                    "        check_integer({:?}, self.{}, {}, {})?;",
                    a.name,
                    a.name,
                    bound(&a.min, &i),
                    bound(&a.max, &i)
                )
                .unwrap();
            }
            _ => {}
        }
    }
    writeln!(s, "        Ok(())\n    }}\n}}").unwrap();
    s
}

/// The attributes of `pairs` that have a value.
fn present<'a>(
    pairs: &'a [(&'a str, &'a Option<String>)],
) -> impl Iterator<Item = (&'a str, &'a str)> {
    pairs
        .iter()
        .filter_map(|(k, v)| v.as_deref().map(|v| (*k, v)))
}

fn capitalize(word: &str) -> String {
    let mut chars = word.chars();
    chars
        .next()
        .map_or_else(String::new, |c| c.to_uppercase().chain(chars).collect())
}
