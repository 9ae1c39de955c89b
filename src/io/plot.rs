//! PNG line plots with plotters, using the DejaVu Sans font kept in the repository (`assets/fonts/`), so
//! nothing depends on system fonts. The image is rendered in memory, then written atomically.

use super::atomic::write_atomic;
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
}

/// One named series of (x, y) points.
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    pub style: Style,
}

const COLOURS: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(0, 0, 0),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(140, 86, 75),
    RGBColor(23, 190, 207),
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
        if let Some(r) = opts.range {
            (x0, x1, y0, y1) = r;
            pad = 0.0;
        }
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
/// axes of equal scale over `range` (x0, x1, y0, y1); `width` pixels wide. Written as PNG.
#[allow(clippy::too_many_arguments)]
pub fn scatter_plot(
    path: &Path,
    title: &str,
    points: &[(f64, f64)],
    values: &[f64],
    (vmin, vmax): (f64, f64),
    walls: &[Vec<(f64, f64)>],
    range: (f64, f64, f64, f64),
    width: u32,
) -> anyhow::Result<()> {
    register_font();
    let (x0, x1, y0, y1) = range;
    let plot_w = width.saturating_sub(100).max(100) as f64;
    let h = ((plot_w * (y1 - y0) / (x1 - x0)) as u32 + 110).clamp(200, 4000);
    let mut buf = vec![0u8; (width * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (width, h)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 20))
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .label_style(("sans-serif", 14))
            .draw()?;
        let span = (vmax - vmin).max(1e-300);
        chart.draw_series(
            points
                .iter()
                .zip(values)
                .filter(|(p, _)| p.0.is_finite() && p.1.is_finite())
                .map(|(p, v)| {
                    let s = ((v - vmin) / span).clamp(0.0, 1.0);
                    Circle::new(*p, 1, colour_map(s).filled())
                }),
        )?;
        for w in walls {
            chart.draw_series(LineSeries::new(w.iter().copied(), BLACK.stroke_width(2)))?;
        }
        root.present()?;
    }
    let img = encode_png(&buf, width, h)?;
    write_atomic(path, &img)?;
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
