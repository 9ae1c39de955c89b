//! The cavity probe of a case: watches the fluid, from a given time on, for the first air cavity that a
//! plunging jet closes, with the definitions of the 2D+t plunge detection (docs/jet-metrics.md): an air region
//! of the level set (appendix B) not connected to the atmosphere, of area at least (2h)², every node of it
//! farther than 3h from every wall, and at least half of it open to the atmosphere at the previous check (so
//! that holes opening inside a stretched sheet are not taken for a closure). The dam break's plunging wave
//! closes one at t√(g/H) = 6.0 in the thesis (§8.4), which validates the detection on a simulated flow.

use crate::analysis::cavity::{self, Cavity};
use crate::analysis::level_set::{self, LevelSet};
use crate::analysis::snapshot::{Snapshot, V2};
use crate::sph::polyline_wall::nearest_point;
use crate::sph::solver::Simulation;

/// Fraction of a new cavity's nodes that must have been atmosphere at the previous check (as the 2D+t
/// plunge detection, `twodt::run::TRAPPED_FRACTION`).
pub const TRAPPED_FRACTION: f64 = 0.5;

/// A cavity closure found by the probe.
#[derive(Clone, Debug)]
pub struct CavityClosure {
    /// Time of the first check that found the cavity closed (s).
    pub time: f64,
    /// Time of the previous check, when it was still open (s): the closure lies in (previous, time].
    pub previous_time: f64,
    /// Area (m²), centroid (m) and the circulation around it, positive clockwise (m²/s).
    pub area: f64,
    pub centroid: V2,
    pub circulation: f64,
}

/// The state of the watch between checks.
#[derive(Default)]
pub struct CavityWatch {
    previous: Option<(f64, LevelSet, Vec<bool>)>,
}

impl CavityWatch {
    /// Checks the simulation now (`dx` the particle spacing, `walls` the wall polylines); returns the closure
    /// if a cavity has closed since the previous check.
    pub fn check(&mut self, sim: &mut Simulation<2>, dx: f64, walls: &[Vec<V2>]) -> Option<CavityClosure> {
        let s = Snapshot::from_simulation(sim, dx);
        let h = s.h;
        let (mut lo, mut hi) = (V2::repeat(f64::INFINITY), V2::repeat(f64::NEG_INFINITY));
        for p in &s.pos {
            lo = lo.inf(p);
            hi = hi.sup(p);
        }
        let pad = V2::repeat(3.0 * h);
        let (mut lo, mut hi) = (lo - pad, hi + pad);
        // Inside the walls' bounding box, but always above the highest particle (the top row of the grid is
        // the atmosphere).
        if let Some((wlo, whi)) = bounding_box(walls.iter().flatten()) {
            lo = lo.sup(&wlo);
            hi.x = hi.x.min(whi.x);
        }
        let ls = level_set::level_set(&s, lo, hi, dx);
        let margin = 3.0 * h;
        let away = |nodes: &[V2]| {
            nodes
                .iter()
                .all(|p| walls.iter().all(|w| (nearest_point(w, p) - p).norm() > margin))
        };
        let atmosphere = cavity::atmosphere_mask(&ls);
        let cavities = cavity::find_cavities(&ls, &atmosphere, (2.0 * h).powi(2), away);
        let previous = self.previous.replace((sim.time, ls.clone(), atmosphere));
        let (t_prev, pls, pmask) = previous?;
        let c: Cavity = cavities
            .into_iter()
            .find(|c| cavity::trapped_fraction(&ls, c, &pls, &pmask) >= TRAPPED_FRACTION)?;
        Some(CavityClosure {
            time: sim.time,
            previous_time: t_prev,
            area: c.area,
            centroid: c.centroid,
            circulation: cavity::circulation(&s, &ls, &c),
        })
    }
}

/// Bounding box of a set of points, if any.
fn bounding_box<'a>(points: impl Iterator<Item = &'a V2>) -> Option<(V2, V2)> {
    points.fold(None, |acc, p| match acc {
        None => Some((*p, *p)),
        Some((lo, hi)) => Some((lo.inf(p), hi.sup(p))),
    })
}
