//! A handout as PDF: one portrait A4 page per lesson step. The teacher's handout has the
//! step's title, its diagram with the answer, its question and the teacher's notes; the
//! student sheet (`Sheet::Students`) has the title, the diagram with the answer hidden, the
//! question and ruled lines to write the answer on, and no notes.
//!
//! Each page is an SVG document made of the same elements as the SVG export ([`svg`]): the
//! diagram's primitives nested at their place, the page's words as labels in the diagram's
//! font. svg2pdf turns each page into a PDF form (its labels as text, in the embedded font, so
//! that they can be selected, searched and extracted), and the PDF writer svg2pdf uses puts
//! the forms on pages. One drawing path, then: what the window shows, the SVG export and the
//! handout all come from [`Primitive`]s.
//!
//! The diagram is drawn for a canvas sized so that its smallest words
//! ([`refraction_diagram::SMALLEST_TEXT`] pixels) are [`SMALLEST_LABEL_PT`] points on
//! paper, and the teacher's page gives it the height its words leave, so that no page has an
//! empty third.

use std::collections::HashMap;
use std::sync::Arc;

use glam::Vec2;
use pdf_writer::{Content, Finish as _, Name, Pdf, Rect, Ref, TextStr};
use svg2pdf::usvg;

use refraction_diagram::{
    Align, Colour, Label, Primitive, SMALLEST_TEXT, Typeface, wrap_breaking_words as wrap,
};

use crate::{RenderError, svg};

/// A page's size in PDF points: A4, portrait.
pub(crate) const PAGE: Vec2 = Vec2::new(595.0, 842.0);

/// The page's margin, in points.
const MARGIN: f32 = 40.0;

/// The smallest words of a diagram on paper, in points: a 10-point box, so that the type is
/// 9.5 points and more where a label's `textLength` fits a viewer's glyphs to it (measured
/// 9.1 points at a 9.5-point box).
pub const SMALLEST_LABEL_PT: f32 = 10.0;

/// Points on paper per pixel of the diagram's canvas.
const PT_PER_PX: f32 = SMALLEST_LABEL_PT / SMALLEST_TEXT;

/// The sizes of the page's words, in points.
const HEADING_SIZE: f32 = 11.0;
const TITLE_SIZE: f32 = 20.0;
const TEXT_SIZE: f32 = 12.0;

/// The space between the lines students write on, in points.
const WRITING_LINE: f32 = 26.0;

/// The ink of the page's words, and the grey of the lines to write on.
const INK: Colour = Colour::hex(0x1a1a1a);
const RULE: Colour = Colour::hex(0xb0b0b0);

/// Which sheet a handout is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Sheet {
    /// The teacher's: the answers and the notes.
    #[default]
    Teacher,
    /// The class's: the questions and the diagrams without their answers, room to write, no
    /// notes.
    Students,
}

/// One page: the words, and the diagram drawn for a canvas of the size the page gives it.
/// Every text may be of any length and hold any character: each is drawn in time linear in
/// its length, cut where it runs past its room, its control characters as spaces.
pub struct Page<'a> {
    /// The deck's title (may be empty), on the line above the step's title, cut with `…` to
    /// leave room for `heading`.
    pub deck: String,
    /// Where the step is, after the deck's title (`2 / 5`), whole.
    pub heading: String,
    /// The step's title.
    pub title: String,
    /// The question for the class, with its label, if any.
    pub question: Option<(String, String)>,
    /// The teacher's notes, with their label (none on the student sheet).
    pub notes: Option<(String, String)>,
    /// Ruled lines under the question to write the answer on (the student sheet).
    pub writing_lines: bool,
    /// The diagram's primitives for a canvas of the size asked, in pixels.
    pub diagram: Box<dyn Fn(Vec2) -> Vec<Primitive> + 'a>,
    /// The link that opens this step in the web build, if the page should carry it: printed
    /// with its QR code at the page's foot.
    pub link: Option<String>,
}

/// The smallest side of a step's QR code, in points (about 30 mm: a phone reads it from the
/// desk).
const QR_SIDE: f32 = 84.0;

/// The smallest module of a QR code on paper, in points (0.53 mm; 3.1 pixels of a page
/// scanned or photographed at 150 dpi, where a phone's reader needs about 2): a longer link's
/// code grows rather than its modules shrink.
pub const QR_MODULE_PT: f32 = 1.5;

/// The largest side of a step's QR code, in points (about 56 mm, a third of the page's
/// height with its link): a link whose code would need more is refused.
pub const QR_MOST_SIDE: f32 = 160.0;

/// The size of the link's words beside its QR code, in points.
const LINK_SIZE: f32 = 8.0;

/// The gap between the QR code and the link's words, and above the foot, in points.
const FOOT_GAP: f32 = 10.0;

/// A page's foot: its link's QR code and the link itself, wrapped whole beside it.
struct Foot {
    /// The link's QR code.
    code: refraction_diagram::QrCode,
    /// The QR code's side, quiet zone included, in points.
    side: f32,
    /// The whole link, wrapped to the room beside the code.
    words: String,
    /// The foot's height, in points: the code's or the words', whichever is taller.
    height: f32,
}

impl Foot {
    /// The foot of a page with `link`: its code at [`QR_MODULE_PT`] or more a module.
    ///
    /// # Errors
    /// The link is too long for a QR code of at most [`QR_MOST_SIDE`] points.
    fn of(face: &Typeface, link: &str) -> Result<Self, RenderError> {
        let too_long = || RenderError::LinkTooLong {
            bytes: link.len(),
            most_mm: (QR_MOST_SIDE * MM_PER_PT).round() as u32,
        };
        let code = refraction_diagram::QrCode::new(link).map_err(|_too_long| too_long())?;
        let side = (code.side_in_modules() as f32 * QR_MODULE_PT).max(QR_SIDE);
        if side > QR_MOST_SIDE {
            return Err(too_long());
        }
        let width = COLUMN - side - FOOT_GAP;
        let words = wrap(face, &one_line(link), LINK_SIZE, width);
        let height = side.max(face.measure(&words, LINK_SIZE).y);
        Ok(Self {
            code,
            side,
            words,
            height,
        })
    }

    /// The room the foot takes at the bottom of the page, gap included.
    fn room(foot: Option<&Self>) -> f32 {
        foot.map_or(0.0, |f| f.height + FOOT_GAP + 2.0)
    }

    /// The QR code at the page's foot, with the link beside it.
    fn primitives(&self) -> Vec<Primitive> {
        let top = PAGE.y - MARGIN - self.height;
        let mut out = self.code.primitives(Vec2::new(MARGIN, top), self.side);
        let x = MARGIN + self.side + FOOT_GAP;
        out.push(Primitive::Text(words(
            self.words.clone(),
            Vec2::new(x, top + 4.0),
            LINK_SIZE,
        )));
        out
    }
}

/// Millimetres per point.
const MM_PER_PT: f32 = 25.4 / 72.0;

/// Whether `c` would not show as itself on a page or in a title bar: a control character, or
/// a mark that reorders the text around it (an override, an embedding, an isolate).
fn acts(c: char) -> bool {
    c.is_control() || matches!(c, '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
}

/// `text` with every character that would not show as itself ([`acts`]) as a space: one
/// line, for a title or a link.
fn one_line(text: &str) -> String {
    text.chars()
        .map(|c| if acts(c) { ' ' } else { c })
        .collect()
}

/// `text` as [`one_line`] gives it, but keeping its line breaks: a question or notes.
fn paragraphs(text: &str) -> String {
    text.lines().map(one_line).collect::<Vec<_>>().join("\n")
}

/// The first characters of the one line `text` that fit in `width` at `size`, ending in `…`
/// when some are left out. Linear in the characters kept (widths add up: the font is
/// measured without kerning).
fn fit(face: &Typeface, text: &str, size: f32, width: f32) -> String {
    if face.width(text, size) <= width {
        return text.to_owned();
    }
    let room = width - face.width("…", size);
    let (mut used, mut out) = (0.0, String::new());
    for c in text.chars() {
        used += face.width(c.encode_utf8(&mut [0; 4]), size);
        if used > room {
            break;
        }
        out.push(c);
    }
    format!("{}…", out.trim_end())
}

/// The line above the title: the deck's title, cut to leave room for where the step is.
fn heading(face: &Typeface, page: &Page<'_>) -> String {
    let place = one_line(&page.heading);
    let deck = one_line(&page.deck);
    if deck.trim().is_empty() {
        return place;
    }
    let after = format!(" · {place}");
    let room = COLUMN - face.width(&after, HEADING_SIZE);
    format!("{}{after}", fit(face, deck.trim(), HEADING_SIZE, room))
}

/// The most characters of a handout's title in its file's metadata: a title bar's width.
const MOST_TITLE_CHARS: usize = 200;

/// The deck's title as the PDF's metadata gives it: one line, its runs of spaces and
/// control characters as one space, at most [`MOST_TITLE_CHARS`] characters.
fn document_title(title: &str) -> String {
    let line = one_line(title);
    let words = line.split_whitespace().collect::<Vec<_>>().join(" ");
    if words.chars().count() <= MOST_TITLE_CHARS {
        return words;
    }
    let kept: String = words.chars().take(MOST_TITLE_CHARS - 1).collect();
    format!("{}…", kept.trim_end())
}

/// A label at `at` (its top left corner) in the page's ink.
fn words(text: String, at: Vec2, size: f32) -> Label {
    Label {
        text,
        at,
        h: Align::Start,
        v: Align::Start,
        size,
        colour: INK,
        background: None,
    }
}

/// The first `count` lines of `text` (wrapped to `width` at `size`), the last ending in `…`
/// when some are left out: what fits on the page of a text that runs past it.
fn at_most(face: &Typeface, text: &str, size: f32, width: f32, count: usize) -> String {
    let mut lines: Vec<&str> = text.lines().take(count + 1).collect();
    if lines.len() <= count {
        return lines.join("\n");
    }
    lines.truncate(count);
    let mut last = lines.pop().unwrap_or_default().to_owned();
    while !last.is_empty() && face.width(&last, size) + face.width("…", size) > width {
        last.pop();
    }
    last.push('…');
    lines.push(&last);
    lines.join("\n")
}

/// Where a page's parts go, in points.
struct PageLayout {
    /// The title's words, wrapped (at most two lines).
    title: String,
    /// The top of the diagram's box.
    diagram_top: f32,
    /// The diagram's box size.
    diagram: Vec2,
    /// The sections under the diagram: label, wrapped text.
    sections: Vec<(String, String)>,
}

/// The width of the page's text and diagram.
const COLUMN: f32 = PAGE.x - 2.0 * MARGIN;

impl PageLayout {
    fn of(face: &Typeface, page: &Page<'_>, foot: Option<&Foot>) -> Self {
        let line = |size: f32| face.line_height(size);
        let title = wrap(face, &one_line(&page.title), TITLE_SIZE, COLUMN);
        let title = at_most(face, &title, TITLE_SIZE, COLUMN, 2);
        let diagram_top = MARGIN
            + line(HEADING_SIZE) * 1.4
            + face.measure(&title, TITLE_SIZE).y
            + TITLE_SIZE * 0.6;
        // Each section: its label's line, its text, a blank line.
        let mut sections = Vec::new();
        for (label, text) in page.question.iter().chain(&page.notes) {
            if !text.trim().is_empty() {
                let text = paragraphs(text);
                sections.push((one_line(label), wrap(face, &text, TEXT_SIZE, COLUMN)));
            }
        }
        let text_height = |sections: &[(String, String)]| -> f32 {
            sections
                .iter()
                .map(|(_, body)| line(TEXT_SIZE) * (body.lines().count() as f32 + 2.3))
                .sum()
        };
        let bottom = PAGE.y - MARGIN - Foot::room(foot);
        // The student sheet keeps a 4:3 diagram and leaves the rest to write on; the teacher's
        // gives the diagram the height its words leave (from half its width to a bit more than it).
        let height = if page.writing_lines {
            COLUMN * 0.75
        } else {
            (bottom - diagram_top - TEXT_SIZE - text_height(&sections))
                .clamp(COLUMN * 0.5, COLUMN * 1.05)
        };
        // Words that would run past the page are cut at its foot, with "…".
        let room = bottom - (diagram_top + height + TEXT_SIZE);
        let mut left = (room / line(TEXT_SIZE)).max(0.0) as usize;
        for (_, body) in &mut sections {
            let lines = left.saturating_sub(2).max(1);
            *body = at_most(face, body, TEXT_SIZE, COLUMN, lines);
            left = left.saturating_sub(body.lines().count() + 2);
        }
        Self {
            title,
            diagram_top,
            diagram: Vec2::new(COLUMN, height),
            sections,
        }
    }

    /// The canvas the diagram is drawn on, in pixels: its box at [`PT_PER_PX`].
    fn canvas(&self) -> Vec2 {
        (self.diagram / PT_PER_PX).round()
    }
}

/// The page's words as labels (the heading and title across the top, the question and the
/// notes under the diagram) and, on the student sheet, the lines to write on.
fn page_words(
    face: &Typeface,
    page: &Page<'_>,
    layout: &PageLayout,
    foot: Option<&Foot>,
) -> Vec<Primitive> {
    let mut out = vec![
        Primitive::Text(words(
            heading(face, page),
            Vec2::new(MARGIN, MARGIN),
            HEADING_SIZE,
        )),
        Primitive::Text(words(
            layout.title.clone(),
            Vec2::new(MARGIN, MARGIN + face.line_height(HEADING_SIZE) * 1.4),
            TITLE_SIZE,
        )),
    ];
    let mut y = layout.diagram_top + layout.diagram.y + TEXT_SIZE;
    for (label, body) in &layout.sections {
        out.push(Primitive::Text(Label {
            colour: INK,
            ..words(label.clone(), Vec2::new(MARGIN, y), TEXT_SIZE)
        }));
        y += face.line_height(TEXT_SIZE) * 1.3;
        out.push(Primitive::Text(words(
            body.clone(),
            Vec2::new(MARGIN, y),
            TEXT_SIZE,
        )));
        y += face.line_height(TEXT_SIZE) * (body.lines().count() as f32 + 1.0);
    }
    if page.writing_lines {
        let mut line_y = y + WRITING_LINE;
        while line_y <= PAGE.y - MARGIN - Foot::room(foot) {
            out.push(Primitive::Polyline {
                points: vec![
                    Vec2::new(MARGIN, line_y),
                    Vec2::new(PAGE.x - MARGIN, line_y),
                ],
                width: 0.6,
                colour: RULE,
            });
            line_y += WRITING_LINE;
        }
    }
    out
}

/// The page as an SVG document, [`PAGE`] points wide and high.
///
/// # Errors
/// The page's link is too long for a QR code a phone reads on paper.
fn page_svg(face: &Typeface, page: &Page<'_>) -> Result<String, RenderError> {
    let foot = page
        .link
        .as_deref()
        .map(|link| Foot::of(face, link))
        .transpose()?;
    let foot = foot.as_ref();
    let layout = PageLayout::of(face, page, foot);
    let canvas = layout.canvas();
    let diagram = (page.diagram)(canvas);
    Ok(format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" \
         width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">\n\
         <rect width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>\n{words}\
         <svg x=\"{x}\" y=\"{y}\" width=\"{dw}\" height=\"{dh}\" viewBox=\"0 0 {cw} {ch}\">\n\
         {diagram}</svg>\n{link}</svg>\n",
        w = PAGE.x,
        h = PAGE.y,
        words = svg::elements(
            face,
            &page_words(face, page, &layout, foot),
            svg::Labels::Text
        ),
        x = MARGIN,
        y = layout.diagram_top,
        dw = layout.diagram.x,
        dh = layout.diagram.y,
        cw = canvas.x,
        ch = canvas.y,
        diagram = svg::elements(face, &diagram, svg::Labels::Text),
        link = svg::elements(
            face,
            &foot.map(Foot::primitives).unwrap_or_default(),
            svg::Labels::Text
        ),
    ))
}

/// The fonts the pages are set in: the diagram's own (egui's Ubuntu Light), for every family
/// the SVG names.
fn fonts() -> Arc<usvg::fontdb::Database> {
    let mut fonts = usvg::fontdb::Database::new();
    fonts.load_font_data(epaint_default_fonts::UBUNTU_LIGHT.to_vec());
    fonts.set_sans_serif_family("Ubuntu");
    Arc::new(fonts)
}

/// `pages` as one PDF document titled `title` (in its metadata: one line of at most
/// 200 characters, without control characters).
///
/// # Errors
/// A page's link is too long for a QR code that a phone reads on paper (its code would be
/// wider than [`QR_MOST_SIDE`] at [`QR_MODULE_PT`] a module); a page cannot be converted (a
/// broken build: the pages are the project's own SVG).
pub fn pdf(title: &str, pages: &[Page<'_>]) -> Result<Vec<u8>, RenderError> {
    let face = Typeface::egui_default();
    let mut options = usvg::Options {
        fontdb: fonts(),
        ..usvg::Options::default()
    };
    options.font_family = "Ubuntu".to_owned();
    let mut alloc = Ref::new(1);
    let (catalog, page_tree) = (alloc.bump(), alloc.bump());
    let mut pdf = Pdf::new();
    let mut kids = Vec::new();
    for page in pages {
        let tree = usvg::Tree::from_str(&page_svg(&face, page)?, &options)
            .map_err(|e| RenderError::Pdf(e.to_string()))?;
        let (chunk, form) = svg2pdf::to_chunk(&tree, svg2pdf::ConversionOptions::default())
            .map_err(|e| RenderError::Pdf(e.to_string()))?;
        let mut renumbered = HashMap::new();
        let chunk = chunk.renumber(|old| *renumbered.entry(old).or_insert_with(|| alloc.bump()));
        let form = renumbered.get(&form).copied().unwrap_or(form);
        let (id, contents) = (alloc.bump(), alloc.bump());
        let mut written = pdf.page(id);
        written
            .media_box(Rect::new(0.0, 0.0, PAGE.x, PAGE.y))
            .parent(page_tree)
            .contents(contents);
        written.resources().x_objects().pair(Name(b"Page"), form);
        written.finish();
        let mut content = Content::new();
        content
            .transform([PAGE.x, 0.0, 0.0, PAGE.y, 0.0, 0.0])
            .x_object(Name(b"Page"));
        pdf.stream(contents, &content.finish());
        pdf.extend(&chunk);
        kids.push(id);
    }
    pdf.catalog(catalog).pages(page_tree);
    pdf.pages(page_tree).count(kids.len() as i32).kids(kids);
    pdf.document_info(alloc.bump())
        .title(TextStr(&document_title(title)))
        // untranslated: the producer's name in the file's metadata.
        .producer(TextStr("refraction-explorer (svg2pdf)"));
    Ok(sorted_resources(pdf.finish()))
}

/// Whether `line` is one entry of a resource dictionary: `/Name N 0 R`.
fn is_resource_entry(line: &[u8]) -> bool {
    let line = line.trim_ascii();
    let Some(rest) = line.strip_prefix(b"/") else {
        return false;
    };
    let mut words = rest.split(|&b| b == b' ');
    let name = words.next().unwrap_or_default();
    let number = words.next().unwrap_or_default();
    !name.is_empty()
        && name.iter().all(u8::is_ascii_alphanumeric)
        && !number.is_empty()
        && number.iter().all(u8::is_ascii_digit)
        && words.next() == Some(b"0")
        && words.next() == Some(b"R")
        && words.next().is_none()
}

/// `pdf` with the entries of each resource dictionary in order: svg2pdf writes them from a
/// hash map, so that two runs would order them differently. Each run of `/Name N 0 R` lines
/// outside the streams is sorted where it stands, so every object keeps its length and place
/// and the cross-reference table stays right: the same handout gives the same bytes.
fn sorted_resources(mut pdf: Vec<u8>) -> Vec<u8> {
    let mut lines: Vec<core::ops::Range<usize>> = Vec::new();
    let mut start = 0;
    let mut in_stream = false;
    while start < pdf.len() {
        let end = pdf[start..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(pdf.len(), |i| start + i + 1);
        let line = &pdf[start..end];
        let trimmed = line.trim_ascii();
        if in_stream {
            in_stream = trimmed != b"endstream";
        } else if trimmed == b"stream" {
            in_stream = true;
        }
        if !in_stream && is_resource_entry(line) && line.ends_with(b"\n") {
            lines.push(start..end);
        } else {
            sort_run(&mut pdf, &mut lines);
        }
        start = end;
    }
    sort_run(&mut pdf, &mut lines);
    pdf
}

/// Sorts the consecutive lines `run` of `pdf` in place, and empties `run`.
fn sort_run(pdf: &mut [u8], run: &mut Vec<core::ops::Range<usize>>) {
    if let (Some(first), Some(last)) = (run.first(), run.last()) {
        let span = first.start..last.end;
        let mut entries: Vec<Vec<u8>> = run.iter().map(|r| pdf[r.clone()].to_vec()).collect();
        entries.sort();
        pdf[span].copy_from_slice(&entries.concat());
    }
    run.clear();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resource_entries_are_sorted_in_place_and_streams_left_alone() {
        let pdf = b"<<\n  /ExtGState <<\n    /gs14 17 0 R\n    /gs1 4 0 R\n  >>\n>>\nstream\n/b 2 0 R\n/a 1 0 R\nendstream\n";
        let sorted = sorted_resources(pdf.to_vec());
        assert_eq!(sorted.len(), pdf.len());
        assert_eq!(
            String::from_utf8(sorted).unwrap(),
            "<<\n  /ExtGState <<\n    /gs1 4 0 R\n    /gs14 17 0 R\n  >>\n>>\nstream\n/b 2 0 R\n/a 1 0 R\nendstream\n"
        );
        assert!(!is_resource_entry(b"/Type /Page"));
    }

    #[test]
    fn one_long_word_is_broken_into_lines_and_cut_at_the_page_s_foot() {
        // Issue 31: one 200,000-character word held a handout for 85 s.
        let face = Typeface::egui_default();
        let word = "x".repeat(200_000);
        let page = Page {
            deck: "Deck".to_owned(),
            heading: "1 / 1".to_owned(),
            title: word.clone(),
            question: None,
            notes: Some(("Notes".to_owned(), word)),
            writing_lines: false,
            diagram: Box::new(|_| Vec::new()),
            link: None,
        };
        let layout = PageLayout::of(&face, &page, None);
        let labels = page_words(&face, &page, &layout, None);
        for label in &labels {
            let Primitive::Text(label) = label else {
                panic!("words are labels")
            };
            let bottom = label.at.y + face.measure(&label.text, label.size).y;
            assert!(
                bottom <= PAGE.y,
                "{} lines run past the page",
                label.text.lines().count()
            );
            for line in label.text.lines() {
                assert!(face.width(line, label.size) <= COLUMN, "{line}");
            }
        }
        let Primitive::Text(title) = &labels[1] else {
            panic!("the title is a label")
        };
        assert_eq!(title.text.lines().count(), 2);
        assert!(title.text.ends_with('…'));
    }

    #[test]
    fn the_diagram_fills_the_page_and_its_words_are_nine_points_or_more() {
        let face = Typeface::egui_default();
        let page = |notes: &str, writing_lines: bool| Page {
            deck: "Deck".to_owned(),
            heading: "1 / 2".to_owned(),
            title: "A step".to_owned(),
            question: Some(("Question".to_owned(), "Which way does it bend?".to_owned())),
            notes: (!writing_lines).then(|| ("Notes".to_owned(), notes.to_owned())),
            writing_lines,
            diagram: Box::new(|_| Vec::new()),
            link: None,
        };
        let teacher = PageLayout::of(&face, &page("Short notes.", false), None);
        let last_word = teacher.diagram_top + teacher.diagram.y + TEXT_SIZE * 8.0;
        assert!(
            PAGE.y - MARGIN - last_word < PAGE.y / 4.0,
            "no empty lower quarter"
        );
        assert!(SMALLEST_TEXT * teacher.diagram.x / teacher.canvas().x >= 9.0);
        let students = page("", true);
        let sheet = PageLayout::of(&face, &students, None);
        let rules = page_words(&face, &students, &sheet, None)
            .iter()
            .filter(|p| matches!(p, Primitive::Polyline { .. }))
            .count();
        assert!(rules >= 6, "{rules} lines to write on");
    }

    /// A page of `deck`'s step 1 of 1 titled `title`, with `link` at its foot.
    fn page_with(deck: &str, title: &str, link: Option<&str>) -> Page<'static> {
        Page {
            deck: deck.to_owned(),
            heading: "1 / 1".to_owned(),
            title: title.to_owned(),
            question: Some(("Question".to_owned(), "Why\u{7}?\nSay.".to_owned())),
            notes: None,
            writing_lines: true,
            diagram: Box::new(|_| Vec::new()),
            link: link.map(str::to_owned),
        }
    }

    /// The texts of `page`'s words, in order.
    fn texts(face: &Typeface, page: &Page<'_>) -> Vec<String> {
        let foot = page.link.as_deref().map(|l| Foot::of(face, l).unwrap());
        let layout = PageLayout::of(face, page, foot.as_ref());
        page_words(face, page, &layout, foot.as_ref())
            .into_iter()
            .filter_map(|p| match p {
                Primitive::Text(label) => Some(label.text),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn a_deck_s_long_title_is_cut_to_one_line_that_keeps_the_step_s_place() {
        // Issue 40: 200,000 characters of words in `[deck]`'s title held a handout for 73 s
        // (the PDF converter lays out one line in time quadratic in its length).
        let face = Typeface::egui_default();
        let words = "light bends toward the normal ".repeat(7_000);
        let heading = &texts(&face, &page_with(&words, "A step", None))[0];
        assert!(heading.ends_with("… · 1 / 1"), "{heading}");
        assert!(!heading.contains('\n'));
        assert!(face.width(heading, HEADING_SIZE) <= COLUMN, "{heading}");
        let short = &texts(&face, &page_with("Snell's law", "A step", None))[0];
        assert_eq!(short, "Snell's law · 1 / 1");
        let bare = &texts(&face, &page_with("", "A step", None))[0];
        assert_eq!(bare, "1 / 1");
    }

    #[test]
    fn control_characters_and_reordering_marks_show_as_spaces_on_the_page_and_in_the_title() {
        let face = Typeface::egui_default();
        let page = page_with("A\u{1}B\u{1b}[31m\u{202e}C\nD", "One\u{7}\ttwo", None);
        let texts = texts(&face, &page);
        assert_eq!(texts[0], "A B [31m C D · 1 / 1");
        assert_eq!(texts[1], "One  two");
        assert!(texts.iter().any(|t| t == "Why ?\nSay."), "{texts:?}");
        for text in &texts {
            assert!(!text.chars().any(|c| acts(c) && c != '\n'), "{text:?}");
        }
        assert_eq!(
            document_title("My\u{0}deck\n\u{202e}one \u{7} two\u{1b}"),
            "My deck one two"
        );
        let long = document_title(&"word ".repeat(1_000));
        assert_eq!(long.chars().count(), MOST_TITLE_CHARS);
        assert!(long.ends_with('…'), "{long}");
        let one_word = document_title(&"x".repeat(1_000));
        assert!(one_word.chars().count() <= MOST_TITLE_CHARS, "{one_word}");
    }

    #[test]
    fn a_link_is_printed_whole_and_its_code_keeps_modules_a_phone_reads() {
        // Issue 40: a long link's code shrank to 0.5 pt a module (read only at 600 dpi) and
        // the printed link was cut with "…".
        let face = Typeface::egui_default();
        let base = "https://school.example/a-long-folder-name/explorer/index.html";
        for length in [80, 230, 500, 640] {
            let link = format!("{base}#state={}", "%22".repeat((length - base.len()) / 3));
            let foot = Foot::of(&face, &link).unwrap();
            let module = foot.side / foot.code.side_in_modules() as f32;
            assert!(
                module >= QR_MODULE_PT,
                "{length} bytes: {module} pt a module"
            );
            assert!(foot.side <= QR_MOST_SIDE);
            assert_eq!(foot.words.replace('\n', ""), link, "printed whole");
            for line in foot.words.lines() {
                assert!(face.width(line, LINK_SIZE) <= COLUMN - foot.side - FOOT_GAP);
            }
            let page = page_with("Deck", "A step", Some(&link));
            let layout = PageLayout::of(&face, &page, Some(&foot));
            assert!(
                layout.diagram_top + layout.diagram.y < PAGE.y - MARGIN - foot.height,
                "{length} bytes: the diagram stays clear of the foot"
            );
        }
        let long = format!("{base}#state={}", "x".repeat(2_000));
        let refused = Foot::of(&face, &long).err().unwrap().to_string();
        assert!(
            refused.contains(&format!("{} bytes", long.len())) && refused.contains("56 mm"),
            "{refused}"
        );
        let page = page_with("Deck", "A step", Some(&long));
        assert!(matches!(
            pdf("Deck", &[page]),
            Err(RenderError::LinkTooLong { .. })
        ));
    }
}
