//! The lid over the air of a 2D+t scene with air (`--air`): a horizontal wall at the top of the air layer that
//! rises as the section displaces water and falls as it leaves, so that tank, section and lid always enclose
//! the same area.
//!
//! Why a lid: the multi-fluid δ-SPH keeps the air's pressure positive with a background pressure
//! (`sph::multi_fluid`), which needs a closed domain; an air layer with a free top and none lifted off the
//! water (a still Athena tank at dx/L 4e-3 with 1 D of air: a gap of four spacings after 0.2 L, E_K/(M g D)
//! 3e-4 against 1e-6 with one phase). Why it moves: in a fixed closed tank the section's area (a few per cent
//! of the tank's) would have to be found by compressing the air, which the equal-stiffness sound speed makes
//! nearly as stiff as the water. Why one wall: the lid meets the hull and the tank's far wall at corners,
//! whose ghosts must mirror through the corner point (Fig. 7.3); drawn as separate walls, each one's ghosts
//! in the corner quadrant mirror into the other's solid and the air ran into both corners at 0.5 √(gL).
//! So with air the section, the lid and the tank are one deforming polyline ([`enclose`]).

use super::profile::SectionProfile;
use crate::sph::deforming_wall::Profile;
use nalgebra::Vector2;

type V2 = Vector2<f64>;

/// The section is sampled this many times finer than the run's spacing for the area the lid keeps: the
/// polygon's area then changes smoothly enough with x for its time derivatives (a resampling at the run's
/// spacing moves it by about 3e-4 of itself).
pub const AREA_SAMPLING: f64 = 10.0;

/// Area of the solid between the symmetry plane y = 0 and the wall polyline `points` (from the symmetry
/// plane's lower end up to its top, as [`SectionProfile::at`] draws it) below the height `z`.
pub fn solid_area_below(points: &[V2], z: f64) -> f64 {
    let (Some(first), Some(last)) = (points.first(), points.last()) else {
        return 0.0;
    };
    // The closed polygon: the wall, then back down the symmetry plane.
    let mut poly: Vec<V2> = points.to_vec();
    poly.push(V2::new(0.0, last.y));
    poly.push(V2::new(0.0, first.y));
    // Clip to z' ≤ z (one edge of Sutherland–Hodgman) and take the shoelace area.
    let mut clipped = Vec::with_capacity(poly.len() + 2);
    for k in 0..poly.len() {
        let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
        let (ina, inb) = (a.y <= z, b.y <= z);
        if ina {
            clipped.push(a);
        }
        if ina != inb {
            let s = (z - a.y) / (b.y - a.y);
            clipped.push(a + (b - a) * s);
        }
    }
    let n = clipped.len();
    (0..n)
        .map(|k| {
            let (a, b) = (clipped[k], clipped[(k + 1) % n]);
            a.x * b.y - b.x * a.y
        })
        .sum::<f64>()
        .abs()
        * 0.5
}

/// The lid of a tank `width` wide, at height `z0` while the section stands at its start.
#[derive(Clone)]
pub struct Lid {
    profile: SectionProfile,
    width: f64,
    z0: f64,
    /// The solid's area below z0 at the start.
    a0: f64,
}

impl Lid {
    pub fn new(profile: &SectionProfile, width: f64, z0: f64) -> Self {
        let mut profile = profile.clone();
        profile.ds /= AREA_SAMPLING;
        let a0 = solid_area_below(&profile.at(0.0).points, z0);
        Lid { profile, width, z0, a0 }
    }

    /// The lid's height at time t: W (z − z0) = A(z, t) − A(z0, 0), the tank's enclosed area kept. Solved by
    /// fixed-point iteration, which contracts by the section's half-breadth at the lid over W (below 1/8
    /// with W = 4B).
    pub fn height(&self, t: f64) -> f64 {
        let pts = self.profile.at(t).points;
        let mut z = self.z0;
        for _ in 0..8 {
            z = self.z0 + (solid_area_below(&pts, z) - self.a0) / self.width;
        }
        z
    }

    /// The lid's height, vertical velocity and acceleration at time t, the last two by central differences
    /// over the time the section takes to move one spacing (its area sampled [`AREA_SAMPLING`] times finer).
    pub fn motion(&self, t: f64) -> (f64, f64, f64) {
        let dt = AREA_SAMPLING * self.profile.ds / self.profile.u.max(1e-12);
        let (zm, z, zp) = (self.height(t - dt), self.height(t), self.height(t + dt));
        (z, (zp - zm) / (2.0 * dt), (zp - 2.0 * z + zm) / (dt * dt))
    }
}

/// The closed wall of a scene with air: the `section` (from the symmetry plane's lower end up, as
/// [`SectionProfile::at`] draws it) up to where it first reaches the lid's height, the lid (height, velocity,
/// acceleration `lid`) across to the far wall at y = `width`, down that wall to the bottom at −`depth`, along
/// the bottom and up the symmetry plane to `tank_end` (half a spacing below the section's start, as the fixed
/// tank of one phase ends, so the ghost lattice is the same across that junction).
pub fn enclose(section: &Profile, lid: (f64, f64, f64), width: f64, depth: f64, tank_end: f64) -> Profile {
    let (z, vz, az) = lid;
    let (p, m) = (&section.points, &section.motion);
    let mut out = Profile::default();
    let mut push = |x: V2, v: V2, a: V2| {
        out.points.push(x);
        out.motion.vel.push(v);
        out.motion.acc.push(a);
    };
    let mut k = 0;
    while k < p.len() && p[k].y < z {
        push(p[k], m.vel[k], m.acc[k]);
        k += 1;
    }
    // Where the section meets the lid: a point of the section whose motion has the section's normal
    // component along the section and the lid's along the lid (the ghosts of each side interpolate the
    // vertex's motion, and free slip reads its normal part: with the section's whole velocity the lid's
    // ghosts took its normal part, up to 1.7 √(gL) down at Athena's raked stem, across the whole lid).
    let (v_lid, a_lid) = (V2::new(0.0, vz), V2::new(0.0, az));
    match k {
        0 => push(V2::new(0.0, z), v_lid, a_lid),
        k if k == p.len() => push(V2::new(p[k - 1].x, z), v_lid, a_lid),
        k => {
            let s = (z - p[k - 1].y) / (p[k].y - p[k - 1].y);
            let at = |v: &[V2]| v[k - 1] + (v[k] - v[k - 1]) * s;
            let tangent = p[k] - p[k - 1];
            let normal = V2::new(-tangent.y, tangent.x).normalize();
            push(
                at(p),
                corner_motion(&normal, &at(&m.vel), vz),
                corner_motion(&normal, &at(&m.acc), az),
            );
        }
    }
    push(V2::new(width, z), v_lid, a_lid);
    push(V2::new(width, -depth), V2::zeros(), V2::zeros());
    push(V2::new(0.0, -depth), V2::zeros(), V2::zeros());
    push(V2::new(0.0, tank_end), V2::zeros(), V2::zeros());
    out
}

/// The vector whose component along the section's unit `normal` is that of `section` and whose vertical
/// component is `lid`: the motion of the corner where the section meets the lid. Where the section runs
/// nearly horizontal at the lid (within 6° of it), the two conditions nearly coincide and the section's
/// motion is kept.
fn corner_motion(normal: &V2, section: &V2, lid: f64) -> V2 {
    if normal.x.abs() < 0.1 {
        return *section;
    }
    V2::new((section.dot(normal) - lid * normal.y) / normal.x, lid)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A rectangle of half-breadth b from the symmetry plane's foot at z = −1 to the top at 1: the area below
    /// z is b (z + 1) wherever z cuts it, 0 below and 2b above.
    /// The closed wall follows the section up to the lid, then the lid, the far wall, the bottom and the
    /// symmetry plane, ending half a spacing below where it began.
    #[test]
    fn enclosed_wall_is_the_section_up_to_the_lid_then_the_tank() {
        let section = Profile {
            points: vec![
                V2::new(0.0, -1.0),
                V2::new(0.2, -0.5),
                V2::new(0.3, 0.5),
                V2::new(0.3, 1.0),
            ],
            motion: crate::sph::polyline_wall::VertexMotion {
                vel: vec![V2::zeros(), V2::new(1.0, 0.0), V2::new(3.0, 0.0), V2::new(3.0, 0.0)],
                acc: vec![V2::zeros(); 4],
            },
        };
        let w = enclose(&section, (0.0, 0.1, 0.0), 2.0, 3.0, -1.05);
        let want = [
            (0.0, -1.0),
            (0.2, -0.5),
            (0.25, 0.0),
            (2.0, 0.0),
            (2.0, -3.0),
            (0.0, -3.0),
            (0.0, -1.05),
        ];
        assert_eq!(w.points.len(), want.len());
        for (p, q) in w.points.iter().zip(want) {
            assert!((p - V2::new(q.0, q.1)).norm() < 1e-12, "{p:?} against {q:?}");
        }
        // The corner moves with the section along the section's normal (the section's velocity there is
        // half-way between its vertices', (2, 0)) and with the lid vertically; the lid's far end with the lid.
        let tangent = V2::new(0.1, 1.0).normalize();
        let normal = V2::new(-tangent.y, tangent.x);
        let corner = w.motion.vel[2];
        assert!(
            (corner.dot(&normal) - V2::new(2.0, 0.0).dot(&normal)).abs() < 1e-12,
            "{corner:?}"
        );
        assert!((corner.y - 0.1).abs() < 1e-12, "{corner:?}");
        assert_eq!(w.motion.vel[3], V2::new(0.0, 0.1));
    }

    #[test]
    fn area_below_a_height_is_the_clipped_rectangle() {
        let b = 0.3;
        let pts = [V2::new(0.0, -1.0), V2::new(b, -1.0), V2::new(b, 1.0)];
        for (z, want) in [(-2.0, 0.0), (-1.0, 0.0), (0.0, b), (0.5, 1.5 * b), (3.0, 2.0 * b)] {
            let got = solid_area_below(&pts, z);
            assert!((got - want).abs() < 1e-14, "z {z}: {got} against {want}");
        }
        // A wedge (a triangle from the keel at (0, −1) to (1, 1)): the area below z is (z + 1)²/4.
        let wedge = [V2::new(0.0, -1.0), V2::new(1.0, 1.0)];
        let got = solid_area_below(&wedge, 0.0);
        assert!((got - 0.25).abs() < 1e-14, "{got}");
    }
}
