//! A link as a QR code, drawn with the diagram's own primitives, so that the window, a PNG or
//! SVG file and the handout show the same code: dark modules on a light square with the quiet
//! zone the standard asks for (four modules), whatever the theme, since phones read dark on
//! light. The code itself is the `qrcode` crate's (error correction level M: a code on a
//! projector or a printed page survives a smudge of 15 %).

use glam::Vec2;
use qrcode::{Color, EcLevel};

use crate::geometry::Colour;
use crate::shapes::Primitive;

/// The modules of light margin around the code (the standard's quiet zone).
pub(crate) const QUIET_ZONE: usize = 4;

/// The dark modules' colour.
pub(crate) const DARK: Colour = Colour::hex(0x000000);

/// The light square's colour.
pub(crate) const LIGHT: Colour = Colour::hex(0xffffff);

/// Why a text has no QR code.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
// untranslated: for developers; the window says `link-qr-too-long`.
#[error("the link is too long for a QR code ({0} bytes)")]
pub struct QrTooLong(pub usize);

/// A QR code: a square of modules, each dark or light.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct QrCode {
    /// Modules per side, without the quiet zone.
    width: usize,
    /// Row after row, `true` for a dark module.
    dark: Vec<bool>,
}

impl QrCode {
    /// The QR code of `text` (a link: its bytes as they are).
    ///
    /// # Errors
    /// The text is longer than the largest code holds at level M (about 2,300 bytes).
    pub fn new(text: &str) -> Result<Self, QrTooLong> {
        let code = qrcode::QrCode::with_error_correction_level(text.as_bytes(), EcLevel::M)
            .map_err(|_data_too_long| QrTooLong(text.len()))?;
        Ok(Self {
            width: code.width(),
            dark: code
                .to_colors()
                .into_iter()
                .map(|c| c == Color::Dark)
                .collect(),
        })
    }

    /// Modules per side, quiet zone included.
    #[must_use]
    pub fn side_in_modules(&self) -> usize {
        self.width + 2 * QUIET_ZONE
    }

    /// Whether the module at `column`, `row` (from the top left, quiet zone excluded) is dark.
    #[must_use]
    pub(crate) fn is_dark(&self, column: usize, row: usize) -> bool {
        column < self.width && row < self.width && self.dark[row * self.width + column]
    }

    /// The code as primitives in a square of `side` pixels whose top left corner is `at`
    /// (quiet zone included): the light square, then each row's runs of dark modules as one
    /// rectangle, each a hair taller than its row so that no seam shows between rows when
    /// the edges are smoothed.
    #[must_use]
    pub fn primitives(&self, at: Vec2, side: f32) -> Vec<Primitive> {
        let module = side / self.side_in_modules() as f32;
        let overlap = (module * 0.1).min(0.5);
        let corner = |x: f32, y: f32| at + Vec2::new(x, y);
        let mut out = vec![Primitive::Polygon {
            points: vec![
                corner(0.0, 0.0),
                corner(side, 0.0),
                corner(side, side),
                corner(0.0, side),
            ],
            colour: LIGHT,
        }];
        for row in 0..self.width {
            let mut column = 0;
            while column < self.width {
                if !self.is_dark(column, row) {
                    column += 1;
                    continue;
                }
                let start = column;
                while self.is_dark(column, row) {
                    column += 1;
                }
                let (x0, x1) = ((start + QUIET_ZONE) as f32, (column + QUIET_ZONE) as f32);
                let y0 = (row + QUIET_ZONE) as f32 * module;
                let y1 = y0 + module + overlap;
                out.push(Primitive::Polygon {
                    points: vec![
                        corner(x0 * module, y0),
                        corner(x1 * module, y0),
                        corner(x1 * module, y1),
                        corner(x0 * module, y1),
                    ],
                    colour: DARK,
                });
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_link_becomes_a_square_of_modules_in_a_quiet_zone() {
        let link = "https://school.example/explorer/#lesson=snell&step=2";
        let code = QrCode::new(link).unwrap();
        assert_eq!((code.width - 17) % 4, 0, "a QR version's size: 17 + 4v");
        // The three finder patterns: dark 7×7 corners.
        for (c, r) in [(0, 0), (code.width - 7, 0), (0, code.width - 7)] {
            assert!(
                code.is_dark(c, r) && code.is_dark(c + 6, r + 6) && !code.is_dark(c + 1, r + 1)
            );
        }
        let drawn = code.primitives(Vec2::new(10.0, 20.0), 330.0);
        let Primitive::Polygon { points, colour } = &drawn[0] else {
            panic!("the light square comes first");
        };
        assert_eq!(
            (points[0], points[2], *colour),
            (Vec2::new(10.0, 20.0), Vec2::new(340.0, 350.0), LIGHT)
        );
        let module = 330.0 / code.side_in_modules() as f32;
        let dark: f32 = drawn[1..]
            .iter()
            .map(|p| match p {
                Primitive::Polygon { points, colour } if *colour == DARK => {
                    assert!(points.iter().all(|p| p.x >= 10.0 + 4.0 * module - 1e-3));
                    (points[1].x - points[0].x) / module
                }
                other => panic!("only dark runs follow: {other:?}"),
            })
            .sum();
        let counted = code.dark.iter().filter(|d| **d).count() as f32;
        assert!(
            (dark - counted).abs() < 0.01,
            "{dark} modules drawn, {counted} dark"
        );
        assert_eq!(QrCode::new(&"x".repeat(5000)), Err(QrTooLong(5000)));
    }
}
