//! The *Fresnel* tool beside the diagram: `Rs`, `Rp`, unpolarised R and T against θi from 0° to
//! 90° for the current media ([`FresnelPlot`], the kernel's fractions), Brewster's and the
//! critical angle marked and named, the current θi as a cursor that follows every drag of W,
//! the values there, and the source of the formula in words.
//!
//! It is a tool beside the diagram rather than a view of its own because its cursor is the
//! diagram's θi: the class watches `Rp` fall to zero while the teacher drags W to Brewster's
//! angle, which a separate view would hide.

use egui::{RichText, Sense, Ui};
use glam::Vec2;
use refraction_i18n::t;

use super::paint;
use refraction_diagram::{FresnelPlot, PlotFrame, Typeface, fresnel_plot, palette::Palette};
use refraction_model::ExplorerState;

/// The plot's least and most height, in points.
const PLOT_HEIGHT: (f32, f32) = (300.0, 900.0);

/// The largest θi a click on the plot sets, in degrees: grazing, but short of 90°, which no
/// ray meets a surface at.
const LARGEST_CLICKED_DEG: f64 = 89.9;

/// The plot as the diagram draws it for an export (curves, landmarks, cursor, legend, values,
/// source), painted across the panel; the θi clicked or dragged to on it, if any.
fn plot(ui: &mut Ui, model: &FresnelPlot, palette: &Palette) -> Option<f64> {
    let face = Typeface::egui_default();
    let width = ui.available_width();
    // Room under the plot for the landmarks in words; in a narrow strip, as tall as its words
    // need (the panel scrolls).
    let height = (ui.available_height() - 110.0)
        .clamp(PLOT_HEIGHT.0, PLOT_HEIGHT.1)
        .max(PlotFrame::height_for(model, width, &face));
    let size = Vec2::new(width, height);
    let angle = refraction_diagram::numbers::number(model.cursor_deg, 1);
    let about = t!("fresnel-plot-about", angle = angle);
    let (response, painter, to_screen) = paint::figure(ui, size, Sense::click_and_drag(), &about);
    let drawn = fresnel_plot(model, size, &face, palette);
    paint::paint(&painter, &to_screen, &drawn);
    if !(response.clicked() || response.dragged()) {
        return None;
    }
    let pointer = response.interact_pointer_pos()?;
    let x = to_screen.inverse().transform_pos(pointer).x;
    let frame = PlotFrame::new(model, size, &face);
    Some(frame.degrees_at(x).min(LARGEST_CLICKED_DEG))
}

/// The landmarks in words, with the formulas that give them.
fn landmarks(ui: &mut Ui, model: &FresnelPlot) {
    let angle = refraction_diagram::numbers::number;
    ui.label(t!(
        "fresnel-at",
        angle = angle(model.cursor_deg, 1),
        mu_i = refraction_i18n::decimal(&model.mu_i.to_string()),
        mu_t = refraction_i18n::decimal(&model.mu_t.to_string())
    ));
    match model.angles.brewster_deg {
        Some(b) => ui.label(t!("fresnel-brewster", angle = angle(b, 1))),
        None => ui.label(t!("fresnel-equal-indices")),
    };
    match model.angles.critical_deg {
        Some(c) => ui.label(t!("fresnel-critical", angle = angle(c, 1))),
        None => ui.label(t!("fresnel-no-critical")),
    };
}

/// Shows the tool for `state` in `palette`: the plot as an export draws it, then the
/// landmarks in words; a click or drag on the plot turns W to the θi under the pointer.
pub(super) fn show(ui: &mut Ui, state: &mut ExplorerState, palette: &Palette) {
    let model = FresnelPlot::of(state);
    // The figure carries its own title.
    ui.label(RichText::new(t!("fresnel-click-hint")).weak());
    if let Some(degrees) = plot(ui, &model, palette) {
        // Clamped to [0, 89.9]: within what the model accepts.
        state.set_incidence_degrees(degrees).ok();
    }
    landmarks(ui, &model);
}
