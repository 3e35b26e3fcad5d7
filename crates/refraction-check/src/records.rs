//! The diagnosis of calls held in memory, for a library caller (such as a Python package) that
//! has each call's fields as arrays rather than a log's lines: the same reading, judging and
//! diagnosis as `check`, without text in between.

use crate::call_check::{Judgement, LineError, Options, Record, Session, Tally};
use crate::diagnosis::{Code, Summary};

/// One call's verdict, as [`check_records`] gives it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CallResult {
    /// Whether the call is right as the diagnosis of all the calls counts it: a reflection
    /// read as sampled is, unless the calls show that the code never transmits there (what
    /// `check` answers that line, `"ok": true`, was written before the log was whole).
    pub ok: bool,
    /// The call's kind as `check` counts it on stderr: `ok`, `reflected (sampled)`, a code
    /// (`eta_inverted`), codes the call alone cannot tell apart joined by `|`, `unexplained`;
    /// for any renderer's refraction the candidate it is (`wrong_side`...).
    pub kind: String,
    /// The mistakes that explain the call, the likeliest first (the answer's `mistakes`).
    pub mistakes: Vec<Code>,
    /// The JSON answer `check` writes for the call's line, as one line.
    pub answer: String,
}

impl From<&Judgement> for CallResult {
    fn from(judgement: &Judgement) -> Self {
        Self {
            ok: judgement.ok(),
            kind: judgement.kind(),
            mistakes: judgement.mistakes(),
            answer: judgement.answer_line(),
        }
    }
}

/// What [`check_records`] found.
#[derive(Clone, Debug)]
pub struct Checked {
    /// Each call's verdict, in order, or why it could not be judged (what `check` answers
    /// with `{"line", "error"}`; counted as `unreadable`).
    pub calls: Vec<Result<CallResult, LineError>>,
    /// The calls counted by kind, as `check` prints them on stderr.
    pub tally: Tally,
    /// The diagnosis of all the calls as one log: what `check --summary` writes
    /// (`serde_json::to_string(&checked.summary)`), its verdict for the exit status.
    pub summary: Summary,
}

/// Judges every call of `records` in `options` (the dialect, `--inside`, `--outside`,
/// `--precision`, `--convention`, `--normal`, `--renderer`) and diagnoses them as one log,
/// exactly as `check` does the same calls written as JSON Lines.
///
/// ```
/// use refraction_check::{Dialect, Options, Record, Value, check_records};
/// use refraction_kernel::api::Api;
///
/// // GLSL's refract with eta upside down for a ray entering glass.
/// let call = Record::from_values(Api::Glsl, [
///     ("I", Value::Vector([0.6, -0.8, 0.0])),
///     ("N", Value::Vector([0.0, 1.0, 0.0])),
///     ("eta", Value::Number(1.5)),
///     ("result", Value::Vector([0.45, -0.893_028_1, 0.0])),
///     ("entering", Value::Flag(true)),
/// ])?;
/// let mut options = Options::new(Dialect::Api(Api::Glsl));
/// (options.inside, options.outside) = (Some(1.5), Some(1.0));
/// let checked = check_records(&options, [call]);
/// assert_eq!(checked.summary.diagnosis[0].code, "eta_inverted");
/// assert!(!checked.calls[0].as_ref().is_ok_and(|c| c.ok));
/// # Ok::<(), refraction_check::LineError>(())
/// ```
#[must_use]
pub fn check_records(options: &Options, records: impl IntoIterator<Item = Record>) -> Checked {
    let mut session = Session::new(*options, crate::Format::JsonLines, false, false);
    // The sampled reflections wait for the whole log: kept with their evidence.
    let mut sampled = Vec::new();
    let mut calls: Vec<_> = records
        .into_iter()
        .enumerate()
        .map(|(i, record)| {
            session.judge(&record).map(|j| {
                let call = CallResult::from(&j);
                if call.kind == crate::SAMPLED {
                    sampled.push((i, j.evidence()));
                }
                call
            })
        })
        .collect();
    for (i, evidence) in sampled {
        if let Some(Ok(call)) = calls.get_mut(i) {
            call.ok = !session.log().counts_wrong(&evidence);
        }
    }
    Checked {
        calls,
        tally: session.tally().clone(),
        summary: session.summary(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::call_check::record::Value;
    use crate::call_check::{Dialect, Format};
    use refraction_kernel::api::Api;

    /// pbrt calls, a right one first, as JSON Lines and as records built in memory.
    const LINES: [&str; 3] = [
        r#"{"wi":[-0.6,0.8,0],"n":[0,1,0],"eta":1.5,"wt":[0.4,-0.916515,0],"returned":true}"#,
        r#"{"wi":[-0.6,-0.8,0],"n":[0,1,0],"eta":1.5,"wt":[0.9,0.43589,0],"returned":true}"#,
        r#"{"wi":[0,0,1],"n":[0,1,0],"eta":1.5,"returned":false}"#,
    ];

    #[test]
    fn records_in_memory_get_the_answers_and_summary_of_the_same_json_lines() {
        let mut options = Options::new(Dialect::Api(Api::Pbrt));
        (options.inside, options.outside) = (Some(1.5), Some(1.0));
        let mut session = Session::new(options, Format::JsonLines, false, false);
        let mut out = Vec::new();
        session
            .run(LINES.join("\n").as_bytes(), &mut out, 1)
            .unwrap();
        let records = LINES.iter().map(|line| {
            let json: serde_json::Value = serde_json::from_str(line).unwrap();
            let values = json.as_object().unwrap().iter().map(|(name, v)| {
                let value = match v {
                    serde_json::Value::Array(a) => {
                        Value::Vector([0, 1, 2].map(|i| a[i].as_f64().unwrap()))
                    }
                    serde_json::Value::Bool(b) => Value::Flag(*b),
                    other => Value::Number(other.as_f64().unwrap()),
                };
                (name.as_str(), value)
            });
            Record::from_values(Api::Pbrt, values.collect::<Vec<_>>()).unwrap()
        });
        let checked = check_records(&options, records);
        let answers: Vec<String> = checked
            .calls
            .iter()
            .map(|c| c.as_ref().unwrap().answer.clone())
            .collect();
        assert_eq!(
            String::from_utf8(out).unwrap().lines().collect::<Vec<_>>(),
            answers
        );
        assert_eq!(checked.tally, *session.tally());
        assert_eq!(
            serde_json::to_string(&checked.summary).unwrap(),
            serde_json::to_string(&session.summary()).unwrap()
        );
        assert_ne!(
            checked.summary.diagnosis[0].code, "none",
            "the second call is wrong"
        );
    }

    /// Mitsuba calls entering glass that logged nothing (`wo` null) at normal incidence, where
    /// F = 4 %, and nowhere near transmit: each right on its own as a sampled reflection.
    fn never_transmitting(count: usize) -> Vec<Record> {
        (0..count)
            .map(|i| {
                let x = 0.001 * i as f64;
                let wi = [x, 0.0, (1.0 - x * x).sqrt()];
                let values = [
                    ("wi", Value::Vector(wi)),
                    ("eta", Value::Number(1.5)),
                    ("wo", Value::Null),
                ];
                Record::from_values(Api::Mitsuba, values).unwrap()
            })
            .collect()
    }

    #[test]
    fn reflections_where_the_code_never_transmits_are_not_ok_once_the_log_is_whole() {
        let mut options = Options::new(Dialect::Api(Api::Mitsuba));
        (options.inside, options.outside) = (Some(1.5), Some(1.0));
        let few = check_records(&options, never_transmitting(2));
        assert!(
            few.calls.iter().all(|c| c.as_ref().is_ok_and(|c| c.ok)),
            "two reflections at 4 % each are likely enough as samples"
        );
        let many = check_records(&options, never_transmitting(20));
        assert_eq!(many.tally.summary(), "20 reflected (sampled)");
        assert_eq!(many.summary.ok, 0, "{:?}", many.summary);
        assert!(
            many.calls.iter().all(|c| c.as_ref().is_ok_and(|c| !c.ok)),
            "a call is ok as the diagnosis counts it"
        );
    }

    #[test]
    fn a_bad_record_is_an_error_in_its_place_and_counted_unreadable() {
        let call = Record::from_values(Api::Glsl, [("eta", Value::Number(1.5))]).unwrap();
        let checked = check_records(&Options::new(Dialect::Api(Api::Glsl)), [call]);
        assert!(checked.calls[0].is_err());
        assert_eq!(checked.tally.summary(), "1 unreadable");
        let wrong = Record::from_values(Api::Glsl, [("I", Value::Number(1.0))]);
        assert!(
            matches!(wrong, Err(LineError::NotAVector { .. })),
            "{wrong:?}"
        );
        let unknown = Record::from_values(Api::Glsl, [("wo", Value::Null)]);
        assert!(
            matches!(unknown, Err(LineError::UnknownField { .. })),
            "{unknown:?}"
        );
    }
}
