//! The hull offsets file: a CSV a naval architect can write by hand or export from a spreadsheet.
//!
//! ```text
//! # name: wigley
//! # status: exact                  (exact | approximation)
//! # length_m: 100                  reference length L (m)
//! # draft_m: 10                    draft D (m)
//! # beam_m: 20                     beam B at the waterline (m)
//! # model_scale: 1                 model scale (1 for full scale)
//! # transom: false                 whether the hull ends in a transom
//! # transom_immersion_m: 0         transom immersion below the waterline (m)
//! # source: ...                    where the offsets come from
//! station,x_over_L,point,y_over_L,z_over_L
//! 0,0.0,0,0.0,-0.1
//! ```
//! Rows: x/L from the stem (0) aft to the transom (1); z = 0 at the calm waterline, positive up; y ≥ 0 the
//! half-breadth; the points of a station are ordered from the keel on the centre plane up to the deck.
//! Other `# key: value` lines are kept as notes. Every problem is reported with the file, the line and what
//! was expected.

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// A problem in a hull file.
#[derive(Debug, PartialEq)]
pub struct HullFileError {
    pub file: String,
    /// 1-based line number (0 when the problem concerns the whole file).
    pub line: usize,
    pub problem: String,
}

impl std::fmt::Display for HullFileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.line == 0 {
            write!(f, "{}: {}", self.file, self.problem)
        } else {
            write!(f, "{}:{}: {}", self.file, self.line, self.problem)
        }
    }
}

impl std::error::Error for HullFileError {}

/// Whether the offsets are the real hull or a labelled approximation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum HullStatus {
    Exact,
    Approximation,
}

/// The declared particulars of a hull.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct HullMeta {
    pub name: String,
    pub status: HullStatus,
    /// Reference length L (m).
    pub length_m: f64,
    /// Draft D (m).
    pub draft_m: f64,
    /// Waterline beam B (m).
    pub beam_m: f64,
    pub model_scale: f64,
    pub transom: bool,
    /// Transom immersion below the waterline (m).
    pub transom_immersion_m: f64,
    pub source: String,
    /// Any other `# key: value` lines.
    pub notes: BTreeMap<String, String>,
}

/// One station: its x/L and its points (y/L, z/L) from keel to deck.
#[derive(Clone, Debug, PartialEq)]
pub struct Station {
    pub x: f64,
    pub points: Vec<[f64; 2]>,
}

/// A parsed and checked hull.
#[derive(Clone, Debug, PartialEq)]
pub struct HullOffsets {
    pub meta: HullMeta,
    pub stations: Vec<Station>,
}

#[derive(Debug, Deserialize)]
struct Row {
    station: i64,
    x_over_l: f64,
    point: i64,
    y_over_l: f64,
    z_over_l: f64,
}

const REQUIRED: [&str; 9] = [
    "name",
    "status",
    "length_m",
    "draft_m",
    "beam_m",
    "model_scale",
    "transom",
    "transom_immersion_m",
    "source",
];

/// Relative tolerance for declared particulars against the offsets (beam, draft): 5 %.
pub const META_TOLERANCE: f64 = 0.05;

impl HullOffsets {
    /// Reads and checks a hull file.
    pub fn read(path: &std::path::Path) -> Result<Self, HullFileError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| HullFileError {
            file: file.clone(),
            line: 0,
            problem: format!("cannot read: {e}"),
        })?;
        Self::parse(&text, &file)
    }

    /// Parses and checks hull-file text; `file` names it in errors.
    pub fn parse(text: &str, file: &str) -> Result<Self, HullFileError> {
        let err = |line: usize, problem: String| HullFileError {
            file: file.to_string(),
            line,
            problem,
        };
        // Metadata.
        let mut kv: BTreeMap<String, (String, usize)> = BTreeMap::new();
        let mut header_line = None;
        let mut data = String::new();
        let mut line_of_record = vec![];
        for (k, raw) in text.lines().enumerate() {
            let line = k + 1;
            let t = raw.trim();
            if let Some(rest) = t.strip_prefix('#') {
                if let Some((key, value)) = rest.split_once(':') {
                    let key = key.trim().to_string();
                    let value = value.split("  ").next().unwrap_or("").trim().to_string();
                    if kv.insert(key.clone(), (value, line)).is_some() {
                        return Err(err(line, format!("metadata `{key}` is given twice")));
                    }
                }
                continue;
            }
            if t.is_empty() {
                continue;
            }
            if header_line.is_none() {
                header_line = Some(line);
                let cols: Vec<&str> = t.split(',').map(|c| c.trim()).collect();
                if cols != ["station", "x_over_L", "point", "y_over_L", "z_over_L"] {
                    return Err(err(
                        line,
                        format!("header must be `station,x_over_L,point,y_over_L,z_over_L`, found `{t}`"),
                    ));
                }
                data.push_str("station,x_over_l,point,y_over_l,z_over_l\n");
                continue;
            }
            data.push_str(t);
            data.push('\n');
            line_of_record.push(line);
        }
        if header_line.is_none() {
            return Err(err(
                0,
                "no header line `station,x_over_L,point,y_over_L,z_over_L` and no offsets".into(),
            ));
        }
        for key in REQUIRED {
            if !kv.contains_key(key) {
                return Err(err(
                    0,
                    format!("metadata `# {key}: ...` is missing (required: {})", REQUIRED.join(", ")),
                ));
            }
        }
        let get = |key: &str| kv.get(key).map(|(v, l)| (v.as_str(), *l)).unwrap();
        let num = |key: &str, positive: bool| -> Result<f64, HullFileError> {
            let (v, l) = get(key);
            let x: f64 = v
                .parse()
                .map_err(|_| err(l, format!("metadata `{key}`: expected a number, found `{v}`")))?;
            if !x.is_finite() || (positive && x <= 0.0) || x < 0.0 {
                return Err(err(
                    l,
                    format!(
                        "metadata `{key}`: expected a {} number, found `{v}`",
                        if positive { "positive" } else { "non-negative" }
                    ),
                ));
            }
            Ok(x)
        };
        let status = match get("status") {
            ("exact", _) => HullStatus::Exact,
            ("approximation", _) => HullStatus::Approximation,
            (v, l) => {
                return Err(err(
                    l,
                    format!("metadata `status`: expected `exact` or `approximation`, found `{v}`"),
                ))
            }
        };
        let transom = match get("transom") {
            ("true", _) => true,
            ("false", _) => false,
            (v, l) => {
                return Err(err(
                    l,
                    format!("metadata `transom`: expected `true` or `false`, found `{v}`"),
                ))
            }
        };
        let notes = kv
            .iter()
            .filter(|(k, _)| !REQUIRED.contains(&k.as_str()))
            .map(|(k, (v, _))| (k.clone(), v.clone()))
            .collect();
        let meta = HullMeta {
            name: get("name").0.to_string(),
            status,
            length_m: num("length_m", true)?,
            draft_m: num("draft_m", true)?,
            beam_m: num("beam_m", true)?,
            model_scale: num("model_scale", true)?,
            transom,
            transom_immersion_m: num("transom_immersion_m", false)?,
            source: get("source").0.to_string(),
            notes,
        };
        if meta.name.is_empty() {
            return Err(err(get("name").1, "metadata `name` is empty".into()));
        }

        // Offsets.
        let mut rdr = csv::ReaderBuilder::new()
            .trim(csv::Trim::All)
            .from_reader(data.as_bytes());
        let mut stations: Vec<(i64, Station, usize)> = vec![];
        for (k, rec) in rdr.deserialize::<Row>().enumerate() {
            let line = line_of_record.get(k).copied().unwrap_or(0);
            let row = rec.map_err(|e| {
                err(
                    line,
                    format!("expected 5 numbers `station,x_over_L,point,y_over_L,z_over_L`: {e}"),
                )
            })?;
            for (name, v) in [
                ("x_over_L", row.x_over_l),
                ("y_over_L", row.y_over_l),
                ("z_over_L", row.z_over_l),
            ] {
                if !v.is_finite() {
                    return Err(err(line, format!("`{name}` is not a finite number")));
                }
            }
            if row.y_over_l < 0.0 {
                return Err(err(
                    line,
                    format!(
                        "negative half-breadth y/L = {} (y is measured from the centre plane, ≥ 0)",
                        row.y_over_l
                    ),
                ));
            }
            // Offsets are fractions of L; a point a ship length or more from the centre plane or the
            // waterline is a typo (a deck point at z/L = 1e6 passed every other check and made each
            // section 1e10 samples long).
            for (name, v) in [("y_over_L", row.y_over_l), ("z_over_L", row.z_over_l)] {
                if v.abs() >= 1.0 {
                    return Err(err(
                        line,
                        format!("`{name}` = {v}: offsets are fractions of the length, expected |{name}| < 1"),
                    ));
                }
            }
            if !(0.0..=1.0).contains(&row.x_over_l) {
                return Err(err(
                    line,
                    format!("x/L = {} outside [0, 1] (stem at 0, transom at 1)", row.x_over_l),
                ));
            }
            match stations.last_mut() {
                Some((id, st, _)) if *id == row.station => {
                    if row.x_over_l != st.x {
                        return Err(err(
                            line,
                            format!("station {} changes x/L from {} to {}", row.station, st.x, row.x_over_l),
                        ));
                    }
                    if row.point as usize != st.points.len() {
                        return Err(err(
                            line,
                            format!(
                                "station {}: point {} out of order (expected {})",
                                row.station,
                                row.point,
                                st.points.len()
                            ),
                        ));
                    }
                    st.points.push([row.y_over_l, row.z_over_l]);
                }
                last => {
                    if let Some((id, st, _)) = last {
                        if row.station != *id + 1 {
                            return Err(err(line, format!("station {} follows station {id}: stations must be numbered consecutively and listed in order", row.station)));
                        }
                        if row.x_over_l <= st.x {
                            return Err(err(line, format!("stations must go aft with increasing x/L: station {} at x/L = {} is not aft of station {id} at {}", row.station, row.x_over_l, st.x)));
                        }
                    }
                    if row.point != 0 {
                        return Err(err(
                            line,
                            format!(
                                "station {} must start with point 0 (the keel), found point {}",
                                row.station, row.point
                            ),
                        ));
                    }
                    stations.push((
                        row.station,
                        Station {
                            x: row.x_over_l,
                            points: vec![[row.y_over_l, row.z_over_l]],
                        },
                        line,
                    ));
                }
            }
        }
        if stations.len() < 4 {
            return Err(err(
                0,
                format!(
                    "{} station(s): at least 4 are needed for a spline surface",
                    stations.len()
                ),
            ));
        }
        for (id, st, line) in &stations {
            let line = *line;
            if st.points.len() < 3 {
                return Err(err(
                    line,
                    format!(
                        "station {id} has {} point(s): at least 3 are needed (keel, waterline region, deck)",
                        st.points.len()
                    ),
                ));
            }
            if st.points[0][0].abs() > 1e-9 {
                return Err(err(line, format!("station {id} does not start on the centre plane: its first point has y/L = {} (expected 0, the keel)", st.points[0][0])));
            }
            if let Some((a, b)) = self_intersection(&st.points) {
                return Err(err(line, format!("station {id} is self-intersecting: segments {a} and {b} cross (points must run from keel to deck without folding)")));
            }
            if st.points.windows(2).any(|w| w[0] == w[1]) {
                return Err(err(
                    line,
                    format!("station {id} repeats a point: consecutive points must differ"),
                ));
            }
        }
        // Metadata against offsets.
        let l = meta.length_m;
        let max_y = stations
            .iter()
            .flat_map(|(_, s, _)| s.points.iter())
            .filter(|p| p[1] <= 1e-12)
            .map(|p| p[0])
            .fold(0.0, f64::max);
        let min_z = stations
            .iter()
            .flat_map(|(_, s, _)| s.points.iter())
            .map(|p| p[1])
            .fold(f64::INFINITY, f64::min);
        let beam_offsets = 2.0 * max_y * l;
        if (beam_offsets - meta.beam_m).abs() > META_TOLERANCE * meta.beam_m {
            return Err(err(get("beam_m").1, format!("metadata `beam_m` = {} m contradicts the offsets: twice the largest half-breadth at or below the waterline is {beam_offsets:.4} m", meta.beam_m)));
        }
        let draft_offsets = -min_z * l;
        if (draft_offsets - meta.draft_m).abs() > META_TOLERANCE * meta.draft_m {
            return Err(err(get("draft_m").1, format!("metadata `draft_m` = {} m contradicts the offsets: the deepest point is {draft_offsets:.4} m below the waterline", meta.draft_m)));
        }
        Ok(HullOffsets {
            meta,
            stations: stations.into_iter().map(|(_, s, _)| s).collect(),
        })
    }

    /// Writes the file format back (metadata, header, rows).
    pub fn to_csv(&self) -> String {
        let m = &self.meta;
        let mut s = String::new();
        s.push_str(&format!("# name: {}\n", m.name));
        s.push_str(&format!(
            "# status: {}\n",
            match m.status {
                HullStatus::Exact => "exact",
                HullStatus::Approximation => "approximation",
            }
        ));
        s.push_str(&format!(
            "# length_m: {}\n# draft_m: {}\n# beam_m: {}\n# model_scale: {}\n",
            m.length_m, m.draft_m, m.beam_m, m.model_scale
        ));
        s.push_str(&format!(
            "# transom: {}\n# transom_immersion_m: {}\n# source: {}\n",
            m.transom, m.transom_immersion_m, m.source
        ));
        for (k, v) in &m.notes {
            s.push_str(&format!("# {k}: {v}\n"));
        }
        s.push_str("station,x_over_L,point,y_over_L,z_over_L\n");
        for (i, st) in self.stations.iter().enumerate() {
            for (j, p) in st.points.iter().enumerate() {
                s.push_str(&format!("{i},{:.9},{j},{:.9},{:.9}\n", st.x, p[0], p[1]));
            }
        }
        s
    }
}

/// First pair of non-adjacent segments of a polyline that cross, if any.
pub fn self_intersection(p: &[[f64; 2]]) -> Option<(usize, usize)> {
    let n = p.len();
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    for i in 0..n.saturating_sub(1) {
        for j in i + 2..n - 1 {
            let (a, b, c, d) = (p[i], p[i + 1], p[j], p[j + 1]);
            let d1 = cross(c, d, a);
            let d2 = cross(c, d, b);
            let d3 = cross(a, b, c);
            let d4 = cross(a, b, d);
            if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
            {
                return Some((i, j));
            }
        }
    }
    None
}
