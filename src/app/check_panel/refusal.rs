//! Why *Check my T* could not check what it was given: the tools' errors as they came, and the
//! panel's own, worded when shown, in the window's language of the moment.

use core::fmt;
use refraction_check::tests_file::TargetError;
use refraction_check::{LineError, PatternError};
use refraction_i18n::t;
use refraction_kernel::InputError;
use refraction_tools::{CheckError, RequestError, VectorError, vector_text::spoken};

/// Why the panel refused a case, a call, a log or a test file.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Refusal {
    /// A call, a log line or any renderer's case that cannot be judged.
    Line(LineError),
    /// The log's pattern.
    Pattern(PatternError),
    /// A whole `check` line pasted in "Your T".
    Check(CheckError),
    /// The case typed in the fields.
    Request(RequestError),
    /// The case cannot be opened in the explorer.
    Input(InputError),
    /// A field that must hold a number.
    NotANumber {
        /// The field's label.
        field: String,
        /// What it holds.
        text: String,
    },
    /// A field that must hold a vector.
    Vector {
        /// The field's label.
        field: String,
        /// Why it cannot be read.
        error: VectorError,
    },
    /// An index field that holds no finite number above 0.
    Index {
        /// The field's label.
        field: String,
        /// What it holds.
        text: String,
    },
    /// The right call's ratio needs indices the explorer does not draw.
    PictureOutside {
        /// The ratio.
        mu: f64,
        /// The explorer's lowest index.
        low: f64,
        /// Its highest.
        high: f64,
    },
    /// Where the tests may not be written.
    Target(TargetError),
}

impl fmt::Display for Refusal {
    #[rustfmt::skip] // the t! keys stay where the translation tests find them
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let words = match self {
            Self::Line(error) => return error.fmt(f),
            Self::Pattern(error) => return error.fmt(f),
            Self::Check(error) => return error.fmt(f),
            Self::Request(error) => return error.fmt(f),
            Self::Input(error) => return error.fmt(f),
            Self::Target(error) => return error.fmt(f),
            Self::Vector { field, error } => return write!(f, "{field}: {error}"),
            Self::NotANumber { field, text } => {
                t!("check-field-not-number", field = field, text = text.trim())
            }
            Self::Index { field, text } => {
                t!("logs-index-invalid", field = field, text = text.trim())
            }
            Self::PictureOutside { mu, low, high } => {
                let [mu, low, high] = [*mu, *low, *high].map(spoken);
                t!("check-picture-outside", mu = mu, low = low, high = high)
            }
        };
        f.write_str(&words)
    }
}

/// `From` each tools' error a refusal carries as it came.
macro_rules! carried {
    ($($error:ty => $variant:ident),* $(,)?) => {
        $(impl From<$error> for Refusal {
            fn from(error: $error) -> Self {
                Self::$variant(error)
            }
        })*
    };
}

carried! {
    LineError => Line,
    PatternError => Pattern,
    CheckError => Check,
    RequestError => Request,
    InputError => Input,
    TargetError => Target,
}
