//! The PNG drawing backend: plotters' `BitMapBackend`, with its own text rendering.
//!
//! plotters 0.3.7 draws `ab_glyph` text by putting each glyph's bitmap at the pen position,
//! dropping the glyph's left side bearing, which spaces letters unevenly ("unt il"). This
//! wrapper forwards every drawing call to the bitmap backend except `draw_text`, which lays the
//! glyphs out itself with `ab_glyph` (advances, kerning, bearings, sub-pixel positions) and
//! blends their coverage. Text sizes for the layout still come from plotters, as for the SVG.

use std::sync::OnceLock;

use ab_glyph::{Font, FontRef, PxScale, ScaleFont, point};
use plotters::backend::{BitMapBackend, RGBPixel};
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
};

use super::plot::FONT_DEJAVU_SANS;

type Inner<'a> = BitMapBackend<'a, RGBPixel>;
type Error<'a> = DrawingErrorKind<<Inner<'a> as DrawingBackend>::ErrorType>;

/// The embedded font, parsed once.
pub(super) fn font() -> Option<&'static FontRef<'static>> {
    static FONT: OnceLock<Option<FontRef<'static>>> = OnceLock::new();
    FONT.get_or_init(|| FontRef::try_from_slice(FONT_DEJAVU_SANS).ok())
        .as_ref()
}

/// A bitmap backend whose text is drawn with [`font`].
pub(super) struct Raster<'a> {
    inner: Inner<'a>,
    font: &'static FontRef<'static>,
}

impl<'a> Raster<'a> {
    pub(super) fn new(inner: Inner<'a>, font: &'static FontRef<'static>) -> Self {
        Self { inner, font }
    }
}

impl<'a> DrawingBackend for Raster<'a> {
    type ErrorType = <Inner<'a> as DrawingBackend>::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        self.inner.get_size()
    }

    fn ensure_prepared(&mut self) -> Result<(), Error<'a>> {
        self.inner.ensure_prepared()
    }

    fn present(&mut self) -> Result<(), Error<'a>> {
        self.inner.present()
    }

    fn draw_pixel(&mut self, point: BackendCoord, color: BackendColor) -> Result<(), Error<'a>> {
        self.inner.draw_pixel(point, color)
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), Error<'a>> {
        self.inner.draw_line(from, to, style)
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), Error<'a>> {
        self.inner.draw_rect(upper_left, bottom_right, style, fill)
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), Error<'a>> {
        self.inner.draw_path(path, style)
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<(), Error<'a>> {
        self.inner.draw_circle(center, radius, style, fill)
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), Error<'a>> {
        self.inner.fill_polygon(vert, style)
    }

    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        size: (u32, u32),
        src: &[u8],
    ) -> Result<(), Error<'a>> {
        self.inner.blit_bitmap(pos, size, src)
    }

    fn draw_text<S: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &S,
        pos: BackendCoord,
    ) -> Result<(), Error<'a>> {
        let color = style.color();
        if color.alpha <= 0.0 || text.is_empty() {
            return Ok(());
        }
        let scale = PxScale::from(style.size() as f32);
        let font = self.font.as_scaled(scale);

        // Pen positions along a baseline at y = 0, y pointing down.
        let mut pen = Vec::with_capacity(text.len());
        let mut x = 0.0f32;
        let mut prev = None;
        for c in text.chars() {
            let id = font.glyph_id(c);
            if let Some(p) = prev {
                x += font.kern(p, id);
            }
            // A combining mark (the dots of θ̇, θ̈) is placed over the glyph before it.
            let mark = ('\u{300}'..='\u{36f}').contains(&c);
            pen.push((id, x, mark));
            x += font.h_advance(id);
            prev = Some(id);
        }
        let anchor = style.anchor();
        let dx = match anchor.h_pos {
            HPos::Left => 0.0,
            HPos::Center => -x / 2.0,
            HPos::Right => -x,
        };
        let dy = match anchor.v_pos {
            VPos::Top => font.ascent(),
            VPos::Center => (font.ascent() + font.descent()) / 2.0,
            VPos::Bottom => font.descent(),
        };

        let transform = style.transform();
        let (w, h) = self.get_size();
        let mut result = Ok(());
        // Bounds of the last base glyph, for the marks that follow it.
        let mut base: Option<ab_glyph::Rect> = None;
        for (id, x, mark) in pen {
            let glyph = id.with_scale_and_position(scale, point(x + dx, dy));
            let Some(mut outline) = self.font.outline_glyph(glyph) else {
                continue; // a space
            };
            if let (true, Some(b)) = (mark, base) {
                // Centred over the base, and above it by a sixteenth of the size when the base is
                // taller than the letters the mark is drawn for (θ rather than x).
                let m = outline.px_bounds();
                let shift_x = (b.min.x + b.max.x - m.min.x - m.max.x) / 2.0;
                let gap = scale.y / 16.0;
                let shift_y = (b.min.y - gap - m.max.y).min(0.0);
                let moved =
                    id.with_scale_and_position(scale, point(x + dx + shift_x, dy + shift_y));
                match self.font.outline_glyph(moved) {
                    Some(o) => outline = o,
                    None => continue,
                }
            } else if !mark {
                base = Some(outline.px_bounds());
            }
            let min = outline.px_bounds().min;
            outline.draw(|gx, gy, coverage| {
                if result.is_err() || coverage <= 0.0 {
                    return;
                }
                let (lx, ly) = (min.x as i32 + gx as i32, min.y as i32 + gy as i32);
                let (tx, ty) = transform.transform(lx, ly);
                let (px, py) = (pos.0 + tx, pos.1 + ty);
                if px >= 0 && py >= 0 && (px as u32) < w && (py as u32) < h {
                    let alpha = color.alpha * f64::from(coverage.min(1.0));
                    result = self
                        .inner
                        .draw_pixel((px, py), BackendColor { alpha, ..color });
                }
            });
            if result.is_err() {
                break;
            }
        }
        result
    }
}
