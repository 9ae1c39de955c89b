//! The cavity probe of a case: watches the fluid, from a given time on, for the first air cavity that a
//! plunging jet closes, with the definitions of the 2D+t plunge detection (docs/reference/jet-metrics.md): an air region
//! of the level set (appendix B) not connected to the atmosphere, of area at least (2h)², every node of it
//! farther than 3h from every wall, and at least half of it open to the atmosphere at the previous check (so
//! that holes opening inside a stretched sheet are not taken for a closure). The dam break's plunging wave
//! closes one at t√(g/H) = 6.0 in the thesis (§8.4), which validates the detection on a simulated flow.

use crate::analysis::cavity;
use crate::analysis::level_set;
use crate::analysis::snapshot::{Snapshot, V2};
use crate::sph::polyline_wall::nearest_point;
use crate::sph::solver::Simulation;

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
    closures: cavity::ClosureWatch,
    previous_time: f64,
}

impl CavityWatch {
    /// Checks the simulation now (`dx` the particle spacing, `walls` the wall polylines); returns the closure
    /// if a cavity has closed since the previous check.
    pub fn check(&mut self, sim: &mut Simulation<2>, dx: f64, walls: &[Vec<V2>]) -> Option<CavityClosure> {
        let s = Snapshot::from_simulation(sim, dx);
        let h = s.h;
        let (lo, hi) = bounding_box(s.pos.iter())?;
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
        let previous_time = std::mem::replace(&mut self.previous_time, sim.time);
        let c = self
            .closures
            .newly_closed(&ls, (2.0 * h).powi(2), away)?
            .into_iter()
            .next()?;
        Some(CavityClosure {
            time: sim.time,
            previous_time,
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
