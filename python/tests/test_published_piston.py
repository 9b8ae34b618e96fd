"""A published piston case: the diesel of Y. J. Lu, S. Li, P. Wang, C. Liu, Y. Zhang, N. Müller, "The Analysis of
Secondary Motion and Lubrication Performance of Piston considering the Piston Skirt Profile", Shock and Vibration 2018,
article 3240469 (open access), on its oil film: preset `lu2018-diesel-oil` (Table 2's engine and oil).

Only the paper's abstract and Table 2 could be read (no stored source holds its body, figures or profile tables), so
the trends asserted are the ones its abstract states, about the skirt profile: a parabolic (barrel) longitudinal
profile, a smaller top radial reduction and a bigger bottom one reduce the secondary displacement and velocity, the
skirt thrust, the friction and the friction power loss. Where this model differs, the test says so:
- a bigger bottom reduction gives the skirt's bottom more room, and the rigid piston uses it (its bottom eccentricity
  grows), while the friction loss falls as stated;
- a smaller top reduction lowers the top eccentricity as stated but leaves the friction loss within 1.3 %;
- the peak side force ("skirt thrust") is the gas load through the rod (7.1 kN here) whatever the profile.
Likely reasons: the paper's JFO mass-conserving cavitation and averaged (flow-factor) Reynolds equation against the
Reynolds condition here, its thermal deformation, its cylinder pressure (not in Table 2: the built-in curve at 80 bar
stands) and its unknown baseline profile (the FMU's default barrel, 10 µm top / 20 µm bottom, stands).

Two engine cycles from the centred start at 1680 rpm, the second measured (the third repeats its eccentricities
and speeds to 1e-4); the coarse 6 × 8 film grid keeps the runs short: at 12 × 18 every figure compared
below moves by under 1 % (FMEP 0.05096 against 0.05120 bar, top eccentricity 36.65 against 36.48 µm) while the
differences asserted are 2.5 % and more.
"""

import numpy as np
import pytest

from pistonslap.fmu import CYCLE
from pistonslap.validation import LU_ON_OIL as ENGINE
from pistonslap.validation import barrel, second_cycle

OMEGA = ENGINE["crank_speed"]
CLEARANCE = (ENGINE["bore"] - ENGINE["piston_diameter"]) / 2
#: rad, the FMU's default skirt_arc (the preset keeps it).
SKIRT_ARC = np.radians(70)


def test_the_barrel_skirt_lowers_the_friction_loss_and_the_lateral_velocity():
    """Abstract: the parabolic longitudinal profile reduces the secondary velocity and the friction power loss.
    Against a straight skirt, the default barrel (10/20 µm) lowers the skirt FMEP by 7.6 % (0.0510 against 0.0551
    bar) and the pin's peak lateral speed by 14 % (13.8 against 16.0 mm/s)."""
    straight, straight_fmep = second_cycle(barrel(0, 0))
    shaped, shaped_fmep = second_cycle(barrel(10, 20))
    assert shaped_fmep < 0.97 * straight_fmep
    speed = {
        name: np.max(np.abs(c["piston_lateral_velocity"])) for name, c in (("straight", straight), ("barrel", shaped))
    }
    assert speed["barrel"] < 0.93 * speed["straight"]


def test_a_smaller_top_drop_keeps_the_skirt_top_closer_to_the_axis():
    """Abstract: a smaller top radial reduction reduces the secondary displacement. The top eccentricity's peak toward
    the thrust wall (bottom drop 20 µm) is 30.9, 36.6 and 47.5 µm at top drops of 5, 10 and 20 µm: each step at least
    10 % (measured 18 and 30 %). Where this model differs: the paper also states a lower friction loss; here the
    FMEP moves by 1.3 % over the three, so it is held within 2 %."""
    runs = [second_cycle(barrel(top, 20)) for top in (5, 10, 20)]
    peaks = [np.max(c["skirt_top_lateral"]) for c, _ in runs]
    assert peaks[1] > 1.1 * peaks[0] and peaks[2] > 1.1 * peaks[1]
    fmep = [f for _, f in runs]
    assert max(fmep) < 1.02 * min(fmep)


def test_a_bigger_bottom_drop_lowers_the_friction_loss():
    """Abstract: a bigger bottom radial reduction reduces the friction power loss. Skirt FMEP 0.0522, 0.0510 and
    0.0490 bar at bottom drops of 10, 20 and 40 µm (top 10 µm): each step at least 1 % lower (measured 2.5 and 3.9 %,
    against a grid error of 0.5 %). Where this model differs: the paper states a smaller secondary displacement too;
    here the rigid skirt's bottom swings into the room the drop gives (toward the anti-thrust wall 13.6, 22.8 and
    43.9 µm), never beyond the clearance plus the drop."""
    runs = {bottom: second_cycle(barrel(10, bottom)) for bottom in (10, 20, 40)}
    fmep = [runs[b][1] for b in (10, 20, 40)]
    assert fmep[1] < 0.99 * fmep[0] and fmep[2] < 0.99 * fmep[1]
    swing = {b: -np.min(c["skirt_bottom_lateral"]) for b, (c, _) in runs.items()}
    assert swing[10] < swing[20] < swing[40]
    for b, reach in swing.items():
        assert reach < CLEARANCE + b * 1e-6


def test_the_piston_changes_sides_at_firing_tdc_and_its_friction_follows_the_stroke():
    """The secondary motion and friction shape of the default barrel (the trend every hydrodynamic skirt study shows;
    the paper's own figures could not be read): the film's side force turns from the anti-thrust to the thrust wall
    within 5° of firing TDC and the skirt top stays on the thrust side from 20° to 380° after it; the skirt friction
    opposes the piston wherever it moves at more than 20 % of its top speed, and its peak is within 25 % of the
    Couette estimate μ·U·A/c (both sides' arcs A = 2·arc·R·L at the radial clearance c: 16.6 N; measured 18.4 N,
    +11 %, the loaded side's film being the thinner)."""
    cycle, _ = second_cycle(barrel(10, 20))
    angle = np.degrees(cycle["crank_angle"] - CYCLE)
    force = cycle["film_force"]
    before, after = force[(angle > 700) & (angle < 715)], force[(angle > 5) & (angle < 20)]
    assert np.all(before > 0) and np.all(after < 0)
    firing = force[(angle < 5) | (angle > 715)]
    assert np.any(firing > 0) and np.any(firing < 0)
    assert np.all(cycle["skirt_top_lateral"][(angle > 20) & (angle < 380)] > 0)

    velocity = np.gradient(cycle["piston_axial"], cycle["crank_angle"]) * OMEGA
    fast = np.abs(velocity) > 0.2 * np.max(np.abs(velocity))
    assert np.all(np.sign(cycle["skirt_friction_force"][fast]) == -np.sign(velocity[fast]))
    area = 2 * SKIRT_ARC * ENGINE["piston_diameter"] / 2 * ENGINE["skirt_length"]
    couette = ENGINE["oil_viscosity"] * np.max(np.abs(velocity)) * area / CLEARANCE
    assert np.max(np.abs(cycle["skirt_friction_force"])) == pytest.approx(couette, rel=0.25)
