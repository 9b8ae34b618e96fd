//! The mass-conserving (JFO) film's oil content: the fill fraction θ of each node (1: a full film,
//! below 1: a cavitated node whose oil, θ·h, runs as streamers at p = 0), its rate at a solve and its
//! advance between solves.
//!
//! A solve (`Reynolds::solve` with `Cavitation::MassConserving`: the partly filled nodes pinned at
//! p = 0, the wedge carrying each face's h times the fill upwind of it) leaves the balance of node k's
//! cell, `ΔA ∂(θh)/∂t = (bₖ + ΔA ḣₖ) − (A p)ₖ`, with b the right-hand side (squeeze `−ḣ ΔA` and the
//! carried wedge) and A p the Poiseuille outflow. With `w = A p − b`,
//!
//! `ΔA h θ̇ = −wₖ + (1 − θₖ) ΔA ḣₖ`:
//!
//! zero on a full node under pressure (w = 0), negative on a full node at p = 0 that the LCP let go
//! (w ≥ 0: rupture, the node starts to empty), the filling or emptying of a partial node (its inflow
//! from pressurised or carried neighbours, its squeeze at constant content). A node that fills to
//! θ = 1 rejoins the LCP at the next solve (reformation). The balance holds node by node to round-off
//! (the faces' fluxes are shared), so the content of the film changes only by what crosses its edges.
//!
//! Between solves θ moves along that rate, with the node's own outflow taken implicitly: writing
//! `θ̇ = s − d θ`, d the wedge's outflow per unit fill over the cell's oil volume (`Film::carried_out`
//! / (ΔA h)), the step is `θ' = (θ + Δt (θ̇ + d θ)) / (1 + Δt d)`, a convex mix of the node's fill and
//! what flows in, so the fill stays within [0, 1] and the transport stable at any Courant number; it
//! is the explicit step to first order in Δt.

use super::reynolds::{Film, Grid, Reynolds};

/// Fill fractions within this of 1 count as full: a node on the set's edge whose `w` is round-off
/// would otherwise leave the LCP by 1e-16 and be held at p = 0 a solve later.
const FULL: f64 = 1e-12;

/// Both sides' values per node (node order j·nx + i): the fill fraction θ ∈ [0, 1], or its rate and
/// decay (`fill::rate`); empty sides under the Reynolds condition, which carries none. With a limited
/// supply (`skirt/supply.rs`) the fill also holds the oil on the liner and where the pin was.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Fill {
    /// Thrust (+x), anti-thrust (−x).
    pub sides: [Vec<f64>; 2],
    /// A limited supply's oil on the liner per side, m (`supply::Liner`'s map); empty when flooded.
    pub liner: [Vec<f64>; 2],
    /// The pin's axial position the liner's oil was exchanged up to, m (a limited supply's).
    pub axial: f64,
}

impl Fill {
    /// Both sides full: a flooded film at rest.
    pub fn flooded(nodes: usize) -> Self {
        Self { sides: [vec![1.0; nodes], vec![1.0; nodes]], ..Self::default() }
    }

    /// The fill `dt` (s, either sign) after a solve that took this fill and gave `rate` and `decay`
    /// (`fill::rate`), kept in [0, 1] (a full node stays full: its rate is 0 or negative); the liner's
    /// oil as it was (`Skirt::fill_after` exchanges it).
    pub fn advanced(&self, (rate, decay): (&Fill, &Fill), dt: f64) -> Fill {
        Fill {
            sides: [0, 1].map(|k| advanced(&self.sides[k], (&rate.sides[k], &decay.sides[k]), dt)),
            liner: self.liner.clone(),
            axial: self.axial,
        }
    }

    /// The share of the nodes' film area that is wetted, Σ θ over the nodes of both sides / their
    /// number; 1 where the fill is not carried (the Reynolds condition's film is full).
    pub fn wetted(&self) -> f64 {
        let n = self.sides[0].len() + self.sides[1].len();
        if n == 0 {
            return 1.0;
        }
        self.sides.iter().flatten().sum::<f64>() / n as f64
    }
}

/// One side's fill `theta` moved `dt` along `rate` with `decay` implicit ([`Fill::advanced`]); a step
/// back in time (a rejected step's solve retaken earlier) is explicit.
pub(crate) fn advanced(theta: &[f64], (rate, decay): (&[f64], &[f64]), dt: f64) -> Vec<f64> {
    unsettled(theta, (rate, decay), dt).map(settle).collect()
}

/// One side's fill `dt` on with each node's oil kept to the flows of its solve (a limited supply's,
/// `Skirt::fill_after`): the content the solve's rates give, `θ h + (h θ̇ + θ ḣ) dt` (h and ḣ at the
/// solve, `before` and `rates`), over the film now, `after` (m), kept in [0, 1]; a full node whose
/// rate does not empty it stays full (its content the gap now). The step is explicit, so that what
/// leaves one node is what enters the next: the faces' fluxes are shared, the film's content changes
/// by its edges' flows alone. Moving θ alone would change a squeezed partial node's oil by
/// `−θ h (ḣ dt/h)²` at every step, the gap's actual change differs from `ḣ dt` by `ḧ dt²/2`, and the
/// implicit decay of [`advanced`] scales each node's rate by `1/(1 + d dt)`; each is of one sign over
/// a landing or a stroke. Returns the fill and what it holds beyond what the flows gave, m of film per
/// node (negative: a node filled beyond full, or emptied below nothing, at a step longer than its
/// flows allow; positive: a full node's gap grew more than its rate said).
pub(crate) fn advanced_conserving(
    theta: &[f64],
    rate: &[f64],
    dt: f64,
    (before, rates, after): (&[f64], &[f64], &[f64]),
) -> (Vec<f64>, Vec<f64>) {
    let gaps = before.iter().zip(rates).zip(after);
    theta
        .iter()
        .zip(rate)
        .zip(gaps)
        .map(|((&t, r), ((h0, hdot), h1))| {
            let content = h0 * (t + r * dt) + t * hdot * dt;
            let kept = if t == 1.0 && *r >= 0.0 { 1.0 } else { settle(content / h1) };
            (kept, kept * h1 - content)
        })
        .unzip()
}

/// Each node's fill `dt` on before [`settle`].
fn unsettled<'a>(theta: &'a [f64], (rate, decay): (&'a [f64], &'a [f64]), dt: f64) -> impl Iterator<Item = f64> + 'a {
    theta.iter().zip(rate).zip(decay).map(move |((t, r), d)| {
        let implicit = dt * d;
        if implicit > 0.0 {
            (t + dt * (r + d * t)) / (1.0 + implicit)
        } else {
            t + dt * r
        }
    })
}

/// θ kept in [0, 1], within [`FULL`] of 1 made 1.
fn settle(theta: f64) -> f64 {
    if theta >= 1.0 - FULL {
        1.0
    } else {
        theta.max(0.0)
    }
}

/// Whether a node of fill `theta` is partly filled (held at p = 0 in a mass-conserving solve).
pub(crate) fn partial(theta: f64) -> bool {
    theta < 1.0
}

/// What a mass-conserving solve is made of, for [`rate`]: the solver after it, its film (h at the
/// nodes and faces) and grid, the fill it took, its right-hand side, the mean surface velocity, ΔA ḣ
/// per node and the cell area ΔA.
pub(crate) struct Solve<'a, S: Fn(usize) -> f64> {
    pub reynolds: &'a Reynolds,
    pub film: &'a Film,
    pub grid: &'a Grid,
    pub fill: &'a [f64],
    pub rhs: &'a [f64],
    pub velocity: (f64, f64),
    pub squeeze: S,
    pub area: f64,
}

/// The fill rate θ̇ (1/s) and decay d (1/s, the node's own outflow per unit fill over its oil
/// volume) per node (node order) of a mass-conserving solve, into `rate` and `decay`.
pub(crate) fn rate<S: Fn(usize) -> f64>(solve: &Solve<S>, (rate, decay): (&mut [f64], &mut [f64])) {
    for (k, (rate, decay)) in rate.iter_mut().zip(decay.iter_mut()).enumerate() {
        let volume = solve.area * solve.film.node[k];
        let theta = solve.fill[k];
        *decay = solve.film.carried_out(solve.grid, solve.velocity, k) / volume;
        *rate = if !partial(theta) && solve.reynolds.free[k] {
            0.0
        } else {
            let w = solve.reynolds.outflow(k) - solve.rhs[k];
            (-w + (1.0 - theta) * (solve.squeeze)(k)) / volume
        };
    }
}
