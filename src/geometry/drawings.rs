//! `bowwave hull show`: the lines drawings of a hull as PNG files — body plan (fore sections on the right,
//! aft sections on the left, as naval architects draw it), profile (keel, stem and deck lines), waterline
//! plan (half-breadths at several heights), and w_n/U along the girth at a few stations.

use super::surface::HullSurface;
use crate::io::plot::{line_plot_with, PlotOptions, Series, Style};
use std::path::{Path, PathBuf};

/// Writes the drawings into `dir`; returns the files.
pub fn draw(s: &HullSurface, dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let name = &s.meta.name;
    let (x0, x1) = s.x_range;
    let mut files = vec![];
    let ng = 200;
    let curve_pts = |x: f64, side: f64| -> Vec<(f64, f64)> {
        let c = s.curve(x).unwrap();
        (0..=ng)
            .map(|k| {
                let p = c.point(k as f64 / ng as f64);
                (side * p.y, p.z)
            })
            .collect()
    };
    // Body plan: 10 sections forward of midship on the right, 10 aft on the left.
    let mid = 0.5 * (x0 + x1);
    let mut series = vec![];
    for i in 0..=10 {
        let xf = x0 + (mid - x0) * i as f64 / 10.0;
        let xa = mid + (x1 - mid) * i as f64 / 10.0;
        series.push(Series {
            name: format!("x/L = {xf:.2}"),
            points: curve_pts(xf.max(x0 + 1e-6), 1.0),
            style: Style::Line,
        });
        series.push(Series {
            name: format!("x/L = {xa:.2}"),
            points: curve_pts(xa.min(x1 - 1e-6), -1.0),
            style: Style::Line,
        });
    }
    let (mut ymax, mut zmin, mut zmax) = (0.0f64, f64::INFINITY, f64::NEG_INFINITY);
    for p in series.iter().flat_map(|s| s.points.iter()) {
        ymax = ymax.max(p.0.abs());
        zmin = zmin.min(p.1);
        zmax = zmax.max(p.1);
    }
    series.push(Series {
        name: "waterline".into(),
        points: vec![(-1.1 * ymax, 0.0), (1.1 * ymax, 0.0)],
        style: Style::Line,
    });
    let (hw, hz) = (1.1 * ymax, 1.1 * (zmax - zmin));
    let h = 700u32;
    let w = ((h as f64) * (2.0 * hw) / hz).clamp(500.0, 1800.0) as u32 + 90;
    let p = dir.join(format!("{name}_body_plan.png"));
    line_plot_with(
        &p,
        &format!("{name}: body plan (aft | fore), units of L"),
        "y/L",
        "z/L",
        &series,
        &PlotOptions {
            size: (w, h),
            legend: false,
            range: Some((-hw, hw, zmin - 0.05 * hz, zmax + 0.05 * hz)),
        },
    )?;
    files.push(p);

    // Profile: keel and deck lines.
    let n = 300;
    let xs: Vec<f64> = (0..=n).map(|i| x0 + (x1 - x0) * i as f64 / n as f64).collect();
    let keel: Vec<(f64, f64)> = xs.iter().map(|&x| (x, s.curve(x).unwrap().point(0.0).z)).collect();
    let deck: Vec<(f64, f64)> = xs.iter().map(|&x| (x, s.curve(x).unwrap().point(1.0).z)).collect();
    let p = dir.join(format!("{name}_profile.png"));
    line_plot_with(
        &p,
        &format!("{name}: profile"),
        "x/L from the stem",
        "z/L",
        &[
            Series {
                name: "keel / stem".into(),
                points: keel,
                style: Style::Line,
            },
            Series {
                name: "deck".into(),
                points: deck,
                style: Style::Line,
            },
            Series {
                name: "waterline".into(),
                points: vec![(x0, 0.0), (x1, 0.0)],
                style: Style::Line,
            },
        ],
        &PlotOptions {
            size: (1400, 450),
            ..Default::default()
        },
    )?;
    files.push(p);

    // Waterline plan: half-breadth at heights z = k·zmin/3 (k = 0..2) and at the deck.
    let breadth_at = |x: f64, z: f64| -> f64 {
        let c = s.curve(x).unwrap();
        let mut last = c.point(0.0);
        if last.z > z {
            return f64::NAN;
        }
        for k in 1..=ng {
            let p = c.point(k as f64 / ng as f64);
            if p.z >= z {
                let f = (z - last.z) / (p.z - last.z);
                return last.y + f * (p.y - last.y);
            }
            last = p;
        }
        f64::NAN
    };
    let mut wl = vec![];
    for k in 0..3 {
        let z = zmin * k as f64 / 3.0;
        wl.push(Series {
            name: format!("z/L = {z:.4}"),
            points: xs.iter().map(|&x| (x, breadth_at(x, z))).collect(),
            style: Style::Line,
        });
    }
    let p = dir.join(format!("{name}_waterlines.png"));
    line_plot_with(
        &p,
        &format!("{name}: waterline plan (half-breadths)"),
        "x/L from the stem",
        "y/L",
        &wl,
        &PlotOptions {
            size: (1400, 450),
            ..Default::default()
        },
    )?;
    files.push(p);

    // w_n along the girth at a few stations.
    let mut wn = vec![];
    for f in [0.05, 0.1, 0.2, 0.3, 0.5, 0.8] {
        let x = x0 + f * (x1 - x0);
        let pts: Vec<(f64, f64)> = s
            .section(x, 0.002)
            .unwrap()
            .iter()
            .map(|q| (q.xi, q.w_n_over_u))
            .collect();
        wn.push(Series {
            name: format!("x/L = {x:.2}"),
            points: pts,
            style: Style::Line,
        });
    }
    let p = dir.join(format!("{name}_wn.png"));
    line_plot_with(
        &p,
        &format!("{name}: expansion velocity w_n/U along the girth (eq. 10.4)"),
        "normalised girth (keel 0, deck 1)",
        "w_n / U",
        &wn,
        &PlotOptions::default(),
    )?;
    files.push(p);
    Ok(files)
}
