//! The "Accuracy vs time" view: runs the `bench` measurement in a background thread with a
//! progress bar (the window never freezes), then plots largest hard-set error against time per
//! ray on log axes, one marker per variant and precision, and names the fastest variant within
//! 10× of the best accuracy.

use refraction_i18n::t;
use std::sync::{Arc, Mutex, PoisonError};

use egui::{Grid, ProgressBar, RichText, Ui};
use egui_plot::{
    Corner, GridInput, GridMark, HLine, HoverPosition, Legend, MarkerShape, Plot, Points,
};

use super::paint::color;
use refraction_bench::Config;
use refraction_diagram::accuracy_plot::{
    BOUND, FLOOR, Marker, axes, decade_label, point_label, variant_colour, variant_marker,
};
use refraction_diagram::numbers::number;
use refraction_diagram::palette::Palette;
use refraction_model::report::Report;

/// What the background measurement has reached.
#[derive(Debug, Default)]
struct Progress {
    fraction: f64,
    report: Option<Report>,
}

/// The view's state: the last report and any measurement under way.
#[derive(Debug, Default)]
pub struct AccuracyView {
    quick: bool,
    running: Option<Arc<Mutex<Progress>>>,
    report: Option<Report>,
}

/// Grid marks of a log10 axis: every power of ten, and 2× and 5× it in between.
#[expect(
    clippy::needless_pass_by_value,
    reason = "egui_plot calls a grid spacer with the input by value"
)]
fn decades(input: GridInput) -> Vec<GridMark> {
    let (low, high) = input.bounds;
    (low.floor() as i32..=high.ceil() as i32)
        .flat_map(|e| {
            [(1.0, 1.0), (2.0, 0.5), (5.0, 0.5)].map(|(m, step_size)| GridMark {
                value: f64::from(e) + f64::log10(m),
                step_size,
            })
        })
        .filter(|mark| (low..=high).contains(&mark.value))
        .collect()
}

/// The value of a log10 coordinate as a label: `0.2`, `50`, `1e4`, `5e-3`.
fn decade_text(mark: GridMark) -> String {
    let value = 10f64.powf(mark.value);
    if mark.value.fract() == 0.0 {
        decade_label(mark.value as i32)
    } else if (0.01..1e4).contains(&value) {
        format!("{}", (value * 1e3).round() / 1e3)
    } else {
        format!("{value:.0e}")
    }
}

impl AccuracyView {
    /// Starts a measurement in a background thread; it wakes the UI as it progresses.
    pub fn start(&mut self, ctx: &egui::Context) {
        let progress = Arc::new(Mutex::new(Progress::default()));
        let config = if self.quick {
            Config::QUICK
        } else {
            Config::FULL
        };
        let (shared, ctx) = (Arc::clone(&progress), ctx.clone());
        std::thread::spawn(move || {
            let report = refraction_bench::run(&config, &mut |fraction| {
                shared
                    .lock()
                    .unwrap_or_else(PoisonError::into_inner)
                    .fraction = fraction;
                ctx.request_repaint();
            });
            shared.lock().unwrap_or_else(PoisonError::into_inner).report = Some(report);
            ctx.request_repaint();
        });
        self.running = Some(progress);
    }

    /// Takes the report from a finished measurement; returns the fraction done otherwise.
    fn poll(&mut self) -> Option<f64> {
        let running = self.running.as_ref()?;
        let mut progress = running.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(report) = progress.report.take() {
            drop(progress);
            self.report = Some(report);
            self.running = None;
            None
        } else {
            Some(progress.fraction)
        }
    }

    /// Shows the view, its plot in `palette`'s colours.
    pub fn show(&mut self, ui: &mut Ui, palette: &Palette) {
        ui.heading(t!("accuracy-heading"));
        ui.label(t!("accuracy-intro"));
        let fraction = self.poll();
        ui.horizontal(|ui| {
            ui.checkbox(&mut self.quick, t!("accuracy-quick"));
            let measure = ui.add_enabled(
                fraction.is_none(),
                egui::Button::new(t!("accuracy-measure")),
            );
            if measure.clicked() {
                self.start(ui.ctx());
            }
        });
        if let Some(fraction) = fraction {
            ui.add(ProgressBar::new(fraction as f32).show_percentage().text(t!(
                "accuracy-measuring",
                percent = number(fraction * 100.0, 0)
            )));
        }
        let Some(report) = &self.report else {
            if fraction.is_none() {
                ui.label(t!("accuracy-press-measure"));
            }
            return;
        };
        if let Some(best) = report.fastest_accurate() {
            let verdict = t!(
                "accuracy-verdict",
                variant = point_label(best),
                time = number(best.ns_per_ray, 2),
                error = number(best.max_err_hard_eps_kappa, 1)
            );
            ui.label(RichText::new(verdict).strong());
        }
        plot(ui, report, palette);
        table(ui, report);
        ui.small(t!(
            "accuracy-footnote",
            random = report.rays,
            hard = report.hard_rays,
            cpu = &report.cpu
        ));
    }
}

/// Error against time, both log10-transformed (`egui_plot` has no log axes), framed on whole
/// decades like the `bench --plot` image.
fn plot(ui: &mut Ui, report: &Report, palette: &Palette) {
    let (x, y) = axes(report);
    Plot::new("accuracy-plot")
        .height((ui.available_height() * 0.6).max(260.0))
        .legend(Legend::default().position(Corner::LeftTop))
        .default_x_bounds(x.low, x.high)
        .default_y_bounds(y.low, y.high)
        .x_axis_label(t!("accuracy-axis-time"))
        .y_axis_label(t!("accuracy-axis-error"))
        .x_grid_spacer(decades)
        .y_grid_spacer(decades)
        .x_axis_formatter(|mark, _| decade_text(mark))
        .y_axis_formatter(|mark, _| decade_text(mark))
        .label_formatter(|hover| {
            let (name, at) = match hover {
                HoverPosition::NearDataPoint {
                    plot_name,
                    position,
                    ..
                } => (*plot_name, position),
                HoverPosition::Elsewhere { position } => ("", position),
            };
            Some(t!(
                "accuracy-hover",
                name = name,
                time = number(10f64.powf(at.x), 3),
                error = number(10f64.powf(at.y), 3)
            ))
        })
        .show(ui, |plot| {
            plot.hline(
                HLine::new(
                    t!("accuracy-bound", bound = number(BOUND, 0)),
                    BOUND.log10(),
                )
                .color(color(palette.alarm)),
            );
            for row in &report.rows {
                let at = [
                    row.ns_per_ray.log10(),
                    row.max_err_hard_eps_kappa.max(FLOOR).log10(),
                ];
                plot.points(
                    Points::new(point_label(row), vec![at])
                        .shape(marker_shape(variant_marker(row.variant)))
                        .filled(row.precision == "f64")
                        .radius(6.0)
                        .color(color(variant_colour(row.variant, palette))),
                );
            }
        });
}

/// `egui_plot`'s shape for a variant's marker.
fn marker_shape(marker: Marker) -> MarkerShape {
    match marker {
        Marker::Circle => MarkerShape::Circle,
        Marker::Square => MarkerShape::Square,
        Marker::Diamond => MarkerShape::Diamond,
        Marker::Triangle => MarkerShape::Up,
        Marker::Plus => MarkerShape::Plus,
        Marker::Cross => MarkerShape::Cross,
    }
}

/// The report's numbers.
fn table(ui: &mut Ui, report: &Report) {
    Grid::new("bench-rows").striped(true).show(ui, |ui| {
        for heading in [
            t!("accuracy-column-variant"),
            t!("accuracy-column-time"),
            t!("accuracy-column-random"),
            t!("accuracy-column-hard"),
            t!("accuracy-column-eps-kappa"),
            t!("accuracy-column-tir"),
        ] {
            ui.label(RichText::new(heading).strong());
        }
        ui.end_row();
        for r in &report.rows {
            ui.label(point_label(r));
            ui.label(number(r.ns_per_ray, 2));
            ui.label(refraction_i18n::decimal(&format!(
                "{:.2e}",
                r.max_err_random
            )));
            ui.label(refraction_i18n::decimal(&format!("{:.2e}", r.max_err_hard)));
            ui.label(number(r.max_err_hard_eps_kappa, 1));
            ui.label(r.tir_mismatches.to_string());
            ui.end_row();
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decade_marks_and_labels() {
        let marks = decades(GridInput {
            bounds: (-1.3, 2.2),
            base_step_size: 0.1,
        });
        let whole: Vec<f64> = marks
            .iter()
            .filter(|m| m.step_size == 1.0)
            .map(|m| m.value)
            .collect();
        assert_eq!(whole, [-1.0, 0.0, 1.0, 2.0]);
        assert_eq!(marks.len(), 10);
        let label = |value| {
            decade_text(GridMark {
                value,
                step_size: 1.0,
            })
        };
        assert_eq!(label(-1.0), "0.1");
        assert_eq!(label(2.0_f64.log10()), "2");
        assert_eq!(label(-3.0 + 5.0_f64.log10()), "5e-3");
    }
}
