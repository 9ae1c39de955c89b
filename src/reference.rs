//! Reference data (analytic ODE solutions and published measurements), embedded from `data/reference/` at
//! compile time so that validation needs no file at run time. Provenance: `data/reference/SOURCES.md`.

use crate::io::csv_table::Table;

/// (file name, contents) of the embedded reference files.
const FILES: &[(&str, &str)] = &[
    (
        "elliptic_drop",
        include_str!("../data/reference/elliptic_drop_monaghan1994_A0_100_R1_DERIVED.csv"),
    ),
    (
        "oscillating_drop",
        include_str!("../data/reference/oscillating_drop_central_force_sigma0_0p5_Omega1_DERIVED.csv"),
    ),
    (
        "martin_moyce_front",
        include_str!("../data/reference/martin_moyce_1952_n2_2_a2.25in_front_table2_ocellaris.csv"),
    ),
    (
        "martin_moyce_height",
        include_str!("../data/reference/martin_moyce_1952_n2_2_a2.25in_residual_height_table6_ocellaris.csv"),
    ),
    (
        "koshizuka_oka_front",
        include_str!("../data/reference/koshizuka_oka_1996_front_pysph.csv"),
    ),
    (
        "marrone_p1",
        include_str!("../data/reference/marrone2011_deltaSPH_damBreak_P1_trixiparticles.csv"),
    ),
    (
        "marrone_p2",
        include_str!("../data/reference/marrone2011_deltaSPH_damBreak_P2_trixiparticles.csv"),
    ),
    (
        "buchner_p1",
        include_str!("../data/reference/buchner2002_damBreak_H600_P1_trixiparticles.csv"),
    ),
    (
        "buchner_p2",
        include_str!("../data/reference/buchner2002_damBreak_H600_P2_trixiparticles.csv"),
    ),
    (
        "wedge_similarity_summary",
        include_str!("../data/reference/zhao_faltinsen1993_wedge_similarity_summary.csv"),
    ),
    (
        "wedge_similarity_pressure",
        include_str!("../data/reference/zhao_faltinsen1993_wedge_similarity_pressure_sun2007fig2_6_digitised.csv"),
    ),
    (
        "two_phase_drop",
        include_str!("../data/reference/two_phase_concentric_drop_A0_Omega1_R1_z2_DERIVED.csv"),
    ),
    (
        "trixi_p1_centre",
        include_str!("../data/reference/trixiparticles_wcsph_damBreak_P4_H600_80_400.csv"),
    ),
    (
        "openfoam_wall_sensors",
        include_str!("../data/reference/openfoam_interfoam_damBreak_H80_free_slip_COMPUTED.csv"),
    ),
];

/// Parses an embedded reference file into a table (header kept as column names).
pub fn load(name: &str) -> Table {
    let text = FILES
        .iter()
        .find(|(n, _)| *n == name)
        .unwrap_or_else(|| panic!("no embedded reference `{name}`"))
        .1;
    let mut rdr = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .from_reader(text.as_bytes());
    let cols: Vec<String> = rdr
        .headers()
        .expect("embedded reference has a header")
        .iter()
        .map(|s| s.trim().to_string())
        .collect();
    let mut t = Table::new(cols);
    for rec in rdr.records() {
        let rec = rec.expect("embedded reference parses");
        t.push(
            rec.iter()
                .map(|s| s.trim().parse::<f64>().unwrap_or(f64::NAN))
                .collect(),
        );
    }
    t
}

/// Column `k` (by position) of a reference table.
pub fn col(t: &Table, k: usize) -> Vec<f64> {
    t.rows.iter().map(|r| r[k]).collect()
}

/// Column by name.
pub fn named(t: &Table, name: &str) -> Vec<f64> {
    t.column(name)
        .unwrap_or_else(|| panic!("reference column `{name}` missing"))
}

/// Linear interpolation of (xs, ys) at x; `None` outside the range.
pub fn interp(xs: &[f64], ys: &[f64], x: f64) -> Option<f64> {
    if xs.is_empty() || x < xs[0] || x > *xs.last().unwrap() {
        return None;
    }
    let k = xs.partition_point(|&v| v < x);
    if k == 0 {
        return Some(ys[0]);
    }
    let (x0, x1, y0, y1) = (xs[k - 1], xs[k], ys[k - 1], ys[k]);
    Some(if x1 > x0 {
        y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    } else {
        y1
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tables that carry text beside their numbers (provenance tags, notes, empty cells where a source has no
    /// value): the columns the code reads, and the rows there must be at least.
    const MIXED: &[(&str, &[&str], usize)] = &[
        (
            "wedge_similarity_summary",
            &[
                "deadrise_deg",
                "cp_max_READ",
                "z_cpmax_over_Vt_READ",
                "wagner_cp_max_DERIVED",
            ],
            3,
        ),
        ("wedge_similarity_pressure", &["deadrise_deg", "z_over_Vt", "cp"], 300),
    ];

    #[test]
    fn all_embedded_references_parse() {
        for (n, cols, rows) in MIXED {
            let t = load(n);
            assert!(t.rows.len() >= *rows, "{n}: {} rows", t.rows.len());
            for c in *cols {
                assert!(named(&t, c).iter().all(|x| x.is_finite()), "{n}: {c} has non-numbers");
            }
        }
        for (n, _) in FILES.iter().filter(|(n, _)| MIXED.iter().all(|m| m.0 != *n)) {
            let t = load(n);
            assert!(t.rows.len() > 5, "{n}");
            assert!(
                t.rows.iter().all(|r| r.iter().all(|x| x.is_finite())),
                "{n} has non-numbers"
            );
        }
    }
}

/// One row of Tables 10.1–10.2 of the thesis (`data/reference/published_jets.csv`).
#[derive(Clone, Debug, PartialEq)]
pub struct PublishedJet {
    pub hull: String,
    pub fr: f64,
    pub dx_over_l: f64,
    pub x_plunge_over_l: f64,
    pub y_plunge_over_l: f64,
    pub h_pj_over_d: f64,
}

const PUBLISHED_JETS: &str = include_str!("../data/reference/published_jets.csv");

/// All rows of the published jet table.
pub fn published_jets() -> Vec<PublishedJet> {
    PUBLISHED_JETS
        .lines()
        .skip(1)
        .filter_map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            let num = |k: usize| f.get(k).and_then(|v| v.trim().parse::<f64>().ok());
            Some(PublishedJet {
                hull: f.first()?.to_string(),
                fr: num(1)?,
                dx_over_l: num(2)? * 1e-4,
                x_plunge_over_l: num(3)?,
                y_plunge_over_l: num(4)?,
                h_pj_over_d: num(5)?,
            })
        })
        .collect()
}

/// The published row for this hull (by name) and Froude number, if any.
pub fn published_jet(hull: &str, fr: f64) -> Option<PublishedJet> {
    published_jets()
        .into_iter()
        .find(|r| r.hull.eq_ignore_ascii_case(hull) && (r.fr - fr).abs() < 1e-9)
}
