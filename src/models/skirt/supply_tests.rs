//! The limited oil supply against closed forms: the starved plane slider's load against the flooded
//! one's, the flow balance of a starved solve through its edges, the liner's exchange, and a liner
//! film thicker than the gap feeding the flooded film.

use super::fill::partial;
use super::fill_tests::{relative, Slider, VISCOSITY};
use super::reynolds::{EdgeFlows, Grid};
use super::supply::Liner;
use super::{CavitationCondition, OilSupply, Skirt, SkirtDesign, SkirtMotion};

const LENGTH: f64 = 1e-2;
const INLET: f64 = 30e-6;
const OUTLET: f64 = 10e-6;
const SPEED: f64 = 0.5;

/// The plane slider: the gap falls linearly from `INLET` to `OUTLET` along the sliding.
fn plane(x: f64) -> f64 {
    INLET - (INLET - OUTLET) * x / LENGTH
}

/// The load per metre of width of a flooded plane slider from gap `h1` (p = 0) to `h0` (p = 0) of
/// this slope, under a mean surface velocity u: with the sliding speed U = 2u, `dp/dx = 6μU (h − h*)/h³`
/// integrates to `W = 6μU (L/(K − 1))² / h0² · (ln K − 2 (K − 1)/(K + 1))`, K = h1/h0, L/(K − 1) =
/// h0 · LENGTH/(INLET − OUTLET) the same for every h1 of the slope.
fn flooded_load(h1: f64) -> f64 {
    let k = h1 / OUTLET;
    let run = OUTLET * LENGTH / (INLET - OUTLET);
    6.0 * VISCOSITY * 2.0 * SPEED * run * run / (OUTLET * OUTLET) * (libm::log(k) - 2.0 * (k - 1.0) / (k + 1.0))
}

/// A starved slider of supply `supply` (m) marched from flooded at steps of 2 cells' transit of the
/// thinnest film's share of the thickest (the fill's own outflow implicit: stable at any step), well
/// past the transit that drains the flooded start; its load's mean and spread (largest
/// less least over the mean) over a further 4 transits. A front that ends between two nodes keeps
/// moving the cell it crosses between full and partly filled, so the march settles to a small
/// oscillation rather than a state.
fn settled(supply: f64) -> (Slider, f64, f64) {
    let mut slider = Slider::new(399, LENGTH, plane, SPEED, 0.0);
    slider.supply = Some(supply);
    let (n, dt) = (slider.grid.nx, 2.0 * slider.grid.dx() / SPEED * OUTLET / INLET);
    for _ in 0..40 * n {
        slider.solve();
        slider.advance(dt);
    }
    let (mut sum, mut low, mut high) = (0.0, f64::INFINITY, 0.0_f64);
    for _ in 0..4 * n {
        slider.solve();
        let load = slider.load();
        (sum, low, high) = (sum + load, low.min(load), high.max(load));
        slider.advance(dt);
    }
    let mean = sum / (4 * n) as f64;
    (slider, mean, (high - low) / mean)
}

#[test]
fn a_starved_plane_slider_carries_the_load_of_its_effective_inlet() {
    // A supply l (m³ per m² on the liner) enters as streamers of content l, the flow u·l (JFO: one flow
    // through cavitated and full zones). The full film starts at the front where the flooded slider
    // beyond it passes that flow: from gap h_s to the outlet h0 a plane slider passes u·2 h_s h0/(h_s +
    // h0), so 2 h_s h0/(h_s + h0) = l, h_s = l h0/(2 h0 − l) (not where the gap is l: the front's
    // pressure gradient is not zero, the full film's Couette flow u h_s exceeding u l). The load is the
    // flooded slider's from h_s; with l ≥ 2 h1 h0/(h1 + h0) the inlet is flooded, and with l ≤ h0 the
    // streamers never fill the gap (no load).
    let mut flooded = Slider::new(399, LENGTH, plane, SPEED, 0.0);
    flooded.steady(0.4);
    // The flooded slider itself against the closed form (measured 1.9e-5 at 400 cells).
    assert!(relative(flooded.load(), flooded_load(INLET)) < 1e-4, "flooded {} vs {}", flooded.load(), flooded_load(INLET));
    for supply in [11e-6, 12e-6, 13e-6, 14e-6] {
        let front = supply * OUTLET / (2.0 * OUTLET - supply);
        let exact = flooded_load(front);
        let (starved, load, spread) = settled(supply);
        // The front lies within a cell, resolved to it (measured: 3.8e-4, 1.9e-4, 5.6e-5 and 4.0e-3 at
        // l = 11, 12, 13, 14 µm, the last a front moving between two nodes, its load's spread 2.5e-3).
        assert!(spread < 5e-3, "l = {supply:e}: the load settles within {spread:e}");
        let (ratio, closed) = (load / flooded.load(), exact / flooded_load(INLET));
        assert!(relative(ratio, closed) < 6e-3, "l = {supply:e}: load ratio {ratio} vs {closed}");
        // Upstream of the front the streamers carry the supply: θ h = l across each face (θ upwind).
        let x_front = (INLET - front) / (INLET - OUTLET) * LENGTH;
        let grid = &starved.grid;
        let streamers: Vec<_> = (0..grid.nx).filter(|&i| grid.x(i) < x_front - 2.0 * grid.dx()).collect();
        assert!(streamers.iter().all(|&i| partial(starved.fill[i])), "l = {supply:e}: partly filled up to the front");
        let content = streamers.iter().map(|&i| relative(starved.fill[i] * starved.film.face_x[i + 1], supply)).fold(0.0_f64, f64::max);
        assert!(content < 1e-8, "l = {supply:e}: θ h vs l off by {content:e}");
    }
    // Enough oil: the flooded slider (its inlet's half cell passes less Couette flow, the edge's
    // pressure lower by that, a difference first order in the cell: measured 2.8e-3).
    let (_, ample, _) = settled(20e-6);
    assert!(relative(ample, flooded.load()) < 4e-3, "ample {ample} vs flooded {}", flooded.load());
    let (_, dry, _) = settled(8e-6);
    assert!(dry == 0.0, "a supply below the outlet gap builds no pressure: {dry}");
}

#[test]
fn a_starved_solve_balances_its_content_with_its_edge_flows_to_round_off() {
    // During the transient from a flooded film, starved, with a squeeze rate: the content's rate over
    // all cells, Σ ΔA (h θ̇ + θ ḣ), is minus the flows out of the edges (`Carried::edge_flows`), the
    // supply's inflow u·min(l, h) at the inlet among them.
    let mut slider = Slider::new(199, LENGTH, plane, SPEED, 2e-4);
    slider.supply = Some(12e-6);
    let dt = 0.2 * slider.grid.dx() / SPEED;
    for step in 0..120 {
        slider.solve();
        if step % 20 == 19 {
            let (area, n) = (slider.area(), slider.grid.nx);
            let content: f64 = (0..n).map(|k| area * (slider.film.node[k] * slider.rate[k] + slider.fill[k] * slider.ht)).sum();
            let flows = slider.edge_flows();
            let scale = SPEED * INLET;
            assert!((content + flows.total()).abs() < 1e-12 * scale, "step {step}: content {content:e} vs edges {:e}", -flows.total());
            assert!(flows.west[0] < 0.0 && flows.west[0] >= -SPEED * 12e-6 * (1.0 + 1e-12), "inflow at most u l: {:e}", flows.west[0]);
        }
        slider.advance(dt);
    }
}

/// The default skirt with a limited supply of `liner_film` (m), mass-conserving.
fn supplied(liner_film: f64) -> Skirt {
    let mut design = SkirtDesign::new(0.04004, 0.04, 0.08, 0.04, 0.0, 70f64.to_radians(), 8.8e-3);
    design.cavitation = CavitationCondition::MassConserving;
    design.supply = OilSupply::Limited { liner_film, travel: (0.11, 0.19) };
    Skirt::new(design).expect("a valid skirt")
}

#[test]
fn the_liner_gains_what_the_edges_give_and_gives_what_they_take() {
    // Flows out of every edge face, some in, over a pin's path of 3.5 cells: the liner's oil changes by
    // their sum times dt to round-off, and a take beyond what its cells hold is reported, not created.
    let skirt = supplied(2e-6);
    let design = skirt.design();
    let grid = Grid::new(design.grid.0, design.grid.1, design.radius_bore * design.arc, design.length);
    let liner = Liner::new(design, &grid).expect("a limited supply");
    let (nx, nz) = (grid.nx, grid.nz);
    let wave = |k: usize, scale: f64| scale * (libm::sin(k as f64 * 0.7) + 0.3);
    let flows = EdgeFlows {
        west: (0..nz).map(|j| wave(j, 1e-9)).collect(),
        east: (0..nz).map(|j| wave(j + 5, 1e-9)).collect(),
        south: (0..nx).map(|i| -wave(i, 4e-8).abs()).collect(),
        north: (0..nx).map(|i| wave(i + 2, 4e-8).abs()).collect(),
    };
    let mut map = liner.start();
    let before = liner.volume(&map);
    let (path, dt) = ((0.15, 0.15 + 3.5 * grid.dz()), 1e-3);
    let lacked = liner.exchange(&mut map, &flows, path, dt);
    assert_eq!(lacked, 0.0);
    let change = liner.volume(&map) - before;
    assert!((change - flows.total() * dt).abs() < 1e-12 * before, "liner {change:e} vs edges {:e}", flows.total() * dt);
    // Ten times the take: the cells the leading edge passes run dry; what they lacked is reported.
    let heavy = EdgeFlows { south: flows.south.iter().map(|q| 10.0 * q).collect(), ..flows.clone() };
    let mut map = liner.start();
    let lacked = liner.exchange(&mut map, &heavy, path, dt);
    assert!(lacked > 0.0 && map.iter().all(|&l| l >= 0.0));
    let change = liner.volume(&map) - before;
    assert!((change - (heavy.total() * dt + lacked)).abs() < 1e-12 * before, "liner {change:e} vs edges and lacked");
}

#[test]
fn a_liner_film_thicker_than_the_gap_feeds_the_flooded_film() {
    // Every inlet face filled (min(1, l/h) = 1) and the film started full: the flooded mass-conserving
    // film's loads and fill rates, bit for bit.
    let motion = SkirtMotion { lateral: 15e-6, tilt: 2e-4, lateral_rate: 0.02, tilt_rate: -0.5, sliding_speed: 10.0 };
    let thick = supplied(1e-3);
    let flooded = Skirt::new(SkirtDesign { supply: OilSupply::Flooded, ..thick.design().clone() }).unwrap();
    for v in [10.0, -10.0] {
        let motion = SkirtMotion { sliding_speed: v, ..motion };
        let fill = thick.starting_fill(&motion, 0.15).expect("a limited supply");
        assert!(fill.sides.iter().flatten().all(|&t| t == 1.0), "a full film at the start");
        let (a, b) = (thick.linearise_filled(&motion, Some(&fill)), flooded.linearise_filled(&motion, None));
        assert_eq!(a.gram, b.gram);
        assert_eq!(a.fill_rate, b.fill_rate);
        assert_eq!(thick.loads_with(&a, &motion), flooded.loads_with(&b, &motion));
        // The thin supply starves it: less film force at the same motion.
        let thin = supplied(1e-6);
        let fill = thin.starting_fill(&motion, 0.15).unwrap();
        let starved = thin.linearise_filled(&motion, Some(&fill));
        let force = |f: &super::FilmLinear| (f.gram * nalgebra::Vector3::new(0.02, -0.5, v))[0].abs();
        assert!(force(&starved) < force(&b), "starved {} vs flooded {}", force(&starved), force(&b));
    }
}

#[test]
fn a_limited_supply_needs_the_mass_conserving_film() {
    let skirt = supplied(2e-6);
    let design = SkirtDesign { cavitation: CavitationCondition::Reynolds, ..skirt.design().clone() };
    let message = Skirt::new(design).unwrap_err().0;
    assert!(message.contains("oil_supply = 2") && message.contains("cavitation = 2"), "{message}");
    let design = SkirtDesign { supply: OilSupply::Limited { liner_film: -1e-6, travel: (0.11, 0.19) }, ..skirt.design().clone() };
    assert!(Skirt::new(design).unwrap_err().0.contains("liner_oil_film"));
}

#[test]
fn the_oil_on_the_liner_and_in_the_film_is_conserved_to_round_off() {
    // A skirt sliding a 80 mm stroke (12 m/s at mid-stroke) on 2 µm of liner oil while it swings ±15 µm
    // across the clearance thirty times a stroke pair (0.2 m/s laterally), 2000 solves a revolution:
    // each step's content follows its solve's flows, what leaves an edge lands on the liner, so the
    // total is the start's to round-off but for what the liner's cells lacked (none here).
    let skirt = supplied(2e-6);
    let (omega, stroke) = (300.0, 0.04);
    let y = |t: f64| 0.15 + stroke * libm::cos(omega * t);
    let motion = |t: f64| SkirtMotion {
        lateral: 15e-6 * libm::sin(30.0 * omega * t),
        lateral_rate: 450e-6 * omega * libm::cos(30.0 * omega * t),
        sliding_speed: -stroke * omega * libm::sin(omega * t),
        ..SkirtMotion::default()
    };
    let mut fill = skirt.starting_fill(&motion(0.0), y(0.0)).unwrap();
    let dt = 2.0 * std::f64::consts::PI / omega / 2000.0;
    let (mut first, mut lacked, mut least) = (None, 0.0, f64::INFINITY);
    for k in 0..4000 {
        let t = k as f64 * dt;
        let linear = skirt.linearise_filled(&motion(t), Some(&fill));
        let total = skirt.liner_oil(&linear.fill).0 + linear.content;
        let first = *first.get_or_insert(total);
        assert!((total - lacked - first).abs() < 1e-12 * first, "step {k}: {:e} of the start", total / first - 1.0);
        least = least.min(linear.fill.wetted());
        let (next, took) = skirt.fill_after(&linear, dt, (&motion(t + dt), y(t + dt)));
        (fill, lacked) = (next, lacked + took);
    }
    assert_eq!(lacked, 0.0);
    assert!(least < 0.5, "the film runs partly filled: wetted {least}");
}
