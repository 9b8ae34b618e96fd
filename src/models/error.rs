//! The error both FMUs' models return, and the range checks of their parameters.

use std::fmt;

/// A refused parameter set or a failed step, with a message naming the cause.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelError(pub String);

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ModelError {}

/// `value` of the parameter `name` (in `unit`) finite, within `[min, max]` and, where `positive`, above 0;
/// otherwise the refusal naming it.
pub fn check_real(name: &str, value: f64, min: Option<f64>, max: Option<f64>, positive: bool, unit: &str) -> Result<(), ModelError> {
    let refuse = |range: String| {
        Err(ModelError(format!("{name} = {value}{}{unit} is out of range: {range}", if unit.is_empty() { "" } else { " " })))
    };
    if !value.is_finite() {
        return refuse("must be finite".into());
    }
    if positive && value <= 0.0 {
        return refuse(format!("must be > 0 {unit}"));
    }
    match (min, max) {
        (Some(lo), Some(hi)) if !(lo..=hi).contains(&value) => refuse(format!("must be in [{lo}, {hi}]")),
        (Some(lo), _) if value < lo => refuse(format!("must be ≥ {lo} {unit}")),
        (_, Some(hi)) if value > hi => refuse(format!("must be ≤ {hi} {unit}")),
        _ => Ok(()),
    }
}

/// Refuses an integer `name` outside `[min, max]`, naming it and the range.
pub fn check_integer(name: &str, value: i32, min: Option<i32>, max: Option<i32>) -> Result<(), ModelError> {
    let below = min.is_some_and(|lo| value < lo);
    let above = max.is_some_and(|hi| value > hi);
    if below || above {
        let lo = min.map_or("−∞".to_string(), |v| v.to_string());
        let hi = max.map_or("∞".to_string(), |v| v.to_string());
        return Err(ModelError(format!("{name} = {value} is not one of {lo}..={hi}")));
    }
    Ok(())
}

/// `Ok` where `ok`, otherwise the refusal `message` gives.
pub fn check(ok: bool, message: impl FnOnce() -> String) -> Result<(), ModelError> {
    if ok {
        Ok(())
    } else {
        Err(ModelError(message()))
    }
}
