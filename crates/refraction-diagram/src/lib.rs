//! What the explorer draws, computed from an [`ExplorerState`](refraction_model::ExplorerState)
//! and the kernel's answer for it,
//! or from a traced scene: shapes with colours, widths, dash patterns and anchored labels, in
//! canvas pixels. No egui and no tiny-skia here: the screen (the explorer's window) and the PNG
//! (`refraction-render`) both draw [`Diagram::primitives`] and [`ScenePicture::primitives`], so
//! what a teacher exports is what the class saw.
//!
//! - [`layout`]: where things go on a canvas of a given size;
//! - [`overlay`]: what is drawn over the state: palette, pan and zoom, a student's T, the
//!   walk-through's highlights;
//! - [`picture`]: the interface diagram itself;
//! - [`scene_picture`]: a traced scene ([`refraction_scene`]), with [`spectrum`] colouring its rays;
//! - [`shapes`], [`geometry`], [`palette`], [`font`]: its vocabulary;
//! - [`placer`]: the one label placer of every view: labels inside the canvas, off what they name;
//! - [`table`], [`equations`], [`quadratic`]: the numbers shown beside it;
//! - [`plot`]: what the plots share: axes, markers whose shapes differ, a legend clear of the data;
//! - [`accuracy_plot`]: the `bench` report as error against time;
//! - [`failure_map`]: a judged log's error against the angle of incidence, a panel per side;
//! - [`animation`]: the frames of the animations exported for slides;
//! - [`fresnel_plot`]: reflectance and transmittance against the angle of incidence;
//! - [`intensities`]: the share of the light each ray carries, for s, p or unpolarised light;
//! - [`walkthrough`]: the paper's derivation step by step with the live numbers;
//! - [`wavefronts`]: why it bends: the fronts λ/μ apart, their speeds, Huygens's construction.

pub mod accuracy_plot;
pub mod animation;
mod buckets;
pub mod equations;
pub mod failure_map;
pub mod font;
pub mod fresnel_plot;
pub mod geometry;
pub mod intensities;
mod lattice;
pub mod layout;
pub mod numbers;
pub mod obstacle;
mod obstacle_grid;
pub mod overlay;
pub mod palette;
pub mod picture;
pub mod placer;
pub mod plot;
pub mod qr;
pub mod quadratic;
pub mod scene_picture;
pub mod scene_words;
pub mod shapes;
pub mod spectrum;
pub mod table;
pub mod walkthrough;
pub mod wavefronts;

pub use layout::Layout;
pub use overlay::{Focus, Overlay};
pub use picture::{Diagram, Handle};
pub use scene_picture::{SceneHandle, SceneHandleId, SceneLayout, ScenePicture};
pub use shapes::{Align, Primitive};
