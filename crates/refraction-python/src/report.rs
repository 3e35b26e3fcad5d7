//! What `check` found on calls held in arrays, as Python shows it: one verdict per call, the
//! summary `check --summary` writes, and a short text (`repr`) and table (a notebook's
//! `_repr_html_`) of the tally, the diagnosis and the first wrong calls.

use refraction_check::{CallResult, Checked};
use refraction_i18n::t;

/// A call that could not be judged, as `check`'s tally counts it.
// untranslated: the tally's name, as `check` counts it on stderr
pub(crate) const UNREADABLE: &str = "unreadable";

/// The most wrong calls the notebook's table lists.
pub(crate) const WRONG_SHOWN: usize = 5;

/// What [`refraction_check::check_records`] found, read as Python reads it.
#[derive(Clone, Debug)]
pub struct Report {
    checked: Checked,
}

impl Report {
    /// The report of `checked`.
    #[must_use]
    pub fn new(checked: Checked) -> Self {
        Self { checked }
    }

    /// How many calls were given.
    #[must_use]
    pub fn len(&self) -> usize {
        self.checked.calls.len()
    }

    /// Whether no call was given (never, for a report `check` made).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.checked.calls.is_empty()
    }

    fn judged(&self) -> impl Iterator<Item = Option<&CallResult>> {
        self.checked.calls.iter().map(|call| call.as_ref().ok())
    }

    /// Whether each call is right (a sampled reflection is; a call that could not be judged
    /// is not).
    #[must_use]
    pub fn ok(&self) -> Vec<bool> {
        self.judged().map(|c| c.is_some_and(|c| c.ok)).collect()
    }

    /// Each call's code as `check` counts it: `ok`, `reflected (sampled)`, a mistake's code,
    /// codes the call alone cannot tell apart joined by `|`, `unexplained`, a candidate's
    /// name for any renderer's refraction (`wrong_side`), or `unreadable`.
    #[must_use]
    pub fn codes(&self) -> Vec<String> {
        self.judged()
            .map(|c| c.map_or_else(|| UNREADABLE.to_owned(), |c| c.kind.clone()))
            .collect()
    }

    /// The mistakes that explain each call, the likeliest first (none for a right call or one
    /// that could not be judged).
    #[must_use]
    pub fn mistakes(&self) -> Vec<Vec<&'static str>> {
        self.judged()
            .map(|c| c.map_or_else(Vec::new, |c| c.mistakes.iter().map(|m| m.name()).collect()))
            .collect()
    }

    /// Each call's JSON answer, as `check` writes its line (`None` for a call that could not be
    /// judged).
    #[must_use]
    pub fn answers(&self) -> Vec<Option<&str>> {
        self.judged()
            .map(|c| c.map(|c| c.answer.as_str()))
            .collect()
    }

    /// Why each call could not be judged (`None` for those judged), as `check` answers the
    /// line with `{"error": ...}`.
    #[must_use]
    pub fn errors(&self) -> Vec<Option<String>> {
        let error = |call: &Result<CallResult, _>| call.as_ref().err().map(ToString::to_string);
        self.checked.calls.iter().map(error).collect()
    }

    /// The calls counted by code, as `check` prints them on stderr.
    #[must_use]
    pub fn tally(&self) -> Vec<(&str, usize)> {
        self.checked.tally.counts().collect()
    }

    /// The diagnosis of all the calls as one log, as `check --summary` writes it (JSON).
    #[must_use]
    pub fn summary_json(&self) -> String {
        refraction_tools::json_line(&self.checked.summary)
    }

    /// The diagnosis in sentences, the verdict first, as `check` closes its stderr.
    #[must_use]
    pub fn sentences(&self) -> Vec<String> {
        self.checked.summary.sentences()
    }

    /// The code of the verdict: `none`, `unchecked` or the bug's.
    #[must_use]
    pub fn verdict(&self) -> Option<&'static str> {
        self.checked.summary.diagnosis.first().map(|f| f.code)
    }

    /// The first line of the text and the table: how many calls, how many right.
    fn title(&self) -> String {
        let ok = self.ok().iter().filter(|ok| **ok).count();
        t!("python-title", calls = self.len(), ok = ok)
    }

    /// The text Python's `repr` gives: the title, the tally and the diagnosis, as `check`
    /// prints them.
    #[must_use]
    pub fn text(&self) -> String {
        let mut lines = vec![self.title(), self.checked.tally.summary()];
        lines.extend(self.sentences());
        lines.join("\n")
    }

    /// Each wrong call's row (from 0), code and explanation, the first [`WRONG_SHOWN`].
    fn first_wrong(&self) -> Vec<(usize, String, String)> {
        let explanation = |answer: &str| {
            serde_json::from_str::<serde_json::Value>(answer)
                .ok()
                .and_then(|a| a["explanation"].as_str().map(str::to_owned))
                .unwrap_or_default()
        };
        self.checked
            .calls
            .iter()
            .enumerate()
            .filter_map(|(row, call)| match call {
                Ok(c) if c.ok => None,
                Ok(c) => Some((row, c.kind.clone(), explanation(&c.answer))),
                Err(e) => Some((row, UNREADABLE.to_owned(), e.to_string())),
            })
            .take(WRONG_SHOWN)
            .collect()
    }

    /// The table a notebook shows (`_repr_html_`): the title, the verdict and its fix, the
    /// calls counted by code, the rest of the diagnosis, and the first wrong calls.
    #[must_use]
    pub fn html(&self) -> String {
        let sentences = self.sentences();
        let mut html = format!("<div><p><strong>{}</strong></p>", escape(&self.title()));
        if let Some(verdict) = sentences.first() {
            html += &format!("<p>{}</p>", escape(verdict));
        }
        html += &table(
            &[t!("python-column-code"), t!("python-column-calls")],
            self.tally()
                .into_iter()
                .map(|(code, n)| vec![code.to_owned(), n.to_string()]),
        );
        for sentence in sentences.iter().skip(1) {
            html += &format!("<p>{}</p>", escape(sentence));
        }
        let wrong = self.first_wrong();
        if !wrong.is_empty() {
            let wrong_calls = self.ok().iter().filter(|ok| !**ok).count();
            html += &format!(
                "<p>{}</p>",
                escape(&t!(
                    "python-first-wrong",
                    shown = wrong.len(),
                    wrong = wrong_calls
                ))
            );
            html += &table(
                &[
                    t!("python-column-row"),
                    t!("python-column-code"),
                    t!("python-column-explanation"),
                ],
                wrong
                    .into_iter()
                    .map(|(row, code, why)| vec![row.to_string(), code, why]),
            );
        }
        html.push_str("</div>");
        html
    }
}

/// An HTML table of `rows` under `headings`, every cell escaped.
fn table(headings: &[String], rows: impl Iterator<Item = Vec<String>>) -> String {
    let row = |tag: &str, cells: &[String]| {
        let mut row = String::from("<tr>");
        for cell in cells {
            row.push_str(&format!(
                "<{tag} style=\"text-align:left\">{}</{tag}>",
                escape(cell)
            ));
        }
        row.push_str("</tr>");
        row
    };
    let mut table = format!("<table><thead>{}</thead><tbody>", row("th", headings));
    for cells in rows {
        table.push_str(&row("td", &cells));
    }
    table.push_str("</tbody></table>");
    table
}

/// `text` as HTML text: `&`, `<`, `>` and quotes written as entities.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_check::{Dialect, Options, Record, Value, check_records};
    use refraction_kernel::api::Api;

    /// Three GLSL calls entering glass: right, eta inverted, and one without its normal.
    fn report() -> Report {
        let call = |result: [f64; 3], n: Option<[f64; 3]>| {
            let mut values = vec![
                ("I", Value::Vector([0.6, -0.8, 0.0])),
                ("eta", Value::Number(1.0 / 1.5)),
                ("result", Value::Vector(result)),
                ("entering", Value::Flag(true)),
            ];
            values.extend(n.map(|n| ("N", Value::Vector(n))));
            Record::from_values(Api::Glsl, values).unwrap()
        };
        let normal = Some([0.0, 1.0, 0.0]);
        let right = [0.4, -0.916_515_138_991_168, 0.0];
        let calls = [
            call(right, normal),
            call([0.9, -0.435_889_894_354_067_4, 0.0], normal),
            call(right, None),
        ];
        let mut options = Options::new(Dialect::Api(Api::Glsl));
        (options.inside, options.outside) = (Some(1.5), Some(1.0));
        Report::new(check_records(&options, calls))
    }

    #[test]
    fn each_call_has_its_verdict_code_and_answer() {
        let r = report();
        assert_eq!(r.len(), 3);
        assert_eq!(r.ok(), vec![true, false, false]);
        let codes = r.codes();
        assert_eq!(codes[0], "ok");
        assert_ne!(codes[1], "ok");
        assert_eq!(codes[2], UNREADABLE);
        assert!(r.mistakes()[0].is_empty() && r.mistakes()[2].is_empty());
        assert!(r.answers()[0].is_some_and(|a| a.contains("\"ok\":true")));
        assert!(r.answers()[2].is_none());
        assert!(
            r.errors()[2].as_deref().is_some_and(|e| e.contains('N')),
            "{:?}",
            r.errors()
        );
        let summary: serde_json::Value = serde_json::from_str(&r.summary_json()).unwrap();
        assert_eq!(summary["judged"], 2);
        assert_eq!(summary["diagnosis"][0]["code"], r.verdict().unwrap());
    }

    #[test]
    fn the_text_and_the_table_say_the_tally_and_the_diagnosis() {
        let r = report();
        let text = r.text();
        assert!(text.starts_with("3 calls, 1 right"), "{text}");
        assert!(text.contains("1 unreadable"), "{text}");
        assert!(text.contains(&r.sentences()[0]), "{text}");
        let html = r.html();
        assert!(
            html.starts_with("<div>") && html.ends_with("</div>"),
            "{html}"
        );
        assert_eq!(html.matches("<table>").count(), 2, "{html}");
        assert!(
            html.contains("<td style=\"text-align:left\">unreadable</td>"),
            "{html}"
        );
        assert!(html.contains("The first 2 of 2 wrong calls"), "{html}");
        assert!(!html.contains("<p>The bug: <"), "text is escaped");
    }

    #[test]
    fn html_text_is_escaped() {
        assert_eq!(escape("a < b & \"c\""), "a &lt; b &amp; &quot;c&quot;");
    }
}
