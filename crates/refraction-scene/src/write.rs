//! A scene written back as a scene file (TOML), so that a scene edited in the explorer (its
//! source moved, its shapes dragged) can be saved and opened again. It fills in the reader's own
//! file structures (with empty spans), so reading what this writes gives back an equal scene.

use toml::Spanned;

use super::format::{
    CauchySpec, MediumSpec, SceneFile, SellmeierSpec, ShapeSpec, SourceSpec, ViewSpec,
};
use super::{Dispersion, Light, Medium, Scene, Shape, SourceKind};

/// A value with no place in a file: written values carry no span.
fn unplaced<T>(value: T) -> Spanned<T> {
    Spanned::new(0..0, value)
}

fn medium_spec(medium: &Medium) -> MediumSpec {
    let (index, cauchy, sellmeier) = match &medium.dispersion {
        Dispersion::Constant(n) => (Some(*n), None, None),
        Dispersion::Cauchy { a, b, c } => (
            None,
            Some(CauchySpec {
                a: *a,
                b: *b,
                c: *c,
            }),
            None,
        ),
        Dispersion::Sellmeier { b, c } => (
            None,
            None,
            Some(SellmeierSpec {
                b: b.clone(),
                c: c.clone(),
            }),
        ),
    };
    MediumSpec {
        index,
        cauchy,
        sellmeier,
        absorption: medium.absorption,
    }
}

impl Scene {
    fn medium_name(&self, medium: usize) -> Spanned<String> {
        unplaced(
            self.media
                .get(medium)
                .map_or("vacuum", |m| m.name.as_str())
                .to_owned(),
        )
    }

    fn shape_spec(&self, shape: &Shape) -> ShapeSpec {
        match shape {
            Shape::Line {
                point,
                normal,
                medium,
            } => ShapeSpec::Line {
                point: point.to_array(),
                normal: normal.to_array(),
                medium: self.medium_name(*medium),
            },
            Shape::Segment { from, to } => ShapeSpec::Segment {
                from: from.to_array(),
                to: to.to_array(),
            },
            Shape::Circle {
                center,
                radius,
                medium,
            } => ShapeSpec::Circle {
                center: center.to_array(),
                radius: *radius,
                medium: self.medium_name(*medium),
            },
            Shape::Polygon { points, medium } => ShapeSpec::Polygon {
                points: points.iter().map(|p| p.to_array()).collect(),
                medium: self.medium_name(*medium),
            },
            Shape::Lens { lens, medium } => ShapeSpec::Lens {
                center: lens.center.to_array(),
                thickness: lens.thickness,
                radii: lens.radii,
                medium: self.medium_name(*medium),
            },
        }
    }

    fn source_spec(&self) -> SourceSpec {
        let s = &self.source;
        SourceSpec {
            kind: s.kind,
            origin: s.origin.to_array(),
            direction: s.direction.to_array(),
            rays: (s.kind != SourceKind::Ray).then_some(s.rays),
            width: (s.kind == SourceKind::Beam).then_some(s.width),
            spread_deg: (s.kind == SourceKind::Fan).then_some(s.spread_deg),
            wavelength_nm: match s.light {
                Light::Wavelength(nm) => Some(nm),
                Light::White => None,
            },
            white: s.light == Light::White,
        }
    }

    /// The scene as a scene file (TOML) that [`Scene::from_toml`] reads back as an equal scene.
    ///
    /// # Errors
    /// The TOML writer refused a value (it accepts every scene that loaded).
    pub fn to_toml(&self) -> Result<String, WriteError> {
        // The built-in vacuum comes first when a file defines none: leave it implicit so that
        // the media keep their order when read back.
        let implicit_vacuum = self.media.first().is_some_and(|m| *m == Medium::vacuum());
        let media = self
            .media
            .iter()
            .skip(usize::from(implicit_vacuum))
            .map(|m| (m.name.clone(), unplaced(medium_spec(m))))
            .collect();
        let file = SceneFile {
            title: self.title.clone(),
            description: self.description.clone(),
            background: Some(self.medium_name(self.background)),
            media,
            shapes: self
                .shapes
                .iter()
                .map(|s| unplaced(self.shape_spec(s)))
                .collect(),
            source: unplaced(self.source_spec()),
            effects: Some(unplaced(self.effects)),
            view: self.view.map(|v| {
                unplaced(ViewSpec {
                    min: v.min.to_array(),
                    max: v.max.to_array(),
                })
            }),
        };
        toml::to_string(&file).map_err(WriteError)
    }
}

/// The TOML writer refused a scene ([`Scene::to_toml`]); it accepts every scene that loaded.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("cannot write the scene as TOML: {0}")]
pub struct WriteError(toml::ser::Error);

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn every_built_in_scene_reads_back_equal_even_after_edits() {
        for info in crate::catalogue() {
            let mut scene = Scene::embedded(info.name).unwrap();
            let text = scene.to_toml().unwrap();
            let back = Scene::from_toml(&text, "written", info.name)
                .unwrap_or_else(|e| panic!("{}: {e}\n{text}", info.name));
            assert_eq!(back, scene, "{}", info.name);
            scene.set_source_origin(DVec2::new(0.125, -0.5)).unwrap();
            scene.move_shape(0, DVec2::new(0.25, 0.0)).unwrap();
            let edited = Scene::from_toml(&scene.to_toml().unwrap(), "edited", info.name).unwrap();
            assert_eq!(edited, scene, "{} after edits", info.name);
        }
    }
}
