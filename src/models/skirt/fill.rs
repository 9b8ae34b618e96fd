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

use super::reynolds::{Film, Reynolds};

/// Fill fractions within this of 1 count as full: a node on the set's edge whose `w` is round-off
/// would otherwise leave the LCP by 1e-16 and be held at p = 0 a solve later.
const FULL: f64 = 1e-12;

/// Both sides' fill fraction per node (node order j·nx + i), θ ∈ [0, 1]; empty sides under the
/// Reynolds condition, which carries none.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Fill {
    /// Thrust (+x), anti-thrust (−x).
    pub sides: [Vec<f64>; 2],
}

impl Fill {
    /// Both sides full: a flooded film at rest.
    pub fn flooded(nodes: usize) -> Self {
        Self { sides: [vec![1.0; nodes], vec![1.0; nodes]] }
    }

    /// The fill `dt` (s, either sign) after a solve that took this fill and gave `rate`: each node
    /// moved along its rate, kept in [0, 1] (a full node stays full: its rate is 0 or negative).
    pub fn advanced(&self, rate: &Fill, dt: f64) -> Fill {
        Fill { sides: [0, 1].map(|k| advanced(&self.sides[k], &rate.sides[k], dt)) }
    }

    /// The share of the nodes' film area that is wetted, Σ θ over the nodes of both sides / their number.
    pub fn wetted(&self) -> f64 {
        let n = self.sides[0].len() + self.sides[1].len();
        self.sides.iter().flatten().sum::<f64>() / n as f64
    }
}

/// One side's fill `theta` moved `dt` along `rate` ([`Fill::advanced`]).
pub(crate) fn advanced(theta: &[f64], rate: &[f64], dt: f64) -> Vec<f64> {
    theta.iter().zip(rate).map(|(t, r)| settle(t + r * dt)).collect()
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

/// The fill rate θ̇ per node (node order) of the mass-conserving solve `reynolds` just made, 1/s, into
/// `out`: `fill` the fill it took, `rhs` its right-hand side, `squeeze(k)` = ΔA ḣₖ, `area` ΔA, `film`
/// the film it solved (h at the nodes).
pub(crate) fn rate(
    reynolds: &Reynolds,
    film: &Film,
    (fill, rhs): (&[f64], &[f64]),
    squeeze: impl Fn(usize) -> f64,
    area: f64,
    out: &mut [f64],
) {
    for (k, rate) in out.iter_mut().enumerate() {
        *rate = if !partial(fill[k]) && reynolds.free[k] {
            0.0
        } else {
            let w = reynolds.outflow(k) - rhs[k];
            (-w + (1.0 - fill[k]) * squeeze(k)) / (area * film.node[k])
        };
    }
}
