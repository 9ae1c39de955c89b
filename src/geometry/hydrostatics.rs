//! Hydrostatics of a hull surface at its design waterline (z = 0): section areas, displacement, waterplane
//! area, form coefficients, LCB, wetted girth. All in units of L (areas L², volume L³).

use super::surface::HullSurface;
use serde::Serialize;

/// Underwater section properties at one x.
#[derive(Clone, Copy, Debug, Default, Serialize)]
pub struct SectionHydro {
    pub x: f64,
    /// Area of the full (port + starboard) section below z = 0.
    pub area: f64,
    /// Half-breadth at the waterline.
    pub half_breadth_wl: f64,
    /// Girth of one side from the keel to the waterline.
    pub girth: f64,
}

/// Integrated hydrostatics.
#[derive(Clone, Copy, Debug, Default, Serialize)]
pub struct Hydrostatics {
    /// Displaced volume ∇/L³.
    pub volume: f64,
    /// Waterplane area A_w/L².
    pub waterplane: f64,
    /// Largest section area A_M/L².
    pub max_section: f64,
    pub cb: f64,
    pub cp: f64,
    pub cm: f64,
    pub cwp: f64,
    /// Longitudinal centre of buoyancy, x/L from the stem.
    pub lcb: f64,
    /// Draft and beam measured on the surface (units of L).
    pub draft: f64,
    pub beam: f64,
}

/// Section properties at x from a dense sampling of the curve (`n` girth points).
pub fn section_hydro(s: &HullSurface, x: f64, n: usize) -> SectionHydro {
    let Some(c) = s.curve(x) else {
        return SectionHydro {
            x,
            ..Default::default()
        };
    };
    let pts: Vec<[f64; 2]> = (0..=n)
        .map(|k| {
            let p = c.point(k as f64 / n as f64);
            [p.y.max(0.0), p.z]
        })
        .collect();
    // Clip the curve at z = 0 (first crossing from the keel).
    let mut under = vec![[0.0, pts[0][1]]];
    let mut girth = 0.0;
    let mut yw = 0.0;
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        if b[1] <= 0.0 {
            girth += (b[0] - a[0]).hypot(b[1] - a[1]);
            under.push(b);
            yw = b[0];
            continue;
        }
        if a[1] <= 0.0 {
            let f = -a[1] / (b[1] - a[1]);
            let c0 = [a[0] + f * (b[0] - a[0]), 0.0];
            girth += (c0[0] - a[0]).hypot(c0[1] - a[1]);
            under.push(c0);
            yw = c0[0];
        }
        break;
    }
    if pts[0][1] > 0.0 {
        return SectionHydro {
            x,
            ..Default::default()
        };
    }
    // Polygon: centre plane at the keel → curve → waterline → back along z = 0 to the centre plane.
    under.push([0.0, 0.0]);
    let mut a2 = 0.0;
    for i in 0..under.len() {
        let (p, q) = (under[i], under[(i + 1) % under.len()]);
        a2 += p[0] * q[1] - q[0] * p[1];
    }
    SectionHydro {
        x,
        area: a2.abs(),
        half_breadth_wl: yw,
        girth,
    }
}

/// Hydrostatics by Simpson's rule over `nx` (even) intervals of x, each section sampled at `ng` girth points.
pub fn hydrostatics(s: &HullSurface, nx: usize, ng: usize) -> (Hydrostatics, Vec<SectionHydro>) {
    let nx = nx + nx % 2;
    let (x0, x1) = s.x_range;
    let dx = (x1 - x0) / nx as f64;
    let secs: Vec<SectionHydro> = (0..=nx).map(|i| section_hydro(s, x0 + i as f64 * dx, ng)).collect();
    let simpson = |f: &dyn Fn(&SectionHydro) -> f64| {
        let mut acc = 0.0;
        for (i, sec) in secs.iter().enumerate() {
            let w = if i == 0 || i == nx {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            acc += w * f(sec);
        }
        acc * dx / 3.0
    };
    let volume = simpson(&|s| s.area);
    let waterplane = 2.0 * simpson(&|s| s.half_breadth_wl);
    let moment = simpson(&|s| s.x * s.area);
    let max_section = secs.iter().map(|s| s.area).fold(0.0, f64::max);
    let beam = 2.0 * secs.iter().map(|s| s.half_breadth_wl).fold(0.0, f64::max);
    let mut draft: f64 = 0.0;
    for sec in &secs {
        if let Some(c) = s.curve(sec.x) {
            draft = draft.max(-c.point(0.0).z);
        }
    }
    let l = x1 - x0;
    let h = Hydrostatics {
        volume,
        waterplane,
        max_section,
        cb: volume / (l * beam * draft),
        cp: volume / (max_section * l),
        cm: max_section / (beam * draft),
        cwp: waterplane / (l * beam),
        lcb: moment / volume,
        draft,
        beam,
    };
    (h, secs)
}
