//! PNG line plots with plotters, using the DejaVu Sans font kept in the repository (`assets/fonts/`), so
//! nothing depends on system fonts. The image is rendered in memory, then written atomically.

use super::atomic::write_atomic;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;

static FONT: Once = Once::new();

fn register_font() {
    FONT.call_once(|| {
        let bytes: &'static [u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, bytes);
    });
}

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Style {
    Line,
    Markers,
    /// Line through the points, each marked.
    LineMarkers,
}

/// One named series of (x, y) points.
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    pub style: Style,
}

/// Series colours in order, repeating after the last (a chart of the dam break's variants and its peers draws 10).
const COLOURS: [RGBColor; 11] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(0, 0, 0),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(140, 86, 75),
    RGBColor(23, 190, 207),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
];

/// Draws the series on linear axes and writes a PNG (1000×600) with a legend.
pub fn line_plot(path: &Path, title: &str, xlabel: &str, ylabel: &str, series: &[Series]) -> anyhow::Result<()> {
    line_plot_with(path, title, xlabel, ylabel, series, &PlotOptions::default())
}

/// Size, legend and fixed ranges of a plot.
#[derive(Clone, Debug)]
pub struct PlotOptions {
    pub size: (u32, u32),
    pub legend: bool,
    /// Fixed (x0, x1, y0, y1); `None`: fitted to the data.
    pub range: Option<(f64, f64, f64, f64)>,
}

impl Default for PlotOptions {
    fn default() -> Self {
        PlotOptions {
            size: (1000, 600),
            legend: true,
            range: None,
        }
    }
}

/// Draws the series with options and writes a PNG.
pub fn line_plot_with(
    path: &Path,
    title: &str,
    xlabel: &str,
    ylabel: &str,
    series: &[Series],
    opts: &PlotOptions,
) -> anyhow::Result<()> {
    register_font();
    let (w, h) = opts.size;
    let mut buf = vec![0u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE)?;
        let pts = series
            .iter()
            .flat_map(|s| s.points.iter())
            .filter(|p| p.0.is_finite() && p.1.is_finite());
        let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        for p in pts {
            x0 = x0.min(p.0);
            x1 = x1.max(p.0);
            y0 = y0.min(p.1);
            y1 = y1.max(p.1);
        }
        if !x0.is_finite() {
            (x0, x1, y0, y1) = (0.0, 1.0, 0.0, 1.0);
        }
        if x1 <= x0 {
            x1 = x0 + 1.0;
        }
        if y1 <= y0 {
            y1 = y0 + 1.0;
        }
        let mut pad = 0.05 * (y1 - y0);
        let mut xpad = 0.03 * (x1 - x0);
        if let Some(r) = opts.range {
            (x0, x1, y0, y1) = r;
            pad = 0.0;
            xpad = 0.0;
        }
        let (x0, x1) = (x0 - xpad, x1 + xpad);
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 24))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, (y0 - pad)..(y1 + pad))?;
        chart
            .configure_mesh()
            .x_desc(xlabel)
            .y_desc(ylabel)
            .label_style(("sans-serif", 16))
            .axis_desc_style(("sans-serif", 18))
            .draw()?;
        for (k, s) in series.iter().enumerate() {
            let c = COLOURS[k % COLOURS.len()];
            let data: Vec<(f64, f64)> = s
                .points
                .iter()
                .copied()
                .filter(|p| p.0.is_finite() && p.1.is_finite())
                .collect();
            match s.style {
                Style::Line => {
                    chart
                        .draw_series(LineSeries::new(data, c.stroke_width(2)))?
                        .label(s.name.as_str())
                        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
                }
                Style::LineMarkers => {
                    chart.draw_series(LineSeries::new(data.clone(), c.stroke_width(2)))?;
                    chart
                        .draw_series(data.into_iter().map(|p| Circle::new(p, 4, c.filled())))?
                        .label(s.name.as_str())
                        .legend(move |(x, y)| {
                            EmptyElement::at((x, y))
                                + PathElement::new(vec![(0, 0), (20, 0)], c.stroke_width(2))
                                + Circle::new((10, 0), 4, c.filled())
                        });
                }
                Style::Markers => {
                    chart
                        .draw_series(data.into_iter().map(|p| Circle::new(p, 4, c.filled())))?
                        .label(s.name.as_str())
                        .legend(move |(x, y)| Circle::new((x + 10, y), 4, c.filled()));
                }
            }
        }
        if opts.legend {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .label_font(("sans-serif", 16))
                .draw()?;
        }
        root.present()?;
    }
    let img = encode_png(&buf, w, h)?;
    write_atomic(path, &img)?;
    Ok(())
}

/// PNG encoding of an RGB buffer (via the `image` crate that plotters' bitmap encoder brings).
fn encode_png(rgb: &[u8], w: u32, h: u32) -> anyhow::Result<Vec<u8>> {
    let mut out = std::io::Cursor::new(Vec::new());
    image::write_buffer_with_format(&mut out, rgb, w, h, image::ColorType::Rgb8, image::ImageFormat::Png)?;
    Ok(out.into_inner())
}

/// Particles coloured by a value (blue → red over [vmin, vmax]) with optional wall polylines in black, on
/// axes of equal scale over `range` (x0, x1, y0, y1) labelled `xlabel`, `ylabel`; `width` pixels wide, with
/// a colour bar of [vmin, vmax] on the right when `bar` is given (its label). Written as PNG.
#[allow(clippy::too_many_arguments)]
pub fn scatter_plot(
    path: &Path,
    title: &str,
    (xlabel, ylabel): (&str, &str),
    points: &[(f64, f64)],
    values: &[f64],
    (vmin, vmax): (f64, f64),
    bar: Option<&str>,
    walls: &[Vec<(f64, f64)>],
    range: (f64, f64, f64, f64),
    width: u32,
) -> anyhow::Result<()> {
    register_font();
    let (x0, x1, y0, y1) = range;
    let bar_w = if bar.is_some() { 130 } else { 0 };
    let plot_w = width.saturating_sub(110 + bar_w).max(100) as f64;
    let h = ((plot_w * (y1 - y0) / (x1 - x0)) as u32 + 125).clamp(200, 4000);
    let mut buf = vec![0u8; (width * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (width, h)).into_drawing_area();
        root.fill(&WHITE)?;
        let (main, side) = root.split_horizontally(width - bar_w);
        let mut chart = ChartBuilder::on(&main)
            .caption(title, ("sans-serif", 20))
            .margin(10)
            .x_label_area_size(50)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(xlabel)
            .y_desc(ylabel)
            .label_style(("sans-serif", 14))
            .axis_desc_style(("sans-serif", 16))
            .draw()?;
        if let Some(label) = bar {
            colour_bar(&side, label, (vmin, vmax))?;
        }
        let span = (vmax - vmin).max(1e-300);
        chart.draw_series(
            points
                .iter()
                .zip(values)
                // Points outside the window would be drawn on its edge: leave them out.
                .filter(|(p, _)| p.0 >= x0 && p.0 <= x1 && p.1 >= y0 && p.1 <= y1)
                .map(|(p, v)| {
                    let s = ((v - vmin) / span).clamp(0.0, 1.0);
                    Circle::new(*p, 1, colour_map(s).filled())
                }),
        )?;
        for w in walls {
            for piece in clip_polyline(w, range) {
                chart.draw_series(LineSeries::new(piece, BLACK.stroke_width(2)))?;
            }
        }
        root.present()?;
    }
    let img = encode_png(&buf, width, h)?;
    write_atomic(path, &img)?;
    Ok(())
}

/// The parts of a polyline inside the window (x0, x1, y0, y1), each segment cut at the window's edges
/// (Liang–Barsky): plotters draws a point outside the window on its edge, which bends a line that leaves it.
pub fn clip_polyline(w: &[(f64, f64)], (x0, x1, y0, y1): (f64, f64, f64, f64)) -> Vec<Vec<(f64, f64)>> {
    let mut pieces: Vec<Vec<(f64, f64)>> = vec![];
    let mut open = false;
    for s in w.windows(2) {
        let (a, b) = (s[0], s[1]);
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        let inside = [(-dx, a.0 - x0), (dx, x1 - a.0), (-dy, a.1 - y0), (dy, y1 - a.1)]
            .iter()
            .all(|&(p, q)| {
                if p == 0.0 {
                    return q >= 0.0;
                }
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
                t0 <= t1
            });
        if !inside {
            open = false;
            continue;
        }
        let at = |t: f64| (a.0 + t * dx, a.1 + t * dy);
        if !(open && t0 == 0.0) {
            pieces.push(vec![at(t0)]);
        }
        pieces.last_mut().expect("a piece").push(at(t1));
        open = t1 == 1.0;
    }
    pieces
}

/// A vertical colour bar of [vmin, vmax] filling `area`, labelled `label`.
fn colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    label: &str,
    (vmin, vmax): (f64, f64),
) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    let span = (vmax - vmin).max(1e-300);
    let mut cb = ChartBuilder::on(area)
        .margin(10)
        .margin_top(40)
        .x_label_area_size(50)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..1.0, vmin..vmax)?;
    cb.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_desc(label)
        .label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 14))
        .draw()?;
    let n = 100;
    cb.draw_series((0..n).map(|k| {
        let a = vmin + span * k as f64 / n as f64;
        let b = vmin + span * (k + 1) as f64 / n as f64;
        Rectangle::new([(0.0, a), (1.0, b)], colour_map((k as f64 + 0.5) / n as f64).filled())
    }))?;
    Ok(())
}

/// Blue (0) → cyan → yellow → red (1).
fn colour_map(s: f64) -> RGBColor {
    let stops = [
        (0.0, (40, 60, 200)),
        (0.35, (40, 200, 220)),
        (0.7, (240, 220, 40)),
        (1.0, (210, 30, 30)),
    ];
    for w in stops.windows(2) {
        let ((a, ca), (b, cb)) = (w[0], w[1]);
        if s <= b {
            let f = (s - a) / (b - a);
            let mix = |p: u8, q: u8| (p as f64 + (q as f64 - p as f64) * f).round() as u8;
            return RGBColor(mix(ca.0, cb.0), mix(ca.1, cb.1), mix(ca.2, cb.2));
        }
    }
    RGBColor(210, 30, 30)
}

/// One panel of a sheet of particle plots.
pub struct ScatterPanel {
    pub title: String,
    pub points: Vec<(f64, f64)>,
    /// Colour values in [0, 1].
    pub values: Vec<f64>,
    pub walls: Vec<Vec<(f64, f64)>>,
    /// (x0, x1, y0, y1), drawn at equal scale.
    pub range: (f64, f64, f64, f64),
}

/// Several particle plots on one sheet, `columns` across, each panel `panel_width` pixels wide and as tall
/// as its range needs at equal scale (the tallest panel of a row sets the row).
pub fn scatter_sheet(
    path: &Path,
    title: &str,
    panels: &[ScatterPanel],
    columns: usize,
    panel_width: u32,
) -> anyhow::Result<()> {
    register_font();
    anyhow::ensure!(!panels.is_empty(), "{}: no panels to draw", path.display());
    let columns = columns.clamp(1, panels.len());
    let rows = panels.len().div_ceil(columns);
    let plot_w = panel_width.saturating_sub(90).max(100) as f64;
    let panel_h = |p: &ScatterPanel| {
        let (x0, x1, y0, y1) = p.range;
        ((plot_w * (y1 - y0) / (x1 - x0)) as u32 + 90).clamp(150, 2000)
    };
    let row_h: Vec<u32> = (0..rows)
        .map(|r| {
            panels[r * columns..((r + 1) * columns).min(panels.len())]
                .iter()
                .map(panel_h)
                .max()
                .unwrap_or(150)
        })
        .collect();
    let (w, h) = (panel_width * columns as u32, row_h.iter().sum::<u32>() + 50);
    let mut buf = vec![0u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE)?;
        let root = root.titled(title, ("sans-serif", 26))?;
        let mut top = 0i32;
        for (r, &rh) in row_h.iter().enumerate() {
            for c in 0..columns {
                let Some(p) = panels.get(r * columns + c) else { break };
                let x_off = (c as u32 * panel_width) as i32;
                let area = root.clone().shrink((x_off, top), (panel_width, panel_h(p)));
                let (x0, x1, y0, y1) = p.range;
                let mut chart = ChartBuilder::on(&area)
                    .caption(&p.title, ("sans-serif", 18))
                    .margin(8)
                    .x_label_area_size(30)
                    .y_label_area_size(55)
                    .build_cartesian_2d(x0..x1, y0..y1)?;
                chart
                    .configure_mesh()
                    .disable_mesh()
                    .label_style(("sans-serif", 12))
                    .draw()?;
                chart.draw_series(
                    p.points
                        .iter()
                        .zip(&p.values)
                        .filter(|(q, _)| q.0 >= x0 && q.0 <= x1 && q.1 >= y0 && q.1 <= y1)
                        .map(|(q, v)| Circle::new(*q, 1, colour_map(v.clamp(0.0, 1.0)).filled())),
                )?;
                for wl in &p.walls {
                    chart.draw_series(LineSeries::new(wl.iter().copied(), BLACK.stroke_width(2)))?;
                }
            }
            top += rh as i32;
        }
        root.present()?;
    }
    let img = encode_png(&buf, w, h)?;
    write_atomic(path, &img)?;
    Ok(())
}

/// A scalar field on a regular grid, values\[i\]\[j\] at (x0 + i dx, y0 + j dy); NaN where undefined.
pub struct Field {
    pub x0: f64,
    pub dx: f64,
    pub y0: f64,
    pub dy: f64,
    pub values: Vec<Vec<f64>>,
}

/// A colour map of a field (blue → red over [vmin, vmax], white where NaN) with line segments drawn over it
/// (contours), a colour bar, and labelled ticks along the top edge at given x (e.g. a second abscissa).
#[allow(clippy::too_many_arguments)]
pub fn field_map(
    path: &Path,
    title: &str,
    (xlabel, ylabel): (&str, &str),
    field: &Field,
    (vmin, vmax): (f64, f64),
    segments: &[[(f64, f64); 2]],
    top_ticks: &[(f64, String)],
    size: (u32, u32),
) -> anyhow::Result<()> {
    register_font();
    let nx = field.values.len();
    let ny = field.values.first().map_or(0, |c| c.len());
    anyhow::ensure!(nx > 0 && ny > 0, "{}: empty field", path.display());
    let (x0, x1) = (field.x0 - 0.5 * field.dx, field.x0 + (nx as f64 - 0.5) * field.dx);
    let (y0, y1) = (field.y0 - 0.5 * field.dy, field.y0 + (ny as f64 - 0.5) * field.dy);
    let (w, h) = size;
    let mut buf = vec![0u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE)?;
        let (main, bar) = root.split_horizontally(w.saturating_sub(150));
        let mut chart = ChartBuilder::on(&main)
            .caption(title, ("sans-serif", 22))
            .margin(15)
            .margin_top(40)
            .x_label_area_size(45)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(xlabel)
            .y_desc(ylabel)
            .label_style(("sans-serif", 14))
            .axis_desc_style(("sans-serif", 16))
            .draw()?;
        let span = (vmax - vmin).max(1e-300);
        chart.draw_series(field.values.iter().enumerate().flat_map(|(i, col)| {
            col.iter()
                .enumerate()
                .filter(|(_, v)| v.is_finite())
                .map(move |(j, v)| {
                    let (cx, cy) = (field.x0 + i as f64 * field.dx, field.y0 + j as f64 * field.dy);
                    Rectangle::new(
                        [
                            (cx - 0.5 * field.dx, cy - 0.5 * field.dy),
                            (cx + 0.5 * field.dx, cy + 0.5 * field.dy),
                        ],
                        colour_map(((v - vmin) / span).clamp(0.0, 1.0)).filled(),
                    )
                })
        }))?;
        chart.draw_series(
            segments
                .iter()
                .map(|s| PathElement::new(vec![s[0], s[1]], BLACK.stroke_width(1))),
        )?;
        for (x, label) in top_ticks.iter().filter(|(x, _)| *x >= x0 && *x <= x1) {
            chart.draw_series(std::iter::once(PathElement::new(
                vec![(*x, y1), (*x, y1 - 0.04 * (y1 - y0))],
                BLACK.stroke_width(2),
            )))?;
            chart.draw_series(std::iter::once(Text::new(
                label.clone(),
                (*x, y1 - 0.05 * (y1 - y0)),
                ("sans-serif", 13)
                    .into_font()
                    .color(&BLACK)
                    .pos(plotters::style::text_anchor::Pos::new(
                        plotters::style::text_anchor::HPos::Center,
                        plotters::style::text_anchor::VPos::Top,
                    )),
            )))?;
        }
        colour_bar(&bar, "", (vmin, vmax))?;
        root.present()?;
    }
    let img = encode_png(&buf, w, h)?;
    write_atomic(path, &img)?;
    Ok(())
}

/// Series on log–log axes (only positive values are drawn), PNG 1000×650 with a legend.
pub fn log_log_plot(path: &Path, title: &str, xlabel: &str, ylabel: &str, series: &[Series]) -> anyhow::Result<()> {
    register_font();
    let pts: Vec<(f64, f64)> = series
        .iter()
        .flat_map(|s| s.points.iter().copied())
        .filter(|p| p.0 > 0.0 && p.1 > 0.0 && p.0.is_finite() && p.1.is_finite())
        .collect();
    anyhow::ensure!(
        !pts.is_empty(),
        "{}: nothing positive to draw on log axes",
        path.display()
    );
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, 0.0f64, f64::INFINITY, 0.0f64);
    for p in &pts {
        x0 = x0.min(p.0);
        x1 = x1.max(p.0);
        y0 = y0.min(p.1);
        y1 = y1.max(p.1);
    }
    // Snap to whole decades so that every axis carries labelled key points, even a narrow one.
    let (x0, x1, y0, y1) = (decade_below(x0), decade_above(x1), decade_below(y0), decade_above(y1));
    let (w, h) = (1000u32, 650u32);
    let mut buf = vec![0u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 20))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(80)
            .build_cartesian_2d(
                (x0..x1)
                    .log_scale()
                    .with_key_points(log_ticks(x0, x1, &[1.0, 2.0, 5.0]))
                    .with_light_points(log_ticks(x0, x1, &[3.0, 4.0, 6.0, 7.0, 8.0, 9.0])),
                (y0..y1)
                    .log_scale()
                    .with_key_points(log_ticks(y0, y1, &[1.0, 2.0, 5.0]))
                    .with_light_points(log_ticks(y0, y1, &[3.0, 4.0, 6.0, 7.0, 8.0, 9.0])),
            )?;
        chart
            .configure_mesh()
            .x_desc(xlabel)
            .y_desc(ylabel)
            .x_label_formatter(&|v| short_number(*v))
            .y_label_formatter(&|v| short_number(*v))
            .label_style(("sans-serif", 14))
            .axis_desc_style(("sans-serif", 15))
            .draw()?;
        for (k, s) in series.iter().enumerate() {
            let c = COLOURS[k % COLOURS.len()];
            let data: Vec<(f64, f64)> = s.points.iter().copied().filter(|p| p.0 > 0.0 && p.1 > 0.0).collect();
            if matches!(s.style, Style::Line | Style::LineMarkers) {
                let width = if s.style == Style::Line { 3 } else { 1 };
                let l = chart.draw_series(LineSeries::new(data.clone(), c.stroke_width(width)))?;
                if s.style == Style::Line {
                    l.label(s.name.as_str())
                        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(3)));
                }
            }
            if matches!(s.style, Style::Markers | Style::LineMarkers) {
                chart
                    .draw_series(data.into_iter().map(|p| Circle::new(p, 5, c.filled())))?
                    .label(s.name.as_str())
                    .legend(move |(x, y)| Circle::new((x + 10, y), 5, c.filled()));
            }
        }
        // Upper right: error-against-cost and error-against-resolution data fall from upper left to lower right.
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 14))
            .draw()?;
        root.present()?;
    }
    let img = encode_png(&buf, w, h)?;
    write_atomic(path, &img)?;
    Ok(())
}

/// The largest power of ten not above `v` (v > 0).
fn decade_below(v: f64) -> f64 {
    10f64.powf(v.log10().floor())
}

/// The smallest power of ten not below `v` (v > 0); one decade above a value that is itself a power of ten.
fn decade_above(v: f64) -> f64 {
    let d = 10f64.powf(v.log10().ceil());
    if d <= v {
        d * 10.0
    } else {
        d
    }
}

/// The values m·10^k (m from `mantissas`) within [lo, hi], rising.
fn log_ticks(lo: f64, hi: f64, mantissas: &[f64]) -> Vec<f64> {
    let mut out = vec![];
    let mut d = decade_below(lo);
    while d <= hi * (1.0 + 1e-12) {
        for m in mantissas {
            let v = m * d;
            if v >= lo * (1.0 - 1e-12) && v <= hi * (1.0 + 1e-12) {
                out.push(v);
            }
        }
        d *= 10.0;
    }
    out
}

/// A tick label with at most three significant digits and no trailing zeros: 0.2, 30, 1e-5.
fn short_number(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if !(1e-3..1e5).contains(&a) {
        return format!("{v:.0e}");
    }
    let digits = (2 - a.log10().floor() as i32).max(0) as usize;
    let s = format!("{v:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// A grid of labelled cells coloured green (true), red (false) or grey (missing): rows down, columns across.
pub fn label_grid(
    path: &Path,
    title: &str,
    rows: &[&str],
    cols: &[&str],
    cells: &[Vec<Option<(bool, String)>>],
) -> anyhow::Result<()> {
    register_font();
    let (cw, ch) = (150u32, 50u32);
    let w = (200 + cw * cols.len() as u32).max(20 + 11 * title.chars().count() as u32);
    let h = 90 + ch * (rows.len() as u32 + 1);
    let mut buf = vec![0u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE)?;
        let font = ("sans-serif", 15).into_font();
        root.draw(&Text::new(title.to_string(), (10, 10), ("sans-serif", 20).into_font()))?;
        for (j, c) in cols.iter().enumerate() {
            root.draw(&Text::new(
                c.to_string(),
                (210 + (j as u32 * cw) as i32, 60),
                font.clone(),
            ))?;
        }
        for (i, r) in rows.iter().enumerate() {
            let y = (90 + i as u32 * ch) as i32;
            root.draw(&Text::new(r.to_string(), (10, y + 15), font.clone()))?;
            for (j, v) in cells[i].iter().enumerate() {
                let x = (200 + j as u32 * cw) as i32;
                let colour = match v {
                    Some((true, _)) => RGBColor(120, 200, 120),
                    Some((false, _)) => RGBColor(220, 90, 80),
                    None => RGBColor(200, 200, 200),
                };
                root.draw(&Rectangle::new(
                    [(x + 2, y + 2), (x + cw as i32 - 2, y + ch as i32 - 2)],
                    colour.filled(),
                ))?;
                let label = match v {
                    Some((_, text)) => text.as_str(),
                    None => "–",
                };
                root.draw(&Text::new(label.to_string(), (x + 10, y + 15), font.clone()))?;
            }
        }
        root.present()?;
    }
    let img = encode_png(&buf, w, h)?;
    write_atomic(path, &img)?;
    Ok(())
}

/// One bar of a tornado chart: the quantity at the low and the high end of a parameter's range, each with
/// its label (the parameter's value; a trailing `*` is the caller's mark of a value it distrusts).
pub struct TornadoBar {
    pub label: String,
    pub low: (f64, String),
    pub high: (f64, String),
}

/// A tornado chart (PNG, 1000 px wide): one horizontal bar per parameter from its low to its high value,
/// widest at the top, a black line at the baseline and a dashed red line with its label at each mark (a
/// published value). Bars are drawn from the baseline to each end, so a parameter whose both ends move the
/// quantity the same way shows as one bar on one side.
pub fn tornado(
    path: &Path,
    title: &str,
    xlabel: &str,
    baseline: f64,
    bars: &[TornadoBar],
    marks: &[(String, f64)],
) -> anyhow::Result<()> {
    register_font();
    let mut bars: Vec<&TornadoBar> = bars.iter().collect();
    let span = |b: &TornadoBar| (b.high.0 - baseline).abs().max((b.low.0 - baseline).abs());
    bars.sort_by(|a, b| span(b).total_cmp(&span(a)));
    let n = bars.len().max(1);
    let (w, h) = (1000u32, 140 + 50 * n as u32);
    let mut lo = baseline;
    let mut hi = baseline;
    for v in bars
        .iter()
        .flat_map(|b| [b.low.0, b.high.0])
        .chain(marks.iter().map(|m| m.1))
        .filter(|v| v.is_finite())
    {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    let pad = 0.08 * (hi - lo).max(1e-9);
    // Room on the right for the end labels.
    let right = 0.22 * (hi - lo).max(1e-9);
    let mut buf = vec![0u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 22))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(290)
            .build_cartesian_2d((lo - pad)..(hi + right), 0f64..n as f64)?;
        chart
            .configure_mesh()
            .disable_y_mesh()
            .disable_y_axis()
            .x_desc(xlabel)
            .label_style(("sans-serif", 15))
            .axis_desc_style(("sans-serif", 17))
            .draw()?;
        let font = ("sans-serif", 14).into_font();
        for (k, b) in bars.iter().enumerate() {
            let y = n as f64 - k as f64 - 0.5;
            let (_, py) = chart.backend_coord(&(lo - pad, y));
            root.draw(&Text::new(
                b.label.clone(),
                (20, py - 8),
                ("sans-serif", 16).into_font(),
            ))?;
            for (is_low, end, colour) in [
                (true, &b.low, RGBColor(31, 119, 180)),
                (false, &b.high, RGBColor(255, 127, 14)),
            ] {
                // An end at the baseline is the approximation itself: labelled only when the whole bar is there,
                // once, on the low side.
                let at_base = end.0 == baseline;
                if !end.0.is_finite() || (at_base && !(is_low && b.high.0 == baseline)) {
                    continue;
                }
                chart.draw_series(std::iter::once(Rectangle::new(
                    [(baseline.min(end.0), y - 0.3), (baseline.max(end.0), y + 0.3)],
                    colour.mix(0.7).filled(),
                )))?;
                chart.draw_series(std::iter::once(Text::new(
                    end.1.clone(),
                    (end.0, y + 0.05),
                    font.clone(),
                )))?;
            }
        }
        chart.draw_series(std::iter::once(PathElement::new(
            vec![(baseline, 0.0), (baseline, n as f64)],
            BLACK.stroke_width(2),
        )))?;
        for (name, v) in marks {
            let red = RGBColor(214, 39, 40);
            let steps = 40;
            for i in (0..steps).step_by(2) {
                let (a, b) = (i as f64 / steps as f64, (i + 1) as f64 / steps as f64);
                chart.draw_series(std::iter::once(PathElement::new(
                    vec![(*v, a * n as f64), (*v, b * n as f64)],
                    red.stroke_width(2),
                )))?;
            }
            chart.draw_series(std::iter::once(Text::new(
                name.clone(),
                (*v, n as f64 - 0.1),
                ("sans-serif", 15).into_font().color(&red),
            )))?;
        }
        root.present()?;
    }
    let img = encode_png(&buf, w, h)?;
    write_atomic(path, &img)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Pixels of exactly the colour map's top colour (value 1) in a PNG.
    fn red_pixels(path: &Path) -> usize {
        let img = image::open(path).unwrap().to_rgb8();
        img.pixels().filter(|p| p.0 == [210, 30, 30]).count()
    }

    /// A wall leaving a snapshot's window was drawn to its far point clamped onto the window's edge, which bent
    /// the bent-wall plate's line at the top of its plunge picture: the wall is cut where it leaves the window.
    #[test]
    fn a_wall_leaving_the_window_is_cut_at_its_edge_not_bent_onto_it() {
        let range = (0.0, 10.0, 0.0, 3.0);
        // The plate from its foot (2.5, 0) to its top (5.45, 3.78) above the window: cut at z = 3.
        let pieces = clip_polyline(&[(5.45, 3.78), (2.5, 0.0), (10.0, 0.0)], range);
        assert_eq!(pieces.len(), 1, "{pieces:?}");
        let p = &pieces[0];
        assert_eq!(p.len(), 3, "{p:?}");
        let y_at_3 = 2.5 + (5.45 - 2.5) * 3.0 / 3.78;
        assert!(
            (p[0].0 - y_at_3).abs() < 1e-12 && (p[0].1 - 3.0).abs() < 1e-12,
            "{:?}",
            p[0]
        );
        assert_eq!((p[1], p[2]), ((2.5, 0.0), (10.0, 0.0)));
        // A polyline that leaves and comes back is two pieces; one wholly outside is none.
        let pieces = clip_polyline(&[(1.0, 1.0), (1.0, 5.0), (2.0, 5.0), (2.0, 1.0)], range);
        assert_eq!(pieces, vec![vec![(1.0, 1.0), (1.0, 3.0)], vec![(2.0, 3.0), (2.0, 1.0)]]);
        assert!(clip_polyline(&[(-1.0, 4.0), (11.0, 4.0)], range).is_empty());
    }

    /// Particles outside a snapshot's window were drawn on its edge (a coloured strip along the right side of
    /// the plunge snapshots, from the particles beyond the window).
    #[test]
    fn particles_outside_the_window_are_not_drawn_on_its_edge() {
        let dir = std::env::temp_dir().join(format!("bowwave-plot-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("scatter.png");
        let draw = |points: &[(f64, f64)]| {
            let values = vec![1.0; points.len()];
            scatter_plot(
                &path,
                "t",
                ("y", "z"),
                points,
                &values,
                (0.0, 1.0),
                None,
                &[],
                (0.0, 1.0, 0.0, 1.0),
                400,
            )
            .unwrap();
            red_pixels(&path)
        };
        assert!(draw(&[(0.5, 0.5)]) > 0, "a point inside the window is drawn");
        assert_eq!(draw(&[(1.5, 0.5), (0.5, -2.0), (f64::NAN, 0.5)]), 0);
        std::fs::remove_dir_all(&dir).ok();
    }
}
