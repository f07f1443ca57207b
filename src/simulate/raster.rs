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

/// DejaVu Sans 2.37 (Bitstream Vera licence with public-domain DejaVu changes; see
/// `assets/fonts/LICENSE-DejaVu.txt`), used for every text of the charts. It covers Latin,
/// Greek (θ, ω, Ω) and the usual symbols (·, ², −).
pub const FONT_DEJAVU_SANS: &[u8] = include_bytes!(concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/assets/fonts/DejaVuSans.ttf"
));

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

/// The text of the PNG plots, checked against the embedded font's own tables (read by hand
/// from `assets/fonts/DejaVuSans.ttf`: 2048 units per em, hhea ascent 1901 and descent −483,
/// no kerning between H and I) and against the layout's stated rules; and one small rendering
/// pinned.
#[cfg(test)]
mod tests {
    use super::*;
    use plotters::style::{FontTransform, IntoFont, TextStyle};
    use plotters_backend::text_anchor::Pos;

    const W: u32 = 64;
    const H: u32 = 40;

    /// A size at which one font unit is 0.01 px: (1901 + 483) / 100, the text height ab_glyph
    /// scales to ascent − descent.
    const SIZE: f64 = 23.84;

    /// H: advance 1540, ink from x = 201 to 1339 and from the baseline to y = 1493 (font units).
    const H_ADVANCE: f64 = 15.40;
    const H_INK: [f64; 2] = [2.01, 13.39];
    const H_TOP: f64 = 14.93;
    const ASCENT: f64 = 19.01;
    const DESCENT: f64 = 4.83;

    /// `text` drawn in black on white, the gray level of each pixel (row-major, W × H).
    fn render(text: &str, size: f64, pos: (i32, i32), anchor: Pos, turn: FontTransform) -> Vec<u8> {
        render_in((W, H), text, size, pos, anchor, turn)
    }

    fn render_in(
        (w, h): (u32, u32),
        text: &str,
        size: f64,
        pos: (i32, i32),
        anchor: Pos,
        turn: FontTransform,
    ) -> Vec<u8> {
        let mut rgb = vec![255u8; (w * h * 3) as usize];
        {
            let bitmap = BitMapBackend::<RGBPixel>::with_buffer_and_format(&mut rgb, (w, h))
                .expect("a buffer of the right size");
            let mut raster = Raster::new(bitmap, font().expect("the embedded font"));
            let style = TextStyle::from(("sans-serif", size).into_font())
                .pos(anchor)
                .transform(turn);
            raster.draw_text(text, &style, pos).expect("drawn");
            raster.present().expect("presented");
        }
        assert!(
            rgb.chunks(3).all(|p| p[0] == p[1] && p[1] == p[2]),
            "black on white is gray"
        );
        rgb.chunks(3).map(|p| p[0]).collect()
    }

    fn top_left() -> Pos {
        Pos::new(HPos::Left, VPos::Top)
    }

    /// The inked pixels' bounds: (first column, last column, first row, last row).
    fn ink(gray: &[u8], w: u32) -> Option<(i32, i32, i32, i32)> {
        let mut b: Option<(i32, i32, i32, i32)> = None;
        for (i, &g) in gray.iter().enumerate() {
            if g < 255 {
                let (x, y) = ((i as u32 % w) as i32, (i as u32 / w) as i32);
                b = Some(match b {
                    None => (x, x, y, y),
                    Some((x0, x1, y0, y1)) => (x0.min(x), x1.max(x), y0.min(y), y1.max(y)),
                });
            }
        }
        b
    }

    /// The inked pixels cover the continuous box [x0, x1] × [y0, y1] to within a pixel.
    #[track_caller]
    fn covers(gray: &[u8], [x0, x1, y0, y1]: [f64; 4]) {
        let (a, b, c, d) = ink(gray, W).expect("something is drawn");
        let near = |px: i32, edge: f64| (f64::from(px) - edge).abs() <= 1.0;
        assert!(
            near(a, x0.floor())
                && near(b, x1.ceil() - 1.0)
                && near(c, y0.floor())
                && near(d, y1.ceil() - 1.0),
            "ink in columns {a}..={b}, rows {c}..={d}; expected about [{x0}, {x1}] × [{y0}, {y1}]"
        );
    }

    #[test]
    fn nothing_is_drawn_for_an_empty_or_blank_text() {
        for text in ["", " ", "   "] {
            let gray = render(text, SIZE, (10, 5), top_left(), FontTransform::None);
            assert_eq!(ink(&gray, W), None, "{text:?}");
        }
    }

    #[test]
    fn a_letter_sits_where_the_font_puts_it() {
        // Anchored at its top left (10, 5): the baseline at 5 + ascent, the ink after the
        // left side bearing (which plotters' own text drawing dropped).
        let gray = render("H", SIZE, (10, 5), top_left(), FontTransform::None);
        let base = 5.0 + ASCENT;
        covers(
            &gray,
            [10.0 + H_INK[0], 10.0 + H_INK[1], base - H_TOP, base],
        );
        // The second letter one advance further.
        let gray = render("HH", SIZE, (10, 5), top_left(), FontTransform::None);
        covers(
            &gray,
            [
                10.0 + H_INK[0],
                10.0 + H_ADVANCE + H_INK[1],
                base - H_TOP,
                base,
            ],
        );
        // Anchored at its bottom right (60, 35): the advance ends at x = 60, the descent at y = 35.
        let anchor = Pos::new(HPos::Right, VPos::Bottom);
        let gray = render("H", SIZE, (60, 35), anchor, FontTransform::None);
        let (x, base) = (60.0 - H_ADVANCE, 35.0 - DESCENT);
        covers(&gray, [x + H_INK[0], x + H_INK[1], base - H_TOP, base]);
        // Turned a quarter (the y axis's label): local (x, y) goes to (y, −x).
        let gray = render("H", SIZE, (10, 35), top_left(), FontTransform::Rotate270);
        covers(
            &gray,
            [
                10.0 + ASCENT - H_TOP,
                10.0 + ASCENT,
                35.0 - H_INK[1],
                35.0 - H_INK[0],
            ],
        );
        // Another letter, other pixels.
        assert_ne!(
            gray,
            render("I", SIZE, (10, 35), top_left(), FontTransform::Rotate270)
        );
    }

    /// A combining dot (θ̇) is drawn above its base letter, clear of it, centred on it.
    #[test]
    fn a_dot_accent_sits_above_its_letter() {
        let theta = render("θ", SIZE, (10, 10), top_left(), FontTransform::None);
        let dotted = render("θ\u{307}", SIZE, (10, 10), top_left(), FontTransform::None);
        let (a, b, top, _) = ink(&theta, W).unwrap();
        let dot: Vec<u8> = theta
            .iter()
            .zip(&dotted)
            .map(|(&t, &d)| if t == d { 255 } else { d })
            .collect();
        let (c, d, _, bottom) = ink(&dot, W).expect("the dot is drawn");
        assert!(
            bottom < top - 1,
            "dot rows end at {bottom}, θ starts at {top}"
        );
        let centre = |x0: i32, x1: i32| f64::from(x0 + x1) / 2.0;
        assert!(
            (centre(a, b) - centre(c, d)).abs() <= 1.0,
            "θ in columns {a}..={b}, its dot in {c}..={d}"
        );
    }

    /// A label at the size of the plots, pinned row by row between bars: ' ' blank, '.' light,
    /// '+' mid, '#' dark. A failure shows the rows that changed, and the whole new rendering
    /// to pin if the change is intended. The text is anchored 3 px down: the dot over θ
    /// reaches above the font's ascent, up to the first row.
    #[test]
    fn a_label_renders_as_pinned() {
        const PINNED: [&str; 15] = [
            "|   .                                            |",
            "|   #.                                           |",
            "|   ..                                           |",
            "|                                                |",
            "|   ...      ..               ..          ..     |",
            "|  +#+#.     ++               .#   #.     .+     |",
            "| .#. ++    .#. .... ...    ...#  .#  ...  #.    |",
            "| .+  ++    .#  +##+.#+#+  +#++#  ++.##++  ++    |",
            "| +#####    ++  +#     .#..#. +#  #..#     ++    |",
            "| ++  .+    ++  ++  .####..#  .# .#  +#+.  .+    |",
            "| .#  ++    .+  ++  ++  #..#  .# ++   .+#  ++    |",
            "|  #+.#.    .#  ++  +#.+#. #+.## +. ....#  +.    |",
            "|  .++.      #. ..  .++++. .++.+.#  .+#+. .#.    |",
            "|            .+                 ..        ++     |",
            "|                                                |",
        ];
        let (w, h) = (48, PINNED.len() as u32);
        let gray = render_in(
            (w, h),
            "θ\u{307} (rad/s)",
            12.0,
            (1, 3),
            top_left(),
            FontTransform::None,
        );
        let art: Vec<String> = gray
            .chunks(w as usize)
            .map(|row| {
                let line: String = row
                    .iter()
                    .map(|&g| match g {
                        255 => ' ',
                        170..=254 => '.',
                        85..=169 => '+',
                        _ => '#',
                    })
                    .collect();
                format!("|{line}|")
            })
            .collect();
        let (pinned, art) = (PINNED.join("\n") + "\n", art.join("\n") + "\n");
        if art != pinned {
            let diff = similar::TextDiff::from_lines(&pinned, &art)
                .unified_diff()
                .context_radius(2)
                .header("pinned", "rendered")
                .to_string();
            panic!("the label renders differently; if intended, pin the new rows:\n{diff}\n{art}");
        }
    }
}
