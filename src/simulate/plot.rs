//! Line charts with `plotters`: one or more panels stacked vertically on a shared x axis,
//! written as SVG and PNG.
//!
//! Text is laid out (both backends) and rasterised (PNG) with the DejaVu Sans font embedded in
//! the program ([`super::FONT_DEJAVU_SANS`], through plotters' `ab_glyph` feature), so nothing depends
//! on the fonts or font libraries of the machine. The SVG names the generic family
//! `sans-serif` in its `<text>` elements and lets the viewer pick the face. The same figure
//! always gives byte-identical SVG and PNG files.

use std::path::Path;
use std::sync::OnceLock;

use plotters::backend::{BitMapBackend, DrawingBackend, RGBPixel, SVGBackend};
use plotters::chart::ChartContext;
use plotters::coord::Shift;
use plotters::coord::cartesian::Cartesian2d;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::{
    ChartBuilder, Color, DrawingArea, IntoDrawingArea, IntoFont, LineSeries, PathElement, RGBColor,
    SeriesLabelPosition, ShapeStyle,
};
use plotters::style::{FontStyle, RGBAColor, TextStyle, register_font};

use super::SimError;
use super::raster::{self, FONT_DEJAVU_SANS, Raster};
use super::table::write_atomic;

/// The family name under which the font is registered, and that the SVG names.
const FAMILY: &str = "sans-serif";

/// Line colours, in series order (the "Tableau 10" palette, then again).
const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// Largest width or height of a figure, in pixels after scaling.
const MAX_PIXELS: u32 = 16_384;

/// One curve: a name for the legend and its points `(x, y)`, joined in order. Non-finite
/// points are left out and break the line.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text (no legend entry if empty).
    pub name: String,
    /// The points, in drawing order.
    pub points: Vec<(f64, f64)>,
}

impl Series {
    /// A series named `name` through `points`.
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self {
            name: name.into(),
            points,
        }
    }

    /// A series from separate abscissae and ordinates.
    ///
    /// # Errors
    /// [`SimError::InvalidInput`] if the lengths differ.
    pub fn from_xy(name: impl Into<String>, xs: &[f64], ys: &[f64]) -> Result<Self, SimError> {
        let name = name.into();
        if xs.len() != ys.len() {
            return Err(SimError::InvalidInput(format!(
                "series \"{name}\": {} abscissae for {} ordinates",
                xs.len(),
                ys.len()
            )));
        }
        Ok(Self {
            name,
            points: xs.iter().copied().zip(ys.iter().copied()).collect(),
        })
    }
}

/// One chart of a [`Figure`]: its y-axis label and its series.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Panel {
    /// Y-axis label, with its unit, e.g. `"θ2 (rad)"`.
    pub y_label: String,
    /// The curves, drawn in order with the colours of a fixed palette.
    pub series: Vec<Series>,
    /// Fixed y range `(min, max)`; by default the data range plus 5 % on each side.
    pub y_range: Option<(f64, f64)>,
}

impl Panel {
    /// An empty panel with this y-axis label.
    pub fn new(y_label: impl Into<String>) -> Self {
        Self {
            y_label: y_label.into(),
            ..Self::default()
        }
    }

    /// The panel with one more series.
    pub fn series(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }

    /// The panel with a fixed y range.
    pub fn y_range(mut self, min: f64, max: f64) -> Self {
        self.y_range = Some((min, max));
        self
    }
}

/// A figure: a title, then `k >= 1` panels stacked vertically that share the x axis (same
/// range; tick labels and x label under the bottom panel only), each with its legend.
///
/// Sizes are in CSS pixels (1/96 in): the SVG has exactly this size, the PNG is `scale` times
/// larger in pixels and declares `96·scale` dpi, so both have the same physical size.
///
/// ```
/// use torseur::simulate::{Figure, Panel, Series};
///
/// let t: Vec<f64> = (0..=100).map(|i| i as f64 * 0.01).collect();
/// let theta: Vec<f64> = t.iter().map(|t| t.sin()).collect();
/// let torque: Vec<f64> = t.iter().map(|t| 2.0 * t.cos()).collect();
/// let figure = Figure::new("Regulator", "t (s)")
///     .panel(Panel::new("θ2 (rad)").series(Series::from_xy("θ2", &t, &theta)?))
///     .panel(Panel::new("Cm (N·m)").series(Series::from_xy("Cm", &t, &torque)?));
/// let svg = figure.to_svg()?;
/// assert!(svg.starts_with("<svg"));
/// let png = figure.to_png(2)?;
/// assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
/// # Ok::<(), torseur::simulate::SimError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Title, above the panels; none (and no room kept for it) when empty.
    pub title: String,
    /// X-axis label, with its unit, e.g. `"t (s)"`.
    pub x_label: String,
    /// The panels, top to bottom.
    pub panels: Vec<Panel>,
    /// Width in CSS pixels. Default 800.
    pub width: u32,
    /// Height in CSS pixels; by default `60 + 300·k` for `k` panels.
    pub height: Option<u32>,
    /// Fixed x range `(min, max)`; by default the range of all the data.
    pub x_range: Option<(f64, f64)>,
}

impl Figure {
    /// A figure with no panel yet.
    pub fn new(title: impl Into<String>, x_label: impl Into<String>) -> Self {
        Self {
            title: title.into(),
            x_label: x_label.into(),
            panels: Vec::new(),
            width: 800,
            height: None,
            x_range: None,
        }
    }

    /// The figure with one more panel, below the others.
    pub fn panel(mut self, panel: Panel) -> Self {
        self.panels.push(panel);
        self
    }

    /// The figure with this size, in CSS pixels.
    pub fn size(mut self, width: u32, height: u32) -> Self {
        self.width = width;
        self.height = Some(height);
        self
    }

    /// The figure with a fixed x range.
    pub fn x_range(mut self, min: f64, max: f64) -> Self {
        self.x_range = Some((min, max));
        self
    }

    /// The size in CSS pixels, checked.
    fn dimensions(&self, scale: u32) -> Result<(u32, u32), SimError> {
        if self.panels.is_empty() {
            return Err(SimError::InvalidInput(
                "a figure needs at least one panel".into(),
            ));
        }
        let k = u32::try_from(self.panels.len()).unwrap_or(u32::MAX);
        let height = self
            .height
            .unwrap_or_else(|| 60u32.saturating_add(300u32.saturating_mul(k)));
        let min_height = 60 + 120 * k.min(1000);
        if !(1..=8).contains(&scale) {
            return Err(SimError::InvalidInput(format!(
                "PNG scale {scale} is not in 1..=8"
            )));
        }
        let (w, h) = (
            self.width.saturating_mul(scale),
            height.saturating_mul(scale),
        );
        if self.width < 300 || height < min_height || w > MAX_PIXELS || h > MAX_PIXELS {
            return Err(SimError::InvalidInput(format!(
                "figure size {}×{height} px (scale {scale}): need width >= 300, height >= \
                 {min_height} for {k} panels, and at most {MAX_PIXELS} px once scaled",
                self.width
            )));
        }
        Ok((self.width, height))
    }

    /// The figure as SVG text.
    ///
    /// # Errors
    /// [`SimError::InvalidInput`] for a figure without panel or of an unusable size, or a
    /// non-finite or empty fixed range; [`SimError::Plot`] if drawing fails.
    pub fn to_svg(&self) -> Result<String, SimError> {
        let (w, h) = self.dimensions(1)?;
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (w, h)).into_drawing_area();
            self.draw(&root, 1.0)?;
            root.present().map_err(plot_err)?;
        }
        Ok(svg)
    }

    /// The figure as a PNG file (8-bit RGB), `scale` times the CSS size (1 to 8; 3 gives
    /// about 300 dpi on a page), with the resolution chunk `pHYs` at `96·scale` dpi.
    ///
    /// # Errors
    /// As [`to_svg`](Self::to_svg), and [`SimError::Png`] if encoding fails.
    pub fn to_png(&self, scale: u32) -> Result<Vec<u8>, SimError> {
        let (w, h) = self.dimensions(scale)?;
        let (w, h) = (w * scale, h * scale);
        let mut pixels = vec![255u8; w as usize * h as usize * 3];
        {
            let font = raster::font()
                .ok_or_else(|| SimError::Plot("the embedded font cannot be parsed".into()))?;
            let bitmap = BitMapBackend::<RGBPixel>::with_buffer_and_format(&mut pixels, (w, h))
                .map_err(plot_err)?;
            let root = Raster::new(bitmap, font).into_drawing_area();
            self.draw(&root, f64::from(scale))?;
            root.present().map_err(plot_err)?;
        }
        let mut png = Vec::new();
        let mut encoder = png::Encoder::new(&mut png, w, h);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        // 96 dpi per unit of scale, in pixels per metre.
        let ppm = (96.0 * f64::from(scale) / 0.0254).round() as u32;
        encoder.set_pixel_dims(Some(png::PixelDimensions {
            xppu: ppm,
            yppu: ppm,
            unit: png::Unit::Meter,
        }));
        let png_err = |e: png::EncodingError| SimError::Png(e.to_string());
        let mut writer = encoder.write_header().map_err(png_err)?;
        writer.write_image_data(&pixels).map_err(png_err)?;
        writer.finish().map_err(png_err)?;
        Ok(png)
    }

    /// Writes the SVG to `path`, atomically.
    ///
    /// # Errors
    /// As [`to_svg`](Self::to_svg), and [`SimError::Io`].
    pub fn save_svg(&self, path: impl AsRef<Path>) -> Result<(), SimError> {
        write_atomic(path.as_ref(), self.to_svg()?.as_bytes())
    }

    /// Writes the PNG to `path`, atomically.
    ///
    /// # Errors
    /// As [`to_png`](Self::to_png), and [`SimError::Io`].
    pub fn save_png(&self, path: impl AsRef<Path>, scale: u32) -> Result<(), SimError> {
        write_atomic(path.as_ref(), &self.to_png(scale)?)
    }

    /// Draws the figure on `root`, every length multiplied by `s`.
    fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        s: f64,
    ) -> Result<(), SimError> {
        ensure_font()?;
        let px = |v: f64| (v * s).round() as u32;
        let font = |size: f64| TextStyle::from((FAMILY, size * s).into_font());
        let x_range = match self.x_range {
            Some(r) => checked_range(r, "x")?,
            None => padded_range(
                self.panels
                    .iter()
                    .flat_map(|p| &p.series)
                    .flat_map(|se| &se.points)
                    .map(|p| p.0),
                0.0,
            ),
        };

        root.fill(&RGBColor(255, 255, 255)).map_err(plot_err)?;
        let body = root.margin(px(8.0), px(8.0), px(8.0), px(16.0));
        // No title band for an empty title (a figure in a document has its caption there).
        let body = if self.title.is_empty() {
            body
        } else {
            body.titled(&self.title, font(20.0)).map_err(plot_err)?
        };

        // Equal plotting heights; the bottom panel also holds the x tick labels and x label.
        let x_label_area = px(52.0);
        let k = self.panels.len();
        let (_, body_h) = body.dim_in_pixel();
        let plot_h = body_h.saturating_sub(x_label_area) as f64 / k as f64;
        let cuts: Vec<u32> = (1..k).map(|i| (plot_h * i as f64).round() as u32).collect();
        let areas = body.split_by_breakpoints(Vec::<u32>::new(), cuts);

        for (i, area) in areas.iter().enumerate().take(k) {
            let at = PanelAt {
                i,
                bottom: i + 1 == k,
                x_range,
                x_label_area,
                s,
            };
            self.draw_panel(area, &at)?;
        }
        Ok(())
    }

    /// Draws panel `at.i` on `area`: its axes and grid, then its curves and legend.
    fn draw_panel<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        at: &PanelAt,
    ) -> Result<(), SimError> {
        let panel = &self.panels[at.i];
        let px = |v: f64| (v * at.s).round() as u32;
        let font = |size: f64| TextStyle::from((FAMILY, size * at.s).into_font());
        let (x_range, bottom) = (at.x_range, at.bottom);
        let y_range = match panel.y_range {
            Some(r) => checked_range(r, "y")?,
            None => padded_range(
                panel.series.iter().flat_map(|se| &se.points).map(|p| p.1),
                0.05,
            ),
        };
        let mut chart = ChartBuilder::on(area)
            .margin_top(px(6.0))
            .margin_bottom(px(if bottom { 0.0 } else { 6.0 }))
            .x_label_area_size(if bottom { at.x_label_area } else { 0 })
            .y_label_area_size(px(78.0))
            .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)
            .map_err(plot_err)?;
        let grid = |c: u8, w: f64| ShapeStyle {
            color: RGBAColor(c, c, c, 1.0),
            filled: false,
            stroke_width: px(w).max(1),
        };
        let mut mesh = chart.configure_mesh();
        mesh.y_desc(panel.y_label.as_str())
            .label_style(font(13.0))
            .axis_desc_style(font(15.0))
            .light_line_style(grid(238, 1.0))
            .bold_line_style(grid(208, 1.0))
            .axis_style(grid(0, 1.0))
            .set_all_tick_mark_size(px(5.0))
            .x_labels(10)
            .y_labels(8)
            .x_label_formatter(&tick_label)
            .y_label_formatter(&tick_label);
        if bottom {
            mesh.x_desc(self.x_label.as_str());
        }
        mesh.draw().map_err(plot_err)?;

        if self.draw_curves(&mut chart, at)? {
            chart
                .configure_series_labels()
                .position(legend_corner(panel, x_range, y_range))
                .margin(px(8.0))
                .legend_area_size(px(28.0))
                .label_font(font(13.0))
                .background_style(RGBColor(255, 255, 255).mix(0.85))
                .border_style(RGBColor(120, 120, 120))
                .draw()
                .map_err(plot_err)?;
        }
        Ok(())
    }

    /// Draws the curves of panel `at.i` (each series split where it is not finite); returns
    /// whether one is labelled for a legend.
    fn draw_curves<DB: DrawingBackend>(
        &self,
        chart: &mut ChartContext<'_, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
        at: &PanelAt,
    ) -> Result<bool, SimError> {
        let (i, panel) = (at.i, &self.panels[at.i]);
        let px = |v: f64| (v * at.s).round() as u32;
        // A legend that would repeat the one above (same series names) is left out.
        let names = |p: &Panel| p.series.iter().map(|s| s.name.clone()).collect::<Vec<_>>();
        let repeated = i > 0 && names(panel) == names(&self.panels[i - 1]);
        let mut labelled = false;
        for (c, series) in panel.series.iter().enumerate() {
            let style = ShapeStyle {
                color: PALETTE[c % PALETTE.len()].to_rgba(),
                filled: false,
                stroke_width: px(2.0).max(1),
            };
            let runs = finite_runs(&series.points);
            for (r, run) in runs.iter().enumerate() {
                let anno = chart
                    .draw_series(LineSeries::new(run.iter().copied(), style))
                    .map_err(plot_err)?;
                if r == 0 && !repeated && !series.name.is_empty() {
                    let len = px(22.0) as i32;
                    anno.label(series.name.as_str())
                        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + len, y)], style));
                    labelled = true;
                }
            }
        }
        Ok(labelled)
    }
}

/// Where a panel is drawn: its index, whether it is the bottom one (with the x labels), the
/// shared x range, the height of the x label area and the scale of every length.
struct PanelAt {
    i: usize,
    bottom: bool,
    x_range: (f64, f64),
    x_label_area: u32,
    s: f64,
}

/// Plots `series` on one chart (one panel) and writes it as SVG to `path_svg` and, if given,
/// as PNG at scale 3 to `path_png`, both atomically.
///
/// # Errors
/// As [`Figure::save_svg`] and [`Figure::save_png`].
pub fn plot(
    series: &[Series],
    title: &str,
    x_label: &str,
    y_label: &str,
    path_svg: &Path,
    path_png: Option<&Path>,
) -> Result<(), SimError> {
    let panel = Panel {
        y_label: y_label.to_string(),
        series: series.to_vec(),
        y_range: None,
    };
    let figure = Figure::new(title, x_label).panel(panel);
    figure.save_svg(path_svg)?;
    if let Some(path) = path_png {
        figure.save_png(path, 3)?;
    }
    Ok(())
}

/// Registers the embedded font with plotters, once per process.
fn ensure_font() -> Result<(), SimError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED
        .get_or_init(|| register_font(FAMILY, FontStyle::Normal, FONT_DEJAVU_SANS).is_ok());
    if ok {
        Ok(())
    } else {
        Err(SimError::Plot("the embedded font cannot be parsed".into()))
    }
}

fn plot_err<E: std::fmt::Display>(e: E) -> SimError {
    SimError::Plot(e.to_string())
}

/// A fixed range, checked: finite and `min < max`.
fn checked_range((lo, hi): (f64, f64), axis: &str) -> Result<(f64, f64), SimError> {
    if lo.is_finite() && hi.is_finite() && lo < hi {
        Ok((lo, hi))
    } else {
        Err(SimError::InvalidInput(format!(
            "{axis} range [{lo}, {hi}] is not a finite interval"
        )))
    }
}

/// The range of the finite `values`, widened by `pad` of its width on each side; a single
/// value `v` gives `v ± max(|v|/10, 1)`, no value `[0, 1]`.
fn padded_range(values: impl Iterator<Item = f64>, pad: f64) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo > hi {
        return (0.0, 1.0);
    }
    let width = hi - lo;
    let (a, b) = if width > 0.0 {
        (lo - pad * width, hi + pad * width)
    } else {
        let d = (lo.abs() / 10.0).max(1.0);
        (lo - d, hi + d)
    };
    // Near f64::MAX the padding overflows: keep the bare data range then.
    if a.is_finite() && b.is_finite() && a < b {
        (a, b)
    } else {
        (lo, hi.max(lo.next_up()))
    }
}

/// The maximal runs of consecutive finite points.
fn finite_runs(points: &[(f64, f64)]) -> Vec<Vec<(f64, f64)>> {
    let mut runs = Vec::new();
    let mut run = Vec::new();
    for &(x, y) in points {
        if x.is_finite() && y.is_finite() {
            run.push((x, y));
        } else if !run.is_empty() {
            runs.push(std::mem::take(&mut run));
        }
    }
    if !run.is_empty() || runs.is_empty() {
        runs.push(run);
    }
    runs
}

/// A tick value as the course prints numbers: a decimal comma, no useless zeros, never
/// « -0 » (`2000`, `0,25`, `-1,5`).
fn tick_label(v: &f64) -> String {
    let r = (v * 1e9).round() / 1e9;
    let r = if r == 0.0 { 0.0 } else { r };
    format!("{r}").replace('.', ",")
}

/// The corner of a panel where the legend hides the fewest points of its curves.
fn legend_corner(panel: &Panel, x: (f64, f64), y: (f64, f64)) -> SeriesLabelPosition {
    let (w, h) = (x.1 - x.0, y.1 - y.0);
    let corners = [
        (SeriesLabelPosition::UpperRight, true, true),
        (SeriesLabelPosition::UpperLeft, false, true),
        (SeriesLabelPosition::LowerRight, true, false),
        (SeriesLabelPosition::LowerLeft, false, false),
    ];
    let hidden = |right: bool, upper: bool| {
        panel
            .series
            .iter()
            .flat_map(|s| &s.points)
            .filter(|(px, py)| {
                let fx = (px - x.0) / w;
                let fy = (py - y.0) / h;
                (if right { fx >= 0.7 } else { fx <= 0.3 })
                    && (if upper { fy >= 0.65 } else { fy <= 0.35 })
            })
            .count()
    };
    corners
        .into_iter()
        .min_by_key(|&(_, r, u)| hidden(r, u))
        .map(|(c, _, _)| c)
        .unwrap_or(SeriesLabelPosition::UpperRight)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_printed_as_the_course_prints_numbers() {
        assert_eq!(tick_label(&2000.0), "2000");
        assert_eq!(tick_label(&0.25), "0,25");
        assert_eq!(tick_label(&-1.5), "-1,5");
        assert_eq!(tick_label(&-0.0), "0");
        assert_eq!(tick_label(&-1e-12), "0");
        assert_eq!(tick_label(&(0.1 + 0.2)), "0,3");
    }

    #[test]
    fn the_legend_goes_where_the_curves_are_not() {
        // A ramp from the lower left to a plateau at the top right: the upper left is free.
        let ramp: Vec<(f64, f64)> = (0..=100)
            .map(|k| {
                let t = f64::from(k) / 100.0;
                (t, (2.0 * t).min(1.0))
            })
            .collect();
        let p = Panel::new("y").series(Series::new("a", ramp));
        assert_eq!(
            legend_corner(&p, (0.0, 1.0), (0.0, 1.0)),
            SeriesLabelPosition::UpperLeft
        );
        // A curve along the bottom: the upper right, the default, is free.
        let low: Vec<(f64, f64)> = (0..=100).map(|k| (f64::from(k) / 100.0, 0.0)).collect();
        let p = Panel::new("y").series(Series::new("a", low));
        assert_eq!(
            legend_corner(&p, (0.0, 1.0), (0.0, 1.0)),
            SeriesLabelPosition::UpperRight
        );
    }
}
