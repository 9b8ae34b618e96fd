//! The FMI 2.0 model description written from a variable table (`modelDescription.xml` of the FMU), its
//! GUID and its generation date, and the XML writing both versions' descriptions share.

use super::*;

/// When the XML is generated, as FMI's xs:dateTime in UTC: `SOURCE_DATE_EPOCH` (seconds) when set,
/// for reproducible builds, else now.
pub(super) fn generation_date_and_time() -> String {
    let seconds = std::env::var("SOURCE_DATE_EPOCH").ok().and_then(|s| s.parse::<u64>().ok()).unwrap_or_else(|| {
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
pub(super) fn guid_of(source: &str) -> String {
    let seed = format!("{}\n{}", env!("CARGO_PKG_VERSION"), source);
    let hash = |basis: u64| seed.bytes().fold(basis, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3));
    let (a, b) = (hash(0xcbf2_9ce4_8422_2325), hash(0x6c62_272e_07bb_0142));
    format!("{{{:08x}-{:04x}-{:04x}-{:04x}-{:012x}}}", a >> 32, (a >> 16) & 0xffff, a & 0xffff, b >> 48, b & 0xffff_ffff_ffff)
}

pub(super) type Xml = Writer<Vec<u8>>;

/// `<name attributes/>`.
pub(super) fn empty<'a>(w: &mut Xml, name: &str, attributes: impl IntoIterator<Item = (&'a str, &'a str)>) -> io::Result<()> {
    w.create_element(name).with_attributes(attributes).write_empty()?;
    Ok(())
}

/// `<name attributes>inner</name>`.
pub(super) fn parent<'a>(
    w: &mut Xml,
    name: &str,
    attributes: impl IntoIterator<Item = (&'a str, &'a str)>,
    inner: impl FnOnce(&mut Xml) -> io::Result<()>,
) -> io::Result<()> {
    w.create_element(name).with_attributes(attributes).write_inner_content(inner)?;
    Ok(())
}

/// The document both FMI versions write: the XML declaration and the root `fmiModelDescription` with
/// `root`'s attributes, opened by a comment naming the table; `inner` writes the elements.
pub(super) fn document(
    root: &[(&str, &str)],
    path: &str,
    variables: &[Resolved],
    inner: impl FnOnce(&mut Xml) -> io::Result<()>,
) -> io::Result<Vec<u8>> {
    let mut w = Writer::new_with_indent(Vec::new(), b' ', 2);
    w.write_event(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)))?;
    parent(&mut w, "fmiModelDescription", root.iter().copied(), |w| {
        let comment = format!(" generated from {path}: {} variables ", variables.len());
        w.write_event(Event::Comment(BytesText::new(&comment)))?;
        inner(w)
    })?;
    let mut xml = w.into_inner();
    xml.push(b'\n');
    Ok(xml)
}

/// The root attributes both versions share after `fmiVersion`, `modelName` and the table's fingerprint:
/// (name, value).
pub(super) fn common_root<'a>(table: &'a Table, generated: &'a str) -> [(&'a str, &'a str); 6] {
    [
        ("description", table.description.as_str()),
        ("version", env!("CARGO_PKG_VERSION")),
        ("license", "MIT"),
        ("generationTool", "PistonSlap build.rs"),
        ("generationDateAndTime", generated),
        ("variableNamingConvention", "flat"),
    ]
}

pub(super) fn model_description(table: &Table, variables: &[Resolved], guid: &str, path: &str) -> io::Result<Vec<u8>> {
    let generated = generation_date_and_time();
    let mut root = vec![("fmiVersion", "2.0"), ("modelName", table.model_name.as_str()), ("guid", guid)];
    root.extend(common_root(table, &generated));
    root.push(("numberOfEventIndicators", "0"));
    document(&root, path, variables, |w| {
        let capabilities = [
            ("modelIdentifier", table.model_name.as_str()),
            ("needsExecutionTool", "false"),
            ("canHandleVariableCommunicationStepSize", "true"),
            ("canInterpolateInputs", table.can_interpolate_inputs.as_str()),
            ("maxOutputDerivativeOrder", table.max_output_derivative_order.as_str()),
            ("canRunAsynchronuously", "false"),
            ("canBeInstantiatedOnlyOncePerProcess", "false"),
            ("canNotUseMemoryManagementFunctions", "true"),
            ("canGetAndSetFMUstate", "true"),
            ("canSerializeFMUstate", "true"),
            ("providesDirectionalDerivative", "false"),
        ];
        empty(w, "CoSimulation", capabilities)?;
        write_units(w, table)?;
        parent(w, "TypeDefinitions", [], |w| {
            table
                .types
                .items
                .iter()
                .try_for_each(|t| parent(w, "SimpleType", [("name", t.name.as_str())], |w| empty(w, "Real", type_attributes(t))))
        })?;
        write_log_categories_and_experiment(w, table)?;
        write_variables(w, variables)?;
        write_structure(w, variables)
    })
}

/// A declared type's quantity, unit and display unit, as both versions' type definitions give them.
pub(super) fn type_attributes(t: &TypeDef) -> impl Iterator<Item = (&str, &str)> {
    let display_unit = t.display_unit.as_deref().map(|d| ("displayUnit", d));
    [("quantity", t.quantity.as_str()), ("unit", t.unit.as_str())].into_iter().chain(display_unit)
}

/// `LogCategories` and `DefaultExperiment`, alike in both versions.
pub(super) fn write_log_categories_and_experiment(w: &mut Xml, table: &Table) -> io::Result<()> {
    parent(w, "LogCategories", [], |w| {
        LOG_CATEGORIES.iter().try_for_each(|&(name, description)| empty(w, "Category", [("name", name), ("description", description)]))
    })?;
    let e = &table.experiment;
    empty(w, "DefaultExperiment", [("startTime", e.start.as_str()), ("stopTime", e.stop.as_str()), ("stepSize", e.step.as_str())])
}

/// Log categories: (name, description). The FMI layer accepts exactly these in fmi2SetDebugLogging.
pub(super) const LOG_CATEGORIES: [(&str, &str); 3] = [
    ("logStatusError", "Errors: refused calls, bad parameters, failed steps"),
    ("logStatusFatal", "Fatal errors: a caught panic; the instance must be freed"),
    ("logEvents", "Debug: events during doStep (PistonSlap: impacts and sliding starts/releases)"),
];

/// `UnitDefinitions`, alike in both versions.
pub(super) fn write_units(w: &mut Xml, table: &Table) -> io::Result<()> {
    parent(w, "UnitDefinitions", [], |w| {
        table.units.items.iter().try_for_each(|u| {
            parent(w, "Unit", [("name", u.name.as_str())], |w| {
                empty(w, "BaseUnit", present(&[("kg", &u.kg), ("m", &u.m), ("s", &u.s), ("K", &u.kelvin), ("rad", &u.rad)]))?;
                u.display.iter().try_for_each(|d| empty(w, "DisplayUnit", [("name", d.name.as_str()), ("factor", d.factor.as_str())]))
            })
        })
    })
}

/// A variable's own attributes: name, value reference, description, causality, variability and, for
/// parameters, initial (FMI 2.0 writes them on `ScalarVariable`, FMI 3.0 on the type element).
pub(super) fn variable_attributes(v: &Resolved) -> Vec<(&'static str, String)> {
    let a = v.a;
    let mut attributes = vec![
        ("name", a.name.clone()),
        ("valueReference", v.vr.to_string()),
        ("description", a.description.clone()),
        ("causality", a.causality.clone()),
        ("variability", v.variability().to_string()),
    ];
    if a.causality == "parameter" {
        attributes.push(("initial", "exact".to_string()));
    }
    attributes
}

/// A variable's value attributes that the table gives: declared type, unit, display unit, start, min, max.
/// unit and displayUnit repeat the declared type's: hosts that do not resolve declaredType (fmpy's
/// ModelVariable.unit) still see them.
pub(super) fn value_attributes(v: &Resolved) -> Vec<(&'static str, String)> {
    let a = v.a;
    let (unit, display_unit) = (v.unit.map(str::to_string), v.display_unit.map(str::to_string));
    let optional = [
        ("declaredType", &a.declared_type),
        ("unit", &unit),
        ("displayUnit", &display_unit),
        ("start", &a.start),
        ("min", &a.min),
        ("max", &a.max),
    ];
    optional.into_iter().filter_map(|(k, v)| v.clone().map(|v| (k, v))).collect()
}

/// `(name, value)` pairs as the writer takes them.
pub(super) fn borrowed<'a>(attributes: &'a [(&'a str, String)]) -> impl Iterator<Item = (&'a str, &'a str)> {
    attributes.iter().map(|(k, v)| (*k, v.as_str()))
}

fn write_variables(w: &mut Xml, variables: &[Resolved]) -> io::Result<()> {
    parent(w, "ModelVariables", [], |w| {
        variables.iter().try_for_each(|v| {
            let (own, value) = (variable_attributes(v), value_attributes(v));
            parent(w, "ScalarVariable", borrowed(&own), |w| empty(w, v.kind, borrowed(&value)))
        })
    })
}

/// Per output, its reference (`reference` of it) and its initial dependencies: with initialDeps="knowns" the
/// references of every input and parameter but the strings, none otherwise. Outputs are computed at the end
/// of each doStep from the state, so during the run they depend on no input (no direct feedthrough).
/// Initially the impact statistics are constants, the kinematics and forces depend on the inputs and the
/// parameters (except the file names).
pub(super) fn output_dependencies(variables: &[Resolved], reference: impl Fn(&Resolved) -> String) -> Vec<(String, String)> {
    let knowns: Vec<String> = variables
        .iter()
        .filter(|v| matches!(v.a.causality.as_str(), "input" | "parameter") && v.kind != "String")
        .map(&reference)
        .collect();
    let knowns = knowns.join(" ");
    let outputs = variables.iter().filter(|v| v.a.causality == "output");
    outputs.map(|v| (reference(v), if v.a.initial_deps.as_deref() == Some("knowns") { knowns.clone() } else { String::new() })).collect()
}

/// FMI 2.0's structure: the outputs and initial unknowns by index (value reference + 1).
fn write_structure(w: &mut Xml, variables: &[Resolved]) -> io::Result<()> {
    let outputs = output_dependencies(variables, |v| (v.vr + 1).to_string());
    let unknowns = |w: &mut Xml, name: &str, initial: bool| {
        parent(w, name, [], |w| {
            outputs.iter().try_for_each(|(index, deps)| {
                empty(w, "Unknown", [("index", index.as_str()), ("dependencies", if initial { deps.as_str() } else { "" })])
            })
        })
    };
    parent(w, "ModelStructure", [], |w| {
        unknowns(w, "Outputs", false)?;
        unknowns(w, "InitialUnknowns", true)
    })
}
