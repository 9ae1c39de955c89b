//! Plots of a validation run: energies, and per case its probes or semi-axes against the references.

use super::col;
use super::jets::{jet_wall_means, taylor_jet_cp};
use super::martin_moyce::mm_column_height;
use crate::cases::run::RunResult;
use crate::io::plot::{line_plot, Series, Style};
use crate::reference::{self, named};
use std::path::Path;

/// Plots of a run: energies, and per case its probes or semi-axes against the references.
pub fn plots(r: &RunResult, dir: &Path) -> anyhow::Result<Vec<std::path::PathBuf>> {
    let mut files = vec![];
    let ts = col(r, "t_star");
    let xy = |a: &[f64], b: &[f64]| a.iter().copied().zip(b.iter().copied()).collect::<Vec<_>>();
    let p = dir.join(format!("{}_energy.png", r.case.name));
    line_plot(
        &p,
        &format!("{}: mechanical energy change", r.case.name),
        "t*",
        "(E_M - E_M0) / scale",
        &[Series {
            name: "dE_M".into(),
            points: xy(&ts, &col(r, "de_mechanical_rel")),
            style: Style::Line,
        }],
    )?;
    files.push(p);
    files.extend(super::references::reference_plots(r, dir)?);
    match super::builtin_experiment(&r.case).unwrap_or("") {
        "dam-break" => {
            let res = r.case.scales.length / r.dx;
            for (probe, mref, bref) in [("P1", "marrone_p1", "buchner_p1"), ("P2", "marrone_p2", "buchner_p2")] {
                let m = reference::load(mref);
                let b = reference::load(bref);
                let mut series = vec![Series {
                    name: format!("bowwave H/dx={res:.0}"),
                    points: xy(&ts, &col(r, &format!("pstar_{probe}"))),
                    style: Style::Line,
                }];
                for n in [40, 80, 320] {
                    let c = format!("p_over_rho_g_H_deltaSPH_H_over_dx_{n}");
                    series.push(Series {
                        name: format!("Marrone 2011 H/dx={n}"),
                        points: xy(&reference::col(&m, 0), &named(&m, &c)),
                        style: Style::Line,
                    });
                }
                series.push(Series {
                    name: "Buchner 2002 exp.".into(),
                    points: xy(&reference::col(&b, 0), &reference::col(&b, 1)),
                    style: Style::Markers,
                });
                if probe == "P1" {
                    series.push(openfoam_series("P1", "OpenFOAM interFoam (VOF) H/dx=80, 90 mm"));
                }
                let p = dir.join(format!("dam-break_{probe}.png"));
                line_plot(
                    &p,
                    &format!("Dam break: pressure at {probe}"),
                    "t sqrt(g/H)",
                    "p / (rho g H)",
                    &series,
                )?;
                files.push(p);
            }
            // P1's centre read by a small sensor, beside another code's reference runs read the same way.
            if let Some(pc) = r.series.column("pstar_P1c") {
                let mut series = vec![Series {
                    name: format!("bowwave H/dx={res:.0}, 8.4 mm sensor"),
                    points: xy(&ts, &pc),
                    style: Style::Line,
                }];
                for n in [80.0, 400.0] {
                    let (tres, tt, tp) = super::trixi_p1_centre(n);
                    series.push(Series {
                        name: format!("TrixiParticles WCSPH H/dx={tres}, 8.4 mm"),
                        points: xy(&tt, &tp),
                        style: Style::Line,
                    });
                }
                let m = reference::load("marrone_p1");
                series.push(Series {
                    name: "Marrone 2011 H/dx=320, 90 mm".into(),
                    points: xy(
                        &reference::col(&m, 0),
                        &named(&m, "p_over_rho_g_H_deltaSPH_H_over_dx_320"),
                    ),
                    style: Style::Line,
                });
                series.push(openfoam_series("P1c", "OpenFOAM interFoam (VOF) H/dx=80, 8.4 mm"));
                let p = dir.join("dam-break_P1c.png");
                line_plot(
                    &p,
                    "Dam break: pressure at the centre of P1 (y = 0.16 m)",
                    "t sqrt(g/H)",
                    "p / (rho g H)",
                    &series,
                )?;
                files.push(p);
            }
        }
        "jet-wall" | "jet-plate" | "jet-floor" => {
            // Mean Cp of each sensor over the steady window, and Taylor's curve.
            let b = r.case.scales.length;
            let sph: Vec<(f64, f64)> = jet_wall_means(r).2.iter().map(|&(y, cp, _)| (y, cp)).collect();
            let theory: Vec<(f64, f64)> = (0..=160)
                .map(|k| {
                    let y_over_h = k as f64 * 0.01;
                    (y_over_h, taylor_jet_cp(y_over_h * 2.0 * b, 2.0 * b))
                })
                .collect();
            let p = dir.join(format!("{}_cp.png", r.case.name));
            let title = match r.case.name.as_str() {
                "jet-plate" => "Plane jet on a flat wall: pressure along the wall",
                "jet-floor" => "Two jets meeting over a floor: pressure on the symmetry plane",
                _ => "Plane jet into a floor-wall corner: pressure along the wall",
            };
            line_plot(
                &p,
                title,
                "y / h (h: full jet width)",
                "Cp = p / (rho U^2 / 2)",
                &[
                    Series {
                        name: "bowwave, mean over t >= 0.4 s".into(),
                        points: sph,
                        style: Style::Markers,
                    },
                    Series {
                        name: "free-streamline solution (Taylor 1966)".into(),
                        points: theory,
                        style: Style::Line,
                    },
                ],
            )?;
            files.push(p);
        }
        "dam-break-mm" => {
            let rt = reference::load("martin_moyce_front");
            let ko = reference::load("koshizuka_oka_front");
            let big_t: Vec<f64> = ts.iter().map(|t| t * 2f64.sqrt()).collect();
            let p = dir.join("dam-break-mm_front.png");
            line_plot(
                &p,
                "Martin-Moyce surge front (n^2 = 2)",
                "T = n t sqrt(g/a)",
                "x / a",
                &[
                    Series {
                        name: "bowwave".into(),
                        points: xy(&big_t, &col(r, "front_star")),
                        style: Style::Line,
                    },
                    Series {
                        name: "Martin & Moyce 1952, Table 2".into(),
                        points: xy(&reference::col(&rt, 0), &reference::col(&rt, 1)),
                        style: Style::Markers,
                    },
                    Series {
                        name: "Koshizuka & Oka 1996".into(),
                        points: xy(&reference::col(&ko, 0), &reference::col(&ko, 1)),
                        style: Style::Markers,
                    },
                ],
            )?;
            files.push(p);
            let hr = reference::load("martin_moyce_height");
            let h = mm_column_height(r);
            let p = dir.join("dam-break-mm_column_height.png");
            line_plot(
                &p,
                "Martin-Moyce residual column height (n^2 = 2)",
                "tau = t sqrt(g/a)",
                "h / (n^2 a)",
                &[
                    Series {
                        name: "bowwave (0.1a from the back wall)".into(),
                        points: xy(&ts, &h),
                        style: Style::Line,
                    },
                    Series {
                        name: "Martin & Moyce 1952, Table 6".into(),
                        points: xy(&reference::col(&hr, 0), &reference::col(&hr, 1)),
                        style: Style::Markers,
                    },
                ],
            )?;
            files.push(p);
        }
        "elliptic-drop" | "oscillating-drop" => {
            let (file, tc, ac) = if r.case.name == "elliptic-drop" {
                ("elliptic_drop", "t_s", "a_semi_axis_x_m")
            } else {
                ("oscillating_drop", "t", "A_semi_axis_x")
            };
            let rt = reference::load(file);
            let p = dir.join(format!("{}_semi_axis.png", r.case.name));
            line_plot(
                &p,
                &format!("{}: semi-axis along x", r.case.name),
                "t (s)",
                "a (m)",
                &[
                    Series {
                        name: "bowwave (2 sqrt<x^2>)".into(),
                        points: xy(&col(r, "t"), &col(r, "semi_axis_x")),
                        style: Style::Line,
                    },
                    Series {
                        name: "ODE solution".into(),
                        points: xy(&named(&rt, tc), &named(&rt, ac)),
                        style: Style::Line,
                    },
                ],
            )?;
            files.push(p);
        }
        "hydrostatic" => {
            let p = dir.join("hydrostatic_bottom_pressure.png");
            line_plot(
                &p,
                "Hydrostatic tank: bottom pressure",
                "t sqrt(g/H)",
                "p / (rho g H)",
                &[Series {
                    name: "bottom probe".into(),
                    points: xy(&ts, &col(r, "pstar_bottom")),
                    style: Style::Line,
                }],
            )?;
            files.push(p);
        }
        _ => {}
    }
    files.extend(sloshing_plots(r, dir)?);
    files.extend(sensor_plot(r, dir)?);
    files.extend(gauge_plot(r, dir)?);
    Ok(files)
}

/// Every gauge's depth over the case's length scale at the outputs, on one figure (`NAME_gauges.png`), for any
/// case with gauges.
fn gauge_plot(r: &RunResult, dir: &Path) -> anyhow::Result<Vec<std::path::PathBuf>> {
    if r.case.probes.gauge.is_empty() {
        return Ok(vec![]);
    }
    let ts = col(r, "t_star");
    let series: Vec<Series> = r
        .case
        .probes
        .gauge
        .iter()
        .map(|g| Series {
            name: format!(
                "{} (x = {} m{})",
                g.name,
                g.x,
                if g.connected { ", connected water only" } else { "" }
            ),
            points: ts
                .iter()
                .copied()
                .zip(col(r, &format!("depthstar_{}", g.name)))
                .collect(),
            style: Style::Line,
        })
        .collect();
    let p = dir.join(format!("{}_gauges.png", r.case.name));
    line_plot(
        &p,
        &format!("{}: wave gauges", r.case.name),
        "t sqrt(g/L)",
        "depth / L",
        &series,
    )?;
    Ok(vec![p])
}

/// Every wall sensor's reading p/(ρ g length) at the outputs, and its peaks between them where they rise above
/// the readings, on one figure (`NAME_sensors.png`), for any case with wall sensors.
fn sensor_plot(r: &RunResult, dir: &Path) -> anyhow::Result<Vec<std::path::PathBuf>> {
    let walls: Vec<_> = r.case.probes.pressure.iter().filter(|p| !p.in_fluid).collect();
    if walls.is_empty() {
        return Ok(vec![]);
    }
    let ts = col(r, "t_star");
    let mut series = vec![];
    for p in walls {
        let v = col(r, &format!("pstar_{}", p.name));
        let peak = col(r, &format!("pstarpeak_{}", p.name));
        // The peaks between outputs where they rise above both readings around them by 1 % of ρgL or more.
        let above: Vec<(f64, f64)> = (1..ts.len())
            .filter(|&k| peak[k] > v[k].max(v[k - 1]) + 0.01)
            .map(|k| (ts[k], peak[k]))
            .collect();
        series.push(Series {
            name: p.name.clone(),
            points: ts.iter().copied().zip(v).collect(),
            style: Style::Line,
        });
        if !above.is_empty() {
            series.push(Series {
                name: format!("{}: peak between outputs", p.name),
                points: above,
                style: Style::Markers,
            });
        }
    }
    let p = dir.join(format!("{}_sensors.png", r.case.name));
    line_plot(
        &p,
        &format!("{}: wall sensors", r.case.name),
        "t sqrt(g/L)",
        "p / (rho g L)",
        &series,
    )?;
    Ok(vec![p])
}

/// A tank in sway from rest with gauges that move with it (whatever its name): the elevation at each gauge
/// against linear potential theory (`validation::sloshing`), one figure per gauge.
fn sloshing_plots(r: &RunResult, dir: &Path) -> anyhow::Result<Vec<std::path::PathBuf>> {
    let Some((x0, l, h, sway)) = super::sloshing::tank(r) else {
        return Ok(vec![]);
    };
    let g = r.case.gravity_magnitude();
    let t = col(r, "t");
    let mut files = vec![];
    for gauge in r.case.probes.gauge.iter().filter(|g| g.moves_with.is_some()) {
        let level = col(r, &format!("eta_{}", gauge.name));
        let s = gauge.x - x0;
        let ours: Vec<(f64, f64)> = t.iter().zip(&level).map(|(&t, &e)| (t, e - level[0])).collect();
        let theory: Vec<(f64, f64)> = t
            .iter()
            .map(|&t| (t, super::sloshing::linear_elevation(l, h, g, &sway, s, t)))
            .collect();
        let p = dir.join(format!("{}_elevation_{}.png", r.case.name, gauge.name));
        line_plot(
            &p,
            &format!(
                "{}: elevation at gauge {} (s/L = {:.3})",
                r.case.name,
                gauge.name,
                s / l
            ),
            "t (s)",
            "elevation (m)",
            &[
                Series {
                    name: format!("bowwave, h/dx = {:.0}", h / r.dx),
                    points: ours,
                    style: Style::Line,
                },
                Series {
                    name: "linear theory".into(),
                    points: theory,
                    style: Style::Line,
                },
            ],
        )?;
        files.push(p);
    }
    Ok(files)
}

/// One sensor of OpenFOAM's free-slip dam break (H/dx 80, the `openfoam_wall_sensors` reference) as a curve.
fn openfoam_series(sensor: &str, name: &str) -> Series {
    let f = reference::load("openfoam_wall_sensors");
    Series {
        name: name.into(),
        points: reference::col(&f, 0).into_iter().zip(named(&f, sensor)).collect(),
        style: Style::Line,
    }
}
