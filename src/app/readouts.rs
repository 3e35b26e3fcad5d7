//! The right panel: the discriminant k, the quadratic in b, the candidates table, the paper's
//! equations with numbers, and the kernel's warnings. Every number is the kernel's.

use egui::{Grid, RichText, Sense, Stroke, Ui, Vec2};
use refraction_i18n::t;

use super::paint::color;
use refraction_diagram::Quadratic;
use refraction_diagram::equations;
use refraction_diagram::numbers::{number, significant_apart, vector};
use refraction_diagram::palette::Palette;
use refraction_diagram::{CandidateRow, candidate_rows};
use refraction_kernel::{Refraction, VectorName, Warning};

/// The mark for a passed (✔) or failed (✖) check.
fn mark(passed: bool) -> &'static str {
    if passed { "✔" } else { "✖" }
}

/// k as a number and as a bar signed about zero (k ranges over 1 − μ² … 1; the bar shows
/// −1 … 1 and saturates beyond).
fn discriminant(ui: &mut Ui, r: &Refraction<f64>, palette: &Palette) {
    let k = number(r.k, 4);
    ui.label(if r.k < 0.0 {
        t!("readouts-discriminant-tir", k = k)
    } else {
        t!("readouts-discriminant", k = k)
    });
    let (response, painter) =
        ui.allocate_painter(Vec2::new(ui.available_width(), 18.0), Sense::hover());
    let rect = response.rect;
    painter.rect_filled(rect, 2.0, color(palette.calm));
    let zero = rect.center().x;
    let end = zero + (r.k.clamp(-1.0, 1.0) as f32) * rect.width() * 0.5;
    let fill = if r.k < 0.0 { palette.alarm } else { palette.n };
    let bar = egui::Rect::from_x_y_ranges(zero.min(end)..=zero.max(end), rect.y_range());
    painter.rect_filled(bar, 0.0, color(fill));
    painter.vline(zero, rect.y_range(), Stroke::new(2.0, color(palette.ink)));
}

/// The paper's eq. 20 in b, with the kernel's two roots. The plot is fitted afresh every
/// frame to both roots (or the vertex, on total internal reflection).
fn quadratic(ui: &mut Ui, r: &Refraction<f64>, palette: &Palette) {
    let q = Quadratic::of(r);
    ui.label(t!(
        "readouts-quadratic",
        section = r.convention.section().to_string(),
        a = number(q.a, 3),
        wn = number(q.wn, 3)
    ));
    let caption = if q.roots.is_empty() {
        t!("readouts-no-roots")
    } else {
        let values: Vec<String> = q.roots.iter().map(|b| number(*b, 4)).collect();
        let separator = refraction_i18n::locale().list_separator();
        t!("readouts-roots", roots = values.join(separator))
    };
    // The parabola as the diagram crate draws it, across the panel.
    let size = glam::Vec2::new(ui.available_width(), 150.0);
    let text = egui::TextStyle::Body.resolve(ui.style()).size.max(13.0);
    let (_, painter, to_screen) = super::paint::figure(ui, size, egui::Sense::hover(), &caption);
    let drawn = refraction_diagram::quadratic_plot(&q, size, text, palette);
    super::paint::paint(&painter, &to_screen, &drawn);
    ui.label(caption);
}

/// The narrowest panel, in body-text heights, that shows the candidates as a table; a
/// narrower one (presentation) shows each candidate as a short block instead of cutting the
/// table off.
const TABLE_WIDTH_IN_LINES: f32 = 30.0;

/// The names of the four checks, in the order of [`passes`].
fn checks() -> [String; 4] {
    [
        "|T|=1".to_owned(),
        t!("readouts-check-snell"),
        t!("readouts-check-side"),
        t!("readouts-check-bend"),
    ]
}

/// Whether `row` passes each of [`checks`].
fn passes(row: &CandidateRow) -> [bool; 4] {
    [
        row.unit,
        row.squared_snell,
        row.correct_side,
        row.tangential,
    ]
}

/// The candidate's role, strong in T's colour for the chosen one, its rule on hover.
fn role_label(ui: &mut Ui, row: &CandidateRow, palette: &Palette) {
    let role = RichText::new(&row.role);
    let role = if row.rule.is_none() {
        role.strong().color(color(palette.t))
    } else {
        role
    };
    let response = ui.label(role);
    if let Some(rule) = &row.rule {
        response.on_hover_text(rule);
    }
}

/// A mark per check, each followed by its name when `named`.
fn marks(ui: &mut Ui, row: &CandidateRow, palette: &Palette, named: bool) {
    for (passed, name) in passes(row).into_iter().zip(checks()) {
        let ink = if passed { palette.n } else { palette.alarm };
        ui.label(RichText::new(mark(passed)).color(color(palette.text_shade(ink))));
        if named {
            ui.label(name);
        }
    }
}

/// The candidates as a table: one row each, a column per coefficient and check.
fn candidate_table(ui: &mut Ui, rows: &[CandidateRow], palette: &Palette) {
    Grid::new("candidates")
        .striped(true)
        .spacing([6.0, 3.0])
        .show(ui, |ui| {
            let names = ["a", "b", "T"].map(str::to_owned);
            let headings = core::iter::once(t!("readouts-candidate"))
                .chain(names)
                .chain(checks());
            for heading in headings {
                ui.label(RichText::new(heading).strong());
            }
            ui.end_row();
            for row in rows {
                role_label(ui, row, palette);
                ui.label(number(row.a, 3));
                ui.label(number(row.b, 3));
                ui.label(RichText::new(vector(row.t, 2)).monospace());
                marks(ui, row, palette, false);
                ui.end_row();
            }
        });
}

/// The candidates as short blocks, for a panel too narrow for the table.
fn candidate_blocks(ui: &mut Ui, rows: &[CandidateRow], palette: &Palette) {
    for row in rows {
        ui.horizontal_wrapped(|ui| {
            role_label(ui, row, palette);
            marks(ui, row, palette, true);
        });
        ui.label(
            RichText::new(format!(
                "a = {}  b = {}  T = {}",
                number(row.a, 3),
                number(row.b, 3),
                vector(row.t, 2)
            ))
            .monospace(),
        );
    }
}

/// The four candidates with their checks.
fn candidates(ui: &mut Ui, r: &Refraction<f64>, palette: &Palette) {
    let rows = candidate_rows(r);
    if rows.is_empty() {
        let alarm = palette.text_shade(palette.alarm);
        ui.label(RichText::new(t!("readouts-no-candidates")).color(color(alarm)));
        return;
    }
    let line = ui.text_style_height(&egui::TextStyle::Body);
    if ui.available_width() >= line * TABLE_WIDTH_IN_LINES {
        candidate_table(ui, &rows, palette);
    } else {
        candidate_blocks(ui, &rows, palette);
    }
    ui.label(t!("readouts-candidates-note"));
}

/// The paper's key equations with the numbers substituted.
fn source_equations(ui: &mut Ui, r: &Refraction<f64>) {
    for eq in equations(r) {
        ui.label(RichText::new(format!("({})  {}", eq.number, eq.formula)).strong());
        ui.label(RichText::new(eq.substituted).monospace());
    }
}

/// The kernel's warnings, or a note that there are none.
fn warnings(ui: &mut Ui, r: &Refraction<f64>, palette: &Palette) {
    if r.warnings.is_empty() {
        ui.label(t!("readouts-no-warnings"));
    }
    for warning in &r.warnings {
        let text = warning_text(warning);
        ui.label(
            RichText::new(format!("⚠ {text}")).color(color(palette.text_shade(palette.warning))),
        );
    }
}

/// A kernel warning in words, its length with 4 significant digits or as many more as tell it
/// from 1 (the kernel's own text,
/// for the command line's JSON, keeps every digit).
fn warning_text(warning: &Warning) -> String {
    match warning {
        Warning::NotUnitLength { vector, length } => {
            let vector = match vector {
                VectorName::W => "W",
                VectorName::N => "N",
            };
            t!(
                "readouts-warning-not-unit",
                vector = vector,
                length = significant_apart(*length, 1.0, 4)
            )
        }
        Warning::NormalFlipped => t!("readouts-warning-flipped"),
    }
}

/// Shows every readout for `r`, in the colours of `palette` (the diagram's theme).
pub(super) fn show(ui: &mut Ui, r: &Refraction<f64>, palette: &Palette) {
    discriminant(ui, r, palette);
    ui.separator();
    quadratic(ui, r, palette);
    ui.separator();
    ui.heading(t!("readouts-candidates"));
    candidates(ui, r, palette);
    ui.separator();
    ui.heading(t!("readouts-warnings"));
    warnings(ui, r, palette);
    ui.separator();
    ui.heading(t!(
        "readouts-equations",
        section = r.convention.section().to_string()
    ));
    source_equations(ui, r);
}
