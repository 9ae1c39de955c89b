//! Air cavities enclosed by the fluid: connected regions of air nodes of the level set (4-connected) that do
//! not reach the top row of the grid (the atmosphere), and the circulation around them.
//!
//! Each node stands for the square cell of side `spacing` centred on it, so a cavity's area is its node
//! count times spacing², and its boundary is the staircase of cell edges between cavity and fluid nodes.
//! The circulation Γ = ∮ u·dl is summed along that staircase with u interpolated at each edge's midpoint
//! by first-order MLS (7.6) from the fluid particles; it is reported positive clockwise in the (y right,
//! z up) plane, the sense of an overturning wave travelling towards +y.

use super::level_set::LevelSet;
use super::snapshot::{Snapshot, V2};
use crate::sph::kernel::{Kernel, KernelKind};
use crate::sph::mls::mls_fit;

/// One enclosed air region.
#[derive(Clone, Debug)]
pub struct Cavity {
    /// Grid nodes (i, j) of the cavity.
    pub nodes: Vec<(usize, usize)>,
    pub area: f64,
    pub centroid: V2,
    /// Node of smallest y (lowest such on ties): where the wall of the cavity facing +y is vertical.
    pub leftmost: V2,
    /// Node of largest y (lowest on ties): where the falling jet closes the cavity.
    pub rightmost: V2,
    pub lo: V2,
    pub hi: V2,
}

/// Floods the 4-connected air nodes reachable from `seeds` that are not yet `visited`, marks them visited
/// and returns them (node index j·ny + i).
fn flood(ls: &LevelSet, seeds: &[usize], visited: &mut [bool]) -> Vec<usize> {
    let (ny, nz) = (ls.ny, ls.nz);
    let is_air = |k: usize| ls.is_air(k % ny, k / ny);
    let mut out = vec![];
    let mut stack: Vec<usize> = vec![];
    for &k in seeds {
        if !visited[k] && is_air(k) {
            visited[k] = true;
            stack.push(k);
        }
    }
    while let Some(k) = stack.pop() {
        out.push(k);
        let (i, j) = (k % ny, k / ny);
        let mut next = [None; 4];
        if i > 0 {
            next[0] = Some(k - 1);
        }
        if i + 1 < ny {
            next[1] = Some(k + 1);
        }
        if j > 0 {
            next[2] = Some(k - ny);
        }
        if j + 1 < nz {
            next[3] = Some(k + ny);
        }
        for kk in next.into_iter().flatten() {
            if !visited[kk] && is_air(kk) {
                visited[kk] = true;
                stack.push(kk);
            }
        }
    }
    out
}

/// Finds the cavities of area at least `min_area`: the air regions outside `atmosphere` (from
/// [`atmosphere_mask`]). `keep` rejects cavities by their nodes (e.g. air trapped against a wall). Sorted by
/// decreasing area.
pub fn find_cavities(ls: &LevelSet, atmosphere: &[bool], min_area: f64, keep: impl Fn(&[V2]) -> bool) -> Vec<Cavity> {
    let ny = ls.ny;
    let mut visited = atmosphere.to_vec();
    let cell_area = ls.spacing * ls.spacing;
    let mut cavities = vec![];
    for k in 0..ls.phi.len() {
        if visited[k] || !ls.is_air(k % ny, k / ny) {
            continue;
        }
        let nodes = flood(ls, &[k], &mut visited);
        let area = nodes.len() as f64 * cell_area;
        if area < min_area {
            continue;
        }
        let ij: Vec<(usize, usize)> = nodes.iter().map(|&k| (k % ny, k / ny)).collect();
        let pts: Vec<V2> = ij.iter().map(|&(i, j)| ls.node(i, j)).collect();
        if !keep(&pts) {
            continue;
        }
        let centroid = pts.iter().fold(V2::zeros(), |a, p| a + p) / pts.len() as f64;
        let pick = |better: &dyn Fn(&V2, &V2) -> bool| {
            let mut b = pts[0];
            for p in &pts {
                if better(p, &b) {
                    b = *p;
                }
            }
            b
        };
        let eps = 1e-9 * ls.spacing;
        let leftmost = pick(&|p, b| p.x < b.x - eps || ((p.x - b.x).abs() <= eps && p.y < b.y));
        let rightmost = pick(&|p, b| p.x > b.x + eps || ((p.x - b.x).abs() <= eps && p.y < b.y));
        let (lo, hi) = pts.iter().fold(
            (V2::repeat(f64::INFINITY), V2::repeat(f64::NEG_INFINITY)),
            |(lo, hi), q| (lo.inf(q), hi.sup(q)),
        );
        cavities.push(Cavity {
            nodes: ij,
            area,
            centroid,
            leftmost,
            rightmost,
            lo,
            hi,
        });
    }
    cavities.sort_by(|a, b| b.area.total_cmp(&a.area));
    cavities
}

/// Number of grid nodes by which the circulation contour is moved off the cavity into the fluid.
pub const CONTOUR_OFFSET: usize = 2;

/// Air nodes connected to the top row of the grid (the atmosphere), as a mask over the nodes.
pub fn atmosphere_mask(ls: &LevelSet) -> Vec<bool> {
    let mut mask = vec![false; ls.ny * ls.nz];
    let top: Vec<usize> = (0..ls.ny).map(|i| (ls.nz - 1) * ls.ny + i).collect();
    flood(ls, &top, &mut mask);
    mask
}

/// Whether the point is an atmosphere node of a grid (with its mask); false outside the grid.
pub fn is_atmosphere(ls: &LevelSet, mask: &[bool], p: &V2) -> bool {
    let f = (p - ls.origin) / ls.spacing;
    let (i, j) = (f.x.round(), f.y.round());
    if i < 0.0 || j < 0.0 || i as usize >= ls.ny || j as usize >= ls.nz {
        return false;
    }
    mask[j as usize * ls.ny + i as usize]
}

/// A plunge traps air that was open to the atmosphere at the previous check: at least this fraction of a
/// new cavity's nodes must have been atmosphere then. Holes that open inside a stretched sheet of particles
/// were fluid before and are not plunges.
pub const TRAPPED_FRACTION: f64 = 0.5;

/// Follows the air of a flow from check to check and reports the cavities that have just closed: those of
/// the current level set (area ≥ `min_area`, nodes accepted by `keep`) of which at least
/// [`TRAPPED_FRACTION`] was atmosphere at the previous check.
#[derive(Clone, Debug, Default)]
pub struct ClosureWatch {
    previous: Option<(LevelSet, Vec<bool>)>,
}

impl ClosureWatch {
    /// A watch that resumes from a saved previous check (level set and its atmosphere mask).
    pub fn resume(previous: Option<(LevelSet, Vec<bool>)>) -> Self {
        ClosureWatch { previous }
    }

    /// The previous check, for saving the watch (checkpoints).
    pub fn previous(&self) -> Option<&(LevelSet, Vec<bool>)> {
        self.previous.as_ref()
    }

    /// The cavities closed since the previous call, in [`find_cavities`] order; `None` on the first call,
    /// which has nothing to compare with. `ls` becomes the previous check.
    pub fn newly_closed(&mut self, ls: &LevelSet, min_area: f64, keep: impl Fn(&[V2]) -> bool) -> Option<Vec<Cavity>> {
        let closed = self.closed_since_previous(ls, min_area, keep);
        self.previous = Some((ls.clone(), atmosphere_mask(ls)));
        closed
    }

    /// The same without moving the previous check to `ls`: for checks between two regular ones (the
    /// step-by-step search of a plunge instant), which all compare with the same earlier check.
    pub fn closed_since_previous(
        &self,
        ls: &LevelSet,
        min_area: f64,
        keep: impl Fn(&[V2]) -> bool,
    ) -> Option<Vec<Cavity>> {
        let (pls, pmask) = self.previous.as_ref()?;
        let atmosphere = atmosphere_mask(ls);
        let cavities = find_cavities(ls, &atmosphere, min_area, keep);
        Some(
            cavities
                .into_iter()
                .filter(|c| trapped_fraction(ls, c, pls, pmask) >= TRAPPED_FRACTION)
                .collect(),
        )
    }
}

/// Share of the cavity's nodes that were atmosphere in an earlier level set (`earlier`, with its mask from
/// [`atmosphere_mask`]). A plunge traps air that was open; a hole that opens inside the fluid was not.
pub fn trapped_fraction(ls: &LevelSet, cavity: &Cavity, earlier: &LevelSet, earlier_mask: &[bool]) -> f64 {
    let open = cavity
        .nodes
        .iter()
        .filter(|&&(i, j)| is_atmosphere(earlier, earlier_mask, &ls.node(i, j)))
        .count();
    open as f64 / cavity.nodes.len().max(1) as f64
}

/// Velocity at `x` by first-order MLS from the fluid particles within the kernel support (Shepard where
/// the fit is ill-conditioned); `None` when no particle is near.
pub fn velocity_at(s: &Snapshot, cells: &crate::sph::neighbours::CellList<2>, x: &V2) -> Option<V2> {
    let kernel = Kernel::<2>::new(KernelKind::RenormalizedGaussian, s.h);
    let mut nb = vec![];
    cells.for_each_within(&s.pos, x, kernel.support, |j, rij, r| {
        nb.push((j, rij, kernel.w(r) * s.vol[j]));
    });
    if nb.is_empty() {
        return None;
    }
    let fit = match mls_fit(s.h, &nb) {
        crate::sph::mls::MlsFit::Empty => crate::sph::mls::MlsFit::Shepard {
            inv_sum: 1.0 / nb.iter().map(|n| n.2).sum::<f64>(),
        },
        f => f,
    };
    let mut u = V2::zeros();
    for (j, dx, wv) in &nb {
        u += s.vel[*j] * fit.weight(dx, *wv).0;
    }
    Some(u)
}

/// Circulation around the cavity, positive clockwise (see module doc). The contour is the staircase
/// around the cavity grown by [`CONTOUR_OFFSET`] nodes, so that it runs inside the fluid where the MLS
/// interpolation has neighbours on all sides.
pub fn circulation(s: &Snapshot, ls: &LevelSet, cavity: &Cavity) -> f64 {
    let support = 3.0 * s.h;
    let cells = s.cells(support);
    let mut inside: std::collections::HashSet<(usize, usize)> = cavity.nodes.iter().copied().collect();
    for _ in 0..CONTOUR_OFFSET {
        let grown: Vec<(usize, usize)> = inside
            .iter()
            .flat_map(|&(i, j)| {
                [
                    (i + 1, j),
                    (i.saturating_sub(1), j),
                    (i, j + 1),
                    (i, j.saturating_sub(1)),
                ]
            })
            .filter(|&(i, j)| i < ls.ny && j < ls.nz)
            .collect();
        inside.extend(grown);
    }
    let mut nodes: Vec<(usize, usize)> = inside.iter().copied().collect();
    nodes.sort_unstable();
    let half = 0.5 * ls.spacing;
    let mut ccw = 0.0;
    for &(i, j) in &nodes {
        let c = ls.node(i, j);
        // (neighbour offset, edge midpoint offset, counter-clockwise tangent of that edge)
        let edges = [
            ((1i64, 0i64), V2::new(half, 0.0), V2::new(0.0, 1.0)),
            ((-1, 0), V2::new(-half, 0.0), V2::new(0.0, -1.0)),
            ((0, 1), V2::new(0.0, half), V2::new(-1.0, 0.0)),
            ((0, -1), V2::new(0.0, -half), V2::new(1.0, 0.0)),
        ];
        for ((di, dj), off, t) in edges {
            let (ni, nj) = (i as i64 + di, j as i64 + dj);
            if ni >= 0 && nj >= 0 && inside.contains(&(ni as usize, nj as usize)) {
                continue;
            }
            if let Some(u) = velocity_at(s, &cells, &(c + off)) {
                ccw += u.dot(&t) * ls.spacing;
            }
        }
    }
    -ccw
}
