//! The mass-conserving (JFO) film against closed forms: a slider whose Rayleigh step ruptures into a
//! pocket that re-forms before the exit, the long journal bearing fed at its thickest film, and the
//! flow balance of each solve.

use super::fill::{self, partial};
use super::reynolds::{Carried, Cavitation, EdgeFlows, Film, Grid, Reynolds};

pub(super) const VISCOSITY: f64 = 0.01;

/// A long film of thickness `h(x)` (per metre of width) under a mean surface velocity `u` along +x and a
/// uniform squeeze rate `ht`, with its fill fraction; flooded at its inlet, or with a `supply` (m) the
/// oil arriving there fills `min(1, supply/h)` of the inlet face's gap (`skirt/supply.rs`).
pub(super) struct Slider {
    pub grid: Grid,
    pub film: Film,
    pub u: f64,
    pub ht: f64,
    pub solver: Reynolds,
    pub fill: Vec<f64>,
    pub rhs: Vec<f64>,
    pub rate: Vec<f64>,
    pub decay: Vec<f64>,
    pub supply: Option<f64>,
}

impl Slider {
    pub fn new(nx: usize, length: f64, h: impl Fn(f64) -> f64, u: f64, ht: f64) -> Self {
        let grid = Grid::long(nx, length);
        let mut film = Film::new(&grid);
        let column = |x: f64| (0.0, h(x));
        let nodes: Vec<_> = (0..nx).map(|i| column(grid.x(i))).collect();
        let faces: Vec<_> = (0..=nx).map(|i| column((i as f64 + 0.5) * grid.dx())).collect();
        film.fill(&grid, (&[(0.0, 0.0)], &[(0.0, 0.0); 2]), (&nodes, &faces), 0.0);
        let solver = Reynolds::new(grid.clone());
        let (fill, rhs, rate, decay) = (vec![1.0; nx], vec![0.0; nx], vec![0.0; nx], vec![0.0; nx]);
        Self { grid, film, u, ht, solver, fill, rhs, rate, decay, supply: None }
    }

    pub fn area(&self) -> f64 {
        self.grid.dx() * self.grid.dz()
    }

    /// The fill of the oil crossing the inlet (the upstream edge's face), one row's.
    pub fn inlet(&self) -> Option<[f64; 1]> {
        let face = if self.u >= 0.0 { self.film.face_x[0] } else { self.film.face_x[self.grid.nx] };
        self.supply.map(|l| [(l / face).min(1.0)])
    }

    /// The flows out of the film's edges after the last solve (`Carried::edge_flows`), m³/s per metre.
    pub fn edge_flows(&self) -> EdgeFlows {
        let inlet = self.inlet();
        let carried = Carried { fill: &self.fill, forward: (self.u >= 0.0, true), inlet: (inlet.as_ref().map(|i| &i[..]), None) };
        carried.edge_flows(&self.solver, &self.film, VISCOSITY, (self.u, 0.0))
    }

    /// One mass-conserving solve at the current fill: the pressure in `solver`, θ̇ in `rate`.
    pub fn solve(&mut self) {
        let area = self.area();
        self.rhs.fill(-self.ht * area);
        let inlet = self.inlet();
        let carried = Carried { fill: &self.fill, forward: (self.u >= 0.0, true), inlet: (inlet.as_ref().map(|i| &i[..]), None) };
        self.film.add_wedge(&self.grid, (self.u, 0.0), Some(&carried), &mut self.rhs);
        self.solver.pin(self.fill.iter().map(|&t| partial(t)));
        self.solver.solve(&self.film, VISCOSITY, &self.rhs, Cavitation::MassConserving, &[]);
        let solve = fill::Solve {
            reynolds: &self.solver,
            film: &self.film,
            grid: &self.grid,
            fill: &self.fill,
            rhs: &self.rhs,
            velocity: (self.u, 0.0),
            squeeze: |_| self.ht * area,
            area,
        };
        fill::rate(&solve, (&mut self.rate, &mut self.decay));
    }

    /// The fill `dt` on.
    pub fn advance(&mut self, dt: f64) {
        self.fill = fill::advanced(&self.fill, (&self.rate, &self.decay), dt);
    }

    /// Marches the fill from flooded to its steady state, the steady JFO solution, at steps of
    /// `courant` cells' transit of the thinnest film's share of the thickest.
    pub fn steady(&mut self, courant: f64) {
        let (hmin, hmax) = self.film.face_x.iter().fold((f64::INFINITY, 0.0_f64), |(a, b), &h| (a.min(h), b.max(h)));
        let dt = courant * self.grid.dx() / self.u.abs() * hmin / hmax;
        for _ in 0..200 * self.grid.nx {
            self.solve();
            if self.rate.iter().all(|r| r.abs() * dt < 1e-10) {
                return;
            }
            self.advance(dt);
        }
        panic!("no steady state");
    }

    /// The load per metre of width, N/m.
    pub fn load(&self) -> f64 {
        self.solver.pressure.iter().sum::<f64>() * self.grid.dx()
    }

    /// x of the first node downstream of `from` where the film is full again after a partial one.
    fn reformation(&self, from: f64) -> f64 {
        let start = (0..self.grid.nx).find(|&i| self.grid.x(i) > from && partial(self.fill[i])).expect("a cavitated node");
        let i = (start..self.grid.nx).find(|&i| !partial(self.fill[i])).expect("a full node downstream");
        self.grid.x(i)
    }
}

pub(super) fn relative(value: f64, exact: f64) -> f64 {
    (value - exact).abs() / exact.abs()
}

/// The stepped slider of `pocket_slider`: h2 on [0, a), h0 on [a, b), h2 on [b, c), h0 on [c, L].
const STEPS: [f64; 3] = [0.2e-2, 0.5e-2, 0.8e-2];
const LENGTH: f64 = 1e-2;
const THIN: f64 = 10e-6;
const THICK: f64 = 20e-6;
const SPEED: f64 = 0.5;

fn stepped(x: f64) -> f64 {
    let [a, b, c] = STEPS;
    if x < a || (b..c).contains(&x) {
        THICK
    } else {
        THIN
    }
}

#[test]
fn a_pocket_ruptures_and_reforms_where_the_jfo_conditions_place_it() {
    // JFO's conditions in a film of piecewise constant h (Jakobsson & Floberg 1957, Olsson 1965): the
    // flow q = u h − h³ p'/(12μ) is one constant through full zones and cavitated ones (there, u θ h
    // at p = 0), p is continuous and ≥ 0. The Rayleigh step [0, b) fed at p = 0 builds pressure and
    // falls back to 0 at the pocket's divergent step b, where the film ruptures (a constant h cannot
    // let p fall to 0 inside: q ≤ u h there forces p' ≥ 0); the streamers fill θ = q/(u h2) of the
    // pocket; the exit land [c, L] needs pressure p(c) = 12μ (q − u h0)(L − c)/h0³ to pass q, which the
    // pocket builds from a reformation front s where p = 0: c − s = p(c) h2³ / (12μ (u h2 − q)).
    let [a, b, c] = STEPS;
    let (u, mu) = (SPEED, VISCOSITY);
    let k = |h: f64, length: f64| length / (h * h * h);
    let q = (u * THICK * k(THICK, a) + u * THIN * k(THIN, b - a)) / (k(THICK, a) + k(THIN, b - a));
    let peak = 12.0 * mu * (u * THICK - q) * k(THICK, a);
    let exit = 12.0 * mu * (q - u * THIN) * k(THIN, LENGTH - c);
    let front = c - exit * THICK.powi(3) / (12.0 * mu * (u * THICK - q));
    let load = 0.5 * peak * b + 0.5 * exit * (LENGTH - front);
    assert!(front > b && front < c, "the front lies in the pocket: {front}");
    let mut slider = Slider::new(199, LENGTH, stepped, u, 0.0);
    slider.steady(0.4);
    let dx = slider.grid.dx();
    // The steps lie on nodes, so the lands' conductances in series are exact; the front lies in a
    // cell, resolved to it, and the load errs to second order in the cell (measured: 1.5e-4, 3.8e-5,
    // 9.6e-6 at 100, 200, 400 cells).
    assert!((slider.reformation(b) - front).abs() <= 1.5 * dx, "front {} vs {front}", slider.reformation(b));
    // The cavity's nodes but the front's (the cell the front crosses, filled by the land's backflow).
    let streamers: Vec<f64> =
        (0..slider.grid.nx - 1).filter(|&i| partial(slider.fill[i]) && partial(slider.fill[i + 1])).map(|i| slider.fill[i]).collect();
    let theta = q / (u * THICK);
    assert!(
        streamers.len() > 20 && streamers.iter().all(|&t| relative(t, theta) < 1e-8),
        "θ = q/(u h2) = {theta} in the cavity: {streamers:?}"
    );
    let rupture = (0..slider.grid.nx).find(|&i| partial(slider.fill[i])).map(|i| slider.grid.x(i)).expect("rupture");
    assert!((rupture - b).abs() <= dx, "rupture at {rupture} vs {b}");
    assert!(relative(slider.load(), load) < 1e-4, "load {} vs {load}", slider.load());
    // The fill's own outflow taken implicitly: steps of many cells' transit reach the same state.
    let mut long_steps = Slider::new(199, LENGTH, stepped, u, 0.0);
    long_steps.steady(8.0);
    assert!(relative(long_steps.load(), slider.load()) < 1e-6, "long steps: {} vs {}", long_steps.load(), slider.load());
    // The Reynolds condition re-forms the film at once at the rupture and builds more from the oil it
    // creates there (measured: 1.64 times the load).
    let mut reynolds = Slider::new(199, LENGTH, stepped, u, 0.0);
    reynolds.solver.solve(
        &reynolds.film,
        VISCOSITY,
        &{
            let mut b = vec![0.0; reynolds.grid.nx];
            reynolds.film.add_wedge(&reynolds.grid, (u, 0.0), None, &mut b);
            b
        },
        Cavitation::Reynolds,
        &[],
    );
    assert!(reynolds.load() > 1.5 * load, "Reynolds {} vs JFO {load}", reynolds.load());
}

#[test]
fn a_long_journal_fed_at_its_thickest_film_is_the_reynolds_condition() {
    // With the oil supplied at ambient pressure where the film is thickest, JFO's rupture is the
    // Swift–Stieber boundary (p = p' = 0) and the film re-forms at the supply, so the steady JFO pressure
    // is the Reynolds condition's (Floberg 1957; Elrod 1981 reproduces it): the load of
    // `long_journal_bearing_with_the_reynolds_condition`'s closed form, here against its own solve.
    let (radius, clearance, e) = (0.05, 50e-6, 0.6);
    let h = |x: f64| clearance * (1.0 + e * libm::cos(x / radius));
    let mut jfo = Slider::new(256, 2.0 * std::f64::consts::PI * radius, h, 0.5 * radius * 100.0, 0.0);
    jfo.steady(0.4);
    let mut reynolds = Slider::new(256, 2.0 * std::f64::consts::PI * radius, h, 0.5 * radius * 100.0, 0.0);
    let mut b = vec![0.0; 256];
    reynolds.film.add_wedge(&reynolds.grid, (reynolds.u, 0.0), None, &mut b);
    reynolds.solver.solve(&reynolds.film, VISCOSITY, &b, Cavitation::Reynolds, &[]);
    let peak = |p: &[f64]| p.iter().fold(0.0_f64, |m, &v| m.max(v));
    // The cavitated arc carries one flow, u h θ across each of its faces, and leaves partly filled.
    let cavity: Vec<usize> = (0..256).filter(|&i| partial(jfo.fill[i])).collect();
    let carried = |i: usize| jfo.fill[i] * jfo.film.face_x[i + 1];
    assert!(
        cavity.contains(&255) && cavity.iter().all(|&i| relative(carried(i), carried(255)) < 1e-6),
        "θ h carried: {:?}",
        cavity.iter().map(|&i| relative(carried(i), carried(255))).fold(0.0_f64, f64::max)
    );
    for (x, y) in jfo.solver.pressure.iter().zip(&reynolds.solver.pressure) {
        assert!((x - y).abs() <= 1e-9 * peak(&reynolds.solver.pressure), "p {x} vs {y}");
    }
}

#[test]
fn each_solve_balances_the_flow_to_round_off() {
    // During the transient from a flooded film, with a squeeze rate: the content's rate over all cells,
    // Σ ΔA (h θ̇ + θ ḣ), equals what crosses the edges: the wedge's inflow u h θ = u h at the inlet less
    // its outflow u h θ at the exit, less the Poiseuille outflow h³/(12μ) p/(dx/1) at both ends.
    let mut slider = Slider::new(199, LENGTH, stepped, SPEED, 2e-4);
    let dt = 0.2 * slider.grid.dx() / SPEED;
    for step in 0..120 {
        slider.solve();
        if step % 20 == 19 {
            let (area, n, dx) = (slider.area(), slider.grid.nx, slider.grid.dx());
            let content: f64 = (0..n).map(|k| area * (slider.film.node[k] * slider.rate[k] + slider.fill[k] * slider.ht)).sum();
            let (inlet, outlet) = (slider.film.face_x[0], slider.film.face_x[n]);
            let conductance = |h: f64| h * h * h / (12.0 * VISCOSITY) / dx;
            let p = &slider.solver.pressure;
            let edges = SPEED * inlet - SPEED * outlet * slider.fill[n - 1] - conductance(inlet) * p[0] - conductance(outlet) * p[n - 1];
            let scale = SPEED * THICK;
            assert!((content - edges).abs() < 1e-12 * scale, "step {step}: content {content:e} vs edges {edges:e}");
            assert!(slider.fill.iter().any(|&t| partial(t)), "step {step}: a cavity exists");
        }
        slider.advance(dt);
    }
}
