//! `frames`: the plunge and the jet measured in another code's 2D+t particle frames, by bowwave's criteria.

use bowwave::geometry::{hull_file::HullOffsets, surface::HullSurface};
use bowwave::io::atomic::write_atomic;
use bowwave::twodt::config::PlungeCirculation;
use bowwave::twodt::external_frames::{measure, FramesSpec, FRAME_GAP_WARNING};
use clap::Args;
use std::path::PathBuf;
use std::sync::Arc;

#[derive(Args)]
pub struct FramesArgs {
    /// Folder of the frames: frames.csv (columns x_over_l,file) and one CSV per frame of the water particles,
    /// columns y,z,u,v,volume in units of L and √(gL) (docs/reference/twodt.md, "Another code's frames";
    /// tools/pysph-2dt/to_frames.py writes them from PySPH's outputs).
    pub dir: PathBuf,
    /// The hull file the other code's sections came from (CSV, docs/reference/hull-format.md).
    #[arg(long)]
    pub hull: PathBuf,
    /// Froude number U/√(gL) the frames were run at.
    #[arg(long)]
    pub fr: f64,
    /// The frames' finest particle spacing dx/L (the free-surface detection and the level set are taken at it).
    #[arg(long)]
    pub dx: f64,
    /// The tank's half width W as a multiple of the beam B, as the other code had it (bowwave's default: 4).
    #[arg(long = "width", value_name = "W_OVER_B", default_value_t = 4.0)]
    pub width_over_beam: f64,
    /// The water depth Z as a multiple of the draft D, as the other code had it (bowwave's default: 2).
    #[arg(long = "depth", value_name = "Z_OVER_D", default_value_t = 2.0)]
    pub depth_over_draft: f64,
    /// Plunge criterion 3, as `bowwave twodt --plunge-depth` (off unless given).
    #[arg(long)]
    pub plunge_depth: Option<f64>,
    /// Plunge criterion 5, as `bowwave twodt --plunge-circulation`: the least Γ/(UD) around the closed cavity,
    /// or `off`.
    #[arg(long, default_value_t = PlungeCirculation::AtLeast(0.02))]
    pub plunge_circulation: PlungeCirculation,
    /// Output folder for crest.csv (x/L, crest η/D, water particles per frame) and plunge.json (the jet's
    /// metrics, or null) (default: DIR/bowwave).
    #[arg(long)]
    pub out: Option<PathBuf>,
}

impl FramesArgs {
    pub fn run(self) -> anyhow::Result<()> {
        anyhow::ensure!(
            self.width_over_beam >= 1.0 && self.width_over_beam.is_finite(),
            "--width {}: expected W/B ≥ 1",
            self.width_over_beam
        );
        anyhow::ensure!(
            self.depth_over_draft > 1.0 && self.depth_over_draft.is_finite(),
            "--depth {}: expected Z/D > 1",
            self.depth_over_draft
        );
        let offsets = HullOffsets::read(&self.hull)?;
        let hull = Arc::new(HullSurface::new(&offsets));
        let spec = FramesSpec {
            fr: self.fr,
            dx: self.dx,
            width_over_beam: self.width_over_beam,
            depth_over_draft: self.depth_over_draft,
            plunge_depth: self.plunge_depth,
            plunge_circulation: self.plunge_circulation.threshold(),
        };
        let r = measure(hull, &spec, &self.dir)?;
        if r.max_gap_over_dx > FRAME_GAP_WARNING {
            eprintln!(
                "warning: frames up to {:.1} dx apart in x/L: a plunge between two of them may be missed (a bowwave \
                 run checks about every 2 dx; write frames at most {FRAME_GAP_WARNING} dx apart near the plunge)",
                r.max_gap_over_dx
            );
        }
        let out = self.out.unwrap_or_else(|| self.dir.join("bowwave"));
        std::fs::create_dir_all(&out).map_err(|e| anyhow::anyhow!("{}: cannot create: {e}", out.display()))?;
        r.crest.write(&out.join("crest.csv"))?;
        write_atomic(
            &out.join("plunge.json"),
            serde_json::to_string_pretty(&r.plunge)?.as_bytes(),
        )?;
        match &r.plunge {
            Some(p) => println!(
                "plunge at x/L {:.4}: y/L {:.4}, H_pj/D {:.3}, Γ/(UD) {:.3}, jet of {} particles",
                p.x_plunge_over_l, p.y_plunge_over_l, p.h_pj_over_d, p.gamma_over_ud, p.jet_particles
            ),
            None => println!("no plunge in {} frames", r.crest.rows.len()),
        }
        println!(
            "wrote {} and {}",
            out.join("crest.csv").display(),
            out.join("plunge.json").display()
        );
        Ok(())
    }
}
