//! An axis-aligned rectangular tank in any dimension D, its walls made of fixed ghost particles (thesis
//! §7.1.1): the 3D counterpart of a rectangular [`super::polyline_wall::PolylineWall`], and the wall of the
//! 3D comparison runs.
//!
//! The ghosts sit on the fluid's lattice, at lo + (i + ½) ds along each axis, in the layers (k + ½) ds < support
//! outside every walled face; the top face (the last axis's upper side) is open, and the side walls end at the
//! tank's top. A ghost outside the tank along one axis mirrors through that face (a plane mirror); outside along
//! all D axes, through the vertex (the central symmetry of Fig. 7.3); in 3D, outside along two axes, through the
//! edge the two faces share ([`Mirror::Axes`]: reflected along those two axes, kept along the edge). In 2D the
//! ghosts are those of the rectangular polyline tank, mirror for mirror (test
//! `two_dimensional_box_has_the_ghosts_of_the_rectangular_polyline_tank`).

use super::boundary::{image_reach, Boundary, FluxNodes, GhostGeometry, Mirror};
use super::polyline_wall::{GhostKind, FLUX_NODES_PER_DX};
use nalgebra::SVector;

/// A still, axis-aligned tank [lo, hi] (m), open at the top (the upper side of the last axis).
#[derive(Clone, Debug)]
pub struct BoxWall<const D: usize> {
    name: String,
    lo: SVector<f64, D>,
    hi: SVector<f64, D>,
    ds: f64,
    support: f64,
    kind: GhostKind,
    base: GhostGeometry<D>,
    /// With [`GhostKind::NormalFlux`], the faces' nodes; none otherwise.
    nodes: FluxNodes<D>,
}

impl<const D: usize> BoxWall<D> {
    /// The tank [lo, hi] for particle spacing `ds` and kernel support `support` (m). Each side must be a whole
    /// number of spacings long (the ghosts then continue the fluid's lattice), else the error says which.
    pub fn new(name: &str, lo: SVector<f64, D>, hi: SVector<f64, D>, ds: f64, support: f64) -> Result<Self, String> {
        if !(ds > 0.0 && support > 0.0) {
            return Err(format!(
                "box wall '{name}': spacing {ds} and support {support} must be positive"
            ));
        }
        let mut cells = [0usize; D];
        for k in 0..D {
            cells[k] = whole_spacings(hi[k] - lo[k], ds).ok_or_else(|| {
                format!(
                    "box wall '{name}': side {k} is {} m long, expected a positive whole number of spacings {ds} m",
                    hi[k] - lo[k]
                )
            })?;
        }
        let mut layers = 0usize;
        while (layers as f64 + 0.5) * ds < support {
            layers += 1;
        }
        let base = lattice_ghosts(&lo, ds, &cells, layers);
        Ok(BoxWall {
            name: name.to_string(),
            lo,
            hi,
            ds,
            support,
            kind: GhostKind::Fixed,
            base,
            nodes: FluxNodes::default(),
        })
    }

    /// The same tank with ghosts of kind `kind`: with [`GhostKind::Images`] the faces get the mirror images of
    /// the fluid at each stage (as the polyline wall's straight sides do) and only the edge and vertex ghosts
    /// stay fixed.
    pub fn with_ghosts(mut self, kind: GhostKind) -> Self {
        self.kind = kind;
        match kind {
            GhostKind::Images => self.base = self.base.filtered(|k| self.base.mirror[k] != Mirror::Plane),
            GhostKind::NormalFlux => {
                self.base = GhostGeometry::default();
                self.nodes = self.face_nodes();
            }
            GhostKind::Fixed => {}
        }
        self
    }

    /// The same tank without the fixed ghosts `keep` refuses (by position and mirror point): where another
    /// wall's ghosts take the lattice nodes, e.g. a hull crossing the tank's symmetry plane.
    pub fn retain_ghosts(mut self, keep: impl Fn(&SVector<f64, D>, &SVector<f64, D>) -> bool) -> Self {
        self.base = self.base.filtered(|k| keep(&self.base.pos[k], &self.base.interp[k]));
        self
    }

    /// Ghost geometry (for tests and plots).
    pub fn base_ghosts(&self) -> &GhostGeometry<D> {
        &self.base
    }
}

/// The number of spacings `ds` in `length` if it is a positive whole number of them (within 1e-6 of one), else
/// `None`. The box's sides, and the blocks of water laid on the same lattice, must be.
pub fn whole_spacings(length: f64, ds: f64) -> Option<usize> {
    let n = length / ds;
    (n >= 1.0 && (n - n.round()).abs() <= 1e-6).then(|| n.round() as usize)
}

/// The ghosts around the box of `cells` lattice cells from `lo`, `layers` deep on every side but the top.
fn lattice_ghosts<const D: usize>(
    lo: &SVector<f64, D>,
    ds: f64,
    cells: &[usize; D],
    layers: usize,
) -> GhostGeometry<D> {
    let mut g = GhostGeometry::default();
    let l = layers as i64;
    // Lattice index ranges: −layers … cells + layers − 1, except the last axis, which stops at the top.
    let range = |k: usize| -> (i64, i64) {
        let n = cells[k] as i64;
        (-l, if k == D - 1 { n } else { n + l })
    };
    let mut idx = [0i64; D];
    for (k, i) in idx.iter_mut().enumerate() {
        *i = range(k).0;
    }
    'cells: loop {
        let mut mask = 0u8;
        let mut pos = SVector::<f64, D>::zeros();
        let mut interp = SVector::<f64, D>::zeros();
        for k in 0..D {
            let n = cells[k] as i64;
            pos[k] = lo[k] + (idx[k] as f64 + 0.5) * ds;
            // Reflect the index through the face it is beyond: i → −1 − i below, 2n − 1 − i above.
            let mirrored = if idx[k] < 0 {
                mask |= 1 << k;
                -1 - idx[k]
            } else if idx[k] >= n {
                mask |= 1 << k;
                2 * n - 1 - idx[k]
            } else {
                idx[k]
            };
            interp[k] = lo[k] + (mirrored as f64 + 0.5) * ds;
        }
        if mask != 0 {
            g.pos.push(pos);
            g.interp.push(interp);
            g.wall_vel.push(SVector::zeros());
            g.wall_acc.push(SVector::zeros());
            g.volume.push(ds.powi(D as i32));
            g.mirror.push(match mask.count_ones() as usize {
                1 => Mirror::Plane,
                m if m == D => Mirror::Point,
                _ => Mirror::Axes(mask),
            });
        }
        // Next index, the first axis fastest.
        for (k, i) in idx.iter_mut().enumerate() {
            *i += 1;
            if *i < range(k).1 {
                continue 'cells;
            }
            *i = range(k).0;
        }
        break;
    }
    g
}

impl<const D: usize> BoxWall<D> {
    /// The normal-flux nodes of the faces (the open top has none): each face cut into cells of
    /// ds / [`FLUX_NODES_PER_DX`] along its other axes, a node at each cell's centre with the cell's area.
    fn face_nodes(&self) -> FluxNodes<D> {
        let mut out = FluxNodes::default();
        for k in 0..D {
            for upper in [false, true] {
                if upper && k == D - 1 {
                    continue; // the open top
                }
                let mut outward = SVector::<f64, D>::zeros();
                outward[k] = if upper { 1.0 } else { -1.0 };
                let axes: Vec<usize> = (0..D).filter(|&a| a != k).collect();
                let cells: Vec<usize> = axes
                    .iter()
                    .map(|&a| {
                        ((self.hi[a] - self.lo[a]) * FLUX_NODES_PER_DX / self.ds)
                            .round()
                            .max(1.0) as usize
                    })
                    .collect();
                let size: Vec<f64> = axes
                    .iter()
                    .zip(&cells)
                    .map(|(&a, &m)| (self.hi[a] - self.lo[a]) / m as f64)
                    .collect();
                let area: f64 = size.iter().product();
                let mut idx = vec![0usize; axes.len()];
                loop {
                    let mut x = SVector::<f64, D>::zeros();
                    x[k] = if upper { self.hi[k] } else { self.lo[k] };
                    for (b, &a) in axes.iter().enumerate() {
                        x[a] = self.lo[a] + (idx[b] as f64 + 0.5) * size[b];
                    }
                    out.pos.push(x);
                    out.outward.push(outward);
                    out.area.push(area);
                    out.wall_vel.push(SVector::zeros());
                    out.wall_acc.push(SVector::zeros());
                    // The next cell, odometer-wise; done when every axis has wrapped.
                    let mut b = 0;
                    while b < idx.len() {
                        idx[b] += 1;
                        if idx[b] < cells[b] {
                            break;
                        }
                        idx[b] = 0;
                        b += 1;
                    }
                    if b == idx.len() {
                        break;
                    }
                }
            }
        }
        out
    }
}

impl<const D: usize> Boundary<D> for BoxWall<D> {
    fn name(&self) -> &str {
        &self.name
    }
    fn moves(&self) -> bool {
        false
    }
    fn ghosts(&self, _t: f64, out: &mut GhostGeometry<D>) {
        out.append(&self.base);
    }
    fn flux_nodes(&self, _t: f64, out: &mut FluxNodes<D>) {
        out.append(&self.nodes);
    }
    /// With [`GhostKind::Images`]: every particle within the support of a wall face, over that face (inside
    /// the tank along the other axes, so not above the side walls' top), gets its image through the face, if
    /// the image can touch the fluid ([`image_reach`]).
    fn images(&self, _t: f64, pos: &[SVector<f64, D>], out: &mut GhostGeometry<D>, source: &mut Vec<usize>) {
        if self.kind != GhostKind::Images {
            return;
        }
        for k in 0..D {
            for upper in [false, true] {
                if upper && k == D - 1 {
                    continue; // the open top
                }
                let face = if upper { self.hi[k] } else { self.lo[k] };
                let depth_of = |x: &SVector<f64, D>| if upper { face - x[k] } else { x[k] - face };
                let nearest = pos.iter().map(depth_of).fold(f64::INFINITY, f64::min);
                let reach = image_reach(self.support, nearest);
                for (j, x) in pos.iter().enumerate() {
                    let depth = depth_of(x);
                    // Over the face: inside the tank along the other axes (the side walls end at the top).
                    let over = (0..D)
                        .filter(|&a| a != k)
                        .all(|a| x[a] >= self.lo[a] && x[a] <= self.hi[a]);
                    if depth <= 0.0 || depth >= reach || !over {
                        continue;
                    }
                    let mut image = *x;
                    image[k] = 2.0 * face - x[k];
                    out.pos.push(image);
                    out.interp.push(*x);
                    out.wall_vel.push(SVector::zeros());
                    out.wall_acc.push(SVector::zeros());
                    out.volume.push(0.0); // the solver gives an image its particle's volume m/ρ
                    out.mirror.push(Mirror::Plane);
                    source.push(j);
                }
            }
        }
    }
    /// A particle beyond a walled face by less than the support is put back min(½ ds, depth + ¼ ds) inside,
    /// its velocity into that face removed (as the polyline wall does).
    fn keep_out(&self, _t: f64, x: &mut SVector<f64, D>, u: &mut SVector<f64, D>) -> bool {
        let beyond = |k: usize, v: f64| v < self.lo[k] || (k + 1 < D && v > self.hi[k]);
        let near = (0..D).all(|k| x[k] > self.lo[k] - self.support && (k + 1 == D || x[k] < self.hi[k] + self.support));
        if !near || x[D - 1] > self.hi[D - 1] || !(0..D).any(|k| beyond(k, x[k])) {
            return false;
        }
        for k in 0..D {
            if x[k] < self.lo[k] {
                let depth = self.lo[k] - x[k];
                x[k] = self.lo[k] + (0.5 * self.ds).min(depth + 0.25 * self.ds);
                u[k] = u[k].max(0.0);
            } else if k + 1 < D && x[k] > self.hi[k] {
                let depth = x[k] - self.hi[k];
                x[k] = self.hi[k] - (0.5 * self.ds).min(depth + 0.25 * self.ds);
                u[k] = u[k].min(0.0);
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::polyline_wall::{ghost_layers, FluidSide};
    use nalgebra::{Vector2, Vector3};

    /// A normal-flux box has no ghosts and nodes that tile its closed faces: each face's areas add up to the
    /// face's, its normals point out of the water, and the open top has none.
    #[test]
    fn normal_flux_box_nodes_tile_its_faces_with_outward_normals() {
        let (dx, support) = (0.1, 0.399);
        let (lo, hi) = (Vector3::new(0.0, 0.0, 0.0), Vector3::new(0.6, 0.4, 0.3));
        let b = BoxWall::new("tank", lo, hi, dx, support)
            .unwrap()
            .with_ghosts(GhostKind::NormalFlux);
        let (mut ghosts, mut nodes) = (GhostGeometry::default(), FluxNodes::default());
        b.ghosts(0.0, &mut ghosts);
        b.flux_nodes(0.0, &mut nodes);
        assert!(ghosts.is_empty());
        let centre = (lo + hi) * 0.5;
        let mut area = [[0.0; 2]; 3];
        for k in 0..nodes.len() {
            let n = nodes.outward[k];
            let axis = n.iamax();
            assert!((n.norm() - 1.0).abs() < 1e-15 && n[axis].abs() == 1.0);
            assert!(
                (nodes.pos[k] - centre).dot(&n) > 0.0,
                "normal into the water at {:?}",
                nodes.pos[k]
            );
            area[axis][usize::from(n[axis] > 0.0)] += nodes.area[k];
        }
        let face = |a: usize| (0..3).filter(|&b| b != a).map(|b| hi[b] - lo[b]).product::<f64>();
        for (a, sides) in area.iter().enumerate() {
            assert!((sides[0] - face(a)).abs() < 1e-12, "axis {a}: {sides:?}");
            let top = if a == 2 { 0.0 } else { face(a) };
            assert!((sides[1] - top).abs() < 1e-12, "axis {a}: {sides:?}");
        }
    }

    #[test]
    fn two_dimensional_box_has_the_ghosts_of_the_rectangular_polyline_tank() {
        let (dx, support) = (0.1, 0.399);
        let b = BoxWall::new("tank", Vector2::new(0.0, 0.0), Vector2::new(2.0, 1.0), dx, support).unwrap();
        let pts = vec![
            Vector2::new(0.0, 1.0),
            Vector2::new(0.0, 0.0),
            Vector2::new(2.0, 0.0),
            Vector2::new(2.0, 1.0),
        ];
        let p = ghost_layers(&pts, FluidSide::Left, dx, support);
        let key = |x: &Vector2<f64>| ((x.x / dx * 2.0).round() as i64, (x.y / dx * 2.0).round() as i64);
        let mut ours: Vec<_> = (0..b.base.len())
            .map(|k| (key(&b.base.pos[k]), key(&b.base.interp[k]), b.base.mirror[k]))
            .collect();
        let mut theirs: Vec<_> = (0..p.len())
            .map(|k| (key(&p.pos[k]), key(&p.interp[k]), p.mirror[k]))
            .collect();
        ours.sort_by_key(|e| (e.0, e.1));
        theirs.sort_by_key(|e| (e.0, e.1));
        assert_eq!(ours.len(), theirs.len());
        assert_eq!(ours, theirs);
    }

    #[test]
    fn three_dimensional_box_mirrors_faces_edges_and_vertices_into_the_tank() {
        let (dx, support) = (0.1, 0.26); // 3 layers: (k + ½) dx < support for k = 0, 1, 2
        let lo = Vector3::new(0.0, 0.0, 0.0);
        let hi = Vector3::new(0.5, 0.4, 0.3);
        let b = BoxWall::new("tank", lo, hi, dx, support).unwrap();
        let g = b.base_ghosts();
        // Outer box (5 + 6) × (4 + 6) × (3 + 3) cells minus the tank's 5 × 4 × 3.
        assert_eq!(g.len(), 11 * 10 * 6 - 5 * 4 * 3);
        let (mut planes, mut edges, mut points) = (0, 0, 0);
        for k in 0..g.len() {
            let (x, xi) = (g.pos[k], g.interp[k]);
            assert!(
                (0..3).all(|a| xi[a] > lo[a] && xi[a] < hi[a]),
                "mirror point {xi:?} outside the tank"
            );
            // Reflected exactly along the axes it is beyond, kept along the others.
            let moved: Vec<usize> = (0..3).filter(|&a| (x[a] - xi[a]).abs() > 1e-12).collect();
            match g.mirror[k] {
                Mirror::Plane => planes += (moved.len() == 1) as usize,
                Mirror::Axes(m) => {
                    edges += 1;
                    assert_eq!(moved.iter().map(|a| 1u8 << a).sum::<u8>(), m);
                }
                Mirror::Point => points += (moved.len() == 3) as usize,
            }
        }
        // Faces: two of 4×3 (x), two of 5×3 (y), the floor 5×4, each 3 deep; edges: four vertical
        // (3 high), two along x (5), two along y (4) on the floor, each 3×3; vertices: the floor's four, 3³.
        assert_eq!(planes, 3 * (2 * 12 + 2 * 15 + 20));
        assert_eq!(edges, 9 * (4 * 3 + 2 * 5 + 2 * 4));
        assert_eq!(points, 4 * 27);
    }

    #[test]
    fn image_faces_mirror_each_particle_through_the_faces_within_its_support() {
        let b = BoxWall::new("tank", Vector3::zeros(), Vector3::new(1.0, 1.0, 1.0), 0.1, 0.4)
            .unwrap()
            .with_ghosts(GhostKind::Images);
        // Only edge and vertex ghosts stay fixed.
        assert!(b.base_ghosts().mirror.iter().all(|m| *m != Mirror::Plane));
        // Near the floor and the x = 0 face: two images; in the middle none; near the open top none.
        let pos = [
            Vector3::new(0.15, 0.5, 0.05),
            Vector3::new(0.5, 0.5, 0.5),
            Vector3::new(0.5, 0.5, 0.95),
        ];
        let (mut out, mut source) = (GhostGeometry::default(), vec![]);
        b.images(0.0, &pos, &mut out, &mut source);
        assert_eq!(source, vec![0, 0]);
        let mut images: Vec<_> = out.pos.iter().map(|p| (p.x, p.z)).collect();
        images.sort_by(|a, b| a.partial_cmp(b).unwrap());
        assert!((images[0].0 + 0.15).abs() < 1e-12 && (images[0].1 - 0.05).abs() < 1e-12);
        assert!((images[1].0 - 0.15).abs() < 1e-12 && (images[1].1 + 0.05).abs() < 1e-12);
        assert!(out.interp.iter().all(|x| *x == pos[0]) && out.mirror.iter().all(|m| *m == Mirror::Plane));
    }

    /// Oracle for the images' reach (`image_reach`) in 3D: on a jittered lattice in the tank, every image a
    /// brute-force search finds within the support of some particle is made, every image made is one the full
    /// support would make, and fewer are made than the full support would.
    #[test]
    fn box_images_are_made_where_they_touch_the_fluid_and_nowhere_deeper() {
        let (dx, support) = (0.1, 0.399);
        let hi = Vector3::new(1.0, 0.6, 1.0);
        let b = BoxWall::new("tank", Vector3::zeros(), hi, dx, support)
            .unwrap()
            .with_ghosts(GhostKind::Images);
        let mut jitter = crate::sph::boundary::image_oracle::jitter(777, 0.2 * dx);
        let mut pos = vec![];
        for i in 0..10 {
            for j in 0..6 {
                for k in 0..6 {
                    let c = |n: usize| (n as f64 + 0.5) * dx;
                    pos.push(Vector3::new(c(i) + jitter(), c(j) + jitter(), c(k) + jitter()));
                }
            }
        }
        let (mut out, mut source) = (GhostGeometry::default(), vec![]);
        b.images(0.0, &pos, &mut out, &mut source);
        let mut candidates = vec![];
        for (n, x) in pos.iter().enumerate() {
            for a in 0..3 {
                if x[a] < support {
                    let mut p = *x;
                    p[a] = -x[a];
                    candidates.push((n, p));
                }
                if a < 2 && hi[a] - x[a] < support {
                    let mut p = *x;
                    p[a] = 2.0 * hi[a] - x[a];
                    candidates.push((n, p));
                }
            }
        }
        crate::sph::boundary::image_oracle::check(&pos, &candidates, &source, &out.pos, support);
    }

    /// Regression: the first version imaged a particle through a side face at any height, above the top
    /// where the wall (its fixed ghosts, and the polyline's images) ends.
    #[test]
    fn particle_above_a_side_wall_gets_no_image() {
        let b = BoxWall::new("tank", Vector3::zeros(), Vector3::new(1.0, 1.0, 1.0), 0.1, 0.4)
            .unwrap()
            .with_ghosts(GhostKind::Images);
        let (mut out, mut source) = (GhostGeometry::default(), vec![]);
        b.images(0.0, &[Vector3::new(0.05, 0.5, 1.1)], &mut out, &mut source);
        assert!(source.is_empty() && out.is_empty());
        b.images(0.0, &[Vector3::new(0.05, 0.5, 0.9)], &mut out, &mut source);
        assert_eq!(source, vec![0]);
    }

    #[test]
    fn box_of_a_fractional_number_of_spacings_is_refused_with_the_side_named() {
        let e = BoxWall::new("tank", Vector3::zeros(), Vector3::new(1.0, 0.25, 1.0), 0.1, 0.4).unwrap_err();
        assert!(e.contains("side 1") && e.contains("whole number"), "{e}");
    }

    #[test]
    fn particle_pushed_through_the_floor_comes_back_without_its_downward_velocity() {
        let b = BoxWall::new("tank", Vector3::zeros(), Vector3::new(1.0, 1.0, 1.0), 0.1, 0.4).unwrap();
        let mut x = Vector3::new(0.5, 0.5, -0.01);
        let mut u = Vector3::new(0.3, 0.0, -1.0);
        assert!(b.keep_out(0.0, &mut x, &mut u));
        assert!((x.z - 0.035).abs() < 1e-12 && u == Vector3::new(0.3, 0.0, 0.0));
        // Above the open top nothing is inside.
        let mut x = Vector3::new(1.05, 0.5, 1.2);
        assert!(!b.keep_out(0.0, &mut x, &mut u));
    }
}
