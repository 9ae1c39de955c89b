//! Pictures and tables of the 2D+t scene: the bow region at the plunge for the study's sheet, PNG snapshots
//! coloured by pressure and by initial depth (thesis Fig. 10.7), VTK frames.

use super::scene::Scene;
use crate::analysis::{cavity, Snapshot};
use crate::io::{csv_table::Table, plot, vtk};
use std::path::Path;

/// The bow region (y < 2B, z > −D) at the plunge, or at the end without one, for the study's sheet of
/// snapshots: particles (y/L, z/L, initial row 0 and 1 marked as 1 and 0.75, deeper ones by depth/D up to
/// 0.5, as in [`depth_plot`]) and the wall polyline.
pub(crate) fn bow_tables(scene: &Scene, s: &Snapshot) -> (Table, Table) {
    let g = &scene.geom;
    let mut parts = Table::new(vec!["y_over_l".into(), "z_over_l".into(), "mark".into()]);
    for (k, p) in s.pos.iter().enumerate() {
        if p.x < 2.0 * g.beam && p.y > -g.draft {
            let id = scene.sim.fluid.id[s.index[k]] as usize;
            let mark = match scene.initial_row[id] {
                0 => 1.0,
                1 => 0.75,
                _ => (scene.initial_depth[id] / g.draft).min(0.5),
            };
            parts.push(vec![p.x, p.y, mark]);
        }
    }
    let mut wall = Table::new(vec!["y_over_l".into(), "z_over_l".into()]);
    for p in scene.profile.at(scene.sim.time).points {
        wall.push(vec![p.x, p.y]);
    }
    (parts, wall)
}

/// Points of a plot.
type PlotPoints = Vec<(f64, f64)>;

/// Particle positions and the current wall polyline, for plots.
fn plot_points(scene: &Scene, s: &Snapshot) -> (PlotPoints, PlotPoints) {
    let pts = s.pos.iter().map(|p| (p.x, p.y)).collect();
    let wall = scene
        .profile
        .at(scene.sim.time)
        .points
        .iter()
        .map(|p| (p.x, p.y))
        .collect();
    (pts, wall)
}

pub(crate) fn write_frame(scene: &Scene, s: &Snapshot, path: &Path) -> anyhow::Result<()> {
    let f = &scene.sim.fluid;
    let pts: Vec<[f64; 3]> = f.pos.iter().map(|p| [p.x, p.y, 0.0]).collect();
    // The snapshot's free surface is the water's: the air (with `--air`) is never on it.
    let mut on_surface = vec![0.0; f.len()];
    for (k, &i) in s.index.iter().enumerate() {
        on_surface[i] = s.on_surface[k] as u8 as f64;
    }
    let mut data = vec![
        vtk::PointData::Scalar("pressure", scene.sim.pressure().to_vec()),
        vtk::PointData::Scalar("initial_depth", f.tag.clone()),
        vtk::PointData::Scalar("free_surface", on_surface),
        vtk::PointData::Vector("velocity", f.vel.iter().map(|v| [v.x, v.y, 0.0]).collect()),
    ];
    if scene.sim.cfg.multi_fluid.is_some() {
        data.push(vtk::PointData::Scalar(
            "phase",
            f.phase.iter().map(|&k| k as f64).collect(),
        ));
    }
    vtk::write_vtp(path, &pts, &data)?;
    Ok(())
}

/// PNG snapshots at the plunge: pressure, and initial depth with the two top rows marked (thesis Fig. 10.7).
pub(crate) fn plunge_plots(scene: &Scene, s: &Snapshot, c: &cavity::Cavity, dir: &Path) -> anyhow::Result<()> {
    let g = &scene.geom;
    let span = (c.hi.x - 0.0).max(g.draft) * 1.3;
    let range = (0.0, span, -0.6 * g.draft, (c.hi.y + 1.2 * g.draft).min(g.z_top));
    let (pts, wall) = plot_points(scene, s);
    let pressure = scene.sim.pressure();
    let p: Vec<f64> = s.index.iter().map(|&i| pressure[i] / g.draft).collect();
    plot::scatter_plot(
        &dir.join("plunge_pressure.png"),
        "pressure p/(ρ g D) at the plunge",
        ("y/L", "z/L"),
        &pts,
        &p,
        (0.0, 1.0),
        Some("p/(ρ g D)"),
        std::slice::from_ref(&wall),
        range,
        1400,
    )?;
    depth_plot(
        scene,
        s,
        &dir.join("plunge_initial_depth.png"),
        range,
        "initial depth / D (top two rows marked red and yellow)",
    )
}

/// Particles coloured by their initial depth, the two top rows marked (thesis Fig. 10.7).
pub(crate) fn depth_plot(
    scene: &Scene,
    s: &Snapshot,
    path: &Path,
    range: (f64, f64, f64, f64),
    title: &str,
) -> anyhow::Result<()> {
    let g = &scene.geom;
    let (pts, wall) = plot_points(scene, s);
    let ids = &scene.sim.fluid.id;
    let marks: Vec<f64> = s
        .index
        .iter()
        .map(|&i| ids[i] as usize)
        .map(|id| match scene.initial_row[id] {
            0 => 1.0,
            1 => 0.75,
            _ => (scene.initial_depth[id] / g.draft).min(0.5),
        })
        .collect();
    plot::scatter_plot(
        path,
        title,
        ("y/L", "z/L"),
        &pts,
        &marks,
        (0.0, 1.0),
        None,
        std::slice::from_ref(&wall),
        range,
        1400,
    )?;
    Ok(())
}
