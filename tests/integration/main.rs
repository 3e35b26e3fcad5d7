//! The end-to-end tests in one binary: the commands run as a user runs them, and the window
//! driven headlessly (`egui_kittest`). One binary links the stack once and runs every test in
//! parallel.
#![expect(
    clippy::unwrap_used,
    reason = "test helpers: a failed unwrap is a failed test, with its message"
)]

mod cli;
mod common;

mod accessibility;
mod accuracy_view;
mod bench_variants;
mod check_api_cli;
mod check_cli;
mod check_guards;
mod clipboard;
mod dev_profile;
mod diagnosis_cli;
mod docs_commands;
mod explorer_canvas;
mod explorer_check;
mod explorer_classroom;
mod explorer_files;
mod explorer_languages;
mod explorer_logs;
mod explorer_panels;
mod explorer_physics;
mod families_cli;
mod hostile_cli;
mod languages_cli;
mod layout_audit;
mod lesson_deck;
mod lessons_cli;
mod links;
mod module_circles;
mod parsers_fuzz;
mod render_cli;
mod renderer_families;
mod renderers;
mod rtiow_flow;
mod scenes_ui;
mod slides_cli;
mod snapshots;
mod software_renderer;
mod solve_cli;
mod student_view;
mod trace_cli;
mod translations;
