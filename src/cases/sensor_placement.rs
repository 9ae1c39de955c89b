//! Where a case's pressure sensor sits: on which wall, along which straight side, facing which way.
//!
//! A wall sensor (`[[probes.pressure]]` without `in_fluid`) is a face of width `size` centred at `position`. It
//! must lie on a wall (the one `wall` names, or the nearest), within [`ON_WALL_TOLERANCE`] of the domain's size,
//! and the whole face on one straight side of it (not past a corner). `direction`, when given, must be that
//! side's direction (either way along it). The solver reads it as the wall pressure averaged over the face
//! ([`crate::sph::wall_sensor`]).

use super::case_file::{CaseFile, PressureProbe};
use crate::sph::polyline_wall::solid_normals;
use nalgebra::Vector2;

type V2 = Vector2<f64>;

/// Largest distance of a wall sensor from its wall, as a fraction of the domain's largest side: 1e-6 (a
/// position typed to six significant digits lies on the wall; one a particle spacing off does not).
pub const ON_WALL_TOLERANCE: f64 = 1e-6;

/// A wall sensor located on its wall.
#[derive(Clone, Debug, PartialEq)]
pub struct Placement {
    /// Index of the wall in the case's `walls`.
    pub wall: usize,
    /// Face centre (m), on the wall.
    pub centre: V2,
    /// Unit direction of the face along the wall.
    pub tangent: V2,
    /// Unit normal of the wall into the fluid.
    pub inward: V2,
}

/// Locates probe `k` on the case's walls, or says (field, what was expected) what is wrong.
pub fn place(case: &CaseFile, k: usize, p: &PressureProbe) -> Result<Placement, (String, String)> {
    let field = |f: &str| format!("probes.pressure[{k}].{f}");
    let x = V2::new(p.position[0], p.position[1]);
    let extent = (0..2)
        .map(|i| case.domain.max[i] - case.domain.min[i])
        .fold(0.0, f64::max);
    let tol = ON_WALL_TOLERANCE * extent;
    let candidates: Vec<usize> = match &p.wall {
        Some(name) => vec![case.wall_named(name).map_err(|expected| (field("wall"), expected))?],
        None => (0..case.walls.len()).collect(),
    };
    if candidates.is_empty() {
        return Err((
            field("position"),
            "a point on a wall, but the case has no wall (a pressure probe in the fluid takes `in_fluid = true`)"
                .into(),
        ));
    }
    // Every straight side within the tolerance of the position, nearest first; remember the nearest of all.
    let mut sides = vec![];
    let mut nearest = (f64::INFINITY, x, 0usize);
    for &w in &candidates {
        let pts: Vec<V2> = case.walls[w].points.iter().map(|q| V2::new(q[0], q[1])).collect();
        let normals = solid_normals(&pts, case.walls[w].fluid_side);
        for (s, seg) in pts.windows(2).enumerate() {
            let ab = seg[1] - seg[0];
            let len = ab.norm();
            if len == 0.0 {
                continue;
            }
            let t = ab / len;
            let along = (x - seg[0]).dot(&t).clamp(0.0, len);
            let foot = seg[0] + t * along;
            let d = (x - foot).norm();
            if d < nearest.0 {
                nearest = (d, foot, w);
            }
            if d <= tol {
                sides.push((d, w, seg[0], seg[1], t, -normals[s]));
            }
        }
    }
    if sides.is_empty() {
        let (d, foot, w) = nearest;
        return Err((
            field("position"),
            format!(
                "a point on a wall (within {tol:.1e} m): the nearest, '{}', is {d:.4} m away, at ({:.6}, {:.6})",
                case.walls[w].name, foot.x, foot.y
            ),
        ));
    }
    sides.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut why = String::new();
    for &(_, w, a, b, t, inward) in &sides {
        if let Some(d) = &p.direction {
            let d = V2::new(d[0], d[1]);
            if (t.x * d.y - t.y * d.x).abs() > 1e-6 {
                why = format!(
                    "a unit `direction` along the wall side ({:.6}, {:.6}) it lies on",
                    t.x, t.y
                );
                continue;
            }
        }
        let half = 0.5 * p.size;
        let (s0, s1) = ((x - a).dot(&t) - half, (x - a).dot(&t) + half);
        let len = (b - a).norm();
        if s0 < -tol || s1 > len + tol {
            why = format!(
                "a face that stays on one straight side of wall '{}': ({:.4}, {:.4})–({:.4}, {:.4}), not past its \
                 corner ({} m wide, centred {:.4} m from the side's start of {:.4} m)",
                case.walls[w].name,
                a.x,
                a.y,
                b.x,
                b.y,
                p.size,
                s0 + half,
                len
            );
            continue;
        }
        return Ok(Placement {
            wall: w,
            centre: x,
            tangent: t,
            inward,
        });
    }
    let f = if why.starts_with("a unit") { "direction" } else { "size" };
    Err((field(f), why))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cases::builtin::builtin_text;

    fn tank() -> CaseFile {
        CaseFile::parse(builtin_text("hydrostatic").unwrap(), "built-in").unwrap()
    }

    fn probe(pos: [f64; 2], size: f64) -> PressureProbe {
        PressureProbe {
            name: "s".into(),
            position: pos.to_vec(),
            direction: None,
            size,
            wall: None,
            in_fluid: false,
        }
    }

    #[test]
    fn a_sensor_on_the_side_wall_faces_the_fluid() {
        let c = tank();
        let pl = place(&c, 0, &probe([2.0, 0.5], 0.1)).unwrap();
        assert_eq!(pl.wall, 0);
        assert!((pl.inward - V2::new(-1.0, 0.0)).norm() < 1e-12);
        assert!(pl.tangent.x.abs() < 1e-12);
        let floor = place(&c, 0, &probe([1.0, 0.0], 0.0)).unwrap();
        assert!((floor.inward - V2::new(0.0, 1.0)).norm() < 1e-12);
    }

    #[test]
    fn a_sensor_inside_the_fluid_is_refused_with_the_distance() {
        let (f, why) = place(&tank(), 3, &probe([1.89, 0.5], 0.0)).unwrap_err();
        assert_eq!(f, "probes.pressure[3].position");
        assert!(why.contains("0.1100 m away"), "{why}");
    }

    #[test]
    fn a_face_past_the_corner_is_refused() {
        let (f, why) = place(&tank(), 0, &probe([2.0, 0.01], 0.05)).unwrap_err();
        assert_eq!(f, "probes.pressure[0].size");
        assert!(why.contains("not past its corner"), "{why}");
    }

    #[test]
    fn a_direction_across_the_wall_is_refused() {
        let mut p = probe([2.0, 0.5], 0.0);
        p.direction = Some(vec![1.0, 0.0]);
        let (f, _) = place(&tank(), 0, &p).unwrap_err();
        assert_eq!(f, "probes.pressure[0].direction");
    }

    #[test]
    fn an_unknown_wall_name_lists_the_walls() {
        let mut p = probe([2.0, 0.5], 0.0);
        p.wall = Some("side".into());
        let (f, why) = place(&tank(), 0, &p).unwrap_err();
        assert_eq!(f, "probes.pressure[0].wall");
        assert!(why.contains("tank"));
    }
}
