//! The keywords of `refraction_check.check` that are `check`'s options (`api`, `inside`,
//! `outside`, `normal`, `convention`, `precision`, `renderer`), checked as the command line
//! checks them, into [`Options`].

use refraction_check::{Dialect, Options, Renderer};
use refraction_kernel::Convention;
use refraction_kernel::api::Api;
use refraction_tools::{Precision, vector_text::parse_vector};

use crate::ArgumentError;

/// `normal` as Python gave it.
#[derive(Clone, Debug, PartialEq)]
pub enum Normal {
    /// A word: an axis (`"+z"`, `"-y"`, `"x"`) or three numbers as programs print them.
    Text(String),
    /// Three numbers.
    Vector([f64; 3]),
}

/// The option keywords as Python gave them (`None` where not given).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Given {
    /// `inside`: the index inside the object.
    pub inside: Option<f64>,
    /// `outside`: the index outside the object.
    pub outside: Option<f64>,
    /// `normal`: the outward normal of calls that log none.
    pub normal: Option<Normal>,
    /// `convention`: `"along-ray"` or `"toward-origin"` (or with an underscore).
    pub convention: Option<String>,
    /// `precision`: `"f32"` or `"f64"` (`"float"`, `"double"`).
    pub precision: Option<String>,
    /// `renderer`: whose code the calls come from, for the words of the fixes.
    pub renderer: Option<String>,
    /// The precision the arrays themselves hold: f32 when an argument is `float32` (or
    /// narrower), which no f64 code would give; used when `precision` is not given.
    pub arrays: Option<Precision>,
}

// untranslated: the words each option takes, as the messages list them
const CONVENTIONS: &str = "along-ray, toward-origin";
// untranslated: the words each option takes, as the messages list them
const PRECISIONS: &str = "f32, f64";
/// The renderers `renderer` names, as the messages list them.
// untranslated: the words each option takes, as the messages list them
pub(crate) const RENDERERS: &str =
    "mitsuba, tungsten, cycles, threejs, pbrt, smallpt, rtiow, glsl, glam, mitsuba-python";

/// The dialect `api` names: an API's (`glsl`, `hlsl`, `pbrt`, `rtiow`, `mitsuba`...), or any
/// renderer's own refraction when `None`.
///
/// # Errors
/// A name that is none of them.
pub fn dialect(api: Option<&str>) -> Result<Dialect, ArgumentError> {
    match api {
        None => Ok(Dialect::Physics),
        Some(name) => {
            Api::from_name(name)
                .map(Dialect::Api)
                .ok_or_else(|| ArgumentError::UnknownApi {
                    name: name.to_owned(),
                })
        }
    }
}

/// An index of refraction: a finite number > 0, as `--inside` and `--outside` take.
fn index(argument: &'static str, value: Option<f64>) -> Result<Option<f64>, ArgumentError> {
    match value {
        Some(x) if !(x.is_finite() && x > 0.0) => Err(ArgumentError::Index {
            argument,
            value: x.to_string(),
        }),
        _ => Ok(value),
    }
}

/// `normal` as a vector: an axis, three numbers, finite and not zero.
fn normal(given: &Normal) -> Result<[f64; 3], ArgumentError> {
    let refused = |value: String| ArgumentError::Normal { value };
    let v = match given {
        Normal::Vector(v) => *v,
        Normal::Text(text) => {
            let word = text.trim().to_ascii_lowercase();
            let (sign, axis) = match word.strip_prefix('-') {
                Some(axis) => (-1.0, axis),
                None => (1.0, word.strip_prefix('+').unwrap_or(&word)),
            };
            match ["x", "y", "z"].iter().position(|a| *a == axis) {
                Some(i) => core::array::from_fn(|j| if i == j { sign } else { 0.0 }),
                None => {
                    parse_vector(text)
                        .map_err(|_not_a_vector| refused(text.clone()))?
                        .value
                }
            }
        }
    };
    if v.iter().all(|c| c.is_finite()) && v != [0.0; 3] {
        Ok(v)
    } else {
        Err(refused(format!("{v:?}")))
    }
}

/// A word option: the value `known` gives for it, or why it names nothing.
fn word<T>(
    argument: &'static str,
    given: Option<&String>,
    expected: &'static str,
    known: impl Fn(&str) -> Option<T>,
) -> Result<Option<T>, ArgumentError> {
    given
        .map(|text| {
            known(text).ok_or_else(|| ArgumentError::UnknownWord {
                argument,
                value: text.clone(),
                expected,
            })
        })
        .transpose()
}

/// The precision a word names.
fn precision(name: &str) -> Option<Precision> {
    match name.to_ascii_lowercase().as_str() {
        "f32" | "float" | "float32" => Some(Precision::F32),
        "f64" | "double" | "float64" => Some(Precision::F64),
        _ => None,
    }
}

/// `check`'s options for `dialect` from the keywords `given`, checked as the command line
/// checks them: both indices or neither, each finite and > 0; `normal` and `convention` only
/// for any renderer's own refraction (without `api`); known words.
///
/// # Errors
/// The first keyword that cannot be used, named.
pub fn options(dialect: Dialect, given: &Given) -> Result<Options, ArgumentError> {
    let mut options = Options::new(dialect);
    options.inside = index("inside", given.inside)?;
    options.outside = index("outside", given.outside)?;
    match (options.inside, options.outside) {
        (Some(_), None) => return Err(sides_apart("inside", "outside")),
        (None, Some(_)) => return Err(sides_apart("outside", "inside")),
        _ => {}
    }
    let physics_only = [
        ("normal", given.normal.is_some()),
        ("convention", given.convention.is_some()),
    ];
    if let (Dialect::Api(_), Some((argument, _))) =
        (dialect, physics_only.iter().find(|(_, given)| *given))
    {
        return Err(ArgumentError::NotWithApi {
            argument,
            api: dialect,
        });
    }
    options.normal = given.normal.as_ref().map(normal).transpose()?;
    options.convention = word(
        "convention",
        given.convention.as_ref(),
        CONVENTIONS,
        |name| Convention::from_name(&name.replace('-', "_")),
    )?;
    options.precision =
        word("precision", given.precision.as_ref(), PRECISIONS, precision)?.or(given.arrays);
    options.renderer = word(
        "renderer",
        given.renderer.as_ref(),
        RENDERERS,
        Renderer::from_name,
    )?;
    // A script calling mi.fresnel and mi.refract itself: its fix is in its own call, in
    // Python, not in Mitsuba's C++ (`renderer="mitsuba"` asks for that).
    if options.renderer.is_none() && dialect == Dialect::Api(Api::Mitsuba) {
        options.renderer = Some(Renderer::MitsubaPython);
    }
    Ok(options)
}

fn sides_apart(given: &'static str, missing: &'static str) -> ArgumentError {
    ArgumentError::SidesApart { given, missing }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_renderers_listed_are_every_renderer() {
        let names: Vec<&str> = Renderer::ALL.iter().map(|r| r.name()).collect();
        assert_eq!(RENDERERS, names.join(", "));
    }

    #[test]
    fn api_names_a_dialect_or_none_the_physics() {
        assert_eq!(dialect(None).unwrap(), Dialect::Physics);
        assert_eq!(dialect(Some("HLSL")).unwrap(), Dialect::Api(Api::Glsl));
        assert_eq!(
            dialect(Some("mitsuba")).unwrap(),
            Dialect::Api(Api::Mitsuba)
        );
        let e = dialect(Some("optix")).unwrap_err().to_string();
        assert!(e.contains("optix") && e.contains("mitsuba"), "{e}");
    }

    #[test]
    fn the_options_are_checked_as_the_command_line_checks_them() {
        let mitsuba = Dialect::Api(Api::Mitsuba);
        let given = Given {
            inside: Some(1.5),
            outside: Some(1.0),
            precision: Some("f64".to_owned()),
            renderer: Some("Tungsten".to_owned()),
            ..Given::default()
        };
        let o = options(mitsuba, &given).unwrap();
        assert_eq!(o.sides(), Some((1.5, 1.0)));
        assert_eq!(o.precision, Some(Precision::F64));
        assert_eq!(o.renderer, Some(Renderer::Tungsten));
        let unnamed = options(mitsuba, &Given::default()).unwrap();
        assert_eq!(unnamed.renderer, Some(Renderer::MitsubaPython));
        for (inside, outside, named) in [
            (Some(f64::NAN), Some(1.0), "inside"),
            (Some(1.5), Some(0.0), "outside"),
            (Some(1.5), None, "outside"),
            (None, Some(1.0), "inside"),
        ] {
            let given = Given {
                inside,
                outside,
                ..Given::default()
            };
            let e = options(mitsuba, &given).unwrap_err().to_string();
            assert!(e.contains(named), "{inside:?} {outside:?}: {e}");
        }
        let normal = Given {
            normal: Some(Normal::Text("+z".to_owned())),
            ..Given::default()
        };
        let e = options(mitsuba, &normal).unwrap_err();
        assert!(matches!(
            e,
            ArgumentError::NotWithApi {
                argument: "normal",
                ..
            }
        ));
        let e = options(
            Dialect::Physics,
            &Given {
                precision: Some("half".to_owned()),
                ..Given::default()
            },
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("half") && e.contains("f32, f64"), "{e}");
    }

    #[test]
    fn a_normal_is_an_axis_or_three_numbers_not_zero() {
        let physics = |n: Normal| {
            let given = Given {
                normal: Some(n),
                ..Given::default()
            };
            options(Dialect::Physics, &given).map(|o| o.normal)
        };
        assert_eq!(
            physics(Normal::Text("-Y".to_owned())),
            Ok(Some([0.0, -1.0, 0.0]))
        );
        assert_eq!(
            physics(Normal::Text("0 0 1".to_owned())),
            Ok(Some([0.0, 0.0, 1.0]))
        );
        assert_eq!(
            physics(Normal::Vector([0.0, 2.0, 0.0])),
            Ok(Some([0.0, 2.0, 0.0]))
        );
        for refused in [
            Normal::Vector([0.0; 3]),
            Normal::Vector([f64::NAN, 0.0, 1.0]),
            Normal::Text("up".to_owned()),
        ] {
            assert!(
                matches!(physics(refused.clone()), Err(ArgumentError::Normal { .. })),
                "{refused:?}"
            );
        }
    }

    #[test]
    fn float32_arrays_mean_f32_unless_precision_says_otherwise() {
        let given = Given {
            arrays: Some(Precision::F32),
            ..Given::default()
        };
        let o = options(Dialect::Physics, &given).unwrap();
        assert_eq!(o.precision, Some(Precision::F32));
        let said = Given {
            precision: Some("double".to_owned()),
            ..given
        };
        let o = options(Dialect::Physics, &said).unwrap();
        assert_eq!(o.precision, Some(Precision::F64));
    }
}
