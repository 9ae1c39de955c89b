//! Station facts measured on a hull surface: where the stem enters the calm water, where the keel is
//! deepest, where the hull is widest, where it ends. These are what a source states about a hull without
//! publishing its offsets (Marrone 2011, Fig. 10.7, for Athena), so a generated approximation is checked by
//! measuring them from its file, not from its generator's parameters.

use super::hydrostatics::section_hydro;
use super::surface::HullSurface;
use serde::Serialize;

/// Grid of x on which the facts are searched before refinement: 1/2000 of the length.
const NX: usize = 2000;
/// Girth samples per section when looking for its widest point.
const NG: usize = 400;

/// Measured station facts (x/L from the stem, heights z/L up from the calm water).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct StationFacts {
    /// Keel height at the first station: positive when the stem's foot is out of the water there.
    pub stem_keel_z: f64,
    /// First x where the keel reaches the calm waterline (water entry of the 2D+t section).
    pub entry: f64,
    /// x of the keel's deepest point, and its depth.
    pub deepest_keel: f64,
    pub draft: f64,
    /// x of the widest section (the largest half-breadth at any height) and of the widest waterline.
    pub widest: f64,
    pub widest_waterline: f64,
    /// x of the last station and its waterline half-breadth (0 without a transom).
    pub end: f64,
    pub end_half_breadth_wl: f64,
}

fn keel_z(s: &HullSurface, x: f64) -> f64 {
    s.curve(x).map_or(f64::INFINITY, |c| c.point(0.0).z)
}

fn widest_y(s: &HullSurface, x: f64) -> f64 {
    s.curve(x).map_or(0.0, |c| {
        (0..=NG).map(|k| c.point(k as f64 / NG as f64).y).fold(0.0, f64::max)
    })
}

/// Refines the argmin of `f` around grid point `i` of `xs` by golden-section search on its two neighbours.
fn refine_min(xs: &[f64], i: usize, f: &dyn Fn(f64) -> f64) -> f64 {
    let (mut a, mut b) = (xs[i.saturating_sub(1)], xs[(i + 1).min(xs.len() - 1)]);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..40 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if f(c) < f(d) {
            b = d;
        } else {
            a = c;
        }
    }
    0.5 * (a + b)
}

fn argmin(xs: &[f64], f: &dyn Fn(f64) -> f64) -> f64 {
    let (i, _) = xs.iter().map(|&x| f(x)).enumerate().fold(
        (0, f64::INFINITY),
        |best, (i, v)| if v < best.1 { (i, v) } else { best },
    );
    refine_min(xs, i, f)
}

/// Measures the facts on a grid of 1/2000 L refined by bisection (entry) and golden section (extrema).
pub fn measure(s: &HullSurface) -> StationFacts {
    let (x0, x1) = s.x_range;
    let xs: Vec<f64> = (0..=NX).map(|i| x0 + (x1 - x0) * i as f64 / NX as f64).collect();
    let entry = match xs.iter().position(|&x| keel_z(s, x) <= 0.0) {
        Some(0) => x0,
        Some(i) => {
            let (mut a, mut b) = (xs[i - 1], xs[i]);
            for _ in 0..50 {
                let m = 0.5 * (a + b);
                if keel_z(s, m) > 0.0 {
                    a = m;
                } else {
                    b = m;
                }
            }
            0.5 * (a + b)
        }
        None => f64::NAN,
    };
    let deepest_keel = argmin(&xs, &|x| keel_z(s, x));
    let widest = argmin(&xs, &|x| -widest_y(s, x));
    let widest_waterline = argmin(&xs, &|x| -section_hydro(s, x, NG).half_breadth_wl);
    StationFacts {
        stem_keel_z: keel_z(s, x0),
        entry,
        deepest_keel,
        draft: -keel_z(s, deepest_keel),
        widest,
        widest_waterline,
        end: x1,
        end_half_breadth_wl: section_hydro(s, x1, NG).half_breadth_wl,
    }
}

impl std::fmt::Display for StationFacts {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "stem foot z/L {:+.4} at x/L 0; water entry x/L {:.4}; deepest keel x/L {:.4} (T/L {:.5}); widest \
             x/L {:.4} (waterline {:.4}); end x/L {:.4} (waterline half-breadth {:.5} L)",
            self.stem_keel_z,
            self.entry,
            self.deepest_keel,
            self.draft,
            self.widest,
            self.widest_waterline,
            self.end,
            self.end_half_breadth_wl
        )
    }
}
