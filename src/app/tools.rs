//! The classroom tools under the diagram, one at a time: check my T, the walk-through,
//! save / open / share, the Fresnel plot and the lesson deck (shown by the window itself, in
//! every view: see [`super::deck`]). Their switches sit in the top bar.

use egui::{Panel, RichText, Role, ScrollArea, Ui, WidgetInfo};
use refraction_i18n::t;

use super::check_panel::CheckPanel;
use super::files_panel::FilesPanel;
use super::fresnel_panel;
use super::walkthrough::WalkThrough;
use refraction_diagram::{Focus, StudentRay, palette::Palette};
use refraction_model::ExplorerState;

/// The window's width a tool takes in presentation: the diagram keeps half the window beside
/// it (tested), and the panel keeps its width from step to step, so the diagram never jumps.
pub(super) const PRESENTATION_TOOL_SHARE: f32 = 0.30;

/// The tool shown beside the diagram.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Tool {
    /// Check a student's T.
    Check,
    /// The guided walk through the derivation.
    WalkThrough,
    /// Save, open, share and copy.
    Files,
    /// Reflectance and transmittance against θi, with the cursor at the diagram's θi.
    Fresnel,
    /// The lesson deck: its steps, built from the window and stepped through.
    Deck,
}

impl Tool {
    /// Every tool, in the order of the bar.
    pub(super) const ALL: [Self; 5] = [
        Self::Check,
        Self::WalkThrough,
        Self::Files,
        Self::Fresnel,
        Self::Deck,
    ];

    /// The switch's label (also its accessible name).
    #[must_use]
    pub(super) fn label(self) -> String {
        match self {
            Self::Check => format!("✔ {}", t!("tool-check")),
            Self::WalkThrough => format!("📖 {}", t!("tool-walk-through")),
            Self::Files => format!("💾 {}", t!("tool-files")),
            Self::Fresnel => format!("📈 {}", t!("tool-fresnel")),
            Self::Deck => format!("📚 {}", t!("tool-deck")),
        }
    }

    /// Whether the tool shows what a step's question asks (T, θt, the share reflected).
    fn shows_the_answer(self) -> bool {
        matches!(self, Self::Check | Self::WalkThrough | Self::Fresnel)
    }

    /// The window's width the tool takes in presentation.
    fn presentation_share(self) -> f32 {
        match self {
            // The deck's list and fields read in a narrow strip; the step's diagram needs room
            // below the step's own strip.
            Self::Deck => PRESENTATION_TOOL_SHARE * 0.85,
            _ => PRESENTATION_TOOL_SHARE,
        }
    }

    /// The panel's first height in points: what the tool shows without scrolling.
    fn height(self) -> f32 {
        match self {
            // The selector, the fields and a verdict's first lines.
            Self::Check => 260.0,
            Self::WalkThrough => 140.0,
            Self::Files => 150.0,
            Self::Fresnel => 330.0,
            // The files row, the buttons and the first steps.
            Self::Deck => 220.0,
        }
    }
}

/// The tools and which one is open.
#[derive(Debug, Default)]
pub(super) struct Tools {
    /// The open tool, if any.
    pub open: Option<Tool>,
    /// Check my T.
    pub check: CheckPanel,
    /// The walk-through.
    pub walk: WalkThrough,
    /// Save, open, share.
    pub files: FilesPanel,
    /// The tool shown last frame, to tell a tool just opened.
    shown: Option<Tool>,
    /// The tool that was open when the lesson deck's opened: the one a step added then keeps.
    pub before_deck: Option<Tool>,
}

impl Tools {
    /// The switches for the top bar: clicking the open tool closes it. In presentation, where
    /// the bar keeps one row, each shows its icon only (its name stays its accessible name and
    /// its hover), and the lesson deck's only while a deck is open (`deck_open`) or its tool
    /// is: a deck is built at the desk.
    pub(super) fn bar(&mut self, ui: &mut Ui, presenting: bool, deck_open: bool) {
        let deck_shown = !presenting || deck_open || self.open == Some(Tool::Deck);
        for tool in Tool::ALL
            .into_iter()
            .filter(|t| *t != Tool::Deck || deck_shown)
        {
            let open = self.open == Some(tool);
            let label = tool.label();
            let compact = presenting;
            let shown = if compact {
                label.split_whitespace().next().unwrap_or_default()
            } else {
                label.as_str()
            };
            let switch = ui.selectable_label(open, shown);
            if compact {
                switch.widget_info(|| WidgetInfo::selected(Role::Button, true, open, &label));
            }
            let switch = if compact {
                switch.on_hover_text(&label)
            } else {
                switch
            };
            if switch.clicked() {
                if tool == Tool::Deck && !open {
                    self.before_deck = self.open;
                }
                self.open = if open { None } else { Some(tool) };
            }
        }
    }

    /// The open tool in its panel ([`frame`]); the lesson deck's is the window's to show.
    /// While a step's answer is hidden (`hidden`), a tool that would show it (the plot's
    /// values at θi, the walk-through's numbers, a student's T against the right one) says so
    /// in its place until the reveal.
    pub(super) fn panel(
        &mut self,
        ui: &mut Ui,
        state: &mut ExplorerState,
        (presenting, hidden): (bool, bool),
        palette: &Palette,
    ) {
        self.shown = self.open;
        let Some(tool) = self.open.filter(|t| *t != Tool::Deck) else {
            return;
        };
        frame(ui, tool, presenting).show(ui, |ui| {
            if hidden && tool.shows_the_answer() {
                ui.label(RichText::new(tool.label()).strong());
                ui.label(t!("deck-answer-hidden"));
                return;
            }
            ScrollArea::vertical().show(ui, |ui| match tool {
                Tool::Check => self.check.show(ui, state),
                Tool::WalkThrough => self.walk.show(ui, state),
                Tool::Files => self.files.show(ui, state),
                Tool::Fresnel => fresnel_panel::show(ui, state, palette),
                Tool::Deck => {}
            });
        });
    }

    /// The tool opened since the last frame, if one was.
    #[must_use]
    pub(super) fn just_opened(&self) -> Option<Tool> {
        self.open.filter(|tool| self.shown != Some(*tool))
    }

    /// Opens a file dropped on the window as a log in Check my T, which opens (a renderer's
    /// log is what a student drops; a state or scene has its own Open).
    pub(super) fn take_dropped(&mut self, ctx: &egui::Context) {
        let dropped = ctx.input(|i| i.raw.dropped_files.first().map(|f| f.path().to_path_buf()));
        if let Some(path) = dropped {
            self.open = Some(Tool::Check);
            self.check.open_log(&path);
        }
    }

    /// What the walk-through highlights, while it is open.
    #[must_use]
    pub(super) fn focus(&self, state: &ExplorerState) -> Option<Focus> {
        (self.open == Some(Tool::WalkThrough))
            .then(|| self.walk.focus(state))
            .flatten()
    }

    /// The student's T to draw (whether or not its panel is open, while its case is shown).
    #[must_use]
    pub(super) fn student(&self, state: &ExplorerState) -> Option<StudentRay> {
        self.check.student(state)
    }
}

/// The panel `tool` is shown in: under the diagram at the desk; beside it in presentation,
/// where the window is wide for its height and a strip across the bottom would squeeze the
/// diagram into a letterbox.
pub(super) fn frame(ui: &Ui, tool: Tool, presenting: bool) -> Panel {
    let window = ui.ctx().content_rect();
    if presenting {
        let width = window.width() * tool.presentation_share();
        Panel::right(format!("{tool:?}-presentation"))
            .resizable(false)
            .exact_size(width)
    } else {
        // A panel only grows to what its scroll area was given last frame: each tool asks
        // for the height its verdict or step needs (at most 45 % of the window), and can
        // be dragged taller.
        let limit = window.height() * 0.45;
        let height = tool.height().min(limit);
        Panel::bottom(format!("{tool:?}"))
            .resizable(true)
            .size_range(height..=limit.max(height))
    }
}
