//! Which image format an output path asks for, decided by its extension in one place, so that
//! no command writes PNG bytes under a JPEG name.

use std::path::Path;

/// An image format this crate writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageFormat {
    /// Portable Network Graphics (`.png`).
    Png,
    /// Scalable Vector Graphics (`.svg`): shapes as paths, labels outlined or as text.
    Svg,
    /// An animated GIF (`.gif`), written by the animations only.
    Gif,
}

/// Every format written, in the order the messages list them.
pub const FORMATS: [ImageFormat; 3] = [ImageFormat::Png, ImageFormat::Svg, ImageFormat::Gif];

/// The extension of a path names no format this crate writes.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "cannot write {path}: `.{extension}` is not a format this program writes; it writes {}",
    written()
)]
pub struct UnsupportedFormat {
    /// The path as given.
    pub path: String,
    /// Its extension, as written.
    pub extension: String,
}

fn written() -> String {
    let names: Vec<String> = FORMATS
        .iter()
        .map(|f| format!("{} (.{})", f.name(), f.extension()))
        .collect();
    names.join(", ")
}

impl ImageFormat {
    /// The format's usual name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Png => "PNG",
            Self::Svg => "SVG",
            Self::Gif => "GIF",
        }
    }

    /// The file extension, lower case, without the dot.
    #[must_use]
    pub fn extension(self) -> &'static str {
        match self {
            Self::Png => "png",
            Self::Svg => "svg",
            Self::Gif => "gif",
        }
    }

    /// The format `path` asks for by its extension (compared without regard to case). A path
    /// without an extension (`/dev/stdout`, a FIFO, `-`) gets PNG.
    ///
    /// # Errors
    /// The extension names no format in [`FORMATS`]; the message names the path and lists the
    /// formats written.
    pub fn for_path(path: &Path) -> Result<Self, UnsupportedFormat> {
        let Some(extension) = path.extension() else {
            return Ok(Self::Png);
        };
        let extension = extension.to_string_lossy();
        FORMATS
            .into_iter()
            .find(|f| extension.eq_ignore_ascii_case(f.extension()))
            .ok_or_else(|| UnsupportedFormat {
                path: path.display().to_string(),
                extension: extension.into_owned(),
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_extension_decides_in_any_case_and_others_are_refused_by_name() {
        for name in ["a.png", "a.PNG", "dir.x/a.Png", "a", "-", "/dev/stdout"] {
            assert_eq!(ImageFormat::for_path(Path::new(name)), Ok(ImageFormat::Png));
        }
        for (name, format) in [("a.svg", ImageFormat::Svg), ("b.GIF", ImageFormat::Gif)] {
            assert_eq!(ImageFormat::for_path(Path::new(name)), Ok(format));
        }
        let err = ImageFormat::for_path(Path::new("out/x.jpg")).unwrap_err();
        assert_eq!(
            err.to_string(),
            "cannot write out/x.jpg: `.jpg` is not a format this program writes; it writes PNG \
             (.png), SVG (.svg), GIF (.gif)"
        );
        assert!(ImageFormat::for_path(Path::new("x.")).is_err());
    }
}
