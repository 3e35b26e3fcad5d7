//! Helpers shared by the headless UI tests.

use egui::{Key, Modifiers, Role};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use refraction_explorer::app::Explorer;

/// Replaces the text of the text field `label` with `text` (Enter is not pressed).
pub fn replace_text(h: &mut Harness<'_, Explorer>, label: &str, text: &str) {
    h.get_by_role_and_label(Role::TextInput, label).focus();
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.run();
    h.get_by_role_and_label(Role::TextInput, label)
        .type_text(text);
    h.run();
}
