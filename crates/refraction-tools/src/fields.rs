//! Reading a `solve` or `check` line into typed fields without building what is not needed.
//!
//! serde's derive skips unknown fields with [`IgnoredAny`], which reads past a value without
//! storing it, and every known field is read shallowly ([`Field`]): a number, a short string,
//! the first three items of an array and how many there were, or just the kind of anything
//! else. So a line's memory is bounded by what is used, not by what it carries, and the
//! messages can still name the kind of a wrong value (`got an array`).

use std::fmt;

use crate::error::JsonError;

use serde::Deserialize;
use serde::de::value::MapAccessDeserializer;
use serde::de::{self, DeserializeSeed, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};

/// How many items of an array are kept: the vectors have three.
const KEPT_ITEMS: usize = 3;

/// A field's value as read shallowly.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) enum Field {
    /// The field is not in the line.
    #[default]
    Absent,
    /// `null`.
    Null,
    /// A number, as f64.
    Number(f64),
    /// A string.
    Text(String),
    /// An array: its first [`KEPT_ITEMS`] items (nested arrays and objects only by kind) and
    /// its length.
    Array {
        /// The first items.
        items: Vec<Self>,
        /// How many items there were.
        len: usize,
    },
    /// Anything else, by kind (`a boolean`, `an object`, an array inside an array).
    Other(&'static str),
}

impl Field {
    /// The kind of value, as messages name it: `a number`, `a string`, `an array`, ...
    pub(crate) fn kind(&self) -> &'static str {
        match self {
            Self::Absent => "nothing",
            Self::Null => "null",
            Self::Number(_) => "a number",
            Self::Text(_) => "a string",
            Self::Array { .. } => "an array",
            Self::Other(kind) => kind,
        }
    }
}

/// Reads a [`Field`]; `nested` values (items of an array) keep no arrays of their own.
#[derive(Clone, Copy)]
struct Shallow {
    nested: bool,
}

impl<'de> Visitor<'de> for Shallow {
    type Value = Field;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("any JSON value")
    }

    fn visit_bool<E>(self, _: bool) -> Result<Field, E> {
        Ok(Field::Other("a boolean"))
    }

    fn visit_i64<E>(self, v: i64) -> Result<Field, E> {
        Ok(Field::Number(v as f64))
    }

    fn visit_u64<E>(self, v: u64) -> Result<Field, E> {
        Ok(Field::Number(v as f64))
    }

    fn visit_f64<E>(self, v: f64) -> Result<Field, E> {
        Ok(Field::Number(v))
    }

    fn visit_str<E>(self, v: &str) -> Result<Field, E> {
        Ok(Field::Text(v.to_owned()))
    }

    fn visit_unit<E>(self) -> Result<Field, E> {
        Ok(Field::Null)
    }

    fn visit_none<E>(self) -> Result<Field, E> {
        Ok(Field::Null)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Field, A::Error> {
        let mut items = Vec::new();
        let mut len = 0;
        loop {
            let more = if self.nested || len >= KEPT_ITEMS {
                seq.next_element::<IgnoredAny>()?.is_some()
            } else {
                seq.next_element_seed(Self { nested: true })?
                    .map(|item| items.push(item))
                    .is_some()
            };
            if !more {
                break;
            }
            len += 1;
        }
        Ok(if self.nested {
            Field::Other("an array")
        } else {
            Field::Array { items, len }
        })
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Field, A::Error> {
        while map.next_entry::<IgnoredAny, IgnoredAny>()?.is_some() {}
        Ok(Field::Other("an object"))
    }
}

impl<'de> DeserializeSeed<'de> for Shallow {
    type Value = Field;

    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<Field, D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de> Deserialize<'de> for Field {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(Shallow { nested: false })
    }
}

/// The fields of a line that `solve` and `check` read; `extra` is `t_yours` for `check` and
/// [`IgnoredAny`] for `solve`. Unknown fields are skipped unread.
#[derive(Deserialize)]
pub(crate) struct Fields<X> {
    #[serde(default)]
    pub w: Field,
    #[serde(default)]
    pub n: Field,
    #[serde(default)]
    pub mu_i: Field,
    #[serde(default)]
    pub mu_t: Field,
    #[serde(default)]
    pub convention: Field,
    #[serde(default)]
    pub precision: Field,
    #[serde(default, rename = "t_yours")]
    pub extra: X,
}

/// [`Fields`], but only from a JSON object: serde's derive would also read a struct from an
/// array, by position.
struct Object<X>(Fields<X>);

struct ObjectVisitor<X>(core::marker::PhantomData<X>);

impl<'de, X: Deserialize<'de> + Default> Visitor<'de> for ObjectVisitor<X> {
    type Value = Object<X>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON object with fields w, n, mu_i, mu_t")
    }

    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Object<X>, A::Error> {
        Fields::deserialize(MapAccessDeserializer::new(map)).map(Object)
    }

    fn visit_bool<E: de::Error>(self, _: bool) -> Result<Object<X>, E> {
        Err(not_an_object("a boolean"))
    }

    fn visit_i64<E: de::Error>(self, _: i64) -> Result<Object<X>, E> {
        Err(not_an_object("a number"))
    }

    fn visit_u64<E: de::Error>(self, _: u64) -> Result<Object<X>, E> {
        Err(not_an_object("a number"))
    }

    fn visit_f64<E: de::Error>(self, _: f64) -> Result<Object<X>, E> {
        Err(not_an_object("a number"))
    }

    fn visit_str<E: de::Error>(self, _: &str) -> Result<Object<X>, E> {
        Err(not_an_object("a string"))
    }

    fn visit_unit<E: de::Error>(self) -> Result<Object<X>, E> {
        Err(not_an_object("null"))
    }

    fn visit_seq<A: SeqAccess<'de>>(self, _: A) -> Result<Object<X>, A::Error> {
        Err(not_an_object("an array"))
    }
}

fn not_an_object<E: de::Error>(kind: &str) -> E {
    E::custom(format!(
        "expected a JSON object with fields w, n, mu_i, mu_t; got {kind}"
    ))
}

impl<'de, X: Deserialize<'de> + Default> Deserialize<'de> for Object<X> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(ObjectVisitor(core::marker::PhantomData))
    }
}

/// Reads the fields of one line (or of a whole state file).
///
/// # Errors
/// Malformed JSON with its place, or not a JSON object.
pub(crate) fn read<X: for<'de> Deserialize<'de> + Default>(
    text: &str,
) -> Result<Fields<X>, JsonError> {
    serde_json::from_str::<Object<X>>(text)
        .map(|o| o.0)
        .map_err(|e| JsonError::from(&e))
}

/// Reads the fields of a parsed JSON value.
///
/// # Errors
/// Not a JSON object.
pub(crate) fn from_value<X: for<'de> Deserialize<'de> + Default>(
    value: &serde_json::Value,
) -> Result<Fields<X>, JsonError> {
    Object::<X>::deserialize(value)
        .map(|o| o.0)
        .map_err(|e| JsonError::from(&e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_are_read_shallowly_and_unknown_ones_skipped() {
        let fields: Fields<IgnoredAny> = read(
            r#"{"w":[1,[2,[3]],{"a":1},4,5],"n":"up","big":[[[[1]]],{"x":[1,2,3]}],"mu_i":true}"#,
        )
        .unwrap();
        assert_eq!(
            fields.w,
            Field::Array {
                items: vec![
                    Field::Number(1.0),
                    Field::Other("an array"),
                    Field::Other("an object")
                ],
                len: 5
            }
        );
        assert_eq!(fields.n, Field::Text("up".into()));
        assert_eq!(fields.mu_i.kind(), "a boolean");
        assert_eq!(fields.mu_t, Field::Absent);
        let err = read::<IgnoredAny>("[1, 2]").map(|_| ()).unwrap_err();
        assert_eq!(
            err.to_string(),
            "expected a JSON object with fields w, n, mu_i, mu_t; got an array"
        );
    }

    #[test]
    fn malformed_json_names_the_line_only_when_there_are_several() {
        let err = read::<IgnoredAny>("{\"w\": }")
            .map(|_| ())
            .unwrap_err()
            .to_string();
        assert!(err.starts_with("malformed JSON at column 7:"), "{err}");
        let err = read::<IgnoredAny>("{\n  \"w\": [1, 0, 0],\n  \"n\": [0 1 0]\n}")
            .map(|_| ())
            .unwrap_err()
            .to_string();
        assert!(
            err.starts_with("malformed JSON at line 3, column 11:"),
            "{err}"
        );
    }
}
