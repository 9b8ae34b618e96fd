//! Constraint forces of Farahanchi's roller slider crank (eq 2.29) for the thesis's mechanism, as CSV on
//! stdout, for `python -m pistonslap.analysis` (Figs 2.4–2.10):
//!   roller_forces cycle LAMBDA RHO FORCING [SAMPLES]      crank angle, f_u, f_l over one crank cycle
//!   roller_forces regions FORCING RHO_MAX LAMBDA_MAX N    rho, lambda, region on an N×N grid (Fig 2.10)
//! Headers name each column's unit in brackets.
//! FORCING is the FMU's roller_forcing: 1 = f(τ) as printed, 2 = corrected.

use pistonslap::models::{Forcing, RollerMechanism, SlidingRegion};
use std::f64::consts::PI;
use std::process::ExitCode;

/// ξ, α, β of the thesis's Ford engine (section 4.1).
fn thesis_mechanism(forcing: &str) -> Result<RollerMechanism, String> {
    let forcing = match forcing {
        "1" => Forcing::Printed,
        "2" => Forcing::Corrected,
        other => return Err(format!("FORCING must be 1 or 2, got {other}")),
    };
    Ok(RollerMechanism { xi: 0.3030, alpha: 1.9, beta: 0.4719, forcing })
}

fn number(text: &str, name: &str) -> Result<f64, String> {
    text.parse::<f64>().ok().filter(|x| x.is_finite()).ok_or(format!("{name} must be a number, got {text}"))
}

fn run(args: &[String]) -> Result<(), String> {
    match args {
        [cmd, lambda, rho, forcing, rest @ ..] if cmd == "cycle" && rest.len() <= 1 => {
            let sc = thesis_mechanism(forcing)?;
            let (lambda, rho) = (number(lambda, "LAMBDA")?, number(rho, "RHO")?);
            let samples = rest.first().map(|s| number(s, "SAMPLES")).transpose()?.unwrap_or(720.0) as usize;
            println!("crank_angle [rad],f_u [thesis units],f_l [thesis units]");
            for k in 0..=samples {
                let theta = 2.0 * PI * k as f64 / samples as f64;
                let (fu, fl) = sc.constraint_forces(theta, lambda, rho);
                println!("{theta},{fu},{fl}");
            }
            Ok(())
        }
        [cmd, forcing, rho_max, lambda_max, n] if cmd == "regions" => {
            let sc = thesis_mechanism(forcing)?;
            let (rho_max, lambda_max, n) = (number(rho_max, "RHO_MAX")?, number(lambda_max, "LAMBDA_MAX")?, number(n, "N")? as usize);
            println!("rho [1],lambda [1],region [none, I, II or III]");
            for i in 0..=n {
                for j in 0..=n {
                    let (rho, lambda) = (rho_max * i as f64 / n as f64, lambda_max * j as f64 / n as f64);
                    let region = match sc.sliding_region(lambda, rho, 1440) {
                        SlidingRegion::Both => "I",
                        SlidingRegion::UpperAlwaysLowerSometimes => "II",
                        SlidingRegion::UpperOnly => "III",
                        SlidingRegion::Other => "none",
                    };
                    println!("{rho},{lambda},{region}");
                }
            }
            Ok(())
        }
        _ => Err("usage: roller_forces cycle LAMBDA RHO FORCING [SAMPLES] | regions FORCING RHO_MAX LAMBDA_MAX N".into()),
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("roller_forces: {message}");
            ExitCode::FAILURE
        }
    }
}
