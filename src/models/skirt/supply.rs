//! The limited oil supply (`oil_supply = 2`): the oil left on the liner, per side, as a map along the
//! stroke, which feeds the skirt's leading edge and receives what leaves the film.
//!
//! The liner is mapped in cells of the skirt grid's axial spacing along Y, the axial position of a
//! liner point measured as the pin's (from the crank centre, along the cylinder axis): a skirt point u
//! below the skirt's top edge lies at `Y = y + pin_from_top − u`, y the pin's position. The map covers
//! every Y the skirt reaches over the stroke (`OilSupply::Limited`'s travel of y), per column of the
//! skirt's grid (each column runs over its own strip of the liner, one column spacing wide), and holds
//! the oil's volume per unit area, m.
//!
//! At a solve, the oil arriving across the leading edge (the top edge while the piston moves away from
//! the crank, V ≥ 0, the bottom edge otherwise) is what lies on the liner just ahead of it, l; the gap
//! at the edge's face is h, and the supply fills `θ = min(1, l/h)` of it (`inlet_fill`): the mean
//! surface velocity V/2 carries `V/2 · min(l, h)` into the film, a full film where the liner holds at
//! least the gap (flooded, as `oil_supply = 1`), streamers of content l where it holds less, which the
//! mass-conserving film carries until the gap closes to l (the starved inlet).
//!
//! Between solves the film's edge flows (`Carried::edge_flows`: the wedge's and the pressure's, out of
//! every edge, negative where oil enters) are exchanged with the liner over the path each edge face
//! takes along it (`Liner::exchange`): what the leading edge takes is taken from the cells it passes,
//! what leaves the trailing edge and the arcs' ends is left on the cells they pass, each spread
//! uniformly over its face's path. Oil the film does not take stays where it lies on the liner (under
//! the skirt, it reappears behind it). A node whose fill would pass full between two solves (streamers
//! squeezed by a closing gap faster than the solves follow) has its excess left on the liner under it,
//! where a shorter interval would have pressed it out through the film and its edges onto the liner.
//! So the oil on the liner and in the film changes only by the film's first-order transport between
//! solves and where a
//! cell would be emptied below zero (what `Liner::exchange` returns, the oil the film took that the liner's cells
//! did not hold, of first order in the time between solves).

use super::reynolds::{EdgeFlows, Grid};
use super::SkirtDesign;
use crate::models::ModelError;

/// How oil reaches the skirt's edges (`oil_supply`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum OilSupply {
    /// Fully flooded: the oil beyond the edges is a full film (`oil_supply = 1`).
    #[default]
    Flooded,
    /// Limited to what lies on the liner (`oil_supply = 2`, mass-conserving cavitation only).
    Limited {
        /// The uniform film the liner starts with, m.
        liner_film: f64,
        /// The range of the pin's axial position y over the stroke, m (from the crank centre, (lowest,
        /// highest)), which places the map.
        travel: (f64, f64),
    },
}

impl OilSupply {
    /// Refuses a supply the film cannot take, naming the field and reason.
    pub(crate) fn validate(&self, mass_conserving: bool) -> Result<(), ModelError> {
        let Self::Limited { liner_film, travel: (low, high) } = *self else {
            return Ok(());
        };
        let refuse = |what: String| Err(ModelError(format!("skirt: {what}")));
        if !mass_conserving {
            return refuse(
                "oil_supply = 2 (limited) needs cavitation = 2 (mass-conserving): the Reynolds condition creates the oil \
                 its film re-forms with, so no supply can limit it"
                    .into(),
            );
        }
        if !(liner_film.is_finite() && liner_film >= 0.0) {
            return refuse(format!("liner_oil_film = {liner_film} m must be finite and ≥ 0"));
        }
        if !(low.is_finite() && high.is_finite() && low <= high) {
            return refuse(format!("supply travel ({low}, {high}) m must be finite and ordered"));
        }
        Ok(())
    }
}

/// The map's geometry for one skirt.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Liner {
    /// Y of the lower end of cell 0, m.
    bottom: f64,
    /// A cell's axial length (the grid's axial spacing) and width (its circumferential spacing), m.
    cell: f64,
    width: f64,
    cells: usize,
    columns: usize,
    /// The pin's distance below the skirt's top edge and the skirt's length, m.
    pin_from_top: f64,
    length: f64,
    /// The axial grid spacing: node row j lies `(j + 1)·spacing` below the top edge.
    spacing: f64,
    /// The film the liner starts with, m.
    start: f64,
}

impl Liner {
    /// The map of `design`'s limited supply on `grid`; none when flooded.
    pub(crate) fn new(design: &SkirtDesign, grid: &Grid) -> Option<Self> {
        let OilSupply::Limited { liner_film, travel: (low, high) } = design.supply else {
            return None;
        };
        let cell = grid.dz();
        // One cell of margin at each end: the pin's lateral motion moves y by far less.
        let bottom = low + design.pin_from_top - design.length - cell;
        let top = high + design.pin_from_top + cell;
        let cells = ((top - bottom) / cell).ceil().max(1.0) as usize;
        Some(Self {
            bottom,
            cell,
            width: grid.dx(),
            cells,
            columns: grid.nx,
            pin_from_top: design.pin_from_top,
            length: design.length,
            spacing: grid.dz(),
            start: liner_film,
        })
    }

    /// A side's map at the start: the uniform film, cell-major (`cell · columns + column`).
    pub(crate) fn start(&self) -> Vec<f64> {
        vec![self.start; self.cells * self.columns]
    }

    /// The film the liner starts with, m.
    pub(crate) fn starting_film(&self) -> f64 {
        self.start
    }

    /// The cell holding Y (the end cells beyond the map).
    fn cell_at(&self, y: f64) -> usize {
        (((y - self.bottom) / self.cell).floor().max(0.0) as usize).min(self.cells - 1)
    }

    /// The oil per column just ahead of the leading edge, m, with the pin at `y` sliding with
    /// `forward` (V ≥ 0: the top edge leads, toward higher Y), into `out`.
    pub(crate) fn ahead(&self, map: &[f64], y: f64, forward: bool, out: &mut Vec<f64>) {
        let top = y + self.pin_from_top;
        let at = if forward { top + 0.5 * self.cell } else { top - self.length - 0.5 * self.cell };
        let c = self.cell_at(at);
        out.clear();
        out.extend_from_slice(&map[c * self.columns..(c + 1) * self.columns]);
    }

    /// Exchanges a side's edge flows `flows` (m³/s, out of the film) over `dt` (s) with its map, the
    /// pin moving from `from` to `to` (m): each face's volume spread uniformly over the cells its path
    /// passes, a cell the film would empty below zero held at zero. Returns the oil the film took
    /// beyond what the cells held, m³ (≥ 0).
    pub(crate) fn exchange(&self, map: &mut [f64], flows: &EdgeFlows, (from, to): (f64, f64), dt: f64) -> f64 {
        let mut lacked = 0.0;
        let (top, bottom) = (self.pin_from_top, self.pin_from_top - self.length);
        let last = self.columns - 1;
        let mut put = |column: usize, offset: f64, q: f64| lacked += self.spread(map, column, (from + offset, to + offset), q * dt);
        for (i, (&south, &north)) in flows.south.iter().zip(&flows.north).enumerate() {
            put(i, top, south);
            put(i, bottom, north);
        }
        for (j, (&west, &east)) in flows.west.iter().zip(&flows.east).enumerate() {
            let offset = top - (j + 1) as f64 * self.spacing;
            put(0, offset, west);
            put(last, offset, east);
        }
        lacked
    }

    /// Leaves `volume` (m³, either sign) on the liner under the node (column, row) of a side, the pin at
    /// `y`; returns what the cell lacked to give it.
    pub(crate) fn leave(&self, map: &mut [f64], (column, row): (usize, usize), y: f64, volume: f64) -> f64 {
        let at = y + self.pin_from_top - (row + 1) as f64 * self.spacing;
        self.spread(map, column, (at, at), volume)
    }

    /// Adds `volume` (m³, either sign) to `column`'s cells along the path (a, b) of Y, uniformly; a
    /// path within a cell puts it all there. Returns what a cell lacked to give it.
    fn spread(&self, map: &mut [f64], column: usize, (a, b): (f64, f64), volume: f64) -> f64 {
        let (low, high) = (a.min(b), a.max(b));
        let (first, last) = (self.cell_at(low), self.cell_at(high));
        let area = self.cell * self.width;
        let mut lacked = 0.0;
        for c in first..=last {
            let share = if first == last {
                1.0
            } else {
                let (start, end) = (self.bottom + c as f64 * self.cell, self.bottom + (c + 1) as f64 * self.cell);
                let (start, end) = (if c == first { low } else { start }, if c == last { high } else { end });
                (end - start) / (high - low)
            };
            let oil = &mut map[c * self.columns + column];
            *oil += volume * share / area;
            if *oil < 0.0 {
                lacked -= *oil * area;
                *oil = 0.0;
            }
        }
        lacked
    }

    /// The oil a side's map holds, m³.
    pub(crate) fn volume(&self, map: &[f64]) -> f64 {
        map.iter().sum::<f64>() * self.cell * self.width
    }

    /// The area a side's map covers, m².
    pub(crate) fn area(&self) -> f64 {
        (self.cells * self.columns) as f64 * self.cell * self.width
    }
}

/// The fill of the oil arriving across the leading edge: `min(1, l/h)` per column, `liner` the oil
/// just ahead (m) and `gap` the film at the edge's faces (m).
pub(crate) fn inlet_fill(liner: &[f64], gap: impl Iterator<Item = f64>, out: &mut Vec<f64>) {
    out.clear();
    out.extend(liner.iter().zip(gap).map(|(&l, h)| (l / h).min(1.0)));
}
