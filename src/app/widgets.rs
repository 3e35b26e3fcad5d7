//! Small widgets the window's strips share.

use egui::{Button, Role, Ui, WidgetInfo};

/// The icon of a button that opens a file chosen in the file dialog.
pub(super) const OPEN_ICON: &str = "🗁";

/// The icon of a button that saves to a file chosen in the file dialog.
pub(super) const SAVE_AS_ICON: &str = "💾";

/// A button of an icon and a name that shows only its icon when `compact` (a strip that must
/// keep to one row on a projector): its name stays its accessible name and leads its hover
/// text. `(enabled, selected)`: a switched-off button is greyed, a selected one shown pressed.
/// Returns whether it was clicked.
pub(super) fn icon_button(
    ui: &mut Ui,
    (icon, name, hover): (&str, String, String),
    (enabled, selected): (bool, bool),
    compact: bool,
) -> bool {
    let full = format!("{icon} {name}");
    let shown = if compact { icon } else { full.as_str() };
    let button = ui.add_enabled(enabled, Button::new(shown).selected(selected));
    button.widget_info(|| WidgetInfo::labeled(Role::Button, enabled, &full));
    let hover = if compact {
        format!("{name}: {hover}")
    } else {
        hover
    };
    button.on_hover_text(hover).clicked()
}
