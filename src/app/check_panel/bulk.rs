//! A whole log judged in the panel: pasted lines, or a log file opened or dropped on the
//! window, in an API's fields or any renderer's own (JSON Lines, CSV with a header, or
//! printf-style lines matching a pattern), read by the same [`Session`] as `check`. Above the
//! table of verdicts (one row per call; a click on a row opens that call in the panel) stand
//! the diagnosis of the whole log, the bug and its fix in the API's own code, and the failure
//! map, each line's error against θi per side; the failing lines can be saved as tests.

use egui::{CollapsingHeader, Grid, RichText, Sense, TextEdit, Ui};
use glam::Vec2;

use super::log_files::{LogFiles, MAX_JUDGED};
use super::refusal::Refusal;
use super::{JSON_LINE_START, field};
use crate::app::paint::{self, verdict_colour, window_palette};
use crate::app::typed::error_label;
use refraction_check::Summary;
use refraction_check::{
    Dialect, Format, Judgement, LineError, Options, Pattern, PatternError, Record, SAMPLED,
    SKIPPED, Session, Tally, fields,
};
use refraction_check::{Failing, MAX_TESTS};
use refraction_diagram::{Primitive, Typeface, failure_map};
use refraction_i18n::t;
use refraction_model::log_map::LinePoint;

/// The most characters the box takes (a paste beyond it is cut there): about 500 log lines.
pub(super) const MAX_PASTED_CHARS: usize = 65_536;

/// The most rows the table shows; the rest are judged and diagnosed but not listed.
pub(super) const MAX_LINES: usize = 500;

/// The most lines the failure map draws, and the most failing lines kept to save as tests.
const MAX_POINTS: usize = 20_000;

/// The longest explanation a row shows (the whole one is in its tooltip and in the panel).
const SHORT_EXPLANATION: usize = 90;

/// The most height the box of pasted lines takes before it scrolls, in points.
const BOX_HEIGHT: f32 = 160.0;

/// One line with a call, judged.
#[derive(Clone, Debug)]
struct Row {
    /// Its line number in the log, from 1.
    line: usize,
    /// The call read and its verdict, or why the line could not be judged.
    verdict: Result<(Record, Judgement), LineError>,
}

/// The verdicts on a log's lines and its diagnosis.
#[derive(Clone, Debug)]
pub(super) struct Table {
    /// How the lines were read: `JSON Lines`, `CSV` or `the pattern` (in the language's words).
    read_as: String,
    rows: Vec<Row>,
    tally: Tally,
    /// The diagnosis of every judged line.
    summary: Summary,
    /// Where each judged line lands on the failure map (the first [`MAX_POINTS`]).
    points: Vec<LinePoint>,
    /// The failing lines, to be saved as tests (the first [`MAX_TESTS`]).
    failing: Vec<Failing>,
    /// Judged lines the table does not list.
    not_listed: usize,
    /// Lines past [`MAX_JUDGED`], not judged at all.
    left_out: usize,
    /// The failure map as last drawn, for the canvas size and palette it was drawn for.
    map: Option<(Vec2, refraction_diagram::palette::Palette, Vec<Primitive>)>,
}

/// Where a log's lines come from and how to read them: the text, the pattern and the indices
/// of the object and its surroundings (for lines that log `entering`).
#[derive(Clone, Debug, Default, PartialEq)]
struct Reading {
    pattern: String,
    inside: String,
    outside: String,
}

/// The pasted text (or the file opened), how to read it, and the last table.
#[derive(Debug, Default)]
pub(super) struct Bulk {
    text: String,
    reading: Reading,
    files: LogFiles,
    table: Option<Result<Table, Refusal>>,
    selected: Option<usize>,
}

/// How the lines are written: by the pattern when one is given, else JSON Lines when the first
/// line is an object, else CSV with that line as its header.
fn how_written(
    dialect: Dialect,
    pattern: &str,
    text: &str,
) -> Result<(Format, String), PatternError> {
    if !pattern.trim().is_empty() {
        let pattern = Pattern::parse(dialect, pattern.trim())?;
        return Ok((Format::Pattern(pattern), t!("check-read-as-pattern")));
    }
    let first = text.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
    if first.trim_start().starts_with(JSON_LINE_START) {
        Ok((Format::JsonLines, t!("check-read-as-json-lines")))
    } else {
        Ok((Format::Csv, t!("check-read-as-csv")))
    }
}

/// A pattern that reads a log of `dialect`'s calls, as its hint shows it: `name={name}` for
/// each API's own arguments and result, or for any renderer's W, N, `entering` and T.
fn example_pattern(dialect: Dialect) -> String {
    let names = match dialect.api() {
        Some(api) => {
            let n = fields::names(api);
            [n.incident, n.normal, n.eta, n.result]
        }
        None => ["w", "n", "entering", "t_yours"],
    };
    let fields: Vec<String> = names.iter().map(|f| format!("{f}={{{f}}}")).collect();
    fields.join(" ")
}

/// An index typed into the field named `name`: empty for none, else a finite number above 0.
fn index(text: &str, name: &str) -> Result<Option<f64>, Refusal> {
    if text.trim().is_empty() {
        return Ok(None);
    }
    refraction_i18n::read_number(text)
        .filter(|x| x.is_finite() && *x > 0.0)
        .map(Some)
        .ok_or_else(|| Refusal::Index {
            field: name.to_owned(),
            text: text.to_owned(),
        })
}

impl Reading {
    /// The options of a run in `dialect` with the indices typed.
    fn options(&self, dialect: Dialect) -> Result<Options, Refusal> {
        Ok(Options {
            inside: index(&self.inside, &t!("logs-inside"))?,
            outside: index(&self.outside, &t!("logs-outside"))?,
            ..Options::new(dialect)
        })
    }

    /// The inside and outside indices' fields and the pattern's.
    fn show(&mut self, ui: &mut Ui) {
        ui.horizontal_wrapped(|ui| {
            field(ui, &t!("logs-inside"), &mut self.inside, 60.0);
            field(ui, &t!("logs-outside"), &mut self.outside, 60.0);
            ui.label(RichText::new(t!("logs-indices-hint")).small());
        });
        ui.horizontal_wrapped(|ui| {
            field(ui, &t!("check-pattern"), &mut self.pattern, 360.0);
        });
    }
}

/// Judges every non-empty line of `text` (up to [`MAX_JUDGED`]) in `dialect`.
fn judge(dialect: Dialect, reading: &Reading, text: &str) -> Result<Table, Refusal> {
    let options = reading.options(dialect)?;
    let (format, read_as) = how_written(dialect, &reading.pattern, text)?;
    let mut session = Session::new(options, format, false, false);
    let lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(i, l)| (i + 1, l));
    let (mut rows, mut points, mut failing) = (Vec::new(), Vec::new(), Vec::new());
    let (mut judged, mut not_listed, mut left_out) = (0, 0, 0);
    for (line, text) in lines {
        if judged == MAX_JUDGED {
            left_out += 1;
            continue;
        }
        judged += 1;
        let verdict = match session.judge_line(text.trim()) {
            Ok(None) => continue,
            Ok(Some(judged)) => judged,
            Err(e) => {
                rows.push(Row {
                    line,
                    verdict: Err(e),
                });
                continue;
            }
        };
        let (record, judgement) = verdict;
        if points.len() < MAX_POINTS {
            points.push(judgement.point());
        }
        if !judgement.ok() && failing.len() < MAX_TESTS {
            failing.push(Failing {
                line,
                record: record.clone(),
                judgement: judgement.clone(),
            });
        }
        if rows.len() < MAX_LINES {
            rows.push(Row {
                line,
                verdict: Ok((record, judgement)),
            });
        } else {
            not_listed += 1;
        }
    }
    session.end_of_input();
    Ok(Table {
        read_as,
        rows,
        tally: session.tally().clone(),
        summary: session.summary(),
        points,
        failing,
        not_listed,
        left_out,
        map: None,
    })
}

/// The tally in the language's words; the mistakes keep their codes, as the table shows them.
fn tally_words(tally: &Tally) -> String {
    let parts: Vec<String> = tally
        .counts()
        .map(|(kind, n)| {
            let kind = match kind {
                SKIPPED => t!("check-tally-skipped"),
                SAMPLED => t!("check-tally-sampled"),
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
    /// The line saying how the log was read, how many lines were judged and what they are.
    fn counts_line(&self) -> String {
        // Every line with a call, listed or not, read or not (a CSV header is none).
        let (read_as, count) = (&self.read_as, self.rows.len() + self.not_listed);
        let mut summary = t!("check-bulk-summary", read_as = read_as, count = count);
        let tally = tally_words(&self.tally);
        if !tally.is_empty() {
            summary.push_str(&format!(" ({tally})"));
        }
        if self.not_listed > 0 {
            let (count, first) = (self.not_listed, MAX_LINES);
            let not_listed = t!("logs-not-listed", count = count, first = first);
            summary.push_str(&format!("; {not_listed}"));
        }
        if self.left_out > 0 {
            let (count, first) = (self.left_out, MAX_JUDGED);
            let left_out = t!("check-bulk-left-out", count = count, first = first);
            summary.push_str(&format!("; {left_out}"));
        }
        summary
    }

    /// The diagnosis of the whole log: the verdict first, in the alarm colour when it names
    /// a mistake.
    fn diagnosis(&self, ui: &mut Ui) {
        ui.label(RichText::new(t!("logs-diagnosis-heading")).strong());
        let right = self
            .summary
            .diagnosis
            .first()
            .is_none_or(|f| f.code == "none");
        for (i, sentence) in self.summary.sentences().into_iter().enumerate() {
            let text = RichText::new(sentence);
            ui.label(if i == 0 {
                text.strong().color(verdict_colour(ui, right))
            } else {
                text
            });
        }
    }

    /// The failure map across the panel's width, drawn from the diagram's primitives (so it
    /// looks as an export would), with an accessible name that says what it shows.
    fn map(&mut self, ui: &mut Ui) {
        let width = ui.available_width().clamp(240.0, 900.0);
        let size = Vec2::new(width, failure_map::height(&self.points, width));
        let about = failure_map::describe(&self.points);
        let (_, painter, to_screen) = paint::figure(ui, size, Sense::hover(), &about);
        let palette = window_palette(ui);
        let fresh = self
            .map
            .as_ref()
            .is_some_and(|(s, p, _)| *s == size && *p == palette);
        if !fresh {
            let face = Typeface::egui_default();
            let drawn = failure_map::primitives(&self.points, size, &face, &palette);
            self.map = Some((size, palette, drawn));
        }
        if let Some((_, _, drawn)) = &self.map {
            paint::paint(&painter, &to_screen, drawn);
        }
    }

    /// The counts, the diagnosis and the rows as plain text, one row a line with tabs between
    /// its cells (a spreadsheet or a message takes it as it is), explanations whole.
    fn as_text(&self) -> String {
        let mut lines = vec![self.counts_line()];
        lines.extend(self.summary.sentences());
        let headings = [
            t!("check-column-line"),
            t!("check-column-ok"),
            t!("check-column-mistakes"),
            t!("check-column-explanation"),
        ];
        lines.push(headings.join("\t"));
        for row in &self.rows {
            let cells = match &row.verdict {
                Ok((_, judgement)) => {
                    let codes: Vec<&str> = judgement.mistakes().iter().map(|c| c.name()).collect();
                    let ok = if judgement.ok() { "✔" } else { "✖" };
                    [
                        ok.to_owned(),
                        codes.join(", "),
                        judgement.explanation().to_owned(),
                    ]
                }
                Err(e) => ["✖".to_owned(), t!("check-row-error"), e.to_string()],
            };
            lines.push(format!("{}\t{}", row.line, cells.join("\t")));
        }
        lines.join("\n")
    }

    /// The counts, the diagnosis, the map and the rows; the record of the row clicked, if one
    /// was.
    fn show(&mut self, ui: &mut Ui, selected: &mut Option<usize>) -> Option<Record> {
        ui.label(self.counts_line());
        self.diagnosis(ui);
        if ui
            .button(format!("📋 {}", t!("logs-copy-diagnosis")))
            .on_hover_text(t!("logs-copy-diagnosis-hover"))
            .clicked()
        {
            ui.ctx().copy_text(self.as_text());
        }
        if !self.points.is_empty() {
            ui.label(RichText::new(t!("logs-map-heading")).strong())
                .on_hover_text(t!("logs-map-hover"));
            self.map(ui);
        }
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
            Ok((_, judgement)) => {
                let ok = judgement.ok();
                let mark = if ok { "✔" } else { "✖" };
                ui.label(RichText::new(mark).color(verdict_colour(ui, ok)));
                let codes: Vec<&str> = judgement.mistakes().iter().map(|c| c.name()).collect();
                ui.label(codes.join(", "));
                let explanation = judgement.explanation();
                ui.label(shortened(explanation)).on_hover_text(explanation);
            }
            Err(e) => {
                ui.label(RichText::new("✖").color(verdict_colour(ui, false)));
                ui.label(t!("check-row-error"));
                error_label(ui, &shortened(&e.to_string()));
            }
        }
        clicked
    }
}

impl Bulk {
    /// Judges the log (the file opened, else the text) and keeps the table.
    fn check(&mut self, dialect: Dialect) {
        let text = self.files.opened_text().unwrap_or(&self.text);
        self.table = Some(judge(dialect, &self.reading, text));
        self.selected = None;
    }

    /// Opens the log file at `path` (dropped on the window): it is judged, and the section
    /// opened on it, when the section shows next.
    pub(super) fn open_file(&mut self, path: &std::path::Path) {
        self.files.open(path);
    }

    /// The text box, or the file judged instead of it.
    fn source(&mut self, ui: &mut Ui) {
        if self.files.opened_ui(ui) {
            return;
        }
        let name = ui.label(t!("check-log-lines"));
        // A pasted log is long: the box scrolls rather than push the table out of view.
        egui::ScrollArea::vertical()
            // untranslated: egui's id of the scroll area
            .id_salt("pasted log lines")
            .max_height(BOX_HEIGHT)
            .min_scrolled_height(BOX_HEIGHT * 0.75)
            .show(ui, |ui| {
                ui.add(
                    TextEdit::multiline(&mut self.text)
                        .char_limit(MAX_PASTED_CHARS)
                        .desired_rows(4)
                        .desired_width(f32::INFINITY)
                        .code_editor(),
                )
                .labelled_by(name.id);
            });
    }

    /// The section's body: the hint, the indices and the pattern, the box (or the file
    /// opened), *Check* and *Open log…*, the table and its dialogs; the record of the row
    /// clicked.
    fn body(&mut self, ui: &mut Ui, dialect: Dialect) -> Option<Record> {
        let (fields, example) = (fields::listed(dialect), example_pattern(dialect));
        let (c, n) = (MAX_PASTED_CHARS, MAX_LINES);
        let hint = t!(
            "logs-hint",
            fields = fields,
            example = example,
            characters = c,
            count = n
        );
        ui.label(hint);
        self.reading.show(ui);
        self.source(ui);
        let asked = ui
            .horizontal_wrapped(|ui| {
                let asked = ui.button(t!("check-lines-button")).clicked();
                self.files.open_button(ui);
                asked
            })
            .inner;
        if asked {
            self.check(dialect);
        }
        let options = self.options(dialect);
        let failing = match &self.table {
            Some(Ok(table)) => table.failing.as_slice(),
            _ => &[],
        };
        self.files.dialogs(ui, failing, &options);
        match &mut self.table {
            None => None,
            Some(Err(e)) => {
                error_label(ui, &e.to_string());
                None
            }
            Some(Ok(table)) => {
                self.files.save_buttons(ui, dialect, &table.failing);
                table.show(ui, &mut self.selected)
            }
        }
    }

    /// The collapsible section for logs in `dialect`; the record of the row clicked, to open.
    /// A log just opened (chosen in the dialog or dropped on the window) is judged, and the
    /// section opened on it.
    pub(super) fn show(&mut self, ui: &mut Ui, dialect: Dialect) -> Option<Record> {
        let fresh = self.files.take_fresh();
        if fresh {
            self.check(dialect);
        }
        CollapsingHeader::new(t!("check-paste-lines"))
            // untranslated: egui's id of the section, the same in every language
            .id_salt("paste log lines")
            .open(fresh.then_some(true))
            .show(ui, |ui| self.body(ui, dialect))
            .body_returned
            .flatten()
    }

    /// The options the log is read with (without the indices where they are not valid), for
    /// a row opened in the panel and the tests saved.
    #[must_use]
    pub(super) fn options(&self, dialect: Dialect) -> Options {
        self.reading
            .options(dialect)
            .unwrap_or_else(|_| Options::new(dialect))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_kernel::api::Api;

    fn reading(pattern: &str) -> Reading {
        Reading {
            pattern: pattern.to_owned(),
            ..Reading::default()
        }
    }

    #[test]
    fn the_diagnosis_and_the_table_copy_as_text_with_a_line_per_call() {
        let csv = "uv,n,etai_over_etat,refracted\n\
                   \"0.6, -0.8, 0\",\"0, 1, 0\",1.5,\"0.4, -0.916515, 0\"\n\
                   1,2\n";
        let table = judge(Dialect::Api(Api::Rtiow), &reading(""), csv).unwrap();
        let text = table.as_text();
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines[0].contains("CSV"), "{text}");
        for sentence in table.summary.sentences() {
            assert!(text.contains(&sentence), "{text}");
        }
        let rows: Vec<&&str> = lines.iter().filter(|l| l.starts_with(['2', '3'])).collect();
        assert_eq!(rows.len(), 2, "{text}");
        assert!(rows.iter().all(|r| r.split('\t').count() == 4), "{text}");
        assert!(rows[0].contains("not_the_api_result"), "{text}");
    }

    #[test]
    fn every_reader_gives_a_row_per_call_and_bad_lines_their_error() {
        let csv = "uv,n,etai_over_etat,refracted\n\
                   \"0.6, -0.8, 0\",\"0, 1, 0\",0.666667,\"0.4, -0.916515, 0\"\n\
                   1,2\n";
        let table = judge(Dialect::Api(Api::Rtiow), &reading(""), csv).unwrap();
        assert_eq!(table.read_as, "CSV (the first line is the header)");
        assert_eq!(table.rows.len(), 2);
        assert_eq!(table.rows[0].line, 2);
        assert!(table.rows[0].verdict.is_ok());
        let e = table.rows[1].verdict.as_ref().unwrap_err();
        let cells = refraction_check::CsvError::Cells {
            count: 2,
            columns: 4,
        };
        assert_eq!(*e, LineError::Csv(cells));
        assert!(
            e.to_string().contains("2 cells where the header has 4"),
            "{e}"
        );
        let log = "start\nLOG (0.6, -0.8, 0) | 0 1 0 | 0.666667 | (0.4, -0.916515, 0)\n";
        let pattern = "LOG {uv} | {n} | {etai_over_etat} | {refracted}";
        let table = judge(Dialect::Api(Api::Rtiow), &reading(pattern), log).unwrap();
        assert_eq!(table.rows.len(), 1);
        assert!(table.rows[0].verdict.as_ref().is_ok_and(|(_, j)| j.ok()));
        assert!(
            table.tally.summary().contains("1 skipped"),
            "{:?}",
            table.tally
        );
        // Right by the book's rules, but nothing says which side the ray comes from (issue 34).
        assert_eq!(table.summary.diagnosis[0].code, "unchecked");
        let e = judge(Dialect::Api(Api::Rtiow), &reading("LOG {I}"), log).unwrap_err();
        assert!(
            matches!(&e, Refusal::Pattern(PatternError::UnknownField { field, .. }) if field == "I"),
            "{e:?}"
        );
        assert!(e.to_string().contains("unknown field {I}"), "{e}");
    }

    #[test]
    fn lines_past_the_table_are_judged_and_diagnosed_but_not_listed() {
        let line = r#"{"I":[0,-1,0],"N":[0,1,0],"eta":1,"result":[0,-1,0]}"#;
        let text = vec![line; MAX_LINES + 3].join("\n");
        let table = judge(Dialect::Api(Api::Glsl), &reading(""), &text).unwrap();
        assert_eq!((table.rows.len(), table.not_listed), (MAX_LINES, 3));
        assert_eq!(table.summary.judged, MAX_LINES + 3);
        assert_eq!(table.points.len(), MAX_LINES + 3);
        assert!(
            table.counts_line().contains("3 more"),
            "{}",
            table.counts_line()
        );
        assert!(shortened(&"word ".repeat(40)).ends_with(" …"));
    }

    #[test]
    fn any_renderer_s_log_is_diagnosed_with_the_indices_typed() {
        // smallpt's REFR branch logging its own fields, nnt inverted on every hit.
        let d = glam::DVec3::new(0.6, -0.8, 0.0);
        let r = refraction_kernel::refract(&refraction_kernel::Incidence::<f64> {
            w: d,
            n: glam::DVec3::Y,
            mu_i: 1.5,
            mu_t: 1.0,
            convention: refraction_kernel::Convention::AlongRay,
        })
        .unwrap();
        let wrong = r.t().unwrap();
        let line = format!(
            "REFR d=({}, {}, 0) nl=(0, 1, 0) into=1 tdir=({}, {}, {})",
            d.x, d.y, wrong.x, wrong.y, wrong.z
        );
        let mut with_indices = Reading {
            pattern: "REFR d={w} nl={n} into={entering} tdir={t_yours}".to_owned(),
            inside: "1,5".to_owned(),
            outside: "1".to_owned(),
        };
        let table = judge(Dialect::Physics, &with_indices, &line).unwrap();
        assert_eq!(table.summary.judged, 1);
        assert_eq!(
            table.summary.diagnosis[0].code, "eta_inverted",
            "{:?}",
            table.summary
        );
        assert_eq!(table.failing.len(), 1);
        with_indices.inside = "-1".to_owned();
        let e = judge(Dialect::Physics, &with_indices, &line).unwrap_err();
        assert!(
            matches!(&e, Refusal::Index { text, .. } if text == "-1"),
            "{e:?}"
        );
        assert!(e.to_string().contains("-1"), "{e}");
    }
}
