//! One logged call as named values, read from a JSON line or from the texts a `--pattern` or
//! CSV header names, with the significant digits its numbers were written with.

use serde_json::Value as Json;

use super::error::LineError;
use super::fields::{self, Dialect, Kind};
use refraction_tools::vector_text::{digits_of, json_vector_digits, parse_number, parse_vector};

/// One field's value.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A number.
    Number(f64),
    /// A 3-vector.
    Vector([f64; 3]),
    /// true/false.
    Flag(bool),
    /// null: nothing came back.
    Null,
    /// A word (path id, precision name).
    Label(String),
}

/// A JSON line's object, each key given once (a key given twice is an error, as `solve` says,
/// rather than the last one silently winning); `None` for JSON that is not an object.
struct Object(Option<serde_json::Map<String, Json>>);

impl<'de> serde::Deserialize<'de> for Object {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(ObjectVisitor)
    }
}

struct ObjectVisitor;

impl<'de> serde::de::Visitor<'de> for ObjectVisitor {
    type Value = Object;

    fn expecting(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        // untranslated: serde's own words, as in every JSON error of `solve` and `check`.
        f.write_str("a JSON object")
    }

    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<Object, A::Error> {
        let mut object = serde_json::Map::new();
        while let Some(key) = map.next_key::<String>()? {
            if object.contains_key(&key) {
                // untranslated: serde's own words for a struct's field given twice (`solve`'s).
                let said = format!("duplicate field `{key}`");
                return Err(serde::de::Error::custom(said));
            }
            let value = map.next_value()?;
            object.insert(key, value);
        }
        Ok(Object(Some(object)))
    }

    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<Object, A::Error> {
        while seq.next_element::<serde::de::IgnoredAny>()?.is_some() {}
        Ok(Object(None))
    }

    fn visit_bool<E>(self, _: bool) -> Result<Object, E> {
        Ok(Object(None))
    }

    fn visit_i64<E>(self, _: i64) -> Result<Object, E> {
        Ok(Object(None))
    }

    fn visit_u64<E>(self, _: u64) -> Result<Object, E> {
        Ok(Object(None))
    }

    fn visit_f64<E>(self, _: f64) -> Result<Object, E> {
        Ok(Object(None))
    }

    fn visit_str<E>(self, _: &str) -> Result<Object, E> {
        Ok(Object(None))
    }

    fn visit_unit<E>(self) -> Result<Object, E> {
        Ok(Object(None))
    }
}

/// The fields of one logged call, each with the significant digits it was written with.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Record {
    values: Vec<(&'static str, Value, Written)>,
}

/// How a field's numbers were written: the significant digits each is trusted to, and
/// whether they show a decimal point or an exponent (a fixed format's `0.6` may be 0.55 to
/// 0.65; a printed `0`, `1` or `-1` is the value it says).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Written {
    /// Significant digits (see [`Record::digits`]).
    pub digits: u32,
    /// Whether a number of the field has a decimal point or an exponent.
    pub decimal: bool,
}

impl Written {
    /// Digits written in full text: `decimal` when one of its numbers has a point or an
    /// exponent.
    fn of_text(digits: u32, text: &str) -> Self {
        let bytes = text.as_bytes();
        let exponent = bytes
            .windows(2)
            .any(|w| (w[0].is_ascii_digit() || w[0] == b'.') && matches!(w[1], b'e' | b'E'));
        let point = bytes
            .windows(2)
            .any(|w| w[0] == b'.' && w[1].is_ascii_digit())
            || bytes
                .windows(2)
                .any(|w| w[0].is_ascii_digit() && w[1] == b'.');
        Self {
            digits,
            decimal: point || exponent,
        }
    }

    /// Digits of numbers held as values (JSON's, or a caller's): never a fixed format's
    /// rounding, as JSON writers print the shortest text that reads back as the number.
    fn of_values(digits: u32) -> Self {
        Self {
            digits,
            decimal: false,
        }
    }
}

/// Whether a vector's text holds a line break between its numbers: printed one number a line
/// (Eigen's `cout << v`, numpy's wrapped rows), whose lines a pattern cannot join for sure.
fn column_printed(text: &str) -> bool {
    let numbers_before = |line: &str| line.chars().any(|c| c.is_ascii_digit());
    let lines: Vec<&str> = text.lines().filter(|l| numbers_before(l)).collect();
    lines.len() > 1
}

fn flag_text(text: &str) -> Option<bool> {
    match text.trim().to_ascii_lowercase().as_str() {
        "true" | "1" | "yes" => Some(true),
        "false" | "0" | "no" => Some(false),
        _ => None,
    }
}

fn is_null_text(text: &str) -> bool {
    matches!(
        text.trim().to_ascii_lowercase().as_str(),
        "null" | "none" | "nullptr" | "-"
    )
}

/// Whether `text` reads as a value of `kind`: [`from_text`] without the message it would
/// write, for a pattern that tries many texts.
pub(super) fn accepts(kind: Kind, text: &str) -> bool {
    match kind {
        Kind::VectorOrNull if is_null_text(text) => true,
        Kind::Vector | Kind::VectorOrNull => parse_vector(text).is_ok(),
        Kind::Number => parse_number(text).is_ok(),
        Kind::Flag => flag_text(text).is_some(),
        Kind::Label => true,
    }
}

/// Reads `text` as a value of `kind`, with its significant digits.
///
/// # Errors
/// The text is not a value of that kind; the message names the field.
pub(crate) fn from_text(kind: Kind, name: &str, text: &str) -> Result<(Value, Written), LineError> {
    let text = text.trim();
    let wrap = |error| LineError::Text {
        field: name.to_owned(),
        error,
    };
    match kind {
        Kind::VectorOrNull if is_null_text(text) => Ok((Value::Null, Written::default())),
        Kind::Vector | Kind::VectorOrNull if column_printed(text) => Err(LineError::ColumnVector {
            field: name.to_owned(),
        }),
        Kind::Vector | Kind::VectorOrNull => parse_vector(text)
            .map(|v| (Value::Vector(v.value), Written::of_text(v.digits, text)))
            .map_err(wrap),
        Kind::Number => parse_number(text)
            .map(|n| (Value::Number(n.value), Written::of_text(n.digits, text)))
            .map_err(wrap),
        Kind::Flag => flag_text(text)
            .map(|f| (Value::Flag(f), Written::default()))
            .ok_or_else(|| LineError::NotFlagText {
                field: name.to_owned(),
                text: text.to_owned(),
            }),
        Kind::Label => Ok((Value::Label(text.to_owned()), Written::default())),
    }
}

fn json_number(value: &Json, name: &str) -> Result<(f64, Written), LineError> {
    match value {
        Json::Number(n) => {
            let x = n.as_f64().unwrap_or(f64::NAN);
            Ok((x, Written::of_values(digits_of(x))))
        }
        Json::Null => Ok((f64::NAN, Written::default())),
        Json::String(text) => parse_number(text)
            .map(|n| (n.value, Written::of_text(n.digits, text)))
            .map_err(|error| LineError::Text {
                field: name.to_owned(),
                error,
            }),
        _ => Err(LineError::NotNumber {
            field: name.to_owned(),
        }),
    }
}

fn json_vector(value: &Json, name: &str) -> Result<(Value, Written), LineError> {
    match value {
        Json::String(text) => from_text(Kind::Vector, name, text),
        Json::Array(items) if items.len() == 3 => {
            let mut out = [0.0; 3];
            for (i, (slot, item)) in out.iter_mut().zip(items).enumerate() {
                *slot = json_number(item, &format!("{name}[{i}]"))?.0;
            }
            let written = Written::of_values(json_vector_digits(out));
            Ok((Value::Vector(out), written))
        }
        Json::Array(items) => Err(LineError::NotThree {
            field: name.to_owned(),
            count: items.len(),
        }),
        _ => Err(LineError::NotAVector {
            field: name.to_owned(),
        }),
    }
}

/// Reads the JSON `value` as a value of `kind`, with its significant digits.
fn from_json(kind: Kind, name: &str, value: &Json) -> Result<(Value, Written), LineError> {
    match (kind, value) {
        (Kind::VectorOrNull, Json::Null) => Ok((Value::Null, Written::default())),
        (Kind::Vector | Kind::VectorOrNull, _) => json_vector(value, name),
        (Kind::Number, _) => json_number(value, name).map(|(x, d)| (Value::Number(x), d)),
        (Kind::Flag, Json::Bool(b)) => Ok((Value::Flag(*b), Written::default())),
        (Kind::Flag, Json::Number(_) | Json::String(_)) => {
            let text = value
                .as_str()
                .map_or_else(|| value.to_string(), str::to_owned);
            from_text(kind, name, &text)
        }
        (Kind::Label, Json::String(text)) => Ok((Value::Label(text.clone()), Written::default())),
        (Kind::Label, Json::Number(n)) => Ok((Value::Label(n.to_string()), Written::default())),
        (Kind::Flag, _) => Err(LineError::NotFlag {
            field: name.to_owned(),
        }),
        (Kind::Label, _) => Err(LineError::NotLabel {
            field: name.to_owned(),
        }),
    }
}

impl Record {
    /// The value of field `name`, if the line has it (a JSON null counts as absent except
    /// where null means something, as for pbrt's `wt`).
    #[must_use]
    pub fn get(&self, name: &str) -> Option<&Value> {
        self.values
            .iter()
            .find(|(n, ..)| *n == name)
            .map(|(_, v, _)| v)
    }

    /// The significant digits field `name` was written with: a vector's most precise
    /// component; 0 for a field without numbers, one absent, or a number written exactly
    /// (17 digits or more, `%a`).
    #[must_use]
    pub fn digits(&self, name: &str) -> u32 {
        self.written(name).digits
    }

    /// How field `name`'s numbers were written (the default for a field absent).
    #[must_use]
    pub(crate) fn written(&self, name: &str) -> Written {
        self.values
            .iter()
            .find(|(n, ..)| *n == name)
            .map_or_else(Written::default, |(.., written)| *written)
    }

    /// Turns flag `name` round, if the record has it: a pattern's `{!entering}` for a renderer
    /// that prints `inside` or `backfacing`.
    pub fn negate(&mut self, name: &str) {
        for (field, value, _) in &mut self.values {
            if let (true, Value::Flag(flag)) = (*field == name, value) {
                *flag = !*flag;
            }
        }
    }

    fn push(&mut self, name: &'static str, (value, written): (Value, Written)) {
        self.values.push((name, value, written));
    }

    /// Reads one JSON line of `api`'s fields; other fields are ignored.
    ///
    /// # Errors
    /// Malformed JSON (with its column), not an object, or an ill-typed field.
    pub fn from_json_line(dialect: impl Into<Dialect>, line: &str) -> Result<Self, LineError> {
        let dialect = dialect.into();
        let object: Object =
            serde_json::from_str(line).map_err(|e| refraction_tools::JsonError::from(&e))?;
        let object = object.0.ok_or(LineError::NotAnObject { dialect })?;
        Self::from_object(dialect, &object)
    }

    /// Reads `dialect`'s fields of a JSON object; other fields are ignored.
    fn from_object(
        dialect: Dialect,
        object: &serde_json::Map<String, Json>,
    ) -> Result<Self, LineError> {
        let mut record = Self::default();
        for (name, kind) in fields::all(dialect) {
            match object.get(name) {
                None => {}
                Some(Json::Null) if kind != Kind::VectorOrNull => {}
                Some(value) => record.push(name, from_json(kind, name, value)?),
            }
        }
        Ok(record)
    }

    /// A record of `dialect`'s fields from values held in memory (a library's arrays rather
    /// than a log's text), read exactly as the same values in a JSON line would be: each
    /// number trusted to the digits of its shortest form, [`Value::Null`] meaning "logged
    /// nothing" where null means something (pbrt's `wt`, Mitsuba's `wo`, `t_yours`) and an
    /// absent field elsewhere; a NaN or infinite number reads as JSON's `null`.
    ///
    /// # Errors
    /// A name that is not one of the dialect's fields (its words name the field), or a value of
    /// the wrong kind for its field (a number for a vector...).
    pub fn from_values<'a>(
        dialect: impl Into<Dialect>,
        values: impl IntoIterator<Item = (&'a str, Value)>,
    ) -> Result<Self, LineError> {
        let dialect = dialect.into();
        let number = |x: f64| serde_json::Number::from_f64(x).map_or(Json::Null, Json::Number);
        let mut object = serde_json::Map::new();
        for (name, value) in values {
            let (field, _) =
                fields::find(dialect, name).ok_or_else(|| LineError::UnknownField {
                    field: name.to_owned(),
                })?;
            let json = match value {
                Value::Number(x) => number(x),
                Value::Vector(v) => Json::Array(v.map(number).to_vec()),
                Value::Flag(flag) => Json::Bool(flag),
                Value::Null => Json::Null,
                Value::Label(text) => Json::String(text),
            };
            object.insert(field.to_owned(), json);
        }
        Self::from_object(dialect, &object)
    }

    /// Reads the texts a pattern or CSV line gave for `api`'s fields.
    ///
    /// # Errors
    /// An unknown field name or a text that is not a value of its field's kind.
    pub fn from_texts<'a>(
        dialect: impl Into<Dialect>,
        texts: impl IntoIterator<Item = (&'a str, &'a str)>,
    ) -> Result<Self, LineError> {
        let (dialect, mut record) = (dialect.into(), Self::default());
        for (name, text) in texts {
            let (field, kind) =
                fields::find(dialect, name).ok_or_else(|| LineError::UnknownField {
                    field: name.to_owned(),
                })?;
            record.push(field, from_text(kind, name, text)?);
        }
        Ok(record)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_kernel::api::Api;

    #[test]
    fn a_key_given_twice_is_refused_and_other_json_is_not_an_object() {
        // Issue 31: the last of two `t_yours` was used without a word.
        let twice =
            r#"{"I":[0.6,-0.8,0],"N":[0,1,0],"eta":0.5,"result":[0,-1,0],"result":[1,0,0]}"#;
        let e = Record::from_json_line(Api::Glsl, twice).unwrap_err();
        assert!(e.to_string().contains("duplicate field `result`"), "{e}");
        for other in ["[1, 2]", "1", "\"I\"", "null", "true"] {
            let e = Record::from_json_line(Api::Glsl, other).unwrap_err();
            assert!(e.to_string().contains("JSON object"), "{other}: {e}");
        }
    }

    #[test]
    fn json_and_text_give_the_same_record() {
        let json = Record::from_json_line(
            Api::Rtiow,
            r#"{"uv":[0.6,-0.8,0],"n":"0 1 0","etai_over_etat":"0.666667","refracted":[0.4,-0.916515,0],"entering":1,"path":7}"#,
        )
        .unwrap();
        let text = Record::from_texts(
            Api::Rtiow,
            [
                ("uv", "vec3(0.6, -0.8, 0)"),
                ("n", "[0, 1, 0]"),
                ("etai_over_etat", "0.666667"),
                ("refracted", "(0.4, -0.916515, 0)"),
                ("entering", "true"),
                ("path", "7"),
            ],
        )
        .unwrap();
        // The same values and digits; only text may be a fixed format's rounding.
        for name in ["uv", "n", "etai_over_etat", "refracted", "entering", "path"] {
            assert_eq!(json.get(name), text.get(name), "{name}");
            assert_eq!(json.digits(name), text.digits(name), "{name}");
        }
        assert_eq!(json.digits("refracted"), 7, "0.916515: six places");
        assert_eq!(json.digits("n"), 1, "0 1 0: no places");
        assert_eq!(json.get("entering"), Some(&Value::Flag(true)));
    }

    #[test]
    fn null_means_nothing_came_back_only_where_it_can() {
        let r =
            Record::from_json_line(Api::Pbrt, r#"{"wi":[0,1,0],"wt":null,"from":null}"#).unwrap();
        assert_eq!(r.get("wt"), Some(&Value::Null));
        assert_eq!(r.get("from"), None);
        let e = Record::from_texts(Api::Glsl, [("wt", "1 2 3")]).unwrap_err();
        assert!(e.to_string().contains("unknown field `wt`"), "{e}");
        let e = Record::from_json_line(Api::Glsl, r#"{"entering":"maybe"}"#).unwrap_err();
        assert!(
            e.to_string().contains("`entering` must be true/false"),
            "{e}"
        );
    }
}
