//! The right panel: the discriminant k, the quadratic in b, the candidates table, the source's
//! equations with numbers, and the kernel's warnings. Every number is the kernel's.

use egui::{Grid, RichText, Sense, Stroke, Ui, Vec2};
use egui_plot::{HLine, Line, Plot, Points};

use super::paint::color;
use refraction_diagram::equations::equations;
use refraction_diagram::numbers::{number, vector};
use refraction_diagram::palette::Palette;
use refraction_diagram::quadratic::Quadratic;
use refraction_diagram::table::{CandidateRow, rows};
use refraction_kernel::Refraction;

/// The mark for a passed (✔) or failed (✖) check.
fn mark(passed: bool) -> &'static str {
    if passed { "✔" } else { "✖" }
}

/// k as a number and as a bar signed about zero (k ranges over 1 − μ² … 1; the bar shows
/// −1 … 1 and saturates beyond).
fn discriminant(ui: &mut Ui, r: &Refraction<f64>, palette: &Palette) {
    let verdict = if r.k < 0.0 {
        "< 0: total internal reflection"
    } else {
        "≥ 0: T exists"
    };
    ui.label(format!(
        "Discriminant k = μ²wn² − μ² + 1 = {} {verdict}",
        number(r.k, 4)
    ));
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

/// The source's eq. 20 in b, with the kernel's two roots. The plot is fitted afresh every
/// frame to both roots (or the vertex, on total internal reflection).
fn quadratic(ui: &mut Ui, r: &Refraction<f64>, palette: &Palette) {
    let q = Quadratic::of(r);
    ui.label(format!(
        "Eq. {}.20, the quadratic in b: b² + 2a·wn·b + a² − 1 = 0 with a = {}, wn = {}",
        r.convention.section(),
        number(q.a, 3),
        number(q.wn, 3),
    ));
    let roots: Vec<[f64; 2]> = q.roots.iter().map(|b| [*b, 0.0]).collect();
    let caption = if roots.is_empty() {
        "no real roots: the parabola no longer reaches zero".to_owned()
    } else {
        let values: Vec<String> = q.roots.iter().map(|b| number(*b, 4)).collect();
        format!(
            "roots b = {} (the candidates' b for this a)",
            values.join(", ")
        )
    };
    let ((x0, x1), (y0, y1)) = q.window();
    Plot::new("quadratic in b")
        .height(150.0)
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .allow_boxed_zoom(false)
        .allow_double_click_reset(false)
        .default_x_bounds(x0, x1)
        .default_y_bounds(y0, y1)
        .reset()
        .show(ui, |plot| {
            plot.hline(HLine::new("zero", 0.0).color(color(palette.guide)));
            plot.line(
                Line::new("f(b)", q.samples((x1 - x0) * 0.5, 161))
                    .color(color(palette.t))
                    .width(2.0),
            );
            plot.points(
                Points::new("roots", roots)
                    .radius(5.0)
                    .color(color(palette.warning)),
            );
        });
    ui.label(caption);
}

/// The narrowest panel, in body-text heights, that shows the candidates as a table; a
/// narrower one (presentation) shows each candidate as a short block instead of cutting the
/// table off.
const TABLE_WIDTH_IN_LINES: f32 = 30.0;

/// The names of the four checks, in the order of [`passes`].
const CHECKS: [&str; 4] = ["|T|=1", "eq.10", "side", "bend"];

/// Whether `row` passes each of [`CHECKS`].
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
    for (passed, name) in passes(row).into_iter().zip(CHECKS) {
        let ink = if passed { palette.n } else { palette.alarm };
        ui.label(RichText::new(mark(passed)).color(color(ink)));
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
            for heading in ["candidate", "a", "b", "T"].into_iter().chain(CHECKS) {
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
    let rows = rows(r);
    if rows.is_empty() {
        ui.label(
            RichText::new("No candidates: k < 0, so b has no real roots and no T exists.")
                .color(color(palette.alarm)),
        );
        return;
    }
    let line = ui.text_style_height(&egui::TextStyle::Body);
    if ui.available_width() >= line * TABLE_WIDTH_IN_LINES {
        candidate_table(ui, &rows, palette);
    } else {
        candidate_blocks(ui, &rows, palette);
    }
    ui.label(
        "All four are unit length and satisfy squared Snell (eq. 10): squaring cannot tell \
         them apart. Only the side and the bend (the source's μ = 1 argument) pick T.",
    );
}

/// The source's key equations with the numbers substituted.
fn source_equations(ui: &mut Ui, r: &Refraction<f64>) {
    for eq in equations(r) {
        ui.label(RichText::new(format!("({})  {}", eq.number, eq.formula)).strong());
        ui.label(RichText::new(eq.substituted).monospace());
    }
}

/// The kernel's warnings, or a note that there are none.
fn warnings(ui: &mut Ui, r: &Refraction<f64>, palette: &Palette) {
    if r.warnings.is_empty() {
        ui.label("No warnings: W and N are unit length and N faces the ray.");
    }
    for warning in &r.warnings {
        ui.label(
            RichText::new(format!("⚠ {warning}")).color(color(palette.text_shade(palette.warning))),
        );
    }
}

/// Shows every readout for `r`, in the colours of `palette` (the diagram's theme).
pub fn show(ui: &mut Ui, r: &Refraction<f64>, palette: &Palette) {
    discriminant(ui, r, palette);
    ui.separator();
    quadratic(ui, r, palette);
    ui.separator();
    ui.heading("The four candidates");
    candidates(ui, r, palette);
    ui.separator();
    ui.heading("Kernel warnings");
    warnings(ui, r, palette);
    ui.separator();
    ui.heading(format!(
        "Source equations, Section {}",
        r.convention.section()
    ));
    source_equations(ui, r);
}
