//! A handout as PDF: one landscape A4 page per lesson step, with its title, its diagram, its
//! question and its notes.
//!
//! Each page is an SVG document made of the same elements as the SVG export ([`svg`]): the
//! diagram's primitives nested at their place, the page's words as labels in the diagram's
//! font. svg2pdf turns each page into a PDF form (its labels as text, in the embedded font, so
//! that they can be selected, searched and extracted), and the PDF writer svg2pdf uses puts
//! the forms on pages. One drawing path, then: what the window shows, the SVG export and the
//! handout all come from [`Primitive`]s.

use std::collections::HashMap;
use std::sync::Arc;

use glam::Vec2;
use pdf_writer::{Content, Finish as _, Name, Pdf, Rect, Ref, TextStr};
use svg2pdf::usvg;

use refraction_diagram::Primitive;
use refraction_diagram::font::Typeface;
use refraction_diagram::geometry::Colour;
use refraction_diagram::placer::wrap;
use refraction_diagram::shapes::{Align, Label};

use crate::{RenderError, svg};

/// A page's size in PDF points: A4, landscape.
pub const PAGE: Vec2 = Vec2::new(842.0, 595.0);

/// The canvas the diagram is drawn on, in pixels (4:3, the page's diagram box scaled up, so
/// that its labels are the size the window gives them).
pub const CANVAS: Vec2 = Vec2::new(1040.0, 780.0);

/// The page's margin, in points.
const MARGIN: f32 = 36.0;

/// Where the diagram sits on the page: its top left corner and width (its height follows
/// [`CANVAS`]'s shape).
const DIAGRAM_AT: Vec2 = Vec2::new(MARGIN, 96.0);
const DIAGRAM_WIDTH: f32 = 500.0;

/// The sizes of the page's words, in points.
const HEADING_SIZE: f32 = 11.0;
const TITLE_SIZE: f32 = 22.0;
const TEXT_SIZE: f32 = 12.0;

/// The ink of the page's words.
const INK: Colour = Colour::hex(0x1a1a1a);

/// One page: the words, and the diagram's primitives for a canvas of [`CANVAS`].
pub struct Page {
    /// The line above the title: the deck and where the step is (`Snell's law · 2 / 5`).
    pub heading: String,
    /// The step's title.
    pub title: String,
    /// The question for the class, with its label, if any.
    pub question: Option<(String, String)>,
    /// The teacher's notes, with their label.
    pub notes: (String, String),
    /// The diagram, drawn for [`CANVAS`].
    pub diagram: Vec<Primitive>,
    /// The link that opens this step in the web build, if the page should carry it: printed
    /// with its QR code under the diagram.
    pub link: Option<String>,
}

/// The side of a step's QR code, in points (about 30 mm: a phone reads it from the desk).
const QR_SIDE: f32 = 84.0;

/// The size of the link's words beside its QR code, in points.
const LINK_SIZE: f32 = 8.0;

/// The QR code of the page's link under the diagram, with the link beside it; nothing
/// without a link (or for a link too long for a QR code, which then stands alone).
fn link_block(face: &Typeface, page: &Page) -> Vec<Primitive> {
    let Some(link) = &page.link else {
        return Vec::new();
    };
    let top = PAGE.y - MARGIN - QR_SIDE;
    let mut out = refraction_diagram::qr::Code::new(link)
        .map(|code| code.primitives(Vec2::new(MARGIN, top), QR_SIDE))
        .unwrap_or_default();
    let x = MARGIN + QR_SIDE + 10.0;
    let width = DIAGRAM_AT.x + DIAGRAM_WIDTH - x;
    let text = at_most(
        face,
        &wrap(face, link, LINK_SIZE, width),
        LINK_SIZE,
        width,
        6,
    );
    out.push(Primitive::Text(words(
        text,
        Vec2::new(x, top + 4.0),
        LINK_SIZE,
    )));
    out
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

/// The page's words as labels: the heading and title across the top, the question and the
/// notes in the column beside the diagram, wrapped to it.
fn page_words(face: &Typeface, page: &Page) -> Vec<Primitive> {
    let column_x = DIAGRAM_AT.x + DIAGRAM_WIDTH + 20.0;
    let column = PAGE.x - MARGIN - column_x;
    let title_width = PAGE.x - 2.0 * MARGIN;
    let title = wrap(face, &page.title, TITLE_SIZE, title_width);
    let mut labels = vec![
        words(
            page.heading.clone(),
            Vec2::new(MARGIN, MARGIN),
            HEADING_SIZE,
        ),
        words(
            at_most(face, &title, TITLE_SIZE, title_width, 2),
            Vec2::new(MARGIN, MARGIN + 18.0),
            TITLE_SIZE,
        ),
    ];
    let mut y = DIAGRAM_AT.y;
    let sections = page.question.iter().chain(core::iter::once(&page.notes));
    for (label, text) in sections.filter(|(_, text)| !text.trim().is_empty()) {
        labels.push(words(label.clone(), Vec2::new(column_x, y), TEXT_SIZE));
        y += face.line_height(TEXT_SIZE) * 1.3;
        let room = ((PAGE.y - MARGIN - y) / face.line_height(TEXT_SIZE)).max(1.0) as usize;
        let body = wrap(face, text, TEXT_SIZE, column);
        let body = at_most(face, &body, TEXT_SIZE, column, room);
        let lines = body.lines().count() as f32;
        labels.push(words(body, Vec2::new(column_x, y), TEXT_SIZE));
        y += face.line_height(TEXT_SIZE) * (lines + 1.0);
    }
    labels.into_iter().map(Primitive::Text).collect()
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

/// The page as an SVG document, [`PAGE`] points wide and high.
fn page_svg(face: &Typeface, page: &Page) -> String {
    let height = DIAGRAM_WIDTH * CANVAS.y / CANVAS.x;
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" \
         width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">\n\
         <rect width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>\n{words}\
         <svg x=\"{x}\" y=\"{y}\" width=\"{dw}\" height=\"{height}\" viewBox=\"0 0 {cw} {ch}\">\n\
         {diagram}</svg>\n{link}</svg>\n",
        w = PAGE.x,
        h = PAGE.y,
        words = svg::elements(face, &page_words(face, page)),
        x = DIAGRAM_AT.x,
        y = DIAGRAM_AT.y,
        dw = DIAGRAM_WIDTH,
        cw = CANVAS.x,
        ch = CANVAS.y,
        diagram = svg::elements(face, &page.diagram),
        link = svg::elements(face, &link_block(face, page)),
    )
}

/// The fonts the pages are set in: the diagram's own (egui's Ubuntu Light), for every family
/// the SVG names.
fn fonts() -> Arc<usvg::fontdb::Database> {
    let mut fonts = usvg::fontdb::Database::new();
    fonts.load_font_data(epaint_default_fonts::UBUNTU_LIGHT.to_vec());
    fonts.set_sans_serif_family("Ubuntu");
    Arc::new(fonts)
}

/// `pages` as one PDF document titled `title`.
///
/// # Errors
/// The embedded font cannot be read, or a page cannot be converted (a broken build: the pages
/// are the project's own SVG).
pub fn pdf(title: &str, pages: &[Page]) -> Result<Vec<u8>, RenderError> {
    let face = Typeface::egui_default()?;
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
        let tree = usvg::Tree::from_str(&page_svg(&face, page), &options)
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
        .title(TextStr(title))
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
        let face = Typeface::egui_default().unwrap();
        let word = "x".repeat(200_000);
        let page = Page {
            heading: "Deck · 1 / 1".to_owned(),
            title: word.clone(),
            question: None,
            notes: ("Notes".to_owned(), word),
            diagram: Vec::new(),
            link: None,
        };
        let labels = page_words(&face, &page);
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
                assert!(
                    face.width(line, label.size) <= PAGE.x - 2.0 * MARGIN,
                    "{line}"
                );
            }
        }
        let Primitive::Text(title) = &labels[1] else {
            panic!("the title is a label")
        };
        assert_eq!(title.text.lines().count(), 2);
        assert!(title.text.ends_with('…'));
    }
}
