//! `bowwave hull check`: the hydrostatics of a hull file beside its declared particulars, with a warning
//! where they disagree by more than 2 %. Declared targets are the metadata `beam_m`, `draft_m` and any note
//! `target_cb`, `target_cp`, `target_cm`, `target_cwp`, `target_lcb` (x/L from the stem).

use super::hull_file::HullOffsets;
use super::hydrostatics::hydrostatics;
use super::surface::HullSurface;
use std::fmt::Write as _;

/// Relative disagreement above which `hull check` warns.
pub const WARN: f64 = 0.02;

/// The report text and the number of warnings.
pub fn check_report(h: &HullOffsets) -> (String, usize) {
    let s = HullSurface::new(h);
    let (hy, secs) = hydrostatics(&s, 400, 1500);
    let l = h.meta.length_m;
    let mut out = String::new();
    let mut warnings = 0;
    let _ = writeln!(
        out,
        "hull `{}` ({:?}), L = {} m, {} stations; source: {}",
        h.meta.name,
        h.meta.status,
        l,
        h.stations.len(),
        h.meta.source
    );
    let _ = writeln!(
        out,
        "{:<28} {:>14} {:>14} {:>9}",
        "quantity", "from surface", "declared", "diff"
    );
    let mut row = |name: &str, ours: f64, declared: Option<f64>| match declared {
        Some(d) => {
            let rel = (ours - d) / d;
            let flag = if rel.abs() > WARN {
                warnings += 1;
                "  WARNING: differs by more than 2 %"
            } else {
                ""
            };
            let _ = writeln!(out, "{name:<28} {ours:>14.5} {d:>14.5} {:>8.2}%{flag}", 100.0 * rel);
        }
        None => {
            let _ = writeln!(out, "{name:<28} {ours:>14.5} {:>14} {:>9}", "-", "");
        }
    };
    let target = |k: &str| {
        h.meta
            .notes
            .get(k)
            .and_then(|v| v.split_whitespace().next())
            .and_then(|v| v.parse::<f64>().ok())
    };
    row("beam B (m)", hy.beam * l, Some(h.meta.beam_m));
    row("draft D (m)", hy.draft * l, Some(h.meta.draft_m));
    row(
        "displacement volume (m^3)",
        hy.volume * l * l * l,
        target("target_volume_m3"),
    );
    row("waterplane area (m^2)", hy.waterplane * l * l, None);
    row("Cb", hy.cb, target("target_cb"));
    row("Cp", hy.cp, target("target_cp"));
    row("Cm", hy.cm, target("target_cm"));
    row("Cwp", hy.cwp, target("target_cwp"));
    row("LCB (x/L from the stem)", hy.lcb, target("target_lcb"));
    let _ = writeln!(out, "\nwetted girth (one side, keel to waterline) per station:");
    let _ = writeln!(out, "{:>8} {:>12} {:>14}", "x/L", "girth (m)", "area (m^2)");
    for st in &h.stations {
        let k = secs
            .iter()
            .min_by(|a, b| (a.x - st.x).abs().total_cmp(&(b.x - st.x).abs()))
            .unwrap();
        let _ = writeln!(out, "{:>8.4} {:>12.4} {:>14.4}", st.x, k.girth * l, k.area * l * l);
    }
    (out, warnings)
}
