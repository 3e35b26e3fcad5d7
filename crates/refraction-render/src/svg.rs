//! The diagram as SVG, for slides: the same [`Primitive`]s the PNG draws, as editable vector
//! shapes, and labels either outlined or as text ([`Labels`]).
//!
//! Fills and strokes become `<path>`s and `<circle>`s with the PNG's colours (opacity as
//! `fill-opacity`/`stroke-opacity`), widths, round caps and joins. Dashes are already cut into
//! pieces by the diagram ([`refraction_diagram::Dash`]), so the pieces of one dashed
//! line (consecutive polylines of one width and colour) become the subpaths of one `<path>`:
//! one object to recolour in a slide, with the PNG's dash pattern exactly. Labels become
//! `<text>` in the PNG's font (egui's Ubuntu Light) and size, one `<tspan>` per line at the
//! baselines the PNG uses, kerning and ligatures off because the PNG places glyphs by their
//! advance widths alone, and each line's `textLength` the width it has in that font, so that a
//! viewer without Ubuntu Light squeezes or spreads its own font to the same width and the text
//! stays inside its box; their background boxes are paths behind them.
//!
//! Not every viewer honours `textLength` (librsvg, and with it much slide software, does not):
//! there the text of a missing font runs out of its box. So a picture written to a file has
//! its labels outlined by default ([`Labels::Outlined`]: the glyphs as paths, in the PNG's
//! font, exactly where the PNG has them, each label a group whose `<title>` holds its words);
//! text that stays text ([`Labels::Text`]) is written on request, and inside a handout, whose
//! PDF embeds the font.

use glam::Vec2;
use skrifa::outline::OutlinePen;

use refraction_diagram::{Colour, Label, Primitive, Typeface};

use crate::{RenderError, check_size};

/// The font the labels ask for: the PNG's (Ubuntu Light, named both ways font tables name
/// it), then any sans-serif where it is not installed.
pub(crate) const FONT_FAMILY: &str = "'Ubuntu Light', Ubuntu, sans-serif";

/// The weight of Ubuntu Light.
const FONT_WEIGHT: u16 = 300;

/// Glyphs placed by their advance widths alone, as the PNG places them.
const TYPESETTING: &str = r#"font-kerning="none" font-variant-ligatures="none""#;

/// Appends one element and a line break.
fn element(out: &mut String, text: &str) {
    out.push_str(text);
    out.push('\n');
}

/// A coordinate or length with at most two decimals (a hundredth of a pixel), trimmed.
fn number(x: f32) -> String {
    trimmed(x, 2)
}

/// `attribute="#rrggbb"` and, when translucent, its opacity attribute.
fn paint(attribute: &str, colour: Colour) -> String {
    let mut out = format!(
        r##"{attribute}="#{:02x}{:02x}{:02x}""##,
        colour.r, colour.g, colour.b
    );
    if colour.a < 255 {
        let opacity = f32::from(colour.a) / 255.0;
        out.push_str(&format!(
            r#" {attribute}-opacity="{}""#,
            trimmed(opacity, 3)
        ));
    }
    out
}

/// `x` with at most `decimals` decimals, trailing zeros dropped, and no "-0".
fn trimmed(x: f32, decimals: usize) -> String {
    let text = format!("{x:.decimals$}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".to_owned()
    } else {
        text.to_owned()
    }
}

/// Text escaped for XML character data and attribute values. A character XML 1.0 cannot carry
/// (a control character other than tab, newline and carriage return, U+FFFE, U+FFFF), as a
/// scene's title or a medium's name may hold, becomes U+FFFD: the document stays well-formed.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for ch in text.chars() {
        match ch {
            '\t' | '\n' | '\r' => out.push(ch),
            '\u{0}'..='\u{1f}' | '\u{fffe}' | '\u{ffff}' => out.push('\u{fffd}'),
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            _ => out.push(ch),
        }
    }
    out
}

/// Appends `M x y L x y …` (and `Z` when closed) to `d`; false, appending nothing, for no
/// points or a non-finite one (which tiny-skia would not draw either).
fn subpath(d: &mut String, points: &[Vec2], closed: bool) -> bool {
    if points.is_empty() || !points.iter().all(|p| p.is_finite()) {
        return false;
    }
    for (i, p) in points.iter().enumerate() {
        let command = if i == 0 { 'M' } else { 'L' };
        if !d.is_empty() {
            d.push(' ');
        }
        d.push_str(&format!("{command}{} {}", number(p.x), number(p.y)));
    }
    if closed {
        d.push_str(" Z");
    }
    true
}

/// The stroke attributes of a polyline or an outline.
fn stroke(width: f32, colour: Colour) -> String {
    format!(
        r#"fill="none" {} stroke-width="{}" stroke-linecap="round" stroke-linejoin="round""#,
        paint("stroke", colour),
        number(width)
    )
}

/// How labels are written.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Labels {
    /// As paths: the glyphs outlined in the PNG's font, right in every viewer; the words in
    /// each label's `<title>`.
    #[default]
    Outlined,
    /// As `<text>`: editable, exact where Ubuntu Light is installed or `textLength` honoured.
    Text,
}

/// Writes outlines as SVG path data.
struct PathData(String);

impl PathData {
    fn point(&mut self, command: char, points: &[(f32, f32)]) {
        self.0.push(command);
        for (i, (x, y)) in points.iter().enumerate() {
            if i > 0 {
                self.0.push(' ');
            }
            self.0.push_str(&format!("{} {}", number(*x), number(*y)));
        }
    }
}

impl OutlinePen for PathData {
    fn move_to(&mut self, x: f32, y: f32) {
        self.point('M', &[(x, y)]);
    }

    fn line_to(&mut self, x: f32, y: f32) {
        self.point('L', &[(x, y)]);
    }

    fn quad_to(&mut self, cx0: f32, cy0: f32, x: f32, y: f32) {
        self.point('Q', &[(cx0, cy0), (x, y)]);
    }

    fn curve_to(&mut self, cx0: f32, cy0: f32, cx1: f32, cy1: f32, x: f32, y: f32) {
        self.point('C', &[(cx0, cy0), (cx1, cy1), (x, y)]);
    }

    fn close(&mut self) {
        self.0.push('Z');
    }
}

/// Writes one label's words as outlines: a group named by its words, one path of glyphs.
fn outlined(out: &mut String, face: &Typeface, label: &Label, top_left: Vec2) {
    let mut pen = PathData(String::new());
    let line_height = face.line_height(label.size);
    for (row, line) in label.text.lines().enumerate() {
        let at = top_left + Vec2::new(0.0, row as f32 * line_height);
        face.outline(line, at, label.size, &mut pen);
    }
    if pen.0.is_empty() {
        return;
    }
    out.push_str(&format!(
        "<g><title>{}</title><path d=\"{}\" {}/></g>\n",
        escape(&label.text),
        pen.0,
        paint("fill", label.colour)
    ));
}

/// Writes one label: its background box as a path, then its words (`labels` says how).
fn text(out: &mut String, face: &Typeface, label: &Label, labels: Labels) {
    let size = face.measure(&label.text, label.size);
    let top_left = label.at - size * Vec2::new(label.h.fraction(), label.v.fraction());
    if !top_left.is_finite() {
        return;
    }
    if let Some(background) = label.background {
        let pad = Vec2::splat(label.size * 0.2);
        let (min, max) = (top_left - pad, top_left + size + pad);
        let corners = [min, Vec2::new(max.x, min.y), max, Vec2::new(min.x, max.y)];
        let mut d = String::new();
        subpath(&mut d, &corners, true);
        element(
            out,
            &format!(r#"<path d="{d}" {}/>"#, paint("fill", background)),
        );
    }
    if labels == Labels::Outlined {
        outlined(out, face, label, top_left);
        return;
    }
    let font = format!(
        r#"font-family="{FONT_FAMILY}" font-weight="{FONT_WEIGHT}" font-size="{}""#,
        number(label.size)
    );
    out.push_str(&format!(
        r#"<text xml:space="preserve" {font} {TYPESETTING} {}>"#,
        paint("fill", label.colour)
    ));
    let (ascent, line_height) = (face.ascent(label.size), face.line_height(label.size));
    for (row, line) in label.text.lines().enumerate() {
        let baseline = top_left.y + ascent + row as f32 * line_height;
        // The line's width in the PNG's font: a viewer without that font fits its own to it,
        // so the text stays inside its box.
        let width = face.width(line, label.size);
        let fitted = if line.trim().is_empty() || width <= 0.0 {
            String::new()
        } else {
            format!(
                r#" textLength="{}" lengthAdjust="spacingAndGlyphs""#,
                number(width)
            )
        };
        out.push_str(&format!(
            r#"<tspan x="{}" y="{}"{fitted}>{}</tspan>"#,
            number(top_left.x),
            number(baseline),
            escape(line)
        ));
    }
    out.push_str("</text>\n");
}

/// Writes the element that starts at `primitives[start]` (a run of polylines of one width and
/// colour becomes one path); returns where the next element starts.
fn draw_group(
    out: &mut String,
    face: &Typeface,
    (primitives, labels): (&[Primitive], Labels),
    start: usize,
) -> usize {
    match &primitives[start] {
        Primitive::Polygon { points, colour } => {
            let mut d = String::new();
            if subpath(&mut d, points, true) {
                element(
                    out,
                    &format!(r#"<path d="{d}" {}/>"#, paint("fill", *colour)),
                );
            }
            start + 1
        }
        Primitive::Polyline { width, colour, .. } => {
            let mut d = String::new();
            let mut end = start;
            while let Some(Primitive::Polyline {
                points,
                width: w,
                colour: c,
            }) = primitives.get(end)
            {
                if w != width || c != colour {
                    break;
                }
                subpath(&mut d, points, false);
                end += 1;
            }
            if !d.is_empty() {
                element(
                    out,
                    &format!(r#"<path d="{d}" {}/>"#, stroke(*width, *colour)),
                );
            }
            end
        }
        Primitive::Disc {
            center,
            radius,
            fill,
            outline_width,
            outline,
        } => {
            if center.is_finite() && radius.is_finite() && *radius > 0.0 {
                element(
                    out,
                    &format!(
                        r#"<circle cx="{}" cy="{}" r="{}" {} {} stroke-width="{}"/>"#,
                        number(center.x),
                        number(center.y),
                        number(*radius),
                        paint("fill", *fill),
                        paint("stroke", *outline),
                        number(*outline_width)
                    ),
                );
            }
            start + 1
        }
        Primitive::Text(label) => {
            text(out, face, label, labels);
            start + 1
        }
    }
}

/// A `width` × `height` SVG document of `primitives`, in drawing order, as [`crate::pixmap`]
/// draws them into pixels, its labels written as `labels` says.
///
/// # Errors
/// A size outside [`crate::SIZE_LIMITS`].
pub fn document(
    width: u32,
    height: u32,
    labels: Labels,
    primitives: impl FnOnce(Vec2, &Typeface) -> Vec<Primitive>,
) -> Result<String, RenderError> {
    check_size(width, height)?;
    let face = Typeface::egui_default();
    let primitives = primitives(Vec2::new(width as f32, height as f32), &face);
    let mut out = format!(
        "{}width=\"{width}\" height=\"{height}\" viewBox=\"0 0 {width} {height}\">\n",
        document_header()
    );
    out.push_str(&elements(&face, &primitives, labels));
    out.push_str("</svg>\n");
    Ok(out)
}

/// How every SVG document [`document`] writes starts, up to its size: what tells a picture of
/// ours from someone else's file.
#[must_use]
pub fn document_header() -> &'static str {
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
}

/// The SVG elements of `primitives`, in drawing order, without a document around them: what
/// [`document`] holds, and what a handout's page nests at its diagram's place.
#[must_use]
pub fn elements(face: &Typeface, primitives: &[Primitive], labels: Labels) -> String {
    let mut out = String::new();
    let mut next = 0;
    while next < primitives.len() {
        next = draw_group(&mut out, face, (primitives, labels), next);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_diagram::Align;

    fn label(text: &str) -> Label {
        Label {
            text: text.to_owned(),
            at: Vec2::new(10.0, 20.0),
            h: Align::Start,
            v: Align::Start,
            size: 16.0,
            colour: Colour::hex(0x112233).with_alpha(128),
            background: Some(Colour::hex(0xffffff)),
        }
    }

    #[test]
    fn an_outlined_label_is_glyph_paths_inside_its_box_named_by_its_words() {
        // Issue 32: librsvg ignores textLength, so text in a missing font ran out of its box.
        let face = Typeface::egui_default();
        let mut out = String::new();
        let label = Label {
            text: "θi = 40°\nW & N".to_owned(),
            ..label("")
        };
        text(&mut out, &face, &label, Labels::Outlined);
        assert!(!out.contains("<text"), "{out}");
        assert!(out.contains("<title>θi = 40°\nW &amp; N</title>"), "{out}");
        let glyphs = out
            .split("<path d=\"")
            .nth(2)
            .unwrap()
            .split('"')
            .next()
            .unwrap();
        let numbers: Vec<f32> = glyphs
            .split(|c: char| c.is_ascii_alphabetic() || c == ' ')
            .filter_map(|n| n.parse().ok())
            .collect();
        let size = face.measure(&label.text, label.size);
        let (min, max) = (
            label.at - Vec2::splat(1.0),
            label.at + size + Vec2::splat(1.0),
        );
        for point in numbers.chunks(2) {
            let p = Vec2::new(point[0], point[1]);
            assert!(
                p.cmpge(min).all() && p.cmple(max).all(),
                "{p} outside {min}–{max}"
            );
        }
    }

    #[test]
    fn numbers_are_short_and_never_negative_zero() {
        assert_eq!(number(1.0), "1");
        assert_eq!(number(-0.001), "0");
        assert_eq!(number(2.345_67), "2.35");
        assert_eq!(number(-12.5), "-12.5");
    }

    #[test]
    fn the_pieces_of_one_dashed_line_are_one_path_and_text_is_escaped() {
        let colour = Colour::hex(0x0072b2);
        let piece = |x: f32| Primitive::Polyline {
            points: vec![Vec2::new(x, 0.0), Vec2::new(x + 5.0, 0.0)],
            width: 2.0,
            colour,
        };
        let doc = document(64, 64, Labels::Text, |_, _| {
            vec![
                piece(0.0),
                piece(10.0),
                piece(20.0),
                Primitive::Polyline {
                    points: vec![Vec2::ZERO, Vec2::new(f32::NAN, 1.0)],
                    width: 3.0,
                    colour,
                },
                Primitive::Text(label("a < b & \"c\"\nsecond")),
                Primitive::Text(label("\u{1b}[31mred\u{0}")),
            ]
        })
        .unwrap();
        assert_eq!(doc.matches("<path d=\"M0 0 L5 0 M10 0").count(), 1, "{doc}");
        assert!(!doc.contains("NaN"), "{doc}");
        assert!(
            doc.contains(">a &lt; b &amp; &quot;c&quot;</tspan><tspan"),
            "{doc}"
        );
        assert!(
            doc.contains(r##"fill="#112233" fill-opacity="0.502""##),
            "{doc}"
        );
        assert_eq!(doc.matches("<tspan").count(), 3);
        // XML 1.0 cannot carry ESC or NUL: they become U+FFFD.
        assert!(doc.contains(">\u{fffd}[31mred\u{fffd}<"), "{doc}");
        assert!(!doc.contains('\u{1b}') && !doc.contains('\u{0}'), "{doc}");
    }

    #[test]
    fn a_bad_size_is_refused_as_for_the_png() {
        let err = document(10, 64, Labels::Text, |_, _| Vec::new())
            .unwrap_err()
            .to_string();
        assert!(err.contains("10×64"), "{err}");
    }
}
