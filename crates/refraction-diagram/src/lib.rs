//! What the explorer draws, computed from an [`ExplorerState`](refraction_model::ExplorerState)
//! and the kernel's answer for it,
//! or from a traced scene: shapes with colours, widths, dash patterns and anchored labels, in
//! canvas pixels. No egui and no tiny-skia here: the screen (the explorer's window) and the PNG
//! (`refraction-render`) both draw [`Diagram::primitives`] and [`ScenePicture::primitives`], so
//! what a teacher exports is what the class saw.
//!
//! Its face is its root; the modules are private but for three namespaces:
//!
//! - [`Layout`]: where things go on a canvas of a given size;
//! - [`Overlay`]: what is drawn over the state: [`palette`], [`PanZoom`], a student's T
//!   ([`StudentRay`]), the walk-through's highlights ([`Focus`]), the light's shares
//!   ([`Shares`]) and the wavefronts ([`WaveOptions`]);
//! - [`Diagram`]: the interface diagram itself, and [`diagram_summary`], what it says in words;
//! - [`ScenePicture`]: a traced scene ([`refraction_scene`]), [`ray_colour`] colouring its
//!   rays, [`scene_title`] and [`scene_description`] saying it in words;
//! - [`Primitive`], [`Figure`], [`Label`], [`Colour`], [`Typeface`], [`palette`]: the
//!   vocabulary;
//! - [`Placer`]: the one label placer of every view: labels inside the canvas, off what they name;
//! - [`candidate_rows`], [`equations`], [`Quadratic`], [`numbers`]: the numbers shown beside it;
//! - [`accuracy_plot`]: the `bench` report as error against time;
//! - [`failure_map`]: a judged log's error against the angle of incidence, a panel per side;
//! - [`Animation`]: the frames of the animations exported for slides;
//! - [`FresnelPlot`]: reflectance and transmittance against the angle of incidence;
//! - [`walkthrough_steps`]: the paper's derivation step by step with the live numbers;
//! - [`QrCode`]: a link as a QR code drawn with the same primitives.

mod accuracy_plot;
mod animation;
mod buckets;
mod equations;
pub mod failure_map;
mod font;
mod fresnel_plot;
mod geometry;
mod intensities;
mod lattice;
mod layout;
pub mod numbers;
mod obstacle;
mod obstacle_grid;
mod overlay;
pub mod palette;
mod picture;
mod placer;
mod plot;
mod qr;
mod quadratic;
mod scene_picture;
mod scene_words;
mod shapes;
mod spectrum;
mod table;
mod walkthrough;
mod wavefronts;

pub use accuracy_plot::{accuracy_markers, accuracy_plot, accuracy_point_label};
pub use animation::{ANIMATION_FPS, ANIMATION_FRAMES, Animation, AnimationFrame};
pub use equations::{Equation, equations};
pub use font::Typeface;
pub use fresnel_plot::{FresnelCurve, FresnelPlot, PlotFrame, fresnel_plot};
pub use geometry::{Colour, Rect};
pub use intensities::Shares;
pub use layout::{IndexScale, Layout, PanZoom, SMALLEST_TEXT, Viewport, ZOOM_RANGE};
pub use obstacle::Obstacle;
pub use overlay::{Focus, Overlay, StudentRay, VectorNames};
pub use picture::{Diagram, Handle, TOUCH_TARGET, diagram_summary};
pub use placer::{Need, Placement, Placer, wrap_breaking_words};
pub use qr::{QrCode, QrTooLong};
pub use quadratic::{Quadratic, quadratic_plot};
pub use scene_picture::{SceneHandle, SceneHandleId, SceneLayout, ScenePicture};
pub use scene_words::{built_in_scene_title, medium_name, scene_description, scene_title};
pub use shapes::{
    Align, ArrowRole, Dash, Figure, LABEL_PAD, Label, Primitive, Stroke, primitive_texts,
};
pub use spectrum::{ray_colour, wavelength_colour};
pub use table::{CandidateRow, candidate_rows};
pub use walkthrough::{WalkthroughStep, walkthrough_steps};
pub use wavefronts::WaveOptions;
