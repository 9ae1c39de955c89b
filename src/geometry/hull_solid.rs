//! The hull as a 3D solid: points of its surface with their outward normals, both sides of the centre
//! plane, sampled finely enough that the nearest sample to any point stands for the nearest surface point
//! (a 3D wall needs that, the 2D+t sections do not). Units of L. Knows nothing of SPH.
//!
//! The side of the hull r(x, ξ) = (x, y(x, ξ), z(x, ξ)) has the outward normal −(r_x × r_ξ) =
//! (−(y_x z_ξ − z_x y_ξ), z_ξ, −y_ξ), normalised: its (y, z) part is the section's normal of eq. (10.3) and its
//! x part is −w_n/U (eq. 10.4) times the section's normal length, so a widening bow faces forward. A transom
//! (`meta.transom`) closes the hull aft with the flat face x = x_end, normal +x. The deck is not sampled: it
//! is the top of the hull, above the water.

use super::surface::HullSurface;

/// A point of the hull's surface, its unit normal into the water and the area of the patch of surface it stands
/// for (units of L and L²).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrientedPoint {
    pub pos: [f64; 3],
    pub normal: [f64; 3],
    pub area: f64,
}

/// The area of a patch dx long along x and ds along a cut x = const of a surface whose unit normal is `normal`:
/// dx ds / |n_yz| (the surface leans along x by the normal's x part).
pub fn patch_area(dx: f64, ds: f64, normal: &[f64; 3]) -> f64 {
    dx * ds / normal[1].hypot(normal[2])
}

/// The weights of the trapezoidal rule over points `at` (a coordinate along a curve): half the distance to each
/// neighbour.
pub fn trapezoid_weights(at: &[f64]) -> Vec<f64> {
    (0..at.len())
        .map(|k| {
            let before = if k > 0 { (at[k] - at[k - 1]).abs() } else { 0.0 };
            let after = if k + 1 < at.len() {
                (at[k + 1] - at[k]).abs()
            } else {
                0.0
            };
            0.5 * (before + after)
        })
        .collect()
}

/// The surface's points at spacing about `ds` (units of L) along x and along the girth, on the side y ≥ 0 and
/// mirrored to y ≤ 0, and on the transom face if the hull has one. The areas are the trapezoidal rule's weights
/// in x and along the girth; a point on the centre plane that has no mirror image (its normal in the plane)
/// carries both sides' share. On the transom the rows at each girth point's height stop half a spacing short
/// of the side (a strip of ds/2 per row not counted).
pub fn oriented_points(s: &HullSurface, ds: f64) -> Vec<OrientedPoint> {
    let (x0, x1) = s.x_range;
    let nx = (((x1 - x0) / ds).ceil() as usize).max(1);
    let xs: Vec<f64> = (0..=nx).map(|i| x0 + (x1 - x0) * i as f64 / nx as f64).collect();
    let wx = trapezoid_weights(&xs);
    let mut half = vec![];
    for (i, &x) in xs.iter().enumerate() {
        let Some(section) = s.section(x, ds) else {
            continue;
        };
        // Arc length along the section, for the girth weights.
        let mut arc = vec![0.0];
        for w in section.windows(2) {
            arc.push(arc.last().unwrap() + (w[1].y - w[0].y).hypot(w[1].z - w[0].z));
        }
        let wg = trapezoid_weights(&arc);
        for (p, w) in section.iter().zip(&wg) {
            let q = p.point;
            let n = [-(q.y_x * q.z_xi - q.z_x * q.y_xi), q.z_xi, -q.y_xi];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            if len > 0.0 {
                let normal = n.map(|c| c / len);
                half.push(OrientedPoint {
                    pos: [x, p.y.max(0.0), p.z],
                    normal,
                    area: patch_area(wx[i], *w, &normal),
                });
            }
        }
        if s.meta.transom && i == nx {
            let heights: Vec<f64> = section.iter().map(|p| p.z).collect();
            for (p, dz) in section.iter().zip(trapezoid_weights(&heights)) {
                let m = (p.y / ds).ceil() as usize;
                for j in 0..m {
                    let dy = p.y / m as f64 * if j == 0 { 0.5 } else { 1.0 };
                    half.push(OrientedPoint {
                        pos: [x, p.y * j as f64 / m as f64, p.z],
                        normal: [1.0, 0.0, 0.0],
                        area: dy * dz,
                    });
                }
            }
        }
    }
    let mirrored_too = |p: &OrientedPoint| p.pos[1] > 0.0 || p.normal[1] != 0.0;
    let mirrored: Vec<OrientedPoint> = half
        .iter()
        .filter(|p| mirrored_too(p))
        .map(|p| OrientedPoint {
            pos: [p.pos[0], -p.pos[1], p.pos[2]],
            normal: [p.normal[0], -p.normal[1], p.normal[2]],
            area: p.area,
        })
        .collect();
    for p in half.iter_mut().filter(|p| !mirrored_too(p)) {
        p.area *= 2.0;
    }
    half.extend(mirrored);
    half
}

/// The section at x/L as a closed polygon (y, z) in units of L: the curve from the keel to the deck, `n` + 1
/// points, closed along the centre plane; `None` outside the hull.
pub fn section_polygon(s: &HullSurface, x: f64, n: usize) -> Option<Vec<[f64; 2]>> {
    let c = s.curve(x)?;
    let mut poly: Vec<[f64; 2]> = (0..=n)
        .map(|k| {
            let p = c.point(k as f64 / n as f64);
            [p.y.max(0.0), p.z]
        })
        .collect();
    let (keel, deck) = (poly[0][1], poly[n][1]);
    poly.push([0.0, deck]);
    poly.push([0.0, keel]);
    Some(poly)
}

/// Whether (|y|, z) lies inside the closed polygon `poly` (crossing number; the hull is symmetric).
pub fn polygon_contains(poly: &[[f64; 2]], y: f64, z: f64) -> bool {
    let y = y.abs();
    let mut inside = false;
    for k in 0..poly.len() {
        let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
        if (a[1] > z) != (b[1] > z) {
            let y_cross = a[0] + (z - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if y < y_cross {
                inside = !inside;
            }
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::wigley;

    /// Wigley's side y = (B/2)(1 − (2x'/L)²)(1 − (z/D)²): at midship half-depth the normal is the gradient of
    /// y − Y(x, z), horizontal in x there; at the bow it faces forward.
    #[test]
    fn wigley_normals_are_the_gradient_of_its_exact_form() {
        let spec = wigley::WigleySpec::default();
        let s = HullSurface::new(&wigley::wigley(&spec));
        let pts = oriented_points(&s, 2e-3);
        let d = 1.0 / spec.l_over_d;
        // The outward normal of y = Y(x, z) on the side y > 0 is ∇(y − Y) = (−∂Y/∂x, 1, −∂Y/∂z), normalised.
        let exact = |x: f64, z: f64| {
            let e = 1e-6;
            let dydx = (wigley::half_breadth(&spec, x + e, z) - wigley::half_breadth(&spec, x - e, z)) / (2.0 * e);
            let dydz = (wigley::half_breadth(&spec, x, z + e) - wigley::half_breadth(&spec, x, z - e)) / (2.0 * e);
            let n = [-dydx, 1.0, -dydz];
            let l = (n[0] * n[0] + 1.0 + n[2] * n[2]).sqrt();
            n.map(|c| c / l)
        };
        // Away from the ends and the waterline's knuckle (the file is wall-sided above it), where the 21
        // stations' spline follows the form: the bound is the interpolant's error, a wrong sign or a
        // missing term of the formula would be O(0.1–1).
        let (mut checked, mut worst) = (0, 0.0f64);
        for p in pts.iter().filter(|p| {
            p.pos[1] > 1e-3 && p.pos[2] < -0.2 * d && p.pos[2] > -0.9 * d && p.pos[0] > 0.1 && p.pos[0] < 0.9
        }) {
            let e = exact(p.pos[0], p.pos[2]);
            let err = (0..3).map(|k| (p.normal[k] - e[k]).abs()).fold(0.0, f64::max);
            worst = worst.max(err);
            assert!(err < 5e-3, "normal {:?} at {:?}, exact {e:?}", p.normal, p.pos);
            checked += 1;
        }
        assert!(checked > 1000, "{checked}");
        println!("{checked} normals, largest component error {worst:.2e}");
        // Both sides, mirrored.
        let port = pts.iter().filter(|p| p.pos[1] < 0.0).count();
        let starboard = pts.iter().filter(|p| p.pos[1] > 0.0).count();
        assert_eq!(port, starboard);
    }

    /// The points' areas add up to the hull's surface: Wigley's wetted surface (up to the waterline z = 0) by
    /// a fine quadrature of its exact form, within 0.5 % (the 21 stations' spline against the form; a missing
    /// lean factor or a double-counted keel would be several per cent; 0.02 % measured).
    #[test]
    fn point_areas_add_up_to_the_wetted_surface() {
        let spec = wigley::WigleySpec::default();
        let s = HullSurface::new(&wigley::wigley(&spec));
        let d = 1.0 / spec.l_over_d;
        let pts = oriented_points(&s, 2e-3);
        let ours: f64 = pts.iter().filter(|p| p.pos[2] < 0.0).map(|p| p.area).sum();
        // Both sides of y = Y(x, z) over 0 < x < 1, −D < z < 0: ∫∫ √(1 + Y_x² + Y_z²) dx dz, twice.
        let (n, e) = (800, 1e-6);
        let mut exact = 0.0;
        for i in 0..n {
            for k in 0..n {
                let (x, z) = ((i as f64 + 0.5) / n as f64, -d * (k as f64 + 0.5) / n as f64);
                let y = |x: f64, z: f64| wigley::half_breadth(&spec, x, z);
                let yx = (y(x + e, z) - y(x - e, z)) / (2.0 * e);
                let yz = (y(x, z + e) - y(x, z - e)) / (2.0 * e);
                exact += 2.0 * (1.0 + yx * yx + yz * yz).sqrt() * d / (n * n) as f64;
            }
        }
        println!("wetted surface {ours:.6} L² against {exact:.6} L²");
        assert!((ours / exact - 1.0).abs() < 5e-3, "{ours} against {exact}");
    }

    #[test]
    fn wigley_section_contains_what_lies_inside_its_exact_form() {
        let spec = wigley::WigleySpec::default();
        let s = HullSurface::new(&wigley::wigley(&spec));
        let poly = section_polygon(&s, 0.5, 400).unwrap();
        let y_wl = wigley::half_breadth(&spec, 0.5, -0.05);
        assert!(polygon_contains(&poly, 0.99 * y_wl, -0.05) && polygon_contains(&poly, -0.99 * y_wl, -0.05));
        assert!(!polygon_contains(&poly, 1.01 * y_wl, -0.05) && !polygon_contains(&poly, 0.0, -0.101));
        assert!(section_polygon(&s, 1.1, 10).is_none());
    }

    /// A transom hull is closed aft by its transom face, facing aft.
    #[test]
    fn transom_face_closes_the_hull_aft() {
        let h = crate::geometry::hull_file::HullOffsets::read(std::path::Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/hulls/athena.csv"
        )))
        .unwrap();
        let s = HullSurface::new(&h);
        let pts = oriented_points(&s, 2e-3);
        let aft: Vec<_> = pts.iter().filter(|p| p.normal == [1.0, 0.0, 0.0]).collect();
        assert!(aft.len() > 100);
        assert!(aft.iter().all(|p| (p.pos[0] - s.x_range.1).abs() < 1e-12));
        // The face spans the centre plane to the transom's half-breadth.
        let widest = aft.iter().map(|p| p.pos[1]).fold(0.0, f64::max);
        let c = s.curve(s.x_range.1).unwrap();
        let half_breadth = (0..=1000).map(|k| c.point(k as f64 / 1000.0).y).fold(0.0, f64::max);
        assert!((widest - half_breadth).abs() < 2e-3, "{widest} against {half_breadth}");
        assert!(aft.iter().any(|p| p.pos[1] == 0.0));
    }
}
