//! Random designs (`designs.rs`) run through the FMU's exported C functions, as a host runs them: every
//! parameter set by name, the inputs and their derivatives set before every communication step, the
//! outputs read and checked after it (`output_checks`), the state saved halfway, restored into a second
//! instance and continued there bit for bit.

use super::designs::Design;
use super::fmu_host::Host;
use super::output_checks::contradiction;

/// Steps the restored instance runs beside the original.
const CONTINUED_STEPS: usize = 3;

/// Why a design did not run through: refused at initialization (a design outside what the FMU accepts),
/// or failed after it.
#[derive(Debug)]
pub enum NotRun {
    Refused(String),
    Failed(String),
}

/// Runs `design` to its end through the FMU; the communication steps it took.
pub fn run(design: &Design) -> Result<usize, NotRun> {
    let host = Host::start(&design.params).map_err(NotRun::Refused)?;
    let failed = |t: f64| move |e: String| NotRun::Failed(format!("at t = {t} s: {e}"));
    let points = design.points();
    let mut before = host.outputs().map_err(failed(0.0))?;
    contradiction(&design.params, &before, &before).map_or(Ok(()), |e| Err(failed(0.0)(e)))?;
    let mut twin: Option<Host> = None;
    for (k, &t_end) in points.iter().enumerate() {
        let t = if k == 0 { 0.0 } else { points[k - 1] };
        if k + 1 == points.len().div_ceil(2) {
            twin = Some(restored(&host, design).map_err(failed(t))?);
        }
        let step = |h: &Host| {
            h.set_inputs(&design.inputs_at(t), &design.derivatives)?;
            h.do_step(t, t_end - t)?;
            h.outputs()
        };
        let now = step(&host).map_err(failed(t))?;
        contradiction(&design.params, &before, &now).map_or(Ok(()), |e| Err(failed(t_end)(e)))?;
        if let Some(other) = &twin {
            let continued = step(other).map_err(|e| failed(t)(format!("restored: {e}")))?;
            if continued.iter().zip(&now).any(|(a, b)| a.to_bits() != b.to_bits()) {
                return Err(failed(t_end)(format!("a restored state continues otherwise:\n  {continued:?}\nnot\n  {now:?}")));
            }
            // The twin was made at k + 1 == half: after its last step, dropped.
            if k + 2 == points.len().div_ceil(2) + CONTINUED_STEPS {
                twin = None;
            }
        }
        before = now;
    }
    Ok(points.len())
}

/// A second instance of `design` given `host`'s state through fmi2GetFMUstate, fmi2SerializeFMUstate,
/// fmi2DeSerializeFMUstate and fmi2SetFMUstate.
fn restored(host: &Host, design: &Design) -> Result<Host, String> {
    let bytes = host.saved()?;
    let other = Host::start(&design.params).map_err(|e| format!("a second instance refused: {e}"))?;
    other.restore(&bytes)?;
    Ok(other)
}
