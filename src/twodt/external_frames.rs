//! The plunge and the jet measured in 2D+t particle frames written by another code (`bowwave frames`): the
//! criteria and metrics of a bowwave run (`docs/reference/jet-metrics.md`) applied to the other code's
//! particles, so that two codes on one hull are compared by one measure (issue #30's cross-check with PySPH,
//! `tools/pysph-2dt/`).
//!
//! The series is a folder holding `frames.csv`, with columns `x_over_l,file` (where the section is in each
//! frame, and the frame's file in the same folder), and one CSV per frame of the water particles, with
//! columns `y,z,u,v,volume`: position (units of L, y from the symmetry plane, z up from the calm level),
//! velocity (units of √(gL)) and volume (L², m/ρ). Frames are read one at a time, in the order of x.
//!
//! What is measured at each frame is what a bowwave run measures at a check: the free surface (thesis
//! eqs. 7.21–7.24, with bowwave's kernel, h = 1.33 dx, whatever kernel the other code used, and behind the
//! section and the tank's walls the layers of particles a bowwave run's fixed ghosts would put there, so
//! that water touching a wall is not read as free surface whatever the other code's walls were), the level set,
//! the air cavities closed since the previous frame away from the walls, and for the first one that meets
//! the criteria, the jet's metrics. A bowwave run checks every ten steps and then finds the plunge to one
//! step; here the plunge is known to one frame interval, the x of the frame where the cavity is first closed.

use super::passage::{eta_outside_waterline, eta_profile, plunge_check, waterline_half_breadth, PlungeScene};
use super::profile::SectionProfile;
use super::result::PlungeMetrics;
use crate::analysis::{cavity, Snapshot};
use crate::geometry::surface::HullSurface;
use crate::input_error::InputError;
use crate::io::csv_table::Table;
use crate::sph::free_surface::{detect, Thresholds};
use crate::sph::kernel::{Kernel, KernelKind};
use crate::sph::neighbours::CellList;
use crate::sph::polyline_wall::{ghost_layers, FluidSide};
use nalgebra::Vector2;
use std::path::{Path, PathBuf};
use std::sync::Arc;

type V2 = Vector2<f64>;

/// The columns of a frame file, in any order.
pub const FRAME_COLUMNS: [&str; 5] = ["y", "z", "u", "v", "volume"];

/// The scene the frames were computed in, and the plunge criteria (as `bowwave twodt` takes them).
#[derive(Clone, Debug)]
pub struct FramesSpec {
    /// Froude number U/√(gL).
    pub fr: f64,
    /// The finest particle spacing of the frames, dx/L.
    pub dx: f64,
    /// Tank half width W/B and depth Z/D.
    pub width_over_beam: f64,
    pub depth_over_draft: f64,
    /// Criterion 3 (`--plunge-depth`), off when `None`.
    pub plunge_depth: Option<f64>,
    /// Criterion 5, the least Γ/(UD) (`--plunge-circulation`), off when `None`.
    pub plunge_circulation: Option<f64>,
}

/// One frame of the series: where the section is and the frame's file.
#[derive(Clone, Debug)]
pub struct FrameEntry {
    pub x_over_l: f64,
    pub path: PathBuf,
}

/// What the frames show: the crest at each frame and the plunge, if one is found.
#[derive(Clone, Debug, Default)]
pub struct FramesResult {
    /// Per frame: x/L, the crest η/D outside the section's waterline (as `eta.csv`'s crest of a bowwave run:
    /// the highest water particle in bins of 4 dx, plus dx/2), water particles.
    pub crest: Table,
    pub plunge: Option<PlungeMetrics>,
    /// The largest step in x/L between two frames, in units of dx/L. A bowwave run compares checks about two
    /// spacings apart; frames much farther apart than that can miss a plunge (see [`FRAME_GAP_WARNING`]).
    pub max_gap_over_dx: f64,
}

/// Frames more than this many spacings apart in x/L are reported: the plunge criterion that tells a jet's
/// trapped air from a hole opening in the water (at least half the new cavity was atmosphere at the
/// previous frame) fails when the jet moves over the cavity's place between frames; a bowwave run checks
/// every 10 steps, about 2 spacings (`docs/reference/twodt.md`, "Another code's frames").
pub const FRAME_GAP_WARNING: f64 = 4.0;

/// The series' frames, sorted by x/L, from its `frames.csv`.
pub fn read_index(dir: &Path) -> Result<Vec<FrameEntry>, InputError> {
    let index = dir.join("frames.csv");
    let file = index.display().to_string();
    let mut r = csv::Reader::from_path(&index).map_err(|e| InputError::Io {
        file: file.clone(),
        source: std::io::Error::other(e.to_string()),
    })?;
    let headers = r
        .headers()
        .map_err(|e| InputError::Syntax {
            file: file.clone(),
            message: e.to_string(),
        })?
        .clone();
    let col = |name: &str| {
        headers
            .iter()
            .position(|h| h.trim() == name)
            .ok_or_else(|| InputError::field(&file, name, "a column (frames.csv has columns x_over_l,file)"))
    };
    let (cx, cf) = (col("x_over_l")?, col("file")?);
    let mut frames = Vec::new();
    for (k, rec) in r.records().enumerate() {
        let rec = rec.map_err(|e| InputError::Syntax {
            file: file.clone(),
            message: format!("row {}: {e}", k + 1),
        })?;
        let row = |c: usize| rec.get(c).unwrap_or("").trim().to_string();
        let x: f64 = row(cx)
            .parse()
            .ok()
            .filter(|x: &f64| x.is_finite())
            .ok_or_else(|| InputError::field(&file, &format!("x_over_l (row {})", k + 1), "a finite number"))?;
        let name = row(cf);
        if name.is_empty() {
            return Err(InputError::field(
                &file,
                &format!("file (row {})", k + 1),
                "a frame file's name",
            ));
        }
        frames.push(FrameEntry {
            x_over_l: x,
            path: dir.join(name),
        });
    }
    if frames.is_empty() {
        return Err(InputError::field(&file, "x_over_l", "at least one frame"));
    }
    frames.sort_by(|a, b| a.x_over_l.total_cmp(&b.x_over_l));
    Ok(frames)
}

/// A frame's water particles.
#[derive(Clone, Debug, Default)]
pub struct FrameParticles {
    pub pos: Vec<V2>,
    pub vel: Vec<V2>,
    pub vol: Vec<f64>,
}

/// Reads one frame file (columns [`FRAME_COLUMNS`]); the error names the file and the column or row.
pub fn read_frame(path: &Path) -> anyhow::Result<FrameParticles> {
    let file = path.display().to_string();
    let t = Table::read(path)?;
    let mut cols = Vec::with_capacity(FRAME_COLUMNS.len());
    for name in FRAME_COLUMNS {
        let c = t.columns.iter().position(|c| c.trim() == name).ok_or_else(|| {
            InputError::field(
                &file,
                name,
                format!("a column (a frame has columns {})", FRAME_COLUMNS.join(",")),
            )
        })?;
        cols.push(c);
    }
    let mut f = FrameParticles::default();
    for (k, r) in t.rows.iter().enumerate() {
        let v: Vec<f64> = cols.iter().map(|&c| r[c]).collect();
        let bad = |field: &str, expected: &str| {
            InputError::field(&file, &format!("{field} (row {})", k + 1), expected.to_string())
        };
        if let Some(c) = v.iter().position(|x| !x.is_finite()) {
            return Err(bad(FRAME_COLUMNS[c], "a finite number").into());
        }
        if v[4] <= 0.0 {
            return Err(bad("volume", "a positive number").into());
        }
        f.pos.push(V2::new(v[0], v[1]));
        f.vel.push(V2::new(v[2], v[3]));
        f.vol.push(v[4]);
    }
    if f.pos.is_empty() {
        anyhow::bail!("{file}: no particle");
    }
    Ok(f)
}

/// The water of a frame as the analyses read it: its free surface detected with bowwave's kernel at spacing
/// `dx`, the layers of fixed ghosts behind each of `walls` (polylines with the water on their right) counted
/// as matter.
pub fn snapshot(f: &FrameParticles, dx: f64, walls: &[&[V2]]) -> Snapshot {
    let kind = KernelKind::RenormalizedGaussian;
    let kernel = Kernel::<2>::new(kind, kind.default_h_over_dx() * dx);
    let mut all = f.pos.clone();
    let mut volume = f.vol.clone();
    for w in walls {
        let g = ghost_layers(w, FluidSide::Right, dx, kernel.support);
        all.extend(&g.pos);
        volume.extend(&g.volume);
    }
    let cells = CellList::build(&all, kernel.support);
    let fs = detect(&kernel, &cells, &all, &volume, f.pos.len(), Thresholds::default());
    Snapshot {
        pos: f.pos.clone(),
        vel: f.vel.clone(),
        vol: f.vol.clone(),
        on_surface: fs.on_surface,
        normal: fs.normal,
        lambda: fs.lambda,
        h: kernel.h,
        dx,
        index: (0..f.pos.len()).collect(),
    }
}

/// Measures the series in `dir` on `hull` (the hull the other code was driven with): the crest at every
/// frame, and the plunge at the first frame whose newly closed cavity meets the criteria. Frames after the
/// plunge are read for the crest only.
pub fn measure(hull: Arc<HullSurface>, spec: &FramesSpec, dir: &Path) -> anyhow::Result<FramesResult> {
    anyhow::ensure!(
        spec.fr > 0.0 && spec.fr.is_finite(),
        "--fr: expected a positive number, got {}",
        spec.fr
    );
    anyhow::ensure!(
        spec.dx > 0.0 && spec.dx.is_finite(),
        "--dx: expected a positive number, got {}",
        spec.dx
    );
    let frames = read_index(dir)?;
    let meta = &hull.meta;
    let (draft, beam) = (meta.draft_m / meta.length_m, meta.beam_m / meta.length_m);
    let (width, depth) = (spec.width_over_beam * beam, spec.depth_over_draft * draft);
    let profile = SectionProfile {
        hull: hull.clone(),
        u: spec.fr,
        x0: frames[0].x_over_l,
        ds: spec.dx,
        z_cut: -depth,
        z_top: 2.0 * draft,
        t_start: 0.0,
    };
    // The tank's far wall and bottom (the symmetry plane is the section's polyline, from the bottom up).
    let tank = [
        V2::new(width, profile.z_top),
        V2::new(width, -depth),
        V2::new(0.0, -depth),
    ];
    let bin = 4.0 * spec.dx;
    let mut crest = Table::new(vec!["x_over_l".into(), "crest_over_d".into(), "water_particles".into()]);
    let mut watch = cavity::ClosureWatch::resume(None);
    let mut plunge = None;
    for fr in &frames {
        let particles = read_frame(&fr.path)?;
        let walls = profile.at(profile.t_at(fr.x_over_l)).points;
        let eta = eta_profile(&particles.pos, width, bin, spec.dx);
        let top = eta_outside_waterline(&eta, bin, waterline_half_breadth(&walls))
            .map(|(_, z)| z / draft)
            .fold(f64::NEG_INFINITY, f64::max);
        crest.push(vec![fr.x_over_l, top, particles.pos.len() as f64]);
        // After the plunge the crest alone is read: no free surface to detect.
        if plunge.is_none() {
            let s = snapshot(&particles, spec.dx, &[&walls, &tank]);
            let scene = PlungeScene {
                draft,
                beam,
                width,
                depth,
                dx: spec.dx,
                walls,
                u: spec.fr,
                x: fr.x_over_l,
                x_bow: hull.x_range.0,
            };
            let criteria = (spec.plunge_depth, spec.plunge_circulation);
            plunge = plunge_check(&scene, &s, criteria, &mut watch, false).map(|(pm, _)| pm);
        }
    }
    let max_gap = frames
        .windows(2)
        .map(|w| w[1].x_over_l - w[0].x_over_l)
        .fold(0.0, f64::max);
    Ok(FramesResult {
        crest,
        plunge,
        max_gap_over_dx: max_gap / spec.dx,
    })
}
