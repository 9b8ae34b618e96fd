//! Turns each variable table `modelDescription/<fmu>.xml` (the one source of truth of its FMU) into, in OUT_DIR,
//! with the prefix `<fmu>_`:
//! - `modelDescription.xml` and `fmi3ModelDescription.xml`: the FMI 2.0 and FMI 3.0 model descriptions shipped
//!   in the FMUs (`<fmu>.fmu`, `<fmu>3.fmu`);
//! - `variables.rs`: the GUID, the variable table and the value-reference dispatch onto the fields of
//!   `Parameters`, `Inputs` and `Outputs` (included by the FMU's room, `src/fmus/<fmu>/variables.rs`);
//! - `contract.rs`: the macros `parameters_struct!`, `inputs_struct!` and `outputs_struct!` that declare the
//!   contract types with one documented field per variable, the defaults and range checks of `Parameters`
//!   and `Inputs`, the finiteness check of the Real outputs and the input derivatives by name (included where
//!   each FMU's room keeps its contract types: `src/fmus/<fmu>/contract.rs`);
//!
//! and once, `log_categories.rs` (included by `src/fmi/description.rs`).
//!
//! Value references are the positions in the table (0, 1, …); ModelStructure indices are those plus one.

#[path = "build/fmi3_model_description.rs"]
mod fmi3_model_description;
#[path = "build/model_description.rs"]
mod model_description;

use fmi3_model_description::fmi3_model_description;
use model_description::{guid_of, model_description, LOG_CATEGORIES};
use quick_xml::events::{BytesDecl, BytesText, Event};
use quick_xml::Writer;
use serde::Deserialize;
use std::io;
use std::path::Path;

/// The folder of the variable tables, one `<fmu>.xml` per FMU of the registry (`src/fmus/`).
const TABLES: &str = "modelDescription";

#[derive(Deserialize)]
struct Table {
    #[serde(rename = "@modelName")]
    model_name: String,
    #[serde(rename = "@description")]
    description: String,
    #[serde(rename = "@canInterpolateInputs", default = "yes")]
    can_interpolate_inputs: String,
    #[serde(rename = "@maxOutputDerivativeOrder", default = "zero")]
    max_output_derivative_order: String,
    #[serde(rename = "DefaultExperiment")]
    experiment: Experiment,
    #[serde(rename = "Units")]
    units: List<Unit>,
    #[serde(rename = "Types")]
    types: List<TypeDef>,
    #[serde(rename = "Variables")]
    variables: List<Variable>,
}

fn yes() -> String {
    "true".into()
}
fn zero() -> String {
    "0".into()
}

/// An element's children, all of one type.
#[derive(Deserialize)]
struct List<T> {
    #[serde(rename = "$value")]
    items: Vec<T>,
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
    #[serde(rename = "@K")]
    kelvin: Option<String>,
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
}

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    // The memcheck test (tests/c_abi.rs) runs where valgrind is installed and is reported ignored elsewhere.
    println!("cargo::rustc-check-cfg=cfg(valgrind)");
    println!("cargo:rerun-if-env-changed=PATH");
    if std::process::Command::new("valgrind").arg("--version").output().is_ok_and(|o| o.status.success()) {
        println!("cargo:rustc-cfg=valgrind");
    }
    println!("cargo:rerun-if-env-changed=SOURCE_DATE_EPOCH");
    let out_dir = std::env::var("OUT_DIR").expect("OUT_DIR");
    println!("cargo:rerun-if-changed={TABLES}");
    let names: Vec<&str> = LOG_CATEGORIES.iter().map(|(n, _)| *n).collect();
    let log_categories =
        format!("/// Log categories accepted by fmi2SetDebugLogging.\npub const LOG_CATEGORIES: [&str; {}] = {names:?};\n", names.len());
    std::fs::write(Path::new(&out_dir).join("log_categories.rs"), log_categories).expect("write OUT_DIR");
    let mut tables: Vec<_> = std::fs::read_dir(TABLES)
        .expect("read modelDescription/")
        .map(|e| e.expect("list modelDescription/").path())
        .filter(|p| p.extension().is_some_and(|x| x == "xml"))
        .collect();
    tables.sort();
    for path in &tables {
        let path = path.to_str().expect("UTF-8 table path");
        println!("cargo:rerun-if-changed={path}");
        let prefix = format!("{}_", Path::new(path).file_stem().and_then(|s| s.to_str()).expect("table name"));
        let source = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("read {path}: {e}"));
        let table: Table = quick_xml::de::from_str(&source).unwrap_or_else(|e| panic!("parse {path}: {e}"));
        let guid = guid_of(&source);
        let variables = resolve(&table);
        check(&variables);

        let out = Path::new(&out_dir);
        let write = |name: &str, text: &[u8]| std::fs::write(out.join(format!("{prefix}{name}")), text).expect("write OUT_DIR");
        write("modelDescription.xml", &model_description(&table, &variables, &guid, path).expect("write modelDescription.xml"));
        write(
            "fmi3ModelDescription.xml",
            &fmi3_model_description(&table, &variables, &guid, path).expect("write fmi3ModelDescription.xml"),
        );
        write("variables.rs", variables_rs(&variables, &guid, &table.model_name, &prefix).as_bytes());
        write("contract.rs", contract_rs(&variables, &table).as_bytes());
    }
}

fn resolve(table: &Table) -> Vec<Resolved<'_>> {
    table
        .variables
        .items
        .iter()
        .enumerate()
        .map(|(vr, v)| {
            let (kind, a) = match v {
                Variable::Real(a) => ("Real", a),
                Variable::Integer(a) => ("Integer", a),
                Variable::String(a) => ("String", a),
            };
            let declared = a.declared_type.as_deref().map(|t| {
                let def = table.types.items.iter().find(|d| d.name == t);
                def.unwrap_or_else(|| panic!("{}: unknown type {t}", a.name))
            });
            let unit = declared.map(|d| d.unit.as_str());
            let display_unit = declared.and_then(|d| d.display_unit.as_deref());
            Resolved { kind, a, vr, unit, display_unit }
        })
        .collect()
}

/// Build-time guard: a malformed table fails the build instead of shipping a wrong FMU.
fn check(variables: &[Resolved]) {
    for (i, v) in variables.iter().enumerate() {
        let a = v.a;
        assert!(variables[..i].iter().all(|w| w.a.name != a.name), "duplicate variable {}", a.name);
        match a.causality.as_str() {
            "input" | "parameter" => assert!(a.start.is_some(), "{} needs a start value", a.name),
            "output" => {
                assert!(a.start.is_none(), "output {} is calculated: no start", a.name);
                assert!(
                    matches!(a.initial_deps.as_deref(), Some("none" | "knowns")),
                    "output {} needs initialDeps=\"none\" or \"knowns\"",
                    a.name
                );
            }
            other => panic!("{}: causality {other} is not used by PistonSlap", a.name),
        }
        if v.kind == "String" {
            assert!(a.causality == "parameter", "String {} must be a parameter", a.name);
        }
    }
}

/// The table as Rust source: the GUID, the log categories, `VARIABLES`, per kind the lists of
/// (value reference => field) per owner, from which `dispatch!` (src/fmi/description.rs) writes the
/// match arms of the getters and setters, and `DESCRIPTION`, all of it as one value.
fn variables_rs(variables: &[Resolved], guid: &str, model_name: &str, prefix: &str) -> String {
    let mut s = format!("/// Fingerprint of the variable table, also in modelDescription.xml.\npub const GUID: &str = {guid:?};\n");
    s += &format!("/// Every variable, indexed by value reference.\npub static VARIABLES: [Variable; {}] = [\n", variables.len());
    for v in variables {
        let (a, causality) = (v.a, capitalize(&v.a.causality));
        let (unit, start, description) = (v.unit.unwrap_or(""), a.start.as_deref().unwrap_or(""), &a.description);
        s += &format!("    Variable {{ name: {:?}, kind: Kind::{}, causality: Causality::{causality}, ", a.name, v.kind);
        s += &format!("unit: {unit:?}, start: {start:?}, description: {description:?} }},\n");
    }
    s += "];\ndispatch! {\n";
    for (kind, functions) in
        [("Real", "get_real real_mut f64"), ("Integer", "get_integer integer_mut i32"), ("String", "get_string string_mut String")]
    {
        let fields = |owner: &str| {
            let of: Vec<String> =
                variables.iter().filter(|v| v.kind == kind && v.owner() == owner).map(|v| format!("{} => {}", v.vr, v.a.name)).collect();
            of.join(", ")
        };
        let (p, i, o) = (fields("parameters"), fields("inputs"), fields("outputs"));
        s += &format!("    {functions}: parameters [{p}] inputs [{i}] outputs [{o}];\n");
    }
    s += "}\n";
    s += &format!(
        "/// The table with its dispatch.\npub const DESCRIPTION: Description<Parameters, Inputs, Outputs> = Description {{\n    \
         model_name: {model_name:?},\n    guid: GUID,\n    \
         model_description_xml: include_str!(concat!(env!(\"OUT_DIR\"), \"/{prefix}modelDescription.xml\")),\n    \
         fmi3_model_description_xml: include_str!(concat!(env!(\"OUT_DIR\"), \"/{prefix}fmi3ModelDescription.xml\")),\n    \
         variables: &VARIABLES,\n    get_real,\n    get_integer,\n    get_string,\n    real_mut,\n    integer_mut,\n    string_mut,\n}};\n"
    );
    s
}

/// The struct macros, `Default` for `Parameters` and `Inputs` from the start values, the range checks of
/// `Parameters`, the finiteness check of the Real outputs and, where the table interpolates inputs,
/// `InputDerivatives` with its access by name.
fn contract_rs(variables: &[Resolved], table: &Table) -> String {
    let literal = |kind: &str, text: &str| match kind {
        "Real" => format!("{:?}_f64", text.parse::<f64>().expect("Real number")),
        "Integer" => format!("{}_i32", text.parse::<i32>().expect("Integer number")),
        _ => format!("String::from({text:?})"),
    };
    let mut s = String::new();
    for owner in ["parameters", "inputs", "outputs"] {
        s += &struct_macro(variables, owner);
    }
    for (owner, ty) in [("parameters", "Parameters"), ("inputs", "Inputs")] {
        // A struct without fields derives its Default.
        if !variables.iter().any(|v| v.owner() == owner) {
            continue;
        }
        s += &format!("impl Default for {ty} {{\n    fn default() -> Self {{\n        Self {{\n");
        for v in variables.iter().filter(|v| v.owner() == owner) {
            s += &format!("            {}: {},\n", v.a.name, literal(v.kind, v.a.start.as_deref().unwrap_or_default()));
        }
        s += "        }\n    }\n}\n";
    }
    s += "impl Parameters {\n    /// Every Real parameter finite and within the table's min/max (and > 0 where marked positive);\n";
    s += "    /// every Integer parameter within its min/max.\n    pub(crate) fn check_ranges(&self) -> Result<(), ModelError> {\n";
    for v in variables.iter().filter(|v| v.owner() == "parameters" && v.kind != "String") {
        let (name, unit, positive) = (&v.a.name, v.unit.unwrap_or(""), v.a.positive);
        let bound = |b: &Option<String>| b.as_deref().map_or("None".to_string(), |b| format!("Some({})", literal(v.kind, b)));
        let (min, max) = (bound(&v.a.min), bound(&v.a.max));
        s += &match v.kind {
            "Real" => format!("        check_real({name:?}, self.{name}, {min}, {max}, {positive}, {unit:?})?;\n"),
            _ => format!("        check_integer({name:?}, self.{name}, {min}, {max})?;\n"),
        };
    }
    s += "        Ok(())\n    }\n}\n";
    s += "impl Outputs {\n    /// The first Real output that is not finite, by name: a step that gives one has failed.\n";
    s += "    pub fn first_non_finite(&self) -> Option<(&'static str, f64)> {\n        let values = [\n";
    let reals: Vec<&Resolved> = variables.iter().filter(|v| v.owner() == "outputs" && v.kind == "Real").collect();
    for v in &reals {
        s += &format!("            self.{},\n", v.a.name);
    }
    s += "        ];\n        // One sum clears them all before any is named (an infinite or NaN value makes it infinite or NaN;\n";
    s += "        // finite values that overflow it are looked at one by one below): the values alone, one addition\n";
    s += "        // each, the names only for a step that failed (every step checks its outputs). Four running sums,\n";
    s += "        // so that the additions do not wait on one another.\n";
    s += "        let mut sums = [0.0_f64; 4];\n";
    s += "        for chunk in values.chunks(4) {\n            for (sum, x) in sums.iter_mut().zip(chunk) {\n                *sum += x;\n            }\n        }\n";
    s += "        if ((sums[0] + sums[1]) + (sums[2] + sums[3])).is_finite() {\n            return None;\n        }\n";
    s += "        let names = [\n";
    for v in &reals {
        s += &format!("            {:?},\n", v.a.name);
    }
    s += "        ];\n        names.into_iter().zip(values).find(|(_, x)| !x.is_finite())\n    }\n}\n";
    if table.can_interpolate_inputs == "true" {
        let inputs: Vec<&Resolved> = variables.iter().filter(|v| v.owner() == "inputs" && v.kind == "Real").collect();
        s += "/// Time derivatives of the continuous inputs at the start of a step, `[first, second]` per input\n";
        s += "/// (fmi2SetRealInputDerivatives); zero means held.\n";
        s += "#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]\npub struct InputDerivatives {\n";
        for v in &inputs {
            let unit = v.unit.unwrap_or("1");
            s += &format!("    #[doc = \"{unit}/s, {unit}/s²: of `{}`.\"]\n    pub {}: [f64; 2],\n", v.a.name, v.a.name);
        }
        s += "}\nimpl InputDerivatives {\n    /// Each input's name, value and derivatives, in the table's order.\n";
        s +=
            &format!("    pub fn with_values(&self, inputs: &Inputs) -> [(&'static str, f64, [f64; 2]); {}] {{\n        [\n", inputs.len());
        for v in &inputs {
            s += &format!("            ({:?}, inputs.{}, self.{}),\n", v.a.name, v.a.name, v.a.name);
        }
        s += "        ]\n    }\n\n";
        s += "    /// The derivatives of the input called `name`, if it is one.\n";
        s += "    pub fn of_mut(&mut self, name: &str) -> Option<&mut [f64; 2]> {\n        match name {\n";
        for v in &inputs {
            s += &format!("            {:?} => Some(&mut self.{}),\n", v.a.name, v.a.name);
        }
        s += "            _ => None,\n        }\n    }\n}\n";
    }
    s
}

/// `<owner>_struct!`, declaring a struct (attributes, visibility and name given) with one public field per variable
/// of `owner`, documented by the variable's unit and description, followed by the fields given (those no variable
/// holds).
fn struct_macro(variables: &[Resolved], owner: &str) -> String {
    let mut s = format!("/// Declares the struct of the table's {owner}, one field per variable, then the given fields.\n");
    s += &format!("macro_rules! {owner}_struct {{\n    ($(#[$attribute:meta])* $vis:vis struct $name:ident {{ $($field:tt)* }}) => {{\n");
    s += "        $(#[$attribute])*\n        $vis struct $name {\n";
    for v in variables.iter().filter(|v| v.owner() == owner) {
        // Brackets escaped: rustdoc would read `[bar]` as a link.
        let description = v.a.description.trim_end_matches('.').replace('[', "\\[").replace(']', "\\]");
        let doc = match v.unit {
            Some(unit) => format!("{unit}: {description}."),
            None => format!("{description}."),
        };
        let ty = match v.kind {
            "Real" => "f64",
            "Integer" => "i32",
            _ => "String",
        };
        s += &format!("            #[doc = {doc:?}]\n            pub {}: {ty},\n", v.a.name);
    }
    s += "            $($field)*\n        }\n    };\n}\n";
    s
}

/// The attributes of `pairs` that have a value.
fn present<'a>(pairs: &'a [(&'a str, &'a Option<String>)]) -> impl Iterator<Item = (&'a str, &'a str)> {
    pairs.iter().filter_map(|(k, v)| v.as_deref().map(|v| (*k, v)))
}

fn capitalize(word: &str) -> String {
    let mut chars = word.chars();
    chars.next().map_or_else(String::new, |c| c.to_uppercase().chain(chars).collect())
}
