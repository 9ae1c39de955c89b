//! The plunging jet at the plunge instant (definitions in docs/reference/jet-metrics.md, our own: the thesis gives
//! none). The jet is the fluid of the overhanging crest beyond the point where the front face of the wave
//! is vertical, bounded below by the cavity: the particles standing above the cavity, column by column of
//! the level-set grid, between the cavity's leftmost node (where its wall is vertical) and its rightmost
//! node (where the jet tip meets the free surface).

use super::cavity::Cavity;
use super::level_set::LevelSet;
use super::snapshot::{Snapshot, V2};
use std::collections::BTreeMap;

/// Geometry and kinematics of the jet (units of the snapshot).
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct JetMetrics {
    pub particles: usize,
    /// S: area, Σ V_j.
    pub area: f64,
    /// Length of the medial line (volume-weighted mean height of each grid column, root to tip, plus half a
    /// column at either end).
    pub length: f64,
    /// Centre of mass (y_G, z_G).
    pub y_g: f64,
    pub z_g: f64,
    /// Centre-of-mass velocity (v_G, w_G).
    pub v_g: f64,
    pub w_g: f64,
    /// Polar moment of inertia about the centre of mass, Σ V |r − r_G|².
    pub i_og: f64,
    /// Inclination of the jet's principal (long) axis to the horizontal, degrees, positive when the axis
    /// descends towards +y.
    pub alpha_g_deg: f64,
    /// Inclination of the centre-of-mass velocity to the horizontal, degrees, positive downwards.
    pub alpha_vg_deg: f64,
}

/// Indices of the jet particles.
pub fn jet_particles(s: &Snapshot, ls: &LevelSet, cavity: &Cavity) -> Vec<usize> {
    // Top of the cavity in each grid column.
    let mut top: BTreeMap<usize, f64> = BTreeMap::new();
    for &(i, j) in &cavity.nodes {
        let z = ls.node(i, j).y;
        let e = top.entry(i).or_insert(f64::NEG_INFINITY);
        *e = e.max(z);
    }
    (0..s.len())
        .filter(|&k| {
            let p = s.pos[k];
            if p.x < cavity.leftmost.x || p.x > cavity.rightmost.x + 0.5 * ls.spacing {
                return false;
            }
            let col = ((p.x - ls.origin.x) / ls.spacing).round();
            if col < 0.0 {
                return false;
            }
            top.get(&(col as usize)).is_some_and(|&zt| p.y > zt)
        })
        .collect()
}

/// Metrics of a set of particles taken as the jet; `None` if it is empty.
pub fn metrics(s: &Snapshot, ls: &LevelSet, idx: &[usize]) -> Option<JetMetrics> {
    if idx.is_empty() {
        return None;
    }
    let area: f64 = idx.iter().map(|&k| s.vol[k]).sum();
    let g = idx.iter().fold(V2::zeros(), |a, &k| a + s.pos[k] * s.vol[k]) / area;
    let v = idx.iter().fold(V2::zeros(), |a, &k| a + s.vel[k] * s.vol[k]) / area;
    let (mut jyy, mut jzz, mut jyz) = (0.0, 0.0, 0.0);
    for &k in idx {
        let d = s.pos[k] - g;
        jyy += s.vol[k] * d.x * d.x;
        jzz += s.vol[k] * d.y * d.y;
        jyz += s.vol[k] * d.x * d.y;
    }
    // Long axis: eigenvector of the largest eigenvalue of [[jyy, jyz], [jyz, jzz]].
    let theta = 0.5 * (2.0 * jyz).atan2(jyy - jzz);
    let mut alpha_g = -theta.to_degrees();
    if alpha_g > 90.0 {
        alpha_g -= 180.0;
    } else if alpha_g <= -90.0 {
        alpha_g += 180.0;
    }
    // Medial line.
    let mut cols: BTreeMap<i64, (f64, f64)> = BTreeMap::new();
    for &k in idx {
        let c = ((s.pos[k].x - ls.origin.x) / ls.spacing).round() as i64;
        let e = cols.entry(c).or_insert((0.0, 0.0));
        e.0 += s.vol[k] * s.pos[k].y;
        e.1 += s.vol[k];
    }
    let line: Vec<V2> = cols
        .iter()
        .map(|(&c, &(zv, v))| V2::new(ls.origin.x + c as f64 * ls.spacing, zv / v))
        .collect();
    let length = line.windows(2).map(|w| (w[1] - w[0]).norm()).sum::<f64>() + ls.spacing;
    Some(JetMetrics {
        particles: idx.len(),
        area,
        length,
        y_g: g.x,
        z_g: g.y,
        v_g: v.x,
        w_g: v.y,
        i_og: jyy + jzz,
        alpha_g_deg: alpha_g,
        alpha_vg_deg: (-v.y).atan2(v.x).to_degrees(),
    })
}
