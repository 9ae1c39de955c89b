//! Neighbour search: a cell list whose cells are half the search reach on a side, built by a counting sort,
//! and the brute-force O(N²) oracle it is tested against.

use nalgebra::SVector;
use rayon::prelude::*;

/// Cells per search reach along each axis (dimensionless). With cells of half the kernel support a search
/// measures the distance to the points of a 5 × 5 block (6.25 R² in 2D, 15.6 R³ in 3D) instead of a 3 × 3
/// block of support-sized cells (9 R², 27 R³): 31 % (2D) and 42 % (3D) fewer candidates for the same
/// neighbours (docs/decisions/cell-list.md).
pub const CELLS_PER_REACH: usize = 2;

/// A uniform grid of cells of edge `reach / CELLS_PER_REACH` over the bounding box of the points.
/// `sorted` holds point indices ordered by cell; the points of cell `c` are
/// `sorted[start[c]..start[c + 1]]`, in increasing index order (the counting sort is stable), and the cells of
/// one row along the first axis are consecutive, so a search reads each row of its block as one slice and
/// every neighbour sum visits its neighbours in a fixed order whatever the thread count.
#[derive(Clone, Debug)]
pub struct CellList<const D: usize> {
    origin: [f64; D],
    /// Cell edge (m).
    cell: f64,
    /// The largest search radius the list answers (m).
    reach: f64,
    dims: [usize; D],
    start: Vec<u32>,
    sorted: Vec<u32>,
}

impl<const D: usize> Default for CellList<D> {
    fn default() -> Self {
        CellList {
            origin: [0.0; D],
            cell: 1.0,
            reach: 1.0,
            dims: [1; D],
            start: vec![0, 0],
            sorted: vec![],
        }
    }
}

impl<const D: usize> CellList<D> {
    /// Cell index of every point, with the grid laid over their bounding box; searches up to radius `reach`.
    pub fn build(points: &[SVector<f64, D>], reach: f64) -> Self {
        let cell = reach / CELLS_PER_REACH as f64;
        let mut lo = [f64::INFINITY; D];
        let mut hi = [f64::NEG_INFINITY; D];
        for p in points {
            for d in 0..D {
                lo[d] = lo[d].min(p[d]);
                hi[d] = hi[d].max(p[d]);
            }
        }
        if points.is_empty() {
            lo = [0.0; D];
            hi = [0.0; D];
        }
        let mut dims = [1usize; D];
        for d in 0..D {
            dims[d] = (((hi[d] - lo[d]) / cell).floor() as usize + 1).max(1);
        }
        let ncell: usize = dims.iter().product();
        let mut list = CellList {
            origin: lo,
            cell,
            reach,
            dims,
            start: vec![0; ncell + 1],
            sorted: vec![0; points.len()],
        };
        // Counting sort by cell.
        let keys: Vec<u32> = points.par_iter().map(|p| list.cell_of(p) as u32).collect();
        for &k in &keys {
            list.start[k as usize + 1] += 1;
        }
        for c in 0..ncell {
            list.start[c + 1] += list.start[c];
        }
        let mut fill = list.start.clone();
        for (i, &k) in keys.iter().enumerate() {
            list.sorted[fill[k as usize] as usize] = i as u32;
            fill[k as usize] += 1;
        }
        list
    }

    fn coords(&self, p: &SVector<f64, D>) -> [isize; D] {
        let mut c = [0isize; D];
        for d in 0..D {
            c[d] = ((p[d] - self.origin[d]) / self.cell).floor() as isize;
        }
        c
    }

    fn cell_of(&self, p: &SVector<f64, D>) -> usize {
        let c = self.coords(p);
        let mut idx = 0usize;
        for d in (0..D).rev() {
            let cd = c[d].clamp(0, self.dims[d] as isize - 1) as usize;
            idx = idx * self.dims[d] + cd;
        }
        idx
    }

    /// Point indices in cell order: the permutation that sorts points by cell (for memory locality).
    pub fn order(&self) -> &[u32] {
        &self.sorted
    }

    /// Calls `f(j, x − x_j, |x − x_j|)` for every point j with |x − x_j| < radius (radius ≤ the list's reach).
    #[inline]
    pub fn for_each_within<F>(&self, points: &[SVector<f64, D>], x: &SVector<f64, D>, radius: f64, mut f: F)
    where
        F: FnMut(usize, SVector<f64, D>, f64),
    {
        self.for_each_within_r2(points, x, radius, |j, rij, d2| f(j, rij, d2.sqrt()));
    }

    /// As [`CellList::for_each_within`] but passes |x − x_j|² (no square root).
    #[inline]
    pub fn for_each_within_r2<F>(&self, points: &[SVector<f64, D>], x: &SVector<f64, D>, radius: f64, f: F)
    where
        F: FnMut(usize, SVector<f64, D>, f64),
    {
        self.visit(points, x, radius, usize::MAX, f);
    }

    /// As [`CellList::for_each_within`] but only over the points of index below `limit` (the fluid, when the
    /// ghosts were appended after it): a point at or above `limit` is passed over without measuring its
    /// distance. Visits the same points in the same order as filtering `for_each_within` by `j < limit`.
    #[inline]
    pub fn for_each_below_within<F>(
        &self,
        points: &[SVector<f64, D>],
        x: &SVector<f64, D>,
        radius: f64,
        limit: usize,
        mut f: F,
    ) where
        F: FnMut(usize, SVector<f64, D>, f64),
    {
        self.visit(points, x, radius, limit, |j, rij, d2| f(j, rij, d2.sqrt()));
    }

    /// Visits the block of cells within `radius` of x's cell, one row along the first axis at a time.
    #[inline]
    fn visit<F>(&self, points: &[SVector<f64, D>], x: &SVector<f64, D>, radius: f64, limit: usize, mut f: F)
    where
        F: FnMut(usize, SVector<f64, D>, f64),
    {
        debug_assert!(radius <= self.reach * (1.0 + 1e-12));
        let r2 = radius * radius;
        let n = (radius / self.cell).ceil() as isize;
        let c = self.coords(x);
        let x_lo = (c[0] - n).max(0);
        let x_hi = (c[0] + n).min(self.dims[0] as isize - 1);
        if x_lo > x_hi {
            return;
        }
        // Offsets along axes 1..D, advanced like an odometer.
        let mut o = [-n; D];
        loop {
            let mut row = 0usize;
            let mut inside = true;
            for d in (1..D).rev() {
                let cd = c[d] + o[d];
                if cd < 0 || cd >= self.dims[d] as isize {
                    inside = false;
                    break;
                }
                row = row * self.dims[d] + cd as usize;
            }
            if inside {
                let base = row * self.dims[0];
                let a = self.start[base + x_lo as usize] as usize;
                let b = self.start[base + x_hi as usize + 1] as usize;
                for &j in &self.sorted[a..b] {
                    let j = j as usize;
                    if j >= limit {
                        continue;
                    }
                    let rij = x - points[j];
                    let d2 = rij.norm_squared();
                    if d2 < r2 {
                        f(j, rij, d2);
                    }
                }
            }
            let mut d = 1;
            loop {
                if d >= D {
                    return;
                }
                o[d] += 1;
                if o[d] <= n {
                    break;
                }
                o[d] = -n;
                d += 1;
            }
        }
    }
}

/// The O(N²) oracle: indices of all points within `radius` of `x`, in increasing order.
pub fn brute_force_within<const D: usize>(points: &[SVector<f64, D>], x: &SVector<f64, D>, radius: f64) -> Vec<usize> {
    (0..points.len()).filter(|&j| (x - points[j]).norm() < radius).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Deterministic pseudo-random numbers in [0, 1) (a 64-bit LCG), so the test needs no extra crate.
    fn lcg(seed: &mut u64) -> f64 {
        *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (*seed >> 11) as f64 / (1u64 << 53) as f64
    }

    #[test]
    fn cell_list_matches_brute_force_in_2d_and_3d() {
        let mut seed = 7u64;
        let pts2: Vec<SVector<f64, 2>> = (0..800)
            .map(|_| SVector::from([lcg(&mut seed) * 3.0, lcg(&mut seed)]))
            .collect();
        let list = CellList::build(&pts2, 0.13);
        for x in pts2.iter().step_by(7) {
            let mut got = vec![];
            list.for_each_within(&pts2, x, 0.13, |j, _, _| got.push(j));
            got.sort();
            assert_eq!(got, brute_force_within(&pts2, x, 0.13));
        }
        let pts3: Vec<SVector<f64, 3>> = (0..600)
            .map(|_| SVector::from([lcg(&mut seed), lcg(&mut seed) * 2.0, lcg(&mut seed)]))
            .collect();
        let list3 = CellList::build(&pts3, 0.2);
        for x in pts3.iter().step_by(5) {
            let mut got = vec![];
            list3.for_each_within(&pts3, x, 0.2, |j, _, _| got.push(j));
            got.sort();
            assert_eq!(got, brute_force_within(&pts3, x, 0.2));
        }
        // Only the points below an index: the same as filtering the full search.
        for x in pts3.iter().step_by(11) {
            let mut got = vec![];
            list3.for_each_below_within(&pts3, x, 0.2, 250, |j, _, _| got.push(j));
            let mut all = vec![];
            list3.for_each_within(&pts3, x, 0.2, |j, _, _| all.push(j));
            all.retain(|&j| j < 250);
            assert_eq!(got, all);
            got.sort();
            assert_eq!(
                got,
                brute_force_within(&pts3, x, 0.2)
                    .into_iter()
                    .filter(|&j| j < 250)
                    .collect::<Vec<_>>()
            );
        }
        // A query point outside the bounding box still finds what is near it.
        let out = SVector::from([-0.05, 0.5]);
        let mut got = vec![];
        list.for_each_within(&pts2, &out, 0.13, |j, _, _| got.push(j));
        got.sort();
        assert_eq!(got, brute_force_within(&pts2, &out, 0.13));
    }

    #[test]
    fn order_is_a_permutation_grouped_by_cell() {
        let mut seed = 3u64;
        let pts: Vec<SVector<f64, 2>> = (0..300)
            .map(|_| SVector::from([lcg(&mut seed), lcg(&mut seed)]))
            .collect();
        let list = CellList::build(&pts, 0.1);
        let mut o: Vec<u32> = list.order().to_vec();
        let keys: Vec<usize> = o.iter().map(|&i| list.cell_of(&pts[i as usize])).collect();
        assert!(keys.windows(2).all(|w| w[0] <= w[1]));
        o.sort();
        assert_eq!(o, (0..300).collect::<Vec<u32>>());
    }
}
