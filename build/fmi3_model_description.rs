//! The FMI 3.0 model description written from the same variable table as the FMI 2.0 one: the same
//! value references, units, types, start values and dependencies, in FMI 3.0's elements (`Float64`, `Int32`,
//! `String`, `Output` and `InitialUnknown` by value reference), with the independent variable `time`, whose
//! value reference is the table's length (the glue's `Description::time_value_reference`).

use super::model_description::{
    borrowed, common_root, document, empty, generation_date_and_time, output_dependencies, parent, type_attributes, value_attributes,
    variable_attributes, write_log_categories_and_experiment, write_units, Xml,
};
use super::*;

/// FMI 3.0's element of a table's kind.
fn element(kind: &str) -> &'static str {
    match kind {
        "Real" => "Float64",
        "Integer" => "Int32",
        _ => "String",
    }
}

pub(super) fn fmi3_model_description(table: &Table, variables: &[Resolved], token: &str, path: &str) -> io::Result<Vec<u8>> {
    assert!(table.units.items.iter().any(|u| u.name == "s"), "{path}: the independent variable time needs the unit s");
    let generated = generation_date_and_time();
    let mut root = vec![("fmiVersion", "3.0"), ("modelName", table.model_name.as_str()), ("instantiationToken", token)];
    root.extend(common_root(table, &generated));
    document(&root, path, variables, |w| {
        // Early return and Event Mode stay off: doStep always reaches the communication point, and the
        // contact states and counts change only inside a step.
        let capabilities = [
            ("modelIdentifier", table.model_name.as_str()),
            ("needsExecutionTool", "false"),
            ("canBeInstantiatedOnlyOncePerProcess", "false"),
            ("canGetAndSetFMUState", "true"),
            ("canSerializeFMUState", "true"),
            ("providesDirectionalDerivatives", "false"),
            ("providesAdjointDerivatives", "false"),
            ("canHandleVariableCommunicationStepSize", "true"),
            ("maxOutputDerivativeOrder", table.max_output_derivative_order.as_str()),
            ("providesIntermediateUpdate", "false"),
            ("mightReturnEarlyFromDoStep", "false"),
            ("canReturnEarlyAfterIntermediateUpdate", "false"),
            ("hasEventMode", "false"),
        ];
        empty(w, "CoSimulation", capabilities)?;
        write_units(w, table)?;
        parent(w, "TypeDefinitions", [], |w| {
            table
                .types
                .items
                .iter()
                .try_for_each(|t| empty(w, "Float64Type", [("name", t.name.as_str())].into_iter().chain(type_attributes(t))))
        })?;
        write_log_categories_and_experiment(w, table)?;
        write_variables(w, variables)?;
        write_structure(w, variables)
    })
}

fn write_variables(w: &mut Xml, variables: &[Resolved]) -> io::Result<()> {
    parent(w, "ModelVariables", [], |w| {
        let time = variables.len().to_string();
        let independent = [
            ("name", "time"),
            ("valueReference", time.as_str()),
            ("description", "Simulation time"),
            ("causality", "independent"),
            ("variability", "continuous"),
            ("unit", "s"),
        ];
        empty(w, "Float64", independent)?;
        variables.iter().try_for_each(|v| {
            let mut attributes = variable_attributes(v);
            let value = value_attributes(v);
            if v.kind == "String" {
                // A String's start is a child element (FMI 3.0 strings may be arrays).
                attributes.extend(value.into_iter().filter(|(k, _)| *k != "start"));
                parent(w, "String", borrowed(&attributes), |w| empty(w, "Start", [("value", v.a.start.as_deref().unwrap_or(""))]))
            } else {
                attributes.extend(value);
                empty(w, element(v.kind), borrowed(&attributes))
            }
        })
    })
}

/// FMI 3.0's structure: the outputs and initial unknowns by value reference.
fn write_structure(w: &mut Xml, variables: &[Resolved]) -> io::Result<()> {
    let outputs = output_dependencies(variables, |v| v.vr.to_string());
    parent(w, "ModelStructure", [], |w| {
        outputs.iter().try_for_each(|(vr, _)| empty(w, "Output", [("valueReference", vr.as_str()), ("dependencies", "")]))?;
        outputs
            .iter()
            .try_for_each(|(vr, deps)| empty(w, "InitialUnknown", [("valueReference", vr.as_str()), ("dependencies", deps.as_str())]))
    })
}
