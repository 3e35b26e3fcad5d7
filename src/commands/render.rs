//! `render`: the explorer's diagram or a traced scene as a PNG or an SVG, or an animation of
//! the diagram as a GIF.

use refraction_tools::{StateFileError, open_state_file};
use std::io::{self, IsTerminal as _};
use std::path::Path;
use std::process::ExitCode;

use refraction_diagram::{Animation, Overlay};
use refraction_explorer::cli::{RenderArgs, ViewArg};
use refraction_model::ExplorerState;
use refraction_render::{
    self as render, ImageFormat, Picture, animation::AnimationSpec, handout::Sheet, svg::Labels,
};
use refraction_scene::Scene;

use super::inputs::{Input, OtherKind, OutputIsInput, kind_of, refuse_inputs, refuse_other_kinds};
use super::output::ProgressLine;
use super::{fail, output, output_error};

/// The still formats: what `render` without `--animate` and `bench --plot` write.
pub(crate) const STILL: [ImageFormat; 2] = [ImageFormat::Png, ImageFormat::Svg];

/// Why `render` (or `bench --plot`) refuses what it was asked, or cannot draw it: each worded
/// once, in the commands' English, naming the option and the path.
#[derive(Debug, thiserror::Error)]
pub(crate) enum RenderFailure {
    /// The path's extension names no format written.
    #[error(transparent)]
    Format(#[from] refraction_render::UnsupportedFormat),
    /// A format written, but not by this option.
    #[error(
        "{option} {path}: `.{extension}` ({name}) is not written here; give a name ending in \
         {allowed}{hint}"
    )]
    NotWrittenHere {
        /// The option that named the path (`--out`, `--plot`).
        option: String,
        /// The path, as given.
        path: String,
        /// Its format's extension.
        extension: &'static str,
        /// Its format's name.
        name: &'static str,
        /// The extensions this option writes, joined by "or".
        allowed: String,
        /// Where the format is written instead, if anywhere.
        hint: &'static str,
    },
    /// The path cannot be written (a missing folder, a directory, no permission).
    #[error(transparent)]
    Unwritable(std::io::Error),
    /// `-` given where standard output already carries the command's own output.
    #[error(
        "{0} - is not allowed here: standard output has the command's own output; give a file \
         name (./- for a file named -)"
    )]
    StdoutNotAllowed(String),
    /// `-` given while standard output is a terminal.
    #[error(
        "{option} - writes {name} bytes to standard output, which is a terminal: redirect it \
         (> file.{extension}, | viewer) or give a file name"
    )]
    StdoutIsTerminal {
        /// The option (`--out`).
        option: String,
        /// The format's name.
        name: &'static str,
        /// The format's extension.
        extension: &'static str,
    },
    /// The state file cannot be read.
    #[error(transparent)]
    State(#[from] StateFileError),
    /// The scene cannot be loaded.
    #[error(transparent)]
    Scene(#[from] refraction_scene::LoadError),
    /// The picture cannot be drawn (a bad size, an animation's limits, an encoder).
    #[error(transparent)]
    Render(#[from] render::RenderError),
    /// Both a scene and a state file.
    #[error(
        "give a SCENE ({scene}) or --state ({state}), not both: --state is the single-interface \
         problem, SCENE a traced scene"
    )]
    SceneAndState {
        /// The scene named.
        scene: String,
        /// The state file named.
        state: String,
    },
    /// `--view` with a scene.
    #[error(
        "--view draws the single interface's views, not a scene ({0}): give --state or nothing"
    )]
    ViewOfScene(String),
    /// `--animate` with a scene.
    #[error("--animate draws the single interface, not a scene ({0}): give --state or nothing")]
    AnimatedScene(String),
    /// `--animate` with another view than the diagram.
    #[error("--animate draws the diagram: leave out --view")]
    AnimatedView,
    /// The progress line could not be written.
    #[error("cannot write the progress to stderr: {0}")]
    Progress(std::io::Error),
    /// `--out` names the state file or the scene file read.
    #[error(transparent)]
    OutputIsInput(#[from] OutputIsInput),
    /// `--out` (or `--plot`) names a file of another kind.
    #[error(transparent)]
    OtherKind(#[from] OtherKind),
}

/// Where an image goes: a file, written by [`refraction_files::write_atomically`], or stdout (`-`).
#[derive(Clone, Copy, Debug)]
pub(crate) enum Destination<'a> {
    /// A file (or a FIFO, or a device).
    File(&'a Path),
    /// Standard output.
    Stdout,
}

/// The format `path` asks for, one of `formats`: by its extension, or the first of `formats`
/// for a path without one (`-`, `/dev/stdout`).
///
/// # Errors
/// An extension that names no format written, or one not among `formats`, naming the path
/// and what may be written there.
pub(crate) fn format_of(
    path: &Path,
    option: &str,
    formats: &[ImageFormat],
) -> Result<ImageFormat, RenderFailure> {
    let format = match path.extension() {
        None => formats.first().copied().unwrap_or(ImageFormat::Png),
        Some(_) => ImageFormat::for_path(path)?,
    };
    if formats.contains(&format) {
        return Ok(format);
    }
    let allowed: Vec<String> = formats
        .iter()
        .map(|f| format!(".{}", f.extension()))
        .collect();
    let hint = if format == ImageFormat::Gif {
        " (a GIF is written by render --animate mu|sweep|wavefronts)"
    } else {
        ""
    };
    Err(RenderFailure::NotWrittenHere {
        option: option.to_owned(),
        path: path.display().to_string(),
        extension: format.extension(),
        name: format.name(),
        allowed: allowed.join(" or "),
        hint,
    })
}

impl<'a> Destination<'a> {
    /// Checks `path` as an image destination before any work is done: its format is one of
    /// `formats` ([`format_of`]); a file's folder exists and what is at the path can be
    /// written ([`refraction_files::check_writable`]); `-` means stdout where `stdout_allowed`, and
    /// stdout must then be neither a terminal nor closed.
    ///
    /// # Errors
    /// What is wrong with the path, naming it.
    pub(crate) fn check(
        path: &'a Path,
        option: &str,
        stdout_allowed: bool,
        formats: &[ImageFormat],
    ) -> Result<Self, RenderFailure> {
        let format = format_of(path, option, formats)?;
        if path != Path::new("-") {
            refraction_files::check_writable(path).map_err(RenderFailure::Unwritable)?;
            return Ok(Self::File(path));
        }
        if !stdout_allowed {
            return Err(RenderFailure::StdoutNotAllowed(option.to_owned()));
        }
        if io::stdout().is_terminal() {
            return Err(RenderFailure::StdoutIsTerminal {
                option: option.to_owned(),
                name: format.name(),
                extension: format.extension(),
            });
        }
        Ok(Self::Stdout)
    }

    /// Writes `bytes` there; `command` names the command in a failure's message.
    pub(crate) fn write(self, command: &str, bytes: &[u8]) -> ExitCode {
        match self {
            Self::File(path) => refraction_files::write_atomically(path, bytes)
                .map_or_else(|e| fail(command, &e), |()| ExitCode::SUCCESS),
            Self::Stdout => output::to_stdout(bytes)
                .map_or_else(|e| output_error(command, &e), |()| ExitCode::SUCCESS),
        }
    }
}

fn initial_state(path: Option<&Path>) -> Result<ExplorerState, RenderFailure> {
    Ok(path.map_or_else(|| Ok(ExplorerState::default()), open_state_file)?)
}

/// The picture asked for, as the bytes of a `format` file: `scene` traced, or else the state
/// in `state` (or the default). The size is checked before the scene is traced.
fn picture(args: &RenderArgs, format: ImageFormat) -> Result<Vec<u8>, RenderFailure> {
    let size = (args.width, args.height);
    let labels = if args.svg_text {
        Labels::Text
    } else {
        Labels::Outlined
    };
    let format = (format, labels);
    render::check_size(size.0, size.1)?;
    let out = args.out.as_path();
    match (&args.scene, &args.state) {
        (Some(scene), Some(state)) => Err(RenderFailure::SceneAndState {
            scene: scene.clone(),
            state: state.display().to_string(),
        }),
        (Some(scene), None) if args.view != ViewArg::Interface => {
            Err(RenderFailure::ViewOfScene(scene.clone()))
        }
        (Some(scene), None) => {
            let s = Scene::load(scene)?;
            Ok(render::still(Picture::Scene(&s), format, size, out)?)
        }
        (None, state) => {
            let s = initial_state(state.as_deref())?;
            view_file(args.view, &s, format, size, out)
        }
    }
}

/// The single interface's `view` of `state` as the bytes of a `format` file of `size`.
fn view_file(
    view: ViewArg,
    state: &ExplorerState,
    format: (ImageFormat, Labels),
    size: (u32, u32),
    out: &Path,
) -> Result<Vec<u8>, RenderFailure> {
    let overlay = Overlay::default();
    let drawn = match view {
        ViewArg::Interface => {
            let picture = Picture::Interface {
                state,
                overlay: &overlay,
            };
            render::still(picture, format, size, out)
        }
        ViewArg::Fresnel => render::still(Picture::FresnelPlot(state), format, size, out),
        ViewArg::Accuracy => {
            let mut progress = ProgressLine::on_terminal("measuring...");
            let config = refraction_bench::Config::QUICK;
            let report = refraction_bench::run(&config, &mut |f| progress.update(f));
            if let Some(e) = progress.finish() {
                return Err(RenderFailure::Progress(e));
            }
            render::still(Picture::AccuracyPlot(&report), format, size, out)
        }
    };
    Ok(drawn?)
}

/// The animation asked for as GIF bytes, with a progress line on a terminal. The frames, rate
/// and size are checked before the state file is read.
fn animation(args: &RenderArgs, animation: Animation) -> Result<Vec<u8>, RenderFailure> {
    if let Some(scene) = &args.scene {
        return Err(RenderFailure::AnimatedScene(scene.clone()));
    }
    if args.view != ViewArg::Interface {
        return Err(RenderFailure::AnimatedView);
    }
    let mut spec = AnimationSpec::new(animation, (args.width, args.height));
    spec.frames = args.frames.unwrap_or(spec.frames);
    spec.fps = args.fps.unwrap_or(spec.fps);
    spec.check()?;
    let start = initial_state(args.state.as_deref())?;
    let mut progress = ProgressLine::on_terminal("drawing frames...");
    let drawn = render::animation::gif(&start, &Overlay::default(), &spec, |done, all| {
        progress.update(done as f64 / all as f64);
        true
    });
    let failed = progress.finish();
    let bytes = drawn?;
    match failed {
        Some(e) => Err(RenderFailure::Progress(e)),
        None => Ok(bytes),
    }
}

/// The files `render` reads for `args`: the state file, or a scene's file (not a built-in
/// scene).
fn inputs_of(args: &RenderArgs) -> Vec<Input> {
    let state = args.state.iter().map(|path| Input {
        path: path.clone(),
        what: "the state file",
    });
    let scene = args
        .scene
        .iter()
        .filter(|name| Scene::embedded(name).is_err())
        .map(|name| Input {
            path: name.into(),
            what: "the scene file",
        });
    state.chain(scene).collect()
}

/// Draws what `args` ask for into `--out` (`-`: stdout): a picture of the single interface or
/// of a traced scene as PNG or SVG, or with `--animate` an animated GIF. The output path (never
/// a file read), the size and the animation's frames and rate are checked before anything is
/// traced or drawn.
pub(crate) fn run(args: &RenderArgs) -> ExitCode {
    if let Some(lesson) = &args.lesson {
        let sheet = if args.students {
            Sheet::Students
        } else {
            Sheet::Teacher
        };
        let size = (args.width, args.height);
        let out = (sheet, args.web_base.as_deref());
        return super::lessons::render(lesson, &args.out, size, out);
    }
    let formats: &[ImageFormat] = match args.animate {
        Some(_) => &[ImageFormat::Gif],
        None => &STILL,
    };
    let drawn = Destination::check(&args.out, "--out", true, formats).and_then(|to| {
        // Standard output too may be a file read (`--out - >> state.svg`).
        let path = match to {
            Destination::File(path) => path,
            Destination::Stdout => Path::new("/dev/stdout"),
        };
        refuse_inputs([path], "--out", &inputs_of(args))?;
        let format = format_of(&args.out, "--out", formats)?;
        refuse_other_kinds([path], "--out", kind_of(format))?;
        let bytes = match args.animate {
            Some(a) => animation(args, a),
            None => format_of(&args.out, "--out", formats).and_then(|f| picture(args, f)),
        };
        bytes.map(|bytes| (to, bytes))
    });
    match drawn {
        Ok((to, bytes)) => to.write("render", &bytes),
        Err(message) => fail("render", &message),
    }
}
