//! CSV logs: a header naming the fields, then one call per line. A vector is one column (`uv`,
//! quoted when it holds commas: `"0.6, -0.8, 0"`) or three (`uv.x,uv.y,uv.z`, `uv_x,...` or
//! `uv[0],...`); columns the API has no field for are ignored; an empty cell is an absent field.

use refraction_kernel::api::Api;

use super::error::{CsvError, LineError};
use super::fields::{self, Dialect, Kind, names};
use super::record::Record;

/// What one column holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Column {
    /// A whole field.
    Field(&'static str),
    /// Component `axis` (0, 1, 2) of a vector field.
    Component(&'static str, usize),
    /// Something the API has no field for.
    Ignored,
}

/// A parsed CSV header.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Header {
    dialect: Dialect,
    columns: Vec<Column>,
}

/// The cells of one CSV line (RFC 4180 quoting: `"a, b"`, `""` for a quote).
///
/// # Errors
/// An unclosed quote.
pub(crate) fn cells(line: &str) -> Result<Vec<String>, CsvError> {
    let mut out = vec![String::new()];
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        let cell = out
            .last_mut()
            // untranslated: a programmer's note, never shown
            .unwrap_or_else(|| unreachable!("out starts non-empty"));
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                chars.next();
                cell.push('"');
            }
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(String::new()),
            _ => cell.push(c),
        }
    }
    if quoted {
        return Err(CsvError::UnclosedQuote);
    }
    Ok(out.into_iter().map(|c| c.trim().to_owned()).collect())
}

fn column(dialect: Dialect, name: &str) -> Column {
    if let Some((field, _)) = fields::find(dialect, name) {
        return Column::Field(field);
    }
    for (axis, suffixes) in [
        [".x", "_x", "[0]"],
        [".y", "_y", "[1]"],
        [".z", "_z", "[2]"],
    ]
    .iter()
    .enumerate()
    {
        for suffix in suffixes {
            let vector = name
                .strip_suffix(suffix)
                .and_then(|base| fields::find(dialect, base));
            if let Some((field, Kind::Vector | Kind::VectorOrNull)) = vector {
                return Column::Component(field, axis);
            }
        }
    }
    Column::Ignored
}

impl Header {
    /// Reads the header line for `dialect`.
    ///
    /// # Errors
    /// A missing argument or result column, a vector with only some of its components.
    pub(crate) fn parse(dialect: impl Into<Dialect>, line: &str) -> Result<Self, CsvError> {
        let dialect = dialect.into();
        let headings = cells(line)?;
        let columns: Vec<Column> = headings.iter().map(|c| column(dialect, c)).collect();
        // A field named twice would be read from either column: refuse it, as JSON's are.
        let clash = |a: &Column, b: &Column| match (a, b) {
            (Column::Field(f), Column::Field(g) | Column::Component(g, _))
            | (Column::Component(f, _), Column::Field(g)) => f == g,
            (Column::Component(f, x), Column::Component(g, y)) => f == g && x == y,
            _ => false,
        };
        for (i, c) in columns.iter().enumerate() {
            if columns[..i].iter().any(|earlier| clash(c, earlier)) {
                let column = headings[i].clone();
                return Err(CsvError::DuplicateColumn { column });
            }
        }
        let has = |field: &str| {
            columns.iter().any(|c| match c {
                Column::Field(f) => *f == field,
                Column::Component(f, _) => *f == field,
                Column::Ignored => false,
            })
        };
        let needed = match dialect {
            Dialect::Api(api) => {
                let n = names(api);
                vec![n.incident, n.normal, n.eta, n.result]
            }
            Dialect::Physics => vec!["w", "n", "t_yours"],
        };
        for field in needed {
            let optional = match dialect {
                Dialect::Api(Api::Mitsuba) => field == "n",
                Dialect::Api(Api::Pbrt) => field == "wt" && has(fields::RETURNED),
                _ => false,
            };
            if !optional && !has(field) {
                let names = line.trim().to_owned();
                return Err(CsvError::NoColumn {
                    field,
                    names,
                    dialect,
                });
            }
        }
        for (field, _) in fields::all(dialect) {
            let axes = (0..3)
                .filter(|&axis| columns.contains(&Column::Component(field, axis)))
                .count();
            if axes != 0 && axes != 3 {
                return Err(CsvError::PartialVector { field, count: axes });
            }
        }
        Ok(Self { dialect, columns })
    }

    /// Reads one data line.
    ///
    /// # Errors
    /// A different number of cells than the header has columns, or a bad value.
    pub(crate) fn record(&self, line: &str) -> Result<Record, LineError> {
        let cells = cells(line)?;
        if cells.len() != self.columns.len() {
            let (count, columns) = (cells.len(), self.columns.len());
            return Err(CsvError::Cells { count, columns }.into());
        }
        let mut texts: Vec<(&str, String)> = Vec::new();
        let mut parts: Vec<(&str, [&str; 3])> = Vec::new();
        for (column, cell) in self.columns.iter().zip(&cells) {
            match *column {
                Column::Field(field) if !cell.is_empty() => texts.push((field, cell.clone())),
                Column::Component(field, axis) => {
                    let index = parts
                        .iter()
                        .position(|(f, _)| *f == field)
                        .unwrap_or_else(|| {
                            parts.push((field, [""; 3]));
                            parts.len() - 1
                        });
                    parts[index].1[axis] = cell;
                }
                _ => {}
            }
        }
        for (field, components) in parts {
            if components.iter().all(|c| !c.is_empty()) {
                texts.push((field, components.join(" ")));
            }
        }
        Record::from_texts(self.dialect, texts.iter().map(|(f, t)| (*f, t.as_str())))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::call_check::record::Value;

    #[test]
    fn vectors_in_one_column_or_three() {
        let header = Header::parse(Api::Glsl, "step,I.x,I.y,I.z,N,eta,result,from,to").unwrap();
        let r = header
            .record(r#"3,0.6,-0.8,0,"0, 1, 0",0.666667,"[0.4, -0.916515, 0]",1,1.5"#)
            .unwrap();
        assert_eq!(r.get("I"), Some(&Value::Vector([0.6, -0.8, 0.0])));
        assert_eq!(r.get("N"), Some(&Value::Vector([0.0, 1.0, 0.0])));
        assert_eq!(r.get("to"), Some(&Value::Number(1.5)));
        assert_eq!(
            (r.digits("I"), r.digits("eta"), r.digits("result")),
            (2, 6, 7)
        );
        let pbrt = Header::parse(Api::Pbrt, "wi_x,wi_y,wi_z,n[0],n[1],n[2],eta,returned").unwrap();
        let r = pbrt.record("0,1,0,0,1,0,1.5,false").unwrap();
        assert_eq!(r.get("returned"), Some(&Value::Flag(false)));
    }

    #[test]
    fn bad_headers_and_lines_say_why() {
        let e = Header::parse(Api::Rtiow, "uv,n,refracted").unwrap_err();
        assert!(e.to_string().contains("no column `etai_over_etat`"), "{e}");
        let e = Header::parse(Api::Glsl, "I,N,eta,result,N").unwrap_err();
        assert!(e.to_string().contains("`N` more than once"), "{e}");
        let e = Header::parse(Api::Glsl, "I,I.x,I.y,I.z,N,eta,result").unwrap_err();
        assert!(e.to_string().contains("`I.x` more than once"), "{e}");
        let e = Header::parse(Api::Glsl, "I.x,I.y,N,eta,result").unwrap_err();
        assert!(
            e.to_string().contains("only 2 of `I`'s 3 components"),
            "{e}"
        );
        let header = Header::parse(Api::Glsl, "I,N,eta,result").unwrap();
        assert!(
            header
                .record("1,2")
                .unwrap_err()
                .to_string()
                .contains("2 cells where the header has 4")
        );
        assert!(cells(r#"a,"b"#).is_err());
        assert_eq!(
            cells(r#"a,"say ""hi""",c"#).unwrap(),
            ["a", r#"say "hi""#, "c"]
        );
    }
}
