//! The scene file as written (TOML): the serde structures that [`Scene::from_toml`] reads, with
//! the span of every value so that an error points at the value itself, and that
//! [`Scene::to_toml`] fills in (with empty spans) to write a scene back.
//!
//! [`Scene::from_toml`]: super::Scene::from_toml
//! [`Scene::to_toml`]: super::Scene::to_toml

use std::collections::BTreeMap;
use std::fmt;

use serde::de::{self, IgnoredAny, SeqAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize};
use toml::Spanned;

use super::source::SourceKind;

/// Exactly `N` numbers as written, `[x, y]` or `[x, y, z]`: one more is an error, not silently
/// dropped (serde reads a fixed-size array's first `N` entries and ignores the rest).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Numbers<const N: usize>(pub [f64; N]);

impl<const N: usize> Serialize for Numbers<N> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.0)
    }
}

/// A point or vector of a scene: two numbers (scenes are 2D).
pub(super) type Pair = Numbers<2>;

impl<const N: usize> Numbers<N> {
    /// What is expected, in words: `two numbers [x, y]`, `three numbers [x, y, z]`.
    fn expected() -> &'static str {
        match N {
            2 => "two numbers [x, y]",
            3 => "three numbers [x, y, z]",
            _ => "a list of numbers",
        }
    }
}

impl<'de, const N: usize> Deserialize<'de> for Numbers<N> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Exactly<const N: usize>;
        impl<'de, const N: usize> Visitor<'de> for Exactly<N> {
            type Value = Numbers<N>;

            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(Numbers::<N>::expected())
            }

            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Numbers<N>, A::Error> {
                let mut numbers = [0.0; N];
                for (found, slot) in numbers.iter_mut().enumerate() {
                    *slot = seq
                        .next_element()?
                        .ok_or_else(|| de::Error::invalid_length(found, &self))?;
                }
                let mut extra = 0;
                while seq.next_element::<IgnoredAny>()?.is_some() {
                    extra += 1;
                }
                if extra > 0 {
                    let why = if N == 2 { ": scenes are 2D" } else { "" };
                    return Err(de::Error::custom(format!(
                        "expected {}, found {}{why}",
                        Numbers::<N>::expected(),
                        N + extra
                    )));
                }
                Ok(Numbers(numbers))
            }
        }
        deserializer.deserialize_seq(Exactly::<N>)
    }
}

/// A scene file as written.
#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SceneFile {
    pub(super) title: String,
    #[serde(default)]
    pub(super) description: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) background: Option<Spanned<String>>,
    #[serde(default)]
    pub(super) media: BTreeMap<String, Spanned<MediumSpec>>,
    #[serde(default)]
    pub(super) shapes: Vec<Spanned<ShapeTable>>,
    pub(super) source: Spanned<SourceSpec>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) effects: Option<Spanned<EffectsSpec>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) view: Option<Spanned<ViewSpec>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct MediumSpec {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) index: Option<Spanned<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) cauchy: Option<Spanned<CauchySpec>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) sellmeier: Option<Spanned<SellmeierSpec>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) absorption: Option<Spanned<f64>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct CauchySpec {
    pub(super) a: f64,
    pub(super) b: f64,
    #[serde(default)]
    pub(super) c: f64,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SellmeierSpec {
    pub(super) b: Vec<f64>,
    pub(super) c: Vec<f64>,
}

/// One `[[shapes]]` table: exactly one of its fields is given (checked when it is built, so that
/// none or two get a message of their own).
#[derive(Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ShapeTable {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) line: Option<Spanned<LineSpec>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) segment: Option<Spanned<SegmentSpec>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) circle: Option<Spanned<CircleSpec>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) polygon: Option<Spanned<PolygonSpec>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) lens: Option<Spanned<LensSpec>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct LineSpec {
    pub(super) point: Spanned<Pair>,
    pub(super) normal: Spanned<Pair>,
    pub(super) medium: Spanned<String>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SegmentSpec {
    pub(super) from: Spanned<Pair>,
    pub(super) to: Spanned<Pair>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct CircleSpec {
    pub(super) center: Spanned<Pair>,
    pub(super) radius: Spanned<f64>,
    pub(super) medium: Spanned<String>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct PolygonSpec {
    pub(super) points: Spanned<Vec<Spanned<Pair>>>,
    pub(super) medium: Spanned<String>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct LensSpec {
    pub(super) center: Spanned<Pair>,
    pub(super) thickness: Spanned<f64>,
    pub(super) radii: Spanned<Pair>,
    pub(super) medium: Spanned<String>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SourceSpec {
    pub(super) kind: SourceKind,
    pub(super) origin: Spanned<Pair>,
    pub(super) direction: Spanned<Pair>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) rays: Option<Spanned<usize>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) width: Option<Spanned<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) spread_deg: Option<Spanned<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) wavelength_nm: Option<Spanned<f64>>,
    #[serde(default)]
    pub(super) white: bool,
}

/// The `[effects]` table: every key optional, defaults from [`super::Effects::default`].
#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct EffectsSpec {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) partial_reflection: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) fresnel: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) dispersion: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) absorption: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) max_depth: Option<Spanned<u32>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) min_intensity: Option<Spanned<f64>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ViewSpec {
    pub(super) min: Spanned<Pair>,
    pub(super) max: Spanned<Pair>,
}
