//! The outputs of the piston's skirt against the liner: with the lubricated skirt its film,
//! asperity and friction loads and the work it absorbed; dry, the corners' gaps as the film
//! thickness and zero loads. The side force is the liner's net lateral force in either case.
//!
//! The asperities are elastic: the work their load takes from the motion is stored, not
//! dissipated, and comes back as the skirt leaves the liner. Their energy is potential energy
//! (`potential_energy`), and the skirt's absorbed work less its change since the start is what the
//! film and the friction dissipated (`film_energy_total`), so that neither total falls as the
//! asperities unload. The work of the film's relaxation term (`books::IMPLICIT`) is no
//! dissipation either: it is `film_relaxation_work`.

use crate::fmus::piston_slap::Outputs;
use crate::models::crank_train::books::{FILM, IMPLICIT, SKIRT_FRICTION, WALL_PUSH};
use crate::models::crank_train::linkage::LinkAngles;
use crate::models::CrankTrain;
use nalgebra::{Vector3, Vector4};

/// Writes the skirt's outputs and `side_force` at (φ, φ̇), the corners' gaps `gaps` and contact
/// forces `forces` (K1, K2 on the −D/2 wall push toward +x, K3, K4 toward −x); after the
/// corners' friction outputs and impulses, which `liner_friction_work` and
/// `liner_impulse_total` add to.
pub(super) fn write(
    model: &CrankTrain,
    (phi, trig, phid): (&Vector3<f64>, &LinkAngles, &Vector3<f64>),
    gaps: &Vector4<f64>,
    forces: &Vector4<f64>,
    out: &mut Outputs,
) {
    let corners = forces[0] + forces[1] - forces[2] - forces[3];
    let linkage = &model.engine().linkage;
    // Each wall's load and its moment about the skirt top: the corners in contact, and the film
    // and asperities on that side.
    let pressed = forces.map(|f| f.max(0.0));
    let depths = linkage.corner_depths();
    let moment = |i: usize, j: usize| pressed[i] * depths[i] + pressed[j] * depths[j];
    let mut walls = [(pressed[0] + pressed[1], moment(0, 1)), (pressed[2] + pressed[3], moment(2, 3))];
    let Some(lubrication) = &model.engine().lubrication else {
        write_walls(walls, out);
        out.side_force = corners;
        [out.min_film_thickness_thrust, out.min_film_thickness_antithrust] = [gaps[2].min(gaps[3]), gaps[0].min(gaps[1])];
        out.liner_friction_work = out.friction_energy_total;
        return;
    };
    let loads = lubrication.loads_at((phi, trig), phid);
    let work = model.drive.stepper().energies();
    out.side_force = corners + loads.lateral_force;
    [out.min_film_thickness_thrust, out.min_film_thickness_antithrust] = loads.min_film;
    (out.film_force, out.asperity_force) = (loads.film_force, loads.asperity_force);
    out.skirt_friction_force = loads.friction_force;
    out.skirt_friction_power = lubrication.friction_power((phi, trig), phid);
    out.film_energy_total = work[FILM] - (loads.asperity_energy - model.asperity_energy_start);
    out.potential_energy += loads.asperity_energy;
    out.film_relaxation_work = work[IMPLICIT];
    out.skirt_wetted_fraction = lubrication.wetted_fraction(model.time());
    out.oil_left_on_liner = lubrication.oil().map_or(0.0, |oil| oil.liner / oil.area);
    (out.film_peak_pressure, out.skirt_max_deflection) = lubrication.film_peaks((phi, trig), phid);
    // A side's moment about the pin is its push times the height above the pin (thrust), or
    // minus that (anti-thrust): about the skirt top, the push times the pin's depth less it.
    let pin = linkage.pin_depth();
    let [thrust, anti] = [loads.wall_push[0], loads.wall_push[1]];
    walls[0] = (walls[0].0 + anti, walls[0].1 + anti * pin + loads.wall_moment[1]);
    walls[1] = (walls[1].0 + thrust, walls[1].1 + thrust * pin - loads.wall_moment[0]);
    write_walls(walls, out);
    out.liner_friction_work = out.friction_energy_total + work[SKIRT_FRICTION];
    // The walls' film and asperity impulses join the corners' (anti-thrust, thrust).
    out.liner_impulse_total = [0, 1].map(|w| out.liner_impulse_total[w] + work[WALL_PUSH[w]]);
}

/// Writes each wall's load and moment about the skirt top, [anti-thrust, thrust], and the depth
/// below the skirt top of the larger load's point of application (0 while neither wall is loaded).
fn write_walls([anti, thrust]: [(f64, f64); 2], out: &mut Outputs) {
    [out.liner_force_antithrust, out.liner_moment_antithrust] = [anti.0, anti.1];
    [out.liner_force_thrust, out.liner_moment_thrust] = [thrust.0, thrust.1];
    let (force, moment) = if thrust.0 >= anti.0 { thrust } else { anti };
    out.liner_force_height = if force > 0.0 { moment / force } else { 0.0 };
}
