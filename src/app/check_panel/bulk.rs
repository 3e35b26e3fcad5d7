//! Pasted log lines in bulk: JSON Lines, CSV with a header, or printf-style lines matching a
//! pattern, read by the same [`Session`] as `check --api`; a table of verdicts, one row per
//! call (bad lines show their error), and a click on a row opens that call in the panel.

use egui::{CollapsingHeader, Grid, RichText, TextEdit, Ui};

use super::{JSON_LINE_START, field};
use crate::app::paint::verdict_colour;
use crate::app::typed::error_label;
use refraction_i18n::t;
use refraction_kernel::api::Api;
use refraction_tools::api_check::{
    Diagnosis, Format, Options, Pattern, Record, SKIPPED, Session, Tally, check_record,
};

/// The most characters the box takes (a paste beyond it is cut there): about 500 log lines.
pub const MAX_PASTED_CHARS: usize = 65_536;

/// The most lines judged; the rest are left out, and the table says so.
pub const MAX_LINES: usize = 500;

/// The longest explanation a row shows (the whole one is in its tooltip and in the panel).
const SHORT_EXPLANATION: usize = 90;

/// One pasted line with a call, judged.
#[derive(Clone, Debug, PartialEq)]
struct Row {
    /// Its line number in the pasted text, from 1.
    line: usize,
    /// The call read and its verdict, or why the line could not be judged.
    verdict: Result<(Record, Diagnosis), String>,
}

/// The verdicts on the pasted lines.
#[derive(Clone, Debug, PartialEq)]
struct Table {
    /// How the lines were read: `JSON Lines`, `CSV` or `the pattern` (in the language's words).
    read_as: String,
    rows: Vec<Row>,
    tally: Tally,
    /// Lines beyond [`MAX_LINES`] that were not judged.
    left_out: usize,
}

/// The pasted text, the pattern and the last table.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Bulk {
    text: String,
    pattern: String,
    table: Option<Result<Table, String>>,
    selected: Option<usize>,
}

/// How the lines are written: by the pattern when one is given, else JSON Lines when the first
/// line is an object, else CSV with that line as its header.
fn how_written(api: Api, pattern: &str, text: &str) -> Result<(Format, String), String> {
    if !pattern.trim().is_empty() {
        let pattern = Pattern::parse(api, pattern.trim())?;
        return Ok((Format::Pattern(pattern), t!("check-read-as-pattern")));
    }
    let first = text.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
    if first.trim_start().starts_with(JSON_LINE_START) {
        Ok((Format::JsonLines, t!("check-read-as-json-lines")))
    } else {
        Ok((Format::Csv, t!("check-read-as-csv")))
    }
}

/// Judges every non-empty line of `text` (up to [`MAX_LINES`]) for `api`.
fn judge(api: Api, pattern: &str, text: &str) -> Result<Table, String> {
    let (format, read_as) = how_written(api, pattern, text)?;
    let options = Options::new(api);
    let mut session = Session::new(options, format, false, false);
    let lines: Vec<(usize, &str)> = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(i, l)| (i + 1, l))
        .collect();
    let left_out = lines.len().saturating_sub(MAX_LINES);
    let mut rows = Vec::new();
    for (line, text) in lines.into_iter().take(MAX_LINES) {
        let verdict = match session.record(text.trim()) {
            Ok(None) => continue,
            Ok(Some(record)) => {
                check_record(&record, &options).map(|(_, diagnosis)| (record, diagnosis))
            }
            Err(e) => Err(e),
        };
        rows.push(Row { line, verdict });
    }
    // The session counted the skipped lines; the verdicts are counted here, as `check` does.
    let mut tally = session.tally().clone();
    for row in &rows {
        match &row.verdict {
            Ok((_, diagnosis)) => tally.add_verdict(diagnosis),
            Err(_) => tally.add("unreadable"),
        }
    }
    Ok(Table {
        read_as,
        rows,
        tally,
        left_out,
    })
}

/// The tally in the language's words; the mistakes keep their codes, as the table shows them.
fn tally_words(tally: &Tally) -> String {
    let parts: Vec<String> = tally
        .counts()
        .map(|(kind, n)| {
            let kind = match kind {
                SKIPPED => t!("check-tally-skipped"),
                "unreadable" => t!("check-tally-unreadable"),
                "unexplained" => t!("check-tally-unexplained"),
                code => code.to_owned(),
            };
            format!("{n} {kind}")
        })
        .collect();
    parts.join(", ")
}

/// The first `SHORT_EXPLANATION` characters of `text`, cut at a word, with an ellipsis.
fn shortened(text: &str) -> String {
    if text.chars().count() <= SHORT_EXPLANATION {
        return text.to_owned();
    }
    let cut: String = text.chars().take(SHORT_EXPLANATION).collect();
    let at_word = cut.rfind(' ').map_or(cut.as_str(), |i| &cut[..i]);
    format!("{at_word} …")
}

impl Table {
    /// The summary line and the rows; the record of the row clicked, if one was.
    fn show(&self, ui: &mut Ui, selected: &mut Option<usize>) -> Option<Record> {
        let (read_as, count) = (&self.read_as, self.rows.len());
        let mut summary = t!("check-bulk-summary", read_as = read_as, count = count);
        let tally = tally_words(&self.tally);
        if !tally.is_empty() {
            summary.push_str(&format!(" ({tally})"));
        }
        if self.left_out > 0 {
            let (count, first) = (self.left_out, MAX_LINES);
            let left_out = t!("check-bulk-left-out", count = count, first = first);
            summary.push_str(&format!("; {left_out}"));
        }
        ui.label(summary);
        let mut opened = None;
        // No scroll area of its own: the tool's panel scrolls, and a nested one would keep a
        // row that is scrolled to (a click, the keyboard) out of view.
        // untranslated: egui's id of the grid
        Grid::new("pasted verdicts grid")
            .striped(true)
            .num_columns(4)
            .show(ui, |ui| {
                for heading in [
                    t!("check-column-line"),
                    t!("check-column-ok"),
                    t!("check-column-mistakes"),
                    t!("check-column-explanation"),
                ] {
                    ui.label(RichText::new(heading).strong());
                }
                ui.end_row();
                for (index, row) in self.rows.iter().enumerate() {
                    if row.show(ui, *selected == Some(index)) {
                        *selected = Some(index);
                        opened = row.verdict.as_ref().ok().map(|(r, _)| r.clone());
                    }
                    ui.end_row();
                }
            });
        opened
    }
}

impl Row {
    /// The row's cells; whether its line number was clicked.
    fn show(&self, ui: &mut Ui, selected: bool) -> bool {
        let clicked = ui
            .selectable_label(selected, t!("check-row-line", line = self.line.to_string()))
            .on_hover_text(t!("check-row-open-hover"))
            .clicked();
        match &self.verdict {
            Ok((_, d)) => {
                let mark = if d.ok { "✔" } else { "✖" };
                ui.label(RichText::new(mark).color(verdict_colour(ui, d.ok)));
                let codes: Vec<&str> = d.mistakes.iter().map(|c| c.name()).collect();
                ui.label(codes.join(", "));
                ui.label(shortened(&d.explanation))
                    .on_hover_text(&d.explanation);
            }
            Err(e) => {
                ui.label(RichText::new("✖").color(verdict_colour(ui, false)));
                ui.label(t!("check-row-error"));
                error_label(ui, &shortened(e));
            }
        }
        clicked
    }
}

impl Bulk {
    /// The collapsible section: the pattern, the box, the Check button and the table; the
    /// record of the row clicked, to open.
    pub fn show(&mut self, ui: &mut Ui, api: Api) -> Option<Record> {
        CollapsingHeader::new(t!("check-paste-lines"))
            // untranslated: egui's id of the section, the same in every language
            .id_salt("paste log lines")
            .show(ui, |ui| {
                let (a, c, n) = (api.name(), MAX_PASTED_CHARS, MAX_LINES);
                let hint = t!("check-paste-lines-hint", api = a, characters = c, count = n);
                ui.label(hint);
                ui.horizontal_wrapped(|ui| {
                    field(ui, &t!("check-pattern"), &mut self.pattern, 360.0);
                });
                let name = ui.label(t!("check-log-lines"));
                ui.add(
                    TextEdit::multiline(&mut self.text)
                        .char_limit(MAX_PASTED_CHARS)
                        .desired_rows(4)
                        .desired_width(f32::INFINITY)
                        .code_editor(),
                )
                .labelled_by(name.id);
                if ui.button(t!("check-lines-button")).clicked() {
                    self.table = Some(judge(api, &self.pattern, &self.text));
                    self.selected = None;
                }
                match &self.table {
                    None => None,
                    Some(Err(e)) => {
                        error_label(ui, e);
                        None
                    }
                    Some(Ok(table)) => table.show(ui, &mut self.selected),
                }
            })
            .body_returned
            .flatten()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_reader_gives_a_row_per_call_and_bad_lines_their_error() {
        let csv = "uv,n,etai_over_etat,refracted\n\
                   \"0.6, -0.8, 0\",\"0, 1, 0\",0.666667,\"0.4, -0.916515, 0\"\n\
                   1,2\n";
        let table = judge(Api::Rtiow, "", csv).unwrap();
        assert_eq!(table.read_as, "CSV (the first line is the header)");
        assert_eq!(table.rows.len(), 2);
        assert_eq!(table.rows[0].line, 2);
        assert!(table.rows[0].verdict.is_ok());
        let e = table.rows[1].verdict.as_ref().unwrap_err();
        assert!(e.contains("2 cells where the header has 4"), "{e}");
        let log = "start\nLOG (0.6, -0.8, 0) | 0 1 0 | 0.666667 | (0.4, -0.916515, 0)\n";
        let pattern = "LOG {uv} | {n} | {etai_over_etat} | {refracted}";
        let table = judge(Api::Rtiow, pattern, log).unwrap();
        assert_eq!(table.rows.len(), 1);
        assert!(table.rows[0].verdict.as_ref().is_ok_and(|(_, d)| d.ok));
        assert!(
            table.tally.summary().contains("1 skipped"),
            "{:?}",
            table.tally
        );
        let e = judge(Api::Rtiow, "LOG {I}", log).unwrap_err();
        assert!(e.contains("unknown field {I}"), "{e}");
    }

    #[test]
    fn lines_past_the_limit_are_left_out_and_counted() {
        let line = r#"{"I":[0,-1,0],"N":[0,1,0],"eta":1,"result":[0,-1,0]}"#;
        let text = vec![line; MAX_LINES + 3].join("\n");
        let table = judge(Api::Glsl, "", &text).unwrap();
        assert_eq!((table.rows.len(), table.left_out), (MAX_LINES, 3));
        assert!(shortened(&"word ".repeat(40)).ends_with(" …"));
    }
}
