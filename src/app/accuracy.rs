//! The "Accuracy vs time" view: runs the `bench` measurement in a background thread with a
//! progress bar (the window never freezes), then plots largest hard-set error against time per
//! ray on log axes, one marker per variant and precision, and names the fastest variant within
//! 10× of the best accuracy.

use std::sync::{Arc, Mutex, PoisonError};

use egui::{Grid, ProgressBar, RichText, Ui};
use egui_plot::{
    Corner, GridInput, GridMark, HLine, HoverPosition, Legend, MarkerShape, Plot, Points,
};

use super::paint::color;
use refraction_bench::{Config, Report};
use refraction_diagram::accuracy_plot::{
    BOUND, FLOOR, Marker, axes, decade_label, point_label, variant_colour, variant_marker,
};
use refraction_diagram::palette;

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

    /// Shows the view.
    pub fn show(&mut self, ui: &mut Ui) {
        ui.heading("What accuracy costs in time");
        ui.label(
            "Times every kernel variant at f32 and f64 on this machine and measures its error \
             against a double-double oracle on random and hard incidences. The plot shows the \
             largest hard-set error in units of ε·κ (what the algorithm loses beyond what the \
             problem itself amplifies) against nanoseconds per ray.",
        );
        let fraction = self.poll();
        ui.horizontal(|ui| {
            ui.checkbox(&mut self.quick, "Quick run (a few seconds)");
            let measure = ui.add_enabled(fraction.is_none(), egui::Button::new("Measure"));
            if measure.clicked() {
                self.start(ui.ctx());
            }
        });
        if let Some(fraction) = fraction {
            ui.add(
                ProgressBar::new(fraction as f32)
                    .show_percentage()
                    .text(format!("measuring… {:.0} %", fraction * 100.0)),
            );
        }
        let Some(report) = &self.report else {
            if fraction.is_none() {
                ui.label("Press Measure to run the benchmark.");
            }
            return;
        };
        ui.label(RichText::new(report.verdict()).strong());
        plot(ui, report);
        table(ui, report);
        ui.small(format!(
            "{} random and {} hard problems on {}. Timings depend on what else the machine is \
             doing; `refraction-explorer bench` gives the same figures on the command line.",
            report.rays, report.hard_rays, report.cpu
        ));
    }
}

/// Error against time, both log10-transformed (egui_plot has no log axes), framed on whole
/// decades like the `bench --plot` image.
fn plot(ui: &mut Ui, report: &Report) {
    let (x, y) = axes(report);
    Plot::new("accuracy against time")
        .height((ui.available_height() * 0.6).max(260.0))
        .legend(Legend::default().position(Corner::LeftTop))
        .default_x_bounds(x.low, x.high)
        .default_y_bounds(y.low, y.high)
        .x_axis_label("time per ray, ns (log)")
        .y_axis_label("largest hard-set error, ε·κ (log)")
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
            Some(format!(
                "{name}\n{:.3} ns, {:.3} ε·κ",
                10f64.powf(at.x),
                10f64.powf(at.y)
            ))
        })
        .show(ui, |plot| {
            plot.hline(
                HLine::new("the default kernel's bound, 32 ε·κ", BOUND.log10())
                    .color(color(palette::ALARM)),
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
                        .color(color(variant_colour(row.variant))),
                );
            }
        });
}

/// egui_plot's shape for a variant's marker.
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
    Grid::new("bench rows").striped(true).show(ui, |ui| {
        for heading in [
            "variant",
            "ns/ray",
            "max err random",
            "max err hard",
            "hard ε·κ",
            "TIR mismatches",
        ] {
            ui.label(RichText::new(heading).strong());
        }
        ui.end_row();
        for r in &report.rows {
            ui.label(point_label(r));
            ui.label(format!("{:.2}", r.ns_per_ray));
            ui.label(format!("{:.2e}", r.max_err_random));
            ui.label(format!("{:.2e}", r.max_err_hard));
            ui.label(format!("{:.1}", r.max_err_hard_eps_kappa));
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
