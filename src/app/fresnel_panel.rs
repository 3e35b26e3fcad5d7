//! The *Fresnel* tool beside the diagram: `R_s`, `R_p`, unpolarised R and T against θi from 0° to
//! 90° for the current media ([`FresnelPlot`], the kernel's fractions), Brewster's and the
//! critical angle marked and named, the current θi as a cursor that follows every drag of W,
//! the values there, and the source of the formula in words.
//!
//! It is a tool beside the diagram rather than a view of its own because its cursor is the
//! diagram's θi: the class watches `R_p` fall to zero while the teacher drags W to Brewster's
//! angle, which a separate view would hide.

use egui::{RichText, Ui};
use egui_plot::{Line, LineStyle, Plot, PlotPoint, Text, VLine, uniform_grid_spacer};
use refraction_i18n::t;

use super::paint::color;
use refraction_diagram::fresnel_plot::{FresnelPlot, curve_strokes, percent, source};
use refraction_diagram::numbers::number;
use refraction_diagram::palette::Palette;
use refraction_diagram::shapes::{Dash, Stroke};
use refraction_model::ExplorerState;

/// The plot's least and most height, in points.
const PLOT_HEIGHT: (f32, f32) = (150.0, 420.0);

/// The egui line style of a diagram dash.
fn style(dash: Dash) -> LineStyle {
    match dash {
        Dash::Solid => LineStyle::Solid,
        Dash::Dotted | Dash::DashDot | Dash::DashDotDot => LineStyle::dotted_loose(),
        Dash::Dashed | Dash::LongDash | Dash::LongDashDot => LineStyle::dashed_loose(),
    }
}

/// The strokes of the four curves at the window's scale (widths in points).
fn strokes(palette: &Palette) -> [Stroke; 4] {
    // 14-point text gives 2-point lines, the unpolarised R thicker.
    curve_strokes(palette, 14.0)
}

/// A marker line at `degrees` with its name at the top of the plot.
fn marker(
    plot: &mut egui_plot::PlotUi<'_>,
    name: &str,
    degrees: f64,
    colour: egui::Color32,
    dash: Dash,
) {
    plot.vline(
        VLine::new(name, degrees)
            .color(colour)
            .width(2.0)
            .style(style(dash)),
    );
    plot.text(
        Text::new(
            name,
            PlotPoint::new(degrees, 1.04),
            RichText::new(name).color(colour),
        )
        .anchor(egui::Align2::CENTER_BOTTOM),
    );
}

/// The largest θi a click on the plot sets, in degrees: grazing, but short of 90°, which no
/// ray meets a surface at.
const LARGEST_CLICKED_DEG: f64 = 89.9;

/// The plot: the curves, the landmarks and the cursor. Returns the θi clicked or dragged to on
/// it, if any.
fn plot(ui: &mut Ui, model: &FresnelPlot, palette: &Palette, height: f32) -> Option<f64> {
    let strokes = strokes(palette);
    Plot::new("fresnel")
        .height(height.clamp(PLOT_HEIGHT.0, PLOT_HEIGHT.1))
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .allow_boxed_zoom(false)
        .include_x(0.0)
        .include_x(90.0)
        .include_y(0.0)
        .include_y(1.12)
        .x_axis_label(t!("fresnel-axis"))
        // Lines every 10°, labels at least every 30° however narrow the plot.
        .x_grid_spacer(uniform_grid_spacer(|_| [10.0, 30.0, 90.0]))
        // The room above 100 % holds the markers' names, not values.
        .y_axis_formatter(|mark, _| {
            if mark.value > 1.0 + 1e-9 {
                String::new()
            } else {
                format!("{} %", number(mark.value * 100.0, 0))
            }
        })
        .show(ui, |plot| {
            let response = plot.response();
            let pressed = response.clicked() || response.dragged();
            let clicked = plot.pointer_coordinate().filter(|_| pressed);
            for (curve, stroke) in model.curves.iter().zip(strokes) {
                let points: Vec<[f64; 2]> = curve.points.iter().map(|&p| p.into()).collect();
                plot.line(
                    Line::new(&curve.name, points)
                        .color(color(stroke.colour))
                        .width(stroke.width)
                        .style(style(stroke.dash)),
                );
            }
            if let Some(b) = model.angles.brewster_deg {
                let name = format!("θB {}°", number(b, 1));
                marker(
                    plot,
                    &name,
                    b,
                    color(palette.text_shade(palette.n)),
                    Dash::Dashed,
                );
            }
            if let Some(c) = model.angles.critical_deg {
                let name = format!("θc {}°", number(c, 1));
                let shade = color(palette.text_shade(palette.critical));
                marker(plot, &name, c, shade, Dash::DashDot);
            }
            let shade = color(palette.text_shade(palette.w));
            plot.vline(
                VLine::new(t!("fresnel-now"), model.cursor_deg)
                    .color(shade)
                    .width(3.0),
            );
            clicked.map(|p| p.x.clamp(0.0, LARGEST_CLICKED_DEG))
        })
        .inner
}

/// A short sample of `stroke`, as the plot draws it, for the legend.
fn sample(ui: &mut Ui, stroke: Stroke) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(32.0, 14.0), egui::Sense::hover());
    let ends = [rect.left_center(), rect.right_center()];
    let line = egui::Stroke::new(stroke.width, color(stroke.colour));
    let shapes = match stroke.dash {
        Dash::Solid => vec![egui::Shape::line_segment(ends, line)],
        Dash::Dashed | Dash::LongDash | Dash::LongDashDot => {
            egui::Shape::dashed_line(&ends, line, 7.0, 4.0)
        }
        Dash::Dotted | Dash::DashDot | Dash::DashDotDot => {
            egui::Shape::dashed_line(&ends, line, 2.0, 4.0)
        }
    };
    ui.painter().extend(shapes);
}

/// The legend with the values at the cursor, one wrapping line per curve (the tool may be a
/// narrow strip beside the diagram in presentation).
fn legend(ui: &mut Ui, model: &FresnelPlot, palette: &Palette) {
    let a = model.at_cursor;
    let values = [a.rs, a.rp, a.reflectance(), a.transmittance()];
    for ((curve, stroke), value) in model.curves.iter().zip(strokes(palette)).zip(values) {
        ui.horizontal(|ui| {
            sample(ui, stroke);
            ui.add(egui::Label::new(format!("{}: {}", curve.name, percent(value))).wrap());
        });
    }
}

/// The landmarks in words.
fn landmarks(ui: &mut Ui, model: &FresnelPlot) {
    ui.label(t!(
        "fresnel-at",
        angle = number(model.cursor_deg, 1),
        mu_i = refraction_i18n::decimal(&model.mu_i.to_string()),
        mu_t = refraction_i18n::decimal(&model.mu_t.to_string())
    ));
    match model.angles.brewster_deg {
        Some(b) => ui.label(t!("fresnel-brewster", angle = number(b, 1))),
        None => ui.label(t!("fresnel-equal-indices")),
    };
    match model.angles.critical_deg {
        Some(c) => ui.label(t!("fresnel-critical", angle = number(c, 1))),
        None => ui.label(t!("fresnel-no-critical")),
    };
}

/// The legend, the landmarks in words and the source of the formula.
fn words(ui: &mut Ui, model: &FresnelPlot, palette: &Palette) {
    ui.label(RichText::new(t!("fresnel-click-hint")).weak());
    legend(ui, model, palette);
    landmarks(ui, model);
    ui.label(RichText::new(source().replace('\n', " ")).small());
}

/// The least width, in points, at which the words go beside the plot rather than under it: a
/// strip under the diagram at the desk is wide and low.
const SIDE_BY_SIDE_WIDTH: f32 = 720.0;

/// Shows the tool for `state` in `palette`; a click or drag on the plot turns W to the θi
/// under the pointer.
pub fn show(ui: &mut Ui, state: &mut ExplorerState, palette: &Palette) {
    let model = FresnelPlot::of(state);
    ui.label(RichText::new(t!("fresnel-heading")).strong());
    let clicked = if ui.available_width() >= SIDE_BY_SIDE_WIDTH {
        ui.horizontal_top(|ui| {
            let width = ui.available_width() * 0.58;
            let height = ui.available_height() - 8.0;
            let clicked = ui
                .vertical(|ui| {
                    ui.set_width(width);
                    plot(ui, &model, palette, height)
                })
                .inner;
            ui.vertical(|ui| words(ui, &model, palette));
            clicked
        })
        .inner
    } else {
        let clicked = plot(ui, &model, palette, ui.available_height() - 150.0);
        words(ui, &model, palette);
        clicked
    };
    if let Some(degrees) = clicked {
        // Clamped to [0, 89.9]: within what the model accepts.
        let _ = state.set_incidence_degrees(degrees);
    }
}
