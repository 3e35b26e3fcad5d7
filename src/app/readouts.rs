//! The right panel: the discriminant k, the quadratic in b, the candidates table, the source's
//! equations with numbers, and the kernel's warnings. Every number is the kernel's.

use egui::{Color32, Grid, RichText, Sense, Stroke, Ui, Vec2};
use egui_plot::{HLine, Line, Plot, Points};

use super::paint::color;
use refraction_diagram::equations::equations;
use refraction_diagram::numbers::{number, vector};
use refraction_diagram::palette;
use refraction_diagram::quadratic::Quadratic;
use refraction_diagram::table::rows;
use refraction_kernel::Refraction;

/// The mark for a passed (✔) or failed (✖) check.
fn mark(passed: bool) -> &'static str {
    if passed { "✔" } else { "✖" }
}

/// k as a number and as a bar signed about zero (k ranges over 1 − μ² … 1; the bar shows
/// −1 … 1 and saturates beyond).
fn discriminant(ui: &mut Ui, r: &Refraction<f64>) {
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
    painter.rect_filled(rect, 2.0, Color32::from_gray(230));
    let zero = rect.center().x;
    let end = zero + (r.k.clamp(-1.0, 1.0) as f32) * rect.width() * 0.5;
    let fill = if r.k < 0.0 {
        palette::ALARM
    } else {
        palette::N
    };
    let bar = egui::Rect::from_x_y_ranges(zero.min(end)..=zero.max(end), rect.y_range());
    painter.rect_filled(bar, 0.0, color(fill));
    painter.vline(zero, rect.y_range(), Stroke::new(2.0, color(palette::INK)));
}

/// The source's eq. 20 in b, with the kernel's two roots.
fn quadratic(ui: &mut Ui, r: &Refraction<f64>) {
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
    Plot::new("quadratic in b")
        .height(150.0)
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .allow_boxed_zoom(false)
        .allow_double_click_reset(false)
        .default_x_bounds(q.vertex() - 1.6, q.vertex() + 1.6)
        .default_y_bounds(-1.1, 1.6)
        .show(ui, |plot| {
            plot.hline(HLine::new("zero", 0.0).color(color(palette::GUIDE)));
            plot.line(
                Line::new("f(b)", q.samples(1.6, 161))
                    .color(color(palette::T))
                    .width(2.0),
            );
            plot.points(
                Points::new("roots", roots)
                    .radius(5.0)
                    .color(color(palette::WARNING)),
            );
        });
    ui.label(caption);
}

/// The four candidates with their checks.
fn candidates(ui: &mut Ui, r: &Refraction<f64>) {
    let rows = rows(r);
    if rows.is_empty() {
        ui.label(
            RichText::new("No candidates: k < 0, so b has no real roots and no T exists.")
                .color(color(palette::ALARM)),
        );
        return;
    }
    Grid::new("candidates")
        .striped(true)
        .spacing([5.0, 3.0])
        .show(ui, |ui| {
            for heading in ["candidate", "a", "b", "T", "|T|=1", "eq.10", "side", "bend"] {
                ui.label(RichText::new(heading).strong());
            }
            ui.end_row();
            for row in rows {
                let role = RichText::new(row.role);
                let role = if row.rule.is_none() {
                    role.strong().color(color(palette::T))
                } else {
                    role
                };
                let response = ui.label(role);
                if let Some(rule) = row.rule {
                    response.on_hover_text(rule);
                }
                ui.label(number(row.a, 3));
                ui.label(number(row.b, 3));
                ui.label(RichText::new(vector(row.t, 2)).small());
                for passed in [
                    row.unit,
                    row.squared_snell,
                    row.correct_side,
                    row.tangential,
                ] {
                    let ink = if passed { palette::N } else { palette::ALARM };
                    ui.label(RichText::new(mark(passed)).color(color(ink)));
                }
                ui.end_row();
            }
        });
    ui.label(
        RichText::new(
            "All four are unit length and satisfy squared Snell (eq. 10): squaring cannot tell \
             them apart. Only the side and the bend (the \
             source's μ = 1 argument) pick T.",
        )
        .small(),
    );
}

/// The source's key equations with the numbers substituted.
fn source_equations(ui: &mut Ui, r: &Refraction<f64>) {
    for eq in equations(r) {
        ui.label(RichText::new(format!("({})  {}", eq.number, eq.formula)).strong());
        ui.label(RichText::new(eq.substituted).monospace().small());
    }
}

/// The kernel's warnings, or a note that there are none.
fn warnings(ui: &mut Ui, r: &Refraction<f64>) {
    if r.warnings.is_empty() {
        ui.label("No warnings: W and N are unit length and N faces the ray.");
    }
    for warning in &r.warnings {
        ui.label(RichText::new(format!("⚠ {warning}")).color(color(palette::WARNING)));
    }
}

/// Shows every readout for `r`.
pub fn show(ui: &mut Ui, r: &Refraction<f64>) {
    discriminant(ui, r);
    ui.separator();
    quadratic(ui, r);
    ui.separator();
    ui.heading("The four candidates");
    candidates(ui, r);
    ui.separator();
    ui.heading("Kernel warnings");
    warnings(ui, r);
    ui.separator();
    ui.heading(format!(
        "Source equations, Section {}",
        r.convention.section()
    ));
    source_equations(ui, r);
}
