//! Free-surface detection, level set, cavities, circulation and jet metrics on synthetic particle sets
//! with known answers.

use bowwave::analysis::{cavity, jet, level_set, Snapshot};
use bowwave::sph::free_surface::{detect, Thresholds};
use bowwave::sph::kernel::{Kernel, KernelKind};
use bowwave::sph::neighbours::CellList;
use nalgebra::Vector2;

type V2 = Vector2<f64>;

fn lattice(dx: f64, lo: V2, hi: V2, keep: impl Fn(&V2) -> bool) -> Vec<V2> {
    let ny = ((hi.x - lo.x) / dx).round() as usize;
    let nz = ((hi.y - lo.y) / dx).round() as usize;
    let mut out = vec![];
    for i in 0..ny {
        for j in 0..nz {
            let p = lo + V2::new((i as f64 + 0.5) * dx, (j as f64 + 0.5) * dx);
            if keep(&p) {
                out.push(p);
            }
        }
    }
    out
}

fn snapshot(pos: Vec<V2>, vel: Vec<V2>, dx: f64) -> Snapshot {
    let h = 1.33 * dx;
    let kernel = Kernel::<2>::new(KernelKind::RenormalizedGaussian, h);
    let vol = vec![dx * dx; pos.len()];
    let cells = CellList::build(&pos, kernel.support);
    let fs = detect(&kernel, &cells, &pos, &vol, pos.len(), Thresholds::default());
    Snapshot {
        pos,
        vel,
        vol,
        on_surface: fs.on_surface,
        normal: fs.normal,
        lambda: fs.lambda,
        h,
        dx,
    }
}

/// A square pool with a circular hole around a clockwise point vortex of circulation Γ: the hole is the
/// one cavity found, and the circulation along its staircase boundary is Γ.
#[test]
fn cavity_around_a_point_vortex_has_its_circulation() {
    let dx = 0.02;
    let radius = 0.15; // 7.5 dx: larger than the 2h the detection resolves
    let centre = V2::new(0.5, 0.5);
    let pos = lattice(dx, V2::zeros(), V2::new(1.0, 1.0), |p| (p - centre).norm() > radius);
    let gamma = 0.3;
    let vel = pos
        .iter()
        .map(|p| {
            let d = p - centre;
            V2::new(d.y, -d.x) * (gamma / (2.0 * std::f64::consts::PI * d.norm_squared()))
        })
        .collect();
    let s = snapshot(pos, vel, dx);
    let ls = level_set::level_set(&s, V2::new(-0.1, -0.1), V2::new(1.1, 1.1), dx);
    let cavities = cavity::find_cavities(&ls, (2.0 * s.h).powi(2), |_| true);
    assert_eq!(cavities.len(), 1, "one enclosed cavity expected");
    let c = &cavities[0];
    assert!((c.centroid - centre).norm() < dx, "centroid {:?}", c.centroid);
    // The free surface lies half a spacing inside the ring of particle centres: area π (R − dx/2)² to a cell.
    let expected = std::f64::consts::PI * (radius - 0.5 * dx).powi(2);
    assert!((c.area / expected - 1.0).abs() < 0.15, "area {} vs {expected}", c.area);
    let g = cavity::circulation(&s, &ls, c);
    assert!((g / gamma - 1.0).abs() < 0.02, "Γ = {g}, expected {gamma}");
}

/// An overturned wave of rectangles: pool, a face column rising from it, a horizontal slab (the jet) and a
/// tip column falling back to the pool. The cavity is the rectangle under the slab, and the jet metrics are
/// those of the slab: area a·b, I_OG/S² = (a² + b²)/(12 a b), horizontal axis, known centre and velocity.
#[test]
fn rectangular_jet_over_a_cavity_has_the_slab_metrics() {
    let dx = 0.01;
    let (y0, y1, z0, z1) = (0.5, 1.4, 0.6, 0.8); // the slab
    let in_wave = |p: &V2| {
        let pool = p.y < 0.0;
        let face = p.x > 0.2 && p.x < y0 && p.y < z1;
        let slab = p.x >= y0 && p.x <= y1 && p.y > z0 && p.y < z1;
        let tip = p.x > y1 && p.x < 1.6 && p.y < z1;
        pool || face || slab || tip
    };
    let pos = lattice(dx, V2::new(0.0, -0.5), V2::new(2.0, 0.8), in_wave);
    let u_jet = V2::new(0.7, -0.4);
    let vel = pos.iter().map(|p| if p.y > z0 { u_jet } else { V2::zeros() }).collect();
    let s = snapshot(pos, vel, dx);
    let ls = level_set::level_set(&s, V2::new(-0.05, -0.55), V2::new(2.05, 1.0), dx);
    let cavities = cavity::find_cavities(&ls, (2.0 * s.h).powi(2), |_| true);
    assert_eq!(cavities.len(), 1);
    let c = &cavities[0];
    let idx = jet::jet_particles(&s, &ls, c);
    let m = jet::metrics(&s, &ls, &idx).expect("jet found");
    let (a, b) = (y1 - y0, z1 - z0);
    let rel = |x: f64, e: f64| (x / e - 1.0).abs();
    assert!(rel(m.area, a * b) < 0.03, "S = {} vs {}", m.area, a * b);
    assert!(rel(m.i_og / (m.area * m.area), (a * a + b * b) / (12.0 * a * b)) < 0.05);
    assert!(rel(m.length, a) < 0.03, "L = {} vs {a}", m.length);
    assert!(m.alpha_g_deg.abs() < 1.0, "α_G = {}", m.alpha_g_deg);
    assert!((m.y_g - 0.5 * (y0 + y1)).abs() < dx && (m.z_g - 0.5 * (z0 + z1)).abs() < dx);
    assert!((m.v_g - u_jet.x).abs() < 1e-12 && (m.w_g - u_jet.y).abs() < 1e-12);
    let expected_vg = (0.4f64).atan2(0.7).to_degrees();
    assert!((m.alpha_vg_deg - expected_vg).abs() < 1e-9);
    // The impact point (rightmost cavity node) is at the tip column's face.
    assert!((c.rightmost.x - y1).abs() < 2.0 * dx, "impact y {}", c.rightmost.x);
}
