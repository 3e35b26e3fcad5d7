//! The "Accuracy vs time" view: runs the `bench` measurement in a background thread with a
//! progress bar (the window never freezes), then plots largest hard-set error against time per
//! ray on log axes, one marker per variant and precision, and names the fastest variant within
//! 10× of the best accuracy. The plot is the diagram crate's, as `bench --plot` draws it.

use refraction_i18n::t;
use std::sync::{Arc, Mutex, PoisonError};

use egui::{Grid, ProgressBar, RichText, Ui};
use glam::Vec2;

use refraction_bench::Config;
use refraction_diagram::{
    Typeface, accuracy_markers, accuracy_plot, accuracy_point_label, numbers::number,
    palette::Palette,
};
use refraction_model::report::Report;

/// What the background measurement has reached.
#[derive(Debug, Default)]
struct Progress {
    fraction: f64,
    report: Option<Report>,
}

/// The view's state: the last report and any measurement under way.
#[derive(Debug, Default)]
pub(super) struct AccuracyView {
    quick: bool,
    running: Option<Arc<Mutex<Progress>>>,
    report: Option<Report>,
}

impl AccuracyView {
    /// Starts a measurement in a background thread; it wakes the UI as it progresses.
    pub(super) fn start(&mut self, ctx: &egui::Context) {
        let progress = Arc::new(Mutex::new(Progress::default()));
        let config = if self.quick {
            Config::QUICK
        } else {
            Config::FULL
        };
        let (shared, ctx) = (Arc::clone(&progress), ctx.clone());
        super::background::spawn(move || {
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
    pub(super) fn show(&mut self, ui: &mut Ui, palette: &Palette) {
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
        if super::background::ONE_THREAD {
            ui.label(RichText::new(t!("web-one-thread")).weak());
        }
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
                variant = accuracy_point_label(best),
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

/// The plot as `bench --plot` and `render --view accuracy` draw it (markers by variant,
/// each named beside it, the bound, whole decades), painted across the view; hovering a marker
/// shows its figures.
fn plot(ui: &mut Ui, report: &Report, palette: &Palette) {
    let face = Typeface::egui_default();
    let width = ui.available_width();
    let height = (ui.available_height() * 0.6).clamp(300.0, width * 0.62);
    let size = Vec2::new(width, height);
    let about = t!("accuracy-plot-about", count = report.rows.len());
    let (response, painter, to_screen) =
        super::paint::figure(ui, size, egui::Sense::hover(), &about);
    super::paint::paint(
        &painter,
        &to_screen,
        &accuracy_plot(report, size, &face, palette),
    );
    let Some(pointer) = response.hover_pos() else {
        return;
    };
    let at = to_screen.inverse().transform_pos(pointer);
    let nearest = accuracy_markers(report, size)
        .into_iter()
        .zip(&report.rows)
        .map(|(p, row)| (p.distance(Vec2::new(at.x, at.y)), row))
        .filter(|(d, _)| *d < 16.0)
        .min_by(|a, b| a.0.total_cmp(&b.0));
    if let Some((_, row)) = nearest {
        response.on_hover_text(t!(
            "accuracy-hover",
            name = accuracy_point_label(row),
            time = number(row.ns_per_ray, 3),
            error = number(row.max_err_hard_eps_kappa, 3)
        ));
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
            ui.label(accuracy_point_label(r));
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
